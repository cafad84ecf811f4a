# feeds.tcl --
#	(motion) Feeds: the machine's feed clamp and the feed of each cutting
#	move (spec/kinematics.md section 8). A move with rotary motion gets
#	inverse time (F = feed / tip path length, 1/min, at most the machine's
#	inverse_time_max: a move of the tip counted, with the worst slowdown,
#	when clamped), or with -feed dpm the combined feed of all axes
#	(mm and degrees) that keeps the block's time; linear moves and -feed
#	direct get the tip feed in mm/min. The feed word is a function of
#	the move and the machine's limits (FeedWord); the planner counts the
#	clamps.

oo::define ::fivax::motion::Planner {
    # Returns feed (mm/min) clamped to the machine's feed_min..feed_max.
    method FeedClamp {feed} {
        ::fivax::motion::Clamp $feed $S(feedMin) $S(feedMax)
    }

    # Returns the cutting moves through the point records pts (the last
    # one the CL point, the others inserted) from the last written point
    # at tip feed (mm/min, clamped here) in feed mode (direct, inverse or
    # dpm, see Tolerances), and adds their rotary travel to
    # the statistics (as Travel: a piece's rotaries turn once, so its
    # travel is that of its ends); a record flagged retract is reached
    # by a retract instead. The feed word of a move: FeedWord.
    # Counts a dwell swing: a move that only turns the rotaries while the
    # tip stays put (at the singular direction, where the path leaves the
    # pole with another azimuth), and the inverse-time clamps.
    method FeedMoves {pts feed mode src} {
        # (the feed changes seldom: its clamp is kept)
        if {$feed != $S(clampIn)} {
            set S(clampIn) $feed
            set S(clampOut) [my FeedClamp $feed]
        }
        set f $S(clampOut)
        set limits [list $S(feedMin) $S(feedMax) $S(itMax)]
        set prev $S(last)
        lassign $prev ja Pa
        set moves {}
        set last [expr {[llength $pts] - 1}]
        incr S(inserted) $last
        set i 0
        foreach p $pts {
            lassign $p jb Pb t - - flag
            lassign $ja - - - a1 a2
            lassign $jb - - - b1 b2
            # (as abs(), see Continues)
            set d1 [expr {$b1 > $a1 ? $b1 - $a1 : $a1 - $b1}]
            set d2 [expr {$b2 > $a2 ? $b2 - $a2 : $a2 - $b2}]
            set S(travel) [expr {$S(travel) + $d1 + $d2}]
            if {$flag eq "retract"} {
                lappend moves {*}[my Retract $prev $p $f $src \
                    [::fivax::motion::LimitReason $S(ctx) $a1 $a2 $t]]
            } else {
                lassign $Pa x0 y0 z0
                lassign $Pb x1 y1 z1
                # (vec::dist written out)
                set d [expr {sqrt(($x1 - $x0) * ($x1 - $x0) + ($y1 - $y0) * ($y1 - $y0)
                    + ($z1 - $z0) * ($z1 - $z0))}]
                if {$d < 1e-9 && $d1 + $d2 > 1e-9} {
                    incr S(dwells)
                    set S(dwellTurn) [expr {$S(dwellTurn) + ($d1 + $d2)}]
                }
                lassign [::fivax::motion::FeedWord $mode $f $d $ja $jb $limits] word slow
                if {$slow > 0} {
                    incr S(clamps)
                    set S(slowdown) [expr {max($S(slowdown), $slow)}]
                }
                lappend moves [my Move feed $jb {X Y Z R} $Pb $t $word $src \
                    [expr {$i < $last ? "inserted" : ""}]]
            }
            set prev $p
            set ja $jb
            set Pa $Pb
            incr i
        }
        return $moves
    }
}

# ::fivax::motion::Clamp -- Returns v clamped to lo..hi (a double inside).
proc ::fivax::motion::Clamp {v lo hi} {
    expr {$v < $lo ? $lo : $v > $hi ? $hi : double($v)}
}

# ::fivax::motion::FeedWord --
#	Returns {word slow} for a cutting move from joints ja to jb ({X Y Z
#	q1 q2}: mm, rad) whose tip travels d mm (workpiece frame) at the tip
#	feed f (mm/min, clamped) in feed mode (direct, inverse, dpm), the
#	machine's limits {feedMin feedMax itMax} (mm/min, 1/min). word is
#	{mode f rate d} (see Move): direct (rate f) when no rotary moves or
#	mode direct; else inverse (rate f/d, at most itMax), or dpm (rate:
#	the combined length sqrt(dX^2+dY^2+dZ^2+dA^2+dB^2) (mm, deg) per
#	block time d/f, clamped to feedMin..feedMax; feedMax for a turn in
#	place). slow: the factor by which an inverse-time clamp makes a move
#	of the tip run slower than programmed, 0 when none (a turn in place,
#	d 0, has no programmed time: a dwell swing).
proc ::fivax::motion::FeedWord {mode f d ja jb limits} {
    lassign $limits feedMin feedMax itMax
    lassign $ja X0 Y0 Z0 a1 a2
    lassign $jb X1 Y1 Z1 b1 b2
    # (as abs(), see Continues)
    if {$mode eq "direct" || (($b1 > $a1 ? $b1 - $a1 : $a1 - $b1) <= 1e-9
            && ($b2 > $a2 ? $b2 - $a2 : $a2 - $b2) <= 1e-9)} {
        return [list [list direct $f $f $d] 0]
    }
    if {$mode eq "inverse"} {
        if {$d * $itMax > $f} {return [list [list inverse $f [expr {$f / $d}] $d] 0]}
        return [list [list inverse $f $itMax $d] [expr {$d > 0 ? $f / $d / $itMax : 0}]]
    }
    if {$d <= 0} {return [list [list dpm $f $feedMax $d] 0]}
    set len [expr {sqrt(($X1 - $X0) ** 2 + ($Y1 - $Y0) ** 2 + ($Z1 - $Z0) ** 2
                        + [::fivax::num::deg [expr {$b1 - $a1}]] ** 2
                        + [::fivax::num::deg [expr {$b2 - $a2}]] ** 2)}]
    list [list dpm $f [Clamp [expr {$len * $f / $d}] $feedMin $feedMax] $d] 0
}
