# motion.tcl --
#	The motion planner: turns CL points (tool tip and axis in the workpiece
#	frame) into machine moves (spec/kinematics.md sections 6 to 8).
#
#	Candidates. Every CL point has up to two inverse solutions (branches);
#	each rotary value stands for its 360-degree aliases within the axis
#	limits (continuous axes: the alias nearest each previous value). Within
#	the singular cone (tool axis within -cone of the direction where the
#	azimuth axis is free) the azimuth is held at its previous values and the
#	tilt chosen to bring the tool axis closest to the CL axis. Azimuth
#	swings above -swing between close points are counted; linearisation
#	splits them (at the cone, the azimuth turns while the tip dwells).
#
#	Choice. A cutting move may go from one candidate to the next when both
#	lie on the same branch (or one is in the singular cone, where branches
#	meet) and no axis turns more than the machine's max_swing; otherwise it
#	needs a retract. Cost = w1 |dq1| + w2 |dq2| (radians, -weights) plus
#	retractCost per retract, so the fewest retracts win, then the least
#	weighted travel. 'optimal' (default) picks the whole sequence by dynamic
#	programming over the candidate graph; 'greedy' takes at each point the
#	candidate with the smallest tilt change, then azimuth change.
#
#	Windows. The optimiser keeps at most -window CL points. When the buffer
#	is full it writes the prefix up to the point where the best paths to all
#	current candidates merge: any whole-operation optimum passes through one
#	of those candidates, so that prefix is exactly the one the optimum has.
#	If they have not merged over half the window (two configurations cost
#	the same all along, e.g. the two branches on a continuous azimuth), it
#	writes the first half along the best path, still with at least half a
#	window of look-ahead, and restarts the tables from there. Either way
#	every written move is checked against the limits and continues from the
#	last written state, and memory stays bounded by the window.
#
#	Linearisation. Each cutting move is checked at the quarter points of the
#	controller's linear joint interpolation (tip against the straight
#	segment, axis against the great circle); CL points are inserted at the
#	middle (position linear, axis slerp) until within -tol / -atol.
#
#	Angles in radians inside; options, words and stats in degrees.

namespace eval ::fivax::motion {
    namespace export create setTool setFrame startPath add flush stats words
    variable seq 0
    variable pi 3.141592653589793
    # Cost of one retract (radian-equivalents of travel): far more than the
    # travel of any window (a few turns per point at most, 100000 points),
    # so the optimiser first minimises retracts, then travel.
    variable retractCost 1e6
    # Tie-breaks at the first point of a path: per violated sign
    # preference, and per radian away from zero (smallest values first).
    variable preferCost 1e-6
    variable zeroCost 1e-9
    # Linearisation splits a cutting move at most this many levels deep.
    variable maxDepth 12
}

# ::fivax::motion::create --
#	Returns a planner for machine (a fivax::machine dict). Options:
#	  -tableOffset {x y z}   overrides the machine's table_offset
#	  -msys 0|1              express CL data in the MSYS frame
#	  -feedMode inverse|direct|dpm   feed of moves with rotary motion
#	  -rotary optimal|greedy         rotary solution choice
#	  -onLimit retract|error         when no in-limit continuation exists
#	  -tol 0.01              tip tolerance of the linearisation (mm; 0: off)
#	  -atol 0.05             its tool-axis tolerance (deg)
#	  -cone 0.0001           singular cone half-angle (deg)
#	  -swing 10              azimuth swing threshold (deg)
#	  -clearance ""          retract distance (mm; "": the machine's)
#	  -weights {1 1}         travel weights of the tilt and azimuth axes
#	  -window 4000           CL points the optimiser holds at most (2..100000;
#	                         about 1.5 kB each)
#	  -angleStep 0           output resolution of the rotary words (deg; 0:
#	                         exact). Rotaries are rounded to it before X Y Z
#	                         are computed, so the linear axes compensate the
#	                         rounding and the tip stays exact (only the X Y Z
#	                         rounding and a tool-axis error below one step
#	                         remain)
#	Errors: {FIVAX MOTION OPTION}, {FIVAX MOTION VALUE}.
proc ::fivax::motion::create {machine args} {
    variable seq
    variable pi
    set h ::fivax::motion::plan[incr seq]
    upvar #0 $h S
    array set S {tableOffset "" msys 0 feedMode inverse rotary optimal
        onLimit retract tol 0.01 atol 0.05 cone 0.0001 swing 10 clearance ""
        weights {1 1} window 4000 angleStep 0}
    set names {-tableOffset -msys -feedMode -rotary -onLimit -tol -atol -cone
        -swing -clearance -weights -window -angleStep}
    foreach {opt val} $args {
        if {$opt ni $names} {
            unset S
            ::fivax::Fail MOTION OPTION "bad option \"$opt\": must be [join $names {, }]"
        }
        set S([string range $opt 1 end]) $val
    }
    try {
        CheckOptions $h
    } on error {msg opts} {
        unset S
        return -options $opts $msg
    }
    set S(machine) $machine
    set S(name) [dict get $machine name]
    set S(frame) {}
    set i 0
    foreach axis [dict get $machine chain] {
        incr i
        foreach key {name min max continuous rollover prefer} {
            set S($key$i) [dict get $axis $key]
        }
        set S(unlimited$i) [expr {$S(continuous$i) && $S(max$i) - $S(min$i) > 1e299}]
        set S(lim$i) [list $S(min$i) $S(max$i) $S(continuous$i) $S(unlimited$i)]
        set ms [dict get $machine max_swing]
        if {$S(rollover$i)} {set ms [expr {min($ms, $pi - 1e-9)}]}
        set S(ms$i) $ms
    }
    set d2r [expr {$pi / 180.0}]
    if {$S(clearance) eq ""} {set S(clearance) [dict get $machine clearance]}
    foreach {key name} {feedMin feed_min feedMax feed_max itMax inverse_time_max safeZ safe_z} {
        set S($key) [dict get $machine $name]
    }
    # -atol 0: no check of the tool axis between blocks
    set S(atolCheck) [expr {$S(atol) > 0 ? $S(atol) * $d2r : Inf}]
    set S(sinCone) [expr {sin($S(cone) * $d2r)}]
    set S(swingRad) [expr {$S(swing) * $d2r}]
    set S(stepRad) [expr {$S(angleStep) * $d2r}]
    lassign $S(weights) S(w1) S(w2)
    array set S {last "" buf {} pathStart 1 points 0 moves 0 travel 0.0
        inserted 0 retracts 0 holds 0 swings 0 unresolved 0 forced 0}
    setTool $h [dict get $machine tool_length]
    return $h
}

# ::fivax::motion::CheckOptions -- Validates the option values of planner h.
proc ::fivax::motion::CheckOptions {h} {
    upvar #0 $h S
    foreach {key choices} {feedMode {inverse direct dpm} rotary {optimal greedy}
        onLimit {retract error}} {
        if {$S($key) ni $choices} {
            ::fivax::Fail MOTION VALUE "bad -$key \"$S($key)\": must be [join $choices {, }]"
        }
    }
    foreach key {tol atol cone swing angleStep} {
        set v [::fivax::parseReal $S($key)]
        if {$v eq "" || $v < 0} {
            ::fivax::Fail MOTION VALUE "bad -$key \"$S($key)\": must be a number >= 0"
        }
        set S($key) $v
    }
    if {$S(clearance) ne ""} {
        set v [::fivax::parseReal $S(clearance)]
        if {$v eq "" || $v < 0} {
            ::fivax::Fail MOTION VALUE "bad -clearance \"$S(clearance)\": must be a number >= 0"
        }
        set S(clearance) $v
    }
    set w [lmap v $S(weights) {::fivax::parseReal $v}]
    if {[llength $w] != 2 || "" in $w || [lindex $w 0] <= 0 || [lindex $w 1] <= 0} {
        ::fivax::Fail MOTION VALUE "bad -weights \"$S(weights)\": must be two numbers > 0"
    }
    set S(weights) $w
    if {![string is entier -strict $S(window)] || $S(window) < 2 || $S(window) > 100000} {
        ::fivax::Fail MOTION VALUE "bad -window \"$S(window)\": must be an integer from 2 to 100000"
    }
}

# ::fivax::motion::setTool --
#	Rebuilds the kinematic model for a tool of length len (mm). Call flush
#	first: points still held would be posted for the new tool.
#	Errors: {FIVAX MOTION STATE} while points are held.
proc ::fivax::motion::setTool {h len} {
    upvar #0 $h S
    if {[llength $S(buf)]} {
        ::fivax::Fail MOTION STATE "setTool with [llength $S(buf)] CL points held: flush first"
    }
    if {$S(tableOffset) eq ""} {
        set S(model) [::fivax::kin::model $S(machine) $len]
    } else {
        set S(model) [::fivax::kin::model $S(machine) $len $S(tableOffset)]
    }
    set S(toolLength) $len
    set S(axes) [dict get $S(machine) chain]
    foreach key {u1 u2 s1 s2} {set S($key) [dict get $S(model) $key]}
}

# ::fivax::motion::setFrame --
#	Sets the MSYS frame (origin and unit X, Y axes of the MCS in absolute
#	coordinates); CL data are mapped through it when -msys is on.
proc ::fivax::motion::setFrame {h origin xaxis yaxis} {
    upvar #0 $h S
    set S(frame) [list $origin $xaxis $yaxis [::fivax::vec::cross $xaxis $yaxis]]
}

# ::fivax::motion::ToWork -- Returns {P t} mapped through the MSYS frame when enabled.
proc ::fivax::motion::ToWork {h P t} {
    upvar #0 $h S
    if {!$S(msys) || $S(frame) eq ""} {return [list $P $t]}
    lassign $S(frame) o x y z
    set Pw [::fivax::vec::add $o [FrameApply $x $y $z $P]]
    list $Pw [FrameApply $x $y $z $t]
}

# ::fivax::motion::FrameApply -- Returns v.x X + v.y Y + v.z Z.
proc ::fivax::motion::FrameApply {x y z v} {
    lassign $v a b c
    ::fivax::vec::add [::fivax::vec::add [::fivax::vec::scale $a $x] \
        [::fivax::vec::scale $b $y]] [::fivax::vec::scale $c $z]
}

# ::fivax::motion::startPath --
#	Marks the start of an operation: its first point follows the machine's
#	sign preference where that costs nothing. Returns the moves still held
#	(as flush).
proc ::fivax::motion::startPath {h} {
    upvar #0 $h S
    set moves [flush $h]
    set S(pathStart) 1
    return $moves
}

# ::fivax::motion::add --
#	Adds one CL point: kind rapid|feed, tip P and axis t (CL frame), feed
#	(mm/min, ignored for rapids), src (FILE:LINE for messages). Returns the
#	moves ready to be written, possibly none while the optimiser's window
#	fills (see flush for the move dict).
#	Errors: {FIVAX MOTION UNREACHABLE}, {FIVAX MOTION LIMIT}.
proc ::fivax::motion::add {h kind P t feed src} {
    upvar #0 $h S
    lassign [ToWork $h $P $t] P t
    set t [::fivax::vec::unit $t]
    incr S(points)
    if {$S(rotary) eq "greedy"} {
        return [Greedy $h $kind $P $t $feed $src]
    }
    Step $h $kind $P $t $feed $src
    if {[llength $S(buf)] < $S(window)} {return {}}
    Commit $h 0
}

# ::fivax::motion::flush --
#	Returns every move still held. A move is a dict: kind rapid|feed|position,
#	joints {X Y Z q1 q2} (mm, rad, chain order), write (which of X Y Z R to
#	write: R = rotaries), P and t (the CL target in the workpiece frame:
#	interpolated for linearisation points, on the tool axis line for
#	retract and approach points, empty for positioning moves), feedMode
#	93|94, feed (mm/min, 1/min for 93, deg/min for dpm), src, tag ("",
#	inserted, retract or reengage) and note (the reason of a retract).
proc ::fivax::motion::flush {h} {
    upvar #0 $h S
    if {![llength $S(buf)]} {return {}}
    Commit $h 1
}

# ::fivax::motion::stats --
#	Returns a dict: points, moves, travel (deg of rotary travel written),
#	inserted (linearisation points), retracts, holds (CL points posted with
#	the azimuth held in the singular cone), swings (azimuth swings above
#	-swing between close points), unresolved (moves still out of tolerance
#	after the deepest split), forced (window commits before the merge).
proc ::fivax::motion::stats {h} {
    upvar #0 $h S
    variable pi
    set d [dict create travel [expr {$S(travel) * 180.0 / $pi}]]
    foreach key {points moves inserted retracts holds swings unresolved forced} {
        dict set d $key $S($key)
    }
    return $d
}

# ::fivax::motion::Fresh --
#	Returns 1 when the next point may take any configuration: nothing
#	written yet, or an operation's first point reached by a rapid.
proc ::fivax::motion::Fresh {h kind} {
    upvar #0 $h S
    expr {$S(last) eq "" || ($S(pathStart) && $kind eq "rapid")}
}

# ::fivax::motion::Greedy --
#	Posts one CL point with the greedy choice: the preferred candidate at
#	a fresh start, else the nearest one that needs no retract (the nearest
#	of all, with a retract, when none does).
proc ::fivax::motion::Greedy {h kind P t feed src} {
    upvar #0 $h S
    variable retractCost
    set refs [LastRefs $h]
    set cands [Candidates $h $t $refs $src]
    if {[Fresh $h $kind]} {
        set choice [Preferred $h $cands]
    } else {
        lassign $refs a1 a2 al
        set isFeed [expr {$kind eq "feed"}]
        set ok {}
        foreach {b1 b2 bl} $cands {
            if {[Cost $S(ms1) $S(ms2) $isFeed $a1 $a2 $al $b1 $b2 $bl] < $retractCost} {
                lappend ok $b1 $b2 $bl
            }
        }
        if {![llength $ok]} {
            if {$S(onLimit) eq "error"} {LimitError $h $a1 $a2 $t $src}
            set ok $cands
        }
        set choice [Nearest [list $a1 $a2] $ok]
    }
    set S(pathStart) 0
    Emit $h $kind $P $t $feed $src {*}$choice
}

# ::fivax::motion::LastRefs -- Returns {q1 q2 branch} of the last written point, or {}.
proc ::fivax::motion::LastRefs {h} {
    upvar #0 $h S
    if {$S(last) eq ""} {return {}}
    lassign $S(last) joints - - - lab
    list [lindex $joints 3] [lindex $joints 4] $lab
}

# ::fivax::motion::Preferred --
#	Returns the first-point choice {q1 q2 branch} among the flat candidate
#	triples: those matching every axis's sign preference if any do, then
#	the smallest tilt, then the smallest azimuth.
proc ::fivax::motion::Preferred {h cands} {
    set ok {}
    foreach {a b lab} $cands {
        if {[PreferCost $h $a $b] == 0} {lappend ok $a $b $lab}
    }
    if {![llength $ok]} {set ok $cands}
    Nearest {0.0 0.0} $ok
}

# ::fivax::motion::PreferCost --
#	Returns preferCost times the number of axes whose sign preference
#	{q1 q2} violates.
proc ::fivax::motion::PreferCost {h q1 q2} {
    upvar #0 $h S
    variable preferCost
    set n 0
    foreach q [list $q1 $q2] p [list $S(prefer1) $S(prefer2)] {
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

# ::fivax::motion::Cost --
#	Returns the cost of going from rotaries {a1 a2} on branch al to
#	{b1 b2} on branch bl: the weighted travel (rad), plus retractCost when
#	a cutting move (isFeed 1) cannot get there continuously: a change of
#	branch outside the singular cone (branch -1), or a swing above the
#	machine's max_swing (ms1, ms2).
proc ::fivax::motion::Cost {ms1 ms2 isFeed a1 a2 al b1 b2 bl {w1 1.0} {w2 1.0}} {
    variable retractCost
    set d1 [expr {abs($b1 - $a1)}]
    set d2 [expr {abs($b2 - $a2)}]
    if {!$isFeed || ([Joins $al $bl] && $d1 <= $ms1 && $d2 <= $ms2)} {
        return [expr {$w1 * $d1 + $w2 * $d2}]
    }
    expr {$w1 * $d1 + $w2 * $d2 + $retractCost}
}

# ::fivax::motion::Joins --
#	Returns 1 when branches la and lb connect: equal, or either -1 (where
#	the two inverse solutions meet).
proc ::fivax::motion::Joins {la lb} {
    expr {$la == $lb || $la < 0 || $lb < 0}
}

# ::fivax::motion::Candidates --
#	Returns the flat list {q1 q2 branch ...} of candidate rotary values for
#	unit axis t. refs are the flat triples of the previous candidates ({}
#	at a first point): continuous axes take the aliases nearest them, and
#	in the singular cone the azimuth is held at theirs (exact solutions
#	there only when no held tilt is within the limits). branch is 0 or 1
#	for the two inverse solutions, -1 where they meet (singular cone,
#	workspace edge).
#	Errors: {FIVAX MOTION UNREACHABLE}; {FIVAX MOTION LIMIT} when every
#	solution lies outside the limits.
proc ::fivax::motion::Candidates {h t refs src} {
    upvar #0 $h S
    lassign [::fivax::kin::orientations $S(model) $t] status sols
    if {$status eq "unreachable"} {
        ::fivax::Fail MOTION UNREACHABLE "$src: tool axis ([AxisText $t]) unreachable on $S(name)"
    }
    set cone [expr {$status eq "singular" || [InCone $h $t]}]
    set out {}
    if {$cone && [llength $refs]} {set out [Held $h $t $refs]}
    if {![llength $out]} {
        set out [Exact $h $sols $refs [expr {$cone || [llength $sols] < 2}]]
    }
    if {![llength $out]} {
        ::fivax::Fail MOTION LIMIT "$src: tool axis ([AxisText $t]) needs a rotary value outside the limits of $S(name)"
    }
    return $out
}

# ::fivax::motion::Exact --
#	Returns the flat candidate triples of the inverse solutions sols, each
#	axis value expanded to its in-limit aliases near refs; branch -1 for
#	all when merged is 1, else the solution's index.
proc ::fivax::motion::Exact {h sols refs merged} {
    set out {}
    set lab [expr {$merged ? -1 : 0}]
    foreach sol $sols {
        lassign $sol a b
        set bs [Aliases $h 2 $b $refs]
        foreach x [Aliases $h 1 $a $refs] {
            foreach y $bs {lappend out $x $y $lab}
        }
        if {!$merged} {incr lab}
    }
    return $out
}

# ::fivax::motion::Held --
#	Returns the candidates in the singular cone: for each previous
#	candidate {p1 p2} the azimuth held at p2, with the tilt (alias nearest
#	p1) that brings the tool axis closest to unit t; the axis is then off
#	by at most the cone angle. All get branch -1.
proc ::fivax::motion::Held {h t refs} {
    set out {}
    foreach {p1 p2 -} $refs {
        set q1 [HoldTilt $h $t $p1 $p2]
        if {$q1 ne "" && [lsearch -exact $out [list $q1 $p2]] < 0} {lappend out [list $q1 $p2]}
    }
    set flat {}
    foreach c $out {lappend flat {*}$c -1}
    return $flat
}

# ::fivax::motion::HoldTilt --
#	Returns the tilt (alias nearest r1 within the limits, "" if none) that
#	brings the tool axis closest to unit t when the azimuth is q2.
proc ::fivax::motion::HoldTilt {h t r1 q2} {
    set best ""
    set bd Inf
    foreach x [Aliases $h 1 [BestTilt $h $t $q2] [list $r1 $q2 -1]] {
        if {abs($x - $r1) < $bd} {
            set bd [expr {abs($x - $r1)}]
            set best $x
        }
    }
    return $best
}

# ::fivax::motion::BestTilt --
#	Returns the tilt q1 (radians, (-pi, pi]) that brings the tool axis
#	closest to unit t when the azimuth is q2: with w = R(u2, -s2 q2) t, the
#	angle th maximising (R(u1, th) Z).w is atan2((u1 x Z).w, (Z - k1 u1).w).
proc ::fivax::motion::BestTilt {h t q2} {
    upvar #0 $h S
    set w [::fivax::vec::rotate $S(u2) [expr {-$S(s2) * $q2}] $t]
    lassign $w wx wy wz
    lassign $S(u1) x1 y1 z1
    set zw [expr {$wz - $z1 * ($x1 * $wx + $y1 * $wy + $z1 * $wz)}]
    set mw [expr {$y1 * $wx - $x1 * $wy}]
    expr {$S(s1) * atan2($mw, $zw) + 0.0}
}

# ::fivax::motion::Aliases --
#	Returns the values equivalent to q (mod 360 deg) that axis i (1 or 2)
#	may take: all within the limits for a limited axis; for a continuous
#	one the alias nearest each ref value (element i of the flat triples
#	refs; with no refs q and its alias of the other sign), with its
#	neighbours when the axis has finite limits.
proc ::fivax::motion::Aliases {h i q refs} {
    upvar #0 $h S
    variable pi
    lassign $S(lim$i) min max continuous unlimited
    set twoPi [expr {2.0 * $pi}]
    if {!$continuous} {
        if {$q >= $min && $q <= $max && $q - $twoPi < $min && $q + $twoPi > $max} {
            return [list $q]
        }
        set vals {}
        set k [expr {ceil(($min - $q) / $twoPi - 1e-9)}]
        for {set v [expr {$q + $twoPi * $k}]} {$v <= $max + 1e-9} {set v [expr {$v + $twoPi}]} {
            lappend vals [expr {$v < $min ? $min : $v > $max ? $max : $v}]
        }
        return $vals
    }
    if {![llength $refs]} {
        set try [list $q [expr {$q > 0 ? $q - $twoPi : $q + $twoPi}]]
    } else {
        set try {}
        foreach {r1 r2 -} $refs {
            set r [expr {$i == 1 ? $r1 : $r2}]
            set v [Near $q $r]
            lappend try $v
            if {!$unlimited} {lappend try [expr {$v - $twoPi}] [expr {$v + $twoPi}]}
        }
    }
    set vals {}
    foreach v $try {
        if {$v >= $min - 1e-9 && $v <= $max + 1e-9 && $v ni $vals} {
            lappend vals [expr {$v < $min ? $min : $v > $max ? $max : $v}]
        }
    }
    return $vals
}

# ::fivax::motion::Near -- Returns the alias of angle q (mod 360 deg) nearest r.
proc ::fivax::motion::Near {q r} {
    expr {$q + 6.283185307179586 * round(($r - $q) / 6.283185307179586)}
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
proc ::fivax::motion::LimitReason {h a1 a2 t} {
    upvar #0 $h S
    variable pi
    set r2d [expr {180.0 / $pi}]
    lassign [::fivax::kin::orientations $S(model) $t] status sols
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
    foreach i {1 2} v $best a [list $a1 $a2] {
        if {$v < $S(min$i) - 1e-9 || $v > $S(max$i) + 1e-9} {
            return [format "%s would leave its limits (%.3f deg, limits %g..%g)" $S(name$i) \
                [expr {$v * $r2d}] [expr {$S(min$i) * $r2d}] [expr {$S(max$i) * $r2d}]]
        }
    }
    foreach i {1 2} v $best a [list $a1 $a2] {
        if {abs($v - $a) > $S(ms$i)} {
            return [format "%s would swing %.3f deg in one cutting move (max_swing %g)" \
                $S(name$i) [expr {abs($v - $a) * $r2d}] [expr {$S(ms$i) * $r2d}]]
        }
    }
    return "the tool axis needs the other inverse solution"
}

# ::fivax::motion::LimitError --
#	Raises {FIVAX MOTION LIMIT}: the cutting move from rotaries {a1 a2} to
#	axis t at src has no in-limit continuation (-onLimit error).
proc ::fivax::motion::LimitError {h a1 a2 t src} {
    upvar #0 $h S
    ::fivax::Fail MOTION LIMIT "$src: [LimitReason $h $a1 $a2 $t] on $S(name)"
}

# ::fivax::motion::Step --
#	Adds one CL point to the optimiser's buffer as a layer
#	{kind P t feed src states}, states being the flat list
#	{q1 q2 branch cost back ...}: cost of the best path from the last
#	written point (normalised to a minimum of 0), back the index of its
#	predecessor in the previous layer (-1 for the first layer).
proc ::fivax::motion::Step {h kind P t feed src} {
    upvar #0 $h S
    variable zeroCost
    if {[llength $S(buf)]} {
        set prev [lindex $S(buf) end 5]
    } elseif {$S(last) ne ""} {
        set prev [list {*}[LastRefs $h] 0.0 -1]
    } else {
        set prev {}
    }
    set refs {}
    foreach {a b lab - -} $prev {lappend refs $a $b $lab}
    set cands [Candidates $h $t $refs $src]
    set fresh [expr {![llength $S(buf)] && [Fresh $h $kind]}]
    set S(pathStart) 0
    if {![llength $prev]} {
        set states {}
        foreach {b1 b2 bl} $cands {
            lappend states $b1 $b2 $bl [expr {[PreferCost $h $b1 $b2]
                + $zeroCost * (abs($b1) + abs($b2))}] -1
        }
    } else {
        set states [Relax $h $prev $cands [expr {$kind eq "feed"}] $t $src]
        if {$fresh} {
            set i 3
            foreach {b1 b2 - c -} $states {
                lset states $i [expr {$c + [PreferCost $h $b1 $b2]}]
                incr i 5
            }
        }
    }
    lappend S(buf) [list $kind $P $t $feed $src $states]
}

# ::fivax::motion::Relax --
#	Returns the states (see Step) of the candidate triples cands reached
#	from the states prev by a move of the given kind (isFeed 1: cutting).
#	With -onLimit error, moves needing a retract are excluded and a layer
#	left unreachable raises {FIVAX MOTION LIMIT} naming src. States equal
#	mod 360 deg on unlimited continuous axes have the same future; only
#	the cheaper is kept.
proc ::fivax::motion::Relax {h prev cands isFeed t src} {
    upvar #0 $h S
    variable retractCost
    set ms1 $S(ms1)
    set ms2 $S(ms2)
    set w1 $S(w1)
    set w2 $S(w2)
    set err [expr {$S(onLimit) eq "error"}]
    set states {}
    set low Inf
    foreach {b1 b2 bl} $cands {
        set best Inf
        set arg -1
        set i 0
        foreach {a1 a2 al ac -} $prev {
            set c [Cost $ms1 $ms2 $isFeed $a1 $a2 $al $b1 $b2 $bl $w1 $w2]
            if {!($err && $c >= $retractCost) && $ac + $c < $best} {
                set best [expr {$ac + $c}]
                set arg $i
            }
            incr i
        }
        lappend states $b1 $b2 $bl $best $arg
        if {$best < $low} {set low $best}
    }
    if {$low == Inf} {
        set i [BestState $prev]
        LimitError $h [lindex $prev [expr {5 * $i}]] [lindex $prev [expr {5 * $i + 1}]] $t $src
    }
    set i 3
    foreach {- - - c -} $states {
        lset states $i [expr {$c - $low}]
        incr i 5
    }
    if {($S(unlimited1) || $S(unlimited2)) && [llength $states] > 5} {
        set states [Fold $h $states]
    }
    return $states
}

# ::fivax::motion::Fold --
#	Returns states with those equal mod 360 deg on the unlimited continuous
#	axes merged into the cheapest of them.
proc ::fivax::motion::Fold {h states} {
    upvar #0 $h S
    variable pi
    set twoPi [expr {2.0 * $pi}]
    set keep [dict create]
    foreach {a b lab c back} $states {
        set ka [expr {$S(unlimited1) ? $a - $twoPi * floor($a / $twoPi + 1e-9) : $a}]
        set kb [expr {$S(unlimited2) ? $b - $twoPi * floor($b / $twoPi + 1e-9) : $b}]
        set key [format "%.7f %.7f %d" $ka $kb $lab]
        if {![dict exists $keep $key] || $c < [lindex [dict get $keep $key] 3]} {
            dict set keep $key [list $a $b $lab $c $back]
        }
    }
    concat {*}[dict values $keep]
}

# ::fivax::motion::BestState -- Returns the index of the cheapest of the flat states.
proc ::fivax::motion::BestState {states} {
    set best -1
    set bc Inf
    set i 0
    foreach {- - - c -} $states {
        if {$c < $bc} {set bc $c; set best $i}
        incr i
    }
    return $best
}

# ::fivax::motion::Trace --
#	Returns the state index of every layer of buf on the best path ending
#	in state index last of the last layer.
proc ::fivax::motion::Trace {buf last} {
    set path [list $last]
    for {set j [expr {[llength $buf] - 1}]} {$j > 0} {incr j -1} {
        set last [lindex $buf $j 5 [expr {5 * $last + 4}]]
        lappend path $last
    }
    lreverse $path
}

# ::fivax::motion::Merge --
#	Returns the index of the last layer of buf where the best paths to all
#	reachable states of the last layer pass through one state, or -1.
proc ::fivax::motion::Merge {buf} {
    set live [dict create]
    set i 0
    foreach {- - - c -} [lindex $buf end 5] {
        if {$c < Inf} {dict set live $i 1}
        incr i
    }
    for {set j [expr {[llength $buf] - 1}]} {$j > 0} {incr j -1} {
        if {[dict size $live] == 1} {return $j}
        set states [lindex $buf $j 5]
        set next [dict create]
        foreach s [dict keys $live] {dict set next [lindex $states [expr {5 * $s + 4}]] 1}
        set live $next
    }
    expr {[dict size $live] == 1 ? 0 : -1}
}

# ::fivax::motion::Commit --
#	Writes the settled part of the buffer and returns its moves: all of it
#	along the best path when all is 1; else the prefix up to the merge
#	point when it covers half the window, or else the first half along
#	the best path, the rest being re-rooted at the last written point.
proc ::fivax::motion::Commit {h all} {
    upvar #0 $h S
    set n [llength $S(buf)]
    set path [Trace $S(buf) [BestState [lindex $S(buf) end 5]]]
    set k $n
    set forced 0
    if {!$all} {
        set m [Merge $S(buf)]
        set k [expr {$m >= $n / 2 - 1 ? $m + 1 : $n / 2}]
        set forced [expr {$m < $n / 2 - 1}]
    }
    set moves {}
    foreach layer [lrange $S(buf) 0 [expr {$k - 1}]] i [lrange $path 0 [expr {$k - 1}]] {
        lassign $layer kind P t feed src states
        lappend moves {*}[Emit $h $kind $P $t $feed $src \
            {*}[lrange $states [expr {5 * $i}] [expr {5 * $i + 2}]]]
    }
    set S(buf) [lrange $S(buf) $k end]
    if {$forced} {
        incr S(forced)
        Reroot $h
    }
    return $moves
}

# ::fivax::motion::Reroot --
#	Recomputes the costs of the held layers from the last written point.
proc ::fivax::motion::Reroot {h} {
    upvar #0 $h S
    set prev [list {*}[LastRefs $h] 0.0 -1]
    set buf {}
    foreach layer $S(buf) {
        lassign $layer kind P t feed src states
        set cands {}
        foreach {a b lab - -} $states {lappend cands $a $b $lab}
        set states [Relax $h $prev $cands [expr {$kind eq "feed"}] $t $src]
        lappend buf [lreplace $layer 5 5 $states]
        set prev $states
    }
    set S(buf) $buf
}

# ::fivax::motion::Emit --
#	Writes CL point (kind P t feed src) with rotaries {q1 q2} on branch lab
#	after the last written point and returns its moves: the rapid sequence,
#	the linearised cutting moves, or a retract, reposition and re-engage.
proc ::fivax::motion::Emit {h kind P t feed src q1 q2 lab} {
    upvar #0 $h S
    variable retractCost
    set b [Record $h $P $t $q1 $q2 $lab]
    if {[InCone $h $t]} {incr S(holds)}
    if {$S(last) eq ""} {
        set moves [First $h $kind $b $feed $src]
    } elseif {$kind eq "rapid"} {
        set moves [Transfer $h $S(last) $b $src]
    } else {
        lassign [LastRefs $h] a1 a2 al
        if {[Cost $S(ms1) $S(ms2) 1 $a1 $a2 $al $q1 $q2 $lab] < $retractCost} {
            CountSwing $h $a2 $q2 [lindex $S(last) 2] $t
            set moves [FeedMoves $h [Linearise $h $S(last) $b 0 $src] $feed $src]
        } else {
            set moves [Retract $h $S(last) $b [FeedClamp $h $feed] $src [LimitReason $h $a1 $a2 $t]]
        }
    }
    Travel $h $moves
    set S(last) $b
    incr S(moves) [llength $moves]
    return $moves
}

# ::fivax::motion::CountSwing --
#	Counts a singular swing: the azimuth turns from a2 to b2 by more than
#	-swing while the CL axis turns from ta to tb by less than that.
proc ::fivax::motion::CountSwing {h a2 b2 ta tb} {
    upvar #0 $h S
    if {abs($b2 - $a2) > $S(swingRad) && [::fivax::vec::angle $ta $tb] < $S(swingRad)} {
        incr S(swings)
    }
}

# ::fivax::motion::Travel -- Adds the rotary travel of moves to the statistics.
proc ::fivax::motion::Travel {h moves} {
    upvar #0 $h S
    if {$S(last) eq ""} {
        set p1 ""
    } else {
        lassign [lindex $S(last) 0] - - - p1 p2
    }
    foreach move $moves {
        lassign [dict get $move joints] - - - q1 q2
        if {$p1 ne ""} {
            set S(travel) [expr {$S(travel) + abs($q1 - $p1) + abs($q2 - $p2)}]
        }
        set p1 $q1
        set p2 $q2
    }
}

# ::fivax::motion::Move --
#	Returns a move dict (see flush) to joints; P and t may be empty.
proc ::fivax::motion::Move {kind joints write P t mode feed src {tag ""} {note ""}} {
    dict create kind $kind joints $joints write $write P $P t $t \
        feedMode $mode feed $feed src $src tag $tag note $note
}

# ::fivax::motion::First --
#	Returns the moves to the very first point b (a point record, see
#	Linearise): a rapid rotates first, then moves X Y, then Z.
proc ::fivax::motion::First {h kind b feed src} {
    lassign $b joints P t
    if {$kind eq "feed"} {
        return [list [Move feed $joints {X Y Z R} $P $t 94 [FeedClamp $h $feed] $src]]
    }
    list [Move position $joints R {} {} 94 0 $src] [Move position $joints {X Y} {} {} 94 0 $src] \
        [Move rapid $joints {X Y Z R} $P $t 94 0 $src]
}

# ::fivax::motion::Transfer --
#	Returns the rapid moves from point record a to point record b. A
#	change of orientation is sequenced safely: Z up to the safe height
#	(safe_z, else clearance above the higher end), rotate, X Y, then down.
proc ::fivax::motion::Transfer {h a b src} {
    upvar #0 $h S
    lassign $b joints P t
    set final [Move rapid $joints {X Y Z R} $P $t 94 0 $src]
    lassign [lindex $a 0] pX pY pZ p1 p2
    lassign $joints X Y Z q1 q2
    if {abs($q1 - $p1) < 1e-9 && abs($q2 - $p2) < 1e-9} {return [list $final]}
    set safe $S(safeZ)
    if {$safe eq ""} {set safe [expr {max($pZ, $Z) + $S(clearance)}]}
    list [Move position [list $pX $pY $safe $p1 $p2] Z {} {} 94 0 $src] \
        [Move position [list $pX $pY $safe $q1 $q2] R {} {} 94 0 $src] \
        [Move position [list $X $Y $safe $q1 $q2] {X Y} {} {} 94 0 $src] $final
}

# ::fivax::motion::Retract --
#	Returns the moves from point record a to point record b when no
#	cutting move can get there: retract along the tool axis by the
#	clearance, rapid to the new configuration above b (Transfer), and
#	re-engage along b's tool axis at feed f (mm/min). reason goes into
#	the note.
proc ::fivax::motion::Retract {h a b f src reason} {
    upvar #0 $h S
    incr S(retracts)
    lassign $a ja Pa ta acta
    lassign $b jb Pb tb actb lab
    set c $S(clearance)
    set Pr [::fivax::vec::add $Pa [::fivax::vec::scale $c $acta]]
    set jr [concat [::fivax::kin::position $S(model) $Pr [lrange $ja 3 4]] [lrange $ja 3 4]]
    set Pe [::fivax::vec::add $Pb [::fivax::vec::scale $c $actb]]
    set je [concat [::fivax::kin::position $S(model) $Pe [lrange $jb 3 4]] [lrange $jb 3 4]]
    set moves [list [Move rapid $jr {X Y Z} $Pr $ta 94 0 $src retract $reason]]
    lappend moves {*}[Transfer $h [list $jr $Pr $ta $acta] [list $je $Pe $tb $actb] $src]
    lappend moves [Move feed $jb {X Y Z R} $Pb $tb 94 $f $src reengage]
}

# ::fivax::motion::Linearise --
#	Returns the point records {joints P t act branch ?retract?} after a up
#	to and including b such that the linear joint interpolation between
#	consecutive ones keeps the tip within -tol of their straight segment
#	and the axis within -atol of the great circle of their actual axes
#	(act), checked at the quarter points. An error e splits the move into
#	about sqrt(e / tol) pieces (the error of a smooth move shrinks with the
#	square of its length), each checked in turn, at most maxDepth levels
#	deep. Where the CL path between a and b runs out of the limits (a piece
#	no cutting move can do, see Cost), it is halved instead, and the piece
#	left at the deepest level gets the flag retract.
proc ::fivax::motion::Linearise {h a b depth src} {
    upvar #0 $h S
    variable maxDepth
    variable retractCost
    if {$S(tol) <= 0} {return [list $b]}
    lassign $a ja Pa - acta la
    lassign $b jb Pb - actb lb
    set ok [expr {[Cost $S(ms1) $S(ms2) 1 [lindex $ja 3] [lindex $ja 4] $la \
        [lindex $jb 3] [lindex $jb 4] $lb] < $retractCost}]
    set n 2
    if {$ok} {
        lassign [::fivax::verify::interpolationError $S(model) $ja $jb $Pa $Pb $acta $actb \
            $S(tol) $S(atolCheck)] dp da
        set e [expr {$dp / $S(tol)}]
        if {$da / $S(atolCheck) > $e} {set e [expr {$da / $S(atolCheck)}]}
        if {$e <= 1.0} {return [list $b]}
        set n [expr {int(ceil(1.1 * sqrt($e)))}]
        set n [expr {$n < 2 ? 2 : $n > 16 ? 16 : $n}]
    }
    if {$depth < $maxDepth} {
        try {
            set pts [Split $h $a $b $n $src]
            lappend pts $b
            set out {}
            set prev $a
            incr depth
            foreach p $pts {
                lappend out {*}[Linearise $h $prev $p $depth $src]
                set prev $p
            }
            return $out
        } trap {FIVAX MOTION} {} {
            # A CL axis in between is out of reach or of the limits.
        }
    }
    if {$ok} {
        incr S(unresolved)
        return [list $b]
    }
    list [lappend b retract]
}

# ::fivax::motion::Split --
#	Returns the point records to insert between point records a and b:
#	the CL points at fractions 1/n .. (n-1)/n (position linear, axis
#	slerp), each with the candidate nearest the joints interpolated there
#	that both ends reach without a retract. When an end lies in the
#	singular cone, where the azimuth is free, and its azimuth is not the
#	one the path leaves it with (see Departure), the azimuth turns there
#	first: that end's CL point again with the new azimuth (the tool dwells
#	at the tip while the azimuth turns).
proc ::fivax::motion::Split {h a b n src} {
    upvar #0 $h S
    variable retractCost
    lassign $a ja Pa ta - la
    lassign $b jb Pb tb - lb
    lassign $ja - - - a1 a2
    lassign $jb - - - b1 b2
    if {abs($b2 - $a2) > 1e-9} {
        foreach end [list $a $b] other [list $b $a] {
            lassign $end je P t
            if {[InCone $h $t]} {
                set c [Quantize $h [Departure $h $end $other $src]]
                if {abs($c - [lindex $je 4]) > 1e-9} {
                    set q1 [HoldTilt $h $t [lindex $je 3] $c]
                    if {$q1 ne ""} {return [list [Record $h $P $t $q1 $c -1]]}
                }
            }
        }
    }
    set out {}
    for {set i 1} {$i < $n} {incr i} {
        set f [expr {double($i) / $n}]
        set g1 [expr {$a1 + $f * ($b1 - $a1)}]
        set g2 [expr {$a2 + $f * ($b2 - $a2)}]
        set t [::fivax::vec::slerp $ta $tb $f]
        lappend out [Record $h [::fivax::vec::lerp $Pa $Pb $f] $t \
            {*}[Pick $h $t $g1 $g2 $la $lb $src]]
    }
    return $out
}

# ::fivax::motion::Departure --
#	Returns the azimuth with which the CL path leaves point record end
#	(in the singular cone) towards point record other: that of the exact
#	candidate nearest other's rotaries at the CL axis ten cone angles away
#	from end; half-way between their azimuths when other is that close.
proc ::fivax::motion::Departure {h end other src} {
    upvar #0 $h S
    lassign $end je - te
    lassign $other jo - to lo
    set angle [::fivax::vec::angle $te $to]
    set step [expr {10.0 * asin(min(1.0, $S(sinCone)))}]
    if {$angle <= $step} {return [expr {0.5 * ([lindex $je 4] + [lindex $jo 4])}]}
    set t [::fivax::vec::slerp $te $to [expr {$step / $angle}]]
    lindex [Pick $h $t [lindex $jo 3] [lindex $jo 4] $lo $lo $src] 1
}

# ::fivax::motion::Pick --
#	Returns the candidate {q1 q2 branch} for unit axis t nearest the
#	rotaries {g1 g2} among those that branches la and lb both reach
#	without a retract (if any do). Fast path, outside the singular cone:
#	each solution's aliases nearest g1 and g2, when in the limits (any
#	other alias is farther than half a turn, so it cannot be nearer).
#	Errors: those of Candidates.
proc ::fivax::motion::Pick {h t g1 g2 la lb src} {
    upvar #0 $h S
    lassign [::fivax::kin::orientations $S(model) $t] status sols
    if {$status eq "regular" && ![InCone $h $t]} {
        lassign $S(lim1) min1 max1
        lassign $S(lim2) min2 max2
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
    lindex [Closest [Candidates $h $t [list $g1 $g2 -1] $src] $g1 $g2 $la $lb] 0
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
        set d [expr {abs($x - $g1) + abs($y - $g2)}]
        if {[Joins $lab $la] && [Joins $lab $lb]} {
            if {$d < $bd} {set bd $d; set best [list $x $y $lab]}
        } elseif {$d < $ad} {
            set ad $d
            set any [list $x $y $lab]
        }
    }
    expr {$best ne "" ? [list $best $bd] : [list $any Inf]}
}

# ::fivax::motion::Record --
#	Returns the point record {joints P t act branch} of CL point P, t with
#	rotaries q1 q2 on branch lab; act is the tool axis they give (t itself
#	outside the singular cone, where candidates are exact).
proc ::fivax::motion::Record {h P t q1 q2 lab} {
    upvar #0 $h S
    # Round to the output resolution first: X Y Z then absorb it.
    set q1 [Quantize $h $q1]
    set q2 [Quantize $h $q2]
    set joints [concat [::fivax::kin::position $S(model) $P [list $q1 $q2]] $q1 $q2]
    if {![InCone $h $t]} {return [list $joints $P $t $t $lab]}
    list $joints $P $t [lindex [::fivax::kin::forward $S(model) $joints] 1] $lab
}

# ::fivax::motion::Quantize -- Returns rotary value q (rad) rounded to the -angleStep output resolution.
proc ::fivax::motion::Quantize {h q} {
    upvar #0 $h S
    if {$S(stepRad) <= 0} {return $q}
    expr {round($q / $S(stepRad)) * $S(stepRad)}
}

# ::fivax::motion::InCone --
#	Returns 1 when unit axis t lies in the singular cone: within -cone of
#	the azimuth axis direction u2 (either way), where the azimuth is free.
proc ::fivax::motion::InCone {h t} {
    upvar #0 $h S
    lassign $t tx ty tz
    lassign $S(u2) ux uy uz
    expr {($ty * $uz - $tz * $uy) ** 2 + ($tz * $ux - $tx * $uz) ** 2
          + ($tx * $uy - $ty * $ux) ** 2 < $S(sinCone) ** 2}
}

# ::fivax::motion::FeedMoves --
#	Returns the cutting moves through the point records pts (the last one
#	the CL point, the others inserted) from the last written point, with
#	feedMode and feed per move (see FeedOf); a record flagged retract is
#	reached by a retract instead.
proc ::fivax::motion::FeedMoves {h pts feed src} {
    upvar #0 $h S
    set f [FeedClamp $h $feed]
    set prev $S(last)
    set moves {}
    set last [expr {[llength $pts] - 1}]
    incr S(inserted) $last
    set i 0
    foreach p $pts {
        lassign $p joints P t - - flag
        if {$flag eq "retract"} {
            lassign [lindex $prev 0] - - - a1 a2
            lappend moves {*}[Retract $h $prev $p $f $src [LimitReason $h $a1 $a2 $t]]
        } else {
            lassign [FeedOf $h $prev $p $f] mode value
            lappend moves [Move feed $joints {X Y Z R} $P $t $mode $value $src \
                [expr {$i < $last ? "inserted" : ""}]]
        }
        set prev $p
        incr i
    }
    return $moves
}

# ::fivax::motion::FeedClamp -- Returns feed (mm/min) clamped to the machine's feed_min..feed_max.
proc ::fivax::motion::FeedClamp {h feed} {
    upvar #0 $h S
    expr {$feed < $S(feedMin) ? $S(feedMin) : $feed > $S(feedMax) ? $S(feedMax) : double($feed)}
}

# ::fivax::motion::FeedOf --
#	Returns {feedMode value} for the cutting move from point record a to
#	b at feed f (mm/min): G94 f when no rotary moves or -feedMode direct;
#	else inverse time G93 f/d (d the tip path length in the workpiece frame,
#	at most inverse_time_max), or dpm: G94 with the combined length
#	sqrt(dX^2+dY^2+dZ^2+dA^2+dB^2) (mm, deg) per block time d/f, clamped
#	to feed_min..feed_max.
proc ::fivax::motion::FeedOf {h a b f} {
    upvar #0 $h S
    variable pi
    lassign [lindex $a 0] X0 Y0 Z0 a1 a2
    lassign [lindex $b 0] X1 Y1 Z1 b1 b2
    if {$S(feedMode) eq "direct" || (abs($b1 - $a1) <= 1e-9 && abs($b2 - $a2) <= 1e-9)} {
        return [list 94 $f]
    }
    set d [::fivax::vec::norm [::fivax::vec::sub [lindex $b 1] [lindex $a 1]]]
    if {$S(feedMode) eq "inverse"} {
        return [list 93 [expr {$d * $S(itMax) > $f ? $f / $d : $S(itMax)}]]
    }
    set r2d [expr {180.0 / $pi}]
    set len [expr {sqrt(($X1 - $X0) ** 2 + ($Y1 - $Y0) ** 2 + ($Z1 - $Z0) ** 2
                        + (($b1 - $a1) * $r2d) ** 2 + (($b2 - $a2) * $r2d) ** 2)}]
    if {$d <= 0} {return [list 94 $S(feedMax)]}
    list 94 [FeedClamp $h [expr {$len * $f / $d}]]
}

# ::fivax::motion::words --
#	Returns the block words of move as a flat list of nc address names and
#	values in output units (mm, degrees; a continuous axis whose controller
#	rolls over is written in [0, 360)). Inverse-time feeds use the address
#	F_inv (the writer defines it with more decimals than F).
proc ::fivax::motion::words {h move} {
    upvar #0 $h S
    variable pi
    set write [dict get $move write]
    lassign [dict get $move joints] X Y Z q1 q2
    set feed [expr {[dict get $move kind] eq "feed"}]
    set words [list G_motion $feed]
    if {$feed} {
        lappend words G_feed [dict get $move feedMode]
    }
    foreach name {X Y Z} value [list $X $Y $Z] {
        if {$name in $write} {lappend words $name $value}
    }
    if {"R" in $write} {
        set names [::fivax::machine::rotaryNames $S(machine)]
        set addr [dict create]
        foreach i {1 2} q [list $q1 $q2] {
            set deg [expr {$q * 180.0 / $pi}]
            if {$S(rollover$i)} {
                set deg [expr {fmod(fmod($deg, 360.0) + 360.0, 360.0)}]
            }
            set slot [lsearch -exact $names $S(name$i)]
            dict set addr [lindex {fourth_axis fifth_axis} $slot] $deg
        }
        lappend words fourth_axis [dict get $addr fourth_axis] \
            fifth_axis [dict get $addr fifth_axis]
    }
    if {$feed} {
        lappend words [expr {[dict get $move feedMode] == 93 ? "F_inv" : "F"}] [dict get $move feed]
    }
    return $words
}
