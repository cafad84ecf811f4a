# fivax.tcl --
#	fivax five-axis post: NX Post Builder-style event handlers. NX (or the
#	replay driver tools/replay.tcl) sources this file once and calls the
#	MOM_* handlers below with the mom_* globals set. The handlers hand the
#	CL data (mom_mcs_goto, mom_tool_axis: workpiece frame) to the planner,
#	turn its move records into blocks through the output layer, check
#	every block, and write with MOM_output_text. Uses only Tcl and the
#	MOM_* commands NX provides; no geometry here.
#
#	Settings: the global list fivax_settings (set by the machine's wrapper
#	post, post/<machine>.tcl, or by the replay driver before this file is
#	sourced), then the environment variable FIVAX_SETTINGS; keys are the
#	option names of [fivax::settings table], e.g. -machine, -tol, -msys.

# The version gate comes first and uses only Tcl 8.4 (NX 12 and earlier).
if {[catch {package require Tcl 8.6}]} {
    MOM_abort "fivax needs Tcl 8.6: NX 1847 or later (this NX runs Tcl [info patchlevel])"
    return
}

set fivax_post_dir [file dirname [file normalize [info script]]]
foreach fivax_dir [list [file join $fivax_post_dir lib] [file join $fivax_post_dir .. lib]] {
    if {[file exists [file join $fivax_dir pkgIndex.tcl]] && $fivax_dir ni $auto_path} {
        set auto_path [linsert $auto_path 0 $fivax_dir]
    }
}
package require fivax 0.1
unset fivax_dir

# fivax_abort --
#	Ends posting on the error msg (return options opts) of a handler:
#	MOM_abort with the CL position and operation, so that inside NX every
#	fivax error ends posting with a message; the message goes to the log
#	too.
proc fivax_abort {msg opts} {
    global mom_path_name
    # messages from the planner and the reader start with the position
    set where [fivax_where]
    if {![string match "event *" $where] && ![regexp {^(\S+:\d+|CL point \([^)]*\)): } $msg]} {
        set msg "$where: $msg"
    }
    if {[info exists mom_path_name] && $mom_path_name ne ""} {
        append msg " (operation $mom_path_name)"
    }
    global fivax
    if {[lindex [dict get $opts -errorcode] 0] ne "FIVAX"} {
        lappend fivax(log) "internal error: [dict get $opts -errorinfo]"
    }
    lappend fivax(log) "error: $msg"
    fivax_close_log
    MOM_abort $msg
    # (NX's MOM_abort does not return; a host whose one does gets the error)
    return -code error -errorcode [dict get $opts -errorcode] $msg
}

# fivax_handler --
#	Defines the proc name (no arguments: an event handler) that runs body
#	and turns any error of it into fivax_abort. (The body is the proc's
#	own, compiled with it: no uplevel on every event.)
proc fivax_handler {name body} {
    proc $name {} [list try $body on error {msg opts} {fivax_abort $msg $opts}]
}

# fivax_where -- Returns FILE:LINE of the current CL record (replay), else the operation and point.
proc fivax_where {} {
    global mom_cl_file mom_cl_line
    if {[info exists mom_cl_line]} {return "$mom_cl_file:$mom_cl_line"}
    global mom_mcs_goto
    if {[info exists mom_mcs_goto(2)]} {
        return [format "CL point (%.4f, %.4f, %.4f)" $mom_mcs_goto(0) $mom_mcs_goto(1) $mom_mcs_goto(2)]
    }
    return "event [MOM_ask_event_type]"
}

# fivax_out --
#	Writes NC lines (empty ones are skipped), kept for the dry run at the
#	end of the program when the setting -dryrun is on.
proc fivax_out {lines} {
    global fivax
    foreach line $lines {
        if {$line eq ""} continue
        MOM_output_text $line
        if {$fivax(dryrun)} {lappend fivax(lines) $line}
    }
}

# fivax_dryrun --
#	Runs the machine dry run (fivax::dryrun) on the lines written; its
#	events end posting with an error listing them (the first 20).
proc fivax_dryrun {} {
    global fivax
    if {!$fivax(dryrun)} return
    set events [fivax::dryrun run $fivax(machine) $fivax(lines) \
        -controller [dict get [$fivax(out) capabilities] controller] \
        -table-offset [dict get $fivax(settings) -table-offset]]
    set fivax(lines) {}
    if {![llength $events]} return
    set shown [fivax::dryrun format [lrange $events 0 19] [fivax_program_name]]
    if {[llength $events] > 20} {lappend shown "... [expr {[llength $events] - 20}] more"}
    fivax::Fail DRYRUN EVENTS "the dry run of the written program found [llength $events]\
        events:\n[join $shown \n]"
}

# fivax_log --
#	Keeps a line for the log file <output>.log (written at the end of the
#	program or on an error) and shows it on the listing device.
proc fivax_log {text} {
    global fivax
    lappend fivax(log) $text
    MOM_output_to_listing_device "fivax: $text"
}

# fivax_warn -- Reports a warning with the CL position.
proc fivax_warn {text} {
    global fivax
    incr fivax(warnings)
    fivax_log "warning: [fivax_where]: $text"
}

# fivax_close_log --
#	Writes the log lines to the log file: the setting -log, else
#	<output>.log beside the NC file when NX names one; nothing when there
#	is no line or no file.
proc fivax_close_log {} {
    global fivax mom_output_file_directory mom_output_file_basename
    if {![info exists fivax(log)] || ![llength $fivax(log)] || ![info exists fivax(settings)]} return
    set file [dict get $fivax(settings) -log]
    if {$file eq "" && [info exists mom_output_file_basename] && $mom_output_file_basename ne ""} {
        set file [file join $mom_output_file_directory $mom_output_file_basename.log]
    }
    if {$file eq ""} return
    set chan [open $file w]
    try {
        puts $chan [join $fivax(log) \n]
    } finally {
        close $chan
    }
    set fivax(log) {}
}

# fivax_setup --
#	Reads the settings and the machine at load time, and sets the mom_kin_*
#	NX needs: a 3-axis mill (NX passes the CL data through; fivax does the
#	kinematics), the output unit of the machine, arcs and helixes in pieces
#	of at most 360 degrees.
fivax_handler fivax_setup {
    global fivax fivax_settings fivax_post_dir env
    global mom_kin_machine_type mom_kin_output_unit mom_kin_arc_output_mode
    global mom_kin_helical_arc_output_mode mom_kin_nurbs_output_type
    if {![info exists fivax_settings]} {set fivax_settings {}}
    set given $fivax_settings
    if {[info exists env(FIVAX_SETTINGS)] && [string is list $env(FIVAX_SETTINGS)]} {
        lappend given {*}$env(FIVAX_SETTINGS)
    }
    set settings [fivax::settings parse $given]
    if {[dict get $settings -machine] eq ""} {
        dict set settings -machine [file join $fivax_post_dir .. machines hh-tilt45.tcl]
    }
    set fivax(settings) $settings
    set fivax(machine) [fivax::machine load [dict get $settings -machine]]
    set fivax(log) {}
    set fivax(warnings) 0
    set fivax(dryrun) [expr {[dict get $settings -dryrun] eq "on"}]
    set fivax(lines) {}
    set mom_kin_machine_type 3_axis_mill
    set mom_kin_output_unit [expr {[dict get $fivax(machine) units] eq "inch" ? "IN" : "MM"}]
    set mom_kin_arc_output_mode FULL_CIRCLE
    set mom_kin_helical_arc_output_mode FULL_CIRCLE
    set mom_kin_nurbs_output_type BSPLINE
}
fivax_setup

# fivax_program_name --
#	Returns the program's name: the output file's base name, else the part
#	name without directory and extension (NX gives a full path).
proc fivax_program_name {} {
    global mom_output_file_basename mom_part_name
    if {[info exists mom_output_file_basename] && $mom_output_file_basename ne ""} {
        return $mom_output_file_basename
    }
    if {[info exists mom_part_name] && $mom_part_name ne ""} {
        return [file rootname [lindex [split $mom_part_name "/\\"] end]]
    }
    return PART
}

fivax_handler MOM_start_of_program {
    global fivax fivax_post_dir mom_definition_file_name mom_output_unit
    set machine $fivax(machine)
    set unit [expr {[dict get $machine units] eq "inch" ? "IN" : "MM"}]
    if {[info exists mom_output_unit] && $mom_output_unit ne "" && $mom_output_unit ne $unit} {
        error "NX writes in $mom_output_unit but the machine [dict get $machine name] is in\
            [dict get $machine units]: set the output unit of the post to $unit"
    }
    # The .def NX loaded with this post is the one source of formats.
    set defFile [file join $fivax_post_dir fivax.def]
    if {[info exists mom_definition_file_name] && $mom_definition_file_name ne ""} {
        set defFile $mom_definition_file_name
    }
    set options [list -def [fivax::def load $defFile] -warn fivax_warn \
        -insert [dict get $fivax(settings) -insert] -arc-words [dict get $fivax(settings) -arc-words]]
    foreach key {-controller -tcp} {
        if {[dict get $fivax(settings) $key] ne ""} {
            lappend options $key [dict get $fivax(settings) $key]
        }
    }
    set fivax(out) [fivax::output create $machine {*}$options]
    set planOptions [fivax::settings pick $fivax(settings) motion]
    if {![dict get [$fivax(out) capabilities] inverse] && [dict get $planOptions -feed] eq "inverse"} {
        # no inverse time (Klartext): F is the feed of all axes together,
        # degrees counted as mm, which keeps the tip feed
        dict set planOptions -feed dpm
        fivax_log "note: [dict get [$fivax(out) capabilities] controller] has no inverse-time feed:\
            moves with rotary motion get the combined feed of all axes (-feed dpm)"
    }
    set fivax(plan) [fivax::motion create $machine -angle-step [$fivax(out) angleStep] \
        -output [$fivax(out) capabilities] {*}$planOptions]
    set fivax(verify) [fivax::verify create $machine {*}[fivax::settings pick $fivax(settings) verify]]
    set fivax(tool) {}
    set fivax(toolChanges) 0
    set fivax(positioned) 0
    set fivax(opStart) 0
    set fivax(zeroFeed) 0
    set fivax(cycle) {}
    fivax_out [$fivax(out) start "[fivax_program_name] - [dict get $machine name]" \
        [fivax_program_name]]
}

fivax_handler MOM_start_of_path {
    global fivax mom_path_name
    fivax_emit [$fivax(plan) startPath]
    fivax_out [list [$fivax(out) comment "OPERATION $mom_path_name"]]
    set fivax(opStart) 1
}

fivax_handler MOM_msys {
    global fivax mom_msys_origin mom_msys_matrix
    set m [lmap i {0 1 2 3 4 5 6 7 8} {set mom_msys_matrix($i)}]
    $fivax(plan) setFrame [list $mom_msys_origin(0) $mom_msys_origin(1) $mom_msys_origin(2)] \
        [lrange $m 0 2] [lrange $m 3 5]
}

proc MOM_first_tool {} {
    MOM_tool_change
}

# The tool number must be a positive integer; a length register of 0 (NX's
# "not set") means the tool number, and so does a negative one (with a
# warning). The spindle goes up to the tool-change height first; the next
# operation approaches from there.
fivax_handler MOM_tool_change {
    global fivax mom_tool_number mom_tool_length mom_tool_length_adjust_register
    if {![info exists mom_tool_number] || ![string is entier -strict $mom_tool_number]
            || $mom_tool_number < 1} {
        error "tool change to tool '[expr {[info exists mom_tool_number] ? $mom_tool_number : ""}]':\
            the tool needs a number of 1 or more (set it in the CAM tool)"
    }
    set len [dict get $fivax(machine) tool_length]
    if {[info exists mom_tool_length] && $mom_tool_length > 0} {set len $mom_tool_length}
    set adjust $mom_tool_number
    if {[info exists mom_tool_length_adjust_register]
            && [string is entier -strict $mom_tool_length_adjust_register]} {
        if {$mom_tool_length_adjust_register > 0} {
            set adjust $mom_tool_length_adjust_register
        } elseif {$mom_tool_length_adjust_register < 0} {
            fivax_warn "length register $mom_tool_length_adjust_register is negative: H$adjust (the tool number) is used"
        }
    }
    # the tool in the spindle again: no second change
    if {[list $mom_tool_number $adjust $len] eq $fivax(tool)} return
    set fivax(tool) [list $mom_tool_number $adjust $len]
    fivax_emit [$fivax(plan) endPlane]
    $fivax(plan) setTool $len
    $fivax(verify) setTool $len
    fivax_out [$fivax(out) toolChange $mom_tool_number $adjust]
    set fivax(positioned) 1
    incr fivax(toolChanges)
}

# Spindle and coolant: the handlers only mark the state when an operation
# starts (as Post Builder posts do); the first move of the operation
# writes it from the mom_spindle_* / mom_coolant_* globals, which NX sets
# at the start of the path whether the events fire or not.
fivax_handler MOM_spindle_rpm {
    global fivax
    if {!$fivax(opStart)} {fivax_spindle}
}

fivax_handler MOM_spindle_off {
    global fivax
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) spindleOff]
}

fivax_handler MOM_coolant_on {
    global fivax
    if {!$fivax(opStart)} {fivax_coolant}
}

fivax_handler MOM_coolant_off {
    global fivax
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) coolantOff]
}

# fivax_spindle --
#	Writes the spindle start from mom_spindle_* (nothing when off or
#	unset, nor for a speed of 0 or, with a warning, a negative one or one
#	below 1 rpm, which would be written S0).
proc fivax_spindle {} {
    global fivax mom_spindle_speed mom_spindle_direction mom_spindle_status
    if {![info exists mom_spindle_speed] || ![string is double -strict $mom_spindle_speed]} return
    if {$mom_spindle_speed < 1} {
        if {$mom_spindle_speed != 0} {
            fivax_warn "spindle speed $mom_spindle_speed rpm is below 1 rpm: not written"
        }
        return
    }
    if {[info exists mom_spindle_status] && $mom_spindle_status eq "OFF"} return
    set direction [expr {[info exists mom_spindle_direction] ? $mom_spindle_direction : "CLW"}]
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) spindle $mom_spindle_speed $direction]
}

# fivax_coolant -- Writes the coolant start from mom_coolant_* (nothing when off or unset).
proc fivax_coolant {} {
    global fivax mom_coolant_status mom_coolant_mode
    if {![info exists mom_coolant_status] || $mom_coolant_status ne "ON"} return
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) coolant [expr {[info exists mom_coolant_mode] ? $mom_coolant_mode : "ON"}]]
}

# The first motion of an operation: NX names it initial_move (after a tool
# change) or first_move in mom_motion_event; the motion type and the
# programmed feed tell rapid from feed (a cycle positions to its R plane).
fivax_handler MOM_initial_move fivax_first_move
fivax_handler MOM_first_move fivax_first_move

# fivax_first_move -- Writes the operation's start (spindle, coolant), then its first motion.
proc fivax_first_move {} {
    global fivax mom_motion_event mom_motion_type mom_programmed_feed_rate
    set fivax(opStart) 0
    if {!$fivax(positioned)} {
        # no tool change before: the position is unknown, start from the top
        fivax_emit [$fivax(plan) flush]
        fivax_out [$fivax(out) safeZ]
        set fivax(positioned) 1
    }
    fivax_spindle
    fivax_coolant
    set event [expr {[info exists mom_motion_event] ? $mom_motion_event : ""}]
    set type [expr {[info exists mom_motion_type] ? $mom_motion_type : ""}]
    if {$event in {rapid_move linear_move circular_move helix_move}} {
        MOM_$event
    } elseif {$type in {RAPID CYCLE} || ([info exists mom_programmed_feed_rate]
            && [string is double -strict $mom_programmed_feed_rate]
            && $mom_programmed_feed_rate == 0)} {
        fivax_motion rapid
    } else {
        fivax_motion feed
    }
}

fivax_handler MOM_rapid_move {fivax_motion rapid}

fivax_handler MOM_linear_move {fivax_motion feed}

# Arcs (CIRCLE + GOTO) and helixes go to the planner, which writes them as
# the control's arcs where they stay arcs in the blocks' frame, else as
# points within the arc tolerance.
fivax_handler MOM_circular_move fivax_arc
fivax_handler MOM_helix_move fivax_arc

# fivax_arc -- Hands the points of the current arc piece to the planner.
proc fivax_arc {} {
    global fivax mom_prev_mcs_goto mom_mcs_goto mom_arc_center mom_arc_axis
    global mom_arc_direction mom_arc_times mom_tool_axis mom_feed_rate
    set feed [expr {[info exists mom_feed_rate] ? $mom_feed_rate : 0.0}]
    if {!($feed > 0)} {fivax_feed_zero $feed arc}
    set xyz {0 1 2}
    fivax_emit [$fivax(plan) arc [lmap i $xyz {set mom_prev_mcs_goto($i)}] \
        [lmap i $xyz {set mom_mcs_goto($i)}] [lmap i $xyz {set mom_arc_center($i)}] \
        [lmap i $xyz {set mom_arc_axis($i)}] \
        [expr {$mom_arc_direction eq "CLW" ? -1 : 1}] \
        [expr {[info exists mom_arc_times] ? $mom_arc_times : 0}] \
        [lmap i $xyz {set mom_tool_axis($i)}] $feed \
        [fivax_where] [dict get $fivax(settings) -arc-tol]]
}

# NURBS (NX's spline motion, mom_kin_nurbs_output_type BSPLINE): the
# curve's points within the arc tolerance go to the planner.
fivax_handler MOM_nurbs_move fivax_nurbs

# fivax_nurbs -- Hands the points of the current NURBS (mom_nurbs_*) to the planner.
proc fivax_nurbs {} {
    global fivax mom_nurbs_order mom_nurbs_knot_count mom_nurbs_knots
    global mom_nurbs_point_count mom_nurbs_points mom_nurbs_weights
    set knots {}
    for {set i 0} {$i < $mom_nurbs_knot_count} {incr i} {lappend knots $mom_nurbs_knots($i)}
    set points {}
    set weights {}
    for {set i 0} {$i < $mom_nurbs_point_count} {incr i} {
        lappend points [list $mom_nurbs_points($i,0) $mom_nurbs_points($i,1) $mom_nurbs_points($i,2)]
        if {[info exists mom_nurbs_weights($i)]} {lappend weights $mom_nurbs_weights($i)}
    }
    set curve [fivax::curve nurbs [expr {$mom_nurbs_order - 1}] $knots $points $weights]
    foreach point [fivax::curve nurbsPoints $curve [dict get $fivax(settings) -arc-tol]] {
        fivax_motion feed $point
    }
}

fivax_handler MOM_gohome_move {fivax_motion rapid}

# fivax_motion --
#	Hands a CL point (default: the current mom_mcs_goto) with the current
#	tool axis to the planner and writes what is ready.
proc fivax_motion {kind {point ""}} {
    global fivax mom_mcs_goto mom_tool_axis mom_feed_rate
    set feed [expr {[info exists mom_feed_rate] ? $mom_feed_rate : 0.0}]
    if {$kind eq "feed" && !($feed > 0)} {set kind [fivax_feed_zero $feed]}
    if {$point eq ""} {
        set point [list $mom_mcs_goto(0) $mom_mcs_goto(1) $mom_mcs_goto(2)]
    }
    fivax_emit [$fivax(plan) add $kind $point \
        [list $mom_tool_axis(0) $mom_tool_axis(1) $mom_tool_axis(2)] \
        $feed [fivax_where]]
}

# fivax_feed_zero --
#	Returns the kind of a cutting move (what: move or arc) whose feed
#	(mm/min) is not above 0: rapid when the programmed feed is 0, which in
#	NX means rapid (nx-conventions.md, mom_programmed_feed_rate), with a
#	warning at the first such move; an error for an arc there (it has no
#	rapid form), a negative feed or a feed per revolution with the
#	spindle stopped (no control moves at it).
proc fivax_feed_zero {feed {what move}} {
    global fivax mom_programmed_feed_rate
    set programmed [expr {[info exists mom_programmed_feed_rate] ? $mom_programmed_feed_rate : $feed}]
    if {$programmed < 0 || $feed < 0} {
        error "cutting move at the negative feed $programmed: program a feed above 0"
    }
    if {$programmed != 0} {
        error "cutting move at a feed of 0 mm/min (a feed of $programmed per revolution\
            with the spindle stopped): start the spindle first"
    }
    if {$what eq "arc"} {
        error "arc at a programmed feed of 0 (rapid in NX): an arc has no rapid form, program a feed"
    }
    if {!$fivax(zeroFeed)} {
        set fivax(zeroFeed) 1
        fivax_warn "cutting moves at a programmed feed of 0 are written as rapids (NX: feed 0 means rapid)"
    }
    return rapid
}

# Drilling: the activation event keeps the cycle's data; each hole goes to
# the planner, which writes the control's canned cycle where the output
# layer has it and the tool is along the machine's Z, else moves.
foreach fivax_event {drill drill_dwell drill_deep drill_break_chip tap bore bore_dwell
        bore_drag bore_no_drag bore_back bore_manual} {
    fivax_handler MOM_$fivax_event [list fivax_cycle $fivax_event]
    fivax_handler MOM_${fivax_event}_move fivax_hole
}
unset fivax_event

# fivax_cycle -- Keeps the data of a cycle activated by NX event name event.
proc fivax_cycle {event} {
    global fivax mom_cycle_rapid_to mom_cycle_feed_to mom_cycle_retract_to mom_cycle_step1
    global mom_cycle_delay mom_cycle_feed_rate mom_feed_rate
    fivax_emit [$fivax(plan) flush]
    set rate [expr {[info exists mom_cycle_feed_rate] && $mom_cycle_feed_rate ne ""
        ? $mom_cycle_feed_rate : [info exists mom_feed_rate] ? $mom_feed_rate : 0.0}]
    set retract [expr {[info exists mom_cycle_retract_to] ? $mom_cycle_retract_to : $mom_cycle_rapid_to}]
    set fivax(cycle) [dict create event $event rapid $mom_cycle_rapid_to feed $mom_cycle_feed_to \
        retract $retract step [expr {[info exists mom_cycle_step1] ? $mom_cycle_step1 : 0.0}] \
        delay [expr {[info exists mom_cycle_delay] ? $mom_cycle_delay : 0.0}] rate $rate]
}

# fivax_hole -- Writes one hole of the active cycle at mom_mcs_goto on mom_tool_axis.
proc fivax_hole {} {
    global fivax mom_mcs_goto mom_tool_axis
    set cycle $fivax(cycle)
    fivax_emit [$fivax(plan) hole [list $mom_mcs_goto(0) $mom_mcs_goto(1) $mom_mcs_goto(2)] \
        [list $mom_tool_axis(0) $mom_tool_axis(1) $mom_tool_axis(2)] $cycle \
        [$fivax(out) canCycle [dict get $cycle event]] [fivax_where]]
}

fivax_handler MOM_cycle_off {
    global fivax
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) cycleOff]
    set fivax(cycle) {}
}

# fivax_emit --
#	Writes the planner's move records as blocks and checks each one;
#	retracts are reported on the listing and in the log. A value the
#	output refuses (beyond a MIN/MAX of the .def) names the move's CL
#	record.
proc fivax_emit {moves} {
    global fivax
    foreach move $moves {
        if {[dict get $move kind] eq "retract"} {
            fivax_log "retract at [dict get $move src]: [dict get $move note]"
        }
        try {
            set lines [$fivax(out) move $move]
        } trap {FIVAX NC} {msg opts} {
            if {[dict get $move src] ne ""} {set msg "[dict get $move src]: $msg"}
            return -code error -errorcode [dict get $opts -errorcode] $msg
        }
        # the move ends with its last block; those before it (G80 ...)
        # carry no CL point
        if {[llength $lines] > 1} {
            foreach line [lrange $lines 0 end-1] {
                fivax_out [list $line]
                $fivax(verify) block $line {kind none P {} t {} src {}}
            }
        }
        set last [lindex $lines end]
        fivax_out [list $last]
        $fivax(verify) block $last $move
    }
}

fivax_handler MOM_end_of_path {
    global fivax
    fivax_emit [$fivax(plan) endPath]
}

fivax_handler MOM_pprint {
    global fivax mom_pprint
    fivax_emit [$fivax(plan) flush]
    fivax_out [list [$fivax(out) comment $mom_pprint]]
}

fivax_handler MOM_insert {
    global fivax mom_Instruction
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) literal $mom_Instruction]
}

fivax_handler MOM_stop {
    global fivax
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) stop 0]
}

fivax_handler MOM_opstop {
    global fivax
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) stop 1]
}

fivax_handler MOM_delay {
    global fivax mom_delay_value mom_delay_mode
    fivax_emit [$fivax(plan) flush]
    if {[info exists mom_delay_value] && (![info exists mom_delay_mode]
            || $mom_delay_mode eq "SECONDS")} {
        fivax_out [$fivax(out) dwell $mom_delay_value]
    } else {
        fivax_warn "a dwell in spindle revolutions is not written: program it in seconds"
    }
}

fivax_handler MOM_end_of_program {
    global fivax fivax_summary
    fivax_emit [$fivax(plan) finish]
    fivax_out [$fivax(out) end]
    fivax_dryrun
    set fivax_summary [dict merge [$fivax(plan) stats] [$fivax(verify) summary] \
        [dict create toolChanges $fivax(toolChanges) postWarnings $fivax(warnings)]]
    MOM_output_to_listing_device "fivax summary: $fivax_summary"
    fivax_close_log
}
