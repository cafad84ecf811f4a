# verify.tcl --
#	Checks an NC program on a virtual machine: reads every block (of any
#	controller of lib/dialect/, from fivax or another post), maps it back by forward
#	kinematics (never the inverse) and reports per operation the tool tip
#	and axis deviation at block ends (with -cl: the tip's distance from
#	the CL path, at most the post's figure, its distance from the CL
#	point it aimed at, by the tip's error along the path: up to 0.0002
#	mm on the bundled and corpus files) and
#	inside joint-space moves (the controller's linear joint interpolation
#	at the quarter points against the straight CL segment the move lies
#	on with -cl, as the post measures it; without, against the straight
#	line between the block ends), rotary travel,
#	rapids after cutting and (with -cl) limit retracts, as the post
#	counts them, rotary values outside the limits, feed anomalies and
#	canned-cycle holes not drilled along the tool axis, and names the
#	worst NC line; then a machine dry run (lib/dryrun.tcl, -dryrun on by
#	default) prints its events, one line "FILE:LINE: kind: what" each.
#	Exits 1 when a figure exceeds the tolerances, a value is outside the
#	limits, a feed is wrong, a hole is drilled off the tool axis, a word
#	or block is not understood or the dry run has an event.
#
#	tclsh tools/verify.tcl -machine M.tcl ?options? part.nc   (-help)

package require Tcl 8.6

set root [file dirname [file dirname [file normalize [info script]]]]
set auto_path [linsert $auto_path 0 [file join $root lib]]
package require fivax::host 0.1
foreach f {toolpath.tcl clpath.tcl svgplot.tcl nctool.tcl} {
    source [file join $root tools lib $f]
}

namespace eval ::verifytool {
    # S: the state of one run (see Run)
    variable S
    variable Options {
        {-machine text {} FILE "machine file, or a shipped machine's name: dmu125p is machines/dmu125p.tcl (required)"}
        {-cl text {} FILE "CLSF the program was posted from: block ends are compared with its CL path"}
        {-msys bool 0 "" "map the CL data through the CLSF's MSYS frame (as replay -msys)"}
        {-tol {real min 0} 0.01 MM "tip tolerance at block ends and inside blocks"}
        {-atol {real min 0} 0.05 DEG "tool axis tolerance"}
        {-mid-tol {maybe real min 0} {} MM "tip tolerance inside blocks (default: -tol)"}
        {-mid-atol {maybe real min 0} {} DEG "tool axis tolerance inside blocks (default: -atol)"}
        {-controller {maybe word} {} NAME "dialect of the NC text (default: the machine's controller)"}
        {-tool-length {maybe real} {} MM "tool length of every tool the CL (-cl) gives none (a CL TLDATA wins, as in the post; default: each tool's from -tools, else the program's FIVAX TOOL comments, else the machine's tool_length)"}
        {-table-offset {maybe vec3} {} "X Y Z" "workpiece-frame position of the table reference point"}
        {-arc-tol {real gt 0} 0.002 MM "chord tolerance of CL arcs (the post's -arc-tol)"}
        {-cutcom3d {enum off post control} off MODE "the program was posted with -cutcom3d post: the CL's cutting points with contact data (-cl) are moved for the cutter -tool-diameter, -tool-corner-radius as the post moved them; control: the control compensates, the CL's points are the path (as off)"}
        {-tool-diameter {maybe real gt 0} {} MM "diameter of the cutter of -cutcom3d post"}
        {-tool-corner-radius {maybe real min 0} {} MM "corner radius of the cutter of -cutcom3d post (default: the CL cutter's)"}
        {-window {int min 1} 32 N "CL segments searched ahead of the last match"}
        {-dryrun {enum on off} on WHEN "machine dry run: spindle, rapids and bodies through the stock, length compensation, modes, tool lengths, program end"}
        {-stock {maybe reals 6} {} "X0 Y0 Z0 X1 Y1 Z1"
            "the dry run's stock box in the workpiece frame (default: the part as the program's own cuts show it)"}
        {-tools text {} FILE "tool table: lines \"T<n> LENGTH <L> ?RADIUS <R>?\" (# comments): each tool's length for the kinematics and the dry run"}
        {-csv text {} FILE "write one row per block: line, op, motion, axes, back-plotted tip and axis, deviations"}
        {-o text {} FILE "write the back-plotted tip path and tool axis as a CLSF"}
        {-svg text {} PREFIX "write PREFIX-axes.svg, PREFIX-deviation.svg and PREFIX-path.svg"}
        {-quiet bool 0 "" "print the verdict line only"}
        {-help bool 0 "" "print this help"}
    }
}

# ::verifytool::Say -- Prints msg on standard output unless quiet.
proc ::verifytool::Say {opts msg} {
    if {![dict get $opts -quiet]} {puts $msg}
}

# ::verifytool::ParseArgs -- Returns {opts ncPath} from argv.
proc ::verifytool::ParseArgs {argv} {
    variable Options
    lassign [::fivax::nctool args $Options $argv verify \
        "tclsh tools/verify.tcl -machine M.tcl ?options? part.nc" \
        "Checks an NC program by forward kinematics." 1 -machine] opts rest
    try {
        ::fivax::settings cutter $opts verify
    } trap {FIVAX OPTION} {msg} {
        ::fivax::nctool die $msg
    }
    list $opts [lindex $rest 0]
}

# ::verifytool::NewOp -- Returns the statistics dict of a new operation name.
proc ::verifytool::NewOp {name} {
    dict create name $name blocks 0 feeds 0 moves 0 endPos 0.0 endPosAt {} endAng 0.0 \
        endAngAt {} midPos 0.0 midPosAt {} midAng 0.0 midAngAt {} arcPos 0.0 arcPosAt {} \
        arcAng 0.0 arcAngAt {} travel {0.0 0.0} \
        rapids 0 limitRetracts 0 limits 0 limitAt {} feedIssues 0 feedAt {} drills 0 drillAt {}
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
#	Checks the NC file path with the options on machine and the tool
#	table tools; returns {ops rows problems warnings names lines}: the
#	operation statistics, one row per motion block (see Csv), the failed
#	checks, the counts of words not understood by kind, the rotary names
#	(chain order) and the file's lines.
proc ::verifytool::Run {opts path machine tools} {
    variable S
    array unset S
    array set S [list opts $opts path $path machine $machine ops {} op [NewOp program] lines {} \
        opIndex -1 clPoints {} clLength "" length "" cursor 0 prev {} cutU "" breakU "" rows {} \
        warnings {} tooling [::fivax::dryrun tooling $tools [dict get $opts -tool-length]] \
        names [lmap a [dict get $machine chain] {dict get $a name}] \
        rollover [lmap a [dict get $machine chain] {dict get $a rollover}] cl {} \
        cutcom 0 cutcomBlocks 0]
    set S(checker) [::fivax::verify create $machine -table-offset [dict get $opts -table-offset] \
        -controller [dict get $opts -controller]]
    if {[dict get $opts -cl] ne ""} {
        set cutter {}
        if {[dict get $opts -cutcom3d] eq "post"} {
            set cutter [list [dict get $opts -tool-diameter] [dict get $opts -tool-corner-radius]]
        }
        set S(cl) [::fivax::clpath read [dict get $opts -cl] [dict get $opts -msys] \
            [dict get $opts -arc-tol] [dict get $machine units] $cutter]
    }
    SetLength
    set lineNo 0
    set chan [::fivax::nctool open $path]
    try {
        while {[gets $chan line] >= 0} {
            incr lineNo
            lappend S(lines) $line
            Line $line $path:$lineNo $lineNo
        }
    } finally {
        close $chan
        $S(checker) destroy
    }
    if {[dict get $S(op) blocks] || $S(opIndex) >= 0} {lappend S(ops) $S(op)}
    if {![llength $S(rows)]} {NoRows}
    if {[llength $S(cl)] && [llength $S(cl)] != $S(opIndex) + 1} {
        puts stderr "verify: warning: [llength $S(cl)] CL operations, [expr {$S(opIndex) + 1}] in the NC file"
    }
    list $S(ops) $S(rows) [Problems] $S(warnings) $S(names) $S(lines)
}

# ::verifytool::DryRun --
#	Returns the dry run's events of the NC lines on machine with the tool
#	table tools as lines "FILE:LINE: kind: what" (none with -dryrun off).
proc ::verifytool::DryRun {opts path machine lines tools} {
    if {[dict get $opts -dryrun] eq "off"} {return {}}
    set args [list -tools $tools -controller [dict get $opts -controller] \
        -table-offset [dict get $opts -table-offset] -tool-length [dict get $opts -tool-length] \
        -stock [dict get $opts -stock]]
    ::fivax::dryrun format [::fivax::dryrun run $machine $lines {*}$args] $path
}

# ::verifytool::Line -- Checks one NC line (at where, line number n).
proc ::verifytool::Line {line where n} {
    variable S
    set blk [$S(checker) read $line]
    foreach c [dict get $blk comments] {
        if {[regexp {^\s*OPERATION\s+(.*?)\s*$} $c -> name]} {StartOp $name}
    }
    Cutcom $line $blk
    set S(tooling) [::fivax::dryrun toolStep $S(tooling) $blk]
    foreach note [dict get $S(tooling) notes] {
        lassign $note kind what
        # (a tool comment the follower cannot read: the others are the dry run's)
        if {$kind eq "unreadable"} {Warn $where "tool comment" $what}
    }
    SetLength
    if {![dict get $blk block]} return
    dict incr S(op) blocks
    foreach {kind word} [dict get $blk unknown] {
        Warn $where $kind "$kind not understood ($word)"
    }
    foreach axis [dict get $blk limit] {
        dict incr S(op) limits
        if {[dict get $S(op) limitAt] eq ""} {dict set S(op) limitAt "$where ($axis)"}
    }
    set pose [dict get $blk pose]
    if {$pose eq "" || ![llength [dict get $blk moved]]} {
        if {[llength [dict get $blk moved]]} {set S(prev) {}}
        return
    }
    set joints [dict get $blk joints]
    lassign $pose P t
    dict incr S(op) moves
    Travel $joints
    set motion [dict get $blk motion]
    if {[$S(checker) countRapid $pose [dict get $blk moved] [dict get $blk hole]]} {
        dict incr S(op) rapids
        # a break in the cut, from the CL place of its last cutting block
        set S(breakU) $S(cutU)
    }
    set figures {{} {} {} {}}
    # the place on the CL path of this block's end (see Place)
    set S(endU) ""
    if {[dict get $blk hole]} {
        # a canned cycle's hole, checked at its bottom; its motions are
        # the controller's, and the tool ends on the return level
        set off [$S(checker) drillOff $joints $pose [dict get $blk space]]
        if {$off ne ""} {
            dict incr S(op) drills
            if {[dict get $S(op) drillAt] eq ""} {
                dict set S(op) drillAt [format "%s: %.3f deg off" $where $off]
            }
        }
        set S(prev) {}
        set figures [Cutting $blk $joints $P $t $where Bottom]
        lappend S(rows) [list $n [dict get $S(op) name] 1 $joints $P $t {*}$figures \
            [dict get $blk F] [dict get $blk mode] $S(length) [Cutter]]
        return
    }
    if {$motion in {1 2 3}} {
        set figures [Cutting $blk $joints $P $t $where]
    } elseif {[llength $S(clPoints)]} {
        set S(endU) [Place $P $t]
    }
    lappend S(rows) [list $n [dict get $S(op) name] $motion $joints $P $t {*}$figures \
        [dict get $blk F] [dict get $blk mode] $S(length) [Cutter]]
    set S(prev) [list $joints $P $t $S(endU)]
}

# ::verifytool::StartOp --
#	Starts operation name: its statistics, the matching CL operation (by
#	order) and its tool length (SetLength).
proc ::verifytool::StartOp {name} {
    variable S
    if {[dict get $S(op) blocks] || $S(opIndex) >= 0} {lappend S(ops) $S(op)}
    set S(op) [NewOp $name]
    incr S(opIndex)
    set S(prev) {}
    set S(cutU) ""
    set S(breakU) ""
    set S(cursor) 0
    set S(clPoints) {}
    set S(clLength) ""
    if {$S(opIndex) < [llength $S(cl)]} {
        set clop [lindex $S(cl) $S(opIndex)]
        set S(clPoints) [dict get $clop points]
        set S(clLength) [dict get $clop length]
    }
    SetLength
}

# ::verifytool::SetLength --
#	Computes with the tool length of the CL operation (its TLDATA: it wins,
#	as in the post), else the tool follower's (-tool-length, else the tool
#	table's for the tool in the spindle, else the program's FIVAX TOOL
#	comment), else the machine's tool_length.
proc ::verifytool::SetLength {} {
    variable S
    set len $S(clLength)
    if {$len eq ""} {set len [dict get $S(tooling) length]}
    if {$len eq ""} {set len [dict get $S(machine) tool_length]}
    if {$S(length) ne "" && $len == $S(length)} return
    set S(length) $len
    $S(checker) setTool $len
}

# ::verifytool::Cutcom --
#	Follows 2D cutter radius compensation (G41/G42 on, G40 off; in the
#	klartext syntax RL/RR, R0) through the NC line and its read block blk, counting the
#	motion blocks under it: they are back-plotted as programmed (the
#	path the CL gives), while the control offsets them by the radius in
#	its register (the post's programs: the wear).
proc ::verifytool::Cutcom {line blk} {
    variable S
    foreach {letter v} [dict get $blk words] {
        if {$letter eq "G" && $v in {40 41 42}} {set S(cutcom) [expr {$v != 40}]}
    }
    # (the klartext syntax: the radius word of an L or C block)
    if {[regexp {^\s*\d+\s+[LC]\M.*\mR([0LR])(\s|$)} $line -> side]} {
        set S(cutcom) [expr {$side ne "0"}]
    }
    if {$S(cutcom) && [llength [dict get $blk moved]]} {incr S(cutcomBlocks)}
}

# ::verifytool::Cutter --
#	Returns {D r}, the cutter of a program compensated for it (its FIVAX
#	TOOL comment gives RADIUS and CORNER: -cutcom3d post), else "".
proc ::verifytool::Cutter {} {
    variable S
    set corner [dict get $S(tooling) corner]
    if {$corner eq ""} {return ""}
    list [expr {2.0 * [dict get $S(tooling) radius]}] $corner
}

# ::verifytool::Warn --
#	Counts a word of kind not understood at where; says what on standard
#	error the first time of its kind.
proc ::verifytool::Warn {where kind what} {
    variable S
    if {![dict exists $S(warnings) $kind]} {puts stderr "verify: $where: $what"}
    dict incr S(warnings) $kind
}

# ::verifytool::Travel --
#	Adds the rotary motion from the previous block to joints (a rotary
#	that rolls over turns the shortest way).
proc ::verifytool::Travel {joints} {
    variable S
    if {$S(prev) eq "" || $joints eq "" || [lindex $S(prev) 0] eq ""} return
    set twoPi [expr {2.0 * acos(-1)}]
    set tr {}
    foreach i {3 4} roll $S(rollover) acc [dict get $S(op) travel] {
        set d [expr {[lindex $joints $i] - [lindex $S(prev) 0 $i]}]
        if {$roll} {set d [expr {$d - $twoPi * round($d / $twoPi)}]}
        lappend tr [expr {$acc + abs($d)}]
    }
    dict set S(op) travel $tr
}

# ::verifytool::Cutting --
#	Checks a cutting block (G1) ending at joints, tip P, axis t: its feed,
#	the inside of the move, and the end against the CL path (by match:
#	Match, or Bottom for a hole). Returns
#	{endPos endAng midPos midAng} ("" where not measured).
proc ::verifytool::Cutting {blk joints P t where {match Match}} {
    variable S
    dict incr S(op) feeds
    set issue [FeedIssue $blk]
    if {$issue ne ""} {
        dict incr S(op) feedIssues
        if {[dict get $S(op) feedAt] eq ""} {dict set S(op) feedAt "$where: $issue"}
    }
    set out {{} {} {} {}}
    set inside {}
    # (an arc is followed along the CL path from the cursor at its start)
    set arc [dict get $blk arc]
    if {$arc ne ""} {set inside [ArcInside $arc [dict get $blk words]]}
    if {[llength $S(clPoints)]} {
        lassign [$match $P $t] endPos endAng S(endU)
        Max S(op) endPos $endPos $where
        Max S(op) endAng $endAng $where
        lset out 0 $endPos
        lset out 1 $endAng
        if {[LimitRetract $S(breakU) $S(endU)]} {dict incr S(op) limitRetracts}
        set S(breakU) ""
        set S(cutU) $S(endU)
    }
    if {$arc eq "" && $S(prev) ne "" && [dict get $blk space] eq "joint" && $joints ne ""
            && [lindex $S(prev) 0] ne ""} {
        # joint mode: the control interpolates the joints linearly (in TCP
        # mode and in a work plane it keeps the tip on the line itself)
        lassign $S(prev) j0 P0 t0 u0
        set segs [Segments $u0 $S(endU) $P0 $P]
        if {![llength $segs]} {set segs [list [list $P0 $P $t0 $t]]}
        # the best fit: the least of the tip's and the axis's errors in
        # parts of their tolerances
        set tol [dict get $S(opts) -tol]
        set atol [dict get $S(opts) -atol]
        set best Inf
        foreach seg $segs {
            lassign [$S(checker) interior $j0 $joints {*}$seg] dp da
            set e [expr {max($tol > 0 ? $dp / $tol : $dp, $atol > 0 ? $da / $atol : 0.0)}]
            if {$e < $best} {
                set best $e
                set inside [list $dp $da]
            }
        }
    }
    if {[llength $inside]} {
        # (arcs apart: the post measures the inside of joint-space blocks)
        set key [expr {$arc ne "" ? "arc" : "mid"}]
        lassign $inside midPos midAng
        Max S(op) ${key}Pos $midPos $where
        Max S(op) ${key}Ang $midAng $where
        lset out 2 $midPos
        lset out 3 $midAng
    }
    return $out
}

# ::verifytool::LimitRetract --
#	Returns 1 when a break in the cut (rapids after cutting) from CL place
#	u0 resumes cutting at CL place u1 with no CL point reached by a RAPID
#	in between nor at u1: the CL cuts on there, so the break is the
#	post's (a retract where no cutting move could continue, the post's
#	"limit retracts"). 0 when either place is unknown.
proc ::verifytool::LimitRetract {u0 u1} {
    variable S
    if {$u0 eq "" || $u1 eq ""} {return 0}
    for {set k [expr {int(floor($u0)) + 1}]} {$k <= round($u1)} {incr k} {
        if {[lindex $S(clPoints) $k 3]} {return 0}
    }
    return 1
}

# ::verifytool::Segments --
#	Returns the CL segments ({A B tA tB}: ends and axes) a joint-space
#	block from CL place u0 to u1 (see Place), tips P0 to P1, may lie on,
#	its inside being measured against the one it fits best: the segment
#	holding the middle of the two places, as the post splits a CL move
#	only along its segment (the block ends themselves may match just
#	across a CL point); for a block shorter than 2 -tol, where the
#	rounding of its ends leaves that in doubt (or the tip hardly moves
#	while the axis turns), also the segments either side. Only segments both ends lie within -tol of; none when either
#	end has no place (the inside is then measured against the straight
#	line between the block ends).
proc ::verifytool::Segments {u0 u1 P0 P1} {
    variable S
    if {$u0 eq "" || $u1 eq ""} {return {}}
    set n [llength $S(clPoints)]
    if {$n < 2} {return {}}
    set tol [dict get $S(opts) -tol]
    set mid [expr {int(floor(0.5 * ($u0 + $u1)))}]
    set near [list $mid]
    if {[::fivax::vec::dist $P0 $P1] < 2.0 * $tol} {lappend near [expr {$mid - 1}] [expr {$mid + 1}]}
    set out {}
    foreach i $near {
        set i [expr {min($n - 2, max(0, $i))}]
        lassign [lindex $S(clPoints) $i] A tA
        lassign [lindex $S(clPoints) [expr {$i + 1}]] B tB
        if {[lindex [::fivax::clpath::Project $A $B $P0] 0] <= $tol
                && [lindex [::fivax::clpath::Project $A $B $P1] 0] <= $tol} {
            lappend out [list $A $B $tA $tB]
        }
    }
    return $out
}

# ::verifytool::Place --
#	Returns the place (segment index plus fraction) on the CL path of a
#	rapid block's end P, t when within -tol of the path ahead of the last
#	match (moving the cursor there), else "".
proc ::verifytool::Place {P t} {
    variable S
    lassign [::fivax::clpath nearest $S(clPoints) $P $t $S(cursor) \
        [dict get $S(opts) -window]] d i s
    if {$d eq "" || $d > [dict get $S(opts) -tol]} {return ""}
    set S(cursor) $i
    expr {$i + $s}
}

# ::verifytool::ArcInside --
#	Returns {d a} for an arc block (arc: {start centre plane dir} in the
#	block's space): the largest distance (mm) of its points within
#	-arc-tol from the CL path and the angle (deg) of the axis from the
#	CL axis there; {} without a CL path. The cursor stays.
proc ::verifytool::ArcInside {arc words} {
    variable S
    if {![llength $S(clPoints)]} {return {}}
    lassign $arc start centre plane dir
    set normal [dict get {17 {0 0 1} 18 {0 1 0} 19 {1 0 0}} $plane]
    set end [lmap c {X Y Z} s $start {
        expr {[dict exists $words $c] ? [dict get $words $c] : $s}
    }]
    set worst {0.0 0.0}
    foreach q [::fivax::curve::arc $start $end $centre $normal [expr {$dir == 3 ? 1 : -1}] 0 \
            [dict get $S(opts) -arc-tol]] {
        lassign [$S(checker) poseAt $q] P t
        lassign [::fivax::clpath nearest $S(clPoints) $P $t $S(cursor) \
            [dict get $S(opts) -window]] d - - - tq
        if {$d > [dict get $S(opts) -tol]} {
            lassign [::fivax::clpath nearest $S(clPoints) $P $t $S(cursor) -1] d - - - tq
        }
        set a [::fivax::num::deg [::fivax::vec::angle $t $tq]]
        set worst [list [expr {max([lindex $worst 0], $d)}] [expr {max([lindex $worst 1], $a)}]]
    }
    return $worst
}

# ::verifytool::FeedIssue --
#	Returns what is wrong with the feed of cutting block blk ("" if
#	nothing): G93 without F, no F at all, F not positive, F above the
#	machine's feed_max (G94) or inverse_time_max (G93).
proc ::verifytool::FeedIssue {blk} {
    variable S
    set F [dict get $blk F]
    set mode [dict get $blk mode]
    if {$mode eq "inverse" && $F eq ""} {return "G93 block without F"}
    set f [expr {$F ne "" ? $F : [dict get $blk feed]}]
    if {$f eq ""} {return "feed move without any F"}
    if {$f <= 0} {return "F $f is not positive"}
    set invMax [dict get $S(machine) inverse_time_max]
    set feedMax [dict get $S(machine) feed_max]
    if {$mode eq "inverse" && $f > $invMax} {
        return "inverse-time F $f above the machine's inverse_time_max $invMax"
    }
    if {$mode eq "direct" && $f > $feedMax} {
        return "F $f mm/min above the machine's feed_max $feedMax"
    }
    return ""
}

# ::verifytool::Match --
#	Returns {d a u}: the distance (mm) of tip P from the CL path (PathDistance),
#	the angle (deg) of axis t from the CL axis at the match and its place
#	(segment index plus fraction), searching ahead of the
#	last match (the whole operation when the window finds nothing within
#	-tol); moves the cursor to the match.
proc ::verifytool::Match {P t} {
    variable S
    lassign [::fivax::clpath nearest $S(clPoints) $P $t $S(cursor) \
        [dict get $S(opts) -window]] d i s Q tq
    if {$d > [dict get $S(opts) -tol]} {
        set far [::fivax::clpath nearest $S(clPoints) $P $t $S(cursor) -1]
        if {[lindex $far 0] < $d} {lassign $far d i s Q tq}
    }
    set S(cursor) $i
    list [PathDistance $P $i] [::fivax::num::deg [::fivax::vec::angle $t $tq]] [expr {$i + $s}]
}

# ::verifytool::PathDistance --
#	Returns the distance (mm) of tip P from the CL path next to its match
#	on segment i: the nearest point of segments i - 1 to i + 1. (The
#	match itself blends tip and axis to find the place; the distance is
#	the tip's own, never more than its distance from the CL point the
#	post aimed at, which lies on that path.)
proc ::verifytool::PathDistance {P i} {
    variable S
    set last [expr {[llength $S(clPoints)] - 1}]
    if {$last < 1} {return [::fivax::vec::dist $P [lindex $S(clPoints) 0 0]]}
    set d Inf
    for {set k [expr {max(0, $i - 1)}]} {$k <= min($last - 1, $i + 1)} {incr k} {
        set dk [lindex [::fivax::clpath::Project [lindex $S(clPoints) $k 0] \
            [lindex $S(clPoints) [expr {$k + 1}] 0] $P] 0]
        if {$dk < $d} {set d $dk}
    }
    return $d
}

# ::verifytool::Bottom --
#	Returns {d a} as Match does for the bottom P, t of a canned cycle's
#	hole, measured to the nearest hole bottom of the CL path (a point
#	reached by feed), never to a point between: a hole too short or too
#	deep fails.
proc ::verifytool::Bottom {P t} {
    variable S
    set n [llength $S(clPoints)]
    set best {Inf 0}
    foreach from [list $S(cursor) 0] to [list [expr {$S(cursor) + [dict get $S(opts) -window]}] $n] {
        for {set i $from} {$i < min($to, $n)} {incr i} {
            lassign [lindex $S(clPoints) $i] Q tq src rapid
            if {$rapid} continue
            set d [::fivax::vec::norm [::fivax::vec::sub $P $Q]]
            if {$d < [lindex $best 0]} {set best [list $d $i]}
        }
        if {[lindex $best 0] <= [dict get $S(opts) -tol]} break
    }
    lassign $best d i
    set S(cursor) $i
    list $d [::fivax::num::deg [::fivax::vec::angle $t [lindex $S(clPoints) $i 1]]]
}

# ::verifytool::NoRows --
#	Fails: no block gave every axis of the machine (naming the letters
#	the file writes that the machine lacks).
proc ::verifytool::NoRows {} {
    variable S
    set letters [lmap k [dict keys $S(warnings)] {
        if {[string match "letter *" $k]} {string range $k 7 end} else continue
    }]
    ::fivax::Fail TOOL MACHINE "$S(path): no block gives all of X Y Z [join $S(names) { }] of\
        machine [dict get $S(machine) name][expr {[llength $letters] ?
            "; the file writes [join $letters {, }]: is it for another machine?" : ""}]"
}

# ::verifytool::Problems -- Returns the failed checks of the operations, one text each.
proc ::verifytool::Problems {} {
    variable S
    set opts $S(opts)
    set tol [dict get $opts -tol]
    set atol [dict get $opts -atol]
    set midTol [dict get $opts -mid-tol]
    if {$midTol eq ""} {set midTol $tol}
    set midAtol [dict get $opts -mid-atol]
    if {$midAtol eq ""} {set midAtol $atol}
    set problems {}
    foreach op $S(ops) {
        dict with op {}
        foreach {key lim unit what} [list endPos $tol mm "tip off the CL path" \
                endAng $atol deg "axis off the CL axis" midPos $midTol mm "tip inside a block" \
                midAng $midAtol deg "axis inside a block" arcPos $midTol mm "tip inside an arc" \
                arcAng $midAtol deg "axis inside an arc"] {
            if {[dict get $op $key] > $lim} {
                lappend problems [format "%s: %s %.6f %s > %g at %s" $name $what \
                    [dict get $op $key] $unit $lim [dict get $op ${key}At]]
            }
        }
        if {$limits} {lappend problems "$name: $limits rotary values outside the limits, first at $limitAt"}
        if {$feedIssues} {lappend problems "$name: $feedIssues feed anomalies, first at $feedAt"}
        if {$drills} {
            lappend problems "$name: $drills canned-cycle holes not drilled along the tool axis, first at $drillAt"
        }
    }
    return $problems
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
        append msg [format "; rotary travel %s %.3f deg, %s %.3f deg" \
            [lindex $names 0] [::fivax::num::deg [lindex $travel 0]] [lindex $names 1] \
            [::fivax::num::deg [lindex $travel 1]]]
        if {$hasCl} {
            append msg [format "; inside arcs vs CL: max %.6f mm at %s, %.6f deg" $arcPos \
                [Where $arcPosAt] $arcAng]
        }
        append msg [format "; %d rapids after cutting" $rapids]
        if {$hasCl} {append msg [format ", %d limit retracts" $limitRetracts]}
        append msg [format "; %d values outside limits; %d feed anomalies" $limits $feedIssues]
        Say $opts $msg
        foreach {key at} {endPos endPosAt midPos midPosAt arcPos arcPosAt} {
            if {[dict get $op $key] > $wv} {
                set wv [dict get $op $key]
                set worst [list [dict get $op $at] $key]
            }
        }
    }
    set rapids 0
    set limitRetracts 0
    foreach op $ops {
        incr rapids [dict get $op rapids]
        incr limitRetracts [dict get $op limitRetracts]
    }
    Say $opts "verify: program: $rapids rapids after cutting[expr {$hasCl ?
        ", $limitRetracts limit retracts" : ""}] (counted as the post's summary counts them)"
    if {$worst ne "" && [lindex $worst 0] ne ""} {
        Say $opts [format "verify: worst NC line %s (%s %.6f mm)" [lindex $worst 0] \
            [dict get {endPos "block end off the CL path" midPos "inside the block"
                arcPos "inside the arc"} [lindex $worst 1]] $wv]
    }
}

# ::verifytool::Where -- Returns where, or "-" when empty.
proc ::verifytool::Where {where} {
    expr {$where eq "" ? "-" : $where}
}

# ::verifytool::CsvFixed -- Returns v with d decimals, "" for "".
proc ::verifytool::CsvFixed {v d} {
    if {$v eq ""} {return ""}
    ::fivax::num::fixed $v $d
}

# ::verifytool::Csv -- Writes the rows as CSV to path.
proc ::verifytool::Csv {path rows names} {
    set out [list [join [list line op motion X Y Z {*}$names x y z i j k \
        end_dpos end_dangle mid_dpos mid_dangle F mode] ,]]
    foreach row $rows {
        lassign $row line op motion joints P t ep ea mp ma F mode
        lassign $joints X Y Z q1 q2
        set vals [list $line [::fivax::nctool::csvField $op] $motion]
        # (a work plane's rotaries are the control's: no joint values)
        foreach v [list $X $Y $Z] {lappend vals [CsvFixed $v 4]}
        foreach q [list $q1 $q2] {
            lappend vals [CsvFixed [expr {$q eq "" ? "" : [::fivax::num::deg $q]}] 4]
        }
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
#	operation (TLDATA: the tool length of its first block, and the cutter
#	a compensated program was run for, else diameter 0), RAPID before
#	G0 points, FEDRAT when the tip feed changes.
proc ::verifytool::Clsf {path rows} {
    set lines {}
    set op ""
    set last ""
    set lastFeed ""
    set prevP {}
    foreach row $rows {
        lassign $row - name motion joints P t - - - - F mode tool cutter
        if {$name ne $op} {
            if {$op ne ""} {lappend lines END-OF-PATH}
            lassign [expr {[llength $cutter] ? $cutter : {0 0}}] D r
            lappend lines "TOOL PATH/[regsub -all {[^A-Za-z0-9_.-]} $name _],TOOL,BACKPLOT" \
                [format "TLDATA/MILL,%s,%s,%s,0.0000,0.0000" [::fivax::num::fixed $D 4] \
                    [::fivax::num::fixed $r 4] [::fivax::num::fixed $tool 4]]
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

# ::verifytool::Plots --
#	Writes the three plots of the rows with names prefix-*.svg; returns
#	the paths. Their x axis is the NC file's line numbers, the worst lines
#	marked; rotary values that wrap (360 to 0) break the line; rapids are
#	dashed in the path.
proc ::verifytool::Plots {prefix rows names tol file} {
    set n [llength $rows]
    set lines [lmap r $rows {lindex $r 0}]
    set xlabel "NC line ([file tail $file])"
    set series {}
    foreach k {3 4} name $names {
        lappend series [list "$name (deg)" $lines [lmap r $rows {
            ::fivax::num::deg [lindex $r 3 $k]}]]
    }
    set axes [::fivax::svgplot chart -title "Rotary axes of [file tail $file]" \
        -xlabel $xlabel -ylabel "axis value (deg)" -series $series -zero 0 -wrap 360]
    set dev {}
    set all {{} {}}
    foreach {k label} {8 "tip inside blocks" 6 "tip at block ends vs CL"} {
        set xs {}
        set ys {}
        foreach r $rows {
            if {[lindex $r $k] ne ""} {lappend xs [lindex $r 0]; lappend ys [lindex $r $k]}
        }
        if {[llength $xs]} {lappend dev [list "$label (mm)" $xs $ys]}
        lset all 0 [concat [lindex $all 0] $xs]
        lset all 1 [concat [lindex $all 1] $ys]
    }
    set deviation [::fivax::svgplot chart -title "Tool tip deviation, [file tail $file]" \
        -xlabel $xlabel -ylabel "deviation (mm)" -series $dev -limit [list $tol "tolerance $tol mm"] \
        -marks [::fivax::svgplot worst {*}$all 3 "line "]]
    set path [::fivax::svgplot projections -title "Back-plotted tool path, [file tail $file]" \
        -points [lmap r $rows {lindex $r 4}] -axes [lmap r $rows {lindex $r 5}] \
        -rapids [lmap r $rows {expr {[lindex $r 2] == 0}}] -every [expr {max(1, $n / 150)}] -whisker 10]
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
        if {[dict get $opts -controller] ne ""} {
            ::fivax::dialect check [dict get $opts -controller] -controller
        }
        set tools [::fivax::nctool toolTable [dict get $opts -tools]]
        lassign [Run $opts $path $machine $tools] ops rows problems warnings names lines
        set events [DryRun $opts $path $machine $lines $tools]
    } trap {FIVAX} {msg} {
        ::fivax::nctool die "verify: $msg"
    } trap {POSIX} {msg} {
        ::fivax::nctool die "verify: $msg"
    }
    Say $opts "verify: [file tail $path] on [dict get $machine name] ([dict get $opts -machine])"
    if {$::verifytool::S(cutcomBlocks)} {
        puts stderr "verify: note: $::verifytool::S(cutcomBlocks) motion blocks under cutter radius\
            compensation (G41/G42, RL/RR) are back-plotted as programmed: the control offsets\
            them by the radius in its register"
    }
    Report $opts $ops $names [expr {[dict get $opts -cl] ne ""}]
    dict for {kind n} $warnings {
        lappend problems "$n words of kind '$kind' not understood (a program it cannot read is not verified)"
    }
    foreach event $events {puts $event}
    if {[dict get $opts -dryrun] eq "on" && ![llength $events]} {
        Say $opts "verify: dry run: 0 events (spindle, rapids and bodies against the stock, length\
            compensation, modes, tool lengths, program end)"
    }
    if {[llength $events]} {
        lappend problems "[llength $events] dry-run events (machine state, stock, bodies: listed above)"
    }
    try {
        if {[dict get $opts -csv] ne ""} {
            Csv [dict get $opts -csv] $rows $names
            Say $opts "verify: wrote [dict get $opts -csv]"
        }
        if {[dict get $opts -o] ne ""} {
            Clsf [dict get $opts -o] $rows
            Say $opts "verify: wrote [dict get $opts -o]"
        }
        if {[dict get $opts -svg] ne ""} {
            foreach f [Plots [dict get $opts -svg] $rows $names [dict get $opts -tol] $path] {
                Say $opts "verify: wrote $f"
            }
        }
    } trap {POSIX} {msg} {
        ::fivax::nctool die "verify: cannot write: $msg"
    }
    if {[llength $problems]} {
        foreach p $problems {puts "verify: FAIL: $p"}
        if {![dict get $opts -msys] && 1 in [lmap op $::verifytool::S(cl) {dict get $op msysTurns}]} {
            puts "verify: note: the CL file's MSYS record turns its MCS: a program posted with -msys is read with -msys"
        }
        exit 1
    }
    puts [format "verify: PASS: %d blocks within %g mm and %g deg" [llength $rows] \
        [dict get $opts -tol] [dict get $opts -atol]]
}

::verifytool::main $argv
