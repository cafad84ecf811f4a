# clpath.tcl --
#	The CL path of a CLSF file as the tools compare against it: per
#	operation (TOOL PATH ... END-OF-PATH) the tool length of its TLDATA and
#	the polyline of its points with their tool axes as NX's events give
#	them to a post (arcs and NURBS as points within the post's chord
#	tolerance, as the post does; holes as their motions), and the nearest
#	point of that polyline to a given tip. Reads the file with the replay's
#	MOM runtime (the text is data). Needs the fivax package.
#
#	A point is {P t src rapid}: tip, unit axis (workpiece frame), FILE:LINE,
#	1 when it was reached by a RAPID.

namespace eval ::fivax::clpath {
    variable postFile [file join [file dirname [file normalize [info script]]] clpath-post.tcl]
    namespace export read nearest
    namespace ensemble create -prefixes 0
}

# ::fivax::clpath::read --
#	Returns the operations of the CL file at path: a list of dicts
#	{name NAME length L points {...}} (L "" when no TLDATA gave one),
#	read by the replay's MOM runtime with the handlers of
#	clpath-post.tcl: lengths in unit (mm or inch, as the machine's),
#	arcs and NURBS as points within arcTol, cycle holes as R plane,
#	bottom and retract points; with msys 1 the points are mapped through
#	the file's MSYS frame (as replay -msys does); with cutter {D r} (not
#	"") the cutting points with contact data are moved for that cutter,
#	as replay -cutcom3d post moves them (fivax::cutcom compensate).
#	Errors: those of fivax::clsf, fivax::mom and fivax::cutcom.
proc ::fivax::clpath::read {path {msys 0} {arcTol 0.002} {unit mm} {cutter {}}} {
    variable postFile
    set rt [::fivax::mom::create -post $postFile -listing ::fivax::clpath::Ignore \
        -autopath $::auto_path -globals [list clpath_msys $msys clpath_tol $arcTol \
        clpath_cutter $cutter mom_kin_output_unit [expr {$unit eq "inch" ? "IN" : "MM"}]]]
    try {
        $rt run $path
        [$rt interp] eval {set ::clpath_ops}
    } finally {
        $rt destroy
    }
}

# ::fivax::clpath::Ignore -- Drops a listing line (the replay reports the CL's warnings).
proc ::fivax::clpath::Ignore {line} {}

# ::fivax::clpath::nearest --
#	Returns {d i s Q tq} for tip P with axis t: the distance d from P to
#	the nearest point Q of the polyline of points (the segment from point
#	i to i+1 at fraction s, tq the axis there by spherical interpolation),
#	searching the segments from index from to from + window (all when
#	window < 0). Where several segments lie within tie (mm) of the nearest
#	(the tip dwelling while the axis turns), the one whose axis is closest
#	to t wins. The fraction s blends the tip's projection and the axis's
#	position on the great circle, weighted by the segment's tip length and
#	its axis turn (100 mm per radian).
proc ::fivax::clpath::nearest {points P t from window {tie 0.002}} {
    set n [llength $points]
    set last [expr {$window < 0 ? $n - 1 : min($n - 1, $from + $window)}]
    set cands {}
    set bd Inf
    for {set i $from} {$i <= $last} {incr i} {
        set j [expr {$i + 1 < $n ? $i + 1 : $i}]
        lassign [Project [lindex $points $i 0] [lindex $points $j 0] $P] d s
        if {$d <= $bd + $tie} {
            # where the axis turns much while the tip moves little, the
            # fraction along the segment is taken from the axis too
            lassign [Blend [lindex $points $i 0] [lindex $points $j 0] \
                [lindex $points $i 1] [lindex $points $j 1] $P $t $s] d s
        }
        if {$d <= $bd + $tie} {
            lappend cands [list $d $i $s $j]
            if {$d < $bd} {set bd $d}
        }
        # a close match found and the path has moved away from it: done
        if {$bd < $tie && $d > $bd + $tie + 1.0} break
        if {$i + 1 >= $n} break
    }
    set best {}
    set ba Inf
    foreach c $cands {
        lassign $c d i s j
        if {$d > $bd + $tie} continue
        set tq [::fivax::vec::slerp [lindex $points $i 1] [lindex $points $j 1] $s]
        set a [::fivax::vec::angle $tq $t]
        if {$a < $ba} {
            set ba $a
            set best [list $d $i $s [::fivax::vec::lerp [lindex $points $i 0] [lindex $points $j 0] $s] $tq]
        }
    }
    return $best
}

# ::fivax::clpath::Project --
#	Returns {d s}: the distance from P to segment A-B and the fraction s
#	(0..1) of its nearest point.
proc ::fivax::clpath::Project {A B P} {
    lassign $A ax ay az
    lassign $B bx by bz
    lassign $P px py pz
    set ux [expr {$bx - $ax}]; set uy [expr {$by - $ay}]; set uz [expr {$bz - $az}]
    set l2 [expr {$ux * $ux + $uy * $uy + $uz * $uz}]
    set s [expr {$l2 > 0 ? (($px - $ax) * $ux + ($py - $ay) * $uy + ($pz - $az) * $uz) / $l2 : 0.0}]
    set s [expr {$s < 0.0 ? 0.0 : $s > 1.0 ? 1.0 : $s}]
    set dx [expr {$px - $ax - $s * $ux}]
    set dy [expr {$py - $ay - $s * $uy}]
    set dz [expr {$pz - $az - $s * $uz}]
    list [expr {sqrt($dx * $dx + $dy * $dy + $dz * $dz)}] $s
}

# ::fivax::clpath::Blend --
#	Returns {d s} on segment A-B with axes tA-tB for tip P and axis t:
#	the fraction s = the tip projection sp blended with the fraction of
#	t's position along the arc tA-tB, weighted by the squares of |B - A|
#	and 100 mm times the arc angle; d = |P - Q(s)|.
proc ::fivax::clpath::Blend {A B tA tB P t sp} {
    set lp [::fivax::vec::norm [::fivax::vec::sub $B $A]]
    set th [::fivax::vec::angle $tA $tB]
    set la [expr {100.0 * $th}]
    if {$la < 1e-9 || $la < 0.01 * $lp} {
        return [list [::fivax::vec::norm [::fivax::vec::sub $P [::fivax::vec::lerp $A $B $sp]]] $sp]
    }
    set n [::fivax::vec::unit [::fivax::vec::cross $tA $tB]]
    set tp [::fivax::vec::sub $t [::fivax::vec::scale [::fivax::vec::dot $t $n] $n]]
    set c [::fivax::vec::cross $tA $tp]
    set a [expr {atan2([::fivax::vec::dot $c $n], [::fivax::vec::dot $tA $tp]) / $th}]
    set a [expr {$a < 0.0 ? 0.0 : $a > 1.0 ? 1.0 : $a}]
    set s [expr {($lp * $lp * $sp + $la * $la * $a) / ($lp * $lp + $la * $la)}]
    list [::fivax::vec::norm [::fivax::vec::sub $P [::fivax::vec::lerp $A $B $s]]] $s
}
