# frames.tcl --
#	(motion) What X Y Z mean in the written blocks, and what that allows:
#	native arcs and tilted work planes.
#
#	Three output frames (spec dialects.md section 0): joint (machine X Y
#	Z, the default), TCP (-tcp: the tool tip in the workpiece frame) and
#	a work plane (an operation whose tool axis stays fixed and off the
#	workpiece Z, on a control with a tilted work plane of its own: the
#	tip in the plane's frame, the rotaries turned by the control). With
#	the rotaries fixed, the map from the tip to X Y Z is a rigid motion in
#	each, so an arc of the CL stays an arc of the blocks: it is written as
#	one when its plane is a coordinate plane of the output frame (G17,
#	G18, G19) and the control has arcs there.
#
#	A work-plane segment (see Route) is held whole until its tool axis
#	changes or something must be written: the memory of one such
#	segment.

oo::define ::fivax::motion::Planner {
    # Returns X Y Z of the written block for joints {X Y Z q1 q2}: machine
    # values, the tool tip (TCP) or the tip in the work plane's frame.
    method Out {joints} {
        if {$S(plane) ne ""} {
            lassign $S(plane) R O
            return [::fivax::plane::toPlane $R $O \
                [lindex [::fivax::kin::forward $S(model) $joints] 0]]
        }
        if {$S(tcp)} {return [lindex [::fivax::kin::forward $S(model) $joints] 0]}
        lrange $joints 0 2
    }

    # Returns point P of the workpiece frame in the output frame, with the
    # rotaries q (a list of two): see Out.
    method OutPoint {P q} {
        if {$S(plane) ne ""} {
            lassign $S(plane) R O
            return [::fivax::plane::toPlane $R $O $P]
        }
        if {$S(tcp)} {return $P}
        ::fivax::kin::position $S(model) $P $q
    }

    # Writes a CL arc from P0 to P1 about center with unit axis n, turning
    # sense (+1 counter-clockwise about n, -1 clockwise) by turns extra
    # full turns, at feed (mm/min), tool axis t (CL frame); returns the
    # move records. A native arc record (see NativeArc) where it can be
    # one, else the arc's points within tol (mm) as cutting moves.
    method arc {P0 P1 center n sense turns t feed src tol} {
        set pre {}
        if {$S(wp) ne "off"} {
            lassign [my Route [list arc $P0 $P1 $center $n $sense $turns $t $feed $src $tol] $t] done pre
            if {$done} {return $pre}
        }
        lassign [my ToWork $P0 $t] P0 tw
        lassign [my ToWork $P1 $t] P1
        lassign [my ToWork $center $n] C nw
        set tw [::fivax::vec::unit $tw]
        set nw [::fivax::vec::unit $nw]
        lassign [my NativeArc $P0 $P1 $C $nw $sense $turns $tw $feed $src] native moves
        set moves [concat $pre $moves]
        if {$native} {return $moves}
        foreach p [::fivax::curve::arc $P0 $P1 $C $nw $sense $turns $tol] {
            lappend moves {*}[my AddWork feed $p $tw $feed $src]
        }
        return $moves
    }

    # Returns {native moves}: native 1 and the moves of a native arc, or
    # native 0 and the moves written before it was found that it cannot
    # be one (the caller writes its points): the -arcs setting is points, the control has no arc in the output
    # frame's plane of the arc, the arc is shorter than two steps of the
    # written X Y Z, the arc makes extra turns, its ends lie
    # at radii more than 0.001 mm apart, the tool axis differs from the
    # last written point's or the arc does not start there. The rotaries
    # stay those of the last point; the record: kind arc (see record.tcl).
    method NativeArc {P0 P1 C n sense turns t feed src} {
        if {$S(arcs) ne "native" || $turns != 0} {return {0 {}}}
        set planes [dict get $S(output) arcPlanes]
        if {![llength $planes]} {return {0 {}}}
        # the radii in the arc's plane (a helix rises along n)
        set u0 [::fivax::vec::sub $P0 $C]
        set u1 [::fivax::vec::sub $P1 $C]
        if {abs([::fivax::vec::norm [::fivax::vec::sub $u0 [::fivax::vec::scale [::fivax::vec::dot $u0 $n] $n]]]
                - [::fivax::vec::norm [::fivax::vec::sub $u1 [::fivax::vec::scale [::fivax::vec::dot $u1 $n] $n]]]) > 0.001} {
            return {0 {}}
        }
        set moves [my flush]
        if {$S(last) eq ""} {return [list 0 $moves]}
        lassign $S(last) jl Pl tl
        if {[::fivax::vec::dist $Pl $P0] > 1e-6
                || [::fivax::vec::angle $tl $t] > 1e-9} {
            return [list 0 $moves]
        }
        set q [lrange $jl 3 4]
        set c [my OutPoint $C $q]
        set axis [::fivax::vec::sub [my OutPoint [::fivax::vec::add $C $n] $q] $c]
        set plane ""
        foreach code {17 18 19} i {2 1 0} {
            if {abs(abs([lindex $axis $i]) - 1.0) < 1e-9 && $code in $planes} {
                set plane $code
                set dir [expr {$sense * [lindex $axis $i] > 0 ? 3 : 2}]
            }
        }
        # a rise below half the output's 0.001 mm (CL points rounded to
        # 4 decimals rise by up to about 1e-4 mm) is a flat arc
        set rise [::fivax::vec::dot [::fivax::vec::sub $P1 $P0] $n]
        if {$plane eq "" || (abs($rise) >= 0.0005 && ![dict get $S(output) helix])} {
            return [list 0 $moves]
        }
        set length [::fivax::curve::arcLength $P0 $P1 $C $n $sense $turns]
        if {$length < 2.0 * $S(length-step)} {
            # its ends may be written alike: a control reads an arc that
            # ends where it starts as a full circle
            return [list 0 $moves]
        }
        set joints [concat [::fivax::kin::position $S(model) $P1 $q] $q]
        set f [my FeedClamp $feed]
        lappend moves [dict merge \
            [my Move arc $joints {X Y Z} $P1 $t [list direct $f $f $length] $src] \
            [dict create start [my Out $jl] center $c plane $plane dir $dir]]
        my Reached [list $joints $P1 $t $t [lindex $S(last) 4]] feed $src
        incr S(moves)
        list 1 $moves
    }

    # Starts watching a new operation for work-plane segments (see Route)
    # unless -workplane is off or the control has no work plane.
    method HoldPlane {} {
        set S(wp) [expr {$S(workplane) ne "off" && [dict get $S(output) plane] ? "free" : "off"}]
        set S(held) ""
        set S(heldAxis) ""
    }

    # Routes CL item (a method call with its arguments) with tool axis t
    # (CL frame); returns {done moves}: done 1 when the item has been
    # taken (held or posted, moves those written), done 0 when the caller
    # posts it itself after moves (the end of a plane, or points written
    # before a new segment is held).
    #
    # A work-plane segment is a run of items with one tool axis off the
    # workpiece Z, entered by a positioning move (or the operation's
    # first item): 3+2 machining. Its items are held until the axis
    # changes at a positioning move or something must be written (see
    # flush); it is then posted in its plane when it cuts (StartPlane),
    # as usual otherwise. An axis change at a cutting move means five-axis
    # machining: the rest of the operation is posted as usual. The state
    # S(wp): off, free (posting as usual, watching), hold, plane; the
    # callers route items only when it is not off.
    method Route {item t} {
        set tw [::fivax::vec::unit [lindex [my ToWork {0.0 0.0 0.0} $t] 1]]
        set positioning [expr {[lindex $item 0] eq "hole"
            || ([lindex $item 0] eq "add" && [lindex $item 1] eq "rapid")}]
        set same [expr {$S(heldAxis) ne "" && [::fivax::vec::angle $tw $S(heldAxis)] < 1e-9}]
        set pre {}
        switch -exact -- $S(wp) {
            hold {
                if {$same} {
                    lappend S(held) $item
                    return {1 {}}
                }
                if {!$positioning} {
                    return [list 0 [my ReleaseHeld off]]
                }
                set pre [my CloseSegment]
            }
            plane {
                if {$same} {return {0 {}}}
                set pre [my EndPlane]
                if {!$positioning} {
                    set S(wp) off
                    return [list 0 $pre]
                }
            }
            free {
                if {$same} {return {0 {}}}
                if {!$positioning && $S(heldAxis) ne ""} {
                    set S(wp) off
                    return {0 {}}
                }
            }
        }
        # a new segment
        set S(heldAxis) $tw
        if {[::fivax::vec::angle $tw {0.0 0.0 1.0}] < 1e-9} {
            set S(wp) free
            return [list 0 $pre]
        }
        # off Z: held; what is pending goes out first
        if {[llength $S(buf)]} {lappend pre {*}[my Commit 1]}
        set S(wp) hold
        set S(held) [list $item]
        list 1 $pre
    }

    # Returns the moves of the held items posted as usual; then watches
    # as state after (free, or off).
    method ReleaseHeld {after} {
        set items $S(held)
        set S(held) ""
        set S(wp) off
        set moves {}
        foreach item $items {lappend moves {*}[my {*}$item]}
        set S(wp) $after
        return $moves
    }

    # Returns the moves of the held segment: in its plane (then ended)
    # when it cuts, as usual otherwise.
    method CloseSegment {} {
        if {![my HeldCuts]} {return [my ReleaseHeld free]}
        concat [my StartPlane] [my EndPlane]
    }

    # Returns 1 when a held item cuts (a feed, an arc or a hole).
    method HeldCuts {} {
        foreach item $S(held) {
            if {[lindex $item 0] in {arc hole} || [lindex $item 1] eq "feed"} {return 1}
        }
        return 0
    }

    # Returns the moves of the held operation in its work plane so far
    # (its tool axis fixed and off Z: called when something must be
    # written): the plane record (see record.tcl), the items with X Y Z in
    # the plane's frame, no rotary words, tip feeds and no linearisation
    # (the rotaries stand still, see Tolerances). The plane stays on for
    # the operation's next items on that axis (see Route, EndPlane). The
    # tool stands at the tool-change height before.
    method StartPlane {} {
        set items $S(held)
        set S(held) ""
        set S(wp) plane
        set t $S(heldAxis)
        set R [::fivax::plane::frame $t]
        set cands [::fivax::motion::Candidates $S(ctx) $t [::fivax::motion::InCone $S(ctx) $t] {} \
            [my ItemSrc [lindex $items 0]]]
        lassign [::fivax::motion::Preferred $S(ctx) $cands] q1
        set moves [list [dict create kind plane matrix $R origin {0.0 0.0 0.0} \
            seq [expr {$q1 < 0 ? -1 : 1}] P {} t {} src "" tag "" note ""]]
        set S(plane) [list $R {0.0 0.0 0.0} $t]
        my Unknown
        foreach item $items {
            lappend moves {*}[my {*}$item]
        }
        concat $moves [my flush]
    }

    # Returns FILE:LINE of a held item (arc: its last argument is a tolerance).
    method ItemSrc {item} {
        lindex $item [expr {[lindex $item 0] eq "arc" ? "end-1" : "end"}]
    }

    # Returns the moves that end the work plane: those held, a retract
    # along the tool axis when the last one cut, and the planeOff record
    # (see record.tcl); the position is unknown afterwards (the next point
    # is approached as a first one).
    method EndPlane {} {
        set S(wp) free
        set moves [my finish]
        set S(plane) ""
        my Unknown
        lappend moves [dict create kind planeOff P {} t {} src $S(lastSrc) tag "" note ""]
    }

    # Returns the moves held (a held segment is posted in its plane when
    # it cuts), then the end of a work plane; watching for work-plane
    # segments goes on (before a tool change).
    method endPlane {} {
        set moves [my flush]
        if {$S(plane) ne ""} {lappend moves {*}[my EndPlane]}
        # the next item starts a new segment
        set S(heldAxis) ""
        return $moves
    }

    # Returns the moves that end an operation (see endPlane).
    method endPath {} {
        set moves [my endPlane]
        set S(wp) off
        return $moves
    }
}
