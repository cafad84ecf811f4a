# moves.tcl --
#	(motion) From chosen rotary values to move records: the first move of
#	a program, rapid transfers to a new orientation, retract, reposition
#	and re-engage where no cutting move can continue, and the statistics
#	of what was written; the path state (the last written point), which
#	only Reached and Unknown set. Inside the planner a point record is
#	the list {joints P t act branch ?retract?}: joints {X Y Z q1 q2} (mm, rad, chain
#	order), the CL point P, t, the tool axis act the rotaries give, and
#	the branch of the solution.

# ::fivax::motion::Record --
#	Returns the point record of CL point P, t with rotaries q1 q2 on branch
#	lab in context ctx; cone is InCone of t. act is t itself outside the
#	singular cone, where candidates are exact. Rotaries are rounded to the
#	output resolution first, so that X Y Z absorb the rounding.
proc ::fivax::motion::Record {ctx P t q1 q2 lab cone} {
    set q [Quantize [dict get $ctx step] $q1 $q2]
    set joints [list {*}[::fivax::kin::position [dict get $ctx model] $P $q] {*}$q]
    if {!$cone} {return [list $joints $P $t $t $lab]}
    list $joints $P $t [lindex [::fivax::kin::forward [dict get $ctx model] $joints] 1] $lab
}

oo::define ::fivax::motion::Planner {
    # Writes CL point (kind P t feed src; cone: InCone of t) with rotaries
    # {q1 q2} on branch lab after the last written point and returns its
    # moves: the rapid sequence, the linearised cutting moves, or a
    # retract, reposition and re-engage.
    method Emit {kind P t feed src cone q1 q2 lab} {
        set b [::fivax::motion::Record $S(ctx) $P $t $q1 $q2 $lab $cone]
        if {$cone} {incr S(holds)}
        if {$S(last) eq ""} {
            set moves [my Travel [my First $kind $b $feed $src]]
        } elseif {$kind eq "rapid"} {
            set moves [my Travel [my Transfer $S(last) $b $src]]
        } else {
            lassign $S(last) ja - ta - al
            lassign $ja - - - a1 a2
            if {[::fivax::motion::Continues $S(ms1) $S(ms2) $a1 $a2 $al $q1 $q2 $lab]} {
                # (as abs(), see Continues)
                if {($q2 > $a2 ? $q2 - $a2 : $a2 - $q2) > $S(swingRad)} {my CountSwing $ta $t}
                # (FeedMoves adds the travel of its moves itself)
                lassign [my Tolerances] tol atol mode
                set moves [my FeedMoves [my Linearise $S(last) $b $tol $atol 0 $src] $feed $mode $src]
            } else {
                set moves [my Travel [my Retract $S(last) $b [my FeedClamp $feed] $src \
                    [::fivax::motion::LimitReason $S(ctx) $a1 $a2 $t]]]
            }
        }
        my Reached $b $kind $src
        incr S(moves) [llength $moves]
        return $moves
    }

    # --- the path state: the last written point ----------------------------
    # S(last): its point record ("" when the position is unknown: the next
    # point is approached as a first one); S(lastKind): the kind of the CL
    # item that reached it (rapid or feed); S(lastSrc): its FILE:LINE;
    # S(lastHole): {q1 q2 z} when it is a canned-cycle hole's initial level
    # (see NextHole), else "". Only Reached and Unknown set them.

    # Records point record b as the last written point, reached by a CL
    # item of kind (rapid|feed) from src; hole as S(lastHole).
    method Reached {b kind src {hole ""}} {
        set S(last) $b
        set S(lastKind) $kind
        set S(lastSrc) $src
        set S(lastHole) $hole
    }

    # Forgets the last written point's position (a tool change, the end of
    # the program or of a work plane): the next point is approached as a
    # first one. Its kind and src stay (the planeOff record names src).
    method Unknown {} {
        set S(last) ""
        set S(lastHole) ""
    }

    # Returns {tol atol mode} for the next cutting move: the tip
    # tolerance (mm, 0: no linearisation), the axis tolerance (rad, Inf:
    # not checked) and the feed mode (direct, inverse, dpm). In a work
    # plane the rotaries stand still and the tip moves straight: no
    # linearisation, tip feeds.
    method Tolerances {} {
        if {$S(plane) ne ""} {return {0.0 Inf direct}}
        list $S(tol) $S(atolCheck) $S(feed)
    }

    # Returns a move record (see record.tcl) of the given kind to joints
    # {X Y Z q1 q2}, writing the axes in write (X Y Z, and last R for both
    # rotaries); feed is {mode feed rate tip} or {} for rapids.
    # X Y Z are those of the output frame (see Out); in a work plane no
    # rotary is written, and as the written X Y Z are no machine values
    # there (the checker reads only those), the machine position is
    # checked against the travel here: {FIVAX MACHINE LIMIT} naming src.
    method Move {kind joints write P t feed src {tag ""} {note ""}} {
        lassign $joints X Y Z q1 q2
        if {$S(plane) ne ""} {
            ::fivax::machine::checkLimits $S(machine) [list X $X Y $Y Z $Z] $src
        }
        # (in the joint frame X Y Z are the machine's, see Out)
        if {$S(plane) ne "" || $S(tcp)} {lassign [my Out $joints] X Y Z}
        if {[lindex $write end] eq "R"} {
            set write [lrange $write 0 end-1]
            if {$S(plane) eq ""} {lappend write $S(n1) $S(n2)}
        }
        if {![llength $feed]} {set feed {direct 0 0 0}}
        lassign $feed mode f rate tip
        # (a list of distinct keys and values is that dict, and cheaper to
        # build than with dict create)
        list kind $kind axes [list X $X Y $Y Z $Z $S(n1) $q1 $S(n2) $q2] write $write \
            feed $f mode $mode rate $rate tip $tip P $P t $t src $src tag $tag note $note
    }

    # Returns the moves to the very first point b (a point record) of kind
    # rapid or feed, from the tool-change height with unknown X Y: the
    # rotaries turn first (at that height), then the tool reaches the
    # point clearance above b along its tool axis (Reach), and goes down
    # that axis onto b (a feed at the entry feed: never a first move that
    # feeds from an unknown position).
    method First {kind b feed src} {
        set a [my Above $b]
        set moves [list [my Move rapid [lindex $a 0] R {} {} {} $src] {*}[my Reach $a $src]]
        if {$kind eq "feed"} {return [lappend moves [my Entry $b $feed $src]]}
        lassign $b joints P t
        lappend moves [my Move rapid $joints {X Y Z R} $P $t {} $src]
    }

    # Returns the rapid moves from the tool-change height (X Y unknown,
    # the rotaries already those of point record a) to a, each above the
    # stock: in a work plane along the tool axis (its Z) first, then
    # across (X Y); with TCP in one block (the tip's X Y Z, with which the
    # control switches TCP and length on); in machine coordinates across
    # at that height (X Y), then down (Z). The move onto a is tagged
    # approach.
    method Reach {a src} {
        lassign $a joints P t
        set onto [my Move rapid $joints {X Y Z} $P $t {} $src approach]
        if {$S(plane) ne ""} {
            return [list [my Move rapid $joints Z {} {} {} $src] [dict set onto write {X Y}]]
        }
        if {$S(tcp)} {return [list $onto]}
        list [my Move rapid $joints {X Y} {} {} {} $src] $onto
    }

    # Returns the point record clearance above point record b along its
    # actual tool axis, with b's rotaries.
    method Above {b} {
        lassign $b jb Pb tb actb lab
        set Pe [::fivax::vec::add $Pb [::fivax::vec::scale $S(clearance) $actb]]
        set je [concat [::fivax::kin::position $S(model) $Pe [lrange $jb 3 4]] [lrange $jb 3 4]]
        list $je $Pe $tb $actb $lab
    }

    # Returns the feed move down to point record b at the entry feed: the
    # machine's entry_feed, else half the cutting feed (mm/min).
    method Entry {b feed src} {
        set f [my FeedClamp [expr {$S(entryFeed) ne "" ? $S(entryFeed) : 0.5 * $feed}]]
        lassign $b jb Pb tb
        my Move feed $jb {X Y Z R} $Pb $tb [list direct $f $f $S(clearance)] $src reengage
    }

    # Returns the rapid moves from point record a to point record b. A
    # change of orientation is sequenced safely: Z up to the safe height
    # (safe_z, else clearance above the higher end), rotate, X Y, then
    # down: onto b itself when above is 0 (b is a clearance point), else
    # onto the point clearance above b and from there down b's tool axis.
    method Transfer {a b src {above 1}} {
        lassign $b joints P t
        set final [my Move rapid $joints {X Y Z R} $P $t {} $src]
        lassign [lindex $a 0] pX pY pZ p1 p2
        lassign $joints X Y Z q1 q2
        if {abs($q1 - $p1) < 1e-9 && abs($q2 - $p2) < 1e-9} {return [list $final]}
        set down [list $final]
        if {$above} {
            lassign [my Above $b] jc Pc
            lassign $jc X Y Z
            set down [list [my Move rapid $jc {X Y Z} $Pc $t {} $src approach] $final]
        }
        set safe $S(safeZ)
        if {$safe eq ""} {set safe [expr {max($pZ, $Z) + $S(clearance)}]}
        list [my Move rapid [list $pX $pY $safe $p1 $p2] Z {} {} {} $src] \
            [my Move rapid [list $pX $pY $safe $q1 $q2] R {} {} {} $src] \
            [my Move rapid [list $X $Y $safe $q1 $q2] {X Y} {} {} {} $src] {*}$down
    }

    # Returns the moves from point record a to point record b when no
    # cutting move can get there: retract along the tool axis by the
    # clearance, rapid to the new configuration above b (Transfer), and
    # re-engage along b's tool axis at the entry feed (f: the cutting
    # feed, mm/min). reason goes into the note.
    method Retract {a b f src reason} {
        incr S(retracts)
        lassign [my Above $a] jr Pr - ta
        set moves [list [my Move retract $jr {X Y Z} $Pr $ta {} $src "" $reason]]
        lappend moves {*}[my Transfer [my Above $a] [my Above $b] $src 0]
        lappend moves [my Entry $b $f $src]
    }

    # Adds the rotary travel of moves (records made by Move: axes X Y Z,
    # then the rotaries) from the last written point to the statistics;
    # returns moves.
    method Travel {moves} {
        set from [expr {$S(last) ne ""}]
        if {$from} {lassign [lindex $S(last) 0] - - - p1 p2}
        foreach move $moves {
            lassign [dict get $move axes] - - - - - - - q1 - q2
            if {$from} {
                # (as abs(), see Continues)
                set S(travel) [expr {$S(travel) + ($q1 > $p1 ? $q1 - $p1 : $p1 - $q1)
                    + ($q2 > $p2 ? $q2 - $p2 : $p2 - $q2)}]
            }
            set from 1
            set p1 $q1
            set p2 $q2
        }
        return $moves
    }

    # Counts a singular swing: called when the azimuth of a cutting move
    # turns by more than -swing, counts it when the CL axis turns from ta
    # to tb by less than that.
    method CountSwing {ta tb} {
        if {[::fivax::vec::angle $ta $tb] < $S(swingRad)} {incr S(swings)}
    }
}
