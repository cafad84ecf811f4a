# verify.tcl --
#	Checks an NC program on a virtual machine: reads every block (fanuc or
#	linuxcnc text, from fivax or another post), maps it back by forward
#	kinematics (never the inverse) and reports per operation the tool tip
#	and axis deviation at block ends (against the CL path with -cl) and
#	inside joint-space moves (the controller's linear joint interpolation
#	against the straight line between the block ends), rotary travel,
#	retracts, rotary values outside the limits and feed anomalies, and
#	names the worst NC line. Exits 1 when a figure exceeds the
#	tolerances, a value is outside the limits or a feed is wrong.
#
#	tclsh tools/verify.tcl -machine M.tcl ?options? part.nc   (-help)

package require Tcl 8.6

set root [file dirname [file dirname [file normalize [info script]]]]
set auto_path [linsert $auto_path 0 [file join $root lib]]
package require fivax 0.1
foreach f {toolpath.tcl clpath.tcl svgplot.tcl nctool.tcl} {
    source [file join $root tools lib $f]
}

namespace eval ::verifytool {
    variable Options {
        {-machine text {} FILE "machine file (required)"}
        {-cl text {} FILE "CLSF the program was posted from: block ends are compared with its CL path"}
        {-msys bool 0 "" "map the CL data through the CLSF's MSYS frame (as replay -msys)"}
        {-tol {real min 0} 0.01 MM "tip tolerance at block ends and inside blocks"}
        {-atol {real min 0} 0.05 DEG "tool axis tolerance"}
        {-mid-tol {maybe real min 0} {} MM "tip tolerance inside blocks (default: -tol)"}
        {-mid-atol {maybe real min 0} {} DEG "tool axis tolerance inside blocks (default: -atol)"}
        {-controller {maybe word} {} NAME "dialect of the NC text (default: the machine's controller)"}
        {-tool-length {maybe real} {} MM "tool length (default: the CL's TLDATA, else the machine's tool_length)"}
        {-table-offset {maybe vec3} {} "X Y Z" "workpiece-frame position of the table reference point"}
        {-arc-tol {real gt 0} 0.002 MM "chord tolerance of CL arcs (the post's -arc-tol)"}
        {-window {int min 1} 32 N "CL segments searched ahead of the last match"}
        {-csv text {} FILE "write one row per block: line, op, motion, axes, back-plotted tip and axis, deviations"}
        {-o text {} FILE "write the back-plotted tip path and tool axis as a CLSF"}
        {-svg text {} PREFIX "write PREFIX-axes.svg, PREFIX-deviation.svg and PREFIX-path.svg"}
        {-quiet bool 0 "" "print the verdict line only"}
        {-help bool 0 "" "print this help"}
    }
}

# ::verifytool::Die -- Prints msg on standard error and exits with status 1.
proc ::verifytool::Die {msg} {
    puts stderr $msg
    exit 1
}

# ::verifytool::Say -- Prints msg on standard output unless quiet.
proc ::verifytool::Say {opts msg} {
    if {![dict get $opts -quiet]} {puts $msg}
}

# ::verifytool::ParseArgs -- Returns {opts ncPath} from argv.
proc ::verifytool::ParseArgs {argv} {
    variable Options
    try {
        lassign [::fivax::opts argv $Options $argv verify] opts rest
    } trap {FIVAX OPTION} {msg} {
        Die $msg
    }
    if {[dict get $opts -help]} {
        puts "usage: tclsh tools/verify.tcl -machine M.tcl ?options? part.nc\n\nChecks an NC\
            program by forward kinematics.\nOptions:\n[::fivax::opts help $Options]"
        exit 0
    }
    if {[llength $rest] != 1} {
        Die "usage: tclsh tools/verify.tcl -machine M.tcl ?options? part.nc (-help for the options)"
    }
    if {[dict get $opts -machine] eq ""} {Die "verify: -machine is required"}
    list $opts [lindex $rest 0]
}

# ::verifytool::NewOp -- Returns the statistics dict of a new operation name.
proc ::verifytool::NewOp {name} {
    dict create name $name blocks 0 feeds 0 endPos 0.0 endPosAt {} endAng 0.0 endAngAt {} \
        midPos 0.0 midPosAt {} midAng 0.0 midAngAt {} travel {0.0 0.0} retracts 0 \
        limits 0 limitAt {} feedIssues 0 feedAt {} matched 0 moves 0
}

# ::verifytool::Max --
#	Raises figure key of the operation dict in opVar to value when larger,
#	noting where.
proc ::verifytool::Max {opVar key value where} {
    upvar 1 $opVar op
    if {$value > [dict get $op $key]} {
        dict set op $key $value
        dict set op ${key}At $where
    }
}

# ::verifytool::Run --
#	Checks the NC file path with the options; returns {ops rows problems}:
#	the operation statistics, the CSV rows and the list of failed checks.
proc ::verifytool::Run {opts path machine} {
    set checker [::fivax::verify create $machine -table-offset [dict get $opts -table-offset] \
        -controller [dict get $opts -controller]]
    set cl {}
    if {[dict get $opts -cl] ne ""} {
        set cl [::fivax::clpath read [dict get $opts -cl] [dict get $opts -msys] \
            [dict get $opts -arc-tol]]
    }
    set names [lmap a [dict get $machine chain] {dict get $a name}]
    set rollover [lmap a [dict get $machine chain] {dict get $a rollover}]
    set feedMax [dict get $machine feed_max]
    set invMax [dict get $machine inverse_time_max]
    set tol [dict get $opts -tol]
    set atol [dict get $opts -atol]
    set window [dict get $opts -window]
    set warnings [dict create]
    set ops {}
    set op [NewOp program]
    set opIndex -1
    set clPoints {}
    set cursor 0
    set prev {}
    set prevMotion ""
    set rows {}
    set problems {}
    set lineNo 0
    set chan [::fivax::nctool::open $path]
    try {
        while {[gets $chan line] >= 0} {
            incr lineNo
            set where $path:$lineNo
            set blk [$checker read $line]
            foreach c [dict get $blk comments] {
                if {[regexp {^\s*OPERATION\s+(.*?)\s*$} $c -> name]} {
                    if {[dict get $op blocks] || $opIndex >= 0} {lappend ops $op}
                    set op [NewOp $name]
                    incr opIndex
                    set prev {}
                    set prevMotion ""
                    set cursor 0
                    set clPoints {}
                    set len [dict get $opts -tool-length]
                    if {$opIndex < [llength $cl]} {
                        set clop [lindex $cl $opIndex]
                        set clPoints [dict get $clop points]
                        if {$len eq ""} {set len [dict get $clop length]}
                    }
                    $checker setTool $len
                }
            }
            if {![dict get $blk block]} continue
            dict incr op blocks
            foreach {kind word} [dict get $blk unknown] {
                if {![dict exists $warnings $kind]} {
                    puts stderr "verify: $where: warning: $kind not understood ($word); read as if absent"
                }
                dict incr warnings $kind
            }
            foreach axis [dict get $blk limit] {
                dict incr op limits
                if {[dict get $op limitAt] eq ""} {dict set op limitAt "$where ($axis)"}
            }
            set joints [dict get $blk joints]
            set moved [dict get $blk moved]
            set motion [dict get $blk motion]
            if {$joints eq "" || ![llength $moved]} {
                if {[llength $moved]} {set prev {}}
                continue
            }
            lassign [$checker tip $joints] P t
            dict incr op moves
            # rotary travel (a rotary that rolls over turns the shortest way)
            if {$prev ne ""} {
                set tr {}
                foreach i {3 4} roll $rollover acc [dict get $op travel] {
                    set d [expr {[lindex $joints $i] - [lindex $prev 0 $i]}]
                    if {$roll} {set d [expr {$d - 2.0 * acos(-1) * round($d / (2.0 * acos(-1)))}]}
                    lappend tr [expr {$acc + abs($d)}]
                }
                dict set op travel $tr
            }
            if {$motion == 0 && $prevMotion == 1} {dict incr op retracts}
            set endPos ""
            set endAng ""
            set midPos ""
            set midAng ""
            if {$motion == 1} {
                dict incr op feeds
                set F [dict get $blk F]
                set mode [dict get $blk mode]
                set issue ""
                if {$mode eq "inverse" && $F eq ""} {
                    set issue "G93 block without F"
                } elseif {$F eq "" && [dict get $blk feed] eq ""} {
                    set issue "feed move without any F"
                } else {
                    set f [expr {$F ne "" ? $F : [dict get $blk feed]}]
                    if {$f <= 0} {
                        set issue "F $f is not positive"
                    } elseif {$mode eq "inverse" && $f > $invMax} {
                        set issue "inverse-time F $f above the machine's inverse_time_max $invMax"
                    } elseif {$mode eq "direct" && $f > $feedMax} {
                        set issue "F $f mm/min above the machine's feed_max $feedMax"
                    }
                }
                if {$issue ne ""} {
                    dict incr op feedIssues
                    if {[dict get $op feedAt] eq ""} {dict set op feedAt "$where: $issue"}
                }
                if {$prev ne ""} {
                    lassign $prev j0 P0 t0
                    lassign [$checker interior $j0 $joints $P0 $P $t0 $t] midPos midAng
                    Max op midPos $midPos $where
                    Max op midAng $midAng $where
                }
                if {[llength $clPoints]} {
                    lassign [::fivax::clpath nearest $clPoints $P $t $cursor $window] d i s Q tq
                    if {$d > $tol} {
                        lassign [::fivax::clpath nearest $clPoints $P $t $cursor -1] d2 i2 s2 Q2 tq2
                        if {$d2 < $d} {lassign [list $d2 $i2 $s2 $Q2 $tq2] d i s Q tq}
                    }
                    set cursor $i
                    set endPos $d
                    set endAng [::fivax::num::deg [::fivax::vec::angle $t $tq]]
                    dict incr op matched
                    Max op endPos $endPos $where
                    Max op endAng $endAng $where
                }
            }
            lappend rows [list $lineNo [dict get $op name] $motion $joints $P $t \
                $endPos $endAng $midPos $midAng [dict get $blk F] [dict get $blk mode]]
            set prev [list $joints $P $t]
            set prevMotion $motion
        }
    } finally {
        close $chan
        $checker destroy
    }
    if {[dict get $op blocks] || $opIndex >= 0} {lappend ops $op}
    if {![llength $rows]} {
        set letters [lmap k [dict keys $warnings] {
            if {[string match "letter *" $k]} {string range $k 7 end} else continue
        }]
        ::fivax::Fail TOOL MACHINE "$path: no block gives all of X Y Z [join $names { }] of\
            machine [dict get $machine name][expr {[llength $letters] ?
                "; the file writes [join $letters {, }]: is it for another machine?" : ""}]"
    }
    if {[llength $cl] && [llength $cl] != $opIndex + 1} {
        puts stderr "verify: warning: [llength $cl] CL operations, [expr {$opIndex + 1}] in the NC file"
    }
    set midTol [dict get $opts -mid-tol]
    if {$midTol eq ""} {set midTol $tol}
    set midAtol [dict get $opts -mid-atol]
    if {$midAtol eq ""} {set midAtol $atol}
    foreach op $ops {
        dict with op {}
        foreach {key lim what} [list endPos $tol mm endAng $atol deg midPos $midTol mm midAng $midAtol deg] {
            if {[dict get $op $key] > $lim} {
                lappend problems [format "%s: %s %.6f %s > %g at %s" $name \
                    [dict get {endPos "tip off the CL path" endAng "axis off the CL axis"
                        midPos "tip inside a block" midAng "axis inside a block"} $key] \
                    [dict get $op $key] $what $lim [dict get $op ${key}At]]
            }
        }
        if {$limits} {lappend problems "$name: $limits rotary values outside the limits, first at $limitAt"}
        if {$feedIssues} {lappend problems "$name: $feedIssues feed anomalies, first at $feedAt"}
    }
    list $ops $rows $problems $warnings $names
}

# ::verifytool::Report -- Prints the per-operation figures and the worst line.
proc ::verifytool::Report {opts ops names hasCl} {
    set worst {}
    set wv -1
    foreach op $ops {
        dict with op {}
        if {!$moves} continue
        set msg [format "verify: %s: %d blocks (%d feed)" $name $blocks $feeds]
        if {$hasCl} {
            append msg [format ", block ends vs CL: max %.6f mm at %s, %.6f deg" \
                $endPos [Where $endPosAt] $endAng]
        }
        append msg [format "; inside blocks: max %.6f mm at %s, %.6f deg" $midPos \
            [Where $midPosAt] $midAng]
        append msg [format "; rotary travel %s %.3f deg, %s %.3f deg; %d retracts;\
            %d values outside limits; %d feed anomalies" [lindex $names 0] \
            [::fivax::num::deg [lindex $travel 0]] [lindex $names 1] \
            [::fivax::num::deg [lindex $travel 1]] $retracts $limits $feedIssues]
        Say $opts $msg
        foreach {key at} {endPos endPosAt midPos midPosAt} {
            if {[dict get $op $key] > $wv} {
                set wv [dict get $op $key]
                set worst [list [dict get $op $at] $key]
            }
        }
    }
    if {$worst ne "" && [lindex $worst 0] ne ""} {
        Say $opts [format "verify: worst NC line %s (%s %.6f mm)" [lindex $worst 0] \
            [expr {[lindex $worst 1] eq "endPos" ? "block end off the CL path" : "inside the block"}] $wv]
    }
}

# ::verifytool::Where -- Returns where, or "-" when empty.
proc ::verifytool::Where {where} {
    expr {$where eq "" ? "-" : $where}
}

# ::verifytool::Csv -- Writes the rows as CSV to path.
proc ::verifytool::Csv {path rows names} {
    set out [list [join [list line op motion X Y Z {*}$names x y z i j k \
        end_dpos end_dangle mid_dpos mid_dangle F mode] ,]]
    foreach row $rows {
        lassign $row line op motion joints P t ep ea mp ma F mode
        lassign $joints X Y Z q1 q2
        set vals [list $line [::fivax::nctool::csvField $op] $motion]
        foreach v [list $X $Y $Z] {lappend vals [::fivax::num::fixed $v 4]}
        foreach q [list $q1 $q2] {lappend vals [::fivax::num::fixed [::fivax::num::deg $q] 4]}
        foreach v [concat $P] {lappend vals [::fivax::num::fixed $v 6]}
        foreach v $t {lappend vals [::fivax::num::fixed $v 7]}
        foreach v [list $ep $ea $mp $ma] {
            lappend vals [expr {$v eq "" ? "" : [format %.6f $v]}]
        }
        lappend vals $F $mode
        lappend out [join $vals ,]
    }
    ::fivax::nctool::writeLines $path $out
}

# ::verifytool::Clsf --
#	Writes the back-plotted path as a CLSF to path: one operation per NC
#	operation, RAPID before G0 points, FEDRAT when the tip feed changes.
proc ::verifytool::Clsf {path rows tool} {
    set lines {}
    set op ""
    set last ""
    set lastFeed ""
    set prevP {}
    foreach row $rows {
        lassign $row - name motion joints P t - - - - F mode
        if {$name ne $op} {
            if {$op ne ""} {lappend lines END-OF-PATH}
            lappend lines "TOOL PATH/[regsub -all {[^A-Za-z0-9_.-]} $name _],TOOL,BACKPLOT" \
                "TLDATA/MILL,0.0000,0.0000,[::fivax::num::fixed $tool 4],0.0000,0.0000"
            set op $name
            set last ""
            set lastFeed ""
        }
        if {$motion == 0} {
            lappend lines RAPID
        } elseif {$F ne "" || $mode eq "inverse"} {
            set f [expr {$F eq "" ? $lastFeed : $F}]
            if {$mode eq "inverse" && $prevP ne "" && $F ne ""} {
                set f [expr {$F * [::fivax::vec::norm [::fivax::vec::sub $P $prevP]]}]
            }
            if {$f ne "" && $f > 0 && [::fivax::num::fixed $f 4] ne $lastFeed} {
                set lastFeed [::fivax::num::fixed $f 4]
                lappend lines "FEDRAT/MMPM,$lastFeed"
            }
        }
        lappend lines [::fivax::toolpath::goto $P $t last]
        set prevP $P
    }
    if {$op ne ""} {lappend lines END-OF-PATH}
    ::fivax::nctool::writeLines $path $lines
}

# ::verifytool::Plots -- Writes the three plots of the rows with names prefix-*.svg; returns the paths.
proc ::verifytool::Plots {prefix rows names tol file} {
    set n [llength $rows]
    set idx {}
    for {set i 0} {$i < $n} {incr i} {lappend idx $i}
    set series {}
    foreach k {3 4} name $names {
        lappend series [list "$name (deg)" $idx [lmap r $rows {
            ::fivax::num::deg [lindex $r 3 $k]}]]
    }
    set axes [::fivax::svgplot chart -title "Rotary axes of [file tail $file]" \
        -xlabel "block (written motion blocks in file order)" -ylabel "axis value (deg)" \
        -series $series -zero 0]
    set dev {}
    foreach {k label} {8 "tip inside blocks" 6 "tip at block ends vs CL"} {
        set xs {}
        set ys {}
        set i 0
        foreach r $rows {
            if {[lindex $r $k] ne ""} {lappend xs $i; lappend ys [lindex $r $k]}
            incr i
        }
        if {[llength $xs]} {lappend dev [list "$label (mm)" $xs $ys]}
    }
    set deviation [::fivax::svgplot chart -title "Tool tip deviation, [file tail $file]" \
        -xlabel "block (written motion blocks in file order)" -ylabel "deviation (mm)" \
        -series $dev -limit [list $tol "tolerance $tol mm"]]
    set path [::fivax::svgplot projections -title "Back-plotted tool path, [file tail $file]" \
        -points [lmap r $rows {lindex $r 4}] -axes [lmap r $rows {lindex $r 5}] \
        -every [expr {max(1, $n / 150)}] -whisker 10]
    set out {}
    foreach {kind text} [list axes $axes deviation $deviation path $path] {
        lappend out [::fivax::svgplot write $prefix-$kind.svg $text]
    }
    return $out
}

# ::verifytool::main -- Parses argv, checks the file, prints the report, exits.
proc ::verifytool::main {argv} {
    lassign [ParseArgs $argv] opts path
    try {
        set machine [::fivax::machine load [dict get $opts -machine]]
        if {[dict get $opts -controller] ne "" &&
                [dict get $opts -controller] ni [::fivax::verify dialects]} {
            Die "verify: bad -controller \"[dict get $opts -controller]\": must be one of\
                [join [::fivax::verify dialects] {, }]"
        }
        lassign [Run $opts $path $machine] ops rows problems warnings names
    } trap {FIVAX} {msg} {
        Die "verify: $msg"
    } trap {POSIX} {msg} {
        Die "verify: $msg"
    }
    Say $opts "verify: [file tail $path] on [dict get $machine name] ([dict get $opts -machine])"
    Report $opts $ops $names [expr {[dict get $opts -cl] ne ""}]
    dict for {kind n} $warnings {
        Say $opts "verify: warning: $n words of kind '$kind' not understood"
    }
    set tool [expr {[dict get $opts -tool-length] ne "" ? [dict get $opts -tool-length] :
        [dict get $machine tool_length]}]
    try {
        if {[dict get $opts -csv] ne ""} {
            Csv [dict get $opts -csv] $rows $names
            Say $opts "verify: wrote [dict get $opts -csv]"
        }
        if {[dict get $opts -o] ne ""} {
            Clsf [dict get $opts -o] $rows $tool
            Say $opts "verify: wrote [dict get $opts -o]"
        }
        if {[dict get $opts -svg] ne ""} {
            foreach f [Plots [dict get $opts -svg] $rows $names [dict get $opts -tol] $path] {
                Say $opts "verify: wrote $f"
            }
        }
    } trap {POSIX} {msg} {
        Die "verify: cannot write: $msg"
    }
    if {[llength $problems]} {
        foreach p $problems {puts "verify: FAIL: $p"}
        exit 1
    }
    puts [format "verify: PASS: %d blocks within %g mm and %g deg" [llength $rows] \
        [dict get $opts -tol] [dict get $opts -atol]]
}

::verifytool::main $argv
