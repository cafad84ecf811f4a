# curve.tcl --
#	CL path geometry the post needs between two CL points: circular and
#	helical arcs (CIRCLE + GOTO) and NURBS curves (NX CLSF NURBS/KNOT/CNTRL)
#	as points within a chord tolerance, and arcs split into pieces the way
#	NX hands them to a post. Points are {x y z} lists in mm.
#
#	An arc turns about the line through center along axis, clockwise
#	(sense -1) or counter-clockwise (sense 1) about axis, from start to
#	end plus turns extra full turns; radius and axial height vary linearly
#	with the angle (helixes, slightly inconsistent CL data). start = end
#	is a full circle.

namespace eval ::fivax::curve {
    namespace export arc arcSplit arcLength radius nurbs nurbsAt nurbsPoints nurbsSamples clsfNurbs
    namespace ensemble create -prefixes 0
    namespace upvar ::fivax::num pi pi reach reach
}

# ::fivax::curve::arc --
#	Returns the points after start up to and including end of an arc (see
#	the file header) with chord error at most tol (mm).
proc ::fivax::curve::arc {start end center axis sense turns tol} {
    variable pi
    set frame [ArcFrame $start $end $center $axis $sense $turns]
    if {$frame eq ""} {return [list $end]}
    lassign $frame - - - - r0 r1 - sweep
    set rmax [expr {max($r0, $r1)}]
    set step [expr {$tol >= $rmax ? $pi / 2.0 : 2.0 * acos(1.0 - $tol / $rmax)}]
    set count [expr {max(1, int(ceil($sweep / $step)))}]
    set out {}
    for {set i 1} {$i < $count} {incr i} {
        lappend out [ArcPoint $frame [expr {double($i) / $count}]]
    }
    lappend out $end
}

# ::fivax::curve::arcSplit --
#	Returns the pieces of an arc (see the file header) each turning at
#	most maxSweep (radians): a list of {endPoint sweep} (sweep in radians),
#	the last ending at end. A degenerate arc (start or end on the axis)
#	is one piece of sweep 0.
proc ::fivax::curve::arcSplit {start end center axis sense turns maxSweep} {
    set frame [ArcFrame $start $end $center $axis $sense $turns]
    if {$frame eq ""} {return [list [list $end 0.0]]}
    set sweep [lindex $frame end-1]
    set count [expr {max(1, int(ceil($sweep / $maxSweep - 1e-9)))}]
    set out {}
    set done 0.0
    for {set i 1} {$i < $count} {incr i} {
        lappend out [list [ArcPoint $frame [expr {$i * $maxSweep / $sweep}]] $maxSweep]
        set done [expr {$done + $maxSweep}]
    }
    lappend out [list $end [expr {$sweep - $done}]]
}

# ::fivax::curve::arcLength --
#	Returns the length (mm) of an arc (see the file header): its sweep at
#	the mean radius, with the axial rise of a helix.
proc ::fivax::curve::arcLength {start end center axis sense turns} {
    set frame [ArcFrame $start $end $center $axis $sense $turns]
    if {$frame eq ""} {return [::fivax::vec::dist $end $start]}
    lassign $frame - - hs he r0 r1 - sweep
    expr {hypot(0.5 * ($r0 + $r1) * $sweep, $he - $hs)}
}

# ::fivax::curve::radius -- Returns the distance of point p from the line through center along axis.
proc ::fivax::curve::radius {p center axis} {
    set n [::fivax::vec::unit $axis]
    set d [::fivax::vec::sub $p $center]
    ::fivax::vec::norm [::fivax::vec::sub $d [::fivax::vec::scale [::fivax::vec::dot $d $n] $n]]
}

# ::fivax::curve::ArcFrame --
#	Returns {center n hs he r0 r1 u sweep sense} of an arc: unit axis n,
#	axial heights of start and end above center, their radii, the unit
#	radial direction u of start, the total sweep (radians, > 0) and the
#	sense; "" when start or end lies on the axis.
#	Errors: {FIVAX CURVE REACH} for a point beyond reach (arc, arcSplit
#	and arcLength raise it too).
proc ::fivax::curve::ArcFrame {start end center axis sense turns} {
    variable pi
    variable reach
    foreach p [list $start $end $center] what {start end centre} {
        foreach c $p {
            if {!(abs($c) <= $reach)} {
                ::fivax::Fail CURVE REACH "arc: its $what ([join [lmap c $p {format %g $c}] ,])\
                    lies beyond [format %g $reach] mm of the origin"
            }
        }
    }
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

# ::fivax::curve::ArcPoint -- Returns the point at fraction f of the arc of frame (see ArcFrame).
proc ::fivax::curve::ArcPoint {frame f} {
    lassign $frame center n hs he r0 r1 u sweep sense
    set dir [::fivax::vec::rotate $n [expr {$sense > 0 ? $f * $sweep : -$f * $sweep}] $u]
    set radial [::fivax::vec::scale [expr {$r0 + $f * ($r1 - $r0)}] $dir]
    set axial [::fivax::vec::scale [expr {$hs + $f * ($he - $hs)}] $n]
    ::fivax::vec::add $center [::fivax::vec::add $radial $axial]
}

# NURBS curves.
#
# A curve is a dict made by [nurbs]: degree p, knots (the full vector, n+p+1
# values), points (n control points {x y z}), weights (n values > 0), domain
# {a b} = {knot p, knot n}, and hom (the points in homogeneous form
# {wx wy wz w}, internal). Evaluation is de Boor's algorithm run as a blossom
# (one parameter per level), which also gives each knot span's Bezier control
# points, which [nurbsSamples] uses to bound the chord error.
#
# NX CLSF convention ([clsfNurbs]). NX writes a spline move as "NURBS/"
# (never with arguments), then KNOT/ records (values in (0,1], ascending,
# the last 1.0) and CNTRL/x,y,z records (never a weight). It maps to:
#   - control points: the current CL position (the GOTO before, or the end
#     of the NURBS before) followed by the CNTRL points;
#   - degree p = #CNTRL - #KNOT + 1: 3 in all 70 corpus curves
#     (nx_fixed_contour_nurbs.cls, every one with #CNTRL = #KNOT + 2);
#   - knots: p+1 zeros, the KNOT values, then p more ones: clamped, so the
#     curve starts at the current position and ends exactly at the last
#     CNTRL point. A GOTO after a NURBS is a separate linear move from there;
#   - weights: all 1 (a polynomial B-spline).
# No public NX document states this; it was established from the corpus
# file by trying every knot layout whose counts fit (degree 1..5; current
# position prepended or not; next GOTO appended or not; a leading zeros,
# b more trailing ones) on all 70 curves:
#   - Of the layouts without the next GOTO, only the one above and a
#     quartic 00000 + KNOT + 111 (which ends up to 17.0 mm short of the last
#     CNTRL point) start at the current position. Without it prepended the
#     curves start 0.30..22.4 mm (mean 6.2) away (quadratic 000 + KNOT +
#     11, the only other layout clamped at both ends) or up to 69.5 mm
#     away (unclamped). With it, a NURBS right after a NURBS (24 of them)
#     starts where the one before ended.
#   - Appending the next GOTO fails: 25 curves have none (another NURBS or
#     the end follows), and after the others it is a stepover (PAINT/COLOR
#     36 in between, 14.6 mm across the pass) or a line to the next GOTO.
#   - Tangents: 21 of the 25 curves after a GOTO line start within 1.5..1.9
#     deg of its direction (4.8..21.4 deg with the quadratic reading; the
#     other four, 5.6..90 deg, follow an engage, stepovers and a short
#     link); the 24 NURBS-to-NURBS joins turn 1.9..5.7 deg.
#   - Independent geometry: the part is an extrusion along X, so the zig
#     and zag passes trace one profile in YZ. Each curve lies within
#     0.029 mm (mean 0.0008) of a curve of another pass (quadratic reading:
#     0.134, mean 0.0049), and the GOTOs lie within median 0.0094, 90%
#     0.0134 mm of the other passes' curves (quadratic reading: 0.0227),
#     about NX's fit tolerance.
# NX's own MOM_nurbs_move variables (mom_nurbs_order, mom_nurbs_knots,
# mom_nurbs_points, mom_nurbs_*_count) are the post's side, not read here.

# ::fivax::curve::nurbs --
#	Returns a NURBS curve from degree p (1 to 32), the full knot vector (n+p+1
#	non-decreasing values; no value more than p+1 times, nor more than p
#	times inside the domain, which must not be empty), n >= p+1 control
#	points {x y z} and n weights > 0 ({} = all 1). Coordinates are at most
#	reach (1e9) in size, weights within [1e-6, 1e6].
#	Errors {FIVAX CURVE DEGREE|KNOTS|POINTS|WEIGHTS} "nurbs: what".
proc ::fivax::curve::nurbs {degree knots points {weights {}}} {
    variable reach
    set p [::fivax::num::int $degree]
    if {$p eq "" || $p < 1 || $p > 32} {
        ::fivax::Fail CURVE DEGREE "nurbs: degree must be an integer from 1 to 32, got '$degree'"
    }
    set n [llength $points]
    if {$n < $p + 1} {
        ::fivax::Fail CURVE POINTS \
            "nurbs: degree $p needs at least [expr {$p + 1}] points, got $n"
    }
    set pts {}
    foreach pt $points {
        if {[llength $pt] != 3} {
            ::fivax::Fail CURVE POINTS "nurbs: point '$pt' is not three numbers"
        }
        lappend pts [lmap c $pt {Real $c $reach POINTS "coordinate"}]
    }
    if {![llength $weights]} {
        set weights [lrepeat $n 1.0]
    } elseif {[llength $weights] != $n} {
        ::fivax::Fail CURVE WEIGHTS \
            "nurbs: $n points need $n weights, got [llength $weights]"
    }
    set w {}
    foreach v $weights {
        set v [Real $v 1e6 WEIGHTS "weight"]
        if {!($v >= 1e-6)} {
            ::fivax::Fail CURVE WEIGHTS "nurbs: weight $v is not within \[1e-6, 1e6\]"
        }
        lappend w $v
    }
    set m [expr {$n + $p + 1}]
    if {[llength $knots] != $m} {
        ::fivax::Fail CURVE KNOTS \
            "nurbs: $n points of degree $p need $m knots, got [llength $knots]"
    }
    set U [lmap u $knots {Real $u 1e9 KNOTS "knot"}]
    set a [lindex $U $p]
    set b [lindex $U $n]
    set run 0
    for {set i 0} {$i < $m} {incr i} {
        set u [lindex $U $i]
        if {$i > 0 && $u < [lindex $U $i-1]} {
            ::fivax::Fail CURVE KNOTS "nurbs: knots decrease at [lindex $U $i-1], $u"
        }
        set run [expr {$i > 0 && $u == [lindex $U $i-1] ? $run + 1 : 1}]
        if {$run > $p + 1 || ($run > $p && $u > $a && $u < $b)} {
            ::fivax::Fail CURVE KNOTS \
                "nurbs: knot $u repeats more than [expr {$run - 1}] times (degree $p)"
        }
    }
    if {!($a < $b)} {
        ::fivax::Fail CURVE KNOTS "nurbs: empty domain \[$a, $b\]"
    }
    set hom {}
    foreach pt $pts wi $w {
        lassign $pt x y z
        lappend hom [list [expr {$wi * $x}] [expr {$wi * $y}] [expr {$wi * $z}] $wi]
    }
    dict create degree $p knots $U points $pts weights $w domain [list $a $b] hom $hom
}

# ::fivax::curve::Real --
#	Returns v as a finite double of size at most max, or raises
#	{FIVAX CURVE code} "nurbs: what 'v' is not a number of size at most max".
proc ::fivax::curve::Real {v max code what} {
    set x [::fivax::num::parse $v]
    if {$x eq "" || abs($x) > $max} {
        ::fivax::Fail CURVE $code "nurbs: $what '$v' is not a number of size at most $max"
    }
    return $x
}

# ::fivax::curve::clsfNurbs --
#	Returns the NURBS curve of an NX CLSF spline move (see the convention
#	above): start is the current CL position {x y z}, knots the values of
#	its KNOT records in order, cntrl the points of its CNTRL records.
#	Errors {FIVAX CURVE KNOTS} (counts, first value not > 0, last not 1),
#	and those of nurbs.
proc ::fivax::curve::clsfNurbs {start knots cntrl} {
    set nk [llength $knots]
    set p [expr {[llength $cntrl] - $nk + 1}]
    if {$nk < 1 || $p < 1} {
        ::fivax::Fail CURVE KNOTS \
            "clsfNurbs: $nk KNOT values need at least [expr {max(1, $nk)}] CNTRL points, got [llength $cntrl]"
    }
    set first [::fivax::num::parse [lindex $knots 0]]
    set last [::fivax::num::parse [lindex $knots end]]
    if {$first eq "" || !($first > 0.0)} {
        ::fivax::Fail CURVE KNOTS "clsfNurbs: the first KNOT value must be > 0, got '[lindex $knots 0]'"
    }
    if {$last eq "" || abs($last - 1.0) > 1e-7} {
        ::fivax::Fail CURVE KNOTS "clsfNurbs: the last KNOT value must be 1, got '[lindex $knots end]'"
    }
    set U [concat [lrepeat [expr {$p + 1}] 0.0] [lrange $knots 0 end-1] [lrepeat [expr {$p + 1}] 1.0]]
    nurbs $p $U [linsert $cntrl 0 $start]
}

# ::fivax::curve::nurbsAt --
#	Returns the point {x y z} of curve at parameter t within its domain.
#	Errors {FIVAX CURVE PARAM}.
proc ::fivax::curve::nurbsAt {curve t} {
    lassign [dict get $curve domain] a b
    set u [::fivax::num::parse $t]
    if {$u eq "" || $u < $a || $u > $b} {
        ::fivax::Fail CURVE PARAM "nurbsAt: parameter '$t' is outside the domain \[$a, $b\]"
    }
    Point $curve $u
}

# ::fivax::curve::Point -- Returns the point of curve at u (in its domain).
proc ::fivax::curve::Point {curve u} {
    set p [dict get $curve degree]
    Project [Blossom [dict get $curve knots] $p [dict get $curve hom] \
        [Span $curve $u] [lrepeat $p $u]]
}

# ::fivax::curve::Span --
#	Returns the index k (p <= k < n) of the non-empty knot span
#	[knot k, knot k+1) holding u; the last one for u at the domain's end.
proc ::fivax::curve::Span {curve u} {
    set U [dict get $curve knots]
    set p [dict get $curve degree]
    set n [llength [dict get $curve points]]
    if {$u >= [lindex $U $n]} {
        set k [expr {$n - 1}]
        while {[lindex $U $k] == [lindex $U $k+1]} {incr k -1}
        return $k
    }
    set lo $p
    set hi $n
    # Invariant: knot lo <= u < knot hi.
    while {$hi - $lo > 1} {
        set mid [expr {($lo + $hi) / 2}]
        if {$u < [lindex $U $mid]} {set hi $mid} else {set lo $mid}
    }
    return $lo
}

# ::fivax::curve::Blossom --
#	Returns the homogeneous blossom value of span k of the curve with knots
#	U, degree p and homogeneous points hom at the p parameters params (de
#	Boor's algorithm with params' r-th value at level r): all equal to t
#	gives the point at t; a..a b..b gives the span's Bezier control points.
proc ::fivax::curve::Blossom {U p hom k params} {
    set d [lrange $hom [expr {$k - $p}] $k]
    for {set r 1} {$r <= $p} {incr r} {
        set s [lindex $params $r-1]
        for {set j $p} {$j >= $r} {incr j -1} {
            set lo [lindex $U [expr {$k - $p + $j}]]
            set al [expr {($s - $lo) / ([lindex $U [expr {$k + 1 + $j - $r}]] - $lo)}]
            set be [expr {1.0 - $al}]
            lassign [lindex $d $j-1] ax ay az aw
            lassign [lindex $d $j] bx by bz bw
            # (1-al) a + al b: exactly a at al = 0 and b at al = 1.
            lset d $j [list [expr {$be * $ax + $al * $bx}] [expr {$be * $ay + $al * $by}] \
                [expr {$be * $az + $al * $bz}] [expr {$be * $aw + $al * $bw}]]
        }
    }
    lindex $d $p
}

# ::fivax::curve::Project -- Returns the point {x y z} of homogeneous h.
proc ::fivax::curve::Project {h} {
    lassign $h x y z w
    if {$w == 1.0} {return [list $x $y $z]}
    list [expr {$x / $w}] [expr {$y / $w}] [expr {$z / $w}]
}

# ::fivax::curve::nurbsPoints --
#	Returns the points after the start of curve up to and including its
#	end such that the polyline from the start through them stays within
#	tol (mm, > 0) of the curve (see nurbsSamples).
proc ::fivax::curve::nurbsPoints {curve tol {limit 100000}} {
    lmap {t pt} [nurbsSamples $curve $tol $limit] {set pt}
}

# ::fivax::curve::nurbsSamples --
#	Returns {t1 p1 t2 p2 ...}: the points of nurbsPoints with their
#	parameters, ascending, the last at the domain's end. Each chord and the
#	piece of curve it replaces are within tol of each other. Work is
#	bounded: needing more than limit points, or more than 8 (limit + n)
#	chord trials, raises {FIVAX CURVE LIMIT}; a bad tol or limit
#	{FIVAX CURVE TOL}.
#	Chords are found by marching: a trial chord from t to t1 is accepted
#	when a bound on the distance of the curve between t and t1 from the
#	chord (from the Bezier control polygons, see Deviation) is at most
#	tol; by continuity the chord is then within tol of the curve too. The
#	next trial length follows from the bound found (~ length squared).
proc ::fivax::curve::nurbsSamples {curve tol {limit 100000}} {
    set tl [::fivax::num::parse $tol]
    if {$tl eq "" || !($tl > 0.0)} {
        ::fivax::Fail CURVE TOL "nurbsPoints: tolerance must be a number > 0, got '$tol'"
    }
    set lim [::fivax::num::int $limit]
    if {$lim eq "" || $lim < 1} {
        ::fivax::Fail CURVE TOL "nurbsPoints: limit must be an integer >= 1, got '$limit'"
    }
    set n [llength [dict get $curve points]]
    lassign [dict get $curve domain] t b
    set from [Point $curve $t]
    set h [expr {$b - $t}]
    set trials [expr {8 * ($lim + $n)}]
    set out {}
    set cache {}
    while {$t < $b} {
        set t1 [expr {min($b, $t + $h)}]
        if {[incr trials -1] < 0 || $t1 <= $t || [llength $out] >= 2 * $lim} {
            ::fivax::Fail CURVE LIMIT \
                "nurbsPoints: cannot meet tolerance $tl within $lim points"
        }
        set to [Point $curve $t1]
        set dev [Deviation $curve $t $t1 $from $to $tl cache]
        # Deviation ~ length squared: aim at 0.8 tol next time.
        set f [expr {$dev > 0.0 ? 0.9 * sqrt($tl / $dev) : 2.0}]
        if {$dev <= $tl} {
            lappend out $t1 $to
            set h [expr {($t1 - $t) * min(2.0, max(1.0, $f))}]
            set t $t1
            set from $to
        } else {
            set h [expr {($t1 - $t) * min(0.7, max(0.05, $f))}]
        }
    }
    return $out
}

# ::fivax::curve::Deviation --
#	Returns a bound on the distance of curve between parameters t0 and t1
#	from the chord from..to; stops early once it exceeds tol. Each Bezier
#	piece (one per knot span crossed, control points P0..Pp, weights w)
#	is bounded by the smaller of
#	  - the largest distance of its control points from the chord (convex
#	    hull), and
#	  - S max|Pi - Li| plus the larger distance of P0, Pp from the chord,
#	    where Li = P0 + i/p (Pp - P0): the piece minus the point sum Ri Li
#	    of its own chord is sum Ri (Pi - Li), and the interior rational
#	    basis functions sum to at most S = wI (1-c) / (wE c + wI (1-c)),
#	    c = 2^(1-p), wI the largest interior and wE the smaller end weight
#	    (3/4 for a cubic, 1/2 for a quadratic with equal weights).
#	Whole spans' control points are kept in the dict in the caller's
#	variable cacheVar.
proc ::fivax::curve::Deviation {curve t0 t1 from to tol cacheVar} {
    upvar 1 $cacheVar cache
    set U [dict get $curve knots]
    set p [dict get $curve degree]
    set hom [dict get $curve hom]
    set c [expr {2.0 ** (1 - $p)}]
    set worst 0.0
    for {set k [Span $curve $t0]} {$k < [llength $U] - 1 && [lindex $U $k] < $t1} {incr k} {
        set a [lindex $U $k]
        set b [lindex $U $k+1]
        set s [expr {max($t0, $a)}]
        set e [expr {min($t1, $b)}]
        if {!($s < $e)} continue
        set whole [expr {$s == $a && $e == $b}]
        if {$whole && [dict exists $cache $k]} {
            set bez [dict get $cache $k]
        } else {
            set bez {}
            for {set i 0} {$i <= $p} {incr i} {
                lappend bez [Blossom $U $p $hom $k \
                    [concat [lrepeat [expr {$p - $i}] $s] [lrepeat $i $e]]]
            }
            if {$whole} {dict set cache $k $bez}
        }
        set q [lmap h $bez {Project $h}]
        set hull 0.0
        foreach pt $q {set hull [expr {max($hull, [SegmentDistance $pt $from $to])}]}
        set p0 [lindex $q 0]
        set pp [lindex $q end]
        set ends [expr {max([SegmentDistance $p0 $from $to], [SegmentDistance $pp $from $to])}]
        set leg 0.0
        set wI 0.0
        for {set i 1} {$i < $p} {incr i} {
            set li [::fivax::vec::lerp $p0 $pp [expr {double($i) / $p}]]
            set leg [expr {max($leg, [::fivax::vec::dist [lindex $q $i] $li])}]
            set wI [expr {max($wI, [lindex $bez $i 3])}]
        }
        set wE [expr {min([lindex $bez 0 3], [lindex $bez end 3])}]
        set S [expr {$wI * (1.0 - $c) / ($wE * $c + $wI * (1.0 - $c))}]
        set worst [expr {max($worst, min($hull, $S * $leg + $ends))}]
        if {$worst > $tol} break
    }
    return $worst
}

# ::fivax::curve::SegmentDistance -- Returns the distance of point q from the segment a-b.
proc ::fivax::curve::SegmentDistance {q a b} {
    lassign $q x y z
    lassign $a ax ay az
    lassign $b bx by bz
    set ux [expr {$bx - $ax}]
    set uy [expr {$by - $ay}]
    set uz [expr {$bz - $az}]
    set dx [expr {$x - $ax}]
    set dy [expr {$y - $ay}]
    set dz [expr {$z - $az}]
    set len2 [expr {$ux * $ux + $uy * $uy + $uz * $uz}]
    set f [expr {$len2 > 0.0 ? ($dx * $ux + $dy * $uy + $dz * $uz) / $len2 : 0.0}]
    set f [expr {min(1.0, max(0.0, $f))}]
    set dx [expr {$dx - $f * $ux}]
    set dy [expr {$dy - $f * $uy}]
    set dz [expr {$dz - $f * $uz}]
    expr {sqrt($dx * $dx + $dy * $dy + $dz * $dz)}
}
