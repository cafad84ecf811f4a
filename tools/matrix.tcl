# matrix.tcl --
#	The safety matrix: posts every CL file on every machine in every
#	dialect, TCP on and off, work planes auto and off (tools/replay.tcl,
#	whose post runs its own dry run), then reads each written program back
#	with tools/verify.tcl (forward kinematics against the CL path and the
#	machine dry run: spindle, rapids into the stock, tool, holder and
#	spindle nose, length compensation, program end, unreadable words).
#	(-verify off: the post's own dry run only, which reads the written text
#	with the verify reader too.)
#	A case passes when the program is posted and verified with no event,
#	or when replay refuses the job with one clean FILE:LINE message that
#	is no internal error and no dry-run event (a tool axis the machine
#	cannot reach, say). Prints one line per failed case and the counts;
#	exits 1 when a case fails.
#
#	tclsh tools/matrix.tcl ?options? ?file.cls ...?   (-help)

package require Tcl 8.6

set root [file dirname [file dirname [file normalize [info script]]]]
set auto_path [linsert $auto_path 0 [file join $root lib]]
package require fivax 0.1
foreach f {nctool.tcl corpus.tcl} {
    source [file join $root tools lib $f]
}

namespace eval ::matrixtool {
    variable Options {
        {-machines text {} "FILES" "machine files (default: every machines/*.tcl)"}
        {-controllers text {} "NAMES" "dialects (default: every controller of lib/dialect/)"}
        {-tcp text {0 1} "VALUES" "TCP settings"}
        {-workplane text {auto off} "VALUES" "work-plane settings"}
        {-tool-length {maybe real gt 0} 100 MM "tool length for CL files without one (replay -tool-length; empty: not given)"}
        {-default-rpm {maybe real gt 0} 10000 RPM "default_rpm of the machines that have none, for CL files without a spindle speed (empty: the machine files as they are)"}
        {-verify {enum on off} on WHEN "read each posted program back with tools/verify.tcl (forward kinematics against the CL, and its own dry run); off: the post's dry run of its own output only"}
        {-jobs {int min 1} 2 N "cases run at once"}
        {-dir text {} DIR "work directory for the programs (default: a temporary one, removed at the end)"}
        {-verbose bool 0 "" "print one line per case"}
        {-help bool 0 "" "print this help"}
    }
    # The block check's tolerances with -verify off, mm and deg (as
    # tools/verify.tcl's defaults).
    variable tolerances {0.01 0.05}
    # S: cases (to run), running (channel -> case), results, root, dir
    variable S
}

# ::matrixtool::DefaultFiles -- Returns tests/data/*.cls and the corpus files.
proc ::matrixtool::DefaultFiles {root} {
    set files [lsort [glob -nocomplain -directory [file join $root tests data] *.cls]]
    lappend files {*}[lsort [glob -nocomplain -directory [::fivax::corpusDir $root] *.cls]]
}

# ::matrixtool::NeedsMsys --
#	Returns 1 when the CL file is posted in its MSYS frame (-msys): it has
#	an MSYS record and its first tool axis points down (the NX five-axis
#	files: their MCS's Z is the machine's -Z); NX files whose first axis
#	points up are in the machine's frame as they are.
proc ::matrixtool::NeedsMsys {path} {
    set chan [::fivax::nctool open $path]
    set msys 0
    try {
        while {[gets $chan line] >= 0} {
            if {[regexp {^\s*MSYS\s*/} $line]} {set msys 1}
            set n {[-+]?[0-9.]+(?:[eE][-+]?\d+)?}
            if {[regexp "^\\s*GOTO\\s*/(?:\\s*$n\\s*,){5}\\s*($n)" $line -> k]} {
                return [expr {$msys && $k < 0}]
            }
        }
    } finally {
        close $chan
    }
    return 0
}

# ::matrixtool::WithRpm --
#	Returns the machine file path, or when the machine has no default_rpm
#	a copy of it in dir with default_rpm rpm (the speed of CL files that
#	give none).
proc ::matrixtool::WithRpm {path rpm dir} {
    if {[dict get [::fivax::machine load $path] default_rpm] ne ""} {return $path}
    set chan [::fivax::nctool open $path]
    set text [read $chan]
    close $chan
    set copy [file join $dir [file tail $path]]
    ::fivax::nctool writeLines $copy [list $text "default_rpm $rpm"]
}

# ::matrixtool::Cases --
#	Returns the cases: dicts of cl machine controller tcp workplane msys
#	and name (the program's file name).
proc ::matrixtool::Cases {opts files machines} {
    set cases {}
    foreach cl $files {
        set msys [NeedsMsys $cl]
        foreach m $machines {
            foreach c [dict get $opts -controllers] {
                foreach t [dict get $opts -tcp] {
                    foreach w [dict get $opts -workplane] {
                        set name [file rootname [file tail $cl]]-[file rootname [file tail $m]]-$c-tcp$t-$w
                        lappend cases [dict create cl $cl machine $m controller $c tcp $t \
                            workplane $w msys $msys name $name]
                    }
                }
            }
        }
    }
    return $cases
}

# ::matrixtool::ReplayArgs -- Returns replay's command line for case (program to nc).
proc ::matrixtool::ReplayArgs {opts case nc} {
    variable S
    # (-verify off: the post's summary tells its own block check)
    set args [list [info nameofexecutable] [file join $S(root) tools replay.tcl] \
        {*}[expr {[dict get $opts -verify] eq "on" ? "-quiet" : ""}] -machine [dict get $case machine] -controller [dict get $case controller] \
        -tcp [dict get $case tcp] -workplane [dict get $case workplane] \
        -o $nc]
    if {[dict get $opts -tool-length] ne ""} {lappend args -tool-length [dict get $opts -tool-length]}
    if {[dict get $case msys]} {lappend args -msys}
    lappend args [dict get $case cl]
}

# ::matrixtool::VerifyArgs -- Returns tools/verify.tcl's command line for case's program nc.
proc ::matrixtool::VerifyArgs {opts case nc} {
    variable S
    set args [list [info nameofexecutable] [file join $S(root) tools verify.tcl] -quiet \
        -machine [dict get $case machine] -controller [dict get $case controller] \
        -cl [dict get $case cl]]
    if {[dict get $case msys]} {lappend args -msys}
    lappend args $nc
}

# ::matrixtool::Start -- Starts the next case's replay when a slot is free.
proc ::matrixtool::Start {opts} {
    variable S
    while {[dict size $S(running)] < [dict get $opts -jobs] && [llength $S(cases)]} {
        set S(cases) [lassign $S(cases) case]
        set nc [file join $S(dir) [dict get $case name].nc]
        dict set case nc $nc
        Spawn $opts $case replay [ReplayArgs $opts $case $nc]
    }
}

# ::matrixtool::Spawn -- Runs command (a list) for case's step, collecting its output.
proc ::matrixtool::Spawn {opts case step command} {
    variable S
    set chan [open |[concat $command [list 2>@1]] r]
    chan configure $chan -blocking 0
    dict set S(running) $chan [dict create case $case step $step out ""]
    chan event $chan readable [list ::matrixtool::Readable $opts $chan]
}

# ::matrixtool::Readable -- Collects output of chan; at its end, the case's next step.
proc ::matrixtool::Readable {opts chan} {
    variable S
    set text [read $chan]
    dict set S(running) $chan out [dict get $S(running) $chan out]$text
    if {![chan eof $chan]} return
    chan configure $chan -blocking 1
    set code [catch {close $chan}]
    set job [dict get $S(running) $chan]
    dict unset S(running) $chan
    set case [dict get $job case]
    set out [string trim [dict get $job out]]
    if {[dict get $job step] eq "replay"} {
        if {$code} {
            Result $opts $case [Refusal $out] $out
        } elseif {[dict get $opts -verify] eq "off"} {
            Result $opts $case [PostChecks $out] $out
        } else {
            Spawn $opts $case verify [VerifyArgs $opts $case [dict get $case nc]]
        }
    } else {
        Result $opts $case [expr {$code ? "failed" : "passed"}] $out
    }
    Start $opts
    if {![dict size $S(running)]} {set S(done) 1}
}

# ::matrixtool::Refusal --
#	Returns how a replay that exited 1 with output out ends: refused (one
#	clean FILE:LINE message, no dry-run event, no internal error) or failed.
proc ::matrixtool::Refusal {out} {
    set last [lindex [split $out \n] end]
    if {[regexp {internal error|dry run|\mevents?\M} $out]} {return failed}
    # a CL record's FILE:LINE, or the machine file's name for a setting
    # the machine cannot take (TCP on a control without a TCP of its own and no tcp_codes)
    if {[regexp {^\S+:\d+: |^\S+\.tcl: } $last]} {return refused}
    return failed
}

# ::matrixtool::PostChecks --
#	Returns passed when the summary out of a replay that exited 0 reports
#	its block check (forward kinematics of the written blocks at their
#	ends and quarter points) within verify's tolerances and no rotary
#	value outside its limits, else failed.
proc ::matrixtool::PostChecks {out} {
    variable tolerances
    lassign $tolerances mm deg
    set found 0
    foreach {- dist ang} [regexp -all -inline {max deviation ([0-9.]+) mm, ([0-9.]+) deg} $out] {
        if {$dist > $mm || $ang > $deg} {return failed}
        incr found
    }
    if {$found != 2 || ![regexp {; 0 rotary values outside limits} $out]} {return failed}
    return passed
}

# ::matrixtool::Result -- Records case's result (passed, refused, failed) with output out.
proc ::matrixtool::Result {opts case result out} {
    variable S
    dict lappend S(results) $result [list $case $out]
    catch {file delete [dict get $case nc]}
    if {[dict get $opts -verbose] || $result eq "failed"} {
        set text [expr {$result eq "passed" ? "" : ": [lindex [split $out \n] end]"}]
        if {$result eq "failed"} {set text ":\n    [join [lrange [split $out \n] 0 11] "\n    "]"}
        puts "$result [dict get $case name]$text"
        flush stdout
    }
}

# ::matrixtool::main -- Runs the matrix of argv; exits 1 when a case fails.
proc ::matrixtool::main {argv} {
    variable S
    variable Options
    lassign [::fivax::nctool args $Options $argv matrix \
        "tclsh tools/matrix.tcl ?options? ?file.cls ...?" \
        "Posts CL files on every machine and dialect and verifies each program (dry run included)."] opts files
    set S(root) $::root
    if {![llength $files]} {set files [DefaultFiles $S(root)]}
    set machines [dict get $opts -machines]
    if {$machines eq ""} {
        set machines [lsort [glob -directory [file join $S(root) machines] *.tcl]]
    }
    if {[dict get $opts -controllers] eq ""} {dict set opts -controllers [::fivax::dialect names]}
    set S(dir) [dict get $opts -dir]
    set temporary [expr {$S(dir) eq ""}]
    if {$temporary} {
        set S(dir) [file join [expr {[info exists ::env(TMPDIR)] ? $::env(TMPDIR) : "/tmp"}] \
            fivax-matrix-[pid]]
    }
    file mkdir $S(dir)
    if {[dict get $opts -default-rpm] ne ""} {
        set machines [lmap m $machines {WithRpm $m [dict get $opts -default-rpm] $S(dir)}]
    }
    set S(cases) [Cases $opts $files $machines]
    set total [llength $S(cases)]
    set S(running) {}
    set S(results) {passed {} refused {} failed {}}
    set start [clock milliseconds]
    # an error in a channel handler is a bug of this tool: stop at once
    interp bgerror {} [list apply {{msg opts} {puts stderr [dict get $opts -errorinfo]; exit 2}}]
    try {
        Start $opts
        if {[dict size $S(running)]} {vwait ::matrixtool::S(done)}
    } finally {
        if {$temporary} {file delete -force $S(dir)}
    }
    set reasons {}
    foreach item [dict get $S(results) refused] {
        lassign $item case out
        set why [regsub {^\S+:\d+: } [lindex [split $out \n] end] ""]
        regsub -all {[-+]?\d+(\.\d+)?} $why N why
        dict incr reasons $why
    }
    dict for {why n} $reasons {puts "refused $n: $why"}
    puts [format "matrix: %d cases in %.0f s: %d passed, %d refused, %d failed" $total \
        [expr {([clock milliseconds] - $start) / 1000.0}] [llength [dict get $S(results) passed]] \
        [llength [dict get $S(results) refused]] [llength [dict get $S(results) failed]]]
    exit [expr {[llength [dict get $S(results) failed]] > 0}]
}

::matrixtool::main $argv
