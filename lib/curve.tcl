# curve.tcl --
#	CL path geometry the post needs between two CL points: circular and
#	helical arcs (CIRCLE + GOTO) as points within a chord tolerance, and
#	split into pieces the way NX hands them to a post. Points are {x y z}
#	lists in mm.
#
#	An arc turns about the line through center along axis, clockwise
#	(sense -1) or counter-clockwise (sense 1) about axis, from start to
#	end plus turns extra full turns; radius and axial height vary linearly
#	with the angle (helixes, slightly inconsistent CL data). start = end
#	is a full circle.

namespace eval ::fivax::curve {
    namespace export arc arcSplit
    namespace ensemble create -prefixes 0
    namespace upvar ::fivax::num pi pi
}

# ::fivax::curve::arc --
#	Returns the points after start up to and including end of an arc (see
#	the file header) with chord error at most tol (mm).
proc ::fivax::curve::arc {start end center axis sense turns tol} {
    variable pi
    set frame [Frame $start $end $center $axis $sense $turns]
    if {$frame eq ""} {return [list $end]}
    lassign $frame - - - - r0 r1 - sweep
    set rmax [expr {max($r0, $r1)}]
    set step [expr {$tol >= $rmax ? $pi / 2.0 : 2.0 * acos(1.0 - $tol / $rmax)}]
    set count [expr {max(1, int(ceil($sweep / $step)))}]
    set out {}
    for {set i 1} {$i < $count} {incr i} {
        lappend out [Point $frame [expr {double($i) / $count}]]
    }
    lappend out $end
}

# ::fivax::curve::arcSplit --
#	Returns the pieces of an arc (see the file header) each turning at
#	most maxSweep (radians): a list of {endPoint sweep} (sweep in radians),
#	the last ending at end. A degenerate arc (start or end on the axis)
#	is one piece of sweep 0.
proc ::fivax::curve::arcSplit {start end center axis sense turns maxSweep} {
    set frame [Frame $start $end $center $axis $sense $turns]
    if {$frame eq ""} {return [list [list $end 0.0]]}
    set sweep [lindex $frame end-1]
    set count [expr {max(1, int(ceil($sweep / $maxSweep - 1e-9)))}]
    set out {}
    set done 0.0
    for {set i 1} {$i < $count} {incr i} {
        lappend out [list [Point $frame [expr {$i * $maxSweep / $sweep}]] $maxSweep]
        set done [expr {$done + $maxSweep}]
    }
    lappend out [list $end [expr {$sweep - $done}]]
}

# ::fivax::curve::Frame --
#	Returns {center n hs he r0 r1 u sweep sense} of an arc: unit axis n,
#	axial heights of start and end above center, their radii, the unit
#	radial direction u of start, the total sweep (radians, > 0) and the
#	sense; "" when start or end lies on the axis.
proc ::fivax::curve::Frame {start end center axis sense turns} {
    variable pi
    set n [::fivax::vec::unit $axis]
    set hs [::fivax::vec::dot [::fivax::vec::sub $start $center] $n]
    set he [::fivax::vec::dot [::fivax::vec::sub $end $center] $n]
    set rs [::fivax::vec::sub [::fivax::vec::sub $start $center] [::fivax::vec::scale $hs $n]]
    set re [::fivax::vec::sub [::fivax::vec::sub $end $center] [::fivax::vec::scale $he $n]]
    set r0 [::fivax::vec::norm $rs]
    set r1 [::fivax::vec::norm $re]
    if {$r0 < 1e-9 || $r1 < 1e-9} {return ""}
    # Signed angle from rs to re about n, then taken in the arc's sense.
    set a [expr {atan2([::fivax::vec::dot [::fivax::vec::cross $rs $re] $n], [::fivax::vec::dot $rs $re])}]
    set sweep [expr {$sense > 0 ? $a : -$a}]
    if {$sweep < 1e-9} {set sweep [expr {$sweep + 2.0 * $pi}]}
    set sweep [expr {$sweep + 2.0 * $pi * $turns}]
    list $center $n $hs $he $r0 $r1 [::fivax::vec::scale [expr {1.0 / $r0}] $rs] $sweep $sense
}

# ::fivax::curve::Point -- Returns the point at fraction f of the arc of frame (see Frame).
proc ::fivax::curve::Point {frame f} {
    lassign $frame center n hs he r0 r1 u sweep sense
    set dir [::fivax::vec::rotate $n [expr {$sense > 0 ? $f * $sweep : -$f * $sweep}] $u]
    set radial [::fivax::vec::scale [expr {$r0 + $f * ($r1 - $r0)}] $dir]
    set axial [::fivax::vec::scale [expr {$hs + $f * ($he - $hs)}] $n]
    ::fivax::vec::add $center [::fivax::vec::add $radial $axial]
}
