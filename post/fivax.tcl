# fivax.tcl --
#	fivax five-axis post: NX Post Builder-style event handlers. NX (or the
#	replay driver tools/replay.tcl) sources this file once and calls the
#	MOM_* handlers below with the mom_* globals set. The handlers hand the
#	CL data (mom_mcs_goto, mom_tool_axis: workpiece frame) to the planner,
#	turn its move records into blocks through the output layer, check
#	every block, and write with MOM_output_text. Uses only Tcl and the
#	MOM_* commands NX provides; no geometry here.
#
#	Settings: set the global dict fivax_settings before this file is
#	sourced (the replay driver does); its keys are the option names of
#	[fivax::settings table], e.g. -machine, -controller, -tol, -msys.

set fivax_post_dir [file dirname [file normalize [info script]]]
foreach fivax_dir [list [file join $fivax_post_dir lib] [file join $fivax_post_dir .. lib]] {
    if {[file exists [file join $fivax_dir pkgIndex.tcl]] && $fivax_dir ni $auto_path} {
        set auto_path [linsert $auto_path 0 $fivax_dir]
    }
}
package require fivax 0.1
unset fivax_dir
if {![info exists fivax_settings]} {set fivax_settings {}}

# fivax_out -- Writes NC lines (empty ones are skipped).
proc fivax_out {lines} {
    foreach line $lines {
        if {$line ne ""} {MOM_output_text $line}
    }
}

# fivax_where -- Returns FILE:LINE of the current CL record when the host knows it.
proc fivax_where {} {
    global mom_cl_file mom_cl_line
    if {[info exists mom_cl_line]} {return "$mom_cl_file:$mom_cl_line"}
    return "event [MOM_ask_event_type]"
}

proc MOM_start_of_program {} {
    global fivax fivax_settings fivax_post_dir mom_part_name
    set settings [fivax::settings parse $fivax_settings]
    set file [dict get $settings -machine]
    if {$file eq ""} {set file [file join $fivax_post_dir .. machines hh-tilt45.tcl]}
    set machine [fivax::machine load $file]
    set options {}
    if {[dict get $settings -controller] ne ""} {
        lappend options -controller [dict get $settings -controller]
    }
    array set fivax [list settings $settings]
    set fivax(out) [fivax::output create $machine {*}$options]
    set fivax(plan) [fivax::motion create $machine -angle-step [$fivax(out) angleStep] \
        {*}[fivax::settings pick $settings motion]]
    set fivax(verify) [fivax::verify create $machine {*}[fivax::settings pick $settings verify]]
    set fivax(toolLength) [dict get $machine tool_length]
    set name [expr {[info exists mom_part_name] ? $mom_part_name : "PART"}]
    fivax_out [$fivax(out) start "$name - [dict get $machine name]"]
}

proc MOM_start_of_path {} {
    global fivax mom_path_name
    fivax_emit [$fivax(plan) startPath]
    fivax_out [list [$fivax(out) comment "OPERATION $mom_path_name"]]
}

proc MOM_msys {} {
    global fivax mom_msys_origin mom_msys_matrix
    set m [lmap i {0 1 2 3 4 5 6 7 8} {set mom_msys_matrix($i)}]
    $fivax(plan) setFrame [list $mom_msys_origin(0) $mom_msys_origin(1) $mom_msys_origin(2)] \
        [lrange $m 0 2] [lrange $m 3 5]
}

proc MOM_first_tool {} {
    MOM_tool_change
}

proc MOM_tool_change {} {
    global fivax mom_tool_number mom_tool_length mom_tool_length_adjust_register
    fivax_emit [$fivax(plan) flush]
    set len $fivax(toolLength)
    if {[info exists mom_tool_length] && $mom_tool_length > 0} {set len $mom_tool_length}
    $fivax(plan) setTool $len
    $fivax(verify) setTool $len
    set adjust $mom_tool_number
    if {[info exists mom_tool_length_adjust_register]} {set adjust $mom_tool_length_adjust_register}
    fivax_out [$fivax(out) toolChange $mom_tool_number $adjust]
}

proc MOM_spindle_rpm {} {
    global fivax mom_spindle_speed mom_spindle_direction
    fivax_emit [$fivax(plan) flush]
    set direction [expr {[info exists mom_spindle_direction] ? $mom_spindle_direction : "CLW"}]
    fivax_out [$fivax(out) spindle $mom_spindle_speed $direction]
}

proc MOM_spindle_off {} {
    global fivax
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) spindleOff]
}

proc MOM_coolant_on {} {
    global fivax mom_coolant_mode
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) coolant [expr {[info exists mom_coolant_mode] ? $mom_coolant_mode : "ON"}]]
}

proc MOM_coolant_off {} {
    global fivax
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) coolantOff]
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

# Arcs (CIRCLE + GOTO) are written as points within the arc tolerance:
# on a five-axis machine without TCP an arc does not stay an arc.
proc MOM_circular_move {} {
    global fivax mom_prev_mcs_goto mom_mcs_goto mom_arc_center mom_arc_axis
    global mom_arc_direction mom_arc_times
    set xyz {0 1 2}
    set points [fivax::curve arc [lmap i $xyz {set mom_prev_mcs_goto($i)}] \
        [lmap i $xyz {set mom_mcs_goto($i)}] [lmap i $xyz {set mom_arc_center($i)}] \
        [lmap i $xyz {set mom_arc_axis($i)}] \
        [expr {$mom_arc_direction eq "CLW" ? -1 : 1}] \
        [expr {[info exists mom_arc_times] ? $mom_arc_times : 0}] \
        [dict get $fivax(settings) -arc-tol]]
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
    fivax_emit [$fivax(plan) add $kind $point \
        [list $mom_tool_axis(0) $mom_tool_axis(1) $mom_tool_axis(2)] \
        $feed [fivax_where]]
}

# fivax_emit --
#	Writes the planner's move records as blocks and checks each one;
#	retracts are reported on the listing.
proc fivax_emit {moves} {
    global fivax
    foreach move $moves {
        if {[dict get $move kind] eq "retract"} {
            MOM_output_to_listing_device "fivax: retract at [dict get $move src]: [dict get $move note]"
        }
        foreach line [$fivax(out) move $move] {
            fivax_out [list $line]
            $fivax(verify) block $line $move
        }
    }
}

proc MOM_end_of_path {} {
    global fivax
    fivax_emit [$fivax(plan) flush]
}

proc MOM_pprint {} {
    global fivax mom_pprint
    fivax_emit [$fivax(plan) flush]
    fivax_out [list [$fivax(out) comment $mom_pprint]]
}

proc MOM_insert {} {
    global fivax mom_Instruction
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) literal $mom_Instruction]
}

proc MOM_stop {} {
    global fivax
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) stop 0]
}

proc MOM_opstop {} {
    global fivax
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) stop 1]
}

proc MOM_delay {} {
    global fivax mom_delay_value
    fivax_emit [$fivax(plan) flush]
    if {[info exists mom_delay_value]} {
        fivax_out [$fivax(out) dwell $mom_delay_value]
    }
}

proc MOM_end_of_program {} {
    global fivax fivax_summary
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) end]
    set fivax_summary [dict merge [$fivax(plan) stats] [$fivax(verify) summary]]
    MOM_output_to_listing_device "fivax summary: $fivax_summary"
}
