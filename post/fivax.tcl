# fivax.tcl --
#	fivax five-axis post: NX Post Builder-style event handlers. NX (or the
#	replay driver tools/replay.tcl) sources this file once and calls the
#	MOM_* handlers below with the mom_* globals set. The handlers read the
#	CL data (mom_mcs_goto, mom_tool_axis: workpiece frame), hand them to the
#	fivax library for machine coordinates, and write blocks with
#	MOM_output_text. Uses only Tcl and the MOM_* commands NX provides.
#
#	Settings: set the global dict fivax_settings before this file is
#	sourced (the replay driver does), or edit the defaults below:
#	  machine       machine file (default ../machines/hh-tilt45.tcl)
#	  controller    dialect: fanuc or linuxcnc (default: the machine's)
#	  table_offset  {x y z}: workpiece origin override for table axes ("")
#	  msys          1: map CL data through the MSYS frame (0)
#	  feed_mode     inverse (G93 on rotary moves), direct or dpm (inverse)
#	  rotary        optimal (whole-path choice) or greedy (optimal)
#	  on_limit      retract (retract, reposition, re-engage) or error (retract)
#	  tol           linearisation tip tolerance, mm; 0 = off (0.01)
#	  clearance     retract distance along the tool axis, mm ("": the machine's)
#	  atol, cone, swing, window, weights: planner fine-tuning, see
#	                lib/motion.tcl (absent: the planner's defaults)
#	  arc_tol       chord tolerance (mm) for arcs written as points (0.002)

set fivax_post_dir [file dirname [file normalize [info script]]]
foreach fivax_dir [list [file join $fivax_post_dir lib] [file join $fivax_post_dir .. lib]] {
    if {[file exists [file join $fivax_dir pkgIndex.tcl]] && $fivax_dir ni $auto_path} {
        set auto_path [linsert $auto_path 0 $fivax_dir]
    }
}
package require fivax 0.1
unset fivax_dir

if {![info exists fivax_settings]} {set fivax_settings {}}
set fivax_settings [dict merge [dict create \
    machine [file join $fivax_post_dir .. machines hh-tilt45.tcl] \
    controller "" table_offset "" msys 0 feed_mode inverse arc_tol 0.002] $fivax_settings]

# fivax_setting -- Returns one post setting.
proc fivax_setting {key} {
    global fivax_settings
    dict get $fivax_settings $key
}

# fivax_out -- Writes one NC line (nothing when the line is empty).
proc fivax_out {line} {
    if {$line ne ""} {MOM_output_text $line}
}

# fivax_where -- Returns FILE:LINE of the current CL record when the host knows it.
proc fivax_where {} {
    global mom_cl_file mom_cl_line
    if {[info exists mom_cl_line]} {return "$mom_cl_file:$mom_cl_line"}
    return "event [MOM_ask_event_type]"
}

# fivax_plan_options -- Returns motion::create options from the post settings.
proc fivax_plan_options {} {
    global fivax_settings
    set options {}
    foreach {key option} {table_offset -tableOffset msys -msys feed_mode -feedMode
        rotary -rotary on_limit -onLimit tol -tol clearance -clearance atol -atol
        cone -cone swing -swing window -window weights -weights} {
        if {[dict exists $fivax_settings $key]} {
            lappend options $option [dict get $fivax_settings $key]
        }
    }
    return $options
}

# fivax_nc_options -- Returns nc::create options from a machine file's output dict.
proc fivax_nc_options {out} {
    set options {}
    foreach {key option} {decimals -decimals angle_decimals -angleDecimals
        feed_decimals -feedDecimals sequence -sequence seq_start -seqStart
        seq_incr -seqIncr} {
        if {[dict exists $out $key]} {lappend options $option [dict get $out $key]}
    }
    return $options
}

proc MOM_start_of_program {} {
    global fivax mom_part_name mom_output_unit
    set machine [fivax::machine::load [fivax_setting machine]]
    set out [dict get $machine output]
    set controller [fivax_setting controller]
    if {$controller eq ""} {set controller [dict get $machine controller]}
    array set fivax [list machine $machine toolNumber 0 pendingLength 0 feedMode 94]
    set fivax(nc) [fivax::nc::create -dialect $controller \
        -units [dict get $machine units] \
        -rotaryNames [fivax::machine::rotaryNames $machine] \
        {*}[fivax_nc_options $out]]
    # The planner rounds rotaries to the written resolution before X Y Z.
    set step [expr {10.0 ** -[dict get [fivax::nc::configure $fivax(nc)] -angleDecimals]}]
    set fivax(plan) [fivax::motion::create $machine -angleStep $step {*}[fivax_plan_options]]
    # Inverse-time F (1/min) needs more decimals than mm/min, and G93 wants
    # F in every block: a second F address, always written.
    set decimals [expr {[dict exists $out inverse_decimals] ? [dict get $out inverse_decimals] : 3}]
    fivax::nc::address $fivax(nc) F_inv -leader F -format %.${decimals}f -force always
    set fivax(verify) [fivax::verify::create $machine \
        -tableOffset [fivax_setting table_offset]]
    set name [expr {[info exists mom_part_name] ? $mom_part_name : "PART"}]
    set program [expr {[dict exists $out program] ? [dict get $out program] : 1000}]
    foreach line [fivax::nc::header $fivax(nc) $program \
        "$name - [dict get $machine name]"] {
        fivax_out $line
    }
    fivax_out [fivax::nc::block $fivax(nc) [list G_units \
        [expr {[dict get $machine units] eq "inch" ? 20 : 21}] G_mode 90 G_feed 94 G_plane 17]]
}

proc MOM_start_of_path {} {
    global fivax mom_path_name
    fivax_emit [fivax::motion::startPath $fivax(plan)]
    fivax_out [fivax::nc::comment $fivax(nc) "OPERATION $mom_path_name"]
}

proc MOM_msys {} {
    global fivax mom_msys_origin mom_msys_matrix
    set m [lmap i {0 1 2 3 4 5 6 7 8} {set mom_msys_matrix($i)}]
    fivax::motion::setFrame $fivax(plan) \
        [list $mom_msys_origin(0) $mom_msys_origin(1) $mom_msys_origin(2)] \
        [lrange $m 0 2] [lrange $m 3 5]
}

proc MOM_first_tool {} {
    MOM_tool_change
}

proc MOM_tool_change {} {
    global fivax mom_tool_number mom_tool_length mom_tool_length_adjust_register
    fivax_emit [fivax::motion::flush $fivax(plan)]
    set len [dict get $fivax(machine) tool_length]
    if {[info exists mom_tool_length] && $mom_tool_length > 0} {set len $mom_tool_length}
    fivax::motion::setTool $fivax(plan) $len
    fivax::verify::setTool $fivax(verify) $len
    set adjust $mom_tool_number
    if {[info exists mom_tool_length_adjust_register]} {set adjust $mom_tool_length_adjust_register}
    fivax_out [fivax::nc::block $fivax(nc) [list T $mom_tool_number M 6]]
    fivax::nc::reset $fivax(nc)
    set fivax(pendingLength) $adjust
}

proc MOM_spindle_rpm {} {
    global fivax mom_spindle_speed mom_spindle_direction
    fivax_emit [fivax::motion::flush $fivax(plan)]
    set m [expr {[info exists mom_spindle_direction] && $mom_spindle_direction eq "CCLW" ? 4 : 3}]
    fivax_out [fivax::nc::block $fivax(nc) [list S [expr {round($mom_spindle_speed)}] M_spindle $m]]
}

proc MOM_spindle_off {} {
    global fivax
    fivax_emit [fivax::motion::flush $fivax(plan)]
    fivax_out [fivax::nc::block $fivax(nc) [list M_spindle 5]]
}

proc MOM_coolant_on {} {
    global fivax mom_coolant_mode
    fivax_emit [fivax::motion::flush $fivax(plan)]
    set m [expr {[info exists mom_coolant_mode] && $mom_coolant_mode eq "MIST" ? 7 : 8}]
    fivax_out [fivax::nc::block $fivax(nc) [list M_coolant $m]]
}

proc MOM_coolant_off {} {
    global fivax
    fivax_emit [fivax::motion::flush $fivax(plan)]
    fivax_out [fivax::nc::block $fivax(nc) [list M_coolant 9]]
}

proc MOM_initial_move {} {
    global mom_motion_event
    MOM_$mom_motion_event
}

proc MOM_first_move {} {
    global mom_motion_event
    MOM_$mom_motion_event
}

proc MOM_rapid_move {} {
    fivax_motion rapid
}

proc MOM_linear_move {} {
    fivax_motion feed
}

# Arcs (CIRCLE + GOTO) are written as points within arc_tol of the arc:
# on a five-axis machine without TCP an arc does not stay an arc.
proc MOM_circular_move {} {
    global mom_prev_mcs_goto mom_mcs_goto mom_arc_center mom_arc_axis
    global mom_arc_direction mom_arc_times
    set xyz {0 1 2}
    set points [fivax::toolpath::arc [lmap i $xyz {set mom_prev_mcs_goto($i)}] \
        [lmap i $xyz {set mom_mcs_goto($i)}] [lmap i $xyz {set mom_arc_center($i)}] \
        [lmap i $xyz {set mom_arc_axis($i)}] \
        [expr {$mom_arc_direction eq "CLW" ? -1 : 1}] \
        [expr {[info exists mom_arc_times] ? $mom_arc_times : 0}] [fivax_setting arc_tol]]
    foreach point $points {
        fivax_motion feed $point
    }
}

proc MOM_gohome_move {} {
    fivax_motion rapid
}

# fivax_motion --
#	Hands a CL point (default: the current mom_mcs_goto) with the current
#	tool axis to the planner and writes what is ready.
proc fivax_motion {kind {point ""}} {
    global fivax mom_mcs_goto mom_tool_axis mom_feed_rate
    set feed [expr {[info exists mom_feed_rate] ? $mom_feed_rate : 0.0}]
    if {$point eq ""} {
        set point [list $mom_mcs_goto(0) $mom_mcs_goto(1) $mom_mcs_goto(2)]
    }
    fivax_emit [fivax::motion::add $fivax(plan) $kind $point \
        [list $mom_tool_axis(0) $mom_tool_axis(1) $mom_tool_axis(2)] \
        $feed [fivax_where]]
}

# fivax_emit --
#	Writes the planner's moves as blocks and checks each one. F is written
#	again after leaving inverse time; retracts are reported on the listing.
proc fivax_emit {moves} {
    global fivax
    foreach move $moves {
        if {[dict get $move tag] eq "retract"} {
            MOM_output_to_listing_device "fivax: retract at [dict get $move src]: [dict get $move note]"
        }
        if {[dict get $move kind] eq "feed"} {
            set mode [dict get $move feedMode]
            if {$mode != $fivax(feedMode) && $mode == 94} {fivax::nc::force $fivax(nc) once F}
            set fivax(feedMode) $mode
        }
        set words [fivax::motion::words $fivax(plan) $move]
        if {$fivax(pendingLength) && [dict exists $words Z]} {
            set words [linsert $words 2 G_length 43 H $fivax(pendingLength)]
            set fivax(pendingLength) 0
        }
        set line [fivax::nc::block $fivax(nc) $words]
        fivax_out $line
        fivax::verify::block $fivax(verify) $line $move
    }
}

proc MOM_end_of_path {} {
    global fivax
    fivax_emit [fivax::motion::flush $fivax(plan)]
}

proc MOM_pprint {} {
    global fivax mom_pprint
    fivax_emit [fivax::motion::flush $fivax(plan)]
    fivax_out [fivax::nc::comment $fivax(nc) $mom_pprint]
}

proc MOM_insert {} {
    global fivax mom_Instruction
    fivax_emit [fivax::motion::flush $fivax(plan)]
    fivax_out $mom_Instruction
}

proc MOM_stop {} {
    global fivax
    fivax_emit [fivax::motion::flush $fivax(plan)]
    fivax_out [fivax::nc::block $fivax(nc) {M 0}]
}

proc MOM_opstop {} {
    global fivax
    fivax_emit [fivax::motion::flush $fivax(plan)]
    fivax_out [fivax::nc::block $fivax(nc) {M 1}]
}

proc MOM_delay {} {
    global fivax mom_delay_value
    fivax_emit [fivax::motion::flush $fivax(plan)]
    if {[info exists mom_delay_value]} {
        fivax_out [fivax::nc::line $fivax(nc) [format "G4 P%d" [expr {round($mom_delay_value * 1000)}]]]
    }
}

proc MOM_end_of_program {} {
    global fivax fivax_summary
    fivax_emit [fivax::motion::flush $fivax(plan)]
    fivax_out [fivax::nc::block $fivax(nc) {M_spindle 5 M_coolant 9}]
    foreach line [fivax::nc::footer $fivax(nc)] {fivax_out $line}
    set fivax_summary [dict merge [fivax::motion::stats $fivax(plan)] \
        [fivax::verify::summary $fivax(verify)]]
    MOM_output_to_listing_device "fivax summary: $fivax_summary"
}
