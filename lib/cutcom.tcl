# cutcom.tcl --
#	3D tool-radius compensation done by the post (issue 26, -cutcom3d
#	post): a CL point programmed for one cutter is moved so that a cutter
#	of another size touches the surface at the same contact point with
#	the same surface normal (the CL's contact data). Cutters are {D r}:
#	diameter and corner radius, 0 <= r <= D/2 (r = D/2 a ball, r = 0 a
#	flat end, else a bull-nose, the torus of kinematics.md section 11).
#	Geometry only: the post decides which moves are compensated.
#	Errors are {FIVAX CUTCOM <detail>}.

namespace eval ::fivax::cutcom {
    namespace export tip compensate concaveRadius fits cutters
    namespace ensemble create -prefixes 0
    # Below this length of the normal's part across the tool axis the
    # contact counts as on the flat bottom (see tip).
    variable flat 1e-4
    # Largest distance (mm) between the CL point and the tip the contact
    # data give for the programmed cutter: more is a contact record that
    # does not belong to its CL point (the CLSF's 4 decimals give < 1e-3).
    variable fit 0.005
}

# ::fivax::cutcom::tip --
#	Returns the tool tip of the cutter {D r} with unit axis t that touches
#	the surface at contact point C with unit surface normal n (pointing
#	out of the material, towards the cutter).
#
#	Derivation (kinematics.md section 11: torus of centre-circle radius
#	R = D/2 - r and tube radius r, the tip the centre of its bottom):
#	where the cutter touches, its own outward normal is -n, so the tube
#	centre is c = C + r n. c lies on the centre circle, at height r above
#	the tip P along t and at distance R from the axis, on the side across
#	the axis that the cutter's normal -n points to: with
#	m = unit(n - (n.t) t), the part of n across the axis,
#	c = P + r t - R m, hence
#	    P = C + r n + R m - r t.
#	Ball (R = 0): P = C + r (n - t); flat end (r = 0): P = C + R m.
#	The compensation of a change of cutter is the difference of two such
#	tips at the same C, n, t:
#	    dP = (r' - r)(n - t) + (R' - R) m.
#	Degenerate case: n along t (the flat bottom on a face square to the
#	axis) leaves m undefined, as every point of the flat bottom touches.
#	Rule: m = 0, the contact taken under the tip (P = C + r (n - t) = C
#	for n = t), so the tip stays on the face whatever the cutter and dP
#	is 0. The rule holds while |n - (n.t) t| < flat: the tip is then
#	off by at most (R' - R) * flat along the face's slope (3e-4 mm for
#	R' - R = 3 mm).
proc ::fivax::cutcom::tip {C n t D r} {
    variable flat
    set R [expr {$D / 2.0 - $r}]
    set across [::fivax::vec::sub $n [::fivax::vec::scale [::fivax::vec::dot $n $t] $t]]
    set len [::fivax::vec::norm $across]
    set P [::fivax::vec::add $C [::fivax::vec::scale $r [::fivax::vec::sub $n $t]]]
    if {$len < $flat} {return $P}
    ::fivax::vec::add $P [::fivax::vec::scale [expr {$R / $len}] $across]
}

# ::fivax::cutcom::compensate --
#	Returns the tip for cutter actual ({D r}) of the CL point P (axis t)
#	programmed for cutter programmed, from its contact point C and unit
#	normal n: P + tip(actual) - tip(programmed) (see tip).
#	Errors: {FIVAX CUTCOM CONTACT} when the contact data do not fit P for
#	the programmed cutter (off by more than fit mm).
proc ::fivax::cutcom::compensate {P t C n programmed actual} {
    variable fit
    set nominal [tip $C $n $t {*}$programmed]
    set off [::fivax::vec::dist $nominal $P]
    if {$off > $fit} {
        ::fivax::Fail CUTCOM CONTACT [format "the contact point and normal do not fit the CL point\
            for the programmed cutter D %g r %g: its tip would lie %.4f mm from it (at most %g)" \
            {*}$programmed $off $fit]
    }
    ::fivax::vec::add $P [::fivax::vec::sub [tip $C $n $t {*}$actual] $nominal]
}

# ::fivax::cutcom::concaveRadius --
#	Returns the radius of the concave bend of the surface between two
#	contacts (points C1 C2, unit normals n1 n2), or Inf where it is
#	flat or convex along the move. On a circle of radius rho bending
#	towards its normal (concave), n = (centre - C) / rho, so
#	dn = -dC / rho and rho = |dC|^2 / -(dn . dC); convex bends give
#	dn . dC > 0. Exact on circles, the curvature of the normal section
#	along the move elsewhere (to the first order in |dC|).
proc ::fivax::cutcom::concaveRadius {C1 n1 C2 n2} {
    set dC [::fivax::vec::sub $C2 $C1]
    set bend [expr {-[::fivax::vec::dot [::fivax::vec::sub $n2 $n1] $dC]}]
    set dd [::fivax::vec::dot $dC $dC]
    if {$bend <= 1e-12 * $dd || $dd == 0.0} {return Inf}
    expr {$dd / $bend}
}

# ::fivax::cutcom::fits --
#	Returns "" when cutter {D r} fits a concave bend of radius rho, else
#	why not: the cutter's smallest radius of curvature is its corner
#	radius r (its torus's tube; the ball's radius), so a concave bend of
#	radius below r is gouged whatever the tool axis. (A necessary check,
#	not a sufficient one: a tilted flat bottom can gouge wider bends.)
proc ::fivax::cutcom::fits {rho D r} {
    if {$rho >= $r} {return ""}
    format "the surface bends concavely with a radius of %.4f mm there, smaller than the\
        corner radius %g mm of the cutter D %g r %g" $rho $r $D $r
}

# ::fivax::cutcom::cutters --
#	Returns {programmed actual}, the cutters {D r} of a compensation: the
#	CL's (diameter D, corner radius r: TLDATA) and the one in the spindle
#	(diameter Da, corner radius ra, by default the CL's r).
#	Errors: {FIVAX CUTCOM TOOL} when the CL gives no diameter or the
#	default corner radius exceeds half of Da.
proc ::fivax::cutcom::cutters {D r Da ra} {
    if {!($D > 0)} {
        ::fivax::Fail CUTCOM TOOL "-cutcom3d post: the CL gives no cutter diameter (TLDATA) to\
            compensate from"
    }
    if {$ra eq ""} {set ra $r}
    if {$ra > $Da / 2.0} {
        ::fivax::Fail CUTCOM TOOL [format "-cutcom3d post: the CL's corner radius %g does not\
            fit the -tool-diameter %g: give -tool-corner-radius (at most %g)" $r $Da [expr {$Da / 2.0}]]
    }
    list [list $D $r] [list $Da $ra]
}
