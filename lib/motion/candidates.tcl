# candidates.tcl --
#	(motion) Candidate rotary values of a CL point, as pure functions of a
#	planning context, the tool axis and reference values.
#
#	Every CL point has up to two inverse solutions (branches); each rotary
#	value stands for its 360-degree aliases within the axis limits
#	(continuous axes: the alias nearest each previous value). Within the
#	singular cone (tool axis within -cone of the direction where the
#	azimuth axis is free) the azimuth is held at its previous values and
#	the tilt chosen to bring the tool axis closest to the CL axis.
#
#	A context (see Context) is a dict: model (kin model), name (machine),
#	axes (the two axis dicts in chain order: tilt, azimuth, with name min
#	max continuous unlimited rollover prefer swing), limits ({min max
#	continuous unlimited} per axis), swing ({ms1 ms2}: max_swing per
#	axis), u2 (the azimuth axis direction), sinCone and its square cone2,
#	step (rotary output resolution, rad). Candidates are flat triples {q1 q2 branch ...};
#	branch is 0 or 1 for the two inverse solutions, -1 where they meet.

# ::fivax::motion::Context --
#	Returns the planning context for kin model, machine name, the
#	planner's per-axis dicts axes, the singular cone and the rotary output
#	resolution (both degrees).
proc ::fivax::motion::Context {model name axes cone step} {
    set sinCone [expr {sin([::fivax::num::rad $cone])}]
    dict create model $model name $name axes $axes \
        limits [lmap a $axes {
            list [dict get $a min] [dict get $a max] [dict get $a continuous] [dict get $a unlimited]
        }] \
        swing [lmap a $axes {dict get $a swing}] u2 [dict get $model u2] \
        sinCone $sinCone cone2 [expr {$sinCone ** 2}] step [::fivax::num::rad $step]
}

# ::fivax::motion::Candidates --
#	Returns the flat candidate triples for unit axis t (cone: InCone of t,
#	which the callers also need). refs are the flat
#	triples of the previous candidates ({} at a first point): continuous
#	axes take the aliases nearest them, and in the singular cone the
#	azimuth is held at theirs (exact solutions there only when no held
#	tilt is within the limits).
#	Errors: {FIVAX MOTION UNREACHABLE}; {FIVAX MOTION LIMIT} when every
#	solution lies outside the limits.
proc ::fivax::motion::Candidates {ctx t cone refs src} {
    lassign [::fivax::kin::orientations [dict get $ctx model] $t] status sols
    if {$status eq "unreachable"} {
        ::fivax::Fail MOTION UNREACHABLE \
            "$src: tool axis ([AxisText $t]) unreachable on [dict get $ctx name]"
    }
    set cone [expr {$status eq "singular" || $cone}]
    if {!$cone || ![llength $refs] || ![llength [set out [Held $ctx $t $refs]]]} {
        # the exact solutions (at most two), each axis value expanded to
        # its in-limit aliases near refs (the azimuth's only where the
        # tilt has some); branch -1 for all where the branches merge,
        # else the solution's index
        lassign [dict get $ctx limits] lim1 lim2
        set out {}
        foreach xs [Aliases $lim1 0 $sols $refs] sol $sols \
                lab [expr {$cone || [llength $sols] < 2 ? {-1 -1} : {0 1}}] {
            if {![llength $xs]} continue
            set ys [lindex [Aliases $lim2 1 [list $sol] $refs] 0]
            foreach x $xs {
                foreach y $ys {lappend out $x $y $lab}
            }
        }
    }
    if {![llength $out]} {
        ::fivax::Fail MOTION LIMIT "$src: tool axis ([AxisText $t]) needs a rotary value\
            outside the limits of [dict get $ctx name]"
    }
    return $out
}

# ::fivax::motion::Held --
#	Returns the candidates in the singular cone: for each previous
#	candidate {p1 p2} the azimuth held at p2, with the tilt (alias nearest
#	p1) that brings the tool axis closest to unit t; the axis is then off
#	by at most the cone angle. All get branch -1.
proc ::fivax::motion::Held {ctx t refs} {
    set out {}
    foreach {p1 p2 -} $refs {
        set q1 [HoldTilt $ctx $t $p1 $p2]
        if {$q1 ne "" && [lsearch -exact $out [list $q1 $p2]] < 0} {lappend out [list $q1 $p2]}
    }
    set flat {}
    foreach c $out {lappend flat {*}$c -1}
    return $flat
}

# ::fivax::motion::HoldTilt --
#	Returns the tilt (alias nearest r1 within the limits, "" if none) that
#	brings the tool axis closest to unit t when the azimuth is q2.
proc ::fivax::motion::HoldTilt {ctx t r1 q2} {
    set best ""
    set bd Inf
    set q1 [BestTilt [dict get $ctx model] $t $q2]
    foreach x [lindex [Aliases [lindex [dict get $ctx limits] 0] 0 [list [list $q1]] [list $r1 $q2 -1]] 0] {
        if {abs($x - $r1) < $bd} {
            set bd [expr {abs($x - $r1)}]
            set best $x
        }
    }
    return $best
}

# ::fivax::motion::BestTilt --
#	Returns the tilt q1 (radians, (-pi, pi] plus the zero offset z1) that
#	brings the tool axis closest to unit t when the azimuth is q2 on kin
#	model: with w = R(u2, -s2 (q2 - z2)) t, the angle th maximising
#	(R(u1, th) Z).w is atan2((u1 x Z).w, (Z - k1 u1).w); q1 = s1 th + z1.
proc ::fivax::motion::BestTilt {model t q2} {
    set w [::fivax::vec::rotate [dict get $model u2] \
        [expr {-[dict get $model s2] * ($q2 - [dict get $model z2])}] $t]
    lassign $w wx wy wz
    lassign [dict get $model u1] x1 y1 z1
    set zw [expr {$wz - $z1 * ($x1 * $wx + $y1 * $wy + $z1 * $wz)}]
    set mw [expr {$y1 * $wx - $x1 * $wy}]
    expr {[dict get $model s1] * atan2($mw, $zw) + [dict get $model z1]}
}

# ::fivax::motion::Aliases --
#	Returns, for the value q of axis i (0 tilt, 1 azimuth; lim its {min
#	max continuous unlimited} from the context's limits) in each {q1 q2}
#	of sols, the values equivalent to q (mod 360 deg) that the axis may
#	take: all within the limits for a limited axis; for a continuous one
#	the alias nearest each ref value (element i of the flat triples refs;
#	with no refs q and its alias of the other sign), with its neighbours
#	when the axis has finite limits.
proc ::fivax::motion::Aliases {lim i sols refs} {
    lassign $lim min max continuous unlimited
    # (6.283185307179586 is 2 pi)
    if {!$continuous} {
        return [lmap sol $sols {
            set q [lindex $sol $i]
            if {$q >= $min && $q <= $max && $q - 6.283185307179586 < $min
                    && $q + 6.283185307179586 > $max} {
                list $q
            } else {
                set vals {}
                set k [expr {ceil(($min - $q) / 6.283185307179586 - 1e-9)}]
                for {set v [expr {$q + 6.283185307179586 * $k}]} {$v <= $max + 1e-9} \
                        {set v [expr {$v + 6.283185307179586}]} {
                    lappend vals [expr {$v < $min ? $min : $v > $max ? $max : $v}]
                }
                set vals
            }
        }]
    }
    lmap sol $sols {
        set q [lindex $sol $i]
        if {![llength $refs]} {
            set try [list $q [expr {$q > 0 ? $q - 6.283185307179586 : $q + 6.283185307179586}]]
        } else {
            set try {}
            foreach {r1 r2 -} $refs {
                set r [expr {$i == 0 ? $r1 : $r2}]
                set v [Near $q $r]
                lappend try $v
                if {!$unlimited} {
                    lappend try [expr {$v - 6.283185307179586}] [expr {$v + 6.283185307179586}]
                }
            }
        }
        set vals {}
        foreach v $try {
            if {$v >= $min - 1e-9 && $v <= $max + 1e-9 && $v ni $vals} {
                lappend vals [expr {$v < $min ? $min : $v > $max ? $max : $v}]
            }
        }
        set vals
    }
}

# ::fivax::motion::Near -- Returns the alias of angle q (mod 360 deg) nearest r.
proc ::fivax::motion::Near {q r} {
    expr {$q + 6.283185307179586 * round(($r - $q) / 6.283185307179586)}
}

# ::fivax::motion::InCone --
#	Returns 1 when unit axis t lies in the singular cone: within -cone of
#	the azimuth axis direction u2 (either way), where the azimuth is free.
proc ::fivax::motion::InCone {ctx t} {
    lassign $t tx ty tz
    lassign [dict get $ctx u2] ux uy uz
    expr {($ty * $uz - $tz * $uy) ** 2 + ($tz * $ux - $tx * $uz) ** 2
          + ($tx * $uy - $ty * $ux) ** 2 < [dict get $ctx cone2]}
}

# ::fivax::motion::Quantize --
#	Returns the list of the rotary values (rad) given, each rounded to the
#	output resolution step (the context's step; 0: exact).
proc ::fivax::motion::Quantize {step args} {
    if {$step > 0} {return [lmap q $args {expr {round($q / $step) * $step}}]}
    return $args
}

# ::fivax::motion::Pick --
#	Returns the candidate {q1 q2 branch} for unit axis t nearest the
#	rotaries {g1 g2} among those that branches la and lb both reach
#	without a retract (if any do). Fast path, outside the singular cone:
#	each solution's aliases nearest g1 and g2, when in the limits (any
#	other alias is farther than half a turn, so it cannot be nearer).
#	Errors: those of Candidates.
proc ::fivax::motion::Pick {ctx t g1 g2 la lb src} {
    lassign [::fivax::kin::orientations [dict get $ctx model] $t] status sols
    set cone [InCone $ctx $t]
    if {$status eq "regular" && !$cone} {
        lassign [dict get $ctx limits] lim1 lim2
        lassign $lim1 min1 max1
        lassign $lim2 min2 max2
        set lab [expr {[llength $sols] == 2 ? 0 : -1}]
        set cands {}
        foreach sol $sols {
            lassign $sol x y
            set x [Near $x $g1]
            set y [Near $y $g2]
            if {$x >= $min1 - 1e-9 && $x <= $max1 + 1e-9 && $y >= $min2 - 1e-9 && $y <= $max2 + 1e-9} {
                lappend cands $x $y $lab
            }
            if {$lab >= 0} {incr lab}
        }
        lassign [Closest $cands $g1 $g2 $la $lb] best d
        if {$best ne "" && $d < Inf} {return $best}
    }
    lindex [Closest [Candidates $ctx $t $cone [list $g1 $g2 -1] $src] $g1 $g2 $la $lb] 0
}

# ::fivax::motion::Closest --
#	Returns {candidate distance}: of the flat candidate triples, the one
#	nearest {g1 g2} (sum of absolute differences) whose branch suits la
#	and lb, else the nearest of all with distance Inf ({} Inf if none).
proc ::fivax::motion::Closest {cands g1 g2 la lb} {
    set best {}
    set bd Inf
    set any {}
    set ad Inf
    foreach {x y lab} $cands {
        # (as abs(), see Continues)
        set d [expr {($x > $g1 ? $x - $g1 : $g1 - $x) + ($y > $g2 ? $y - $g2 : $g2 - $y)}]
        if {[Joins $lab $la] && [Joins $lab $lb]} {
            if {$d < $bd} {set bd $d; set best [list $x $y $lab]}
        } elseif {$d < $ad} {
            set ad $d
            set any [list $x $y $lab]
        }
    }
    expr {$best ne "" ? [list $best $bd] : [list $any Inf]}
}

# ::fivax::motion::Continues --
#	Returns 1 when a cutting move can go continuously from rotaries
#	{a1 a2} on branch al to {b1 b2} on branch bl, 0 when it needs a
#	retract: a change of branch outside the singular cone (branch -1), or
#	a swing above the machine's max_swing (ms1, ms2).
proc ::fivax::motion::Continues {ms1 ms2 a1 a2 al b1 b2 bl} {
    # (abs() is a command call in expr: the ternaries give the same results
    # at a fraction of the cost, a zero differing only in its sign; the same
    # branch joins: Joins is asked only when they differ)
    expr {($al == $bl || [Joins $al $bl]) && ($b1 > $a1 ? $b1 - $a1 : $a1 - $b1) <= $ms1
        && ($b2 > $a2 ? $b2 - $a2 : $a2 - $b2) <= $ms2}
}

# ::fivax::motion::Joins --
#	Returns 1 when branches la and lb connect: equal, or either -1 (where
#	the two inverse solutions meet).
proc ::fivax::motion::Joins {la lb} {
    expr {$la == $lb || $la < 0 || $lb < 0}
}

# ::fivax::motion::Preferred --
#	Returns the first-point choice {q1 q2 branch} among the flat candidate
#	triples: those matching every axis's sign preference if any do, then
#	the smallest tilt, then the smallest azimuth.
proc ::fivax::motion::Preferred {ctx cands} {
    set ok {}
    foreach {a b lab} $cands {
        if {[PreferCost $ctx $a $b] == 0} {lappend ok $a $b $lab}
    }
    if {![llength $ok]} {set ok $cands}
    Nearest {0.0 0.0} $ok
}

# ::fivax::motion::PreferCost --
#	Returns preferCost times the number of axes whose sign preference
#	{q1 q2} violates.
proc ::fivax::motion::PreferCost {ctx q1 q2} {
    variable preferCost
    set n 0
    foreach q [list $q1 $q2] axis [dict get $ctx axes] {
        set p [dict get $axis prefer]
        if {($p > 0 && $q < -1e-12) || ($p < 0 && $q > 1e-12)} {incr n}
    }
    expr {$n * $preferCost}
}

# ::fivax::motion::Nearest --
#	Returns the triple {q1 q2 branch} of the flat candidate list with the
#	smallest change of q1 from ref, ties (within 1e-9 rad) broken by the
#	smallest change of q2.
proc ::fivax::motion::Nearest {ref cands} {
    lassign $ref r1 r2
    set best {}
    foreach {a b lab} $cands {
        set d1 [expr {abs($a - $r1)}]
        set d2 [expr {abs($b - $r2)}]
        if {$best eq "" || $d1 < $b1 - 1e-9 || (abs($d1 - $b1) <= 1e-9 && $d2 < $b2)} {
            set best [list $a $b $lab]
            set b1 $d1
            set b2 $d2
        }
    }
    return $best
}

# ::fivax::motion::AxisText -- Returns i,j,k rounded for messages.
proc ::fivax::motion::AxisText {t} {
    join [lmap c $t {format %.6g $c}] ,
}

# ::fivax::motion::LimitReason --
#	Returns why a cutting move from rotaries {a1 a2} cannot reach unit axis
#	t: the exact solution nearest them (aliases nearest them, limits
#	ignored) leaves an axis's limits, turns it more than max_swing, or lies
#	on the other branch. Degrees in the text.
proc ::fivax::motion::LimitReason {ctx a1 a2 t} {
    lassign [::fivax::kin::orientations [dict get $ctx model] $t] status sols
    set best {}
    set bd Inf
    foreach sol $sols {
        lassign $sol x y
        if {$status eq "singular"} {set y $a2}
        set x [Near $x $a1]
        set y [Near $y $a2]
        set d [expr {abs($x - $a1) + abs($y - $a2)}]
        if {$d < $bd} {set bd $d; set best [list $x $y]}
    }
    foreach v $best axis [dict get $ctx axes] {
        dict with axis {}
        if {$v < $min - 1e-9 || $v > $max + 1e-9} {
            return [format "%s would leave its limits (%.3f deg, limits %g..%g)" $name \
                [::fivax::num::deg $v] [::fivax::num::deg $min] [::fivax::num::deg $max]]
        }
    }
    foreach v $best a [list $a1 $a2] axis [dict get $ctx axes] {
        dict with axis {}
        if {abs($v - $a) > $swing} {
            return [format "%s would swing %.3f deg in one cutting move (max_swing %g)" \
                $name [::fivax::num::deg [expr {abs($v - $a)}]] [::fivax::num::deg $swing]]
        }
    }
    return "the tool axis needs the other inverse solution"
}

# ::fivax::motion::LimitError --
#	Raises {FIVAX MOTION LIMIT}: the cutting move from rotaries {a1 a2} to
#	axis t at src has no in-limit continuation (-on-limit error).
proc ::fivax::motion::LimitError {ctx a1 a2 t src} {
    ::fivax::Fail MOTION LIMIT "$src: [LimitReason $ctx $a1 $a2 $t] on [dict get $ctx name]"
}
