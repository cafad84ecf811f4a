# replay.tcl --
#	Replays a CLSF file through a fivax post outside NX, emulating NX's MOM
#	runtime, and writes the NC program.
#
#	tclsh tools/replay.tcl ?options? part.cls     ("-" reads standard input)
#	Run with -help for the options: the posting job's settings
#	([fivax::settings table], the same table the post reads) plus -post,
#	-o, -quiet, -check-process.
#
#	The post. -post picks it as NX does: by name (a shipped post,
#	post/NAME.tcl, default fivax) or as a post's .tcl file, its .def the
#	one its template_post.dat line names (nctool postDef: NAME.def beside
#	it, else fivax.def beside it); a shop's copied and edited post runs as
#	it is. The
#	settings given on the command line go on top of the post's own (its
#	wrapper's fivax_settings), as FIVAX_SETTINGS does inside NX; the checks
#	below use the settings the post assembles (read from it once loaded).
#
#	Every option value, the machine file and the output path are checked
#	before anything runs. Errors are one line ("FILE:LINE: what", or
#	"replay: ..."), exit status 1, never a Tcl stack trace.
#
#	Output. Without -o the program streams to standard output; with -o it
#	goes to a temporary file beside the target, renamed into place at the
#	end (a FIFO or character device named by -o is written directly, like
#	standard output), and the post's log (warnings, retracts, errors) to
#	<target>.log beside it by the same rule (without -log; a FIFO or
#	device target has no log). Every block reaches its destination one output
#	buffer late: when a run fails (a written value outside the machine's
#	limits is refused right after it was formatted) the held-back buffer
#	is dropped, so the offending block is never written. The temporary
#	files are removed on every exit path: errors and a broken pipe here,
#	and signals (which pure Tcl cannot catch) by a guard process that
#	removes them when this process ends in any way (see ::replay::Guard).
#	A run that fails after the -o path was checked also removes the
#	program (and its log) an earlier run left there, and says so.
#
#	Progress. When standard error is a terminal (and without -quiet) a
#	progress line there, at most twice a second, for each stage: posting
#	(records, percent of the input bytes, rate, the time left to post and
#	whether the dry run follows), then the dry run of the written program
#	(lines read, moves followed through the stock: it takes about as long
#	as posting). The time left is estimated from the rate of the later
#	half of the stage so far (see Left).

package require Tcl 8.6

namespace eval ::replay {
    variable root [file dirname [file dirname [file normalize [info script]]]]
    # Options of the command line only; the others are the job settings.
    variable cliOptions {
        {-post text fivax NAME|FILE
            "the post, as NX picks it: a shipped post's name (post/NAME.tcl) or a post's .tcl file; its .def is NAME.def beside it, else fivax.def beside it"}
        {-o text {} FILE "output NC file (default, or -: standard output)"}
        {-quiet bool 0 "" "no summary and no progress line on standard error"}
        {-check-process {enum auto on off} auto WHEN "block check in a second process: on, off, or auto: on for a CL file of 1 MB or more with two processors or more"}
        {-help bool 0 "" "print this help"}
    }
    # Output buffer (bytes): blocks reach the destination one buffer late.
    variable bufferSize 65536
    # Shortest time between two progress lines (ms).
    variable progressMs 500
    # The time left is estimated from the progress of the later half of
    # the stage so far, over this much at least (ms).
    variable rateMs 5000
    # Smallest CL file (bytes) -check-process auto checks in a second
    # process (about 15k records: starting it takes about 0.1 s; the -help
    # text says 1 MB).
    variable checkProcessBytes 1000000
    # The run's state (see Reset).
    variable R
    # The settings the environment gives the post (FIVAX_SETTINGS, as in
    # NX); the command line's go on top (see Runtime).
    variable environment {}
    if {[info exists ::env(FIVAX_SETTINGS)] && [string is list $::env(FIVAX_SETTINGS)]} {
        set environment $::env(FIVAX_SETTINGS)
    }
}
set auto_path [linsert $auto_path 0 [file join $::replay::root lib]]
package require fivax::host 0.1
source [file join $::replay::root tools lib nctool.tcl]

# ::replay::Reset -- Clears the run's state: output target, sink, guard, progress.
proc ::replay::Reset {} {
    variable R
    array unset R
    array set R {
        target "" stale {} tmp "" log "" out "" sink "" guard "" held "" discard 0 broken ""
        rt "" shown 0 start 0 last 0 size "" samples {} stage "" stageStart 0 dryrun 0
    }
}
::replay::Reset

# ::replay::Say -- Prints msg on standard error (a closed stderr is ignored).
proc ::replay::Say {msg} {
    ClearProgress
    catch {puts stderr $msg}
}

# ::replay::Die --
#	Cleans up, prints msg on standard error and exits with status 1; the
#	previous program at a file target (and its log) is removed (see
#	RemovePrevious).
proc ::replay::Die {msg} {
    Cleanup
    Say $msg
    RemovePrevious
    exit 1
}

# ::replay::RemovePrevious --
#	Removes the files of R(stale), the -o file target and its log left
#	by an earlier run, once this run has failed: a program at the -o path
#	after a failed run would pass for this run's. Says so on standard
#	error.
proc ::replay::RemovePrevious {} {
    variable R
    foreach path $R(stale) {
        if {[catch {file type $path} type] || $type ne "file"} continue
        if {![catch {file delete -- $path}]} {
            Say "replay: removed the previous $path: this run failed"
        }
    }
    set R(stale) {}
}

# ::replay::Table -- Returns the command line's option table.
proc ::replay::Table {} {
    variable cliOptions
    concat [::fivax::settings table] $cliOptions
}

# ::replay::ParseArgs --
#	Returns {opts given clsf} of argv: every option (defaults filled in),
#	the job settings given on the command line, the CLSF path.
proc ::replay::ParseArgs {argv} {
    try {
        lassign [::fivax::opts given [Table] $argv replay] given rest
        set opts [dict merge [::fivax::opts parse [Table] {}] $given]
    } trap {FIVAX OPTION UNKNOWN} {msg} {
        if {[regexp {unknown option "(.*)": must be} $msg -> name]} {
            Die "replay: unknown option $name (-help lists the options)"
        }
        Die $msg
    } trap {FIVAX OPTION} {msg} {
        Die $msg
    }
    if {[dict get $opts -help]} {
        # (a reader that stops early, as head or less, is no error)
        catch {puts "usage: tclsh tools/replay.tcl ?options? part.cls\n\nReplays an NX CLSF file through the fivax post.\nOptions:\n[::fivax::opts help [Table]]"}
        exit 0
    }
    if {[llength $rest] == 0} {
        Die "usage: tclsh tools/replay.tcl ?options? part.cls (-help for the options)"
    }
    if {[llength $rest] > 1} {
        Die "replay: expected one CL file after the options, got [llength $rest] words: [lrange $rest 0 3]"
    }
    list $opts [dict filter $given key {*}[::fivax::opts names [::fivax::settings table]]] \
        [lindex $rest 0]
}

# ::replay::PostFiles --
#	Returns {tcl def} of the post that -post names: a shipped post's name
#	(post/NAME.tcl) or a post's .tcl file (a path, or a name ending in
#	.tcl), its .def NAME.def beside it, else fivax.def beside it (nctool
#	postDef, as the wrappers' template_post.dat lines name them); dies
#	when either cannot be read.
proc ::replay::PostFiles {post} {
    variable root
    if {[llength [file split $post]] > 1 || [string match *.tcl $post]} {
        set tcl [file normalize $post]
    } else {
        set tcl [file join $root post $post.tcl]
        if {![file isfile $tcl]} {
            set names [lsort [lmap f [glob -nocomplain -directory [file join $root post] *.tcl] {
                file rootname [file tail $f]
            }]]
            Die "replay: bad -post \"$post\": no shipped post of that name (post/ has [join $names {, }]);\
                a post's own file is named with its path or .tcl"
        }
    }
    if {![file isfile $tcl] || ![file readable $tcl]} {Die "replay: -post $post: cannot read $tcl"}
    set def [::fivax::nctool postDef $tcl]
    if {![file isfile $def] || ![file readable $def]} {
        Die "replay: -post $post: cannot read its .def $def (its own .def beside it, else fivax.def)"
    }
    list $tcl $def
}

# ::replay::CheckInput --
#	Dies unless clsf ("-": standard input) is a file that can be read.
proc ::replay::CheckInput {clsf} {
    if {$clsf eq "-"} return
    if {[file isdirectory $clsf]} {Die "$clsf: cannot read CL file: is a directory"}
    if {![file readable $clsf]} {Die "$clsf: cannot read CL file"}
}

# ::replay::CheckMachineFile --
#	Dies unless the machine file the settings given on the command line
#	name (if any) can be read.
proc ::replay::CheckMachineFile {given} {
    if {![dict exists $given -machine]} return
    try {
        set file [::fivax::machine find [dict get $given -machine]]
    } trap {FIVAX MACHINE NOFILE} {msg} {
        Die $msg
    }
    if {![file isfile $file] || ![file readable $file]} {Die "$file: machine file not found"}
}

# ::replay::CheckMachine --
#	Loads and checks the machine file of settings, its output settings
#	(with the post's .def defFile, as the post makes its output layer) and
#	the settings that depend on them (the post's check, fivax::settings
#	output); returns the machine dict or dies.
proc ::replay::CheckMachine {settings defFile} {
    try {
        set machine [::fivax::machine load [dict get $settings -machine]]
        [::fivax::settings output $settings $machine $defFile replay] destroy
    } trap {FIVAX} {msg} {
        Die $msg
    }
    return $machine
}

# ::replay::Resolve --
#	Returns the path a symbolic link path finally points to (path itself
#	when it is no link); dies on a loop.
proc ::replay::Resolve {path} {
    for {set hops 0} {$hops < 40} {incr hops} {
        if {[catch {file type $path} type] || $type ne "link"} {return $path}
        set to [file readlink $path]
        set path [file normalize [file join [file dirname $path] $to]]
    }
    Die "replay: $path: too many levels of symbolic links"
}

# ::replay::SameFile -- Returns 1 when paths a and b name the same existing file.
proc ::replay::SameFile {a b} {
    if {[catch {file stat $a sa}] || [catch {file stat $b sb}]} {return 0}
    expr {$sa(dev) == $sb(dev) && $sa(ino) == $sb(ino)}
}

# ::replay::CheckTarget --
#	Checks the path out of option (-o or -log) against the inputs (clsf,
#	machine file) and returns {direct path} or {file path}: the resolved
#	target and how it is written (direct: a FIFO or character device,
#	opened as it is; file: a regular file). Dies with "replay: -o ...".
proc ::replay::CheckTarget {option out clsf machineFile} {
    set path [Resolve [file normalize $out]]
    set shown "replay: $option $out"
    foreach {input what} [list $clsf "the CL file" $machineFile "the machine file"] {
        if {$input ne "-" && [SameFile $path $input]} {Die "$shown: is $what"}
    }
    if {[file exists $path]} {
        switch -- [file type $path] {
            directory {Die "$shown: is a directory"}
            fifo - characterSpecial {
                if {![file writable $path]} {Die "$shown: permission denied"}
                return [list direct $path]
            }
            file {
                if {![file writable $path]} {Die "$shown: permission denied"}
            }
            default {Die "$shown: not a regular file ([file type $path])"}
        }
    }
    set dir [file dirname $path]
    if {![file isdirectory $dir]} {Die "$shown: no such directory: $dir"}
    if {![file writable $dir]} {Die "$shown: cannot write in $dir: permission denied"}
    list file $path
}

# ::replay::Guard --
#	Starts the guard of the temporary files tmp and tmp.log: a shell that
#	ignores the usual signals and removes them once its standard input (a
#	pipe from this process) closes, i.e. when this process ends, whatever
#	ends it (exit, error, SIGINT, SIGTERM, SIGHUP, SIGKILL). After the
#	renames the paths are gone and the removal does nothing. Returns the
#	pipe, or "" where no POSIX shell runs it (the error paths still
#	remove them).
proc ::replay::Guard {tmp} {
    set script {trap "" HUP INT QUIT PIPE TERM; cat >/dev/null; rm -f -- "$1" "$1.log"}
    # In a session of its own (where setsid exists) signals sent to this
    # process group, even SIGKILL, do not reach it.
    set cmd [list sh -c $script fivax-guard $tmp]
    if {[auto_execok setsid] ne ""} {set cmd [linsert $cmd 0 setsid]}
    if {[catch {open |[concat $cmd {>/dev/null 2>/dev/null}] w} chan]} {
        return ""
    }
    return $chan
}

# ::replay::OpenTarget --
#	Opens the output: standard output (target ""), a direct target, or a
#	temporary file beside a file target under a guard, whose log goes to
#	log ("": none). Sets R(out).
proc ::replay::OpenTarget {target log} {
    variable R
    if {$target eq ""} {
        set R(out) stdout
    } else {
        lassign $target how path
        if {$how eq "direct"} {
            if {[catch {open $path WRONLY} chan]} {
                Die "replay: -o $path: cannot write: [string trim [lindex [split $chan :] end]]"
            }
            set R(out) $chan
        } else {
            set R(target) $path
            set tmp $path.tmp-[pid]-[clock clicks]
            set R(guard) [Guard $tmp]
            if {[catch {open $tmp {WRONLY CREAT EXCL}} chan]} {
                Die "replay: -o $path: cannot write: [string trim [lindex [split $chan :] end]]"
            }
            set R(tmp) $tmp
            set R(log) $log
            set R(out) $chan
        }
    }
    chan configure $R(out) -translation binary -buffering full
}

# ::replay::Sink --
#	The reflected channel the post writes to. Each buffer written is
#	passed on to R(out) when the next one arrives, and the last one when
#	the run succeeded (Finish); a failed run drops it (R(discard)). A
#	write error on R(out) (a closed pipe) marks the run broken.
proc ::replay::Sink {cmd chan args} {
    variable R
    switch -- $cmd {
        initialize {return {initialize finalize watch write}}
        finalize - watch {return}
        write {
            set data [lindex $args 0]
            if {!$R(discard)} {
                Pass $R(held)
                set R(held) $data
            }
            return [string length $data]
        }
    }
}

# ::replay::Pass -- Writes data to R(out); a failure marks the run broken and raises.
proc ::replay::Pass {data} {
    variable R
    if {$data eq ""} return
    if {[catch {puts -nonewline $R(out) $data} msg]} {Broken $msg}
}

# ::replay::Broken --
#	Marks the run broken by the write error msg (R(broken): its reason,
#	e.g. "broken pipe"), drops what is held and raises {REPLAY BROKEN}.
proc ::replay::Broken {msg} {
    variable R
    set R(broken) [regsub {^.*: } $msg ""]
    set R(discard) 1
    return -code error -level 2 -errorcode {REPLAY BROKEN} "output closed: $msg"
}

# ::replay::Finish --
#	Ends a successful run: the sink's last buffers go out, the output is
#	closed and a temporary file renamed into place.
proc ::replay::Finish {} {
    variable R
    flush $R(sink)
    close $R(sink)
    set R(sink) ""
    Pass $R(held)
    set R(held) ""
    if {[catch {flush $R(out)} msg]} {Broken $msg}
    if {$R(out) ne "stdout"} {
        close $R(out)
        set R(out) ""
    }
    if {$R(tmp) ne ""} {
        if {$R(log) ne "" && [file exists $R(tmp).log]} {
            file rename -force $R(tmp).log $R(log)
        }
        file rename -force $R(tmp) $R(target)
        set R(tmp) ""
    }
    set R(stale) {}
    CloseGuard
}

# ::replay::LogFile --
#	Returns <target>.log, the log file beside the file target path, or ""
#	when that is the target itself; dies when it cannot be written or is
#	one of the inputs (clsf, the machine file).
proc ::replay::LogFile {path clsf machineFile} {
    set log [file rootname $path].log
    if {$log eq $path} {return ""}
    foreach {input what} [list $clsf "the CL file" $machineFile "the machine file"] {
        if {$input ne "-" && [SameFile $log $input]} {Die "replay: -o $path: its log $log is $what"}
    }
    if {[file exists $log] && ([file type $log] ne "file" || ![file writable $log])} {
        Die "replay: -o $path: its log $log is not a writable file"
    }
    return $log
}

# ::replay::Cleanup --
#	Ends a failed run: drops what the sink holds, closes the output and
#	removes the temporary file; safe to call more than once.
proc ::replay::Cleanup {} {
    variable R
    set R(discard) 1
    set R(held) ""
    if {$R(sink) ne ""} {
        catch {close $R(sink)}
        set R(sink) ""
    }
    if {$R(out) ne "" && $R(out) ne "stdout"} {
        catch {close $R(out)}
        set R(out) ""
    }
    if {$R(tmp) ne ""} {
        catch {file delete -force $R(tmp) $R(tmp).log}
        set R(tmp) ""
    }
    CloseGuard
}

# ::replay::CloseGuard -- Closes the guard's pipe (it then removes nothing or the leftover).
proc ::replay::CloseGuard {} {
    variable R
    if {$R(guard) ne ""} {
        catch {close $R(guard)}
        set R(guard) ""
    }
}

# ::replay::Listing -- Prints a listing line of the post on stderr (the summary is printed apart).
proc ::replay::Listing {text} {
    if {![string match "fivax summary:*" $text]} {Say $text}
}

# ::replay::Tick --
#	The CL reader's progress command (records read, line, bytes read):
#	shows the posting stage's progress line when R(progressMs) has passed
#	since the last.
proc ::replay::Tick {records line bytes} {
    variable R
    if {![Due]} return
    set frac ""
    if {$R(size) ne "" && $R(size) > 0} {set frac [expr {min(1.0, double($bytes) / $R(size))}]}
    set ms [Sample posting $frac]
    ShowProgress [ProgressText $records $frac $ms [Left $R(samples)] $R(dryrun)]
}

# ::replay::ProgressText --
#	Returns the posting stage's progress line for records read, the
#	fraction frac of the input bytes read ("" when the size is unknown)
#	after ms milliseconds, s seconds left ("" when unknown), dryrun 1
#	when the dry run follows.
proc ::replay::ProgressText {records frac ms s dryrun} {
    set text [format "fivax: %d records" $records]
    if {$frac ne ""} {append text [format ", %d%%" [expr {int($frac * 100)}]]}
    append text [format ", %d records/s" [expr {round($records * 1000.0 / max($ms, 1))}]]
    append text [LeftText $s [expr {$dryrun ? " to post, then the dry run" : ""}]]
}

# ::replay::DryRunTick --
#	The dry run's progress command (what: lines read, moves followed;
#	done of total): shows its progress line as Tick does.
proc ::replay::DryRunTick {what done total} {
    variable R
    if {![Due]} return
    set frac [expr {double($done) / max($total, 1)}]
    Sample "dry run $what" $frac
    ShowProgress [format "fivax: dry run: %d of %d %s, %d%%%s" $done $total $what \
        [expr {int($frac * 100)}] [LeftText [Left $R(samples)] ""]]
}

# ::replay::Due --
#	Returns 1 (and notes the time) when R(progressMs) has passed since the
#	last progress line.
proc ::replay::Due {} {
    variable R
    variable progressMs
    set now [clock milliseconds]
    if {$now - $R(last) < $progressMs} {return 0}
    set R(last) $now
    return 1
}

# ::replay::Sample --
#	Adds the sample {ms frac} (ms since the stage began) of stage (a new
#	stage starts its samples anew); returns ms. frac "": none.
proc ::replay::Sample {stage frac} {
    variable R
    set now [clock milliseconds]
    if {$stage ne $R(stage)} {
        set R(stage) $stage
        set R(stageStart) [expr {$stage eq "posting" ? $R(start) : $now}]
        set R(samples) {{0 0.0}}
    }
    set ms [expr {$now - $R(stageStart)}]
    if {$frac ne ""} {lappend R(samples) [list $ms $frac]}
    return $ms
}

# ::replay::Left --
#	Returns the seconds left of a stage from its progress samples {ms
#	frac} (ms since it began, the fraction done; oldest first), "" while
#	unknown: the rest at the rate of the later half of the time so far
#	(at least rateMs). The whole stage's average rate misjudged it for
#	long: the reader runs ahead of the work while the planner fills its
#	window, and a program's operations do not cost alike per byte (a fast
#	first half made 4:48 look like 1:11).
proc ::replay::Left {samples} {
    variable rateMs
    lassign [lindex $samples end] ms frac
    if {$frac eq "" || $frac <= 0 || $ms <= 0} {return ""}
    set from [expr {$ms - max($rateMs, $ms / 2.0)}]
    # the last sample at or before from (the first when none is)
    set base [lindex $samples 0]
    foreach sample $samples {
        if {[lindex $sample 0] > $from} break
        set base $sample
    }
    lassign $base ms0 frac0
    if {$frac <= $frac0 || $ms <= $ms0} {return ""}
    expr {round((1.0 - $frac) * ($ms - $ms0) / ($frac - $frac0) / 1000.0)}
}

# ::replay::LeftText -- Returns ", M:SS left" and then tail for seconds s, "" when s is "".
proc ::replay::LeftText {s tail} {
    if {$s eq ""} {return ""}
    format ", %d:%02d left%s" [expr {$s / 60}] [expr {$s % 60}] $tail
}

# ::replay::ShowProgress -- Writes text over the progress line on stderr.
proc ::replay::ShowProgress {text} {
    variable R
    set pad [expr {max(0, $R(shown) - [string length $text])}]
    catch {
        puts -nonewline stderr "\r$text[string repeat " " $pad]"
        flush stderr
    }
    set R(shown) [string length $text]
}

# ::replay::ClearProgress -- Removes the progress line from stderr, if shown.
proc ::replay::ClearProgress {} {
    variable R
    if {!$R(shown)} return
    catch {
        puts -nonewline stderr "\r[string repeat " " $R(shown)]\r"
        flush stderr
    }
    set R(shown) 0
}

# ::replay::Terminal -- Returns 1 when chan is a terminal (it has the serial -mode option).
proc ::replay::Terminal {chan} {
    expr {![catch {chan configure $chan -mode}]}
}

# ::replay::CheckProcess --
#	Returns 1 when the block check runs in a second process: -check-process
#	on, or auto for a CL file of checkProcessBytes or more on a machine
#	with two processors or more (getconf tells; 0 when it cannot).
proc ::replay::CheckProcess {when clsf} {
    variable checkProcessBytes
    switch -- $when {
        on {return 1}
        off {return 0}
    }
    if {$clsf eq "-" || ![file isfile $clsf] || [file size $clsf] < $checkProcessBytes} {return 0}
    if {[catch {exec getconf _NPROCESSORS_ONLN} n] || ![string is entier -strict $n]} {return 0}
    expr {$n >= 2}
}

# ::replay::Runtime --
#	Returns a new MOM runtime (fivax::mom create, options args) with the
#	post postFile and its .def defFile loaded, the settings given added
#	on top of the post's own as FIVAX_SETTINGS adds them inside NX (after
#	those of the environment).
proc ::replay::Runtime {postFile defFile given args} {
    variable root
    variable environment
    set ::env(FIVAX_SETTINGS) [concat $environment $given]
    ::fivax::mom create -post $postFile -def $defFile \
        -autopath [list [file join $root lib] [info library]] {*}$args
}

# ::replay::PostSettings --
#	Returns the settings the post postFile (.def defFile) posts with, the
#	settings given on top (see Runtime), as the post assembles them when
#	it loads; {} for a post that is no fivax post (an NX post such as
#	Post Builder makes: it runs as it is, and takes none of the settings:
#	dies when some are given); dies with the post's message when it stops
#	loading. (The post loads without the -log given: a post that stops
#	loading writes its log, and that file is not checked yet.)
proc ::replay::PostSettings {postFile defFile given} {
    try {
        set rt [Runtime $postFile $defFile [dict remove $given -log]]
    } trap {FIVAX} {msg} {
        Die $msg
    } on error {msg} {
        Die "replay: -post $postFile: the post does not load: $msg"
    }
    try {
        set child [$rt interp]
        if {![$child eval {info exists ::fivax(settings)}]} {
            if {[dict size $given]} {
                Die "replay: -post $postFile: [join [dict keys $given] {, }]: settings of fivax\
                    posts, and this post is none (it sets no fivax(settings))"
            }
            return {}
        }
        set settings [$child eval {set ::fivax(settings)}]
        dict merge $settings [dict filter $given key -log]
    } finally {
        $rt destroy
    }
}

# ::replay::Post --
#	Runs the post postFile (.def defFile) on clsf with the settings given
#	(see Runtime), writing NC text to channel chan; out is the output
#	file as NX names it to the post ("" for a stream). Returns the
#	runtime statistics merged with the post's summary. An error that
#	names no place gets the current CL record's FILE:LINE; one that is
#	no fivax error is marked internal. With process 1 the post's checker
#	runs in a second process (tools/lib/checkproc.tcl); when the post
#	stops on an error of its own, an error that process found in an
#	earlier block is reported instead (the post in one process would
#	have stopped there). With progress 1 the post's dry run shows its
#	progress (DryRunTick).
proc ::replay::Post {postFile defFile given clsf chan out process progress} {
    variable root
    set globals {}
    if {$out ne ""} {
        dict set globals mom_output_file_full_name $out
        dict set globals mom_output_file_directory [file dirname $out]/
        dict set globals mom_output_file_basename [file rootname [file tail $out]]
        dict set globals mom_output_file_suffix [string trimleft [file extension $out] .]
    }
    set rt [Runtime $postFile $defFile $given -channel $chan -listing ::replay::Listing \
        -globals $globals]
    if {$progress} {
        # the dry run at the end of the program (in the post's interpreter)
        # shows its progress too
        [$rt interp] alias ::replay_dryrun_tick ::replay::DryRunTick
        [$rt interp] eval {::fivax::dryrun::progress ::replay_dryrun_tick}
    }
    if {$process} {
        set child [$rt interp]
        $child eval [list source [file join $root tools lib checkproc.tcl]]
        $child eval [list ::fivax::checkproc::install [info nameofexecutable] [file join $root lib]]
    }
    try {
        set stats [$rt run $clsf]
        set child [$rt interp]
        if {[$child eval {info exists ::fivax_summary}]} {
            set stats [dict merge $stats [$child eval {set ::fivax_summary}]]
        }
        return $stats
    } on error {msg opts} {
        set code [dict get $opts -errorcode]
        if {$process} {
            set failure [[$rt interp] eval ::fivax::checkproc::failure]
            if {[llength $failure]} {lassign $failure code msg}
        }
        if {[lindex $code 0] ne "FIVAX" && [lindex $code 0] ne "REPLAY"} {
            set msg "internal error: $msg"
        }
        append msg [MsysHint $code [$rt interp]]
        if {![regexp {^[^\n]*:\d+: } $msg]} {
            set child [$rt interp]
            if {[$child eval {info exists ::mom_cl_line}]} {
                set msg "[$child eval {set ::mom_cl_file}]:[$child eval {set ::mom_cl_line}]: $msg"
            }
        }
        return -code error -errorcode $code $msg
    } finally {
        $rt destroy
    }
}

# ::replay::MsysHint --
#	Returns the hint added to the message of an error (code: its error
#	code) when the post in interpreter child stopped on an unreachable
#	tool axis (its fivax(abortCode)), the CL file's MSYS record turns the
#	MCS and the post's -msys setting is off; else "".
proc ::replay::MsysHint {code child} {
    if {$code eq {FIVAX MOM ABORT} && [$child eval {info exists ::fivax(abortCode)}]} {
        set code [$child eval {set ::fivax(abortCode)}]
    }
    if {$code ne {FIVAX MOTION UNREACHABLE} || [$child eval {dict get $::fivax(settings) -msys}]
            || ![$child eval {array exists ::mom_msys_matrix}]} {return ""}
    set axes [$child eval {lmap i {0 1 2 3 4 5} {set ::mom_msys_matrix($i)}}]
    foreach a $axes b {1 0 0 0 1 0} {
        if {abs($a - $b) > 1e-9} {
            return "; the CL file's MSYS record turns its MCS in NX's absolute frame:\
                try -msys, which posts the CL data in that frame"
        }
    }
    return ""
}

# ::replay::Summary --
#	Prints the run's figures (stats) on standard error; the tool changes,
#	dwell swings and clamped inverse-time feeds only when there are any,
#	each explained (machine: the machine dict).
proc ::replay::Summary {stats machine} {
    dict with stats {}
    # the runtime's warnings (unknown records) and the post's
    if {[info exists postWarnings]} {incr warnings $postWarnings}
    Say [format "fivax: %d records read, %d blocks written, %d warnings" \
        $records $blocks $warnings]
    if {[info exists checked]} {
        Say [format "fivax: %d CL points checked by forward kinematics: max deviation %.6f mm, %.6f deg" \
            $checked $maxPos $maxAng]
        Say [format "fivax: %d cutting moves checked at quarter points: max deviation %.6f mm, %.6f deg; %d rotary values outside limits" \
            $segments $maxMidPos $maxMidAng $limitViolations]
    }
    if {[info exists inserted]} {
        Say [format "fivax: %d points inserted, %d limit retracts, %d rapids after cutting, rotary travel %.3f deg; %d azimuth holds, %d singular swings, %d moves left out of tolerance" \
            $inserted $retracts $rapidsAfterCut $travel $holds $swings $unresolved]
        if {$toolChanges} {Say "fivax: [Count $toolChanges {tool change}]"}
        if {$dwells} {
            Say [format "fivax: %s: cutting blocks where the rotaries turn, %.3f deg in all,\
                with the tip in place (the CL turns the tool axis at one point, or the path\
                leaves the singular tool axis with another azimuth)" \
                [Count $dwells {dwell swing}] $dwellTurn]
        }
        if {$clamps} {
            set max [format %g [dict get $machine inverse_time_max]]
            Say [format "fivax: %s written at the machine's largest inverse-time feed,\
                inverse_time_max %s: these blocks are short for their feed (G93 F = feed /\
                length, 1/min), so they run slower than programmed, the worst %.2f times; the\
                path is unchanged (raise inverse_time_max if the control takes a larger F)" \
                [Count $clamps {cutting block}] $max $slowdown]
        }
    }
    if {[info exists dryrun] && $dryrun} {
        Say "fivax: dry run of the written program: 0 events (spindle, rapids and bodies\
            against the stock, length compensation, modes, tool lengths, program end)"
    }
}

# ::replay::Count -- Returns "n noun", the noun with an s unless n is 1.
proc ::replay::Count {n noun} {
    expr {$n == 1 ? "$n $noun" : "$n ${noun}s"}
}

# ::replay::main --
#	Checks the command line, the machine file and the output path, posts
#	the file through the sink, and puts the output in place.
proc ::replay::main {argv} {
    variable R
    variable bufferSize
    Reset
    lassign [ParseArgs $argv] opts given clsf
    lassign [PostFiles [dict get $opts -post]] postFile defFile
    CheckInput $clsf
    CheckMachineFile $given
    set settings [PostSettings $postFile $defFile $given]
    # an NX post of its own (no fivax settings): no machine file, no log, no dry run
    set fivax [expr {[dict size $settings] > 0}]
    set machineFile [expr {$fivax ? [dict get $settings -machine] : ""}]
    set target ""
    if {[dict get $opts -o] ni {"" -}} {
        set target [CheckTarget -o [dict get $opts -o] $clsf $machineFile]
        # from here on a failed run removes the program of an earlier one
        if {[lindex $target 0] eq "file"} {set R(stale) [list [lindex $target 1]]}
    }
    if {$fivax} {
        set machine [CheckMachine $settings $defFile]
        if {[dict get $settings -log] ne ""} {
            CheckTarget -log [dict get $settings -log] $clsf $machineFile
        }
        Say "fivax: posting for machine [file normalize $machineFile]"
    } else {
        set machine {}
        Say "fivax: posting with the NX post $postFile"
    }
    set progress [expr {![dict get $opts -quiet] && [Terminal stderr]}]
    if {$progress} {::fivax::clsf::progress ::replay::Tick}
    set R(dryrun) [expr {$fivax && [dict get $settings -dryrun] eq "on"}]
    set R(start) [clock milliseconds]
    set R(last) $R(start)
    if {$clsf ne "-" && [file isfile $clsf]} {set R(size) [file size $clsf]}
    # the post's log beside a file target: a temporary name, kept only when
    # the run succeeds
    set log ""
    if {$fivax && [lindex $target 0] eq "file" && [dict get $settings -log] eq ""} {
        set log [LogFile [lindex $target 1] $clsf $machineFile]
        if {$log ne ""} {lappend R(stale) $log}
    }
    OpenTarget $target $log
    if {$log ne ""} {dict set given -log $R(tmp).log}
    set out [expr {[lindex $target 0] eq "file" ? [file normalize [dict get $opts -o]] : ""}]
    set R(sink) [chan create write ::replay::Sink]
    chan configure $R(sink) -translation lf -encoding utf-8 -buffering full \
        -buffersize $bufferSize
    try {
        set stats [Post $postFile $defFile $given $clsf $R(sink) $out \
            [expr {$fivax && [CheckProcess [dict get $opts -check-process] $clsf]}] \
            [expr {$fivax && $progress}]]
        if {[dict exists $stats limitViolations] && [dict get $stats limitViolations] > 0} {
            # A safety net: the checker refuses such a value when it is written.
            error "[dict get $stats limitViolations] values outside the machine's limits; no NC file written"
        }
        Finish
    } on error {msg} {
        if {$R(broken) ne ""} {
            Die "replay: the output was closed before the end of the program ($R(broken)); stopped"
        }
        Die $msg
    }
    ::fivax::clsf::progress ""
    ClearProgress
    if {![dict get $opts -quiet]} {Summary $stats $machine}
}

if {[info exists ::argv0] && [file normalize $::argv0] eq [file normalize [info script]]} {
    ::replay::main $argv
}
