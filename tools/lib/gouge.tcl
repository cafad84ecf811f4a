# gouge.tcl --
#	Contact and gouge check of a toroidal end mill against a surface,
#	independent of the path generator: it knows only the surface S(u,v)
#	(toolpath define/at), the cutter (D, r) and each CL point (tool tip
#	P, unit axis t), nothing of contact points, lead or tilt. For each
#	CL point it finds the smallest signed distance from the surface to
#	the cutter solid (flat bottom disc of radius R0 = D/2 - r, torus of
#	tube radius r, cylinder of radius D/2 above): negative = the surface
#	enters the cutter (gouge), 0 = touching, positive = a gap. The search:
#	the surface point nearest P (a 21 x 21 grid, then a pattern search;
#	or the caller's hint, the previous point's contact), a 7 x 7 grid of surface points around it spanning the cutter, and a
#	pattern search from the best two (u, v stay in [0, 1]).

namespace eval ::fivax::gouge {
    namespace export sdf margin
    namespace ensemble create -prefixes 0
    # Height of the cutter solid above the tip (mm).
    variable height 40.0
}

# ::fivax::gouge::sdf --
#	Returns the signed distance (mm) from point x to the cutter solid of
#	diameter D and corner radius r with tip P and unit axis t (negative
#	inside). In the cutter's half plane (rho radial, h along t): the union
#	of the box |rho| <= R0, 0 <= h <= H, the disc of radius r about
#	(R0, r) and the box |rho| <= D/2, r <= h <= H; inside the union the
#	value is the depth below the nearest part's boundary.
proc ::fivax::gouge::sdf {x P t D r} {
    variable height
    lassign $x x1 x2 x3
    lassign $P p1 p2 p3
    lassign $t t1 t2 t3
    set d1 [expr {$x1 - $p1}]
    set d2 [expr {$x2 - $p2}]
    set d3 [expr {$x3 - $p3}]
    set h [expr {$d1 * $t1 + $d2 * $t2 + $d3 * $t3}]
    set rho [expr {sqrt(max(0.0, $d1 * $d1 + $d2 * $d2 + $d3 * $d3 - $h * $h))}]
    set R0 [expr {$D / 2.0 - $r}]
    # box |rho| <= R0, 0 <= h <= height
    set qx [expr {$rho - $R0}]
    set qy [expr {abs($h - $height / 2.0) - $height / 2.0}]
    set f [expr {hypot(max($qx, 0.0), max($qy, 0.0)) + min(max($qx, $qy), 0.0)}]
    if {$r > 0} {
        # tube of the torus
        set g [expr {hypot($rho - $R0, $h - $r) - $r}]
        # box |rho| <= D/2, r <= h <= height
        set qx [expr {$rho - $D / 2.0}]
        set qy [expr {abs($h - ($height + $r) / 2.0) - ($height - $r) / 2.0}]
        set k [expr {hypot(max($qx, 0.0), max($qy, 0.0)) + min(max($qx, $qy), 0.0)}]
        set f [expr {min($f, $g, $k)}]
    }
    return $f
}

# ::fivax::gouge::margin --
#	Returns {min u v}: the smallest signed distance (mm) from surface surf
#	to the cutter (D, r) at CL point {P t}, and where on the surface;
#	hint {u v} (the previous point's) saves the global search.
proc ::fivax::gouge::margin {surf cl D r {hint {}}} {
    lassign $cl P t
    # the centre of the search: hint {u v} when its surface point lies
    # within D of the tip, else the surface point nearest the tip
    if {$hint ne "" && [Dist2 $surf {*}$hint $P] < $D * $D} {
        set uv $hint
    } else {
        set best Inf
        foreach u [Steps 0.0 1.0 20] {
            foreach v [Steps 0.0 1.0 20] {
                set d [Dist2 $surf $u $v $P]
                if {$d < $best} {set best $d; set uv [list $u $v]}
            }
        }
        set uv [Search [list ::fivax::gouge::Dist2 $surf] [list $P] $uv 0.05]
    }
    lassign $uv u0 v0
    # a grid spanning the cutter around it
    lassign [::fivax::toolpath::at $surf $u0 $v0] - Su Sv
    set du [expr {min(0.5, 1.2 * $D / max(1e-9, [::fivax::vec::norm $Su]))}]
    set dv [expr {min(0.5, 1.2 * $D / max(1e-9, [::fivax::vec::norm $Sv]))}]
    set cands {}
    foreach u [Steps [expr {$u0 - $du}] [expr {$u0 + $du}] 6] {
        foreach v [Steps [expr {$v0 - $dv}] [expr {$v0 + $dv}] 6] {
            set u [Clamp $u]
            set v [Clamp $v]
            lappend cands [list [Sdf $surf $u $v $P $t $D $r] $u $v]
        }
    }
    set result {Inf 0 0}
    foreach c [lrange [lsort -real -index 0 $cands] 0 1] {
        lassign $c - u v
        lassign [Search [list ::fivax::gouge::Sdf $surf] [list $P $t $D $r] [list $u $v] \
            [expr {max($du, $dv) / 6.0}]] u v
        set f [Sdf $surf $u $v $P $t $D $r]
        if {$f < [lindex $result 0]} {set result [list $f $u $v]}
    }
    return $result
}

# ::fivax::gouge::Steps -- Returns n + 1 values from a to b.
proc ::fivax::gouge::Steps {a b n} {
    set out {}
    for {set i 0} {$i <= $n} {incr i} {lappend out [expr {$a + ($b - $a) * $i / double($n)}]}
    return $out
}

# ::fivax::gouge::Clamp -- Returns x clamped into [0, 1].
proc ::fivax::gouge::Clamp {x} {
    expr {$x < 0.0 ? 0.0 : $x > 1.0 ? 1.0 : $x}
}

# ::fivax::gouge::Dist2 -- Returns the squared distance from S(u, v) of surf to P.
proc ::fivax::gouge::Dist2 {surf u v P} {
    lassign [::fivax::toolpath::point $surf $u $v] x y z
    lassign $P a b c
    expr {($x - $a) ** 2 + ($y - $b) ** 2 + ($z - $c) ** 2}
}

# ::fivax::gouge::Sdf -- Returns the cutter's signed distance at S(u, v) of surf.
proc ::fivax::gouge::Sdf {surf u v P t D r} {
    sdf [::fivax::toolpath::point $surf $u $v] $P $t $D $r
}

# ::fivax::gouge::Search --
#	Returns {u v} in [0, 1]^2 minimising {*}cmd u v {*}extra by a pattern
#	search from uv with first step h, down to steps of 1e-7 (1e-5 mm on
#	a 100 mm patch: the minimum's value is then exact to ~1e-10 mm).
proc ::fivax::gouge::Search {cmd extra uv h} {
    lassign $uv u v
    set f [{*}$cmd $u $v {*}$extra]
    while {$h > 1e-7} {
        set moved 0
        foreach {a b} {1 0 -1 0 0 1 0 -1} {
            set uu [Clamp [expr {$u + $a * $h}]]
            set vv [Clamp [expr {$v + $b * $h}]]
            set g [{*}$cmd $uu $vv {*}$extra]
            if {$g < $f} {
                set f $g
                set u $uu
                set v $vv
                set moved 1
                break
            }
        }
        if {!$moved} {set h [expr {$h / 2.0}]}
    }
    list $u $v
}
