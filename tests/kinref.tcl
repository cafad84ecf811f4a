# kinref.tcl --
#	Reference kinematics for the tests, kept out of lib/ (the post does not
#	need them): the full inverse (every joint vector for a tip and axis)
#	built from the library's orientations and position, and the closed
#	forms of the papers (spec/kinematics.md sections 3-5), which cross-check
#	the generic chain. Angles in radians.

namespace eval ::kinref {
    namespace upvar ::fivax::num pi pi
}

# ::kinref::inverse --
#	Returns every joint vector {X Y Z q1 q2} putting the tip at P with axis t
#	(one or two; {} when t is unreachable). At a singular t, q2 is azimuth
#	(default 0.0: callers pass their previous azimuth).
proc ::kinref::inverse {model P t {azimuth 0.0}} {
    lassign [::fivax::kin::orientations $model $t] status sols
    set out {}
    foreach q $sols {
        if {$status eq "singular"} {lset q 1 $azimuth}
        lappend out [list {*}[::fivax::kin::position $model $P $q] {*}$q]
    }
    return $out
}

# ::kinref::Wrap -- Returns angle a (radians) wrapped into (-pi, pi].
proc ::kinref::Wrap {a} {
    variable pi
    set a [expr {atan2(sin($a), cos($a)) + 0.0}]
    if {$a <= -$pi} {set a [expr {$a + 2.0 * $pi}]}
    return $a
}

# ::kinref::closedHeadHead --
#	Returns the {X Y Z B C} (radians) of kinematics.md section 3 for tip P and
#	unit axis t on a head-head machine with B tilted by alpha (radians),
#	L = pivot + tool length and offset yH (C sense -1, B sense +1). One
#	solution when B = 0 (then C = 0) or B = 180 deg, none when
#	K < -cos(2 alpha).
proc ::kinref::closedHeadHead {alpha L yH P t} {
    lassign $P x y z
    lassign $t I J K
    set ca [expr {cos($alpha)}]
    set sa [expr {sin($alpha)}]
    set cb [expr {($K - $sa * $sa) / ($ca * $ca)}]
    if {$cb < -1.0 - 1e-12 || $cb > 1.0 + 1e-12} {return {}}
    set cb [expr {min(1.0, max(-1.0, $cb))}]
    set B [expr {acos($cb)}]
    set out {}
    variable pi
    foreach Bs [expr {$B > 0.0 && $B < $pi ? [list $B [expr {-$B}]] : [list $B]}] {
        set p [expr {$ca * sin($Bs)}]
        set q [expr {0.5 * sin(2.0 * $alpha) * (1.0 - cos($Bs))}]
        set pq [expr {$p * $p + $q * $q}]
        if {$pq == 0.0} {
            set C 0.0
        } else {
            set C [expr {atan2(($I * $q - $J * $p) / $pq, ($I * $p + $J * $q) / $pq)}]
        }
        set C [Wrap $C]
        set Bs [Wrap $Bs]
        lappend out [list \
            [expr {$x + $yH * $ca * sin($C) + $L * $I}] \
            [expr {$y - $yH * $ca * (1.0 - cos($C)) + $L * $J}] \
            [expr {$z - $L * (1.0 - $K)}] $Bs $C]
    }
    return $out
}

# ::kinref::closedHeadTable --
#	Returns the {X Y Z B C} (radians) of kinematics.md section 4 for tip P and
#	unit axis t: head B about +Y through (0,0,L) above the tip (sense +1),
#	table C about +Z through center (default the origin, sense -1).
proc ::kinref::closedHeadTable {L P t {center {0 0 0}}} {
    variable pi
    lassign $P x y z
    lassign $t I J K
    lassign $center cx cy cz
    set B [expr {acos(min(1.0, max(-1.0, $K)))}]
    if {hypot($I, $J) == 0.0} {
        set sols [list [list $B 0.0]]
    } else {
        set C [expr {atan2(-$J, $I)}]
        set sols [list [list $B $C] [list [expr {-$B}] [expr {$C + $pi}]]]
    }
    set out {}
    foreach s $sols {
        lassign $s B C
        set B [Wrap $B]
        set C [Wrap $C]
        set dx [expr {$x - $cx}]
        set dy [expr {$y - $cy}]
        lappend out [list \
            [expr {$cx + $dx * cos($C) - $dy * sin($C) + $L * sin($B)}] \
            [expr {$cy + $dx * sin($C) + $dy * cos($C)}] \
            [expr {$z + $L * (cos($B) - 1.0)}] $B $C]
    }
    return $out
}

# ::kinref::nutatingTilt --
#	Returns phi = acos(2K - 1) (radians), the outer-axis angle of a 45-degree
#	nutating table for tool-axis component K (kinematics.md section 5).
#	Errors: {FIVAX KIN UNREACHABLE} for K < 0 (beyond 1e-12).
proc ::kinref::nutatingTilt {K} {
    if {![string is double -strict $K]} {::fivax::Fail KIN VALUE "K is not a number: $K"}
    if {$K < -1e-12} {
        ::fivax::Fail KIN UNREACHABLE "tool axis K = $K < 0 is out of reach of a 45-degree nutating table"
    }
    expr {acos(min(1.0, max(-1.0, 2.0 * $K - 1.0)))}
}
