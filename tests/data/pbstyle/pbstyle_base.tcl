# pbstyle_base.tcl --
#	The base file of tests/data/pbstyle/pbstyle.tcl, in the part Post
#	Builder posts leave to ugpost_base.tcl: sequence-number helpers, the
#	warning handler (a sequence number past the .def's maximum restarts the
#	numbering), the per-block hook MOM_before_output, the output files of
#	program groups, and the handlers of events the post leaves alone.
#	Written for fivax's tests; no Siemens code. Like a stock post it reads
#	the globals NX sets without asking whether they exist.

set pb_blocks 0
set pb_warnings 0
set pb_groups 0
set pb_group_files {}

# SEQNO_RESET -- The numbering of the .def's SEQUENCE, else 10 by 10.
proc SEQNO_RESET {} {
    global mom_sequence_number mom_sequence_increment mom_sequence_frequency
    global mom_def_sequence_start mom_def_sequence_increment mom_def_sequence_frequency
    if {[info exists mom_def_sequence_start]} {
        set mom_sequence_number $mom_def_sequence_start
        set mom_sequence_increment $mom_def_sequence_increment
        set mom_sequence_frequency $mom_def_sequence_frequency
    } else {
        set mom_sequence_number 10
        set mom_sequence_increment 10
        set mom_sequence_frequency 1
    }
}

# SEQNO_SET -- Restarts the numbering and switches it on.
proc SEQNO_SET {} {
    global mom_sequence_number mom_sequence_increment mom_sequence_frequency
    MOM_reset_sequence $mom_sequence_number $mom_sequence_increment $mom_sequence_frequency
    MOM_set_seq_on
}

# OPEN_FILES --
#	The output file anew, as Post Builder's base file does: closed, an
#	earlier run's removed, opened again.
proc OPEN_FILES {} {
    global mom_output_file_full_name
    if {![info exists mom_output_file_full_name]} return
    MOM_close_output_file $mom_output_file_full_name
    if {[file exists $mom_output_file_full_name]} {MOM_remove_file $mom_output_file_full_name}
    if {![file exists $mom_output_file_full_name]} {MOM_open_output_file $mom_output_file_full_name}
}

# MOM_catch_warning -- NX's warnings: a sequence number past the maximum restarts the numbering.
proc MOM_catch_warning {} {
    global mom_warning_info mom_seqnum pb_warnings
    global mom_sequence_number mom_sequence_increment mom_sequence_frequency
    incr pb_warnings
    if {[regexp {mom_seqnum} $mom_warning_info]} {
        MOM_reset_sequence $mom_sequence_number $mom_sequence_increment $mom_sequence_frequency
    }
    MOM_output_to_listing_device "pbstyle: warning at N[format %.0f $mom_seqnum]: $mom_warning_info"
}

# MOM_before_output -- Every block passes here in mom_o_buffer; the post may change it.
proc MOM_before_output {} {
    global mom_o_buffer pb_blocks pb_sys_strip_spaces
    incr pb_blocks
    if {$pb_sys_strip_spaces} {set mom_o_buffer [string trimright $mom_o_buffer]}
}

# MOM_start_of_group -- A program group: its own output file when group output is on.
proc MOM_start_of_group {} {
    global mom_group_name pb_groups pb_sys_group_output pb_group_files
    global mom_output_file_directory mom_output_file_basename
    incr pb_groups
    if {$pb_sys_group_output && [info exists mom_output_file_directory]} {
        set file ${mom_output_file_directory}${mom_output_file_basename}_[string tolower $mom_group_name].ptp
        MOM_open_output_file $file
        lappend pb_group_files $file
    }
}

# MOM_end_of_group -- Closes the group's output file.
proc MOM_end_of_group {} {
    global pb_group_files
    foreach file $pb_group_files {MOM_close_output_file $file}
    set pb_group_files {}
}

# Events the post does not write.
proc MOM_msys {} {}
proc MOM_set_csys {} {}
proc MOM_opstop {} {}
proc MOM_tool_preselect {} {}
