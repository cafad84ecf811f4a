# curve.tcl --
#	CL path geometry the post needs between two CL points: circular and
#	helical arcs (CIRCLE + GOTO) as points within a chord tolerance. Points
#	are {x y z} lists in mm.

namespace eval ::fivax::curve {
    namespace export arc
    namespace ensemble create -prefixes 0
    namespace upvar ::fivax::num pi pi
}

# ::fivax::curve::arc --
#	Returns the points after start up to and including end of an arc about
#	the line through center along unit axis, turning clockwise (sense -1)
#	or counter-clockwise (sense 1) about axis, plus turns extra full turns,
#	with chord error at most tol (mm). Radius and the axial height vary
#	linearly from start to end (helixes, slightly inconsistent CL data).
#	start = end is a full circle.
proc ::fivax::curve::arc {start end center axis sense turns tol} {
    variable pi
    set n [::fivax::vec::unit $axis]
    set hs [::fivax::vec::dot [::fivax::vec::sub $start $center] $n]
    set he [::fivax::vec::dot [::fivax::vec::sub $end $center] $n]
    set rs [::fivax::vec::sub [::fivax::vec::sub $start $center] [::fivax::vec::scale $hs $n]]
    set re [::fivax::vec::sub [::fivax::vec::sub $end $center] [::fivax::vec::scale $he $n]]
    set r0 [::fivax::vec::norm $rs]
    set r1 [::fivax::vec::norm $re]
    if {$r0 < 1e-9 || $r1 < 1e-9} {return [list $end]}
    # Signed angle from rs to re about n, then taken in the arc's sense.
    set a [expr {atan2([::fivax::vec::dot [::fivax::vec::cross $rs $re] $n], [::fivax::vec::dot $rs $re])}]
    set sweep [expr {$sense > 0 ? $a : -$a}]
    if {$sweep < 1e-9} {set sweep [expr {$sweep + 2.0 * $pi}]}
    set sweep [expr {$sweep + 2.0 * $pi * $turns}]
    set rmax [expr {max($r0, $r1)}]
    set step [expr {$tol >= $rmax ? $pi / 2.0 : 2.0 * acos(1.0 - $tol / $rmax)}]
    set count [expr {max(1, int(ceil($sweep / $step)))}]
    set u [::fivax::vec::scale [expr {1.0 / $r0}] $rs]
    set out {}
    for {set i 1} {$i < $count} {incr i} {
        set f [expr {double($i) / $count}]
        set dir [::fivax::vec::rotate $n [expr {$sense > 0 ? $f * $sweep : -$f * $sweep}] $u]
        set radial [::fivax::vec::scale [expr {$r0 + $f * ($r1 - $r0)}] $dir]
        set axial [::fivax::vec::scale [expr {$hs + $f * ($he - $hs)}] $n]
        lappend out [::fivax::vec::add $center [::fivax::vec::add $radial $axial]]
    }
    lappend out $end
}
