# verify.tcl --
#	Checks written NC blocks against the CL data they stand for: reads the
#	axis words back from the block text (so output rounding counts), runs
#	the forward kinematics (never the inverse) and measures the tip and axis
#	deviation at each CL point and, for cutting moves, at the quarter points
#	of the controller's linear joint interpolation against the straight CL
#	segment and the great circle of the tool axis (spec section 7). It knows
#	nothing of how the planner chose the blocks.

namespace eval ::fivax::verify {
    namespace export create setTool block summary interpolationError
    variable seq 0
    variable pi 3.141592653589793
}

# ::fivax::verify::create --
#	Returns a checker for machine; option -tableOffset {x y z} as for the planner.
proc ::fivax::verify::create {machine args} {
    variable seq
    set h ::fivax::verify::check[incr seq]
    upvar #0 $h S
    set S(tableOffset) ""
    foreach {opt val} $args {
        switch -- $opt {
            -tableOffset {set S(tableOffset) $val}
            default {::fivax::Fail VERIFY OPTION "bad option \"$opt\": must be -tableOffset"}
        }
    }
    set S(machine) $machine
    set S(names) [lmap axis [dict get $machine chain] {dict get $axis name}]
    set S(rollover) [lmap axis [dict get $machine chain] {dict get $axis rollover}]
    set S(limits) [lmap axis [dict get $machine chain] {
        if {[dict get $axis continuous] && [dict get $axis rollover]} {
            list -1e300 1e300
        } else {
            list [dict get $axis min] [dict get $axis max]
        }
    }]
    array set S {X {} Y {} Z {} q1 {} q2 {} prev {} checked 0 segments 0
        maxPos 0.0 maxAng 0.0 maxMidPos 0.0 maxMidAng 0.0 limitViolations 0
        worst {} worstMid {}}
    setTool $h [dict get $machine tool_length]
    return $h
}

# ::fivax::verify::setTool -- Switches the checker to a tool of length len (mm).
proc ::fivax::verify::setTool {h len} {
    upvar #0 $h S
    if {$S(tableOffset) eq ""} {
        set S(model) [::fivax::kin::model $S(machine) $len]
    } else {
        set S(model) [::fivax::kin::model $S(machine) $len $S(tableOffset)]
    }
    set S(prev) {}
}

# ::fivax::verify::block --
#	Reads the axis words of the NC line, updates the modal machine state,
#	and when move carries a CL target (P, t) measures the deviation.
proc ::fivax::verify::block {h line move} {
    upvar #0 $h S
    variable pi
    set text [regsub -all {\([^)]*\)} $line ""]
    # (a flat pattern: nested groups with -all -inline cost 30 times more)
    foreach word [regexp -all -inline {[A-Z][-+.0-9]+} $text] {
        set letter [string index $word 0]
        set value [string range $word 1 end]
        if {![string is double -strict $value]} continue
        if {$letter in {X Y Z}} {
            set S($letter) $value
        } elseif {[set i [lsearch -exact $S(names) $letter]] >= 0} {
            set q [expr {$value * $pi / 180.0}]
            lassign [lindex $S(limits) $i] min max
            if {$q < $min - 1e-9 || $q > $max + 1e-9} {incr S(limitViolations)}
            set S(q[expr {$i + 1}]) $q
        }
    }
    set P [dict get $move P]
    if {$P eq "" || $S(X) eq "" || $S(Y) eq "" || $S(Z) eq "" || $S(q1) eq "" || $S(q2) eq ""} {
        if {$P eq ""} {set S(prev) {}}
        return
    }
    set t [dict get $move t]
    set joints [list $S(X) $S(Y) $S(Z) $S(q1) $S(q2)]
    lassign [::fivax::kin::forward $S(model) $joints] Pm tm
    set dp [::fivax::vec::norm [::fivax::vec::sub $Pm $P]]
    set da [expr {[::fivax::vec::angle $tm $t] * 180.0 / $pi}]
    incr S(checked)
    if {$dp > $S(maxPos)} {set S(maxPos) $dp; set S(worst) [dict get $move src]}
    if {$da > $S(maxAng)} {set S(maxAng) $da}
    if {[dict get $move kind] eq "feed" && $S(prev) ne ""} {
        Segment $h $S(prev) $joints $P $t [dict get $move src]
    }
    set S(prev) [list $joints $P $t]
}

# ::fivax::verify::Segment --
#	Measures the tip and axis at the quarter points of the linear joint
#	interpolation from the previous checked block to joints; a rotary that
#	rolls over turns the shortest way.
proc ::fivax::verify::Segment {h prev joints P t src} {
    upvar #0 $h S
    variable pi
    lassign $prev j0 P0 t0
    foreach i {3 4} roll $S(rollover) {
        if {$roll} {
            set a [lindex $j0 $i]
            set d [expr {[lindex $joints $i] - $a}]
            lset joints $i [expr {$a + $d - 2.0 * $pi * round($d / (2.0 * $pi))}]
        }
    }
    incr S(segments)
    lassign [interpolationError $S(model) $j0 $joints $P0 $P $t0 $t] dp da
    set da [expr {$da * 180.0 / $pi}]
    if {$dp > $S(maxMidPos)} {set S(maxMidPos) $dp; set S(worstMid) $src}
    if {$da > $S(maxMidAng)} {set S(maxMidAng) $da}
}

# ::fivax::verify::interpolationError --
#	Returns {dp da}: the largest distance (mm) of the tool tip from the
#	segment P0-P1 and the largest angle (rad) of the tool axis from the
#	great-circle arc between unit axes t0 and t1, at the quarter points
#	(middle first) of the linear interpolation of joint vectors j0 to j1 on
#	model (forward kinematics only). With tol and atol it stops at the
#	first point beyond either. Also used by the planner's linearisation.
proc ::fivax::verify::interpolationError {model j0 j1 P0 P1 t0 t1 {tol Inf} {atol Inf}} {
    lassign $j0 X0 Y0 Z0 a0 b0
    lassign $j1 X1 Y1 Z1 a1 b1
    set dX [expr {$X1 - $X0}]
    set dY [expr {$Y1 - $Y0}]
    set dZ [expr {$Z1 - $Z0}]
    set da [expr {$a1 - $a0}]
    set db [expr {$b1 - $b0}]
    lassign $P0 px py pz
    lassign $P1 qx qy qz
    set ux [expr {$qx - $px}]
    set uy [expr {$qy - $py}]
    set uz [expr {$qz - $pz}]
    set len2 [expr {$ux * $ux + $uy * $uy + $uz * $uz}]
    # Arc t0-t1: unit normal n; the point t is beside the arc (not beyond
    # an end) when t.(n x t0) >= 0 and t.(t1 x n) >= 0.
    lassign $t0 ax ay az
    lassign $t1 bx by bz
    set nx [expr {$ay * $bz - $az * $by}]
    set ny [expr {$az * $bx - $ax * $bz}]
    set nz [expr {$ax * $by - $ay * $bx}]
    set nl [expr {sqrt($nx * $nx + $ny * $ny + $nz * $nz)}]
    set arc [expr {$nl >= 1e-12}]
    if {$arc} {
        set nx [expr {$nx / $nl}]
        set ny [expr {$ny / $nl}]
        set nz [expr {$nz / $nl}]
        set ex [expr {$ny * $az - $nz * $ay}]
        set ey [expr {$nz * $ax - $nx * $az}]
        set ez [expr {$nx * $ay - $ny * $ax}]
        set fx [expr {$by * $nz - $bz * $ny}]
        set fy [expr {$bz * $nx - $bx * $nz}]
        set fz [expr {$bx * $ny - $by * $nx}]
    }
    set dp 0.0
    set dg 0.0
    foreach s {0.5 0.25 0.75} {
        lassign [::fivax::kin::forward $model [list [expr {$X0 + $s * $dX}] \
            [expr {$Y0 + $s * $dY}] [expr {$Z0 + $s * $dZ}] \
            [expr {$a0 + $s * $da}] [expr {$b0 + $s * $db}]]] P t
        lassign $P x y z
        lassign $t tx ty tz
        set x [expr {$x - $px}]
        set y [expr {$y - $py}]
        set z [expr {$z - $pz}]
        # (ternaries: min() and max() are ten times slower in expr)
        set u [expr {$len2 > 0.0 ? ($x * $ux + $y * $uy + $z * $uz) / $len2 : 0.0}]
        set u [expr {$u < 0.0 ? 0.0 : $u > 1.0 ? 1.0 : $u}]
        set x [expr {$x - $u * $ux}]
        set y [expr {$y - $u * $uy}]
        set z [expr {$z - $u * $uz}]
        set d [expr {sqrt($x * $x + $y * $y + $z * $z)}]
        if {$d > $dp} {set dp $d}
        if {$arc && $tx * $ex + $ty * $ey + $tz * $ez >= 0.0
                && $tx * $fx + $ty * $fy + $tz * $fz >= 0.0} {
            set g [expr {abs($tx * $nx + $ty * $ny + $tz * $nz)}]
            set g [expr {$g < 1.0 ? asin($g) : 1.5707963267948966}]
        } else {
            set g [Angle $tx $ty $tz $ax $ay $az]
            set g2 [Angle $tx $ty $tz $bx $by $bz]
            if {$g2 < $g} {set g $g2}
        }
        if {$g > $dg} {set dg $g}
        if {$dp > $tol || $dg > $atol} break
    }
    list $dp $dg
}

# ::fivax::verify::Angle -- Returns the angle (rad) between vectors (x y z) and (a b c).
proc ::fivax::verify::Angle {x y z a b c} {
    set u [expr {$y * $c - $z * $b}]
    set v [expr {$z * $a - $x * $c}]
    set w [expr {$x * $b - $y * $a}]
    expr {atan2(sqrt($u * $u + $v * $v + $w * $w), $x * $a + $y * $b + $z * $c)}
}

# ::fivax::verify::summary --
#	Returns a dict: checked (CL points), segments, maxPos (mm), maxAng (deg)
#	at the CL points, maxMidPos (mm), maxMidAng (deg) inside cutting moves,
#	limitViolations, worst and worstMid (FILE:LINE of the largest errors).
proc ::fivax::verify::summary {h} {
    upvar #0 $h S
    dict create checked $S(checked) segments $S(segments) maxPos $S(maxPos) \
        maxAng $S(maxAng) maxMidPos $S(maxMidPos) maxMidAng $S(maxMidAng) \
        limitViolations $S(limitViolations) worst $S(worst) worstMid $S(worstMid)
}
