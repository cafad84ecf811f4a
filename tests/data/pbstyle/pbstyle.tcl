# pbstyle.tcl --
#	A three-axis mill post in the shape Post Builder gives its posts,
#	written for fivax's tests (no Siemens code): it sources its base file
#	from UGII_CAM_POST_DIR as those posts source ugpost_base.tcl, writes
#	its blocks with MOM_do_template from pbstyle.def, writes the program
#	header and switches numbering on in MOM_machine_mode, and reads the
#	globals NX sets on every event as those posts do: without asking
#	whether they exist.

set cam_post_dir [MOM_ask_env_var UGII_CAM_POST_DIR]

if {![info exists mom_sys_post_initialized]} {
    source ${cam_post_dir}pbstyle_base.tcl

    set mom_sys_leader(X) X
    set mom_sys_leader(Y) Y
    set mom_sys_leader(Z) Z
    set mom_sys_rapid_code 0
    set mom_sys_linear_code 1
    set mom_sys_circle_code(CLW) 2
    set mom_sys_circle_code(CCLW) 3
    set mom_sys_cutcom_code(OFF) 40
    set mom_sys_cutcom_plane_code(XY) 17
    set mom_sys_cutcom_plane_code(ZX) 18
    set mom_sys_cutcom_plane_code(YZ) 19
    set mom_sys_output_code(ABSOLUTE) 90
    set mom_sys_output_code(INCREMENTAL) 91
    set mom_sys_unit_code(IN) 70
    set mom_sys_unit_code(MM) 71
    set mom_sys_adjust_code 43
    set mom_sys_return_code 28
    set mom_sys_home_pos(2) 0
    set mom_sys_tool_change_code 6
    set mom_sys_spindle_direction_code(CLW) 3
    set mom_sys_spindle_direction_code(CCLW) 4
    set mom_sys_spindle_direction_code(OFF) 5
    set mom_sys_coolant_code(OFF) 9
    set mom_sys_coolant_code(ON) 8
    set mom_sys_feed_rate_mode_code(MMPM) 94
    set mom_sys_feed_rate_mode_code(IPM) 94
    set mom_sys_end_of_program_code 30
    set mom_sys_feed_param(MMPM,format) Feed
    set mom_kin_machine_type 3_axis_mill
    set mom_kin_output_unit MM
    set mom_kin_arc_output_mode FULL_CIRCLE
    set mom_kin_helical_arc_output_mode LINEAR
    set mom_kin_rapid_feed_rate 10000
    set pb_sys_group_output 1
    set pb_sys_strip_spaces 1
    set mom_sys_post_initialized 1
}

# MOM_start_of_program -- Numbering off until the header; the working directory.
proc MOM_start_of_program {} {
    global pb_started pb_tmp_dir mom_warning_info mom_cutcom_status mom_cutcom_plane
    global mom_coolant_status
    set pb_started 0
    set mom_cutcom_status OFF
    set mom_cutcom_plane XY
    set mom_coolant_status ON
    set pb_tmp_dir [MOM_ask_env_var UGII_TMP_DIR]
    set mom_warning_info ""
    OPEN_FILES
    SEQNO_RESET
    MOM_set_seq_off
}

# MOM_machine_mode -- The program header, once: %, numbering on, the modes.
proc MOM_machine_mode {} {
    global pb_started mom_machine_mode
    if {$pb_started || $mom_machine_mode ne "MILL"} return
    set pb_started 1
    MOM_do_template rewind_stop_code
    SEQNO_SET
    MOM_do_template absolute_mode
}

# MOM_start_of_path -- The operation's name as a comment.
proc MOM_start_of_path {} {
    global mom_operation_name mom_update_post_cmds_from_tool pb_first_of_path
    set pb_first_of_path 1
    if {$mom_update_post_cmds_from_tool} {MOM_output_literal "(TOOL DATA UPDATED)"}
    MOM_output_literal "(OPERATION $mom_operation_name)"
}

# MOM_first_tool -- The first tool is a tool change.
proc MOM_first_tool {} {
    MOM_tool_change
}

# MOM_tool_change -- T M6, then the spindle at the first move.
proc MOM_tool_change {} {
    global mom_tool_name
    MOM_output_literal "(TOOL $mom_tool_name)"
    MOM_do_template tool_change
}

# MOM_spindle_rpm -- The spindle is started with the first move.
proc MOM_spindle_rpm {} {}

# MOM_before_motion -- The feed of the move, the rapid rate on rapids.
proc MOM_before_motion {} {
    global mom_feed_rate mom_feed_rate_output_mode mom_motion_type feed
    global mom_pos mom_prev_pos mom_cycle_spindle_axis pb_rotary_moved
    if {$mom_feed_rate_output_mode ni {MMPM IPM}} {
        MOM_abort "pbstyle: feed mode $mom_feed_rate_output_mode"
    }
    set feed $mom_feed_rate
    set pb_rotary_moved [expr {$mom_pos(3) != $mom_prev_pos(3) || $mom_pos(4) != $mom_prev_pos(4)}]
    if {$mom_cycle_spindle_axis != 2} {MOM_abort "pbstyle: spindle axis $mom_cycle_spindle_axis"}
}

# MOM_initial_move --
#	Positions in X Y, length compensation in Z, spindle on; then a feed
#	move (mom_motion_event is initial_move for a straight motion: its
#	feed tells) or a curve (which keeps its own event name).
proc MOM_initial_move {} {
    global mom_motion_event mom_programmed_feed_rate
    MOM_do_template initial_move
    MOM_do_template tool_length_adjust
    MOM_do_template spindle_rpm
    if {$mom_motion_event ne "initial_move"} {
        MOM_$mom_motion_event
    } elseif {$mom_programmed_feed_rate != 0} {
        MOM_linear_move
    }
}

# MOM_first_move -- The motion itself.
proc MOM_first_move {} {
    global mom_motion_event
    MOM_$mom_motion_event
}

proc MOM_rapid_move {} {MOM_do_template rapid_move}

proc MOM_linear_move {} {MOM_do_template linear_move}

proc MOM_circular_move {} {
    global mom_current_motion
    if {$mom_current_motion ni {circular_move initial_move first_move}} {
        MOM_abort "pbstyle: circular move as $mom_current_motion"
    }
    MOM_do_template circular_move
}

proc MOM_end_of_path {} {
    MOM_do_template coolant_off
}

# MOM_end_of_program -- Home, spindle off, end, the times and the block count.
proc MOM_end_of_program {} {
    global mom_machine_time mom_cutting_time pb_blocks pb_groups pb_warnings
    MOM_do_template spindle_off
    MOM_do_template return_home
    MOM_do_template end_of_program
    MOM_set_seq_off
    MOM_output_literal [format "(MACHINE TIME %.3f CUTTING TIME %.3f)" $mom_machine_time $mom_cutting_time]
    MOM_output_literal "(BLOCKS $pb_blocks GROUPS $pb_groups WARNINGS $pb_warnings)"
    MOM_do_template rewind_stop_code
}
