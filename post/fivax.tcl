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
unset fivax_dir
# (before fivax_abort exists: a post copied without lib/ stops with a message)
if {[catch {package require fivax 0.1} fivax_msg]} {
    MOM_abort "fivax cannot load its library (lib/ must sit next to post/, see README.md,\
        Using the post inside NX): $fivax_msg"
    return
}
unset fivax_msg

# fivax_abort --
#	Ends posting on the error msg (return options opts) of a handler, the
#	one way every failure leaves the post: MOM_abort with the message,
#	the CL position and the operation, the message also in the log (never
#	a Tcl trace). An error that is no fivax error is marked "internal
#	error" (a bug to report), as the command line marks it. Its error
#	code stays in fivax(abortCode) for the host (MOM_abort takes only the
#	message).
proc fivax_abort {msg opts} {
    global fivax mom_path_name
    set code [dict get $opts -errorcode]
    set fivax(abortCode) $code
    if {[lindex $code 0] ne "FIVAX"} {set msg "internal error: $msg"}
    # messages from the planner and the reader start with the position
    set where [fivax_where]
    if {![string match "event *" $where] && ![regexp {^(\S+:\d+|CL point \([^)]*\)): } $msg]} {
        set msg "$where: $msg"
    }
    if {[info exists mom_path_name] && $mom_path_name ne ""} {
        append msg " (operation $mom_path_name)"
    }
    lappend fivax(log) "error: $msg"
    if {$code ne {FIVAX POST LOG}} {
        try {
            fivax_close_log
        } trap {FIVAX POST LOG} {logMsg} {
            append msg "; $logMsg"
        }
    }
    MOM_abort $msg
    # (NX's MOM_abort does not return; a host whose one does gets the error)
    return -code error -errorcode $code $msg
}

# fivax_handler --
#	Defines the proc name (no arguments: an event handler) that runs body
#	and turns any error of it into fivax_abort. (The body is a lambda,
#	compiled at the first call and kept, so that an error raised one
#	level up, fivax::Fail in the body itself, is caught too; no uplevel
#	on every event.)
proc fivax_handler {name body} {
    proc $name {} [list try [list apply [list {} $body]] on error {msg opts} {fivax_abort $msg $opts}]
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
    # (every line shown names its place: the count of the rest goes first)
    set shown [fivax::dryrun format [lrange $events 0 19] [fivax_program_name]]
    set rest [expr {[llength $events] > 20 ? " (the first 20 shown)" : ""}]
    fivax::Fail DRYRUN EVENTS "the dry run of the written program found [llength $events]\
        events$rest:\n[join $shown \n]"
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
#	is no line or no file. Errors: {FIVAX POST LOG} when the file cannot
#	be written (its lines are dropped).
proc fivax_close_log {} {
    global fivax mom_output_file_directory mom_output_file_basename
    if {![info exists fivax(log)] || ![llength $fivax(log)] || ![info exists fivax(settings)]} return
    set file [dict get $fivax(settings) -log]
    if {$file eq "" && [info exists mom_output_file_basename] && $mom_output_file_basename ne ""} {
        set file [file join $mom_output_file_directory $mom_output_file_basename.log]
    }
    if {$file eq ""} return
    set lines $fivax(log)
    set fivax(log) {}
    try {
        set chan [open $file w]
        try {
            puts $chan [join $lines \n]
        } finally {
            close $chan
        }
    } trap {POSIX} {msg} {
        fivax::Fail POST LOG "the log file cannot be written: $msg"
    }
}

# fivax_setup --
#	Reads the settings and the machine at load time, and sets the mom_kin_*
#	NX needs: a 3-axis mill (NX passes the CL data through; fivax does the
#	kinematics), the output unit of the machine, arcs and helixes in pieces
#	of at most 360 degrees; and the mom_sys_* the .def's LEADERs and
#	BLOCK_TEMPLATEs read (leaders and codes, as the output layer writes
#	them: fivax::output sysVars), so that a shop's own block in the .def,
#	written with MOM_do_template, has the post's words.
fivax_handler fivax_setup {
    global fivax fivax_settings env
    global mom_kin_machine_type mom_kin_output_unit mom_kin_arc_output_mode
    global mom_kin_helical_arc_output_mode mom_kin_nurbs_output_type
    if {![info exists fivax_settings]} {set fivax_settings {}}
    set given $fivax_settings
    if {[info exists env(FIVAX_SETTINGS)] && [string is list $env(FIVAX_SETTINGS)]} {
        lappend given {*}$env(FIVAX_SETTINGS)
    }
    set settings [fivax::settings complete [fivax::settings parse $given]]
    set fivax(settings) $settings
    set fivax(machine) [fivax::machine load [dict get $settings -machine]]
    foreach {name value} [fivax::output sysVars $fivax(machine) [dict get $settings -controller]] {
        set ::$name $value
    }
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
        fivax::Fail POST UNIT "NX writes in $mom_output_unit but the machine [dict get $machine name]\
            is in [dict get $machine units]: set the output unit of the post to $unit"
    }
    # The .def NX loaded with this post is the one source of formats; the
    # settings are checked against its resolution as the command line does.
    set defFile [file join $fivax_post_dir fivax.def]
    if {[info exists mom_definition_file_name] && $mom_definition_file_name ne ""} {
        set defFile $mom_definition_file_name
    }
    set fivax(out) [fivax::settings output $fivax(settings) $machine $defFile fivax_settings \
        -warn fivax_warn]
    set planOptions [fivax::settings pick $fivax(settings) motion]
    set caps [$fivax(out) capabilities]
    if {![dict get $caps inverse] && [dict get $planOptions -feed] eq "inverse"
            && ![dict get $caps tcp]} {
        # the planner writes -feed dpm for such a writer (in TCP mode F is
        # the tip feed itself: nothing to note)
        fivax_log "note: [dict get $caps controller] has no inverse-time feed:\
            moves with rotary motion get the combined feed of all axes (-feed dpm)"
    }
    set fivax(plan) [fivax::motion create $machine -angle-step [$fivax(out) angleStep] \
        -length-step [lindex [$fivax(out) resolution] 0] -output [$fivax(out) capabilities] {*}$planOptions]
    set fivax(verify) [fivax::verify create $machine {*}[fivax::settings pick $fivax(settings) verify]]
    set fivax(tool) {}
    set fivax(toolChanges) 0
    set fivax(positioned) 0
    set fivax(opStart) 0
    set fivax(zeroFeed) 0
    set fivax(cycle) {}
    set fivax(spindleOn) 0
    set fivax(cutcomWarned) 0
    set fivax(contactPrev) {}
    set fivax(opContacts) 0
    set fivax(c3d) {}
    fivax_cutcom3d_control_check $caps
    set fivax(cutcomQueue) {}
    set fivax(first) {}
    fivax_out [$fivax(out) start "[fivax_program_name] - [dict get $machine name]" \
        [fivax_program_name]]
}

fivax_handler MOM_start_of_path {
    global fivax mom_path_name
    fivax_emit [$fivax(plan) startPath]
    fivax_out [list [$fivax(out) comment "OPERATION $mom_path_name"]]
    set fivax(opStart) 1
    set fivax(cutcomWarned) 0
    set fivax(contactPrev) {}
    set fivax(opContacts) 0
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
# operation approaches from there. The tool change leaves the spindle
# stopped (M6 stops it on the controls fivax writes for; a tool change
# deferred to the spindle start takes the speed): the next cut starts it again. Every change is
# followed by the comment FIVAX TOOL n LENGTH L [RADIUS R], the tool
# the program was computed for, which the dry run reads.
fivax_handler MOM_tool_change {
    global fivax mom_tool_number mom_tool_length_adjust_register
    if {![info exists mom_tool_number] || ![string is entier -strict $mom_tool_number]
            || $mom_tool_number < 1} {
        set n [expr {[info exists mom_tool_number] ? $mom_tool_number : ""}]
        fivax::Fail POST TOOL "tool change to tool '$n': the tool needs a number of 1 or more\
            (set it in the CAM tool)"
    }
    set len [fivax_tool_length "tool $mom_tool_number"]
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
    fivax_out [list [$fivax(out) comment [fivax_tool_comment $mom_tool_number $len]]]
    set fivax(positioned) 1
    set fivax(spindleOn) 0
    incr fivax(toolChanges)
}

# fivax_tool_length --
#	Returns the length of the tool (what: its name in messages) being
#	changed to: the CL's (TLDATA, mom_tool_length above 0), else the
#	setting -tool-length, else, where the written X Y Z do not depend on
#	it (table-table machines, TCP mode), the machine file's tool_length.
#	Joint mode on a head machine with neither is an error: its X Y Z
#	would be computed for a length the machine does not have.
proc fivax_tool_length {what} {
    global fivax mom_tool_length
    if {[info exists mom_tool_length] && [string is double -strict $mom_tool_length]
            && $mom_tool_length > 0} {
        return $mom_tool_length
    }
    set given [dict get $fivax(settings) -tool-length]
    if {$given ne ""} {return $given}
    set machine $fivax(machine)
    if {![dict get [$fivax(out) capabilities] tcp] && [dict get $machine kind] ne "tabletable"} {
        fivax::Fail POST LENGTH "$what has no length in the CL (no TLDATA; a CUTTER height is\
            not a gauge length), and joint mode on [dict get $machine name] (a head machine)\
            computes X Y Z from it: give the tool's length with -tool-length MM"
    }
    return [dict get $machine tool_length]
}

# fivax_tool_comment --
#	Returns the text FIVAX TOOL n LENGTH L RADIUS R of tool number n of
#	length len: R from mom_tool_diameter, left out when the CL gives none;
#	with -cutcom3d post the radius and CORNER radius of the cutter the
#	program is compensated for.
proc fivax_tool_comment {n len} {
    global fivax mom_tool_diameter
    set text [format "FIVAX TOOL %d LENGTH %.3f" $n $len]
    if {[dict get $fivax(settings) -cutcom3d] eq "post"} {
        lassign [lindex [fivax_cutters] 1] D r
        append text [format " RADIUS %.3f CORNER %.3f" [expr {$D / 2.0}] $r]
    } elseif {[info exists mom_tool_diameter] && [string is double -strict $mom_tool_diameter]
            && $mom_tool_diameter > 0} {
        append text [format " RADIUS %.3f" [expr {$mom_tool_diameter / 2.0}]]
    }
    return $text
}

# Spindle and coolant: the handlers only mark the state when an operation
# starts (as Post Builder posts do); the first move of the operation
# writes it from the mom_spindle_* / mom_coolant_* globals, which NX sets
# at the start of the path whether the events fire or not. No cutting
# move is written with the spindle stopped (see fivax_cutting).
fivax_handler MOM_spindle_rpm {
    global fivax
    if {!$fivax(opStart)} {fivax_spindle}
}

fivax_handler MOM_spindle_off {
    global fivax
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) spindleOff]
    set fivax(spindleOn) 0
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
    global mom_spindle_speed mom_spindle_status
    if {[info exists mom_spindle_status] && $mom_spindle_status eq "OFF"} return
    set speed [fivax_cl_speed]
    if {$speed ne ""} {
        fivax_spindle_start $speed
    } elseif {[info exists mom_spindle_speed] && [string is double -strict $mom_spindle_speed]
            && $mom_spindle_speed != 0} {
        fivax_warn "spindle speed $mom_spindle_speed rpm is below 1 rpm: not written"
    }
}

# fivax_cl_speed --
#	Returns the CL's spindle speed (mom_spindle_speed, rpm), or "" when
#	there is none or it is below 1 rpm (it would be written S0).
proc fivax_cl_speed {} {
    global mom_spindle_speed
    if {![info exists mom_spindle_speed] || ![string is double -strict $mom_spindle_speed]
            || $mom_spindle_speed < 1} {
        return ""
    }
    return $mom_spindle_speed
}

# fivax_spindle_start -- Writes the spindle start at speed (rpm) in mom_spindle_direction.
proc fivax_spindle_start {speed} {
    global fivax mom_spindle_direction
    set direction [expr {[info exists mom_spindle_direction] ? $mom_spindle_direction : "CLW"}]
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) spindle $speed $direction]
    set fivax(spindleOn) 1
}

# fivax_cutting --
#	Starts the spindle, if it is stopped, before a cutting move (what:
#	its name in messages): at the CL's speed (its last one, with a
#	warning, when the CL stopped the spindle and did not start it again),
#	else at the machine file's default_rpm (with a warning), else an
#	error naming the operation.
proc fivax_cutting {what} {
    global fivax mom_spindle_status
    if {$fivax(spindleOn)} return
    set stopped [expr {[info exists mom_spindle_status] && $mom_spindle_status eq "OFF"}]
    set speed [fivax_cl_speed]
    set default [dict get $fivax(machine) default_rpm]
    if {$speed ne "" && $stopped} {
        fivax_warn "$what with the spindle stopped (SPINDL/OFF): started again at the CL's\
            last speed, [format %g $speed] rpm"
    } elseif {$speed eq "" && $default ne ""} {
        set speed $default
        fivax_warn "no spindle speed in the CL: started at the machine's default_rpm,\
            [format %g $speed] rpm"
    } elseif {$speed eq ""} {
        fivax::Fail POST SPINDLE "$what with the spindle stopped: the CL gives no speed (SPINDL)\
            and the machine [dict get $fivax(machine) name] has no default_rpm: set the speed in\
            the CAM operation, or a default_rpm in the machine file"
    }
    fivax_spindle_start $speed
}

# fivax_coolant -- Writes the coolant start from mom_coolant_* (nothing when off or unset).
proc fivax_coolant {} {
    global fivax mom_coolant_status mom_coolant_mode
    if {![info exists mom_coolant_status] || $mom_coolant_status ne "ON"} return
    fivax_emit [$fivax(plan) flush]
    fivax_out [$fivax(out) coolant [expr {[info exists mom_coolant_mode] ? $mom_coolant_mode : "ON"}]]
}

# 2D cutter compensation (CUTCOM/LEFT|RIGHT|OFF: MOM_cutcom_on/off with
# mom_cutcom_mode, mom_cutcom_register). The CL is the tool centre path
# (NX "centerline data", Creo OUTPUT_ON_CENTER, SolidWorks CAM's path
# offset by the tool radius): the output layer writes G41/G42 D (or the
# dialect's radius words) where the tool stands along the Z of the written X Y Z (3-axis,
# 3+2) for the control's wear correction, G40 (R0) at CUTCOM/OFF, and
# warns where it cannot (simultaneous five-axis). The planner holds moves
# (a whole operation for its work plane), so a change waits in
# fivax(cutcomQueue) for the first move from a later CL line (fivax_emit);
# without CL lines (inside NX) the planner's moves go out first. The
# operation's first CUTCOM says that the register holds the wear.
fivax_handler MOM_cutcom_on {
    global fivax mom_cutcom_mode mom_cutcom_register
    set mode [expr {[info exists mom_cutcom_mode] ? $mom_cutcom_mode : "ON"}]
    if {$mode ni {LEFT RIGHT}} {
        fivax_warn "CUTCOM/$mode names no side (LEFT or RIGHT): no cutter compensation written,\
            the CL path is posted as the tool centre path"
        return
    }
    set reg [lindex $fivax(tool) 0]
    if {[info exists mom_cutcom_register] && [string is entier -strict $mom_cutcom_register]
            && $mom_cutcom_register > 0} {
        set reg $mom_cutcom_register
    }
    if {![string is entier -strict $reg]} {set reg 0}
    fivax_cutcom $mode $reg
    if {$fivax(cutcomWarned)} return
    set fivax(cutcomWarned) 1
    fivax_warn "CUTCOM/$mode: the CL path is the tool centre path, written with the control's\
        cutter compensation (G41/G42, RL/RR) where the tool stands along Z: its register must\
        hold the wear (actual less programmed radius), not the radius"
}

fivax_handler MOM_cutcom_off {fivax_cutcom OFF 0}

# fivax_cutcom --
#	Passes the compensation side (LEFT, RIGHT, OFF) with register reg to
#	the output layer before the first move of a later CL line.
proc fivax_cutcom {side reg} {
    global fivax mom_cl_line
    if {[info exists mom_cl_line]} {
        lappend fivax(cutcomQueue) [list $mom_cl_line $side $reg]
    } else {
        fivax_emit [$fivax(plan) flush]
        $fivax(out) cutcom $side $reg
    }
}

# fivax_cutcom_due --
#	Passes the waiting compensation changes of CL lines before src (a
#	move's FILE:LINE; "" for a move of no CL line: none) to the output
#	layer, all of them when src is "end".
proc fivax_cutcom_due {src} {
    global fivax
    if {$src eq ""} return
    set line [expr {$src eq "end" ? Inf : [lindex [split $src :] end]}]
    while {[llength $fivax(cutcomQueue)]} {
        lassign [lindex $fivax(cutcomQueue) 0] at side reg
        if {!($at < $line)} break
        set fivax(cutcomQueue) [lrange $fivax(cutcomQueue) 1 end]
        $fivax(out) cutcom $side $reg
    }
}

# The first motion of an operation. NX fires MOM_initial_move for it
# after a tool change, else MOM_first_move ("This event occurs at the
# first motion after a tool change event. If the first motion is a cycle
# move, a MOM_initial_move event is generated for the
# mom_cycle_rapid_to_pos": NX's event dictionary, Post Builder's
# POSTBUILD/app/mom_vars_csv.txt). In MOM_first_move mom_motion_event
# names the motion's own event (rapid_move, linear_move, circular_move,
# nurbs_move, drill_move ...): Post Builder's MOM_first_move ends with
# `catch {MOM_$mom_motion_event}`; in MOM_initial_move it may be
# initial_move (the dictionary lists that value), and Post Builder's
# MOM_initial_move only positions (MOM_rapid_move or MOM_linear_move by
# mom_programmed_feed_rate) and
# leaves a cycle's first hole to the hole's own event after it. NX
# documents no more than that, so the post takes every order: the
# first-move handler writes the whole motion the event names (a cycle's
# hole, approached no lower than its R plane; an arc, a helix or a NURBS
# from its start), and the motion's own event fired after it at the same
# point is not written twice (fivax_again). A cycle's first motion that
# names no hole and is neither a hole's R point nor its top (NX's
# mom_cycle_rapid_to_pos tells) waits for the hole's event.
fivax_handler MOM_initial_move fivax_first_move
fivax_handler MOM_first_move fivax_first_move

# fivax_first_move -- Writes the operation's start (spindle, coolant), then its first motion.
proc fivax_first_move {} {
    global fivax mom_motion_event mom_motion_type mom_programmed_feed_rate
    set fivax(opStart) 0
    if {!$fivax(positioned)} {
        # no tool change before: the position is unknown, start from the top
        fivax_emit [$fivax(plan) flush]
        if {$fivax(tool) eq ""} {
            # no tool change at all: the tool in the spindle needs its length too
            set len [fivax_tool_length "the tool (the CL names none)"]
            set fivax(tool) [list "" "" $len]
            $fivax(plan) setTool $len
            $fivax(verify) setTool $len
        }
        fivax_out [$fivax(out) safeZ]
        set fivax(positioned) 1
    }
    fivax_spindle
    if {!$fivax(spindleOn) && [fivax_cl_speed] eq ""
            && [dict get $fivax(machine) default_rpm] ne ""} {
        # no speed in the CL: the machine's default, before the approach
        fivax_cutting "the operation"
    }
    fivax_coolant
    set event [expr {[info exists mom_motion_event] ? $mom_motion_event : ""}]
    set type [expr {[info exists mom_motion_type] ? $mom_motion_type : ""}]
    if {[llength $fivax(cycle)] && ($type eq "CYCLE" || ([string match *_move $event]
            && [string range $event 0 end-5] in $fivax(cycleEvents)))} {
        fivax_first_hole $event
        return
    }
    set kind line
    switch -- $event {
        circular_move - helix_move {
            global mom_prev_mcs_goto
            if {![info exists mom_prev_mcs_goto(2)]} {
                fivax::Fail POST FIRST "an arc is the program's first motion: it has no start point\
                    (program a move to its start before it)"
            }
            fivax_motion feed [lmap i {0 1 2} {set mom_prev_mcs_goto($i)}]
            fivax_arc
            set kind arc
        }
        nurbs_move {
            global mom_nurbs_points
            fivax_motion feed [lmap i {0 1 2} {set mom_nurbs_points(0,$i)}]
            fivax_nurbs
            set kind nurbs
        }
        rapid_move {fivax_motion rapid}
        linear_move {fivax_motion feed}
        default {
            if {$type in {RAPID CYCLE} || ([info exists mom_programmed_feed_rate]
                    && [string is double -strict $mom_programmed_feed_rate]
                    && $mom_programmed_feed_rate == 0)} {
                fivax_motion rapid
            } else {
                fivax_motion feed
            }
        }
    }
    set fivax(first) [list $kind [fivax_goto] $event]
}

# fivax_first_hole --
#	Writes the hole a cycle's first motion (event: its mom_motion_event)
#	carries, or keeps the motion's point for the hole event that follows
#	when it does not tell its hole (see fivax::motion firstHole).
proc fivax_first_hole {event} {
    global fivax mom_tool_axis mom_cycle_rapid_to_pos
    set rapidPos {}
    if {[info exists mom_cycle_rapid_to_pos(2)]} {
        set rapidPos [lmap i {0 1 2} {set mom_cycle_rapid_to_pos($i)}]
    }
    set P [fivax_goto]
    set t [lmap i {0 1 2} {set mom_tool_axis($i)}]
    set top [fivax::motion firstHole $P $t $fivax(cycle) $rapidPos \
        [expr {$event eq "[dict get $fivax(cycle) event]_move"}]]
    if {$top eq ""} {
        set fivax(first) [list pending $P $event]
        return
    }
    fivax_hole $top
    set fivax(first) [list hole $top $event]
}

# fivax_goto -- Returns mom_mcs_goto as a list.
proc fivax_goto {} {
    global mom_mcs_goto
    list $mom_mcs_goto(0) $mom_mcs_goto(1) $mom_mcs_goto(2)
}

# fivax_again --
#	Returns 1 when a motion event of kind (line, arc, nurbs, hole or
#	other) at the current mom_mcs_goto repeats the first motion the
#	first-move handler wrote (the order in which NX fires the motion's own
#	event after MOM_initial_move / MOM_first_move): it is not written
#	again. A hole that the first motion left to this event is drilled
#	here; an error when it never comes (fivax_settle) or when a curve
#	comes after a first motion that did not name it reached its end by a
#	straight move. (A first motion that is a full circle repeated in
#	pieces ending at the same point cannot be told from its own event
#	fired again: its second turn is not written.)
proc fivax_again {kind} {
    global fivax mom_tool_axis
    if {![llength $fivax(first)]} {return 0}
    lassign $fivax(first) first P event
    set here [fivax_goto]
    if {$first eq "pending" && $kind eq "hole"
            && [fivax::motion holeOfFirst $P [lmap i {0 1 2} {set mom_tool_axis($i)}] \
                $fivax(cycle) $here]} {
        set fivax(first) {}
        return 0
    }
    fivax_settle
    if {![fivax::motion samePoint $here $P]} {return 0}
    if {$first eq "line" && $kind in {arc nurbs} && $event ni {rapid_move linear_move}} {
        fivax::Fail POST FIRST "the operation's first motion came as a straight move to this\
            point (mom_motion_event '$event'), then as MOM_[expr {$kind eq "arc" ? "circular" : "nurbs"}]_move:\
            the curve cannot be written (NX should name the motion in mom_motion_event)"
    }
    expr {$first eq $kind}
}

# fivax_settle --
#	Ends the first-move state at the end of a cycle or operation: an error
#	when a cycle's first motion left its hole to an event that never came.
proc fivax_settle {} {
    global fivax
    lassign $fivax(first) first P event
    set fivax(first) {}
    if {$first eq "pending"} {
        fivax::Fail POST FIRST "the cycle's first motion (to [join $P ", "]) named no hole\
            (mom_motion_event '$event') and no hole event followed it there: the first hole\
            cannot be placed"
    }
}

fivax_handler MOM_rapid_move {
    if {![fivax_again line]} {fivax_motion rapid}
}

fivax_handler MOM_linear_move {
    if {![fivax_again line]} {fivax_motion feed}
}

# Arcs (CIRCLE + GOTO) and helixes go to the planner, which writes them as
# the control's arcs where they stay arcs in the blocks' frame, else as
# points within the arc tolerance.
fivax_handler MOM_circular_move {
    if {![fivax_again arc]} fivax_arc
}
fivax_handler MOM_helix_move {
    if {![fivax_again arc]} fivax_arc
}

# fivax_arc -- Hands the points of the current arc piece to the planner.
proc fivax_arc {} {
    global fivax mom_prev_mcs_goto mom_mcs_goto mom_arc_center mom_arc_axis
    global mom_arc_direction mom_arc_times mom_tool_axis mom_feed_rate
    set feed [expr {[info exists mom_feed_rate] ? $mom_feed_rate : 0.0}]
    if {!($feed > 0)} {fivax_feed_zero $feed arc}
    set mode [dict get $fivax(settings) -cutcom3d]
    if {$mode ne "off"} {
        global mom_contact_status
        if {[info exists mom_contact_status] && $mom_contact_status eq "ON"} {
            fivax::Fail CUTCOM ARC "-cutcom3d $mode: an arc with contact data cannot be\
                compensated: output the path as points (no CIRCLE records)"
        }
        set fivax(contactPrev) {}
    }
    fivax_cutting "arc"
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
fivax_handler MOM_nurbs_move {
    if {![fivax_again nurbs]} fivax_nurbs
}

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

fivax_handler MOM_gohome_move {
    fivax_again other
    fivax_motion rapid
}

# fivax_motion --
#	Hands a CL point (default: the current mom_mcs_goto) with the current
#	tool axis to the planner and writes what is ready.
proc fivax_motion {kind {point ""}} {
    global fivax mom_mcs_goto mom_tool_axis mom_feed_rate
    set feed [expr {[info exists mom_feed_rate] ? $mom_feed_rate : 0.0}]
    if {$kind eq "feed" && !($feed > 0)} {set kind [fivax_feed_zero $feed]}
    if {$kind eq "feed"} {fivax_cutting "cutting move"}
    if {$point eq ""} {
        set point [list $mom_mcs_goto(0) $mom_mcs_goto(1) $mom_mcs_goto(2)]
        switch -- [dict get $fivax(settings) -cutcom3d] {
            post {set point [fivax_cutcom3d $kind $point]}
            control {fivax_cutcom3d_normal $kind}
        }
    }
    fivax_emit [$fivax(plan) add $kind $point \
        [list $mom_tool_axis(0) $mom_tool_axis(1) $mom_tool_axis(2)] \
        $feed [fivax_where]]
}

# 3D tool-radius compensation by the post (-cutcom3d post): a cutting
# move whose GOTO came with contact data (NX's mom_contact_status ON,
# mom_contact_point, mom_contact_normal) goes to the planner moved for the
# cutter in the spindle (fivax::cutcom compensate: same contact, same
# normal); the rest of the pipeline (linearisation, limits, the block
# check, the dry run) runs on the moved point. Rapids and moves without
# contact data stay as programmed; an operation with none at all is
# warned about at its end.

# fivax_cutcom3d --
#	Returns the CL point of a move of kind (rapid or feed) for the cutter
#	in the spindle. Errors where the contact data do not fit the point,
#	or where the surface bends concavely tighter than the cutter's corner
#	radius between two consecutive contacts (it would gouge there).
proc fivax_cutcom3d {kind point} {
    global fivax mom_contact_status mom_contact_point mom_contact_normal mom_tool_axis
    if {$kind ne "feed" || ![info exists mom_contact_status] || $mom_contact_status ne "ON"} {
        set fivax(contactPrev) {}
        return $point
    }
    set xyz {0 1 2}
    set C [lmap i $xyz {set mom_contact_point($i)}]
    set n [lmap i $xyz {set mom_contact_normal($i)}]
    lassign [fivax_cutters] programmed actual
    if {[llength $fivax(contactPrev)]} {
        set why [fivax::cutcom fits [fivax::cutcom concaveRadius {*}$fivax(contactPrev) $C $n] \
            {*}$actual]
        if {$why ne ""} {
            fivax::Fail CUTCOM GOUGE [format "-cutcom3d post: %s: it would gouge where the\
                programmed cutter D %g r %g did not" $why {*}$programmed]
        }
    }
    set fivax(contactPrev) [list $C $n]
    incr fivax(opContacts)
    fivax::cutcom compensate $point [lmap i $xyz {set mom_tool_axis($i)}] $C $n $programmed $actual
}

# 3D tool-radius compensation by the control (-cutcom3d control): the
# CL point goes to the planner as programmed (the tip of the CL's cutter),
# and each cutting move record the planner makes of it is written with the
# unit surface normal of its contact (output layer: the dialect's
# cutcom3d form); the control offsets by its tool table's delta values.

# fivax_cutcom3d_control_check --
#	Errors when -cutcom3d control is set and the output layer (its
#	capabilities caps) has no 3D compensation of the control's own, or
#	writes no TCP mode (the normal is given in the workpiece frame).
proc fivax_cutcom3d_control_check {caps} {
    global fivax
    if {[dict get $fivax(settings) -cutcom3d] ne "control"} return
    if {![dict get $caps cutcom3d]} {
        fivax::Fail OPTION VALUE "fivax_settings: -cutcom3d control: [dict get $caps controller]\
            has no 3D tool-radius compensation of its own: use -cutcom3d post -tool-diameter MM\
            (the post moves the points for the cutter in the spindle)"
    }
    if {![dict get $caps tcp]} {
        fivax::Fail OPTION VALUE "fivax_settings: -cutcom3d control needs TCP mode (-tcp 1):\
            the control's 3D compensation takes the tip and the surface normal in the\
            workpiece frame"
    }
}

# fivax_cutcom3d_normal --
#	Keeps the unit surface normal of the GOTO being read (a cutting move
#	of kind feed with contact data), in the workpiece frame, for its move
#	records (see fivax_cutcom3d_attach), by its FILE:LINE.
proc fivax_cutcom3d_normal {kind} {
    global fivax mom_contact_status mom_contact_normal
    if {$kind ne "feed" || ![info exists mom_contact_status] || $mom_contact_status ne "ON"} return
    incr fivax(opContacts)
    dict set fivax(c3d) [fivax_where] \
        [$fivax(plan) workVector [lmap i {0 1 2} {set mom_contact_normal($i)}]]
}

# fivax_cutcom3d_attach --
#	Returns the move records moves with the key normal added to each
#	cutting move to a CL point with contact data: its normal. (In TCP
#	mode, which -cutcom3d control needs, the planner inserts no points
#	between CL points: the control keeps the tip on the line itself.)
proc fivax_cutcom3d_attach {moves} {
    global fivax
    lmap move $moves {
        set src [dict get $move src]
        if {[dict get $move kind] eq "feed" && [dict exists $fivax(c3d) $src]} {
            dict set move normal [dict get $fivax(c3d) $src]
            if {[dict get $move tag] eq ""} {dict unset fivax(c3d) $src}
        }
        set move
    }
}

# fivax_cutters --
#	Returns {programmed actual}, the cutters {D r} of -cutcom3d post: the
#	CL's (TLDATA: mom_tool_diameter, mom_tool_corner1_radius) and the one
#	in the spindle (-tool-diameter, -tool-corner-radius).
proc fivax_cutters {} {
    global fivax mom_tool_diameter mom_tool_corner1_radius
    fivax::cutcom cutters [expr {[info exists mom_tool_diameter] ? $mom_tool_diameter : 0.0}] \
        [expr {[info exists mom_tool_corner1_radius] ? $mom_tool_corner1_radius : 0.0}] \
        [dict get $fivax(settings) -tool-diameter] [dict get $fivax(settings) -tool-corner-radius]
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
        fivax::Fail POST FEED "cutting move at the negative feed $programmed: program a feed above 0"
    }
    if {$programmed != 0} {
        fivax::Fail POST FEED "cutting move at a feed of 0 mm/min (a feed of $programmed per\
            revolution with the spindle stopped): start the spindle first"
    }
    if {$what eq "arc"} {
        fivax::Fail POST FEED "arc at a programmed feed of 0 (rapid in NX): an arc has no rapid\
            form, program a feed"
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
set fivax(cycleEvents) {drill drill_dwell drill_deep drill_break_chip tap bore bore_dwell
    bore_drag bore_no_drag bore_back bore_manual}
foreach fivax_event $fivax(cycleEvents) {
    fivax_handler MOM_$fivax_event [list fivax_cycle $fivax_event]
    fivax_handler MOM_${fivax_event}_move {
        if {![fivax_again hole]} {fivax_hole [fivax_goto]}
    }
}
unset fivax_event

# fivax_cycle --
#	Keeps the data of a cycle activated by NX event name event; a dwell
#	in revolutions (mom_cycle_delay_mode REVOLUTIONS) becomes seconds.
proc fivax_cycle {event} {
    global fivax mom_cycle_rapid_to mom_cycle_feed_to mom_cycle_retract_to mom_cycle_step1
    global mom_cycle_delay mom_cycle_feed_rate mom_feed_rate mom_cycle_delay_mode mom_cycle_delay_revs
    fivax_emit [$fivax(plan) flush]
    set delay [expr {[info exists mom_cycle_delay] ? $mom_cycle_delay : 0.0}]
    if {[info exists mom_cycle_delay_mode] && $mom_cycle_delay_mode eq "REVOLUTIONS"} {
        set delay [fivax_revs_seconds $mom_cycle_delay_revs]
    }
    set rate [expr {[info exists mom_cycle_feed_rate] && $mom_cycle_feed_rate ne ""
        ? $mom_cycle_feed_rate : [info exists mom_feed_rate] ? $mom_feed_rate : 0.0}]
    set retract [expr {[info exists mom_cycle_retract_to] ? $mom_cycle_retract_to : $mom_cycle_rapid_to}]
    set fivax(cycle) [dict create event $event rapid $mom_cycle_rapid_to feed $mom_cycle_feed_to \
        retract $retract step [expr {[info exists mom_cycle_step1] ? $mom_cycle_step1 : 0.0}] \
        delay $delay rate $rate]
}

# fivax_revs_seconds --
#	Returns the seconds revs spindle revolutions take at the spindle speed
#	in effect (60 * revs / rpm). Errors when no speed in rpm is in effect
#	(none programmed, spindle off, or a surface speed): the dwell would be
#	written with a time it does not have.
proc fivax_revs_seconds {revs} {
    global mom_spindle_speed mom_spindle_mode mom_spindle_status
    if {![info exists mom_spindle_speed] || ![string is double -strict $mom_spindle_speed]
            || !($mom_spindle_speed >= 1)
            || ([info exists mom_spindle_status] && $mom_spindle_status eq "OFF")
            || ([info exists mom_spindle_mode] && $mom_spindle_mode ni {RPM ""})} {
        fivax::Fail POST DWELL "a dwell of $revs spindle revolutions with no spindle speed in rpm\
            in effect: program SPINDL/RPM before it, or the dwell in seconds"
    }
    expr {60.0 * $revs / $mom_spindle_speed}
}

# fivax_hole -- Writes one hole of the active cycle, its top at top on mom_tool_axis.
proc fivax_hole {top} {
    global fivax mom_tool_axis
    fivax_cutting "hole"
    set cycle $fivax(cycle)
    fivax_emit [$fivax(plan) hole $top \
        [list $mom_tool_axis(0) $mom_tool_axis(1) $mom_tool_axis(2)] $cycle \
        [$fivax(out) canCycle [dict get $cycle event]] [fivax_where]]
}

fivax_handler MOM_cycle_off {
    global fivax
    fivax_settle
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
    if {[llength $fivax(c3d)]} {set moves [fivax_cutcom3d_attach $moves]}
    foreach move $moves {
        if {[llength $fivax(cutcomQueue)]} {fivax_cutcom_due [dict get $move src]}
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
    fivax_settle
    set mode [dict get $fivax(settings) -cutcom3d]
    if {$mode ne "off" && !$fivax(opContacts)} {
        fivax_warn "-cutcom3d $mode: the operation has no contact data (CONTACT records):\
            its moves are posted for the CL's cutter, not compensated"
    }
    fivax_emit [$fivax(plan) endPath]
    fivax_cutcom_due end
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

# A dwell in seconds, or in spindle revolutions (mom_delay_mode
# REVOLUTIONS) as the seconds they take at the spindle speed in effect.
fivax_handler MOM_delay {
    global fivax mom_delay_value mom_delay_mode mom_delay_revs
    fivax_emit [$fivax(plan) flush]
    if {[info exists mom_delay_mode] && $mom_delay_mode eq "REVOLUTIONS"} {
        fivax_out [$fivax(out) dwell [fivax_revs_seconds $mom_delay_revs]]
    } else {
        fivax_out [$fivax(out) dwell $mom_delay_value]
    }
}

fivax_handler MOM_end_of_program {
    global fivax fivax_summary
    fivax_emit [$fivax(plan) finish]
    fivax_out [$fivax(out) end]
    fivax_dryrun
    set fivax_summary [dict merge [$fivax(plan) stats] [$fivax(verify) summary] \
        [dict create toolChanges $fivax(toolChanges) postWarnings $fivax(warnings) \
            dryrun $fivax(dryrun)]]
    MOM_output_to_listing_device "fivax summary: $fivax_summary"
    fivax_close_log
}
