# mom.tcl --
#	NX's MOM runtime, emulated for replay outside NX: CLSF records become
#	NX events (MOM_start_of_program, MOM_start_of_path, MOM_linear_move,
#	...) fired into the post's interpreter, with the mom_* globals NX would
#	set, and the MOM_* commands a post calls. Knows no geometry.
#	See spec/nx-conventions.md sections 1-3 and 5.5.

namespace eval ::fivax::mom {
    namespace export create run destroy stats postInterp
    variable seq 0
    # MOM_* commands with behaviour (implemented by Cmd<name> below).
    variable commands {
        MOM_output_literal MOM_output_text MOM_do_template MOM_force
        MOM_suppress MOM_set_seq_on MOM_set_seq_off MOM_reset_sequence
        MOM_abort MOM_abort_event MOM_output_to_listing_device
        MOM_log_message MOM_reload_variable MOM_reload_kinematics
        MOM_update_kinematics MOM_ask_event_type MOM_ask_env_var
        MOM_ask_address_value MOM_set_address_format MOM_display_message
        MOM_validate_machine_model MOM_has_definition_element
    }
    # MOM_* commands a Post Builder post may probe: harmless no-ops here.
    variable stubs {
        MOM_force_block MOM_disable_address MOM_enable_address MOM_incremental
        MOM_set_line_leader MOM_add_to_address_buffer MOM_add_to_block_buffer
        MOM_add_to_line_buffer MOM_open_output_file MOM_close_output_file
        MOM_load_definition_file MOM_set_env_var MOM_skip_handler_to_event
        MOM_set_debug_mode MOM_reload_iks_parameters MOM_load_kinematics
        MOM_cancel_suppress_force_once_per_event MOM_list_user_defined_events
        MOM_load_oper_ude_exps MOM_remove_file MOM_run_user_function
        MOM_ask_oper_csys MOM_ask_syslog_name MOM_check_out_license
        MOM_convert_point MOM_abort_program MOM_do_template_file
        MOM_map_to_rotated_csys MOM_rotate_mach_csys MOM_ask_ess_exp_value
        MOM_ask_init_junction_xform MOM_ask_machine_zero_junction_name
        MOM_post_oper_path MOM_run_postprocess MOM_before_each_add_var
    }
}

# ::fivax::mom::create --
#	Returns a runtime handle: a child interpreter holding only Tcl and the
#	MOM_* commands, with the post sourced into it.
#	Options: -post FILE (the event handler file), -def FILE (its .def),
#	-channel CHAN (NC output), -listing CMDPREFIX (called with each listing
#	line), -globals DICT (globals set in the post before it is sourced),
#	-autopath LIST (package path of the post interpreter).
proc ::fivax::mom::create {args} {
    variable seq
    set h ::fivax::mom::rt[incr seq]
    upvar #0 $h S
    array set S {
        post "" def "" channel "" listing "" globals {} autopath {}
    }
    foreach {opt val} $args {
        switch -- $opt {
            -post - -def - -channel - -listing - -globals - -autopath {
                set S([string range $opt 1 end]) $val
            }
            default {::fivax::Fail MOM OPTION "bad option \"$opt\": must be -post, -def, -channel, -listing, -globals or -autopath"}
        }
    }
    array set S {
        event "" records 0 blocks 0 warnings 0 events 0 pathOpen 0
        headerPending 0 rapid 0 circle {} cycle {} axis {0.0 0.0 1.0}
        point {} tool {} toolKey {} prevToolKey {} toolChanged 0 firstMove 1
        toolNames {} handlers {} msysPending 0 unknown {}
    }
    set S(nc) [::fivax::nc::create -sequence 0]
    if {$S(def) ne ""} {
        set S(defDict) [::fivax::def::load $S(def)]
        ::fivax::def::configure $S(nc) $S(defDict)
    } else {
        set S(defDict) {blocks {}}
    }
    set S(interp) [interp create]
    set child $S(interp)
    if {[llength $S(autopath)]} {
        $child eval [list set ::auto_path $S(autopath)]
    }
    foreach cmd [set [namespace current]::commands] {
        $child alias $cmd ::fivax::mom::Cmd[string range $cmd 3 end] $h
    }
    foreach cmd [set [namespace current]::stubs] {
        $child alias $cmd ::fivax::mom::Stub
    }
    dict for {name value} $S(globals) {
        $child eval [list set ::$name $value]
    }
    if {$S(post) ne ""} {
        $child eval [list source $S(post)]
    }
    return $h
}

# ::fivax::mom::postInterp -- Returns the post interpreter of runtime h.
proc ::fivax::mom::postInterp {h} {
    upvar #0 $h S
    return $S(interp)
}

# ::fivax::mom::destroy -- Deletes runtime h and its interpreter.
proc ::fivax::mom::destroy {h} {
    upvar #0 $h S
    if {[interp exists $S(interp)]} {interp delete $S(interp)}
    unset S
}

# ::fivax::mom::stats -- Returns a dict of counters: records, events, blocks, warnings.
proc ::fivax::mom::stats {h} {
    upvar #0 $h S
    dict create records $S(records) events $S(events) blocks $S(blocks) \
        warnings $S(warnings)
}

# ::fivax::mom::run --
#	Replays the CLSF file path through the post of runtime h: start of
#	program, every record as its NX events, end of program.
proc ::fivax::mom::run {h path} {
    upvar #0 $h S
    set reader [::fivax::clsf::open $path]
    try {
        Start $h $path
        while {[set rec [::fivax::clsf::next $reader]] ne ""} {
            incr S(records)
            Record $h $rec
        }
        Finish $h
    } finally {
        ::fivax::clsf::close $reader
    }
    stats $h
}

# ::fivax::mom::Start -- Sets program-level globals and fires MOM_start_of_program.
proc ::fivax::mom::Start {h path} {
    upvar #0 $h S
    set name [file rootname [file tail $path]]
    Globals $h [list mom_part_name $name mom_date [clock format [clock seconds]] \
        mom_logname fivax mom_ug_version fivax-replay mom_output_unit MM \
        mom_part_unit MM mom_machine_mode MILL mom_cl_file $path]
    Fire $h start_of_program
}

# ::fivax::mom::Finish -- Closes an open path and fires MOM_end_of_program.
proc ::fivax::mom::Finish {h} {
    upvar #0 $h S
    FlushHeader $h
    if {$S(pathOpen)} {EndPath $h}
    Fire $h end_of_program
    UnknownTotals $h
}

# ::fivax::mom::Globals -- Sets the globals of a flat name/value list in the post interp.
proc ::fivax::mom::Globals {h pairs} {
    upvar #0 $h S
    foreach {name value} $pairs {
        $S(interp) eval [list set ::$name $value]
    }
}

# ::fivax::mom::Array -- Sets global array name(0..n-1) from the list values.
proc ::fivax::mom::Array {h name values} {
    upvar #0 $h S
    set pairs {}
    set i 0
    foreach v $values {lappend pairs $i $v; incr i}
    $S(interp) eval [list array set ::$name $pairs]
}

# ::fivax::mom::Fire --
#	Calls MOM_<event> in the post if the post defines it (as NX does);
#	MOM_abort_event leaves the handler quietly. Returns 1 if a handler ran.
proc ::fivax::mom::Fire {h event} {
    upvar #0 $h S
    set proc MOM_$event
    if {![dict exists $S(handlers) $proc]} {
        dict set S(handlers) $proc [llength [$S(interp) eval [list info commands ::$proc]]]
    }
    if {![dict get $S(handlers) $proc]} {return 0}
    set previous $S(event)
    set S(event) $event
    incr S(events)
    try {
        $S(interp) eval [list $proc]
    } trap {FIVAX MOM ABORT_EVENT} {} {
    } finally {
        set S(event) $previous
    }
    return 1
}

# ::fivax::mom::Listing -- Passes one line to the listing command, if any.
proc ::fivax::mom::Listing {h text} {
    upvar #0 $h S
    if {[llength $S(listing)]} {{*}$S(listing) $text}
}

# ::fivax::mom::Where -- Returns FILE:LINE of record rec.
proc ::fivax::mom::Where {rec} {
    return "[dict get $rec file]:[dict get $rec line]"
}

# Record kinds that belong to an operation's header: they are gathered
# until the first other record, then MOM_start_of_path fires with them.
namespace eval ::fivax::mom {
    variable headerKinds {TLDATA CUTTER MSYS LOAD SELECT UNITS}
}

# ::fivax::mom::Record -- Maps one CLSF record to globals and events.
proc ::fivax::mom::Record {h rec} {
    upvar #0 $h S
    variable headerKinds
    set kind [dict get $rec kind]
    Globals $h [list mom_cl_line [dict get $rec line]]
    if {$S(headerPending) && $kind ni $headerKinds} {FlushHeader $h}
    switch -- $kind {
        GOTO      {Motion $h $rec}
        RAPID     {set S(rapid) 1}
        FEDRAT    {Feed $h $rec}
        CIRCLE    {set S(circle) $rec}
        TOOLPATH  {ToolPath $h $rec}
        TLDATA    {ToolData $h $rec}
        CUTTER    {ToolData $h $rec}
        MSYS      {Msys $h $rec}
        LOAD      {Load $h $rec}
        SELECT    {
            Globals $h [list mom_tool_preselect_number [dict get $rec tool] \
                mom_next_tool_number [dict get $rec tool]]
            if {!$S(headerPending)} {EnsurePath $h; Fire $h tool_preselect}
        }
        SPINDL    {Spindle $h $rec}
        COOLNT    {Coolant $h $rec}
        CUTCOM    {Cutcom $h $rec}
        FROM      {FromHome $h $rec from}
        GOHOME    {FromHome $h $rec gohome}
        TLAXIS    {set S(axis) [dict get $rec axis]}
        PPRINT    {Globals $h [list mom_pprint [dict get $rec text]]; Fire $h pprint}
        INSERT    {Globals $h [list mom_Instruction [dict get $rec text]]; Fire $h insert}
        PARTNO    {Globals $h [list mom_part_name [dict get $rec text]]}
        END_OF_PATH {if {$S(pathOpen)} {EndPath $h}}
        STOP      {EnsurePath $h; Fire $h stop}
        OPSTOP    {EnsurePath $h; Fire $h opstop}
        DELAY     {Delay $h $rec}
        CYCLE     {Cycle $h $rec}
        UNITS     {Units $h $rec}
        MULTAX - FINI - END {}
        default   {Unknown $h $rec}
    }
}

# ::fivax::mom::ToolPath -- Starts gathering a new operation's header.
proc ::fivax::mom::ToolPath {h rec} {
    upvar #0 $h S
    if {$S(pathOpen)} {EndPath $h}
    set name [dict get $rec name]
    Globals $h [list mom_path_name $name mom_operation_name $name \
        mom_tool_name [dict get $rec tool]]
    set S(toolKey) [list name [dict get $rec tool]]
    set S(headerPending) 1
}

# ::fivax::mom::ToolData -- Sets mom_tool_* from a TLDATA or CUTTER record.
proc ::fivax::mom::ToolData {h rec} {
    upvar #0 $h S
    set pairs [list mom_tool_diameter [dict get $rec diameter] \
        mom_tool_corner1_radius [dict get $rec corner1_radius]]
    if {[dict exists $rec length]} {
        lappend pairs mom_tool_length [dict get $rec length]
    }
    foreach {key var} {taper_angle mom_tool_taper_angle tip_angle mom_tool_tip_angle
        flute_length mom_tool_flute_length} {
        if {[dict exists $rec $key]} {lappend pairs $var [dict get $rec $key]}
    }
    if {[dict exists $rec type]} {
        lappend pairs mom_tool_type [expr {[dict get $rec type] eq "DRILL"
            ? "Drilling Tool" : "Milling Tool"}]
    }
    Globals $h $pairs
    if {!$S(headerPending)} {EnsurePath $h}
}

# ::fivax::mom::Msys --
#	Sets mom_msys_origin and mom_msys_matrix (X, Y, Z axis rows); MOM_msys
#	fires at once, or right after MOM_start_of_path inside a header.
proc ::fivax::mom::Msys {h rec} {
    upvar #0 $h S
    set x [dict get $rec xaxis]
    set y [dict get $rec yaxis]
    Array $h mom_msys_origin [dict get $rec origin]
    Array $h mom_msys_matrix [concat $x $y [::fivax::vec::cross $x $y]]
    if {$S(headerPending)} {
        set S(msysPending) 1
    } else {
        Fire $h msys
    }
}

# ::fivax::mom::Load -- LOAD/TOOL: sets the tool number and adjust register.
proc ::fivax::mom::Load {h rec} {
    upvar #0 $h S
    set n [dict get $rec tool]
    set adjust [dict get $rec adjust]
    if {$adjust eq ""} {set adjust $n}
    Globals $h [list mom_tool_number $n mom_tool_adjust_register $adjust \
        mom_tool_length_adjust_register $adjust mom_next_tool_number $n]
    set S(toolKey) [list number $n]
    set S(toolNumbered) 1
    if {!$S(headerPending)} {
        EnsurePath $h
        Fire $h load_tool
        ToolChange $h
    }
}

# ::fivax::mom::EnsurePath --
#	Opens an implicit operation for CL files without TOOL PATH records
#	(APT, Creo, Makino), so every event happens inside a path.
proc ::fivax::mom::EnsurePath {h} {
    upvar #0 $h S
    if {$S(pathOpen) || $S(headerPending)} {
        if {$S(headerPending)} {FlushHeader $h}
        return
    }
    Globals $h [list mom_path_name [$S(interp) eval {set ::mom_part_name}]]
    set S(headerPending) 1
    FlushHeader $h
}

# ::fivax::mom::FlushHeader --
#	Fires MOM_start_of_path with the gathered header, then the tool event
#	when the tool differs from the previous operation's.
proc ::fivax::mom::FlushHeader {h} {
    upvar #0 $h S
    if {!$S(headerPending)} return
    set S(headerPending) 0
    set S(pathOpen) 1
    set S(firstMove) 1
    set S(toolChanged) 0
    set child $S(interp)
    if {![info exists S(toolNumbered)]} {
        # No LOAD/TOOL: number tools by first appearance of their names.
        set key $S(toolKey)
        if {$key eq ""} {set key {name DEFAULT}}
        set idx [lsearch -exact $S(toolNames) $key]
        if {$idx < 0} {lappend S(toolNames) $key; set idx [expr {[llength $S(toolNames)] - 1}]}
        set n [expr {$idx + 1}]
        Globals $h [list mom_tool_number $n mom_tool_adjust_register $n \
            mom_tool_length_adjust_register $n]
    }
    foreach {var default} {mom_tool_length 0.0 mom_tool_diameter 0.0
        mom_tool_corner1_radius 0.0 mom_tool_name "" mom_tool_number 1} {
        if {![$child eval [list info exists ::$var]]} {
            Globals $h [list $var $default]
        }
    }
    Fire $h start_of_path
    if {$S(msysPending)} {
        set S(msysPending) 0
        Fire $h msys
    }
    ToolChange $h
}

# ::fivax::mom::ToolChange --
#	Fires MOM_first_tool for the program's first tool, MOM_tool_change when
#	the tool differs from the last one, nothing otherwise.
proc ::fivax::mom::ToolChange {h} {
    upvar #0 $h S
    set key [list [$S(interp) eval {set ::mom_tool_number}] $S(toolKey)]
    if {$key eq $S(prevToolKey)} return
    set first [expr {$S(prevToolKey) eq ""}]
    set S(prevToolKey) $key
    set S(toolChanged) 1
    Globals $h [list mom_tool_change_type AUTO]
    Fire $h [expr {$first ? "first_tool" : "tool_change"}]
}

# ::fivax::mom::EndPath -- Fires MOM_end_of_path and resets per-path state.
proc ::fivax::mom::EndPath {h} {
    upvar #0 $h S
    Fire $h end_of_path
    set S(pathOpen) 0
    set S(rapid) 0
    set S(circle) {}
    set S(cycle) {}
    unset -nocomplain S(toolNumbered)
}

# ::fivax::mom::Feed -- FEDRAT: sets the programmed feed and its mode.
proc ::fivax::mom::Feed {h rec} {
    upvar #0 $h S
    set value [dict get $rec value]
    set mode [string map {PERMIN MMPM PERREV MMPR} [dict get $rec unit]]
    if {$mode eq ""} {set mode MMPM}
    Globals $h [list mom_feed_rate_mode $mode mom_programmed_feed_rate $value \
        mom_feed_cut_value $value]
    if {$mode in {MMPR IPR}} {
        set rpm [$S(interp) eval {expr {[info exists ::mom_spindle_speed] ? $::mom_spindle_speed : 0.0}}]
        Globals $h [list mom_feed_rate_per_rev $value mom_feed_rate [expr {$value * $rpm}]]
    } else {
        Globals $h [list mom_feed_rate $value]
    }
    set S(feed) $value
}

# ::fivax::mom::Motion --
#	GOTO: fires the motion it completes (rapid, linear, circular, or a
#	cycle hole), through MOM_initial_move / MOM_first_move for the first
#	motion of a path, each preceded by MOM_before_motion.
proc ::fivax::mom::Motion {h rec} {
    upvar #0 $h S
    EnsurePath $h
    if {[llength [dict get $rec axis]]} {set S(axis) [dict get $rec axis]}
    SetPosition $h [dict get $rec point] $S(axis)
    if {[llength $S(cycle)]} {
        Globals $h [list mom_motion_event [dict get $S(cycle) event]_move \
            mom_motion_type CYCLE]
        Fire $h [dict get $S(cycle) event]_move
        return
    }
    if {$S(rapid)} {
        set event rapid_move
        Globals $h [list mom_motion_type RAPID mom_programmed_feed_rate 0]
    } elseif {[llength $S(circle)]} {
        set event circular_move
        Circle $h $S(circle)
        Globals $h [list mom_motion_type CUT]
    } else {
        set event linear_move
        if {![info exists S(feed)]} {
            ::fivax::Fail MOM FEED "[Where $rec]: GOTO: feed move before any FEDRAT"
        }
        Globals $h [list mom_motion_type CUT mom_programmed_feed_rate $S(feed) \
            mom_feed_rate $S(feed)]
    }
    set S(rapid) 0
    set S(circle) {}
    Globals $h [list mom_motion_event $event]
    Fire $h before_motion
    if {$S(firstMove)} {
        set S(firstMove) 0
        Fire $h [expr {$S(toolChanged) ? "initial_move" : "first_move"}]
    } else {
        Fire $h $event
    }
}

# ::fivax::mom::SetPosition --
#	Sets mom_mcs_goto, mom_tool_axis and their mom_prev_* copies.
#	mom_pos mirrors mom_mcs_goto: the replay runtime does no kinematics.
proc ::fivax::mom::SetPosition {h point axis} {
    upvar #0 $h S
    if {$S(point) ne ""} {
        Array $h mom_prev_mcs_goto $S(point)
        Array $h mom_prev_tool_axis $S(prevAxis)
    } else {
        Array $h mom_prev_mcs_goto $point
        Array $h mom_prev_tool_axis $axis
    }
    set S(point) $point
    set S(prevAxis) $axis
    Array $h mom_mcs_goto $point
    Array $h mom_tool_axis $axis
    Array $h mom_pos $point
}

# ::fivax::mom::Circle --
#	Sets mom_arc_* from a CIRCLE record. mom_arc_direction is the turning
#	sense about mom_arc_axis: NX-style CIRCLEs (11 numbers: NX, Makino)
#	turn clockwise about their vector, the short APT form (6 or 7 numbers:
#	Creo, SolidWorks CAM) counter-clockwise (nx-conventions.md 5.4).
proc ::fivax::mom::Circle {h rec} {
    Array $h mom_arc_center [dict get $rec center]
    Array $h mom_arc_axis [dict get $rec axis]
    set sense [expr {[llength [dict get $rec numbers]] >= 11 ? "CLW" : "CCLW"}]
    set pairs [list mom_arc_radius [dict get $rec radius] mom_arc_times \
        [dict get $rec times] mom_arc_direction $sense]
    foreach key {tolerance intol tool_diameter tool_radius} {
        if {[dict exists $rec $key]} {
            lappend pairs mom_arc_[string map {intol intol_fraction} $key] [dict get $rec $key]
        }
    }
    Globals $h $pairs
}

# ::fivax::mom::FromHome -- FROM and GOHOME: set the position and fire the event.
proc ::fivax::mom::FromHome {h rec which} {
    upvar #0 $h S
    EnsurePath $h
    if {[llength [dict get $rec axis]]} {set S(axis) [dict get $rec axis]}
    Array $h mom_${which}_pos [dict get $rec point]
    if {$which eq "from"} {
        Array $h mom_from_ref_pos [dict get $rec point]
        SetPosition $h [dict get $rec point] $S(axis)
        Globals $h [list mom_motion_type FROM mom_motion_event from_move]
        Fire $h from_move
    } else {
        SetPosition $h [dict get $rec point] $S(axis)
        Globals $h [list mom_motion_type GOHOME mom_motion_event gohome_move \
            mom_programmed_feed_rate 0]
        Fire $h before_motion
        Fire $h gohome_move
    }
    set S(rapid) 0
}

# ::fivax::mom::Spindle -- SPINDL: fires MOM_spindle_rpm or MOM_spindle_off.
proc ::fivax::mom::Spindle {h rec} {
    EnsurePath $h
    if {[dict get $rec state] eq "OFF"} {
        Globals $h [list mom_spindle_status OFF]
        Fire $h spindle_off
        return
    }
    set pairs [list mom_spindle_status ON mom_spindle_mode [dict get $rec mode]]
    if {[dict get $rec speed] ne ""} {
        lappend pairs mom_spindle_speed [dict get $rec speed] mom_spindle_rpm [dict get $rec speed]
    }
    if {[dict get $rec direction] ne ""} {
        lappend pairs mom_spindle_direction [dict get $rec direction]
    }
    Globals $h $pairs
    Fire $h spindle_rpm
}

# ::fivax::mom::Coolant -- COOLNT: fires MOM_coolant_on or MOM_coolant_off.
proc ::fivax::mom::Coolant {h rec} {
    EnsurePath $h
    set mode [dict get $rec mode]
    Globals $h [list mom_coolant_mode $mode mom_coolant_status [expr {$mode eq "OFF" ? "OFF" : "ON"}]]
    Fire $h [expr {$mode eq "OFF" ? "coolant_off" : "coolant_on"}]
}

# ::fivax::mom::Cutcom -- CUTCOM: fires MOM_cutcom_on or MOM_cutcom_off.
proc ::fivax::mom::Cutcom {h rec} {
    EnsurePath $h
    set mode [dict get $rec mode]
    Globals $h [list mom_cutcom_mode $mode mom_cutcom_status [expr {$mode eq "OFF" ? "OFF" : "ON"}] \
        mom_cutcom_plane [dict get $rec plane] mom_cutcom_register [dict get $rec register]]
    Fire $h [expr {$mode eq "OFF" ? "cutcom_off" : "cutcom_on"}]
}

# ::fivax::mom::Delay -- DELAY: fires MOM_delay with mom_delay_value or mom_delay_revs.
proc ::fivax::mom::Delay {h rec} {
    EnsurePath $h
    if {[dict exists $rec revs]} {
        Globals $h [list mom_delay_revs [dict get $rec revs] mom_delay_mode REVOLUTIONS]
    } else {
        Globals $h [list mom_delay_value [dict get $rec value] mom_delay_mode SECONDS]
    }
    Fire $h delay
}

# ::fivax::mom::Units -- UNITS: sets mom_part_unit and mom_output_unit (MM or IN).
proc ::fivax::mom::Units {h rec} {
    set unit [expr {[dict get $rec value] eq "INCH" ? "IN" : "MM"}]
    Globals $h [list mom_part_unit $unit mom_output_unit $unit]
}

# ::fivax::mom::Cycle --
#	CYCLE/<type>: sets mom_cycle_* from the RAPTO/FEDTO/RTRCTO/feed words
#	and fires the activation event (MOM_drill, MOM_drill_deep, ...);
#	following GOTOs become MOM_<cycle>_move; CYCLE/OFF fires MOM_cycle_off.
proc ::fivax::mom::Cycle {h rec} {
    upvar #0 $h S
    EnsurePath $h
    set type [string tolower [dict get $rec type]]
    if {$type eq "off"} {
        set S(cycle) {}
        Fire $h cycle_off
        return
    }
    set args [dict get $rec args]
    set event $type
    set first [string tolower [lindex $args 0]]
    if {$type eq "drill" && $first in {deep brkchp break_chip dwell text csink}} {
        set event drill_[string map {brkchp break_chip} $first]
    } elseif {$type eq "deep"} {
        set event drill_deep
    }
    if {![regexp {^[a-z][a-z0-9_]*$} $event]} {set event cycle}
    set pairs {}
    foreach {word var} {RAPTO mom_cycle_rapid_to FEDTO mom_cycle_feed_to
        RTRCTO mom_cycle_retract_to DEPTH mom_cycle_feed_to STEP mom_cycle_step1
        CLEAR mom_cycle_rapid_to MMPM mom_cycle_feed_rate IPM mom_cycle_feed_rate
        DWELL mom_cycle_delay} {
        set idx [lsearch -exact $args $word]
        if {$idx >= 0 && [string is double -strict [lindex $args $idx+1]]} {
            lappend pairs $var [lindex $args $idx+1]
        }
    }
    Globals $h [concat [list mom_cycle_type $type mom_cycle_event $event] $pairs]
    set S(cycle) [dict create event $event]
    if {![Fire $h $event]} {
        incr S(warnings)
        Listing $h "warning: [Where $rec]: the post has no MOM_$event: the holes of this cycle are not output"
    }
}

# ::fivax::mom::Unknown --
#	An unknown record: a warning with FILE:LINE (the first five of each
#	word; Finish counts the rest), and MOM_<word> fired if the post
#	defines it (the word is used only if it is a plain name).
proc ::fivax::mom::Unknown {h rec} {
    upvar #0 $h S
    set major [dict get $rec major]
    set word [string tolower [string map {- _ " " _} $major]]
    Globals $h [list mom_record_major $major mom_record_args [dict get $rec args]]
    if {[regexp {^[a-z][a-z0-9_]*$} $word] && [Fire $h $word]} return
    incr S(warnings)
    dict incr S(unknown) $major
    if {[dict get $S(unknown) $major] <= 5} {
        Listing $h "warning: [Where $rec]: unknown record '$major' ignored"
    }
}

# ::fivax::mom::UnknownTotals -- Lists how many unknown records of each word went unreported.
proc ::fivax::mom::UnknownTotals {h} {
    upvar #0 $h S
    dict for {major count} $S(unknown) {
        if {$count > 5} {
            Listing $h "warning: [expr {$count - 5}] more '$major' records ignored ($count in all)"
        }
    }
}

# ---- MOM_* commands (called from the post interpreter) --------------------

# ::fivax::mom::Write -- Writes one NC line to the output channel.
proc ::fivax::mom::Write {h text} {
    upvar #0 $h S
    if {$text eq ""} return
    incr S(blocks)
    if {$S(channel) ne ""} {puts $S(channel) $text}
}

# ::fivax::mom::Stub -- A MOM_* command NX has and replay does not need.
proc ::fivax::mom::Stub {args} {
    return ""
}

# MOM_output_text: one literal line, never numbered.
proc ::fivax::mom::Cmd_output_text {h text args} {
    Write $h $text
    return $text
}

# MOM_output_literal: one literal line, numbered when sequencing is on.
proc ::fivax::mom::Cmd_output_literal {h text args} {
    upvar #0 $h S
    set line [::fivax::nc::line $S(nc) $text]
    Write $h $line
    return $line
}

# MOM_do_template: formats a .def block template with the post's globals.
proc ::fivax::mom::Cmd_do_template {h name {mode ""}} {
    upvar #0 $h S
    if {![dict exists $S(defDict) blocks $name]} {
        ::fivax::Fail MOM TEMPLATE "MOM_do_template: no block template '$name'"
    }
    set words {}
    foreach word [dict get $S(defDict) blocks $name] {
        if {[dict exists $word literal]} {
            # A literal word goes out as a forced address-less text.
            lappend words {} [dict get $word literal]
            continue
        }
        set addr [dict get $word address]
        Leader $h $addr
        if {[dict exists $word expr] && [dict get $word expr] ne ""} {
            # Template text is post code (the .def), evaluated with expr
            # rules in the post interpreter as NX does; never CL data.
            try {
                set value [GlobalExpr $h [dict get $word expr]]
            } on error {msg} {
                if {[dict exists $word opt] && [dict get $word opt]} continue
                ::fivax::Fail MOM TEMPLATE "MOM_do_template $name: $addr: $msg"
            }
        } else {
            set value ""
        }
        lappend words $addr $value
    }
    set line [::fivax::nc::block $S(nc) $words]
    if {$mode ne "CREATE"} {Write $h $line}
    return $line
}

# ::fivax::mom::GlobalExpr --
#	Evaluates a .def expression (post code, never CL data) with expr rules
#	in the post interpreter's global namespace, as NX does, even while a
#	handler is running.
proc ::fivax::mom::GlobalExpr {h text} {
    upvar #0 $h S
    $S(interp) eval [list namespace eval :: [list expr $text]]
}

# ::fivax::mom::Leader --
#	Sets the leader of address addr from its .def LEADER expression (post
#	code such as [$mom_sys_leader(X)]), evaluated in the post interpreter.
proc ::fivax::mom::Leader {h addr} {
    upvar #0 $h S
    if {![dict exists $S(defDict) addresses $addr leader_expr]} return
    set text [dict get $S(defDict) addresses $addr leader_expr]
    if {$text eq ""} return
    ::fivax::nc::address $S(nc) $addr -leader [GlobalExpr $h $text]
}

# MOM_force Always|Once|Off addr...
proc ::fivax::mom::Cmd_force {h mode args} {
    upvar #0 $h S
    ::fivax::nc::force $S(nc) [string tolower $mode] $args
}

# MOM_suppress Always|Once|Off addr...
proc ::fivax::mom::Cmd_suppress {h mode args} {
    upvar #0 $h S
    ::fivax::nc::suppress $S(nc) [string tolower $mode] $args
}

# MOM_set_seq_on: returns the previous state.
proc ::fivax::mom::Cmd_set_seq_on {h} {
    upvar #0 $h S
    ::fivax::nc::sequence $S(nc) on
}

# MOM_set_seq_off: returns the previous state.
proc ::fivax::mom::Cmd_set_seq_off {h} {
    upvar #0 $h S
    ::fivax::nc::sequence $S(nc) off
}

# MOM_reset_sequence start incr ?freq?
proc ::fivax::mom::Cmd_reset_sequence {h start incr args} {
    upvar #0 $h S
    ::fivax::nc::resetSequence $S(nc) $start $incr
}

# MOM_abort msg: ends posting with an error.
proc ::fivax::mom::Cmd_abort {h {msg "MOM_abort"}} {
    ::fivax::Fail MOM ABORT $msg
}

# MOM_abort_event: leaves the current handler.
proc ::fivax::mom::Cmd_abort_event {h {msg ""}} {
    return -code error -errorcode {FIVAX MOM ABORT_EVENT} $msg
}

# MOM_output_to_listing_device text
proc ::fivax::mom::Cmd_output_to_listing_device {h text} {
    Listing $h $text
}

# MOM_log_message text
proc ::fivax::mom::Cmd_log_message {h text args} {
    Listing $h $text
}

# MOM_display_message msg title type ?buttons?: batch answer is button 1.
proc ::fivax::mom::Cmd_display_message {h msg args} {
    Listing $h $msg
    return 1
}

# MOM_reload_variable ?-a? var: the replay generator reads the post's globals directly.
proc ::fivax::mom::Cmd_reload_variable {h args} {
    return ""
}

# MOM_reload_kinematics: kinematics live in the post's library here.
proc ::fivax::mom::Cmd_reload_kinematics {h} {
    return ""
}

# MOM_update_kinematics: no legacy names to map in replay.
proc ::fivax::mom::Cmd_update_kinematics {h} {
    return ""
}

# MOM_ask_event_type: name of the current event.
proc ::fivax::mom::Cmd_ask_event_type {h} {
    upvar #0 $h S
    return $S(event)
}

# MOM_ask_env_var name: value of an environment variable, or "".
proc ::fivax::mom::Cmd_ask_env_var {h name} {
    if {[info exists ::env($name)]} {return $::env($name)}
    return ""
}

# MOM_ask_address_value addr
proc ::fivax::mom::Cmd_ask_address_value {h addr} {
    upvar #0 $h S
    ::fivax::nc::value $S(nc) $addr
}

# MOM_set_address_format addr format
proc ::fivax::mom::Cmd_set_address_format {h addr format} {
    upvar #0 $h S
    if {[dict exists $S(defDict) formats $format]} {
        set format [dict get $S(defDict) formats $format]
    }
    ::fivax::nc::address $S(nc) $addr -format $format
}

# MOM_validate_machine_model: replay has no machine model to validate.
proc ::fivax::mom::Cmd_validate_machine_model {h args} {
    return TRUE
}

# MOM_has_definition_element BLOCK|ADDRESS|FORMAT name
proc ::fivax::mom::Cmd_has_definition_element {h type name} {
    upvar #0 $h S
    set key [dict get {BLOCK blocks ADDRESS addresses FORMAT formats} [string toupper $type]]
    expr {[dict exists $S(defDict) $key $name] ? 1 : 0}
}
