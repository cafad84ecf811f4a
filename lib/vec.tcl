# vec.tcl --
#	3-vectors as 3-element lists of doubles, and rotations about an axis
#	through the origin (Rodrigues' formula). Angles in radians.

namespace eval ::fivax::vec {
    namespace export add sub scale dot cross norm dist unit rotate angle lerp slerp
    namespace ensemble create -prefixes 0
    namespace upvar ::fivax::num pi pi
}

# ::fivax::vec::add -- Returns a + b.
proc ::fivax::vec::add {a b} {
    lassign $a ax ay az
    lassign $b bx by bz
    list [expr {$ax + $bx}] [expr {$ay + $by}] [expr {$az + $bz}]
}

# ::fivax::vec::sub -- Returns a - b.
proc ::fivax::vec::sub {a b} {
    lassign $a ax ay az
    lassign $b bx by bz
    list [expr {$ax - $bx}] [expr {$ay - $by}] [expr {$az - $bz}]
}

# ::fivax::vec::scale -- Returns s * a for a scalar s.
proc ::fivax::vec::scale {s a} {
    lassign $a ax ay az
    list [expr {$s * $ax}] [expr {$s * $ay}] [expr {$s * $az}]
}

# ::fivax::vec::dot -- Returns the dot product a . b.
proc ::fivax::vec::dot {a b} {
    lassign $a ax ay az
    lassign $b bx by bz
    expr {$ax * $bx + $ay * $by + $az * $bz}
}

# ::fivax::vec::cross -- Returns the cross product a x b.
proc ::fivax::vec::cross {a b} {
    lassign $a ax ay az
    lassign $b bx by bz
    list [expr {$ay * $bz - $az * $by}] [expr {$az * $bx - $ax * $bz}] \
        [expr {$ax * $by - $ay * $bx}]
}

# ::fivax::vec::norm -- Returns the Euclidean length of a.
proc ::fivax::vec::norm {a} {
    lassign $a ax ay az
    expr {sqrt($ax * $ax + $ay * $ay + $az * $az)}
}

# ::fivax::vec::dist -- Returns |a - b| (the same number as [norm [sub a b]]).
proc ::fivax::vec::dist {a b} {
    lassign $a ax ay az
    lassign $b bx by bz
    set x [expr {$ax - $bx}]
    set y [expr {$ay - $by}]
    set z [expr {$az - $bz}]
    expr {sqrt($x * $x + $y * $y + $z * $z)}
}

# ::fivax::vec::unit -- Returns a / |a|; errors {FIVAX VEC ZERO} on a zero vector.
proc ::fivax::vec::unit {a} {
    lassign $a ax ay az
    set n [expr {sqrt($ax * $ax + $ay * $ay + $az * $az)}]
    if {$n == 0.0} {::fivax::Fail VEC ZERO "cannot normalise a zero vector"}
    list [expr {$ax / $n}] [expr {$ay / $n}] [expr {$az / $n}]
}

# ::fivax::vec::rotate --
#	Returns v turned by the right-hand angle a (radians) about the unit
#	vector u through the origin (Rodrigues' formula).
proc ::fivax::vec::rotate {u a v} {
    lassign $u ux uy uz
    lassign $v vx vy vz
    set c [expr {cos($a)}]
    set s [expr {sin($a)}]
    set k [expr {(1.0 - $c) * ($ux * $vx + $uy * $vy + $uz * $vz)}]
    list [expr {$vx * $c + ($uy * $vz - $uz * $vy) * $s + $ux * $k}] \
        [expr {$vy * $c + ($uz * $vx - $ux * $vz) * $s + $uy * $k}] \
        [expr {$vz * $c + ($ux * $vy - $uy * $vx) * $s + $uz * $k}]
}

# ::fivax::vec::angle --
#	Returns the angle (radians, 0..pi) between a and b, accurate near 0 and pi.
proc ::fivax::vec::angle {a b} {
    # atan2(|a x b|, a . b), written out (the same numbers as norm, cross, dot)
    lassign $a ax ay az
    lassign $b bx by bz
    set x [expr {$ay * $bz - $az * $by}]
    set y [expr {$az * $bx - $ax * $bz}]
    set z [expr {$ax * $by - $ay * $bx}]
    expr {atan2(sqrt($x * $x + $y * $y + $z * $z), $ax * $bx + $ay * $by + $az * $bz)}
}

# ::fivax::vec::lerp -- Returns a + s (b - a).
proc ::fivax::vec::lerp {a b s} {
    lassign $a ax ay az
    lassign $b bx by bz
    list [expr {$ax + $s * ($bx - $ax)}] [expr {$ay + $s * ($by - $ay)}] \
        [expr {$az + $s * ($bz - $az)}]
}

# ::fivax::vec::slerp --
#	Returns the unit vector at fraction s of the great-circle arc from unit
#	a to unit b (plain normalised lerp when they are (anti)parallel).
proc ::fivax::vec::slerp {a b s} {
    variable pi
    set w [angle $a $b]
    if {$w < 1e-12 || $w > $pi - 1e-9} {
        return [unit [lerp $a $b $s]]
    }
    set sw [expr {sin($w)}]
    set fa [expr {sin((1.0 - $s) * $w) / $sw}]
    set fb [expr {sin($s * $w) / $sw}]
    add [scale $fa $a] [scale $fb $b]
}
