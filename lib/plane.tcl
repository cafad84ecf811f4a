# plane.tcl --
#	Tilted work planes (3+2): the frame of an operation whose tool axis is
#	fixed, and the angles the controls define such a frame with. A frame
#	is a rotation matrix R, a list of three rows, whose columns are the
#	plane's X', Y' and Z' axes in the workpiece frame (Z' the tool axis);
#	a point P of the workpiece frame has plane coordinates R^T (P - O).
#
#	Conventions (../shared/spec/dialects.md sections 1-3), angles in
#	degrees:
#	(a controller's file names its convention: its writer table's plane)
#	  zxz   I J K: Euler Z-X'-Z'' intrinsic,
#	        R = Rz(I) Rx(J) Rz(K)
#	  xyz   A B C axis by axis X, Y, Z, each about the axis the
#	        rotations before left: R = Rx(A) Ry(B) Rz(C)
#	  spatial  SPA SPB SPC: about the fixed X, then Y, then Z:
#	        R = Rz(SPC) Ry(SPB) Rx(SPA)
#	Each convention has a decomposition (angles) and a composition
#	(matrix) that the tests run as a round trip.

namespace eval ::fivax::plane {
    namespace export frame angles matrix toPlane fromPlane
    namespace ensemble create -prefixes 0
}

# ::fivax::plane::frame --
#	Returns the frame of tool axis t (a unit vector): Z' = t, X' the
#	workpiece X projected onto the plane (the workpiece Y where t is
#	within 1e-6 rad of X), Y' = Z' x X'.
proc ::fivax::plane::frame {t} {
    set z [::fivax::vec::unit $t]
    set x [::fivax::vec::sub {1.0 0.0 0.0} [::fivax::vec::scale [lindex $z 0] $z]]
    if {[::fivax::vec::norm $x] < 1e-6} {
        set x [::fivax::vec::sub {0.0 1.0 0.0} [::fivax::vec::scale [lindex $z 1] $z]]
    }
    set x [::fivax::vec::unit $x]
    Columns $x [::fivax::vec::cross $z $x] $z
}

# ::fivax::plane::angles --
#	Returns the three angles (deg) of frame R in convention (zxz, xyz or
#	spatial). Where the middle rotation leaves the other two on one axis
#	(a gimbal lock) the last angle is 0.
proc ::fivax::plane::angles {convention R} {
    lassign $R r1 r2 r3
    lassign $r1 r11 r12 r13
    lassign $r2 r21 r22 r23
    lassign $r3 r31 r32 r33
    switch -exact -- $convention {
        zxz {
            # R33 = cos J; R13 = sin I sin J, R23 = -cos I sin J;
            # R31 = sin J sin K, R32 = sin J cos K
            set j [expr {acos(max(-1.0, min(1.0, $r33)))}]
            if {sin($j) < 1e-9} {
                set i [expr {atan2($r21, $r11)}]
                set k 0.0
            } else {
                set i [expr {atan2($r13, -$r23)}]
                set k [expr {atan2($r31, $r32)}]
            }
            set out [list $i $j $k]
        }
        xyz {
            # R13 = sin B; R23 = -sin A cos B, R33 = cos A cos B;
            # R12 = -cos B sin C, R11 = cos B cos C
            set b [expr {asin(max(-1.0, min(1.0, $r13)))}]
            if {cos($b) < 1e-9} {
                set a [expr {atan2($r32, $r22)}]
                set c 0.0
            } else {
                set a [expr {atan2(-$r23, $r33)}]
                set c [expr {atan2(-$r12, $r11)}]
            }
            set out [list $a $b $c]
        }
        spatial {
            # R31 = -sin B; R32 = cos B sin A, R33 = cos B cos A;
            # R21 = cos B sin C, R11 = cos B cos C
            set b [expr {asin(max(-1.0, min(1.0, -$r31)))}]
            if {cos($b) < 1e-9} {
                set a [expr {atan2(-$r23, $r22)}]
                set c 0.0
            } else {
                set a [expr {atan2($r32, $r33)}]
                set c [expr {atan2($r21, $r11)}]
            }
            set out [list $a $b $c]
        }
        default {::fivax::Fail PLANE VALUE "unknown angle convention \"$convention\""}
    }
    lmap v $out {::fivax::num::deg $v}
}

# ::fivax::plane::matrix -- Returns the frame of angles (deg) in convention (see angles).
proc ::fivax::plane::matrix {convention angles} {
    lassign [lmap v $angles {::fivax::num::rad $v}] a b c
    switch -exact -- $convention {
        zxz {Mul [Mul [Rot z $a] [Rot x $b]] [Rot z $c]}
        xyz {Mul [Mul [Rot x $a] [Rot y $b]] [Rot z $c]}
        spatial {Mul [Mul [Rot z $c] [Rot y $b]] [Rot x $a]}
        default {::fivax::Fail PLANE VALUE "unknown angle convention \"$convention\""}
    }
}

# ::fivax::plane::toPlane -- Returns the plane coordinates R^T (P - O) of workpiece point P.
proc ::fivax::plane::toPlane {R O P} {
    set d [::fivax::vec::sub $P $O]
    lassign $R r1 r2 r3
    set out {}
    foreach i {0 1 2} {
        lappend out [expr {[lindex $r1 $i] * [lindex $d 0] + [lindex $r2 $i] * [lindex $d 1]
            + [lindex $r3 $i] * [lindex $d 2]}]
    }
    return $out
}

# ::fivax::plane::fromPlane -- Returns the workpiece point O + R Q of plane point Q.
proc ::fivax::plane::fromPlane {R O Q} {
    ::fivax::vec::add $O [lmap row $R {::fivax::vec::dot $row $Q}]
}

# ::fivax::plane::Columns -- Returns the matrix with columns a, b, c.
proc ::fivax::plane::Columns {a b c} {
    lmap i {0 1 2} {list [lindex $a $i] [lindex $b $i] [lindex $c $i]}
}

# ::fivax::plane::Rot -- Returns the rotation by angle (rad) about axis x, y or z.
proc ::fivax::plane::Rot {axis angle} {
    set c [expr {cos($angle)}]
    set s [expr {sin($angle)}]
    switch -exact -- $axis {
        x {list {1.0 0.0 0.0} [list 0.0 $c [expr {-$s}]] [list 0.0 $s $c]}
        y {list [list $c 0.0 $s] {0.0 1.0 0.0} [list [expr {-$s}] 0.0 $c]}
        z {list [list $c [expr {-$s}] 0.0] [list $s $c 0.0] {0.0 0.0 1.0}}
    }
}

# ::fivax::plane::Mul -- Returns the matrix product A B.
proc ::fivax::plane::Mul {A B} {
    set cols [lmap i {0 1 2} {lmap r $B {lindex $r $i}}]
    lmap row $A {lmap col $cols {::fivax::vec::dot $row $col}}
}
