# verify.tcl --
#	Checks written NC blocks against the CL data they stand for: reads the
#	axis words back from the block text (so output rounding counts), runs
#	the forward kinematics (never the inverse) and measures the tip and axis
#	deviation at each CL point and, for cutting moves, at the quarter points
#	of the controller's linear joint interpolation against the straight CL
#	segment and the great circle of the tool axis (spec section 7).

namespace eval ::fivax::verify {
    namespace export create setTool block summary
    variable seq 0
    variable pi 3.141592653589793
}

# ::fivax::verify::create --
#	Returns a checker for machine; option -tableOffset {x y z} as for the planner.
proc ::fivax::verify::create {machine args} {
    variable seq
    set h ::fivax::verify::check[incr seq]
    upvar #0 $h S
    set S(tableOffset) ""
    foreach {opt val} $args {
        switch -- $opt {
            -tableOffset {set S(tableOffset) $val}
            default {::fivax::Fail VERIFY OPTION "bad option \"$opt\": must be -tableOffset"}
        }
    }
    set S(machine) $machine
    set S(names) [lmap axis [dict get $machine chain] {dict get $axis name}]
    set S(limits) [lmap axis [dict get $machine chain] {
        if {[dict get $axis continuous] && [dict get $axis rollover]} {
            list -1e300 1e300
        } else {
            list [dict get $axis min] [dict get $axis max]
        }
    }]
    array set S {X {} Y {} Z {} q1 {} q2 {} prev {} checked 0 segments 0
        maxPos 0.0 maxAng 0.0 maxMidPos 0.0 maxMidAng 0.0 limitViolations 0
        worst {} worstMid {}}
    setTool $h [dict get $machine tool_length]
    return $h
}

# ::fivax::verify::setTool -- Switches the checker to a tool of length len (mm).
proc ::fivax::verify::setTool {h len} {
    upvar #0 $h S
    if {$S(tableOffset) eq ""} {
        set S(model) [::fivax::kin::model $S(machine) $len]
    } else {
        set S(model) [::fivax::kin::model $S(machine) $len $S(tableOffset)]
    }
    set S(prev) {}
}

# ::fivax::verify::block --
#	Reads the axis words of the NC line, updates the modal machine state,
#	and when move carries a CL target (P, t) measures the deviation.
proc ::fivax::verify::block {h line move} {
    upvar #0 $h S
    variable pi
    set text [regsub -all {\([^)]*\)} $line ""]
    foreach {- letter value} [regexp -all -inline {([A-Z])([-+]?[0-9]*\.?[0-9]+)} $text] {
        if {$letter in {X Y Z}} {
            set S($letter) $value
        } elseif {[set i [lsearch -exact $S(names) $letter]] >= 0} {
            set q [expr {$value * $pi / 180.0}]
            lassign [lindex $S(limits) $i] min max
            if {$q < $min - 1e-9 || $q > $max + 1e-9} {incr S(limitViolations)}
            set S(q[expr {$i + 1}]) $q
        }
    }
    set P [dict get $move P]
    if {$P eq "" || $S(X) eq "" || $S(Y) eq "" || $S(Z) eq "" || $S(q1) eq "" || $S(q2) eq ""} {
        if {$P eq ""} {set S(prev) {}}
        return
    }
    set t [dict get $move t]
    set joints [list $S(X) $S(Y) $S(Z) $S(q1) $S(q2)]
    lassign [::fivax::kin::forward $S(model) $joints] Pm tm
    set dp [::fivax::vec::norm [::fivax::vec::sub $Pm $P]]
    set da [expr {[::fivax::vec::angle $tm $t] * 180.0 / $pi}]
    incr S(checked)
    if {$dp > $S(maxPos)} {set S(maxPos) $dp; set S(worst) [dict get $move src]}
    if {$da > $S(maxAng)} {set S(maxAng) $da}
    if {[dict get $move kind] eq "feed" && $S(prev) ne ""} {
        Segment $h $S(prev) $joints $P $t [dict get $move src]
    }
    set S(prev) [list $joints $P $t]
}

# ::fivax::verify::Segment --
#	Measures the tip and axis at the quarter points of the linear joint
#	interpolation from the previous checked block to joints.
proc ::fivax::verify::Segment {h prev joints P t src} {
    upvar #0 $h S
    variable pi
    lassign $prev j0 P0 t0
    incr S(segments)
    foreach s {0.25 0.5 0.75} {
        set js [lmap a $j0 b $joints {expr {$a + $s * ($b - $a)}}]
        lassign [::fivax::kin::forward $S(model) $js] Ps ts
        set dp [SegmentDistance $Ps $P0 $P]
        set da [expr {[GreatCircleDistance $ts $t0 $t] * 180.0 / $pi}]
        if {$dp > $S(maxMidPos)} {set S(maxMidPos) $dp; set S(worstMid) $src}
        if {$da > $S(maxMidAng)} {set S(maxMidAng) $da}
    }
}

# ::fivax::verify::SegmentDistance -- Returns the distance from point p to segment a-b.
proc ::fivax::verify::SegmentDistance {p a b} {
    set ab [::fivax::vec::sub $b $a]
    set len2 [::fivax::vec::dot $ab $ab]
    set u [expr {$len2 > 0 ? [::fivax::vec::dot [::fivax::vec::sub $p $a] $ab] / $len2 : 0.0}]
    set u [expr {min(1.0, max(0.0, $u))}]
    ::fivax::vec::norm [::fivax::vec::sub $p [::fivax::vec::lerp $a $b $u]]
}

# ::fivax::verify::GreatCircleDistance --
#	Returns the angle (rad) from unit t to the great-circle arc a-b.
proc ::fivax::verify::GreatCircleDistance {t a b} {
    set n [::fivax::vec::cross $a $b]
    set len [::fivax::vec::norm $n]
    if {$len < 1e-12} {return [::fivax::vec::angle $t $a]}
    set n [::fivax::vec::scale [expr {1.0 / $len}] $n]
    # Inside the arc's wedge the distance is to the plane, else to an end.
    set proj [::fivax::vec::sub $t [::fivax::vec::scale [::fivax::vec::dot $t $n] $n]]
    if {[::fivax::vec::dot [::fivax::vec::cross $a $proj] $n] >= 0
            && [::fivax::vec::dot [::fivax::vec::cross $proj $b] $n] >= 0} {
        return [expr {asin(min(1.0, abs([::fivax::vec::dot $t $n])))}]
    }
    expr {min([::fivax::vec::angle $t $a], [::fivax::vec::angle $t $b])}
}

# ::fivax::verify::summary --
#	Returns a dict: checked (CL points), segments, maxPos (mm), maxAng (deg)
#	at the CL points, maxMidPos (mm), maxMidAng (deg) inside cutting moves,
#	limitViolations, worst and worstMid (FILE:LINE of the largest errors).
proc ::fivax::verify::summary {h} {
    upvar #0 $h S
    dict create checked $S(checked) segments $S(segments) maxPos $S(maxPos) \
        maxAng $S(maxAng) maxMidPos $S(maxMidPos) maxMidAng $S(maxMidAng) \
        limitViolations $S(limitViolations) worst $S(worst) worstMid $S(worstMid)
}
