# helpers.tcl --
#	Shared test setup: loads fivax from this checkout (never an installed
#	copy) and the test and tool helpers (tests/kinref.tcl,
#	tools/lib/toolpath.tcl), tcllib's math::linearalgebra (the reference
#	rotations' products, independent of lib/), registers the float
#	matchers, and the real-CL-corpus constraint.
#
#	Conventions for test files: procs a file defines carry its module's
#	name as a prefix (motionPlan, clsfStats) so that no two files define
#	the same name in the one interpreter; temporary files come from
#	makeFile/makeDirectory and are removed by the test that made them
#	(tests/all.tcl fails when any is left behind); errors are asserted with
#	-errorCode; results carry measured values (see customMatch le).

package require tcltest 2.5
package require math::linearalgebra
namespace import ::tcltest::*

set ::fivaxRoot [file dirname [file dirname [file normalize [info script]]]]
set ::auto_path [linsert $::auto_path 0 [file join $::fivaxRoot lib]]
package require fivax::host 0.1
source [file join $::fivaxRoot tests kinref.tcl]
source [file join $::fivaxRoot tools lib toolpath.tcl]
source [file join $::fivaxRoot tools lib corpus.tcl]

# Where the real CL files live (outside the repo, never copied into it):
# FIVAX_CORPUS, else ../shared/data/cl beside the checkout.
set ::clCorpus [::fivax::corpusDir $::fivaxRoot]
testConstraint clsfCorpus [file isdirectory $::clCorpus]
if {![testConstraint clsfCorpus] && ![info exists ::corpusNoted]} {
    set ::corpusNoted 1
    puts "corpus tests skipped: $::clCorpus is not a directory (set FIVAX_CORPUS to the real CL files)"
}
# A constraint per controller of lib/dialect/ (fanuc, haas, ...): the tests
# of one controller's own words run only while its file is there.
apply {{} {foreach c [fivax::dialect names] {testConstraint $c 1}}}

# approxList --
#	Returns 1 when the flat number lists want and got have equal length and
#	agree element-wise within tol.
proc approxList {tol want got} {
    if {[llength $want] != [llength $got]} {return 0}
    foreach w $want g $got {
        if {![string is double -strict $g] || abs($w - $g) > $tol} {return 0}
    }
    return 1
}
customMatch approx {approxList 1e-9}
customMatch mm {approxList 1e-6}
customMatch coarse {approxList 1e-3}

# boundsMatch --
#	Returns 1 when got is a list as long as the list of bounds want and
#	each number of got is at most its bound (a bound "-" takes any value
#	of got as it is: a word, a count). The measured values are the
#	result, so a failure shows them beside the bounds.
proc boundsMatch {want got} {
    if {[llength $want] != [llength $got]} {return 0}
    foreach w $want g $got {
        if {$w eq "-"} continue
        if {[string is double -strict $w]} {
            if {![string is double -strict $g] || !($g <= $w)} {return 0}
        } elseif {$w ne $g} {
            return 0
        }
    }
    return 1
}
customMatch le boundsMatch


# corpusFile -- Returns the path of the named real CL file.
proc corpusFile {name} {
    file join $::clCorpus $name
}

# machineRpm --
#	Returns the path of the temporary file rpm-<name>.tcl: the shipped
#	machine file machines/name.tcl with default_rpm 10000, for the real CL
#	files that have no SPINDL record (most NX ones: no cut without a
#	speed), and with travel (a travel value) in place of its own when
#	given. The test that calls it removes it (removeFile rpm-<name>.tcl).
proc machineRpm {name {travel ""}} {
    set text [viewFile [file join $::fivaxRoot machines $name.tcl]]
    if {$travel ne ""} {regsub -line {^travel\s.*$} $text [list travel $travel] text}
    makeFile "$text\ndefault_rpm 10000\n" rpm-$name.tcl
}

# runReplay --
#	Runs tools/replay.tcl with args; returns {code output} (output:
#	standard output and error together). Every NC file a successful run
#	writes (-o) is then checked by tools/verify.tcl against the CL file
#	with the same machine, frame and tolerances (verifyReplayOutput): when
#	that check fails, the code is 2 and verify's report ends the output,
#	so that the test fails showing it.
proc runReplay {args} {
    set code [catch {exec [info nameofexecutable] [file join $::fivaxRoot tools replay.tcl] \
        {*}$args 2>@1} out]
    set out [regsub {\n?child process exited abnormally$} $out ""]
    if {!$code} {
        lassign [verifyReplayOutput $args] vcode vout
        if {$vcode} {
            set code 2
            append out "\ntools/verify.tcl on the written file failed:\n$vout"
        }
    }
    if {!$code} {
        set opts [ReplayOptions $args]
        if {[dict exists $opts -o] && [file isfile [dict get $opts -o]]} {
            set problems [programProblems [dict get $opts -o] [dict get $opts -machine] \
                [expr {[dict exists $opts -controller] ? [dict get $opts -controller] : ""}]]
            if {[llength $problems]} {
                set code 3
                append out "\nprogram structure of the written file:\n[join $problems \n]"
            }
        }
    }
    list $code $out
}

# ReplayOptions --
#	Returns the options of a replay command line argList as a dict
#	(switches -msys -quiet -help with value 1; -machine defaulted).
proc ReplayOptions {argList} {
    set opts [dict create -machine [file join $::fivaxRoot machines hh-tilt45.tcl]]
    for {set i 0} {$i < [llength $argList] - 1} {incr i} {
        set w [lindex $argList $i]
        if {$w in {-msys -quiet -help}} {
            dict set opts $w 1
        } else {
            dict set opts $w [lindex $argList [incr i]]
        }
    }
    return $opts
}

# programProblems --
#	Reads the NC file path (for the machine file and controller, "": the
#	machine's) and returns what breaks the safe program structure, one
#	"LINE: what" each (at most 20), by the text alone:
#	- the safety line (Fanuc, LinuxCNC: G40 G49 G80; Sinumerik: G40) and
#	  a work offset (G54..G59; Klartext has neither) before the first
#	  motion; no sequence number twice; no text that is not NC words or
#	  a comment;
#	- every tool change (M6, TOOL CALL) right after a block taking Z up
#	  in machine coordinates (G53 Z, SUPA Z, M91), work-plane and TCP
#	  cancels and the rotaries' move home aside, and the program's first
#	  motion such a block;
#	- the approach after it: rotaries alone, then X Y alone, then the
#	  first Z move alone (with TCP it may carry X Y: the tip's X Y Z in
#	  one block; G43 controls (fanuc, linuxcnc, haas): with G43 or the
#	  TCP G code (G43.4, G234) since the tool change;
#	  Sinumerik's D and Klartext's TOOL CALL compensate the length
#	  themselves), before any cut
#	  (whether the first cut is the post's entry down the tool axis or
#	  the CL's own move the text cannot tell: program.test checks the
#	  entry by forward kinematics);
#	- the end: the last feed block followed by a rapid, not by the Z up,
#	  and the last move of X, Y or Z up in machine coordinates.
proc programProblems {path machineFile {controller ""}} {
    set machine [fivax::machine load $machineFile]
    if {$controller eq ""} {set controller [dict get $machine controller]}
    set checker [fivax::verify create $machine -controller $controller]
    set rotaries [fivax::machine rotaryNames $machine]
    # the controller's safety G codes, its G43 length compensation and TCP G codes
    set writer [fivax::dialect writer $controller]
    set safety [lmap {- v} [dict get $writer safety] {set v}]
    # (G43 controls: their safety line cancels it)
    set gLength [dict exists [dict get $writer safety] G_length]
    set tcpG [dict get [fivax::dialect reader $controller] tcpG]
    # blocks that may stand between the Z up and the tool change
    set cancels {G69$|CYCLE800\(\)|PLANE RESET|TRAFOOF|FUNCTION RESET TCPM|^(N\d+ )?G49$}
    if {[llength [dict get $machine tcp_codes]]} {
        append cancels "|^(N\\d+ )?M[lindex [dict get $machine tcp_codes] 1]\$"
    }
    set problems {}
    set seen {}
    set header {}
    set modal {}
    # prevBlock: {G53? Z?} of the last block
    set prevBlock {0 0}
    # approach: 1 from a tool change (or the start) to its first Z move;
    # stage: what moved last in it (none, rotary, xy)
    set approach 1
    set stage none
    set toolChanged 0
    set motions 0
    set lastFeed 0
    set afterFeed ""
    set lastMotion ""
    set lengthOn 0
    set n 0
    try {
        foreach line [split [viewFile $path] \n] {
            incr n
            set blk [$checker read $line]
            if {![dict get $blk block]} continue
            if {[regexp {^N(\d+)} $line -> num]} {
                if {[dict exists $seen $num]} {
                    lappend problems "$n: N$num again (line [dict get $seen $num])"
                }
                dict set seen $num $n
            }
            foreach {kind word} [dict get $blk unknown] {
                if {$kind eq "text"} {lappend problems "$n: not NC words: $word"}
            }
            set words [dict get $blk words]
            set codes {G {} M {}}
            foreach {l v} $words {
                if {$l in {G M}} {dict lappend codes $l [expr {$v + 0}]}
            }
            set gs [dict get $codes G]
            set machineZ [expr {53 in $gs}]
            if {!$motions} {lappend header {*}$gs}
            if {[regexp $cancels $line]} continue
            if {43 in $gs || [llength [lmap g $tcpG {if {$g ni $gs} continue}]]} {set lengthOn 1}
            if {6 in [dict get $codes M] || [regexp {^\d+ TOOL CALL \d} $line]} {
                if {!([lindex $prevBlock 0] && [lindex $prevBlock 1])} {
                    lappend problems "$n: tool change not right after Z up in machine coordinates"
                }
                set approach 1
                set stage none
                set toolChanged 1
                set lengthOn 0
            }
            # the axes whose value this block changes
            set changed {}
            set hasZ 0
            foreach {l v} $words {
                if {$l ni [concat {X Y Z} $rotaries]} continue
                if {$l eq "Z"} {set hasZ 1}
                if {$machineZ} {
                    dict unset modal $l
                } else {
                    if {![dict exists $modal $l] || abs([dict get $modal $l] - $v) > 1e-9} {
                        lappend changed $l
                    }
                    dict set modal $l $v
                }
            }
            # (the rotaries' move home between the Z up and the tool change)
            set rotOnly [expr {[llength $words] && ![llength [lmap {l v} $words {
                if {$l in {X Y Z} || ($l ni $rotaries && $l ni {G N})} {set l} else continue
            }]]}]
            if {!($rotOnly && $prevBlock eq {1 1})} {set prevBlock [list $machineZ $hasZ]}
            if {![llength [dict get $blk moved]]} continue
            if {!$motions} {
                foreach g $safety {
                    if {$g ni $header} {lappend problems "$n: no G$g before the first motion"}
                }
                if {$controller ne "heidenhain"
                        && ![llength [lmap g $header {if {$g >= 54 && $g <= 59} {set g} else continue}]]} {
                    lappend problems "$n: no work offset (G54..G59) before the first motion"
                }
                if {!$machineZ} {lappend problems "$n: the first motion is not Z up in machine coordinates"}
            }
            incr motions
            # (the rotaries may go home after the Z up)
            if {$hasZ || "X" in $changed || "Y" in $changed} {set lastMotion [list $n $machineZ]}
            if {$machineZ} {
                if {$afterFeed eq ""} {set afterFeed machineZ}
                continue
            }
            set cut [expr {[dict get $blk motion] == 1 || [dict get $blk hole]}]
            set rot [llength [lmap a $changed {if {$a in $rotaries} {set a} else continue}]]
            set xy [expr {"X" in $changed || "Y" in $changed}]
            set z [expr {"Z" in $changed}]
            if {$approach && !$cut} {
                if {$z} {
                    if {$rot || ($xy && [dict get $blk space] ne "tcp")} {
                        lappend problems "$n: the approach's first Z move moves more than Z"
                    }
                    if {$toolChanged && $gLength && !$lengthOn} {
                        lappend problems "$n: no G43 or G43.4 from the tool change to the first Z move"
                    }
                    set approach 0
                    set toolChanged 0
                } elseif {$rot && $xy} {
                    lappend problems "$n: the approach turns rotaries and moves X Y in one block"
                } elseif {$rot && $stage eq "xy"} {
                    lappend problems "$n: the approach turns rotaries after moving X Y"
                } elseif {$xy} {
                    set stage xy
                } elseif {$rot} {
                    set stage rotary
                }
            } elseif {$approach && $cut} {
                lappend problems "$n: a cut before the approach reached Z"
                set approach 0
            }
            if {[dict get $blk motion] == 1} {
                set lastFeed $n
                set afterFeed ""
            } elseif {$afterFeed eq ""} {
                set afterFeed rapid
            }
        }
    } finally {
        $checker destroy
    }
    if {$lastFeed && $afterFeed ne "rapid"} {
        lappend problems "$lastFeed: the last cut is not followed by a retract"
    }
    if {$motions && ![lindex $lastMotion 1]} {
        lappend problems "[lindex $lastMotion 0]: the program does not end with Z up in machine coordinates"
    }
    lrange $problems 0 19
}

# verifyReplayOutput --
#	Runs tools/verify.tcl on the NC file a replay with command line args
#	wrote (-o), against its CL file (the last word), with the replay's
#	-machine, -msys, -table-offset, -controller, -arc-tol, -tool-length
#	(verify's overrides the CL's TLDATA: give it only for CL files with
#	none) and -cutcom3d with its cutter; inside
#	blocks with the replay's -tol and -atol plus 0.001 of output rounding
#	(-tol 0: not linearised, -atol 0: axis not linearised; not checked). Returns {code output}; {0 {}}
#	when nothing was written.
proc verifyReplayOutput {argList} {
    set opts [dict create -machine [file join $::fivaxRoot machines hh-tilt45.tcl]]
    set switches {-msys -quiet -help}
    set cl [lindex $argList end]
    for {set i 0} {$i < [llength $argList] - 1} {incr i} {
        set w [lindex $argList $i]
        if {$w in $switches} {
            dict set opts $w 1
        } else {
            dict set opts $w [lindex $argList [incr i]]
        }
    }
    if {![dict exists $opts -o] || ![file isfile [dict get $opts -o]] || $cl eq "-"} {
        return {0 {}}
    }
    set vargs [list -quiet -machine [dict get $opts -machine] -cl $cl]
    if {[dict exists $opts -msys]} {lappend vargs -msys}
    foreach key {-table-offset -controller -arc-tol -tool-length -dryrun -cutcom3d -tool-diameter
            -tool-corner-radius} {
        if {[dict exists $opts $key]} {lappend vargs $key [dict get $opts $key]}
    }
    # inside blocks: the replay's tolerances (0: not linearised) plus
    # the output rounding of the block ends (as e2eSpec: 0.001 mm)
    set tol [expr {[dict exists $opts -tol] ? [dict get $opts -tol] : 0.01}]
    set atol [expr {[dict exists $opts -atol] ? [dict get $opts -atol] : 0.05}]
    if {$tol == 0} {
        # no linearisation at all
        lappend vargs -mid-tol 1e9 -mid-atol 1e9
    } else {
        lappend vargs -mid-tol [expr {$tol + 0.001}] -mid-atol [expr {$atol == 0 ? 1e9 : $atol + 0.001}]
    }
    set code [catch {exec [info nameofexecutable] [file join $::fivaxRoot tools verify.tcl] \
        {*}$vargs [dict get $opts -o] 2>@1} out]
    list $code [regsub {\n?child process exited abnormally$} $out ""]
}

# testRotation --
#	Returns the 3x3 rotation (rows) about axis x, y or z by deg degrees,
#	written here, independently of lib/plane.tcl, to check its angles.
proc testRotation {axis deg} {
    set a [expr {$deg * acos(-1) / 180.0}]
    set c [expr {cos($a)}]
    set s [expr {sin($a)}]
    switch -- $axis {
        x {list {1.0 0.0 0.0} [list 0.0 $c [expr {-$s}]] [list 0.0 $s $c]}
        y {list [list $c 0.0 $s] {0.0 1.0 0.0} [list [expr {-$s}] 0.0 $c]}
        z {list [list $c [expr {-$s}] 0.0] [list $s $c 0.0] {0.0 0.0 1.0}}
    }
}

# testProduct -- Returns the product of the 3x3 matrices given, left to right (tcllib).
proc testProduct {args} {
    set R [::math::linearalgebra::mkIdentity 3]
    foreach B $args {
        set R [::math::linearalgebra::matmul $R $B]
    }
    return $R
}

# twoToolPrograms --
#	Posts, on hh-tilt45 in joint mode (-tcp 0: the head's X Y Z depend on
#	the tool length), the bundled sim5.cls path twice, with tool 1 (length
#	75) as it is and then with tool 2 (length 140, operation SWARF_B), and
#	that second operation alone, into the temporary directory. Returns the
#	paths {two second} of the two NC programs (name prefix: prefix).
proc twoToolPrograms {prefix} {
    set f [open [file join $::fivaxRoot tests data sim5.cls]]
    set lines [split [string trim [read $f]] \n]
    close $f
    set second [concat {"TOOL PATH/SWARF_B,TOOL,BALL6" "TLDATA/MILL,6.0000,3.0000,140.0000,0.0000,0.0000"
        "LOAD/TOOL,2,ADJUST,2"} [lrange $lines 3 end]]
    set out {}
    foreach {name cl} [list two [concat $lines $second] second $second] {
        set path [makeFile [join $cl \n] $prefix-$name.cls]
        set nc [file join [temporaryDirectory] $prefix-$name.nc]
        exec [info nameofexecutable] [file join $::fivaxRoot tools replay.tcl] -quiet \
            -machine [file join $::fivaxRoot machines hh-tilt45.tcl] -tcp 0 -o $nc $path 2>@1
        file delete $path [file rootname $nc].log
        lappend out $nc
    }
    return $out
}

# svgSeries --
#	Returns {xs ys starts} of the series (class series) named name in the
#	SVG text of a chart (tools/lib/svgplot.tcl): its points mapped back to
#	data values through the tick labels (xtick, ytick) of its panel, and
#	the indices of the points where a subpath starts (M: a break).
proc svgSeries {text name} {
    package require tdom
    set doc [dom parse $text]
    try {
        set node ""
        foreach n [$doc selectNodes {//*[@class='series']}] {
            if {[$n getAttribute data-name] eq $name} {set node $n}
        }
        if {$node eq ""} {return "no series $name"}
        set panel [$node parentNode]
        foreach axis {x y} {
            set ticks [lmap t [$panel selectNodes ".//*\[@class='${axis}tick'\]"] {
                list [$t getAttribute $axis] [$t text]
            }]
            lassign [lindex $ticks 0] p0 v0
            lassign [lindex $ticks end] p1 v1
            set map($axis) [list $p0 $v0 [expr {($v1 - $v0) / double($p1 - $p0)}]]
        }
        set xs {}
        set ys {}
        set starts {}
        foreach {- pen px py} [regexp -all -inline {([ML])([-0-9.]+),([-0-9.]+)} [$node getAttribute d]] {
            if {$pen eq "M"} {lappend starts [llength $xs]}
            foreach axis {x y} p [list $px $py] {
                lassign $map($axis) p0 v0 k
                lappend ${axis}s [expr {$v0 + ($p - $p0) * $k}]
            }
        }
        list $xs $ys $starts
    } finally {
        $doc delete
    }
}
