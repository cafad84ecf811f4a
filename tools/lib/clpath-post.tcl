# clpath-post.tcl --
#	The event handlers fivax::clpath read runs a CLSF through (with the
#	replay's MOM runtime, lib/mom.tcl): they collect the CL path as NX
#	hands it to a post, with units converted, arcs and helixes in pieces
#	of at most 90 degrees, NURBS as curves and cycles as holes, and write
#	no NC. The runtime's interpretation of the CL is shared with the post;
#	the kinematics is not (the verifier maps NC back by forward kinematics).
#
#	Globals set by the caller: clpath_msys (1: map points through the
#	CLSF's MSYS frame), clpath_tol (chord tolerance of arcs and NURBS),
#	mom_kin_output_unit (MM or IN: the unit of the points), clpath_cutter
#	({D r}: cutting points with contact data moved for that cutter, "":
#	as written).
#	Result: clpath_ops, a list of {name NAME length L points {{P t src rapid} ...}
#	msysTurns 0|1} (msysTurns: the operation's MSYS record turns its MCS
#	in the absolute frame, so a program posted with -msys is read with it).

package require fivax

set mom_kin_arc_output_mode QUADRANT
set mom_kin_helical_arc_output_mode QUADRANT
set clpath_ops {}
set clpath_op {}
set clpath_frame {}
set clpath_turned 0

# clpath_vec -- Returns the three elements of global array name as a list.
proc clpath_vec {name} {
    upvar #0 $name a
    list $a(0) $a(1) $a(2)
}

# clpath_map -- Returns v mapped through the MSYS frame (a point when isPoint, else a direction).
proc clpath_map {v isPoint} {
    if {$::clpath_frame eq ""} {return $v}
    lassign $::clpath_frame o x y z
    lassign $v a b c
    set w [fivax::vec add [fivax::vec add [fivax::vec scale $a $x] [fivax::vec scale $b $y]] \
        [fivax::vec scale $c $z]]
    expr {$isPoint ? [fivax::vec add $o $w] : $w}
}

# clpath_point -- Adds point P (default mom_mcs_goto) on the current tool axis to the operation.
proc clpath_point {rapid {P ""}} {
    if {$P eq ""} {set P [clpath_vec mom_mcs_goto]}
    if {$::clpath_op eq ""} {clpath_open ""}
    dict lappend ::clpath_op points [list [clpath_map $P 1] \
        [clpath_map [fivax::vec unit [clpath_vec mom_tool_axis]] 0] \
        "$::mom_cl_file:$::mom_cl_line" $rapid]
}

# clpath_cut --
#	A cutting move to mom_mcs_goto: its point, moved for clpath_cutter
#	when the move has contact data (mom_contact_status ON).
proc clpath_cut {} {
    set P [clpath_vec mom_mcs_goto]
    if {[llength $::clpath_cutter] && [info exists ::mom_contact_status]
            && $::mom_contact_status eq "ON"} {
        set cutters [fivax::cutcom cutters $::mom_tool_diameter $::mom_tool_corner1_radius \
            {*}$::clpath_cutter]
        set P [fivax::cutcom compensate $P [clpath_vec mom_tool_axis] \
            [clpath_vec mom_contact_point] [clpath_vec mom_contact_normal] {*}$cutters]
    }
    clpath_point 0 $P
}

# clpath_open -- Starts the operation name (closing the open one).
proc clpath_open {name} {
    clpath_close
    # (the runtime's default tool length 0: no TLDATA gave one)
    set length [expr {$::mom_tool_length > 0 ? $::mom_tool_length : ""}]
    set ::clpath_op [dict create name $name length $length points {}]
}

# clpath_close -- Adds the open operation to clpath_ops.
proc clpath_close {} {
    if {$::clpath_op ne ""} {
        dict set ::clpath_op msysTurns $::clpath_turned
        lappend ::clpath_ops $::clpath_op
    }
    set ::clpath_op {}
}

proc MOM_start_of_path {} {clpath_open $::mom_path_name}
proc MOM_end_of_path {} {clpath_close}
proc MOM_end_of_program {} {clpath_close}

proc MOM_msys {} {
    set m [lmap i {0 1 2 3 4 5 6 7 8} {set ::mom_msys_matrix($i)}]
    set ::clpath_turned 0
    foreach a $m b {1 0 0 0 1 0 0 0 1} {
        if {abs($a - $b) > 1e-9} {set ::clpath_turned 1}
    }
    if {$::clpath_msys} {
        set ::clpath_frame [list [clpath_vec mom_msys_origin] [lrange $m 0 2] [lrange $m 3 5] \
            [lrange $m 6 8]]
    }
}

proc MOM_initial_move {} clpath_first
proc MOM_first_move {} clpath_first
proc MOM_rapid_move {} {clpath_point 1}
proc MOM_linear_move {} clpath_cut
proc MOM_from_move {} {clpath_point 1}
proc MOM_gohome_move {} {clpath_point 1}

# MOM_circular_move -- An arc or helix piece (at most 90 degrees) as points within clpath_tol.
proc MOM_circular_move {} {
    foreach P [fivax::curve arc [clpath_vec mom_prev_mcs_goto] [clpath_vec mom_mcs_goto] \
            [clpath_vec mom_arc_center] [clpath_vec mom_arc_axis] \
            [expr {$::mom_arc_direction eq "CLW" ? -1 : 1}] 0 $::clpath_tol] {
        clpath_point 0 $P
    }
}

# MOM_helix_move -- A helix piece as an arc piece (without it the runtime linearises helixes).
proc MOM_helix_move {} MOM_circular_move

# MOM_nurbs_move -- The NURBS (mom_nurbs_*) as points within clpath_tol.
proc MOM_nurbs_move {} {
    set knots [lmap i [lsearch -all [lrepeat $::mom_nurbs_knot_count x] x] {
        set ::mom_nurbs_knots($i)}]
    set points [lmap i [lsearch -all [lrepeat $::mom_nurbs_point_count x] x] {
        list $::mom_nurbs_points($i,0) $::mom_nurbs_points($i,1) $::mom_nurbs_points($i,2)}]
    set curve [fivax::curve nurbs [expr {$::mom_nurbs_order - 1}] $knots $points]
    foreach P [fivax::curve nurbsPoints $curve $::clpath_tol] {clpath_point 0 $P}
}

# clpath_first --
#	An operation's first motion: the motion mom_motion_event names (the
#	runtime fires MOM_initial_move / MOM_first_move in place of its
#	event), an arc, helix or NURBS from its start (the CL point before it, the
#	last of the previous operation), else the point.
proc clpath_first {} {
    switch -- $::mom_motion_event {
        circular_move - helix_move {
            clpath_point 0 [clpath_vec mom_prev_mcs_goto]
            MOM_circular_move
        }
        nurbs_move {
            clpath_point 0 [lmap j {0 1 2} {set ::mom_nurbs_points(0,$j)}]
            MOM_nurbs_move
        }
        default {
            if {$::mom_motion_type eq "CUT"} clpath_cut else {clpath_point 1}
        }
    }
}

# clpath_hole -- A cycle's hole: rapid to the R plane, feed to the bottom, rapid out.
proc clpath_hole {} {
    clpath_point 1 [clpath_vec mom_cycle_rapid_to_pos]
    clpath_point 0 [clpath_vec mom_cycle_feed_to_pos]
    clpath_point 1 [clpath_vec mom_cycle_retract_to_pos]
}

foreach clpath_event {drill drill_deep drill_break_chip drill_dwell tap bore bore_dwell
        bore_drag bore_no_drag bore_back bore_manual} {
    proc MOM_${clpath_event}_move {} clpath_hole
}
