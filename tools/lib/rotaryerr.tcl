# rotaryerr.tcl --
#	Kinematic error of the rotary axes (kinematics.md section 10): for
#	angular errors of the two rotaries, the tool tip error in the
#	workpiece frame, forward(q + dq) - forward(q), and the orientation
#	error as the angle between the perturbed and the nominal tool axis,
#	on any machine's forward kinematics. The errors are constant, or
#	signed by each axis's direction of motion (the TTR-TR study's rule
#	(24), printed there with an impossible |.| < 0; here: the sign of the
#	axis's last motion, + before it has moved). Needs the fivax package.

namespace eval ::fivax::kinerr {
    namespace export at signs path
    namespace ensemble create -prefixes 0
}

# ::fivax::kinerr::at --
#	Returns {dx dy dz dpos dangle}: the tip error (mm, workpiece frame),
#	its length and the axis error (degrees) at joints {X Y Z q1 q2} for
#	rotary errors dq = {dq1 dq2} (radians) on kin model.
proc ::fivax::kinerr::at {model joints dq} {
    lassign [::fivax::kin::forward $model $joints] P t
    lassign $dq d1 d2
    lassign $joints X Y Z q1 q2
    lassign [::fivax::kin::forward $model [list $X $Y $Z [expr {$q1 + $d1}] [expr {$q2 + $d2}]]] Pe te
    set d [::fivax::vec::sub $Pe $P]
    list {*}$d [::fivax::vec::norm $d] [::fivax::num::deg [::fivax::vec::angle $t $te]]
}

# ::fivax::kinerr::signs --
#	Returns one sign (1 or -1) per value of the axis values list: the sign
#	of the change from the value before, the previous sign where the axis
#	does not move, 1 before its first motion.
proc ::fivax::kinerr::signs {values} {
    set out {}
    set sign 1
    set last ""
    foreach v $values {
        if {$last ne "" && $v != $last} {set sign [expr {$v > $last ? 1 : -1}]}
        lappend out $sign
        set last $v
    }
    return $out
}

# ::fivax::kinerr::path --
#	Returns one {dx dy dz dpos dangle} per joint vector of jointsList on
#	its kin model (models: one per joint vector, e.g. each block's tool
#	length), for the rotary errors errors = {e1 e2} (radians) applied as
#	they are (mode constant) or signed by each axis's direction of motion
#	(mode direction).
proc ::fivax::kinerr::path {models jointsList errors mode} {
    lassign $errors e1 e2
    if {$mode eq "direction"} {
        set s1 [signs [lmap j $jointsList {lindex $j 3}]]
        set s2 [signs [lmap j $jointsList {lindex $j 4}]]
    } else {
        set s1 [lrepeat [llength $jointsList] 1]
        set s2 $s1
    }
    lmap model $models j $jointsList a $s1 b $s2 {
        at $model $j [list [expr {$a * $e1}] [expr {$b * $e2}]]
    }
}
