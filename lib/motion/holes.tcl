# holes.tcl --
#	(motion) Drilling: one hole of a canned cycle. Where the output layer
#	has the cycle and the tool is the machine's Z at the hole's rotaries
#	(always on a table-table machine; on a head with the tilt at its
#	zero), the hole is one record of kind cycle for the control's canned
#	cycle; otherwise the cycle is expanded into rapid, feed and dwell
#	moves along the hole's axis. A hole never vanishes: a cycle that can
#	be neither is an error.
#
#	Distances of a cycle are signed, along the tool axis from the hole
#	top (NX's mom_cycle_*_to): rapid (the R plane), feed (the bottom),
#	retract (where the tool returns; the higher of it and the R plane is
#	the initial level a canned cycle returns to with G98).

namespace eval ::fivax::motion {
    # Expanded peck drilling: the tool rapids back down to this distance
    # (mm) above the depth reached; chip breaking backs off this much.
    variable peckClearance 0.5
    # Cycles that expand into moves: feed out (bore) or rapid out.
    variable expandable {drill drill_dwell drill_deep drill_break_chip bore bore_dwell}
    # Two CL points closer than this (mm) are the same point.
    variable samePoint 1e-6
    namespace export firstHole holeOfFirst samePoint
}

# ::fivax::motion::firstHole --
#	Returns the top of the hole that an operation's first motion (tip P,
#	axis t, CL frame) carries while the cycle dict cycle (see hole) is
#	active, or "" when the motion does not tell. rapidPos is NX's
#	mom_cycle_rapid_to_pos ("" when unset), named 1 when the motion's
#	mom_motion_event names the cycle's hole event. P is the hole's R
#	point when it is rapidPos (NX: "If the first motion is a cycle move,
#	a MOM_initial_move event is generated for the mom_cycle_rapid_to_pos",
#	Post Builder's mom_vars_csv.txt), the top when rapidPos is its R
#	point, else the top when named (a hole event's point is the hole's
#	top).
proc ::fivax::motion::firstHole {P t cycle rapidPos named} {
    set up [::fivax::vec::scale [dict get $cycle rapid] [::fivax::vec::unit $t]]
    if {[llength $rapidPos] == 3} {
        if {[samePoint $P $rapidPos]} {return [::fivax::vec::sub $P $up]}
        if {[samePoint [::fivax::vec::add $P $up] $rapidPos]} {return $P}
    }
    if {$named} {return $P}
    return ""
}

# ::fivax::motion::holeOfFirst --
#	Returns 1 when top (a hole event's point) is the hole of an
#	operation's first motion at P (axis t, cycle as for firstHole) that
#	did not tell its hole: P is the top or the top's R point.
proc ::fivax::motion::holeOfFirst {P t cycle top} {
    set r [::fivax::vec::add $top [::fivax::vec::scale [dict get $cycle rapid] [::fivax::vec::unit $t]]]
    expr {[samePoint $P $top] || [samePoint $P $r]}
}

# ::fivax::motion::samePoint -- Returns 1 when the CL points a and b coincide.
proc ::fivax::motion::samePoint {a b} {
    variable samePoint
    expr {[::fivax::vec::dist $a $b] < $samePoint}
}

oo::define ::fivax::motion::Planner {
    # Returns the move records of one hole: top P and axis t (CL frame),
    # the cycle dict {event rapid feed retract step delay rate} (distances
    # in mm along t from the top, step the peck depth, 0 for none; delay
    # the dwell at the bottom in seconds; rate the feed, mm/min), native
    # 1 when the output layer has this canned cycle, src FILE:LINE. Held
    # CL points are written first.
    # Errors: those of Candidates; {FIVAX MOTION CYCLE} for a cycle that
    # can neither be native nor expanded here.
    method hole {P t cycle native src} {
        namespace upvar ::fivax::motion expandable expandable
        set pre {}
        if {$S(wp) ne "off"} {
            lassign [my Route [list hole $P $t $cycle $native $src] $t] done pre
            if {$done} {return $pre}
        }
        set moves [concat $pre [my flush]]
        lassign [my ToWork $P $t] P t
        set t [::fivax::vec::unit $t]
        incr S(points)
        set ctx $S(ctx)
        set refs [my LastRefs]
        set cands [::fivax::motion::Candidates $ctx $t [::fivax::motion::InCone $ctx $t] $refs $src]
        if {[my Fresh rapid]} {
            lassign [::fivax::motion::Preferred $ctx $cands] q1 q2 lab
        } else {
            lassign [::fivax::motion::Nearest [lrange $refs 0 1] $cands] q1 q2 lab
        }
        set S(pathStart) 0
        dict with cycle {}
        set rec(initial) [my HolePoint $P $t [expr {max($rapid, $retract)}] $q1 $q2 $lab]
        set rec(r) [my HolePoint $P $t $rapid $q1 $q2 $lab]
        set rec(bottom) [my HolePoint $P $t $feed $q1 $q2 $lab]
        set native [expr {$native && [my AlongOutZ $t [lrange [lindex $rec(bottom) 0] 3 4]]}]
        if {!$native && $event ni $expandable} {
            ::fivax::Fail MOTION CYCLE "$src: a $event cycle with the tool not along the\
                machine's Z axis cannot be expanded into moves on [dict get $ctx name]"
        }
        set f [my FeedClamp $rate]
        set zi [lindex [my Out [lindex $rec(initial) 0]] 2]
        if {$native && [my NextHole $q1 $q2 $zi]} {
            # the canned cycle goes on: it moves to the hole at the last
            # hole's initial level, the point of the hole's axis where the
            # output Z (along t: see AlongOutZ) is that level
            set up [expr {[lindex $S(lastHole) 2] - $zi}]
            set zi [lindex $S(lastHole) 2]
            set new {}
            set rec(initial) [my HolePoint $P $t [expr {max($rapid, $retract) + $up}] $q1 $q2 $lab]
        } else {
            set new [my Approach $rec(initial) $src]
        }
        if {$native} {
            lappend new [dict merge [my Move cycle [lindex $rec(bottom) 0] {X Y Z} \
                [lindex $rec(bottom) 1] $t [list direct $f $f 0.0] $src] \
                [dict create event $event r [lindex [my Out [lindex $rec(r) 0]] 2] initial $zi \
                    step $step delay $delay]]
        } else {
            lappend new {*}[my Expand $event rec $t $step $delay $f $src]
        }
        my Travel $new
        my Reached $rec(initial) rapid $src [expr {$native ? [list $q1 $q2 $zi] : ""}]
        incr S(moves) [llength $new]
        concat $moves $new
    }

    # Returns 1 when a canned cycle's next hole needs no approach: the
    # last written record was a canned-cycle hole with rotaries q1 q2,
    # and its initial level is not below zi (Z of the output frame: the
    # machine's, the workpiece's in TCP mode, the work plane's).
    method NextHole {q1 q2 zi} {
        if {$S(lastHole) eq ""} {return 0}
        lassign $S(lastHole) p1 p2 z
        expr {abs($p1 - $q1) < 1e-9 && abs($p2 - $q2) < 1e-9 && $zi <= $z + 1e-9}
    }

    # Returns 1 when the tool axis t (workpiece frame) at rotaries q is
    # the Z axis of the output frame, so that a canned cycle drills along
    # it: the machine's Z (joint mode), the workpiece Z (TCP), the plane's
    # Z (a work plane, always).
    method AlongOutZ {t q} {
        if {$S(plane) ne ""} {return 1}
        if {$S(tcp)} {return [expr {[::fivax::vec::angle $t {0.0 0.0 1.0}] < 1e-9}]}
        set axisZ [::fivax::kin::toolInMachine $S(model) $q]
        expr {abs([lindex $axisZ 2] - 1.0) < 1e-9}
    }

    # Returns the point record of the point d along unit t from P with
    # rotaries q1 q2 on branch lab.
    method HolePoint {P t d q1 q2 lab} {
        ::fivax::motion::Record $S(ctx) [::fivax::vec::add $P [::fivax::vec::scale $d $t]] \
            $t $q1 $q2 $lab [::fivax::motion::InCone $S(ctx) $t]
    }

    # Returns the rapid moves to point record b from the last written point.
    method Approach {b src} {
        if {$S(last) eq ""} {return [my First rapid $b 0.0 $src]}
        my Transfer $S(last) $b $src
    }

    # Returns the moves of a cycle expanded along unit axis t through the
    # point records in the array named recVar (initial, r, bottom): rapid
    # to the R plane, feed to the bottom (in pecks of step for the deep
    # and chip-breaking drills), dwell delay seconds, then out: bores feed
    # back to the R plane, all rapid to the initial level.
    method Expand {event recVar t step delay f src} {
        namespace upvar ::fivax::motion peckClearance clear
        upvar 1 $recVar rec
        set feed [list direct $f $f 0.0]
        set moves {}
        set top [lindex $rec(r) 1]
        set depth [::fivax::vec::dot [::fivax::vec::sub [lindex $rec(bottom) 1] $top] $t]
        lassign $rec(r) jr Pr
        lappend moves [my Move rapid $jr {X Y Z} $Pr $t {} $src]
        if {$step > 0 && $event in {drill_deep drill_break_chip}} {
            # depth is negative: peck downwards from the R plane
            set d 0.0
            while {$d - $step > $depth + 1e-9} {
                set d [expr {$d - $step}]
                lappend moves [my HoleMove feed $top $t $d $feed $src]
                if {$event eq "drill_deep"} {
                    lappend moves [my HoleMove rapid $top $t 0.0 {} $src]
                    lappend moves [my HoleMove rapid $top $t [expr {$d + $clear}] {} $src]
                } else {
                    lappend moves [my HoleMove rapid $top $t [expr {$d + $clear}] {} $src]
                }
            }
        }
        lassign $rec(bottom) jb Pb
        lappend moves [my Move feed $jb {X Y Z} $Pb $t $feed $src]
        if {$delay > 0} {
            lappend moves [dict merge [my Move dwell $jb {} {} {} {} $src] [dict create seconds $delay]]
        }
        if {$event in {bore bore_dwell}} {
            lappend moves [my Move feed $jr {X Y Z} $Pr $t $feed $src]
        }
        lassign $rec(initial) ji Pi
        lappend moves [my Move rapid $ji {X Y Z} $Pi $t {} $src]
    }

    # Returns a move of kind to the point d along unit t from the point
    # top, with the rotaries of the last hole record, feed as for Move.
    method HoleMove {kind top t d feed src} {
        upvar 1 rec rec
        lassign [lindex $rec(r) 0] - - - q1 q2
        set p [my HolePoint $top $t $d $q1 $q2 [lindex $rec(r) 4]]
        my Move $kind [lindex $p 0] {X Y Z} [lindex $p 1] $t $feed $src
    }
}
