# motion.tcl --
#	The motion planner: turns CL points (tool tip and axis in the workpiece
#	frame) into machine moves: picks the rotary solution (first-point
#	preference, then continuity), holds the azimuth at the singular
#	direction, keeps values inside the axis limits, sequences rapids to a
#	new orientation safely and computes feeds. Angles in radians.
#	See spec/kinematics.md sections 6 to 8.

namespace eval ::fivax::motion {
    namespace export create setTool setFrame add flush stats
    variable seq 0
    variable pi 3.141592653589793
}

# ::fivax::motion::create --
#	Returns a planner for machine (a fivax::machine dict). Options:
#	-tableOffset {x y z} (overrides the machine's), -msys 0|1 (express CL
#	data in the MSYS frame), -feedMode inverse|direct (moves with rotary
#	motion get G93 inverse time, or plain mm/min).
proc ::fivax::motion::create {machine args} {
    variable seq
    set h ::fivax::motion::plan[incr seq]
    upvar #0 $h S
    array set S {tableOffset "" msys 0 feedMode inverse}
    foreach {opt val} $args {
        switch -- $opt {
            -tableOffset - -msys - -feedMode {set S([string range $opt 1 end]) $val}
            default {::fivax::Fail MOTION OPTION "bad option \"$opt\": must be -tableOffset, -msys or -feedMode"}
        }
    }
    set S(machine) $machine
    set S(frame) {}
    set S(prev) {}
    set S(prevP) {}
    set S(prevT) {}
    array set S {points 0 moves 0 travel 0.0}
    setTool $h [dict get $machine tool_length]
    return $h
}

# ::fivax::motion::setTool -- Rebuilds the kinematic model for a tool of length len (mm).
proc ::fivax::motion::setTool {h len} {
    upvar #0 $h S
    if {$S(tableOffset) eq ""} {
        set S(model) [::fivax::kin::model $S(machine) $len]
    } else {
        set S(model) [::fivax::kin::model $S(machine) $len $S(tableOffset)]
    }
    set S(toolLength) $len
    set S(axes) [dict get $S(machine) chain]
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

# ::fivax::motion::add --
#	Adds one CL point: kind rapid|feed, tip P and unit axis t (CL frame),
#	feed (mm/min, ignored for rapids), src (FILE:LINE for messages).
#	Returns the list of moves ready to be written (see flush).
proc ::fivax::motion::add {h kind P t feed src} {
    upvar #0 $h S
    lassign [ToWork $h $P $t] P t
    incr S(points)
    set q [Choose $h $t $src]
    set xyz [::fivax::kin::position $S(model) $P $q]
    set joints [concat $xyz $q]
    set moves [expr {$kind eq "rapid"
        ? [RapidMoves $h $joints $P $t $src]
        : [list [FeedMove $h $joints $P $t $feed $src]]}]
    if {$S(prev) ne ""} {
        set S(travel) [expr {$S(travel) + abs([lindex $q 0] - [lindex $S(prev) 3])
            + abs([lindex $q 1] - [lindex $S(prev) 4])}]
    }
    set S(prev) $joints
    set S(prevP) $P
    set S(prevT) $t
    incr S(moves) [llength $moves]
    return $moves
}

# ::fivax::motion::flush --
#	Returns the moves still held (none in this planner: it writes as it
#	goes). A move is a dict: kind rapid|feed|position, joints {X Y Z q1 q2}
#	(mm, rad, chain order), write (which of X Y Z R to write: R = rotaries),
#	P and t (the CL target, empty for positioning moves), feedMode 93|94,
#	feed (mm/min or 1/min), src.
proc ::fivax::motion::flush {h} {
    return {}
}

# ::fivax::motion::stats -- Returns a dict: points, moves, travel (deg of rotary travel).
proc ::fivax::motion::stats {h} {
    upvar #0 $h S
    variable pi
    dict create points $S(points) moves $S(moves) \
        travel [expr {$S(travel) * 180.0 / $pi}]
}

# ::fivax::motion::Choose --
#	Returns the rotary values {q1 q2} for axis t: among the in-limit
#	candidates, the first point follows the machine's preference, later
#	points the smallest change of the tilt axis, then of the azimuth.
#	At the singular direction the azimuth is held (spec section 6).
proc ::fivax::motion::Choose {h t src} {
    upvar #0 $h S
    lassign [::fivax::kin::orientations $S(model) $t] status sols
    if {$status eq "unreachable"} {
        ::fivax::Fail MOTION UNREACHABLE "$src: tool axis ([AxisText $t]) unreachable on [dict get $S(machine) name]"
    }
    if {$status eq "singular"} {
        set hold [expr {$S(prev) eq "" ? 0.0 : [lindex $S(prev) 4]}]
        set sols [list [list [lindex $sols 0 0] $hold]]
    }
    set cands [Candidates $h $sols]
    if {![llength $cands]} {
        ::fivax::Fail MOTION LIMIT "$src: tool axis ([AxisText $t]) needs a rotary value outside the limits of [dict get $S(machine) name]"
    }
    if {$S(prev) eq ""} {
        return [Preferred $h $cands]
    }
    Nearest [lrange $S(prev) 3 4] $cands
}

# ::fivax::motion::AxisText -- Returns i,j,k rounded for messages.
proc ::fivax::motion::AxisText {t} {
    join [lmap c $t {format %.6g $c}] ,
}

# ::fivax::motion::Candidates --
#	Returns every {q1 q2} equivalent (mod 360 deg per axis) to one of sols
#	that lies inside the axis limits; continuous axes keep the value nearest
#	the previous one (unwound).
proc ::fivax::motion::Candidates {h sols} {
    upvar #0 $h S
    variable pi
    set out {}
    foreach sol $sols {
        set lists {}
        foreach q $sol axis $S(axes) i {3 4} {
            set vals {}
            if {[dict get $axis continuous]} {
                set ref [expr {$S(prev) eq "" ? 0.0 : [lindex $S(prev) $i]}]
                set k [expr {round(($ref - $q) / (2.0 * $pi))}]
                set v [expr {$q + 2.0 * $pi * $k}]
                if {$v >= [dict get $axis min] - 1e-9 && $v <= [dict get $axis max] + 1e-9} {
                    lappend vals $v
                }
            } else {
                set min [dict get $axis min]
                set max [dict get $axis max]
                set k [expr {ceil(($min - $q) / (2.0 * $pi) - 1e-9)}]
                for {set v [expr {$q + 2.0 * $pi * $k}]} {$v <= $max + 1e-9} \
                    {set v [expr {$v + 2.0 * $pi}]} {
                    lappend vals [expr {min(max($v, $min), $max)}]
                }
            }
            lappend lists $vals
        }
        foreach a [lindex $lists 0] {
            foreach b [lindex $lists 1] {lappend out [list $a $b]}
        }
    }
    return $out
}

# ::fivax::motion::Preferred --
#	Returns the first-point choice: candidates matching every axis's sign
#	preference if any do, then the smallest tilt, then the smallest azimuth.
proc ::fivax::motion::Preferred {h cands} {
    upvar #0 $h S
    set ok {}
    foreach c $cands {
        set match 1
        foreach q $c axis $S(axes) {
            set p [dict get $axis prefer]
            if {($p > 0 && $q < -1e-12) || ($p < 0 && $q > 1e-12)} {set match 0}
        }
        if {$match} {lappend ok $c}
    }
    if {![llength $ok]} {set ok $cands}
    Nearest {0.0 0.0} $ok
}

# ::fivax::motion::Nearest --
#	Returns the candidate with the smallest change of q1 from ref, ties
#	(within 1e-9 rad) broken by the smallest change of q2.
proc ::fivax::motion::Nearest {ref cands} {
    lassign $ref r1 r2
    set best {}
    foreach c $cands {
        lassign $c a b
        set d1 [expr {abs($a - $r1)}]
        set d2 [expr {abs($b - $r2)}]
        if {$best eq "" || $d1 < $b1 - 1e-9 || (abs($d1 - $b1) <= 1e-9 && $d2 < $b2)} {
            set best $c
            set b1 $d1
            set b2 $d2
        }
    }
    return $best
}

# ::fivax::motion::FeedMove --
#	Returns the move to joints at feed: G94 mm/min when only linear axes
#	move, G93 inverse time (feed / tip path length) when a rotary moves.
proc ::fivax::motion::FeedMove {h joints P t feed src} {
    upvar #0 $h S
    set mode 94
    set f $feed
    if {$S(prev) ne "" && $S(feedMode) eq "inverse"} {
        lassign $S(prev) - - - p1 p2
        lassign $joints - - - q1 q2
        if {abs($q1 - $p1) > 1e-9 || abs($q2 - $p2) > 1e-9} {
            set mode 93
            set d [::fivax::vec::norm [::fivax::vec::sub $P $S(prevP)]]
            set fmax [dict get $S(machine) inverse_time_max]
            set f [expr {$d > 0 ? min($feed / $d, $fmax) : $fmax}]
        }
    }
    dict create kind feed joints $joints write {X Y Z R} P $P t $t \
        feedMode $mode feed $f src $src
}

# ::fivax::motion::RapidMoves --
#	Returns the rapid moves to joints. A change of orientation is
#	sequenced safely: Z up to the safe height, rotate, X Y, then Z down.
proc ::fivax::motion::RapidMoves {h joints P t src} {
    upvar #0 $h S
    set final [dict create kind rapid joints $joints write {X Y Z R} P $P t $t \
        feedMode 94 feed 0 src $src]
    lassign $joints X Y Z q1 q2
    if {$S(prev) eq ""} {
        return [list [Position [concat $X $Y $Z $q1 $q2] R $src] \
            [Position $joints {X Y} $src] $final]
    }
    lassign $S(prev) pX pY pZ p1 p2
    if {abs($q1 - $p1) < 1e-9 && abs($q2 - $p2) < 1e-9} {return [list $final]}
    set safe [dict get $S(machine) safe_z]
    if {$safe eq ""} {
        set safe [expr {max($pZ, $Z) + [dict get $S(machine) clearance]}]
    }
    list [Position [list $pX $pY $safe $p1 $p2] Z $src] \
        [Position [list $pX $pY $safe $q1 $q2] R $src] \
        [Position [list $X $Y $safe $q1 $q2] {X Y} $src] $final
}

# ::fivax::motion::Position -- Returns a rapid positioning move writing only the axes in write.
proc ::fivax::motion::Position {joints write src} {
    dict create kind position joints $joints write $write P {} t {} \
        feedMode 94 feed 0 src $src
}

# ::fivax::motion::outputNames --
#	Returns the rotary axis names in output order (alphabetical: the 4th
#	axis word, then the 5th).
proc ::fivax::motion::outputNames {h} {
    upvar #0 $h S
    lsort [lmap axis $S(axes) {dict get $axis name}]
}

# ::fivax::motion::words --
#	Returns the block words of move as a flat list of nc address names and
#	values in output units (mm, degrees; a continuous axis whose controller
#	rolls over is written in [0, 360)).
proc ::fivax::motion::words {h move} {
    upvar #0 $h S
    variable pi
    set write [dict get $move write]
    lassign [dict get $move joints] X Y Z q1 q2
    set words [list G_motion [expr {[dict get $move kind] eq "feed" ? 1 : 0}]]
    if {[dict get $move kind] eq "feed"} {
        lappend words G_feed [dict get $move feedMode]
    }
    foreach name {X Y Z} value [list $X $Y $Z] {
        if {$name in $write} {lappend words $name $value}
    }
    if {"R" in $write} {
        set names [outputNames $h]
        set addr [dict create]
        foreach axis $S(axes) q [list $q1 $q2] {
            set deg [expr {$q * 180.0 / $pi}]
            if {[dict get $axis continuous] && [dict get $axis rollover]} {
                set deg [expr {fmod(fmod($deg, 360.0) + 360.0, 360.0)}]
            }
            set slot [lsearch -exact $names [dict get $axis name]]
            dict set addr [lindex {fourth_axis fifth_axis} $slot] $deg
        }
        lappend words fourth_axis [dict get $addr fourth_axis] \
            fifth_axis [dict get $addr fifth_axis]
    }
    if {[dict get $move kind] eq "feed"} {
        lappend words F [dict get $move feed]
    }
    return $words
}
