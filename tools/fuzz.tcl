# fuzz.tcl --
#	Fuzzes the command line end to end: mutates real CL files (the corpus,
#	../shared/data/cl, and tests/data/*.cls), machine files and command
#	lines, runs tools/replay.tcl on each case in a process of its own (with
#	a time limit, several at once; a quarter of the cases with the block
#	check in a second process, -check-process on) and checks how each run
#	ends:
#
#	  posted   exit 0; every number in the NC text finite and inside the
#	           machine's travel and rotary limits; one program of the
#	           controller's dialect (one header, one end); no value a
#	           control refuses (F0, S0, negative S T H, a number of 13
#	           digits or more); a DELAY written as a dwell; every inserted
#	           unknown record word warned about;
#	           nothing but the NC file and its log in the case directory
#	  refused  exit 1 and one line on stderr: "FILE:LINE: message" (CL
#	           problems), "replay: ..." (command line, output) or
#	           "MACHINEFILE: ..." (machine file), or the dry run's
#	           "FILE:LINE: the dry run ... found N events" and its events
#	           "NC:LINE: kind: what"; no output file, no file left behind
#	and never: a Tcl stack trace, an "internal error", a time-out, another
#	exit status, an evaluated payload (a canary file that must not appear),
#	NaN or Inf in the output, a partial or stray file. Any such failure
#	makes the exit status 1.
#
#	tclsh tools/fuzz.tcl ?-cases 10000? ?-seed 1? ?-jobs 2? ?-timeout 10? ...
#	(-help lists the options). The last line reads
#	"fuzz: N cases ... failed=F" (see Report).

package require Tcl 8.6

namespace eval ::fuzz {
    variable root [file dirname [file dirname [file normalize [info script]]]]
    variable Options {
        {-cases {int min 1} 10000 N "cases to run"}
        {-seed {int min 0 max 2147483647} 1 N "random seed: the same seed makes the same cases"}
        {-jobs {int min 1 max 64} 2 N "cases run at once"}
        {-timeout {real gt 0} 10 SEC "time limit of one case"}
        {-lines {int min 5 max 100000} 80 N "CL lines of an excerpt at most (plus its header)"}
        {-corpus text {} DIR "real CL files (default: FIVAX_CORPUS or ../shared/data/cl)"}
        {-dir text {} DIR "work directory (default: a new one under the system's temp directory); removed at the end"}
        {-keep text {} DIR "copy the failing cases into DIR"}
        {-verbose bool 0 "" "print one line per case"}
        {-help bool 0 "" "print this help"}
    }

    # Words a CL record may carry that are post handlers or MOM commands
    # (a record must never reach them), and harmless unknown ones.
    variable handlerWords {
        END_OF_PROGRAM START_OF_PROGRAM TOOL_CHANGE FIRST_TOOL SPINDLE_OFF
        SPINDLE_RPM COOLANT_ON COOLANT_OFF END_OF_PATH START_OF_PATH
        LINEAR_MOVE RAPID_MOVE CIRCULAR_MOVE INITIAL_MOVE FIRST_MOVE GOHOME_MOVE
        OUTPUT_TEXT OUTPUT_LITERAL ABORT ABORT_EVENT FORCE SUPPRESS DO_TEMPLATE
        SET_SEQ_OFF RESET_SEQUENCE PPRINT_ INSERT_ DELAY_ OPSTOP_
    }
    variable plainWords {exit ::exit rename source eval subst uplevel interp after vwait
        EXIT/0 SOURCE/x RENAME/exit,x SET/MODE,X NURBS/1 FOO_BAR}
    # Numbers put in place of a CL number.
    variable badNumbers {
        nan NaN -nan inf -inf Inf Infinity 1e308 -1e308 1.7976931348623157e308 -0 -0.0
        "" " " 1e-320 0x10 1e400 -1e400 017 +5 1.2.3 1e -- 1,5 .e3 ++1
        1e14 1e50 1e101 -3.55e302 1.1e39 99999999999999999999
    }
    variable bigNumbers {1e14 1e50 1e101 -3.55e302 1.1e39 99999999999999999999}
    # Records inserted as they are: values no control accepts, edge cases.
    variable valueRecords {
        SPINDL/RPM,1e300,CLW SPINDL/RPM,-5,CLW SPINDL/RPM,0,CLW SPINDL/OFF
        LOAD/TOOL,-5 LOAD/TOOL,1,ADJUST,-5 LOAD/TOOL,99999999 SELECT/TOOL,-3
        FEDRAT/0 FEDRAT/MMPM,1e-9 FEDRAT/-100 FEDRAT/1e300 FEDRAT/MMPR,0.1
        DELAY/2 DELAY/-1 DELAY/1e300 DELAY/REV,3 DELAY/0
        CUTCOM/LEFT,-1 TLDATA/MILL,10,0,-50,0,0 TLDATA/MILL,10,0,1e300,0,0
        TLDATA/MILL,10,0,0,0,0 CIRCLE/1.1e39,0,0,0,0,1,5 CIRCLE/0,0,0,0,0,1,1e300
        MSYS/0,0,0,1,0,0,1,0,0 TLAXIS/0,0,0 TLAXIS/0,0,-1 UNITS/INCHES
        CYCLE/DRILL,RAPTO,2,FEDTO,-5,MMPM,100 CYCLE/OFF COOLNT/ON COOLNT/OFF
        END-OF-PATH FINI STOP OPSTOP RAPID {PPRINT/ } {PPRINT/(a) %} INSERT/G4P1
        {TOOL PATH/,TOOL,} {TOOL PATH/X,TOOL,[y]} GOHOME/0,0,100 FROM/1e300,0,0
    }
    # Command-line variants: refused ones (a bad value, an unknown option)
    # and valid ones.
    variable badArgs {
        {-tol 1e-300} {-tol -1} {-tol abc} {-tol nan} {-atol 1e-300} {-arc-tol 1e-300}
        {-arc-tol 0} {-table-offset {1e308 0 0}} {-table-offset {1 2}}
        {-table-offset {1 2 [exec touch CANARY]}} {-msys banana} {-window 1}
        {-window 1000000000} {-clearance 1e308} {-clearance -1} {-weights {0 1}}
        {-weights 1} {-cone -1} {-swing inf} {-controller x} {-feed x} {-rotary x}
        {-on-limit x} {-bogus} {-x 1} {--tol 1} {-TOL 1} {-machine} {-o}
        {-o .} {-o nodir/x.nc} {-o in.cls} {-o m.tcl} {-machine nowhere.tcl}
        {-machine .} {-machine /dev/null} {-log .} {-log nodir/x.log} {-log in.cls}
        {-tcp x} {-insert x}
    }
    variable goodArgs {
        {-feed direct} {-feed dpm} {-rotary greedy} {-msys} {-tol 0} {-atol 0}
        {-on-limit error} {-tol 0.001} {-clearance 0}
        {-window 2} {-weights {1 3}} {-table-offset {10 -20 30}} {-arc-tol 0.5}
        {-tcp 1} {-log run.log}
        {-insert verbatim}
    }
    variable payloads {
        {[exec touch CANARY]} {[open CANARY w]} {[file mkdir CANARY]} {$::env(HOME)}
        {[set ::x 1]} {`touch CANARY`} {$(touch CANARY)} {;exec touch CANARY}
        {\[exec touch CANARY\]} "\[exec touch CANARY\]\n" {{*}[exec touch CANARY]}
        {[source CANARY]} {${CANARY}} {[::exit 3]} {[exit 3]}
    }
    # The failure classes, in the order of the report.
    variable classNames {stacktrace timeout exit canary stray partial nonfinite limits noplace
        internal lifecycle values dwell dispatch}
    # Refusals whose message names no cause the user can act on.
    variable badMessages {normalise a zero vector|wrong # args|no such variable|invalid command name}
    variable R
    array set R {}
}
set auto_path [linsert $auto_path 0 [file join $::fuzz::root lib]]
package require fivax 0.1
source [file join $::fuzz::root tools lib corpus.tcl]

# --- random choices ------------------------------------------------------

# ::fuzz::Rand -- Returns a random integer in [0, n).
proc ::fuzz::Rand {n} {
    expr {int(rand() * $n)}
}

# ::fuzz::Pick -- Returns a random element of list.
proc ::fuzz::Pick {list} {
    lindex $list [Rand [llength $list]]
}

# ::fuzz::Chance -- Returns 1 with probability p.
proc ::fuzz::Chance {p} {
    expr {rand() < $p}
}

# --- sources -------------------------------------------------------------

# ::fuzz::ReadBytes -- Returns the bytes of file path.
proc ::fuzz::ReadBytes {path} {
    set f [open $path rb]
    try {read $f} finally {close $f}
}

# ::fuzz::WriteBytes -- Writes bytes to file path.
proc ::fuzz::WriteBytes {path bytes} {
    set f [open $path wb]
    try {puts -nonewline $f $bytes} finally {close $f}
}

# ::fuzz::Sources --
#	Returns {name lines ...} of the CL files: tests/data/*.cls and, when
#	the corpus directory exists, its *.cls (else a printed reason).
proc ::fuzz::Sources {corpus} {
    variable root
    set files [lsort [glob -nocomplain -directory [file join $root tests data] *.cls]]
    if {[file isdirectory $corpus]} {
        lappend files {*}[lsort [glob -nocomplain -directory $corpus *.cls]]
    } else {
        puts "fuzz: corpus skipped: $corpus is not a directory (set FIVAX_CORPUS to the real CL files)"
    }
    set out {}
    foreach f $files {
        lappend out [file tail $f] [split [string map {\r\n \n} [ReadBytes $f]] \n]
    }
    return $out
}

# ::fuzz::Excerpt --
#	Returns lines cut down to its header (the lines before the first GOTO,
#	at most 30), a FEDRAT, and a random window of at most most lines.
proc ::fuzz::Excerpt {lines most} {
    set first [lsearch -regexp $lines {^\s*GOTO\s*/}]
    if {$first < 0 || $first > 30} {set first [expr {min(30, [llength $lines])}]}
    set body [lrange $lines $first end]
    if {[llength $body] > $most} {
        set start [Rand [expr {[llength $body] - $most + 1}]]
        set body [lrange $body $start [expr {$start + 4 + [Rand [expr {$most - 4}]]}]]
    }
    concat [lrange $lines 0 [expr {$first - 1}]] [list FEDRAT/MMPM,1000] $body
}

# --- CL mutations (each: lines canary -> {lines tag}; canary is the
# stand-in that MakeCase replaces by the canary file's path) ----------------

# ::fuzz::Line -- Returns a random line index of lines (0 when empty).
proc ::fuzz::Line {lines} {
    expr {[llength $lines] ? [Rand [llength $lines]] : 0}
}

# ::fuzz::Insert -- Returns lines with text inserted as a line at a random place.
proc ::fuzz::Insert {lines text} {
    linsert $lines [Rand [expr {[llength $lines] + 1}]] $text
}

# ::fuzz::Payload -- Returns a random payload aimed at the canary file.
proc ::fuzz::Payload {canary} {
    variable payloads
    string map [list CANARY $canary] [Pick $payloads]
}

# ::fuzz::M_drop -- Drops a random line.
proc ::fuzz::M_drop {lines canary} {
    list [lreplace $lines [set i [Line $lines]] $i] drop
}
# ::fuzz::M_dup -- Duplicates a random line.
proc ::fuzz::M_dup {lines canary} {
    set i [Line $lines]
    list [linsert $lines $i [lindex $lines $i]] dup
}
# ::fuzz::M_swap -- Swaps two random lines.
proc ::fuzz::M_swap {lines canary} {
    set i [Line $lines]
    set j [Line $lines]
    set a [lindex $lines $i]
    lset lines $i [lindex $lines $j]
    lset lines $j $a
    list $lines swap
}
# ::fuzz::M_truncfile -- Cuts the file at a random byte.
proc ::fuzz::M_truncfile {lines canary} {
    set text [join $lines \n]
    list [split [string range $text 0 [Rand [string length $text]]] \n] truncfile
}
# ::fuzz::M_truncline -- Cuts a random line at a random byte.
proc ::fuzz::M_truncline {lines canary} {
    set i [Line $lines]
    set l [lindex $lines $i]
    list [lreplace $lines $i $i [string range $l 0 [Rand [string length $l]]]] truncline
}
# ::fuzz::M_flip -- Flips one bit of a random byte.
proc ::fuzz::M_flip {lines canary} {
    set i [Line $lines]
    set l [lindex $lines $i]
    if {$l eq ""} {return [list $lines flip]}
    set p [Rand [string length $l]]
    scan [string index $l $p] %c c
    set c [expr {($c ^ (1 << [Rand 8])) & 255}]
    list [lreplace $lines $i $i [string replace $l $p $p [format %c $c]]] flip
}
# ::fuzz::M_special -- Inserts a Tcl special character ([ ] $ { } \ ; ") into a random line.
proc ::fuzz::M_special {lines canary} {
    set ch [Pick [list \[ \] \$ \{ \} \\ \; \" "\$\$" "\{\}" "\[\]" "\\\n"]]
    set i [Line $lines]
    set l [lindex $lines $i]
    set p [Rand [expr {[string length $l] + 1}]]
    list [lreplace $lines $i $i [string replace $l $p -1 $ch]] special
}
# ::fuzz::M_nul -- Inserts NUL or another control character into a random line.
proc ::fuzz::M_nul {lines canary} {
    set i [Line $lines]
    set l [lindex $lines $i]
    set p [Rand [expr {[string length $l] + 1}]]
    list [lreplace $lines $i $i [string replace $l $p -1 [Pick {"\x00" "\x01" "\x1b" "\x7f" "\x0c" "\x1a"}]]] nul
}
# ::fuzz::M_utf8 -- Inserts bytes that are not UTF-8 into a random line.
proc ::fuzz::M_utf8 {lines canary} {
    set bad [Pick {"\xff" "\xc3" "\xed\xa0\x80" "\xc0\x80" "\xfe\xff" "\xe2\x82"}]
    set i [Line $lines]
    set l [lindex $lines $i]
    set p [Rand [expr {[string length $l] + 1}]]
    list [lreplace $lines $i $i [string replace $l $p -1 $bad]] utf8
}
# ::fuzz::M_goodutf8 -- Inserts a PPRINT with valid UTF-8 text (must post).
proc ::fuzz::M_goodutf8 {lines canary} {
    list [Insert $lines "PPRINT/[Pick {"\xc3\xa9t\xc3\xa9" "90\xc2\xb0" "\xe2\x82\xac5" "\xf0\x9f\x94\xa7"}]"] goodutf8
}
# ::fuzz::M_bom -- Puts a byte order mark at the start of the file or of a line.
proc ::fuzz::M_bom {lines canary} {
    if {[Chance 0.5]} {
        lset lines 0 "\xef\xbb\xbf[lindex $lines 0]"
        return [list $lines bom]
    }
    set i [Line $lines]
    list [lreplace $lines $i $i "\xef\xbb\xbf[lindex $lines $i]"] bom-mid
}
# ::fuzz::M_crlf -- Ends the lines with CRLF, or with CR alone.
proc ::fuzz::M_crlf {lines canary} {
    set sep [Pick {"\r" "\r\r"}]
    if {[Chance 0.3]} {
        # CR-only line ends (old Mac files)
        return [list [list [join $lines "\r"]] cr-only]
    }
    list [lmap l $lines {string cat $l "\r"}] crlf
}
# ::fuzz::M_longline -- Inserts a line of 65537 to 100000 characters.
proc ::fuzz::M_longline {lines canary} {
    set n [expr {[Chance 0.5] ? 100000 : 65537 + [Rand 1000]}]
    set text [Pick [list [string repeat x $n] "GOTO/[string repeat 1 $n],1,1" \
        "PPRINT/[string repeat {[exec touch CANARY]} [expr {$n / 20}]]" \
        [string repeat "1," [expr {$n / 2}]]]]
    list [Insert $lines [string map [list CANARY $canary] $text]] longline
}
# ::fuzz::M_chain -- Inserts a GOTO continued by $ over 100 to 70000 lines.
proc ::fuzz::M_chain {lines canary} {
    set n [Pick {100 5000 40000 70000}]
    set unit [Pick [list "\$" " ,\$" "1,\$" "\$\$ c \$"]]
    set chain "GOTO/1,\$\n[string repeat "$unit\n" $n]2,3"
    list [Insert $lines $chain] chain-$n
}
# ::fuzz::M_number -- Replaces a number by nan, inf, 1e308, -0, 400 digits, an empty field, ...
proc ::fuzz::M_number {lines canary} {
    variable badNumbers
    set re {[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?}
    set idx [lsearch -all -regexp $lines "/.*$re"]
    if {![llength $idx]} {return [list $lines number-none]}
    set i [Pick $idx]
    set l [lindex $lines $i]
    set slash [string first / $l]
    set spots [regexp -all -inline -indices -start $slash $re $l]
    set spot [Pick $spots]
    set v [Pick $badNumbers]
    lassign $spot a b
    list [lreplace $lines $i $i [string replace $l $a $b $v]] "number:$v"
}
# ::fuzz::M_axis -- Gives a GOTO a zero, non-unit, downward or flipping tool axis.
proc ::fuzz::M_axis {lines canary} {
    set idx [lsearch -all -regexp $lines {^\s*GOTO\s*/}]
    if {![llength $idx]} {return [list $lines axis-none]}
    set i [Pick $idx]
    set toks [split [lindex [split [lindex $lines $i] /] 1] ,]
    lassign $toks x y z
    set axis [Pick {{0 0 0} {2 0 0} {0.5 0 0} {1e-8 0 1} {0 0 -1} {-1 0 0} {0 0.7071 -0.7071} {1 0 0}}]
    set new "GOTO/$x,$y,$z,[join $axis ,]"
    set lines [lreplace $lines $i $i $new]
    if {$axis eq {-1 0 0} || [Chance 0.3]} {
        # the opposite axis next: a 180 degree flip
        lassign $axis ai aj ak
        set flip [lmap c $axis {expr {-$c}}]
        set lines [linsert $lines [expr {$i + 1}] "GOTO/$x,$y,$z,[join $flip ,]"]
        return [list $lines "axis:[join $axis ,]+flip"]
    }
    list $lines "axis:[join $axis ,]"
}
# ::fuzz::M_bigcoord -- Inserts a GOTO with a coordinate from 1e14 to 1e302 after an axis change.
proc ::fuzz::M_bigcoord {lines canary} {
    variable bigNumbers
    set idx [lsearch -all -regexp $lines {^\s*GOTO\s*/}]
    if {![llength $idx]} {return [list $lines bigcoord-none]}
    set i [Pick $idx]
    set v [Pick $bigNumbers]
    set lines [linsert $lines $i "GOTO/0,0,$v,0,0.6,0.8" "GOTO/1,2,3,0,0,1"]
    list $lines "bigcoord:$v"
}
# ::fuzz::M_word -- Inserts a record word that names a post handler or a Tcl command.
proc ::fuzz::M_word {lines canary} {
    variable handlerWords
    variable plainWords
    if {[Chance 0.6]} {
        set w [Pick $handlerWords]
        set text [Pick [list $w $w/1 "$w/[Payload $canary]"]]
        return [list [Insert $lines $text] "word:$w"]
    }
    set w [Pick $plainWords]
    list [Insert $lines $w] "plainword:$w"
}
# ::fuzz::M_payload -- Inserts a record carrying a Tcl or shell payload aimed at the canary.
proc ::fuzz::M_payload {lines canary} {
    set p [Payload $canary]
    set text [Pick [list $p PPRINT/$p INSERT/$p PARTNO/$p "TOOL PATH/$p,TOOL,$p" \
        "GOTO/$p,1,1" "FEDRAT/$p" "MSYS/$p" "$p/$p" "PPRINT $p" "LOAD/TOOL,$p" \
        "SPINDL/RPM,$p,CLW" "CYCLE/$p"]]
    list [Insert $lines $text] payload
}
# ::fuzz::M_value -- Inserts a record with a value no control accepts or an edge case.
proc ::fuzz::M_value {lines canary} {
    variable valueRecords
    set r [Pick $valueRecords]
    list [Insert $lines $r] "value:$r"
}
# ::fuzz::M_empty -- Makes the file empty or comments only.
proc ::fuzz::M_empty {lines canary} {
    list [Pick [list {} {{$$ only a comment}} {{} {} {}} {PAINT/PATH}]] empty
}

# The CL mutations, with weights.
namespace eval ::fuzz {
    variable mutations {
        drop 4 dup 4 swap 3 truncfile 3 truncline 3 flip 5 special 5 nul 2 utf8 2
        goodutf8 1 bom 1 crlf 2 longline 1 chain 1 number 8 axis 4 bigcoord 1
        word 4 payload 5 value 6 empty 1
    }
}

# ::fuzz::Mutation -- Returns the name of a random CL mutation (by weight).
proc ::fuzz::Mutation {} {
    variable mutations
    set total 0
    foreach {name w} $mutations {incr total $w}
    set r [Rand $total]
    foreach {name w} $mutations {
        if {[incr r -$w] < 0} {return $name}
    }
}

# --- machine and command-line mutations -----------------------------------

# ::fuzz::MutateMachine --
#	Returns {text tag}: the machine file text changed by one mutation.
proc ::fuzz::MutateMachine {text canary} {
    set kind [Pick {limits99999 limits3600 dropkey badnum zerodir minmax unknownkey
        travel badtravel output payload}]
    switch -- $kind {
        limits99999 - limits3600 {
            set v [string range $kind 6 end]
            set text [regsub -all {min\s+-?[0-9.]+} $text "min -$v"]
            set text [regsub -all {max\s+-?[0-9.]+} $text "max $v"]
            set text [regsub -all {continuous 1} $text "continuous 0 min -$v max $v"]
        }
        dropkey {
            set key [Pick {name axes sense side direction min travel}]
            set text [regsub "\\m$key\\M\\s+(\\{\[^\{\}\]*\\}|\\S+)" $text ""]
        }
        badnum {
            set v [Pick [list abc nan 1e308 Inf 1e400 "\[exec touch $canary\]" 0x10 ""]]
            set key [Pick {pivot y_H alpha min max tool_length clearance}]
            set text [regsub "\\m$key\\M\\s+\\S+" $text "$key [list $v]"]
        }
        zerodir {
            if {![regsub {direction\s+\{[^\}]*\}} $text {direction {0 0 0}} text]} {
                append text "\nalpha 0\n"
            }
        }
        minmax {
            set text [regsub {min\s+(-?[0-9.]+)\s+max\s+(-?[0-9.]+)} $text {min \2 max \1}]
        }
        unknownkey {
            set text [Pick [list "$text\npivott 3\n" [regsub {sense} $text {speed 3 sense}] "$text\nexec touch\n"]]
        }
        travel {
            set text [regsub {travel\s+\{.*?\}\}} $text [Pick {
                "travel {X {-10 10} Y {-10 10} Z {-10 10}}" "travel {Z {0 1e5}}"
                "travel {}" "travel {X {-1e5 1e5}}"}]]
        }
        badtravel {
            set text [regsub {travel\s+\{.*?\}\}} $text [Pick {
                "travel {Z {5 -5}}" "travel {W {0 1}}" "travel {Z {a b}}" "travel {Z}"
                "travel {Z {1e308 1e309}}" "travel {X {0 1} X {0 2}}" "travel \{"}]]
        }
        output {
            set text "$text\noutput [list [Pick {{decimals abc} {program -1} {decimals 12} {bogus 1} {angle_decimals 0}}]]\n"
        }
        payload {
            set text "$text\ndescription \[exec touch $canary\]\n"
        }
    }
    list $text machine:$kind
}

# ::fuzz::Args -- Returns {args tag}: a random command-line variant.
proc ::fuzz::Args {canary} {
    variable badArgs
    variable goodArgs
    if {[Chance 0.5]} {
        set a [Pick $badArgs]
        return [list [string map [list CANARY $canary] $a] "args:[join $a { }]"]
    }
    set a [Pick $goodArgs]
    list $a "args:[join $a { }]"
}

# --- cases ---------------------------------------------------------------

# ::fuzz::MakeCase --
#	Writes case i's files (seeded by seed and i) into its directory and
#	returns the case dict: id dir cl mode args machine tags canary cmd.
proc ::fuzz::MakeCase {i seed sources machines most work} {
    variable root
    expr {srand(($seed * 1000003 + $i) % 2147483647)}
    set dir [file join $work c$i]
    file mkdir $dir
    set canary [file join $dir CANARY]
    # The mutations aim at a stand-in of fixed length, the canary's path
    # put in its place when the files are written: the random draws that
    # depend on a text's length (a cut, a flipped byte) then make the same
    # case whatever the work directory's name.
    set token @CANARY@
    set aim [list $token $canary]
    lassign [lrange $sources [expr {2 * [Rand [expr {[llength $sources] / 2}]]}] end] name lines
    set lines [Excerpt $lines $most]
    set tags [list src:$name]
    set n [expr {[Chance 0.05] ? 0 : [Pick {1 1 1 1 1 1 2 2 2 3}]}]
    for {set k 0} {$k < $n} {incr k} {
        lassign [M_[Mutation] $lines $token] lines tag
        lappend tags $tag
    }
    WriteBytes [file join $dir in.cls] [string map $aim [join $lines \n]]\n
    set machine [lindex $machines [expr {$i % [llength $machines]}]]
    lappend tags machine:[file rootname [file tail $machine]]
    if {[Chance 0.08]} {
        lassign [MutateMachine [ReadBytes $machine] $token] text tag
        WriteBytes [file join $dir m.tcl] [string map $aim $text]
        set machine m.tcl
        lappend tags $tag
    }
    set args {}
    if {[Chance 0.08]} {
        lassign [Args $token] args tag
        set args [lmap a $args {string map $aim $a}]
        lappend tags $tag
    }
    if {"-controller" ni $args && [Chance 0.2]} {
        set controller [Pick [lsearch -all -inline -not -exact [fivax::dialect names] [fivax::dialect default]]]
        set args [linsert $args 0 -controller $controller]
        lappend tags controller:$controller
    }
    if {[Chance 0.25]} {
        # the block check in its own process (replay -check-process)
        set args [linsert $args 0 -check-process on]
        lappend tags check:process
    }
    set mode [Pick {file file file file file file file stdout stdout stdin}]
    if {"-o" in $args} {set mode custom}
    set cmd [list [info nameofexecutable] [file join $root tools replay.tcl] -quiet \
        -machine $machine {*}$args]
    switch -- $mode {
        file {lappend cmd -o out.nc in.cls}
        stdout - custom {lappend cmd in.cls}
        stdin {lappend cmd - < in.cls}
    }
    dict create id $i dir $dir mode $mode tags $tags canary $canary cmd $cmd \
        machine [expr {$machine eq "m.tcl" ? [file join $dir m.tcl] : $machine}] \
        err [file join $work c$i.err]
}

# --- running -------------------------------------------------------------

# ::fuzz::Launch -- Starts case c (a dict) in its directory, with its time limit.
proc ::fuzz::Launch {c} {
    variable R
    set id [dict get $c id]
    set here [pwd]
    cd [dict get $c dir]
    try {
        set chan [open |[concat [dict get $c cmd] [list 2> [dict get $c err]]] r]
    } finally {
        cd $here
    }
    chan configure $chan -blocking 0 -translation binary
    dict set c chan $chan
    dict set c out ""
    dict set c timedOut 0
    dict set c start [clock milliseconds]
    set R(case,$id) $c
    set R(timer,$id) [after [expr {int($R(timeout) * 1000)}] [list ::fuzz::Kill $id]]
    chan event $chan readable [list ::fuzz::Readable $id]
}

# ::fuzz::Kill -- Ends case id's process (time-out).
proc ::fuzz::Kill {id} {
    variable R
    dict set R(case,$id) timedOut 1
    catch {exec kill -KILL {*}[pid [dict get $R(case,$id) chan]]}
}

# ::fuzz::Readable -- Collects case id's standard output; at its end, finishes the case.
proc ::fuzz::Readable {id} {
    variable R
    set chan [dict get $R(case,$id) chan]
    dict append R(case,$id) out [read $chan]
    if {![eof $chan]} return
    after cancel $R(timer,$id)
    chan configure $chan -blocking 1
    set status 0
    if {[catch {close $chan} msg opts]} {
        set ec [dict get $opts -errorcode]
        switch -- [lindex $ec 0] {
            CHILDSTATUS {set status [lindex $ec 2]}
            CHILDKILLED {set status "killed by [lindex $ec 2]"}
            default {set status "close: $msg"}
        }
    }
    dict set R(case,$id) status $status
    dict set R(case,$id) ms [expr {[clock milliseconds] - [dict get $R(case,$id) start]}]
    # A killed run's guard removes its temporary file just after: wait.
    after [expr {[dict get $R(case,$id) timedOut] ? 300 : 0}] [list ::fuzz::Finish $id]
}

# ::fuzz::Finish -- Classifies case id, records the result, starts the next case.
proc ::fuzz::Finish {id} {
    variable R
    set c $R(case,$id)
    unset R(case,$id) R(timer,$id)
    set classes [Classify $c]
    Record $c $classes
    file delete -force [dict get $c dir] [dict get $c err]
    incr R(running) -1
    Next
}

# ::fuzz::Next -- Starts cases until R(jobs) run or none is left; ends the loop when all are done.
proc ::fuzz::Next {} {
    variable R
    while {$R(running) < $R(jobs) && $R(next) < $R(cases)} {
        set c [MakeCase $R(next) $R(seed) $R(sources) $R(machines) $R(lines) $R(work)]
        incr R(next)
        incr R(running)
        Launch $c
    }
    if {$R(running) == 0 && $R(next) >= $R(cases)} {set R(done) 1}
}

# --- checking ------------------------------------------------------------

# ::fuzz::Classify --
#	Returns the failure classes of the finished case c ({} when it posted
#	or was refused as it must be), and sets R(outcome,<id>).
proc ::fuzz::Classify {c} {
    variable R
    set id [dict get $c id]
    set dir [dict get $c dir]
    set err [expr {[file exists [dict get $c err]] ? [ReadBytes [dict get $c err]] : ""}]
    set err [encoding convertfrom utf-8 $err]
    set status [dict get $c status]
    set classes {}
    set files [glob -nocomplain -tails -directory $dir -types hidden *]
    lappend files {*}[glob -nocomplain -tails -directory $dir *]
    set files [lsort -unique [lsearch -all -inline -not -regexp $files {^\.\.?$}]]
    if {[file exists [dict get $c canary]] || [file exists [file join $R(work) CANARY]]} {
        lappend classes canary
    }
    if {[regexp {while executing|invoked from within|\(procedure "|\("eval" body line|\(file "} $err]} {
        lappend classes stacktrace
    }
    set allowed {in.cls m.tcl}
    # where a successful run put the program (custom: the -o of its args)
    # and its log beside it; a -log of the args whatever the end
    set ncFile ""
    if {[dict get $c mode] eq "file"} {
        set ncFile out.nc
    } elseif {[set at [lsearch -exact [dict get $c cmd] -o]] >= 0} {
        set ncFile [lindex [dict get $c cmd] $at+1]
    }
    if {$status eq "0" && $ncFile ne ""} {lappend allowed $ncFile [file rootname $ncFile].log}
    if {[set at [lsearch -exact [dict get $c cmd] -log]] >= 0} {
        lappend allowed [lindex [dict get $c cmd] $at+1]
    }
    set stray [lmap f $files {if {$f in $allowed || $f eq "CANARY"} continue; set f}]
    if {[dict get $c timedOut]} {
        lappend classes timeout
    } elseif {$status eq "0"} {
        set R(outcome,$id) posted
        set nc [dict get $c out]
        if {$ncFile ne ""} {
            set path [file join $dir $ncFile]
            set nc [expr {[file isfile $path] ? [ReadBytes $path] : ""}]
        }
        lappend classes {*}[CheckNc $c $nc $err]
    } elseif {$status eq "1"} {
        set R(outcome,$id) refused
        if {"out.nc" in $files} {lappend classes partial}
        set last [lindex [split [string trimright $err \n] \n] end]
        variable badMessages
        if {[string match "*internal error*" $last] || [regexp $badMessages $last]} {
            lappend classes internal
        } elseif {![regexp {^(in\.cls|<stdin>):\d+: \S} $last]
                && !([regexp -line {^(in\.cls|<stdin>):\d+: the dry run of the written program found} $err]
                     && [regexp {^\S+:\d+: \S} $last])
                && ![regexp {^replay: \S} $last]
                && [string first "[MachineArg $c]: " $last] != 0
                && !([string match "*args:*" [dict get $c tags]] && [regexp {^(\S+: (machine file not found|cannot read)|usage: )} $last])} {
            lappend classes noplace
        }
    } else {
        set R(outcome,$id) failed
        lappend classes exit
    }
    if {[llength $stray]} {lappend classes stray}
    dict set R(detail,$id) files $stray
    dict set R(detail,$id) err [string range $err end-600 end]
    return [lsort -unique $classes]
}

# ::fuzz::MachineArg --
#	Returns the machine file as case c's command line names it (messages
#	about it start with that name).
proc ::fuzz::MachineArg {c} {
    set cmd [dict get $c cmd]
    lindex $cmd [lsearch -exact $cmd -machine]+1
}

# ::fuzz::CheckNc --
#	Returns the failure classes of the NC text nc of posted case c (stderr
#	err): nonfinite, limits, lifecycle, values, dwell, dispatch.
proc ::fuzz::CheckNc {c nc err} {
    set classes {}
    set lines [split [string trimright [encoding convertfrom utf-8 $nc] \n] \n]
    # INSERT records go out verbatim (the CAM's own text): not checked
    set cl [encoding convertfrom utf-8 [ReadBytes [file join [dict get $c dir] in.cls]]]
    set inserts [lmap {- t} [regexp -all -inline -line {^\s*INSERT\s*/(.*)$} $cl] {string trim $t}]
    set code [lmap l $lines {
        if {[regsub {^N?\d+ } $l ""] in $inserts} continue
        string trim [regsub -all {\([^)]*\)|;.*$} $l ""]
    }]
    set code [lsearch -all -inline -not -exact $code ""]
    set text [join $code \n]
    if {[regexp -nocase {[A-Z][-+]?(nan|inf)} $text]} {lappend classes nonfinite}
    if {[catch {fivax::machine load [dict get $c machine]} m]} {set m ""}
    set form [dict get [fivax::dialect writer [Controller $c $m]] form]
    if {![Inside $text $m $form]} {lappend classes limits}
    if {![OneProgram $code $form]} {lappend classes lifecycle}
    # values a control refuses (the F of a dwell is its time), and numbers
    # of 13 digits or more in any line (no control reads them)
    set blocks [lsearch -all -inline -not -regexp $code [dict get $form dwell]]
    if {[regexp {\m[FS][-+]?(0+\.?0*|\.0+)(\s|$)|\m[FSTHD]-} [join $blocks \n]]
            || [regexp {[0-9]{13}} $text]} {
        lappend classes values
    }
    # a DELAY of a positive time is written as a dwell (unless the line
    # before continues into it with a single trailing $: then it is part
    # of that record, a comment say)
    set dwell 0
    set continued 0
    foreach l [split $cl \n] {
        if {!$continued && [regexp {^\s*DELAY\s*/\s*([0-9]*\.?[0-9]+)\s*$} $l -> t] && $t > 0} {
            set dwell 1
        }
        set l [string trimright $l]
        set continued [expr {[string index $l end] eq "\$" && [string index $l end-1] ne "\$"}]
    }
    if {$dwell && ![regexp -- [dict get $form dwell] $text]} {
        lappend classes dwell
    }
    lappend classes {*}[CheckWords $c $err]
    return $classes
}

# ::fuzz::Inside --
#	Returns 1 when every axis word of NC text is finite and, on machine m
#	(a machine dict, "" when it cannot be loaded), inside its rotary
#	limits and, unless the program has a work plane or TCP (where X Y Z
#	are no machine values: form's free, see OneProgram), its travel.
proc ::fuzz::Inside {text m form} {
    set free [dict get $form free]
    set machineXyz [expr {$free eq "" || ![regexp -- $free $text]}]
    foreach {- letter value} [regexp -all -inline {\m([A-EU-Z])([-+]?[0-9]*\.?[0-9]+)} $text] {
        if {![string is double -strict $value] || abs($value) >= 1e7} {return 0}
        if {$m eq "" || $letter eq "D" || (!$machineXyz && $letter in {X Y Z})} continue
        if {$letter ni {X Y Z}} {set value [fivax::num rad $value]}
        if {[llength [fivax::machine outside $m [list $letter $value]]]} {return 0}
    }
    return 1
}

# ::fuzz::Controller --
#	Returns the dialect case c posts in: its -controller, else machine m's
#	(a machine dict or ""), else the default controller.
proc ::fuzz::Controller {c m} {
    set cmd [dict get $c cmd]
    if {[set at [lsearch -exact $cmd -controller]] >= 0} {return [lindex $cmd $at+1]}
    if {$m ne ""} {return [dict get $m controller]}
    fivax::dialect default
}

# ::fuzz::OneProgram --
#	Returns 1 when the NC lines code (comments and empty lines removed)
#	are one program of the form form (a controller's writer table's
#	form: lib/output.tcl): its opening and closing lines (where it has
#	them) around it, one start of modes and one end (M30, M2) as the
#	last block.
proc ::fuzz::OneProgram {code form} {
    dict with form {}
    set last end
    if {$first ne ""} {
        if {![regexp $first [lindex $code 0]] || ![regexp $close [lindex $code end]]
                || [llength [lsearch -all -regexp $code "$first|$close"]] != 2} {
            return 0
        }
        set last end-1
    }
    expr {[llength [lsearch -all -regexp $code $start]] == 1
        && [llength [lsearch -all -regexp $code $end]] == 1
        && [regexp $end [lindex $code $last]]}
}

# ::fuzz::CheckWords --
#	Returns {dispatch} when a post-handler word inserted as a record of
#	posted case c's CL file (not inside a record continued by $) was not
#	warned about in stderr err as an unknown record (so it reached the
#	post). (A refused run writes no program; the reader may refuse a line
#	before the records above it are dispatched.)
proc ::fuzz::CheckWords {c err} {
    set cl [split [ReadBytes [file join [dict get $c dir] in.cls]] \n]
    foreach tag [dict get $c tags] {
        if {![regexp {^word:(.*)$} $tag -> w]} continue
        set at [lsearch -regexp $cl "^\\s*$w\\s*(/|\$)"]
        if {$at < 0 || ($at > 0 && [string index [string trimright [lindex $cl $at-1]] end] eq "\$")} {
            continue
        }
        if {![string match "*unknown record '$w'*" $err]} {return dispatch}
    }
    return {}
}

# --- results -------------------------------------------------------------

# ::fuzz::Record -- Counts case c's outcome and failure classes.
proc ::fuzz::Record {c classes} {
    variable R
    set id [dict get $c id]
    if {![info exists R(outcome,$id)]} {set R(outcome,$id) failed}
    dict incr R(outcomes) $R(outcome,$id)
    foreach class $classes {dict incr R(classes) $class}
    if {![dict get $c timedOut] && [dict get $c ms] > $R(slowest)} {
        set R(slowest) [dict get $c ms]
    }
    if {[llength $classes]} {
        incr R(failed)
        lappend R(failures) [Describe $c $classes]
        Keep $c failed $classes
    }
    if {$R(verbose)} {
        puts [format "case %d: %s %s %s" $id $R(outcome,$id) [dict get $c tags] $classes]
    }
    unset R(outcome,$id) R(detail,$id)
}

# ::fuzz::Describe -- Returns a report line of case c with classes.
proc ::fuzz::Describe {c classes} {
    variable R
    set id [dict get $c id]
    set last [lindex [split [string trimright [dict get $R(detail,$id) err] \n] \n] end]
    set files [dict get $R(detail,$id) files]
    format "case %d \[%s\] (%s): %s%s\n    cmd: %s\n    stderr: %s" $id [join $classes ,] \
        [join [dict get $c tags] { }] [dict get $c status] \
        [expr {[llength $files] ? " files left: $files" : ""}] \
        [lrange [dict get $c cmd] 2 end] [string range $last 0 300]
}

# ::fuzz::Keep -- Copies case c (with classes) into R(keep)/c<id>-<what> when -keep is set.
proc ::fuzz::Keep {c what classes} {
    variable R
    if {$R(keep) eq ""} return
    set to [file join $R(keep) c[dict get $c id]-$what]
    file mkdir $to
    foreach f [glob -nocomplain -directory [dict get $c dir] *] {
        catch {file copy -force $f $to}
    }
    catch {file copy -force [dict get $c err] [file join $to stderr.txt]}
    WriteBytes [file join $to case.txt] "[Describe $c $classes]\n"
}

# ::fuzz::Report -- Prints the summary; returns the exit status (1 when a case failed).
proc ::fuzz::Report {seconds} {
    variable R
    variable classNames
    foreach line $R(failures) {puts "FAILED: $line"}
    set counts [lmap class $classNames {
        string cat $class= [expr {[dict exists $R(classes) $class] ? [dict get $R(classes) $class] : 0}]
    }]
    puts "fuzz: classes: [join $counts { }]"
    puts "fuzz: the slowest case that finished took $R(slowest) ms"
    puts [format "fuzz: %d cases in %.0f s (seed %d, %d jobs): posted=%d refused=%d failed=%d" \
        $R(cases) $seconds $R(seed) $R(jobs) \
        [expr {[dict exists $R(outcomes) posted] ? [dict get $R(outcomes) posted] : 0}] \
        [expr {[dict exists $R(outcomes) refused] ? [dict get $R(outcomes) refused] : 0}] \
        $R(failed)]
    expr {$R(failed) > 0}
}

# ::fuzz::main -- Parses argv, runs the cases, prints the report; returns the exit status.
proc ::fuzz::main {argv} {
    variable Options
    variable R
    variable root
    try {
        lassign [::fivax::opts argv $Options $argv fuzz] opts rest
    } trap {FIVAX OPTION} {msg} {
        puts stderr $msg
        return 1
    }
    if {[dict get $opts -help]} {
        puts "usage: tclsh tools/fuzz.tcl ?options?\nOptions:\n[::fivax::opts help $Options]"
        return 0
    }
    if {[llength $rest]} {
        puts stderr "fuzz: unexpected arguments: $rest"
        return 1
    }
    set corpus [dict get $opts -corpus]
    if {$corpus eq ""} {set corpus [::fivax::corpusDir $root]}
    set work [dict get $opts -dir]
    if {$work eq ""} {
        set base [expr {[info exists ::env(TMPDIR)] ? $::env(TMPDIR) : "/tmp"}]
        set work [file join $base fivax-fuzz-[pid]]
    }
    set work [file normalize $work]
    if {[file exists $work] && [llength [glob -nocomplain -directory $work *]]} {
        puts stderr "fuzz: -dir $work is not empty"
        return 1
    }
    file mkdir $work
    array unset R
    array set R [list cases [dict get $opts -cases] seed [dict get $opts -seed] \
        jobs [dict get $opts -jobs] timeout [dict get $opts -timeout] \
        slowest 0 \
        lines [dict get $opts -lines] keep [dict get $opts -keep] \
        verbose [dict get $opts -verbose] work $work next 0 running 0 done 0 \
        outcomes {} classes {} failed 0 failures {}]
    if {$R(keep) ne ""} {file mkdir $R(keep)}
    set R(sources) [Sources $corpus]
    set R(machines) [lsort [glob -directory [file join $root machines] *.tcl]]
    set t0 [clock milliseconds]
    # an error in the harness's own event handlers ends the run (it would
    # otherwise wait for the case that raised it for ever)
    interp bgerror {} [list apply {{msg opts} {
        puts stderr "fuzz: internal error of the harness: [dict get $opts -errorinfo]"
        exit 2
    }}]
    try {
        after 0 ::fuzz::Next
        vwait ::fuzz::R(done)
    } finally {
        set left [glob -nocomplain -directory $work *]
        file delete -force $work
    }
    Report [expr {([clock milliseconds] - $t0) / 1000.0}]
}

if {[info exists ::argv0] && [file normalize $::argv0] eq [file normalize [info script]]} {
    exit [::fuzz::main $argv]
}
