# kin.tcl --
#	Forward and inverse kinematics of two-rotary-axis (five-axis) machines:
#	the generic chain of kinematics.md section 2, an inverse that solves the
#	orientation with Paden-Kahan subproblem 2 and the position from the
#	linear position equation, and the error of the controller's linear
#	joint interpolation between two poses (section 7), which the planner
#	and the checker both measure. Angles in radians, lengths in the
#	machine's units. (The papers' closed forms, kept as cross-checks, live
#	in tests/kinref.tcl.)
#
#	Conventions (chain = machine dict 'chain', forward order): axis 1 is the
#	tool-side (tilt) axis, axis 2 the azimuth axis. Joint vectors are
#	{X Y Z q1 q2} in the machine's own (written) values. With R(u, a) the
#	right-hand rotation about unit u and th_i = s_i (q_i - z_i) (s_i the
#	axis sense, z_i its zero offset: the written value at the zero pose,
#	machine file key 'offset'), every machine kind satisfies
#
#	    t = R(u2, th2) R(u1, th1) Z                                  (O)
#
#	head-head:   tip = XYZ + R2(R1(0 - p1) + p1 - p2) + p2
#	head-table:  P   = R2(XYZ + R1(0 - p1) + p1 - p2) + p2
#	table-table: P   = R2(R1(XYZ - p1) + p1 - p2) + p2
#
#	(table axes: R here is the inverse of the rotation the table gives the
#	part, so a positive ISO table angle moves the tool positively relative
#	to the part). u_i, p_i are zero-pose directions and absolute points.
#	Errors: {FIVAX KIN <DETAIL>}.

namespace eval ::fivax::kin {
    namespace export model forward orientations position interpolationError \
        interpolationBound toolInMachine
    namespace ensemble create -prefixes 0
    namespace upvar ::fivax::num pi pi

    # |t x u2| below this (t within ~1e-12 rad of the azimuth axis) is
    # reported 'singular'; the round-trip error this causes is < 1e-12.
    variable singularTol 1e-12
    # Reach margin D = r |u1 x u2| - |d| (see orientations): D < -edgeTol is
    # unreachable, |D| <= edgeTol is the workspace edge itself (one solution,
    # g = 0; the two near-coincident roots would differ by ~sqrt(D) in the
    # angles but only by ~D in the tool axis, so merging them costs < 1e-11).
    variable edgeTol 1e-12
    # interpolationBound's last call: its bound list, end 1 (tip and axis
    # lists, X Y Z) and the terms of that end (see there).
    variable lastEnd {}
}

# ::fivax::kin::model --
#	Returns the kinematic model of machine (a fivax::machine dict) for one
#	tool: L = pivot + toolLength ("" = the machine's tool_length), absolute
#	axis points (head: point + (0,0,L); table: point + tableOffset, default
#	the machine's table_offset) and precomputed constants for the hot paths.
#	Errors: {FIVAX KIN VALUE} for a non-numeric tool length or offset.
proc ::fivax::kin::model {machine toolLength {tableOffset ""}} {
    if {$toolLength eq ""} {set toolLength [dict get $machine tool_length]}
    set tl [::fivax::num::parse $toolLength]
    if {$tl eq ""} {::fivax::Fail KIN VALUE "tool length is not a number: $toolLength"}
    if {$tableOffset eq ""} {set tableOffset [dict get $machine table_offset]}
    if {![string is list $tableOffset] || [llength $tableOffset] != 3} {
        ::fivax::Fail KIN VALUE "table offset is not a list of 3 numbers: $tableOffset"
    }
    set off {}
    foreach c $tableOffset {
        set v [::fivax::num::parse $c]
        if {$v eq ""} {::fivax::Fail KIN VALUE "table offset is not a list of 3 numbers: $tableOffset"}
        lappend off $v
    }
    lassign $off ox oy oz
    set L [expr {[dict get $machine pivot] + $tl}]
    set m [dict create L $L toolLength $tl tableOffset $off kind [dict get $machine kind]]
    set names {}
    set geo {}
    set i 0
    foreach ax [dict get $machine chain] {
        incr i
        lappend names [dict get $ax name]
        lassign [dict get $ax dir] ux uy uz
        lassign [dict get $ax point] px py pz
        if {[dict get $ax side] eq "head"} {
            set p [list $px $py [expr {$pz + $L}]]
        } else {
            set p [list [expr {$px + $ox}] [expr {$py + $oy}] [expr {$pz + $oz}]]
        }
        dict set m u$i [list $ux $uy $uz]
        dict set m p$i $p
        dict set m s$i [dict get $ax sense]
        dict set m side$i [dict get $ax side]
        set z 0.0
        if {[dict exists $ax offset]} {set z [expr {double([dict get $ax offset])}]}
        dict set m z$i $z
        lappend geo $ux $uy $uz {*}$p [expr {double([dict get $ax sense])}] $z
    }
    dict set m names $names
    set kc [dict get {headhead 0 headtable 1 tabletable 2} [dict get $machine kind]]
    # Constants of a head axis 1 (the point it turns is the zero-pose tip,
    # -p1 from p1), by the very expressions of forward and position: for
    # forward v = -p1, u1.v and u1 x v; for position u1.p1 and u1 x p1.
    lassign $geo ux1 uy1 uz1 px1 py1 pz1
    set vx [expr {-$px1}]; set vy [expr {-$py1}]; set vz [expr {-$pz1}]
    lappend geo $vx $vy $vz [expr {$ux1 * $vx + $uy1 * $vy + $uz1 * $vz}] \
        [expr {$uy1 * $vz - $uz1 * $vy}] [expr {$uz1 * $vx - $ux1 * $vz}] \
        [expr {$ux1 * $vy - $uy1 * $vx}] \
        [expr {$ux1 * $px1 + $uy1 * $py1 + $uz1 * $pz1}] [expr {$uy1 * $pz1 - $uz1 * $py1}] \
        [expr {$uz1 * $px1 - $ux1 * $pz1}] [expr {$ux1 * $py1 - $uy1 * $px1}]
    dict set m geo [linsert $geo 0 $kc]

    # Orientation constants for (O): w = u1.u2, n = u1 x u2, nn = |n|^2,
    # k1 = u1.Z, m1 = u1 x Z, zp = Z - k1 u1 (Z projected off u1).
    lassign [dict get $m u1] x1 y1 z1
    lassign [dict get $m u2] x2 y2 z2
    set w [expr {$x1 * $x2 + $y1 * $y2 + $z1 * $z2}]
    set nx [expr {$y1 * $z2 - $z1 * $y2}]
    set ny [expr {$z1 * $x2 - $x1 * $z2}]
    set nz [expr {$x1 * $y2 - $y1 * $x2}]
    set nn [expr {$nx * $nx + $ny * $ny + $nz * $nz}]
    if {$nn < 1e-18} {::fivax::Fail KIN GEOMETRY "axes [join $names { and }] are parallel"}
    set k1 $z1
    set dP [expr {-$x1 * $x2 - $y1 * $y2 + $z1 * (1.0 - $z2)}]
    set dM [expr {$x1 * $x2 + $y1 * $y2 + $z1 * (1.0 + $z2)}]
    set m1x $y1
    set m1y [expr {-$x1}]
    set zpx [expr {-$k1 * $x1}]
    set zpy [expr {-$k1 * $y1}]
    set zpz [expr {1.0 - $k1 * $z1}]
    if {$zpx * $zpx + $zpy * $zpy + $zpz * $zpz < 1e-18} {
        ::fivax::Fail KIN GEOMETRY "axis [lindex $names 0] is parallel to the tool axis"
    }
    set m1u2 [expr {$m1x * $x2 + $m1y * $y2}]
    set m1n [expr {$m1x * $nx + $m1y * $ny}]
    set zpu2 [expr {$zpx * $x2 + $zpy * $y2 + $zpz * $z2}]
    set zpn [expr {$zpx * $nx + $zpy * $ny + $zpz * $nz}]
    # (with w k1 and the namespace's constants, negated ones too:
    # orientations reads them all from the list)
    variable singularTol
    variable edgeTol
    variable pi
    dict set m ori [list $x1 $y1 $z1 $x2 $y2 $z2 $nx $ny $nz $w $nn [expr {sqrt($nn)}] \
                        $k1 $dP $dM $m1u2 $m1n $zpu2 $zpn \
                        [expr {double([dict get $m s1])}] [expr {double([dict get $m s2])}] \
                        [dict get $m z1] [dict get $m z2] [expr {$w * $k1}] \
                        $singularTol $edgeTol [expr {-$edgeTol}] $pi [expr {-$pi}]]

    # Constants of interpolationBound: rh = |u1 x p1|, the distance of the
    # tip from a head axis 1 (the point it turns is the zero-pose tip,
    # -p1 from p1); k1 = |u1 x Z|, the distance of Z from axis 1 on the
    # unit sphere; scale, the size of the axis points (rounding margin).
    lassign [dict get $m p1] px1 py1 pz1
    lassign [dict get $m p2] px2 py2 pz2
    set rh [expr {sqrt(($y1 * $pz1 - $z1 * $py1) ** 2 + ($z1 * $px1 - $x1 * $pz1) ** 2
        + ($x1 * $py1 - $y1 * $px1) ** 2)}]
    set scale [expr {abs($px1) + abs($py1) + abs($pz1) + abs($px2) + abs($py2) + abs($pz2)}]
    # (axis 1's direction and point last: only a table-table bound reads them)
    dict set m bound [list $kc $x2 $y2 $z2 $px2 $py2 $pz2 $rh \
        [expr {sqrt($x1 * $x1 + $y1 * $y1)}] $scale $x1 $y1 $z1 $px1 $py1 $pz1]
    return $m
}

# ::fivax::kin::forward --
#	Returns {P t}: tool tip and unit tool axis in the workpiece frame for the
#	joint vector {X Y Z q1 q2} (kinematics.md section 2).
proc ::fivax::kin::forward {model joints} {
    lassign $joints X Y Z q1 q2
    lassign [dict get $model geo] kc ux1 uy1 uz1 px1 py1 pz1 s1 z1 ux2 uy2 uz2 px2 py2 pz2 s2 z2 \
        vx vy vz vu ex ey ez
    set a [expr {$s1 * ($q1 - $z1)}]
    set c1 [expr {cos($a)}]
    set n1 [expr {sin($a)}]
    set a [expr {$s2 * ($q2 - $z2)}]
    set c2 [expr {cos($a)}]
    set n2 [expr {sin($a)}]
    # v: the point entering axis 1, relative to p1, with u1.v and u1 x v
    # (on a head the model's constants, v = -p1)
    if {$kc == 2} {
        set vx [expr {$X - $px1}]; set vy [expr {$Y - $py1}]; set vz [expr {$Z - $pz1}]
        set vu [expr {$ux1 * $vx + $uy1 * $vy + $uz1 * $vz}]
        set ex [expr {$uy1 * $vz - $uz1 * $vy}]
        set ey [expr {$uz1 * $vx - $ux1 * $vz}]
        set ez [expr {$ux1 * $vy - $uy1 * $vx}]
    }
    # R1 (v) + p1 - p2, Rodrigues
    set k [expr {(1.0 - $c1) * $vu}]
    set wx [expr {$vx * $c1 + $ex * $n1 + $ux1 * $k + $px1 - $px2}]
    set wy [expr {$vy * $c1 + $ey * $n1 + $uy1 * $k + $py1 - $py2}]
    set wz [expr {$vz * $c1 + $ez * $n1 + $uz1 * $k + $pz1 - $pz2}]
    if {$kc == 1} {
        set wx [expr {$wx + $X}]; set wy [expr {$wy + $Y}]; set wz [expr {$wz + $Z}]
    }
    # R1 Z
    set k [expr {(1.0 - $c1) * $uz1}]
    set tx [expr {$uy1 * $n1 + $ux1 * $k}]
    set ty [expr {-$ux1 * $n1 + $uy1 * $k}]
    set tz [expr {$c1 + $uz1 * $k}]
    # R2 (w) + p2, R2 t
    set k [expr {(1.0 - $c2) * ($ux2 * $wx + $uy2 * $wy + $uz2 * $wz)}]
    set Px [expr {$wx * $c2 + ($uy2 * $wz - $uz2 * $wy) * $n2 + $ux2 * $k + $px2}]
    set Py [expr {$wy * $c2 + ($uz2 * $wx - $ux2 * $wz) * $n2 + $uy2 * $k + $py2}]
    set Pz [expr {$wz * $c2 + ($ux2 * $wy - $uy2 * $wx) * $n2 + $uz2 * $k + $pz2}]
    if {$kc == 0} {
        set Px [expr {$Px + $X}]; set Py [expr {$Py + $Y}]; set Pz [expr {$Pz + $Z}]
    }
    set k [expr {(1.0 - $c2) * ($ux2 * $tx + $uy2 * $ty + $uz2 * $tz)}]
    list [list $Px $Py $Pz] \
        [list [expr {$tx * $c2 + ($uy2 * $tz - $uz2 * $ty) * $n2 + $ux2 * $k}] \
             [expr {$ty * $c2 + ($uz2 * $tx - $ux2 * $tz) * $n2 + $uy2 * $k}] \
             [expr {$tz * $c2 + ($ux2 * $ty - $uy2 * $tx) * $n2 + $uz2 * $k}]]
}

# ::fivax::kin::toolInMachine --
#	Returns the tool direction in the machine frame at rotaries {q1 q2}:
#	turned by the head axes only (table axes turn the part, not the tool),
#	so always Z on a table-table machine. It is forward's tool axis with
#	the table axes at their zero pose.
proc ::fivax::kin::toolInMachine {model q} {
    lassign $q q1 q2
    switch -- [lindex [dict get $model geo] 0] {
        1 {set q2 [dict get $model z2]}
        2 {
            set q1 [dict get $model z1]
            set q2 [dict get $model z2]
        }
    }
    lindex [forward $model [list 0.0 0.0 0.0 $q1 $q2]] 1
}

# ::fivax::kin::orientations --
#	Returns {status sols} for the tool axis t (normalised here): 'regular'
#	with one or two {q1 q2} (radians in (-pi, pi]), 'singular' (t along the
#	azimuth axis u2, q2 free) with {{q1 0.0}}, or 'unreachable' with {}.
#	Errors: {FIVAX KIN ZERO} for a zero t.
#
#	Solves (O) as Paden-Kahan subproblem 2: c = R1 Z = R2^-1 t lies on the
#	circle of Z about u1 and on the circle of t about u2, so with h = u2.t,
#	c = a u1 + b u2 + g (u1 x u2),  a = d/nn,  b = (h - w k1)/nn,
#	d = k1 - w h,  nn = 1 - w^2 = |u1 x u2|^2,  g = +-sqrt(G)/nn,
#	G = (1 - h^2) nn - d^2   (the Gram determinant of u1, u2, c).
#	Near t = +-u2 everything is taken from r = |t x u2| (1 - h^2 = r^2, and
#	d = (k1 - w) + w r^2/(1 + h) for h > 0), so G, g and the azimuth stay
#	accurate to a few ulps even 1e-12 rad from the singular direction.
#	Reachable iff D = r sqrt(nn) - |d| >= 0 (G = D (r sqrt(nn) + |d|));
#	|D| <= edgeTol is taken as the edge itself (g = 0, one solution).
#	Then th1 = angle from Z to c about u1 and th2 = angle from c to t about
#	u2 (subproblem 1, written with precomputed dot products), q_i = s_i th_i.
proc ::fivax::kin::orientations {model t} {
    lassign $t tx ty tz
    set tn [expr {sqrt($tx * $tx + $ty * $ty + $tz * $tz)}]
    if {$tn == 0.0} {::fivax::Fail KIN ZERO "tool axis is a zero vector"}
    if {$tn != 1.0} {
        set tx [expr {$tx / $tn}]; set ty [expr {$ty / $tn}]; set tz [expr {$tz / $tn}]
    }
    lassign [dict get $model ori] x1 y1 z1 x2 y2 z2 nx ny nz w nn sqnn \
        k1 dP dM m1u2 m1n zpu2 zpn s1 s2 o1 o2 wk1 singularTol edgeTol medge pi mpi
    set h [expr {$x2 * $tx + $y2 * $ty + $z2 * $tz}]
    # e = t x u2, r = |e| = |t_perp|
    set ex [expr {$ty * $z2 - $tz * $y2}]
    set ey [expr {$tz * $x2 - $tx * $z2}]
    set ez [expr {$tx * $y2 - $ty * $x2}]
    set r2 [expr {$ex * $ex + $ey * $ey + $ez * $ez}]
    set r [expr {sqrt($r2)}]
    if {$h > 0.0} {
        set d [expr {$dP + $w * $r2 / (1.0 + $h)}]
    } else {
        set d [expr {$dM - $w * $r2 / (1.0 - $h)}]
    }
    set rs [expr {$r * $sqnn}]
    # (abs() is a command call in expr: the ternary gives the same result)
    set ad [expr {$d > 0.0 ? $d : 0.0 - $d}]
    set D [expr {$rs - $ad}]
    if {$D < $medge} {return {unreachable {}}}
    set b [expr {($h - $wk1) / $nn}]
    set bm [expr {$b * $m1u2}]
    set bz [expr {$b * $zpu2}]
    if {$r < $singularTol} {
        set q [expr {$s1 * atan2($bm, $bz) + $o1}]
        if {$q <= $mpi || $q > $pi} {set q [Wrap $q]}
        set q2 [expr {$o2 <= $mpi || $o2 > $pi ? [Wrap $o2] : $o2}]
        return [list singular [list [list $q $q2]]]
    }
    set a [expr {$d / $nn}]
    if {$D > $edgeTol} {
        set g [expr {sqrt($D * ($rs + $ad)) / $nn}]
    } else {
        set g 0.0
    }
    # c.e = a u1.e + g n.e;  c_perp.t_perp = a u1.t_perp + g n.t
    set ue [expr {$x1 * $ex + $y1 * $ey + $z1 * $ez}]
    set ne [expr {$nx * $ex + $ny * $ey + $nz * $ez}]
    set ut [expr {$x1 * ($tx - $h * $x2) + $y1 * ($ty - $h * $y2) + $z1 * ($tz - $h * $z2)}]
    set nt [expr {$nx * $tx + $ny * $ty + $nz * $tz}]
    set au [expr {$a * $ue}]
    set at [expr {$a * $ut}]
    # g and -g: two solutions when g > 0 (a list from expr would get its
    # string made by expr's number test)
    set gs [list $g]
    if {$g > 0.0} {lappend gs [expr {-$g}]}
    set sols {}
    foreach gg $gs {
        set q1 [expr {$s1 * atan2($bm + $gg * $m1n, $bz + $gg * $zpn) + $o1}]
        set q2 [expr {$s2 * atan2($au + $gg * $ne, $at + $gg * $nt) + $o2}]
        if {$q1 <= $mpi || $q1 > $pi} {set q1 [Wrap $q1]}
        if {$q2 <= $mpi || $q2 > $pi} {set q2 [Wrap $q2]}
        lappend sols [list $q1 $q2]
    }
    list regular $sols
}

# ::fivax::kin::position --
#	Returns {X Y Z}: the linear axes that put the tool tip at P (workpiece
#	frame) with rotaries q = {q1 q2}; the forward chain solved for XYZ.
proc ::fivax::kin::position {model P q} {
    lassign $P Px Py Pz
    lassign $q q1 q2
    lassign [dict get $model geo] kc ux1 uy1 uz1 px1 py1 pz1 s1 z1 ux2 uy2 uz2 px2 py2 pz2 s2 z2 \
        hx hy hz - - - - pu pcx pcy pcz
    set a [expr {$s1 * ($q1 - $z1)}]
    set c1 [expr {cos($a)}]
    set n1 [expr {sin($a)}]
    set a [expr {$s2 * ($q2 - $z2)}]
    set c2 [expr {cos($a)}]
    set n2 [expr {sin($a)}]
    if {$kc == 0} {
        # XYZ = P - (R2 (R1 (-p1) + p1 - p2) + p2)   (hx.. -p1, pu.. u1.p1, u1 x p1)
        set k [expr {-(1.0 - $c1) * $pu}]
        set wx [expr {$hx * $c1 - $pcx * $n1 + $ux1 * $k + $px1 - $px2}]
        set wy [expr {$hy * $c1 - $pcy * $n1 + $uy1 * $k + $py1 - $py2}]
        set wz [expr {$hz * $c1 - $pcz * $n1 + $uz1 * $k + $pz1 - $pz2}]
        set k [expr {(1.0 - $c2) * ($ux2 * $wx + $uy2 * $wy + $uz2 * $wz)}]
        return [list \
            [expr {$Px - ($wx * $c2 + ($uy2 * $wz - $uz2 * $wy) * $n2 + $ux2 * $k + $px2)}] \
            [expr {$Py - ($wy * $c2 + ($uz2 * $wx - $ux2 * $wz) * $n2 + $uy2 * $k + $py2)}] \
            [expr {$Pz - ($wz * $c2 + ($ux2 * $wy - $uy2 * $wx) * $n2 + $uz2 * $k + $pz2)}]]
    }
    # Undo the table axis 2: v = R2^-1 (P - p2) + p2   (R^-1 = R(u, -a))
    set vx [expr {$Px - $px2}]; set vy [expr {$Py - $py2}]; set vz [expr {$Pz - $pz2}]
    set k [expr {(1.0 - $c2) * ($ux2 * $vx + $uy2 * $vy + $uz2 * $vz)}]
    set mx [expr {$vx * $c2 - ($uy2 * $vz - $uz2 * $vy) * $n2 + $ux2 * $k + $px2}]
    set my [expr {$vy * $c2 - ($uz2 * $vx - $ux2 * $vz) * $n2 + $uy2 * $k + $py2}]
    set mz [expr {$vz * $c2 - ($ux2 * $vy - $uy2 * $vx) * $n2 + $uz2 * $k + $pz2}]
    if {$kc == 1} {
        # XYZ = m - (R1 (-p1) + p1)
        set k [expr {-(1.0 - $c1) * $pu}]
        return [list \
            [expr {$mx + $px1 * $c1 + $pcx * $n1 - $ux1 * $k - $px1}] \
            [expr {$my + $py1 * $c1 + $pcy * $n1 - $uy1 * $k - $py1}] \
            [expr {$mz + $pz1 * $c1 + $pcz * $n1 - $uz1 * $k - $pz1}]]
    }
    # Undo the table axis 1: XYZ = R1^-1 (m - p1) + p1
    set vx [expr {$mx - $px1}]; set vy [expr {$my - $py1}]; set vz [expr {$mz - $pz1}]
    set k [expr {(1.0 - $c1) * ($ux1 * $vx + $uy1 * $vy + $uz1 * $vz)}]
    list [expr {$vx * $c1 - ($uy1 * $vz - $uz1 * $vy) * $n1 + $ux1 * $k + $px1}] \
        [expr {$vy * $c1 - ($uz1 * $vx - $ux1 * $vz) * $n1 + $uy1 * $k + $py1}] \
        [expr {$vz * $c1 - ($ux1 * $vy - $uy1 * $vx) * $n1 + $uz1 * $k + $pz1}]
}

# ::fivax::kin::interpolationError --
#	Returns {dp da}: the largest distance (mm) of the tool tip from the
#	segment P0-P1 and the largest angle (rad) of the tool axis from the
#	great-circle arc between unit axes t0 and t1, at the quarter points
#	(middle first) of the linear interpolation of joint vectors j0 to j1 on
#	model (forward kinematics only). With tol and atol it stops at the
#	first point beyond either. The planner's linearisation and the checker
#	both measure with it.
proc ::fivax::kin::interpolationError {model j0 j1 P0 P1 t0 t1 {tol Inf} {atol Inf}} {
    lassign $j0 X0 Y0 Z0 a0 b0
    lassign $j1 X1 Y1 Z1 a1 b1
    set dX [expr {$X1 - $X0}]
    set dY [expr {$Y1 - $Y0}]
    set dZ [expr {$Z1 - $Z0}]
    set da [expr {$a1 - $a0}]
    set db [expr {$b1 - $b0}]
    lassign $P0 px py pz
    lassign $P1 qx qy qz
    set ux [expr {$qx - $px}]
    set uy [expr {$qy - $py}]
    set uz [expr {$qz - $pz}]
    set len2 [expr {$ux * $ux + $uy * $uy + $uz * $uz}]
    # Arc t0-t1: unit normal n; the point t is beside the arc (not beyond
    # an end) when t.(n x t0) >= 0 and t.(t1 x n) >= 0.
    lassign $t0 ax ay az
    lassign $t1 bx by bz
    set nx [expr {$ay * $bz - $az * $by}]
    set ny [expr {$az * $bx - $ax * $bz}]
    set nz [expr {$ax * $by - $ay * $bx}]
    set nl [expr {sqrt($nx * $nx + $ny * $ny + $nz * $nz)}]
    set arc [expr {$nl >= 1e-12}]
    if {$arc} {
        set nx [expr {$nx / $nl}]
        set ny [expr {$ny / $nl}]
        set nz [expr {$nz / $nl}]
        set ex [expr {$ny * $az - $nz * $ay}]
        set ey [expr {$nz * $ax - $nx * $az}]
        set ez [expr {$nx * $ay - $ny * $ax}]
        set fx [expr {$by * $nz - $bz * $ny}]
        set fy [expr {$bz * $nx - $bx * $nz}]
        set fz [expr {$bx * $ny - $by * $nx}]
    }
    set dp 0.0
    set dg 0.0
    foreach s {0.5 0.25 0.75} {
        lassign [forward $model [list [expr {$X0 + $s * $dX}] \
            [expr {$Y0 + $s * $dY}] [expr {$Z0 + $s * $dZ}] \
            [expr {$a0 + $s * $da}] [expr {$b0 + $s * $db}]]] P t
        lassign $P x y z
        lassign $t tx ty tz
        set x [expr {$x - $px}]
        set y [expr {$y - $py}]
        set z [expr {$z - $pz}]
        # (ternaries: min() and max() are ten times slower in expr)
        set u [expr {$len2 > 0.0 ? ($x * $ux + $y * $uy + $z * $uz) / $len2 : 0.0}]
        set u [expr {$u < 0.0 ? 0.0 : $u > 1.0 ? 1.0 : $u}]
        set x [expr {$x - $u * $ux}]
        set y [expr {$y - $u * $uy}]
        set z [expr {$z - $u * $uz}]
        set d [expr {sqrt($x * $x + $y * $y + $z * $z)}]
        if {$d > $dp} {set dp $d}
        if {$arc && $tx * $ex + $ty * $ey + $tz * $ez >= 0.0
                && $tx * $fx + $ty * $fy + $tz * $fz >= 0.0} {
            set g [expr {$tx * $nx + $ty * $ny + $tz * $nz}]
            set g [expr {$g > 0.0 ? $g : 0.0 - $g}]
            set g [expr {$g < 1.0 ? asin($g) : 1.5707963267948966}]
        } else {
            set g [::fivax::vec::angle $t $t0]
            set g2 [::fivax::vec::angle $t $t1]
            if {$g2 < $g} {set g $g2}
        }
        if {$g > $dg} {set dg $g}
        if {$dp > $tol || $dg > $atol} break
    }
    list $dp $dg
}

# ::fivax::kin::interpolationBound --
#	Returns {bp ba}: upper bounds of what interpolationError measures for
#	the same move (tip distance from the segment P0-P1, mm; axis angle
#	from the great-circle arc t0-t1, rad), from the two ends alone and
#	without forward kinematics, given that the tip and the unit axis at
#	j0 and at j1 lie within ep (mm) and ea (chord length) of P0, t0 and
#	P1, t1. A move whose bounds are within a tolerance needs no
#	quarter-point check: the check could not find more.
#
#	Derivation (kinematics.md sections 2 and 7). The controller moves the
#	joints linearly, j(s) = j0 + s (j1 - j0), s in [0, 1]: each angle at
#	the rate w_i = |dq_i| (rad), the linear axes by the constant vector
#	V = dXYZ. A C2 curve c(s) stays within max|c''|/8 of the chord of its
#	ends (the error of linear interpolation, s(1 - s)/2 max|c''|, also
#	for vectors: write it with the Green function of d2/ds2). A point
#	turned about the unit axis u at the rate w through p, y = R(u) x + p,
#	has y' = R (w u x x + x') and
#	    y'' = R (w^2 u x (u x x) + 2 w u x x' + x''),
#	so |y''| <= w^2 r + 2 w |u x x'| + |x''|, r = |u x x| its distance
#	from the axis. Along the chain of section 2:
#	  head-head    tip = XYZ + R2 g + p2, g = R1 (-p1) + p1 - p2: XYZ adds
#	               nothing to c''; the zero-pose tip turns at distance
#	               r1 = |u1 x p1| about axis 1 and g at r2 about axis 2:
#	               |c''| <= w1^2 r1 + 2 w1 w2 r1 + w2^2 r2
#	  head-table   tip = R2 g + p2, g = XYZ + R1 (-p1) + p1 - p2, g' = V +
#	               w1 u1 x R1 (-p1): the extra term 2 w2 |u2 x V|
#	  table-table  tip = R2 h + p2, h = R1 (XYZ - p1) + p1 - p2, |h'| <=
#	               w1 r1 + |V|, |h''| <= w1^2 r1 + 2 w1 |u1 x V|: the
#	               extra terms 2 w2 |V| + 2 w1 |u1 x V|
#	With R = max(r1, r2) and w = w1 + w2 this is R w^2 plus 2 w |V| at
#	most where linear axes ride on table axes. The radii are bounded over
#	the move from their ends: r1 = |u1 x (XYZ - p1)| on a table-table
#	machine is convex in s (the point moves on a line), so at most its
#	larger end; r2 changes no faster than the point it measures moves
#	(speed S: w1 r1 on heads, plus |V| where XYZ rides on axis 2), so
#	min(r2(0) + s S, r2(1) + (1 - s) S) <= (r2(0) + r2(1) + S)/2. The
#	ends' r2 come from P0, P1 (the turned point is tip - XYZ - p2 on a
#	head-head machine, tip - p2 otherwise), plus ep.
#	The axis t(s) = R2 R1 Z (relation (O) of kin.tcl) has in the same way
#	|t''| <= w1^2 k1 + 2 w1 w2 k1 + w2^2 k2 <= w^2, k1 = |u1 x Z| and k2
#	<= (|u2 x t0| + |u2 x t1| + 2 ea + w1 k1)/2.
#	Against the reference ends: the straight point (1 - s) P0 + s P1 of
#	the segment is within ep of the chord, so the tip is within
#	|c''|/8 + ep of the segment; the axis t(s) is within e = |t''|/8 + ea
#	of the chord point m = (1 - s) t0 + s t1, whose direction lies on the
#	arc, so its angle from the arc is at most asin(e) (the ball of radius
#	e about a unit vector subtends that angle). Margins cover rounding:
#	1e-9 of the coordinates' size for the tip, and 1e-10 rad plus ten
#	times the error of the arc's normal (about 1e-15/|t0 x t1|, where
#	interpolationError measures against the arc) for the axis.
#	ba is Inf when e reaches 1.
proc ::fivax::kin::interpolationBound {model j0 j1 P0 P1 t0 t1 ep ea} {
    variable lastEnd
    lassign $j0 X0 Y0 Z0 a0 b0
    lassign $j1 X1 Y1 Z1 a1 b1
    set bound [dict get $model bound]
    # The terms of an end: s, the distance from axis 2 of the point it
    # turns (relative to p2: tip - XYZ - p2 on a head-head machine, tip -
    # p2 otherwise), n = |u2 x t|, and q, on a table-table machine the
    # distance of XYZ from axis 1 (else 0). End 0's are the last call's
    # end 1 ones when the move starts there, as the moves of a path do:
    # the same bound, tip and axis lists (eq: the very objects, found equal
    # at once; equal strings are equal numbers) and X Y Z (never NaN: expr
    # makes none; signed zeros do not matter: the terms square what they
    # sum). Otherwise they are those of end 1 of the move that stays at
    # end 0, bounded first (its own end 0 taken as 0: only its end 1 is
    # kept).
    lassign $lastEnd cb cP ct cX cY cZ s0 n0 q0
    if {!($cb eq $bound && $cP eq $P0 && $ct eq $t0 && $cX == $X0 && $cY == $Y0 && $cZ == $Z0)} {
        set lastEnd [list $bound $P0 $t0 $X0 $Y0 $Z0 0.0 0.0 0.0]
        interpolationBound $model $j0 $j0 $P0 $P0 $t0 $t0 0.0 0.0
        lassign $lastEnd - - - - - - s0 n0 q0
    }
    lassign $bound kc ux2 uy2 uz2 px2 py2 pz2 rh k1 scale
    lassign $P0 x0 y0 z0
    lassign $P1 x1 y1 z1
    lassign $t1 bx by bz
    # (abs() is a command call in expr: the ternaries give the same results
    # at a fraction of the cost; a zero may differ only in its sign)
    set w1 [expr {$a1 > $a0 ? $a1 - $a0 : $a0 - $a1}]
    set w2 [expr {$b1 > $b0 ? $b1 - $b0 : $b0 - $b1}]
    # the terms of end 1
    if {$kc == 0} {
        set fx [expr {$x1 - $X1 - $px2}]; set fy [expr {$y1 - $Y1 - $py2}]; set fz [expr {$z1 - $Z1 - $pz2}]
    } else {
        set fx [expr {$x1 - $px2}]; set fy [expr {$y1 - $py2}]; set fz [expr {$z1 - $pz2}]
    }
    set s1 [expr {sqrt(($uy2 * $fz - $uz2 * $fy) ** 2 + ($uz2 * $fx - $ux2 * $fz) ** 2
        + ($ux2 * $fy - $uy2 * $fx) ** 2)}]
    set n1 [expr {sqrt(($uy2 * $bz - $uz2 * $by) ** 2 + ($uz2 * $bx - $ux2 * $bz) ** 2
        + ($ux2 * $by - $uy2 * $bx) ** 2)}]
    set q1 0.0
    if {$kc == 2} {
        lassign [lrange $bound end-5 end] ux1 uy1 uz1 px1 py1 pz1
        set fx [expr {$X1 - $px1}]; set fy [expr {$Y1 - $py1}]; set fz [expr {$Z1 - $pz1}]
        set q1 [expr {sqrt(($uy1 * $fz - $uz1 * $fy) ** 2 + ($uz1 * $fx - $ux1 * $fz) ** 2
            + ($ux1 * $fy - $uy1 * $fx) ** 2)}]
    }
    set lastEnd [list $bound $P1 $t1 $X1 $Y1 $Z1 $s1 $n1 $q1]
    set r2 [expr {$s0 + $s1 + 2.0 * $ep}]
    if {$kc == 0} {
        set r1 $rh
        set r2 [expr {0.5 * ($r2 + $w1 * $r1)}]
        set lin 0.0
    } else {
        set vx [expr {$X1 - $X0}]
        set vy [expr {$Y1 - $Y0}]
        set vz [expr {$Z1 - $Z0}]
        set v [expr {sqrt($vx * $vx + $vy * $vy + $vz * $vz)}]
        if {$kc == 1} {
            set r1 $rh
            set lin [expr {2.0 * $w2 * sqrt(($uy2 * $vz - $uz2 * $vy) ** 2
                + ($uz2 * $vx - $ux2 * $vz) ** 2 + ($ux2 * $vy - $uy2 * $vx) ** 2)}]
        } else {
            set r1 [expr {$q1 > $q0 ? $q1 : $q0}]
            set lin [expr {2.0 * $w2 * $v + 2.0 * $w1 * sqrt(($uy1 * $vz - $uz1 * $vy) ** 2
                + ($uz1 * $vx - $ux1 * $vz) ** 2 + ($ux1 * $vy - $uy1 * $vx) ** 2)}]
        }
        set r2 [expr {0.5 * ($r2 + $w1 * $r1 + $v)}]
    }
    set size [expr {$scale + ($X0 > 0.0 ? $X0 : 0.0 - $X0) + ($Y0 > 0.0 ? $Y0 : 0.0 - $Y0)
        + ($Z0 > 0.0 ? $Z0 : 0.0 - $Z0) + ($X1 > 0.0 ? $X1 : 0.0 - $X1)
        + ($Y1 > 0.0 ? $Y1 : 0.0 - $Y1) + ($Z1 > 0.0 ? $Z1 : 0.0 - $Z1)
        + ($x0 > 0.0 ? $x0 : 0.0 - $x0) + ($y0 > 0.0 ? $y0 : 0.0 - $y0)
        + ($z0 > 0.0 ? $z0 : 0.0 - $z0) + ($x1 > 0.0 ? $x1 : 0.0 - $x1)
        + ($y1 > 0.0 ? $y1 : 0.0 - $y1) + ($z1 > 0.0 ? $z1 : 0.0 - $z1)}]
    # w1^2 + 2 w1 w2, the factor of r1 and of k1
    set ww [expr {$w1 * ($w1 + 2.0 * $w2)}]
    set bp [expr {($ww * $r1 + $w2 * $w2 * $r2 + $lin) / 8.0 + $ep
        + 1e-9 * (1.0 + $size)}]
    # the axis: k2 from |u2 x t| at the ends
    set k2 [expr {0.5 * ($n0 + $n1 + 2.0 * $ea + $w1 * $k1)}]
    set e [expr {($ww * $k1 + $w2 * $w2 * $k2) / 8.0 + $ea}]
    if {$e >= 1.0} {return [list $bp Inf]}
    lassign $t0 ax ay az
    set nl [expr {sqrt(($ay * $bz - $az * $by) ** 2 + ($az * $bx - $ax * $bz) ** 2
        + ($ax * $by - $ay * $bx) ** 2)}]
    set ba [expr {asin($e) + 1e-10 + ($nl > 5e-13 ? 1e-14 / $nl : 0.0)}]
    list $bp $ba
}

# ::fivax::kin::Wrap -- Returns angle a (radians) wrapped into (-pi, pi], never -0.0.
proc ::fivax::kin::Wrap {a} {
    variable pi
    set a [expr {atan2(sin($a), cos($a)) + 0.0}]
    if {$a <= -$pi} {set a [expr {$a + 2.0 * $pi}]}
    return $a
}
