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
#	  DEGENERATE  a surface point whose normal vanishes (names u, v)
#	  SURFACE     an unknown built-in surface name
#
#	Surfaces (define, at, frame, passes): a surface is a dict made by
#	define from a built-in name (paper, plane, cylinder, sphere) or a
#	user file of three expressions (tools/lib/surfexpr.tcl, sourced
#	when needed); u and v run over [0, 1].

namespace eval ::fivax::toolpath {
    namespace export surface partials normal torusCL raster sweep clsf goto
    namespace export surfaces define at point frame passes
    namespace ensemble create -prefixes 0
    namespace upvar ::fivax::num pi Pi
    # this file's directory (surfexpr.tcl is sourced from it when needed)
    variable Home [file dirname [file normalize [info script]]]
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
#	through the CL points {P t} (or {P t C n}: contact data). Options
#	(mm, mm/min):
#	  -op VARIABLE_CONTOUR -tool <D..R..> -number 1
#	  -D 16 -r 4 -length 75        TLDATA/MILL values
#	  -rpm 8000 -feed 1000         SPINDL/RPM (clockwise), FEDRAT/MMPM
#	  -clearance 50                approach and retract distance along t
#	  -breaks {}                   indices of points that start a new pass:
#	                               before each, a retract GOTO along the
#	                               axis, RAPID, approach GOTO and FEDRAT
#	  -contact 0                   1: a CONTACT/x,y,z,i,j,k record (contact
#	                               point, surface normal) before each
#	                               point's GOTO (points {P t C n})
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
        {-breaks any {} "I ..." "indices of the points that start a new pass (lift between passes)"}
        {-contact bool 0 "" "write each point's contact point and surface normal (CONTACT record before its GOTO; points {P t C n})"}
    } $args clsf]
    dict with o {}
    CheckTool ${-D} ${-r}
    if {![llength $points]} {
        ::fivax::Fail TOOLPATH EMPTY "no CL points to write"
    }
    set want [expr {${-contact} ? 4 : 2}]
    set points [lmap pt $points {
        if {[llength $pt] != $want && [llength $pt] != 4} {
            ::fivax::Fail TOOLPATH VALUE "CL point must be\
                [expr {${-contact} ? "{P t C n}" : "{P t} or {P t C n}"}], got \"$pt\""
        }
        lassign $pt p0 t0 c0 n0
        set p [CheckVec point $p0]
        set t [CheckUnit "tool axis" $t0]
        if {${-contact}} {
            list $p $t [CheckVec "contact point" $c0] [CheckUnit "surface normal" $n0]
        } else {
            list $p $t
        }
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
    set i 0
    foreach pt $points {
        lassign $pt p t
        if {$i > 0 && $i in ${-breaks}} {
            lappend lines [goto [::fivax::vec add $pp [::fivax::vec scale ${-clearance} $pt0]] \
                               $pt0 lastAxis] RAPID \
                [goto [::fivax::vec add $p [::fivax::vec scale ${-clearance} $t]] $t lastAxis] \
                "FEDRAT/MMPM,[::fivax::num::fixed ${-feed} 4]"
        }
        if {${-contact}} {lappend lines [Contact {*}[lrange $pt 2 3]]}
        lappend lines [goto $p $t lastAxis]
        set pp $p
        set pt0 $t
        incr i
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

# ::fivax::toolpath::Contact --
#	Returns the CONTACT line of contact point c and unit surface normal n
#	(the contact data of the GOTO after it: lib/clsf.tcl ParseContact).
proc ::fivax::toolpath::Contact {c n} {
    set nums [concat [lmap x $c {::fivax::num::fixed $x 4}] [lmap x $n {::fivax::num::fixed $x 7}]]
    return "CONTACT/[join $nums ,]"
}

# ::fivax::toolpath::CheckUnit --
#	Returns v as 3 doubles (CheckVec); raises AXIS unless its length is 1
#	within 1e-6 (name names it).
proc ::fivax::toolpath::CheckUnit {name v} {
    set u [CheckVec $name $v]
    if {abs([::fivax::vec norm $u] - 1.0) > 1e-6} {
        ::fivax::Fail TOOLPATH AXIS "$name is not a unit vector: $v"
    }
    return $u
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


# ::fivax::toolpath::surfaces -- Returns the names of the built-in surfaces.
proc ::fivax::toolpath::surfaces {} {
    return {paper plane cylinder sphere}
}

# ::fivax::toolpath::define --
#	Returns the surface dict of spec: a built-in name (see surfaces) or
#	the path of a user surface file. Built-ins over u, v in [0, 1], mm:
#	  paper     the spec's S(u,v) (kinematics.md section 11)
#	  plane     (100u - 50, 100v - 50, -28)
#	  cylinder  x = 100u - 50, y = 100v - 50 on the cylinder of radius 60
#	            about the X axis, top at z = 0: z = sqrt(3600 - y^2) - 60
#	  sphere    x, y as above on the sphere of radius 100 about
#	            (0, 0, -100): z = sqrt(10000 - x^2 - y^2) - 100
#	Errors: {FIVAX TOOLPATH SURFACE}, and {FIVAX SURFACE ...} of a file.
proc ::fivax::toolpath::define {spec} {
    if {$spec in [surfaces]} {return [dict create kind $spec name $spec]}
    if {![file exists $spec]} {
        ::fivax::Fail TOOLPATH SURFACE "unknown surface '$spec': must be one of\
            [join [surfaces] {, }] or a surface file"
    }
    if {[namespace which ::fivax::surfexpr::load] eq ""} {
        source [file join $::fivax::toolpath::Home surfexpr.tcl]
    }
    dict merge [::fivax::surfexpr::load $spec] [dict create kind file name [file tail $spec]]
}

# ::fivax::toolpath::at --
#	Returns {S Su Sv}: the point and partial derivatives of surface surf
#	at (u, v): analytic for the built-ins, central differences (step
#	1e-6) for a user file.
proc ::fivax::toolpath::at {surf u v} {
    switch -exact -- [dict get $surf kind] {
        paper {
            return [list [surface $u $v] {*}[partials $u $v]]
        }
        plane {
            return [list [list [expr {100.0 * $u - 50.0}] [expr {100.0 * $v - 50.0}] -28.0] \
                {100.0 0.0 0.0} {0.0 100.0 0.0}]
        }
        cylinder {
            set y [expr {100.0 * $v - 50.0}]
            set w [expr {sqrt(3600.0 - $y * $y)}]
            return [list [list [expr {100.0 * $u - 50.0}] $y [expr {$w - 60.0}]] \
                {100.0 0.0 0.0} [list 0.0 100.0 [expr {-100.0 * $y / $w}]]]
        }
        sphere {
            set x [expr {100.0 * $u - 50.0}]
            set y [expr {100.0 * $v - 50.0}]
            set w [expr {sqrt(10000.0 - $x * $x - $y * $y)}]
            return [list [list $x $y [expr {$w - 100.0}]] \
                [list 100.0 0.0 [expr {-100.0 * $x / $w}]] [list 0.0 100.0 [expr {-100.0 * $y / $w}]]]
        }
        file {
            set h 1e-6
            set S [FilePoint $surf $u $v]
            set Su [::fivax::vec scale [expr {0.5 / $h}] [::fivax::vec sub \
                [FilePoint $surf [expr {$u + $h}] $v] [FilePoint $surf [expr {$u - $h}] $v]]]
            set Sv [::fivax::vec scale [expr {0.5 / $h}] [::fivax::vec sub \
                [FilePoint $surf $u [expr {$v + $h}]] [FilePoint $surf $u [expr {$v - $h}]]]]
            return [list $S $Su $Sv]
        }
    }
}

# ::fivax::toolpath::point --
#	Returns the point S(u, v) of surface surf (at without the partials:
#	the gouge check's inner loop).
proc ::fivax::toolpath::point {surf u v} {
    switch -exact -- [dict get $surf kind] {
        paper {
            set p [expr {$u * (3.55 + $u * (-14.8 + $u * (21.1 - 9.9 * $u)))}]
            return [list [expr {100.0 * $u - 50.0}] [expr {100.0 * $v - 50.0}] \
                [expr {-80.0 * $v * ($v - 1.0) * $p - 28.0}]]
        }
        file {return [FilePoint $surf $u $v]}
        default {return [lindex [at $surf $u $v] 0]}
    }
}

# ::fivax::toolpath::FilePoint -- Returns the point of the user surface surf at (u, v).
proc ::fivax::toolpath::FilePoint {surf u v} {
    lmap c {x y z} {
        ::fivax::surfexpr::value [dict get $surf $c] $u $v \
            "[dict get $surf file]:[dict get $surf lines $c]: "
    }
}

# ::fivax::toolpath::frame --
#	Returns {S n Su Sv} at (u, v): the surface point, the unit normal
#	unit(Su x Sv) and the partial derivatives. Errors: DEGENERATE where
#	Su x Sv vanishes.
proc ::fivax::toolpath::frame {surf u v} {
    lassign [at $surf $u $v] S Su Sv
    set c [::fivax::vec cross $Su $Sv]
    set len [::fivax::vec norm $c]
    if {!($len > 1e-9 * [::fivax::vec norm $Su] * [::fivax::vec norm $Sv])} {
        ::fivax::Fail TOOLPATH DEGENERATE [format "surface %s: the normal vanishes at u = %.6g,\
            v = %.6g (Su x Sv = 0): the surface is degenerate there" [dict get $surf name] $u $v]
    }
    list $S [::fivax::vec scale [expr {1.0 / $len}] $c] $Su $Sv
}

# ::fivax::toolpath::passes --
#	Returns the passes of a parallel (zig-zag) tool path on surface surf
#	for a toroidal cutter: a list of passes, each a list of CL points
#	{P t C n} (tool tip, unit axis, cut with torusCL, and the contact
#	point and unit surface normal there). Options (mm, degrees):
#	  -D 6 -r 2            cutter diameter and corner radius
#	  -lead 25 -tilt 5     lead and tilt angles
#	  -stepover 1          distance between passes (arc length across)
#	  -step 1              distance between CL points along a pass
#	  -along u             feed along u (passes at constant v) or v
#	Passes run forwards and backwards in turn; the first and the last
#	lie on the edges of the parameter square. Errors: DEGENERATE,
#	those of torusCL, {FIVAX OPTION ...}.
proc ::fivax::toolpath::passes {surf args} {
    set o [::fivax::opts::parse {
        {-D {real gt 0} 6 MM "cutter diameter"} {-r {real min 0} 2 MM "corner radius"}
        {-lead real 25 DEG "lead angle"} {-tilt real 5 DEG "tilt angle"}
        {-stepover {real gt 0} 1 MM "distance between passes"}
        {-step {real gt 0} 1 MM "distance between points"}
        {-along {enum u v} u DIR "feed direction"}
    } $args passes]
    dict with o {}
    CheckTool ${-D} ${-r}
    set beta [::fivax::num::rad ${-lead}]
    set theta [::fivax::num::rad ${-tilt}]
    set feedU [expr {${-along} eq "u"}]
    # pass positions: equal arc length across, along the middle iso-curve
    set across [Stations $surf [expr {!$feedU}] 0.5 ${-stepover}]
    set out {}
    set k 0
    foreach w $across {
        set ss [Stations $surf $feedU $w ${-step}]
        if {$k % 2} {set ss [lreverse $ss]}
        set dir [expr {$k % 2 ? -1.0 : 1.0}]
        set pass {}
        foreach s $ss {
            lassign [expr {$feedU ? [list $s $w] : [list $w $s]}] u v
            lassign [frame $surf $u $v] S n Su Sv
            set d [expr {$feedU ? $Su : $Sv}]
            # the feed tangent, made exactly orthogonal to n
            set d [::fivax::vec sub $d [::fivax::vec scale [::fivax::vec dot $d $n] $n]]
            set tau [::fivax::vec scale $dir [::fivax::vec unit $d]]
            lappend pass [list {*}[torusCL $S $n $tau ${-D} ${-r} $beta $theta] $S $n]
        }
        lappend out $pass
        incr k
    }
    return $out
}

# ::fivax::toolpath::Stations --
#	Returns the parameter values (0 to 1, both included) of points spaced
#	equally by at most step (mm of arc length) along the iso-curve of surf where
#	the other parameter is w: along u when alongU, else along v. The
#	arc length is summed over 400 chords.
proc ::fivax::toolpath::Stations {surf alongU w step} {
    set n 400
    set len {0.0}
    set acc 0.0
    set prev {}
    for {set i 0} {$i <= $n} {incr i} {
        set s [expr {double($i) / $n}]
        set p [lindex [at $surf {*}[expr {$alongU ? [list $s $w] : [list $w $s]}]] 0]
        if {$prev ne ""} {
            set acc [expr {$acc + [::fivax::vec norm [::fivax::vec sub $p $prev]]}]
            lappend len $acc
        }
        set prev $p
    }
    set count [expr {max(1, int(ceil($acc / $step - 1e-9)))}]
    set out {}
    set j 0
    for {set k 0} {$k <= $count} {incr k} {
        set target [expr {$acc * $k / $count}]
        while {$j < $n - 1 && [lindex $len $j+1] < $target} {incr j}
        set a [lindex $len $j]
        set b [lindex $len $j+1]
        set f [expr {$b > $a ? ($target - $a) / ($b - $a) : 0.0}]
        lappend out [expr {min(1.0, ($j + $f) / $n)}]
    }
    return $out
}
