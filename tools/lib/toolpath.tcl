# toolpath.tcl --
#	Synthetic five-axis CL data for the tools and the tests (not loaded by
#	the post): the example surface S(u,v) of kinematics.md section 11, tool
#	tip and axis of a toroidal end mill at a contact point, a zig-zag
#	raster over S, simple sweep paths that exercise the rotary axes
#	(winding, the +Z pole), and NX-style CLSF text for them. Needs the
#	fivax package (vec, num, opts).
#
#	Points are {x y z} lists in mm; a CL point is {P t}: tool tip P and unit
#	tool axis t (tip towards spindle), as NX writes them. Angles given to
#	torusCL are radians; options of raster and sweep are degrees.
#	Errors are {FIVAX OPTION ...} for options and {FIVAX TOOLPATH <detail>}:
#	  VALUE   an argument that is not a valid number
#	  TOOL    cutter dimensions out of range (D > 0, 0 <= r <= D/2)
#	  LEAD    lead angle not inside (-90, 90) degrees
#	  FRAME   n or tau not unit, or not orthogonal to each other
#	  AXIS    a CL point whose tool axis is not a unit vector
#	  EMPTY   clsf called with no points

namespace eval ::fivax::toolpath {
    namespace export surface partials normal torusCL raster sweep clsf goto
    namespace ensemble create -prefixes 0
    namespace upvar ::fivax::num pi Pi
}

# ::fivax::toolpath::surface --
#	Returns S(u,v) = (100u - 50, 100v - 50, -80 v (v - 1) p(u) - 28) with
#	p(u) = 3.55u - 14.8u^2 + 21.1u^3 - 9.9u^4 (kinematics.md section 11).
proc ::fivax::toolpath::surface {u v} {
    set u [Real u $u]
    set v [Real v $v]
    set p [expr {$u * (3.55 + $u * (-14.8 + $u * (21.1 - 9.9 * $u)))}]
    list [expr {100.0 * $u - 50.0}] [expr {100.0 * $v - 50.0}] \
        [expr {-80.0 * $v * ($v - 1.0) * $p - 28.0}]
}

# ::fivax::toolpath::partials --
#	Returns {Su Sv}, the analytic partial derivatives dS/du and dS/dv.
proc ::fivax::toolpath::partials {u v} {
    set u [Real u $u]
    set v [Real v $v]
    lassign [Slopes $u $v] zu zv
    list [list 100.0 0.0 $zu] [list 0.0 100.0 $zv]
}

# ::fivax::toolpath::normal --
#	Returns the unit normal unit(Su x Sv) of S at (u,v); its z is positive.
proc ::fivax::toolpath::normal {u v} {
    set u [Real u $u]
    set v [Real v $v]
    lassign [Slopes $u $v] zu zv
    # Su x Sv = (-100 zu, -100 zv, 10000); divide by 100 first.
    set len [expr {sqrt($zu * $zu + $zv * $zv + 10000.0)}]
    list [expr {-$zu / $len}] [expr {-$zv / $len}] [expr {100.0 / $len}]
}

# ::fivax::toolpath::Slopes -- Returns {dz/du dz/dv} of S at (u,v).
proc ::fivax::toolpath::Slopes {u v} {
    set p [expr {$u * (3.55 + $u * (-14.8 + $u * (21.1 - 9.9 * $u)))}]
    set dp [expr {3.55 + $u * (-29.6 + $u * (63.3 - 39.6 * $u))}]
    list [expr {-80.0 * $v * ($v - 1.0) * $dp}] [expr {-80.0 * (2.0 * $v - 1.0) * $p}]
}

# ::fivax::toolpath::torusCL --
#	Returns {P t}: tool tip P and unit axis t of a toroidal cutter (diameter
#	D, corner radius r, R0 = D/2 - r) touching contact point cc, where the
#	part has the unit normal n (pointing out of the material, towards the
#	tool), for unit feed direction tau (tangent) and lead beta and tilt theta
#	in radians. With b = tau x n:
#	  t   = sin(theta) sin(beta) b - cos(theta) sin(beta) tau + cos(beta) n
#	  C_c = CC + (r + R0/sin(beta)) n - R0 cot(beta) t   (torus centre)
#	  P   = C_c - r t
#	C_c is computed in the equivalent division-free form
#	CC + r n + R0 (sin(beta) n - cos(beta) m), m = sin(theta) b - cos(theta) tau.
#	The tube centre nearest CC is then CC + r n on the outer, lower quarter
#	of the tube. A negative lead equals lead -beta with tilt theta + pi (same
#	axis; the contact stays on the outer quarter). Lead 0 exactly gives
#	t = n and P = CC (the flat bottom sits on CC); note that the limit of
#	the formula as beta -> 0+ is instead the edge contact
#	P = CC - R0 m, a jump of R0.
#	Errors: TOOL, LEAD (|beta| >= pi/2), FRAME (n, tau not orthonormal).
proc ::fivax::toolpath::torusCL {cc n tau D r lead tilt} {
    variable Pi
    set cc [CheckVec cc $cc]
    set n [CheckVec n $n]
    set tau [CheckVec tau $tau]
    foreach name {D r lead tilt} {set $name [Real $name [set $name]]}
    CheckTool $D $r
    if {!(abs($lead) < $Pi / 2.0)} {
        ::fivax::Fail TOOLPATH LEAD "lead must lie inside (-pi/2, pi/2), got $lead"
    }
    set nn [::fivax::vec norm $n]
    set nt [::fivax::vec norm $tau]
    set nd [::fivax::vec dot $n $tau]
    if {abs($nn - 1.0) > 1e-6 || abs($nt - 1.0) > 1e-6 || abs($nd) > 1e-6} {
        ::fivax::Fail TOOLPATH FRAME \
            "n and tau must be orthogonal unit vectors (|n| $nn, |tau| $nt, n.tau $nd)"
    }
    if {$lead < 0} {
        set lead [expr {-$lead}]
        set tilt [expr {$tilt + $Pi}]
    }
    set sb [expr {sin($lead)}]
    set cb [expr {cos($lead)}]
    set b [::fivax::vec cross $tau $n]
    set m [::fivax::vec sub [::fivax::vec scale [expr {sin($tilt)}] $b] \
               [::fivax::vec scale [expr {cos($tilt)}] $tau]]
    set t [::fivax::vec add [::fivax::vec scale $sb $m] [::fivax::vec scale $cb $n]]
    set R0 [expr {$D / 2.0 - $r}]
    set c [::fivax::vec add $cc [::fivax::vec scale $r $n]]
    if {$lead != 0.0} {
        set c [::fivax::vec add $c [::fivax::vec scale $R0 \
            [::fivax::vec sub [::fivax::vec scale $sb $n] [::fivax::vec scale $cb $m]]]]
    }
    list [::fivax::vec sub $c [::fivax::vec scale $r $t]] $t
}

# ::fivax::toolpath::raster --
#	Returns the CL points {P t} of a zig-zag raster over S, u and v in
#	[0, 1], cut with torusCL. Options (degrees, mm):
#	  -D 16 -r 4      cutter diameter and corner radius
#	  -lead 10        lead angle beta; -tilt 0  tilt angle theta
#	  -passes 10      number of passes (1: a single pass at the middle)
#	  -step 100       contact points per pass (>= 2), both edges included
#	  -along u        feed along u (passes at constant v) or v
#	Pass k runs forwards when k is even and backwards when it is odd; tau
#	is the unit partial derivative along the pass, signed with the feed.
proc ::fivax::toolpath::raster {args} {
    variable Pi
    set o [::fivax::opts::parse {
        {-D real 16 MM "cutter diameter"} {-r real 4 MM "corner radius"}
        {-lead real 10 DEG "lead angle"} {-tilt real 0 DEG "tilt angle"}
        {-passes {int min 1} 10 N "passes"} {-step {int min 1} 100 N "points per pass"}
        {-along {enum u v} u DIR "feed direction"}
    } $args raster]
    dict with o {}
    CheckTool ${-D} ${-r}
    if {${-step} < 2} {
        ::fivax::Fail TOOLPATH VALUE "-step must be at least 2, got ${-step}"
    }
    set beta [::fivax::num::rad ${-lead}]
    set theta [::fivax::num::rad ${-tilt}]
    set out {}
    for {set k 0} {$k < ${-passes}} {incr k} {
        set w [expr {${-passes} == 1 ? 0.5 : double($k) / (${-passes} - 1)}]
        set dir [expr {$k % 2 ? -1.0 : 1.0}]
        for {set i 0} {$i < ${-step}} {incr i} {
            set s [expr {double($i) / (${-step} - 1)}]
            if {$dir < 0} {set s [expr {1.0 - $s}]}
            if {${-along} eq "u"} {
                set u $s
                set v $w
                set d [lindex [partials $u $v] 0]
            } else {
                set u $w
                set v $s
                set d [lindex [partials $u $v] 1]
            }
            set tau [::fivax::vec scale $dir [::fivax::vec unit $d]]
            lappend out [torusCL [surface $u $v] [normal $u $v] $tau \
                             ${-D} ${-r} $beta $theta]
        }
    }
    return $out
}

# ::fivax::toolpath::sweep --
#	Returns n synthetic CL points {P t} for kinematics tests. The axis is
#	t = (sin a cos f, sin a sin f, cos a): tilt a off +Z, azimuth f from +X
#	towards +Y. Options (degrees, mm):
#	  -shape circle   tip path: point (fixed at the centre), line or circle
#	  -n 360          number of points (>= 2), both ends included
#	  -R 50           circle radius; half the length of the line
#	  -center {0 0}   x y of the circle centre, line midpoint or the point
#	  -z 0            height of the tip path
#	  -phase 0        circle: position angle of the first point
#	  -turns 1        circle: turns of the position angle (< 0: clockwise)
#	  -pitch 0        circle: z rise per turn (a helix when not 0)
#	  -heading 0      line: direction in XY; runs from centre - R to + R
#	  -tilt 30        tilt a of the axis off +Z
#	  -from 0 -to 360 azimuth f, linear from -from to -to (may wind > 360)
#	  -through-singular 0
#	                  1: azimuth fixed at -from, tilt linear from +tilt
#	                  through 0 to -tilt, so the axis crosses the +Z pole;
#	                  point (n-1)/2 (rounded down) is exactly (0,0,1), and
#	                  for even n the second half has one step more.
#	Tip and axis move with the same fraction i/(n-1) of the path.
proc ::fivax::toolpath::sweep {args} {
    set o [::fivax::opts::parse {
        {-shape {enum point line circle} circle SHAPE "tip path"} {-n {int min 1} 360 N "points"}
        {-R real 50 MM "radius"} {-center {reals 2} {0 0} "X Y" "centre"} {-z real 0 MM "height"}
        {-phase real 0 DEG "first position angle"} {-turns real 1 N "turns"}
        {-pitch real 0 MM "rise per turn"} {-heading real 0 DEG "line direction"}
        {-tilt real 30 DEG "axis tilt"} {-from real 0 DEG "first azimuth"}
        {-to real 360 DEG "last azimuth"} {-through-singular bool 0 "" "cross the pole"}
    } $args sweep]
    dict with o {}
    if {${-n} < 2} {
        ::fivax::Fail TOOLPATH VALUE "-n must be at least 2, got ${-n}"
    }
    lassign ${-center} cx cy
    set last [expr {${-n} - 1}]
    set pole [expr {$last / 2}]
    set out {}
    for {set i 0} {$i < ${-n}} {incr i} {
        set s [expr {double($i) / $last}]
        switch -exact -- ${-shape} {
            point {set p [list $cx $cy ${-z}]}
            line {
                set h [::fivax::num::rad ${-heading}]
                set l [expr {${-R} * (2.0 * $s - 1.0)}]
                set p [list [expr {$cx + $l * cos($h)}] [expr {$cy + $l * sin($h)}] ${-z}]
            }
            circle {
                set a [::fivax::num::rad [expr {${-phase} + 360.0 * ${-turns} * $s}]]
                set p [list [expr {$cx + ${-R} * cos($a)}] [expr {$cy + ${-R} * sin($a)}] \
                           [expr {${-z} + ${-pitch} * ${-turns} * $s}]]
            }
        }
        if {${-through-singular}} {
            set f [::fivax::num::rad ${-from}]
            if {$i == $pole} {
                set a 0.0
            } elseif {$i < $pole} {
                set a [::fivax::num::rad [expr {${-tilt} * double($pole - $i) / $pole}]]
            } else {
                set a [::fivax::num::rad [expr {-${-tilt} * double($i - $pole) / ($last - $pole)}]]
            }
        } else {
            set f [::fivax::num::rad [expr {${-from} + (${-to} - ${-from}) * $s}]]
            set a [::fivax::num::rad ${-tilt}]
        }
        set t [list [expr {sin($a) * cos($f)}] [expr {sin($a) * sin($f)}] [expr {cos($a)}]]
        lappend out [list $p $t]
    }
    return $out
}

# ::fivax::toolpath::clsf --
#	Returns the lines (no newlines) of an NX-style CLSF operation that cuts
#	through the CL points {P t}. Options (mm, mm/min):
#	  -op VARIABLE_CONTOUR -tool <D..R..> -number 1
#	  -D 16 -r 4 -length 75        TLDATA/MILL values
#	  -rpm 8000 -feed 1000         SPINDL/RPM (clockwise), FEDRAT/MMPM
#	  -clearance 50                approach and retract distance along t
#	Record order: TOOL PATH, TLDATA, MSYS (identity), $$ centerline data,
#	LOAD/TOOL, SPINDL, COOLNT/ON, RAPID + GOTO approach, FEDRAT, one GOTO per
#	point, retract GOTO, COOLNT/OFF, END-OF-PATH. Lengths have 4 decimals,
#	axis components 7; i,j,k are written only when their text changes (the
#	first GOTO always has them). "-0.0000" is never written.
#	Errors: EMPTY, AXIS, VALUE, OPTION.
proc ::fivax::toolpath::clsf {points args} {
    set o [::fivax::opts::parse {
        {-op word VARIABLE_CONTOUR NAME "operation name"} {-tool {maybe word} {} NAME "tool name"}
        {-number {int min 1} 1 N "tool number"} {-D real 16 MM "diameter"}
        {-r real 4 MM "corner radius"} {-length real 75 MM "tool length"}
        {-rpm real 8000 RPM "spindle speed"} {-feed real 1000 MMPM "feed"}
        {-clearance real 50 MM "approach distance"}
    } $args clsf]
    dict with o {}
    CheckTool ${-D} ${-r}
    if {![llength $points]} {
        ::fivax::Fail TOOLPATH EMPTY "no CL points to write"
    }
    set points [lmap pt $points {
        if {[llength $pt] != 2} {
            ::fivax::Fail TOOLPATH VALUE "CL point must be {P t}, got \"$pt\""
        }
        lassign $pt p0 t0
        set p [CheckVec point $p0]
        set t [CheckVec axis $t0]
        if {abs([::fivax::vec norm $t] - 1.0) > 1e-6} {
            ::fivax::Fail TOOLPATH AXIS "tool axis is not a unit vector: $t0"
        }
        list $p $t
    }]
    if {${-tool} eq ""} {
        set -tool [format MILL_D%s_R%s [Short ${-D}] [Short ${-r}]]
    }
    set lines {}
    lappend lines "TOOL PATH/${-op},TOOL,${-tool}" \
        "TLDATA/MILL,[::fivax::num::fixed ${-D} 4],[::fivax::num::fixed ${-r} 4],[::fivax::num::fixed ${-length} 4],0.0000,0.0000" \
        "MSYS/0.0000,0.0000,0.0000,1.0000000,0.0000000,0.0000000,0.0000000,1.0000000,0.0000000" \
        "\$\$ centerline data" \
        "LOAD/TOOL,${-number}" \
        "SPINDL/RPM,[Short ${-rpm}],CLW" \
        "COOLNT/ON" \
        "RAPID"
    set lastAxis ""
    lassign [lindex $points 0] p t
    lappend lines [goto [::fivax::vec add $p [::fivax::vec scale ${-clearance} $t]] $t lastAxis]
    lappend lines "FEDRAT/MMPM,[::fivax::num::fixed ${-feed} 4]"
    foreach pt $points {
        lassign $pt p t
        lappend lines [goto $p $t lastAxis]
    }
    lappend lines [goto [::fivax::vec add $p [::fivax::vec scale ${-clearance} $t]] $t lastAxis] \
        "COOLNT/OFF" "END-OF-PATH"
    return $lines
}

# ::fivax::toolpath::goto --
#	Returns the GOTO line for tip p and axis t; appends i,j,k only when their
#	text differs from the variable named lastVar (updated).
proc ::fivax::toolpath::goto {p t lastVar} {
    upvar 1 $lastVar last
    lassign $p x y z
    lassign $t i j k
    set line "GOTO/[::fivax::num::fixed $x 4],[::fivax::num::fixed $y 4],[::fivax::num::fixed $z 4]"
    set axis "[::fivax::num::fixed $i 7],[::fivax::num::fixed $j 7],[::fivax::num::fixed $k 7]"
    if {$axis ne $last} {
        append line , $axis
        set last $axis
    }
    return $line
}

# ::fivax::toolpath::Short --
#	Returns x as an integer when it is whole, else with 4 decimals.
proc ::fivax::toolpath::Short {x} {
    if {$x == round($x) && abs($x) < 1e15} {
        return [format %lld [expr {round($x)}]]
    }
    ::fivax::num::fixed $x 4
}

# ::fivax::toolpath::Real --
#	Returns x as a double (decimal, so 017 is 17.0); raises VALUE unless x
#	is a finite number.
proc ::fivax::toolpath::Real {name x} {
    set v [::fivax::num::parse $x]
    if {$v eq ""} {
        ::fivax::Fail TOOLPATH VALUE "bad $name \"$x\": must be a finite number"
    }
    return $v
}

# ::fivax::toolpath::CheckVec --
#	Returns v as 3 doubles (decimal: 017 is 17.0); raises VALUE unless it
#	is 3 finite numbers.
proc ::fivax::toolpath::CheckVec {name v} {
    set out {}
    if {[string is list $v] && [llength $v] == 3} {
        set out [lmap c $v {::fivax::num::parse $c}]
    }
    if {[llength $out] != 3 || "" in $out} {
        ::fivax::Fail TOOLPATH VALUE "bad $name \"$v\": must be 3 finite numbers"
    }
    return $out
}

# ::fivax::toolpath::CheckTool -- Raises TOOL unless D > 0 and 0 <= r <= D/2.
proc ::fivax::toolpath::CheckTool {D r} {
    if {!($D > 0) || !($r >= 0) || $r > $D / 2.0} {
        ::fivax::Fail TOOLPATH TOOL "bad cutter D $D r $r: need D > 0 and 0 <= r <= D/2"
    }
}

