# feeds.tcl --
#	(motion) Feeds: the machine's feed clamp and the feed of each cutting
#	move (spec/kinematics.md section 8). A move with rotary motion gets
#	inverse time (F = feed / tip path length, 1/min, at most the machine's
#	inverse_time_max: counted, with the worst slowdown, when clamped), or with -feed dpm the combined feed of all axes
#	(mm and degrees) that keeps the block's time; linear moves and -feed
#	direct get the tip feed in mm/min.

oo::define ::fivax::motion::Planner {
    # Returns feed (mm/min) clamped to the machine's feed_min..feed_max.
    method FeedClamp {feed} {
        expr {$feed < $S(feedMin) ? $S(feedMin) : $feed > $S(feedMax) ? $S(feedMax) : double($feed)}
    }

    # Returns {mode feed rate tip} for the cutting move from point record
    # a to b at tip feed f (mm/min): mode direct (rate f) when no rotary
    # moves or -feed direct; else inverse (rate f/d, d the tip path length
    # in the workpiece frame, at most inverse_time_max), or dpm (rate: the
    # combined length sqrt(dX^2+dY^2+dZ^2+dA^2+dB^2) (mm, deg) per block
    # time d/f, clamped to feed_min..feed_max).
    # Counts a dwell swing: a move that only turns the rotaries while the
    # tip stays put (at the singular direction, where the path leaves the
    # pole with another azimuth).
    method FeedOf {a b f} {
        lassign $a ja Pa
        lassign $b jb Pb
        lassign $ja X0 Y0 Z0 a1 a2
        lassign $jb X1 Y1 Z1 b1 b2
        # (vec::dist written out)
        lassign $Pb x1 y1 z1
        lassign $Pa x0 y0 z0
        set x [expr {$x1 - $x0}]
        set y [expr {$y1 - $y0}]
        set z [expr {$z1 - $z0}]
        set d [expr {sqrt($x * $x + $y * $y + $z * $z)}]
        # (as abs(), see Cost)
        set d1 [expr {$b1 > $a1 ? $b1 - $a1 : $a1 - $b1}]
        set d2 [expr {$b2 > $a2 ? $b2 - $a2 : $a2 - $b2}]
        if {$d < 1e-9 && $d1 + $d2 > 1e-9} {
            incr S(dwells)
            set S(dwellTurn) [expr {$S(dwellTurn) + ($d1 + $d2)}]
        }
        if {$S(feed) eq "direct" || ($d1 <= 1e-9 && $d2 <= 1e-9)} {
            return [list direct $f $f $d]
        }
        if {$S(feed) eq "inverse"} {
            if {$d * $S(itMax) > $f} {return [list inverse $f [expr {$f / $d}] $d]}
            # clamped: the move runs slower than programmed
            incr S(clamps)
            if {$d > 0} {
                set S(slowdown) [expr {max($S(slowdown), $f / $d / $S(itMax))}]
            }
            return [list inverse $f $S(itMax) $d]
        }
        if {$d <= 0} {return [list dpm $f $S(feedMax) $d]}
        set len [expr {sqrt(($X1 - $X0) ** 2 + ($Y1 - $Y0) ** 2 + ($Z1 - $Z0) ** 2
                            + [::fivax::num::deg [expr {$b1 - $a1}]] ** 2
                            + [::fivax::num::deg [expr {$b2 - $a2}]] ** 2)}]
        list dpm $f [my FeedClamp [expr {$len * $f / $d}]] $d
    }
}
