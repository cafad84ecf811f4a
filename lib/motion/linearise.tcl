# linearise.tcl --
#	(motion) Linearisation (spec/kinematics.md section 7): between two
#	blocks the controller interpolates the joints linearly and the tool tip
#	leaves the straight CL segment. Each cutting move is checked at the
#	quarter points of that interpolation (tip against the straight segment,
#	axis against the great circle) and CL points are inserted (position
#	linear, axis slerp) until within -tol / -atol. Where a move leaves the
#	singular cone with another azimuth, the azimuth turns first while the
#	tip dwells.
#
#	The tolerance holds for the values written, as the post's check and
#	tools/verify.tcl measure them. The rotaries of a point record are
#	already those written (rounded to -angle-step, X Y Z computed for
#	them); X Y Z are rounded by the output to -length-step. So each move
#	is measured with its ends' X Y Z as written (Written): the quarter
#	points are those the control interpolates. The budget this takes from
#	-tol: forward kinematics moves the tip rigidly with X Y Z (a
#	translation, turned by the table axes on table machines), so at the
#	ends the tip is within h = sqrt(3)/2 step of the CL point (each axis
#	off by at most half a step), and inside the move the rounding's
#	contribution, interpolated linearly between the ends, is at most h
#	too: a move whose exact joints keep the tip within tol - h keeps it
#	within tol when written. The bound (kin interpolationBound) takes h as
#	its end error ep; the quarter points are measured exactly.

oo::define ::fivax::motion::Planner {
    # Returns the point records after a up to and including b such that
    # the linear joint interpolation between consecutive ones, with X Y Z
    # as written (Written), keeps the tip within tol (mm; 0: none
    # inserted) of their straight segment and the axis within atol (rad;
    # Inf: not checked) of the great circle of their actual axes (act),
    # checked at the quarter points. An error e splits the move into about sqrt(e / tol)
    # pieces (the error of a smooth move shrinks with the square of its
    # length), each checked in turn, at most maxDepth levels deep and into
    # at most maxPieces pieces in all (a move of absurd length would
    # otherwise take 16^maxDepth of them). Where the CL path between a and
    # b runs out of the limits (a piece no cutting move can do, see
    # Continues), it is halved instead, and the piece left at the deepest level gets
    # the flag retract. Refused with src: a move whose CL axes are
    # opposite (no great circle between them), and, before it is split, a
    # move ending outside the machine's travel.
    method Linearise {a b tol atol depth src} {
        if {$tol <= 0} {return [list $b]}
        lassign $a ja Pa ta acta la
        lassign $b jb Pb tb actb lb
        if {$depth == 0} {
            # (axes with a positive dot product are less than 90 deg apart)
            lassign $ta ax ay az
            lassign $tb bx by bz
            if {$ax * $bx + $ay * $by + $az * $bz <= 0.0} {
                ::fivax::motion::CheckFlip $ta $tb $src
            }
            set S(pieces) 0
        }
        set ok [::fivax::motion::Continues $S(ms1) $S(ms2) [lindex $ja 3] [lindex $ja 4] $la \
            [lindex $jb 3] [lindex $jb 4] $lb]
        set n 2
        if {$ok} {
            # First the bound (kin interpolationBound): it proves most moves
            # within tolerance without the quarter points. The tips of the
            # written joints of a and b are within S(xyzError) of their CL
            # points (see the file header); their axes act are within
            # S(actError) of the joints' axis: the rotary rounding (half a
            # step on each axis) and the 6.3e-9 rad a candidate may be
            # moved onto a limit.
            set wa [my Written $ja]
            set wb [my Written $jb]
            lassign [::fivax::kin::interpolationBound $S(model) $wa $wb $Pa $Pb $acta $actb \
                $S(xyzError) $S(actError)] bp ba
            if {$bp <= $tol && $ba <= $atol} {return [list $b]}
            lassign [::fivax::kin::interpolationError $S(model) $wa $wb $Pa $Pb $acta $actb \
                $tol $atol] dp da
            set e [expr {$dp / $tol}]
            if {$da / $atol > $e} {set e [expr {$da / $atol}]}
            if {$e <= 1.0} {return [list $b]}
            set n [expr {int(ceil(1.1 * sqrt($e)))}]
            set n [expr {$n < 2 ? 2 : $n > 16 ? 16 : $n}]
        }
        if {$depth == 0} {
            lassign $jb X Y Z
            ::fivax::machine::checkLimits $S(machine) [list X $X Y $Y Z $Z] $src
        }
        namespace upvar ::fivax::motion maxDepth maxDepth maxPieces maxPieces
        if {$depth < $maxDepth && $S(pieces) < $maxPieces} {
            incr S(pieces) $n
            try {
                set pts [::fivax::motion::Split $S(ctx) $a $b $n $src]
                lappend pts $b
                set out {}
                set prev $a
                incr depth
                foreach p $pts {
                    lappend out {*}[my Linearise $prev $p $tol $atol $depth $src]
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

    # Sets S(xyzDecimals) (the decimals of -length-step, "" when exact or
    # in a work plane's frame) and S(xyzError) (the largest distance the
    # rounding of X Y Z moves the tip, see the file header).
    method WrittenResolution {} {
        set step $S(length-step)
        set S(xyzDecimals) ""
        set S(xyzError) 0.0
        if {$step <= 0} return
        set S(xyzDecimals) [expr {max(0, int(round(-log10($step))))}]
        # (1e-12: the margin of the reader's decimal to double conversion)
        set S(xyzError) [expr {sqrt(3.0) / 2.0 * $step + 1e-12}]
    }

    # Returns joints {X Y Z q1 q2} with X Y Z as the output writes them
    # (format with -length-step's decimals, read back); unchanged when
    # exact or in a work plane (its X Y Z are written in the plane's frame,
    # where the rotaries stand still and the tip moves straight).
    method Written {joints} {
        if {$S(xyzDecimals) eq "" || $S(plane) ne ""} {return $joints}
        lassign $joints x y z q1 q2
        set f %.$S(xyzDecimals)f
        list [expr {double([format $f $x])}] [expr {double([format $f $y])}] \
            [expr {double([format $f $z])}] $q1 $q2
    }
}

# ::fivax::motion::CheckFlip --
#	Raises {FIVAX MOTION FLIP} naming src when the unit CL axes ta and tb
#	of a cutting move are opposite (within flipSlack): the axis could turn
#	from one to the other about any great circle, so the CL path between
#	them is undefined. (Linearise calls it only for axes at least 90 deg
#	apart.)
proc ::fivax::motion::CheckFlip {ta tb src} {
    variable pi
    variable flipSlack
    if {[::fivax::vec::angle $ta $tb] <= $pi - $flipSlack} return
    ::fivax::Fail MOTION FLIP "$src: the tool axis turns 180 deg in one cutting move\
        (([AxisText $ta]) to ([AxisText $tb])): the way it turns is undefined;\
        add a CL point between them"
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
proc ::fivax::motion::Split {ctx a b n src} {
    lassign $a ja Pa ta - la
    lassign $b jb Pb tb - lb
    lassign $ja - - - a1 a2
    lassign $jb - - - b1 b2
    if {abs($b2 - $a2) > 1e-9} {
        foreach end [list $a $b] other [list $b $a] {
            lassign $end je P t
            if {[InCone $ctx $t]} {
                set c [lindex [Quantize [dict get $ctx step] [Departure $ctx $end $other $src]] 0]
                if {abs($c - [lindex $je 4]) > 1e-9} {
                    set q1 [HoldTilt $ctx $t [lindex $je 3] $c]
                    if {$q1 ne ""} {return [list [Record $ctx $P $t $q1 $c -1 1]]}
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
        lappend out [Record $ctx [::fivax::vec::lerp $Pa $Pb $f] $t \
            {*}[Pick $ctx $t $g1 $g2 $la $lb $src] [InCone $ctx $t]]
    }
    return $out
}

# ::fivax::motion::Departure --
#	Returns the azimuth with which the CL path leaves point record end
#	(in the singular cone) towards point record other: that of the exact
#	candidate nearest other's rotaries at the CL axis ten cone angles away
#	from end; half-way between their azimuths when other is that close.
proc ::fivax::motion::Departure {ctx end other src} {
    lassign $end je - te
    lassign $other jo - to lo
    set angle [::fivax::vec::angle $te $to]
    set step [expr {10.0 * asin(min(1.0, [dict get $ctx sinCone]))}]
    if {$angle <= $step} {return [expr {0.5 * ([lindex $je 4] + [lindex $jo 4])}]}
    set t [::fivax::vec::slerp $te $to [expr {$step / $angle}]]
    lindex [Pick $ctx $t [lindex $jo 3] [lindex $jo 4] $lo $lo $src] 1
}
