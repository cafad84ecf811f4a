# mom.tcl --
#	NX's MOM runtime, emulated for replay outside NX: CLSF records become
#	NX events (MOM_start_of_program, MOM_start_of_path, MOM_linear_move,
#	...) fired into the post's interpreter, with the mom_* globals NX would
#	set, and the MOM_* commands a post calls. See spec/nx-conventions.md
#	sections 1-3 and 5.5. What it does as NX does (where the behaviour is
#	inferred, the comment says so and from what):
#	- spindle and coolant data of an operation's header are globals at
#	  MOM_start_of_path; MOM_spindle_rpm / MOM_coolant_on fire after the
#	  tool change, as user-defined events do;
#	- the first motion of an operation fires MOM_initial_move (after a tool
#	  change) or MOM_first_move in place of its own event, with
#	  mom_motion_event initial_move for a straight initial move, else
#	  naming the motion's event (Post Builder's MOM_first_move ends with
#	  `catch {MOM_$mom_motion_event}`; see MotionEvent); a cycle's first hole
#	  fires it at the hole's R point first, then the hole's event (NX's
#	  event dictionary: "If the first motion is a cycle move, a
#	  MOM_initial_move event is generated for the mom_cycle_rapid_to_pos");
#	- cycles fire their activation event (MOM_drill ...) with mom_cycle_*,
#	  one MOM_<cycle>_move per hole and MOM_cycle_off;
#	- arcs and helixes come in pieces by the post's mom_kin_arc_output_mode
#	  and mom_kin_helical_arc_output_mode, a helix as linear moves to a
#	  post without MOM_helix_move;
#	- lengths are converted from the CL's units to the post's
#	  mom_kin_output_unit;
#	- the globals NX sets on every event are set (NxGlobals, Move,
#	  SetPosition, Arc: mom_prev_pos, mom_last_pos, mom_current_motion,
#	  the rapid rate in mom_feed_rate, mom_pos_arc_*, the times),
#	  MOM_machine_mode fires before the first operation,
#	  MOM_start_of_group / _end_of_group around the program (one group,
#	  PROGRAM), as Post Builder posts expect (their header and
#	  numbering start there);
#	- MOM_do_template runs each .def block as one proc compiled in the
#	  post interpreter (TemplateScript); every line passes the post's
#	  MOM_before_output in mom_o_buffer; a sequence number past the .def's
#	  maximum is NX's warning to MOM_catch_warning; MOM_open_output_file
#	  and MOM_close_output_file open and close real files;
#	- only the CL words below reach the post; any other record is a
#	  warning with FILE:LINE.

namespace eval ::fivax::mom {
    namespace export create
    namespace ensemble create -prefixes 0
    # Record kinds that belong to an operation's header: they are gathered
    # until the first other record, then MOM_start_of_path fires with them.
    variable headerKinds {TLDATA CUTTER MSYS LOAD SELECT UNITS SPINDL COOLNT}
    # How far (mm) an arc's start or end may lie off its CIRCLE's radius.
    variable arcRadiusTol 0.01
    # CYCLE words: the NX cycle event of a cycle type and modifier.
    variable cycleEvents {
        DRILL drill  DRILL,DEEP drill_deep  DEEP drill_deep
        DRILL,BRKCHP drill_break_chip  BRKCHP drill_break_chip
        DRILL,DWELL drill_dwell  TAP tap  BORE bore  BORE,DWELL bore_dwell
        BORE,DRAG bore_drag  BORE,NODRAG bore_no_drag  BORE,BACK bore_back
        BORE,MANUAL bore_manual
    }
    # mm per length unit of the CL and output units.
    variable unitLength {MM 1.0 IN 25.4}
    variable Options {
        {-post text {} FILE "the post's event handler file (sourced in the post interpreter)"}
        {-def text {} FILE "the post's .def file (for MOM_do_template)"}
        {-channel text {} CHAN "channel the NC output goes to"}
        {-listing any {} CMD "command prefix called with each listing line"}
        {-globals any {} DICT "globals set in the post interpreter before the post is sourced"}
        {-autopath any {} LIST "package path of the post interpreter"}
    }
    # The body of the proc ::fivax::mom::runtime::Dispatch {ops} the
    # runtime defines in the post interpreter: what it does there, in one
    # crossing per batch of records (see Runtime Flush). ops is a flat list
    # of operations {op name value}: v sets the variable name (a global:
    # named with its :: by the runtime, no name to build here, or by its
    # bare name one of those the proc links first, the globals of every
    # motion), a sets the global array name from the pairs value, p sets a
    # position (see Runtime SetPosition: name is the previous {x y z i j
    # k}, value the current one), e fires MOM_name (MOM_abort_event leaves
    # the handler quietly) as NX calls it: at level #0, by its bare name
    # (Post Builder's CALLED_BY matches [info level -2] against
    # "MOM_linear_move*"). The event being fired is the variable event of
    # that namespace (for MOM_ask_event_type).
    # (The globals of every motion are linked by global once per batch, so
    # that set and lassign find local names; an error puts the event back
    # by an on-error handler, which unlike finally costs nothing when
    # there is none.)
    variable dispatch {
        variable event
        global mom_prev_mcs_goto mom_prev_tool_axis mom_mcs_goto mom_tool_axis mom_pos \
            mom_cl_line mom_motion_type mom_programmed_feed_rate mom_feed_rate mom_motion_event \
            mom_prev_pos mom_last_pos
        set saved $event
        try {
            foreach {op name value} $ops {
                switch -- $op {
                    v {set $name $value}
                    a {array set ::$name $value}
                    p {
                        lassign $name mom_prev_mcs_goto(0) mom_prev_mcs_goto(1) \
                            mom_prev_mcs_goto(2) mom_prev_tool_axis(0) \
                            mom_prev_tool_axis(1) mom_prev_tool_axis(2)
                        lassign $value mom_mcs_goto(0) mom_mcs_goto(1) mom_mcs_goto(2) \
                            mom_tool_axis(0) mom_tool_axis(1) mom_tool_axis(2)
                        lassign $value mom_pos(0) mom_pos(1) mom_pos(2)
                        lassign $name mom_prev_pos(0) mom_prev_pos(1) mom_prev_pos(2)
                        lassign $name mom_last_pos(0) mom_last_pos(1) mom_last_pos(2)
                    }
                    e {
                        set event $name
                        try {uplevel #0 [list MOM_$name]} trap {FIVAX MOM ABORT_EVENT} {} {}
                    }
                }
            }
        } on error {msg opts} {
            set event $saved
            return -options $opts $msg
        }
        set event $saved
    }
    # The body of MOM_output_text {text args} and of the proc
    # ::fivax::mom::runtime::Output {text args} in the post interpreter,
    # where every line goes out (MOM_output_text, MOM_output_literal,
    # MOM_do_template, whatever the post redefines): the line in mom_o_buffer
    # through the post's MOM_before_output, as NX passes it (hook: the
    # post has one; lines the handler writes itself skip it), then to
    # the runtime (Write). Returns the line written.
    variable output {
        variable ::fivax::mom::runtime::hook
        variable ::fivax::mom::runtime::busy
        if {$hook && !$busy && $text ne ""} {
            set busy 1
            try {
                set ::mom_o_buffer $text
                ::MOM_before_output
                set text $::mom_o_buffer
            } finally {
                set busy 0
            }
        }
        ::fivax::mom::runtime::Write $text
    }
    # The body of the MOM_do_template the runtime defines in the post
    # interpreter: the block template name's compiled proc (see
    # TemplateScript).
    variable doTemplate {
        set proc ::fivax::mom::runtime::tpl::$name
        if {[namespace which -command $proc] eq ""} {
            return -code error -errorcode {FIVAX MOM TEMPLATE} \
                "MOM_do_template: no block template '$name'"
        }
        $proc $mode
    }
    # Waiting operations (elements of the ops list) past which a record
    # ends the batch: the runtime crosses into the post interpreter when
    # about this many are waiting (a plain GOTO makes 21).
    variable batch 4000
    # MOM_* commands with behaviour (implemented by Cmd<name> below).
    variable commands {
        MOM_force MOM_suppress MOM_set_seq_on MOM_set_seq_off MOM_reset_sequence
        MOM_abort MOM_abort_event MOM_output_to_listing_device
        MOM_log_message MOM_reload_variable MOM_reload_kinematics
        MOM_update_kinematics MOM_ask_event_type MOM_ask_env_var
        MOM_ask_address_value MOM_set_address_format MOM_display_message
        MOM_validate_machine_model MOM_has_definition_element
        MOM_open_output_file MOM_close_output_file MOM_remove_file
    }
    # MOM_* commands a Post Builder post may probe: harmless no-ops here.
    variable stubs {
        MOM_force_block MOM_disable_address MOM_enable_address MOM_incremental
        MOM_set_line_leader MOM_add_to_address_buffer MOM_add_to_block_buffer
        MOM_add_to_line_buffer MOM_load_definition_file MOM_set_env_var MOM_skip_handler_to_event
        MOM_set_debug_mode MOM_reload_iks_parameters MOM_load_kinematics
        MOM_cancel_suppress_force_once_per_event MOM_list_user_defined_events
        MOM_load_oper_ude_exps MOM_run_user_function
        MOM_ask_oper_csys MOM_ask_syslog_name MOM_check_out_license
        MOM_convert_point MOM_abort_program MOM_do_template_file
        MOM_map_to_rotated_csys MOM_rotate_mach_csys MOM_ask_ess_exp_value
        MOM_ask_init_junction_xform MOM_ask_machine_zero_junction_name
        MOM_post_oper_path MOM_run_postprocess MOM_before_each_add_var
    }
}

# ::fivax::mom::create --
#	Returns a new Runtime object: a child interpreter holding only Tcl and
#	the MOM_* commands, with the post sourced into it; options as in the
#	Options table. Destroy it with "$runtime destroy".
proc ::fivax::mom::create {args} {
    variable Options
    Runtime new [::fivax::opts::parse $Options $args "mom create"]
}

# ::fivax::mom::FirstUnit --
#	Returns the length unit (MM or IN) of the CL file at path as its first
#	UNITS or FEDRAT record tells (NX's CLSF has no UNITS record: the
#	feed's unit, IPM or MMPM, tells), MM when neither says.
proc ::fivax::mom::FirstUnit {path} {
    set reader [::fivax::clsf::open $path]
    try {
        while {[dict size [set rec [$reader next]]]} {
            switch -- [dict get $rec kind] {
                UNITS {return [expr {[dict get $rec value] eq "INCH" ? "IN" : "MM"}]}
                FEDRAT {
                    switch -- [dict get $rec unit] {
                        IPM - IPR {return IN}
                        MMPM - MMPR {return MM}
                    }
                }
            }
        }
    } finally {
        $reader destroy
    }
    return MM
}

# ::fivax::mom::CycleParams --
#	Returns {event params} of a CYCLE record: the NX cycle event (drill,
#	drill_deep, drill_break_chip, drill_dwell, tap, bore, bore_dwell,
#	bore_drag, bore_no_drag, bore_back, bore_manual) and the dict of its
#	mom_cycle_* globals, lengths multiplied by scale. Reads the NX form
#	(RAPTO r, FEDTO f: signed distances along the tool axis from the hole
#	top; RTRCTO r|AUTO|MANUAL) and the APT form of Creo and others (CLEAR
#	c: the R plane c above the top; DEPTH d: the bottom d below it), STEP
#	s1 ?s2 s3?, DWELL s (seconds: mom_cycle_delay) or DWELL,REV,n
#	(mom_cycle_delay_revs, mom_cycle_delay_mode REVOLUTIONS), and the
#	feed MMPM|IPM|MMPR|IPR f. A DWELL word makes a drill or bore cycle
#	its dwelling form.
#	Errors: {FIVAX MOM CYCLE} "FILE:LINE: CYCLE: what" for a word or
#	cycle it does not know, a missing depth or R plane, or a bottom not
#	below the R plane: a hole never vanishes silently.
proc ::fivax::mom::CycleParams {rec scale} {
    variable cycleEvents
    set where "[Where $rec]: CYCLE"
    set type [string toupper [dict get $rec type]]
    set args [dict get $rec args]
    set key $type
    if {[lindex $args 0] in {DEEP BRKCHP DRAG NODRAG BACK MANUAL}} {
        append key ,[lindex $args 0]
        set args [lrange $args 1 end]
    }
    set p [dict create mom_cycle_type $key mom_cycle_retract_mode MANUAL \
        mom_cycle_feed_rate "" mom_cycle_feed_rate_mode "" mom_cycle_delay 0.0 \
        mom_cycle_delay_revs 0.0 mom_cycle_delay_mode SECONDS \
        mom_cycle_step1 0.0 mom_cycle_step2 0.0 mom_cycle_step3 0.0]
    set dwell 0
    set n [llength $args]
    for {set i 0} {$i < $n} {incr i} {
        set word [lindex $args $i]
        set next [lindex $args $i+1]
        set num [string is double -strict $next]
        switch -- $word {
            RAPTO - CLEAR - FEDTO - DEPTH - RTRCTO - STEP - DWELL - MMPM - IPM - MMPR - IPR {}
            default {::fivax::Fail MOM CYCLE "$where: unexpected [expr {[string is double -strict $word]
                ? "number $word" : "word '$word'"}]"}
        }
        if {$word eq "RTRCTO" && $next in {AUTO MANUAL}} {
            dict set p mom_cycle_retract_mode $next
            incr i
            continue
        }
        if {$word eq "DWELL" && $next eq "REV" && [string is double -strict [lindex $args $i+2]]} {
            dict set p mom_cycle_delay_revs [lindex $args $i+2]
            dict set p mom_cycle_delay_mode REVOLUTIONS
            set dwell 1
            incr i 2
            continue
        }
        if {!$num} {::fivax::Fail MOM CYCLE "$where: $word needs a number"}
        incr i
        switch -- $word {
            RAPTO - CLEAR {dict set p mom_cycle_rapid_to [expr {$next * $scale}]}
            FEDTO {dict set p mom_cycle_feed_to [expr {$next * $scale}]}
            DEPTH {dict set p mom_cycle_feed_to [expr {-$next * $scale}]}
            RTRCTO {
                dict set p mom_cycle_retract_to [expr {$next * $scale}]
                dict set p mom_cycle_retract_mode AUTO
            }
            DWELL {
                dict set p mom_cycle_delay $next
                set dwell 1
            }
            STEP {
                set j 1
                dict set p mom_cycle_step1 [expr {$next * $scale}]
                while {$j < 3 && [string is double -strict [lindex $args $i+1]]} {
                    incr j
                    incr i
                    dict set p mom_cycle_step$j [expr {[lindex $args $i] * $scale}]
                }
            }
            default {
                dict set p mom_cycle_feed_rate [expr {$next * $scale}]
                dict set p mom_cycle_feed_rate_mode $word
            }
        }
    }
    foreach {var what} {mom_cycle_feed_to "a depth (FEDTO or DEPTH)"
        mom_cycle_rapid_to "an R plane (RAPTO or CLEAR)"} {
        if {![dict exists $p $var]} {::fivax::Fail MOM CYCLE "$where: $key needs $what"}
    }
    if {![dict exists $p mom_cycle_retract_to]} {
        dict set p mom_cycle_retract_to [dict get $p mom_cycle_rapid_to]
    }
    if {[dict get $p mom_cycle_feed_to] >= [dict get $p mom_cycle_rapid_to]} {
        ::fivax::Fail MOM CYCLE "$where: the hole bottom ([dict get $p mom_cycle_feed_to]) is\
            not below the R plane ([dict get $p mom_cycle_rapid_to]) along the tool axis"
    }
    if {$dwell && $key in {DRILL BORE}} {append key ,DWELL}
    if {![dict exists $cycleEvents $key]} {
        ::fivax::Fail MOM CYCLE "$where: unsupported cycle $key"
    }
    list [dict get $cycleEvents $key] $p
}

# ::fivax::mom::TemplateScript --
#	Returns the script that defines, in the post interpreter, one proc
#	::fivax::mom::runtime::tpl::<name> {mode} per BLOCK_TEMPLATE of the
#	.def dict defDict: it evaluates the leaders of the block's addresses
#	and its words, compiled once with the proc (the .def is post code, as
#	NX takes it; CL data reach it only as the values of variables), hands
#	them to the runtime in one call (Block: TemplateBlock, with the
#	leaders that changed) and writes the block (Output) unless mode is
#	CREATE. A word
#	of a String address is text with the post's variables in it (subst),
#	any other an expression (expr); a \opt word that fails is left out,
#	any other failure is {FIVAX MOM TEMPLATE} "MOM_do_template NAME:
#	ADDRESS: message". The variables the texts name are the post's
#	globals; a text with a command in it runs in the global frame.
proc ::fivax::mom::TemplateScript {defDict} {
    set script "namespace eval ::fivax::mom::runtime::tpl {}\n"
    dict for {name words} [dict get $defDict blocks] {
        set body [TemplateBody $defDict $name $words]
        append script [list proc ::fivax::mom::runtime::tpl::$name {_fx_mode} $body] \n
    }
    return $script
}

# ::fivax::mom::TemplateBody -- Returns the body of block template name's proc (see TemplateScript).
proc ::fivax::mom::TemplateBody {defDict name words} {
    set vars {}
    set code {}
    set leaders 0
    foreach word $words {
        if {[dict exists $word literal]} {
            # a literal word goes out as a forced address-less text
            lappend code [list lappend _fx_w {} [dict get $word literal]]
            continue
        }
        set addr [dict get $word address]
        lappend code [list set _fx_a $addr]
        set leader [dict get $defDict addresses $addr leader_expr]
        if {$leader ne ""} {
            # a leader goes to the runtime when it changed
            lappend vars {*}[TemplateVars $leader]
            set leaders 1
            lappend code "set _fx_v \[[TemplateEval expr $leader]\]" \
                "if {!\[[list info exists _fx_leader($addr)]\] || \$[list _fx_leader($addr)] ne \$_fx_v} {[list lappend _fx_l $addr] \$_fx_v}"
        }
        set text [dict get $word expr]
        lappend vars {*}[TemplateVars $text]
        set eval [TemplateEval [expr {[::fivax::def::textAddress $defDict $addr]
            ? "subst" : "expr"}] $text]
        if {[dict get $word opt]} {
            lappend code "if {!\[[list catch $eval _fx_v]\]} {lappend _fx_w [list $addr] \$_fx_v}"
        } else {
            lappend code "lappend _fx_w [list $addr] \[$eval\]"
        }
    }
    set vars [lsearch -all -inline -not -glob [lsort -unique $vars] _fx_*]
    set head [list set _fx_w {}]\n[list set _fx_l {}]
    if {[llength $vars]} {set head [list global {*}$vars]\n$head}
    set tail {set _fx_line [::fivax::mom::runtime::Block $_fx_l $_fx_w]}
    if {$leaders} {
        set head "variable _fx_leader\n$head"
        append tail \n {foreach {_fx_a _fx_v} $_fx_l {set _fx_leader($_fx_a) $_fx_v}}
    }
    append tail \n {if {$_fx_mode eq "CREATE"} {return $_fx_line}} \n \
        {::fivax::mom::runtime::Output $_fx_line}
    set fail "[list return -code error -errorcode {FIVAX MOM TEMPLATE}] \[[list format \
        {MOM_do_template %s: %s: %s} $name] \$_fx_a \$_fx_msg\]"
    return "$head\n[list try [join $code \n] on error _fx_msg $fail]\n$tail"
}

# ::fivax::mom::TemplateEval --
#	Returns the command that evaluates .def text with how (expr or subst)
#	in a template proc: compiled in the proc, or in the global frame
#	(uplevel #0) when the text has a command in it.
proc ::fivax::mom::TemplateEval {how text} {
    if {[string first "\[" $text] >= 0} {return [list uplevel #0 [list $how $text]]}
    list $how $text
}

# ::fivax::mom::TemplateVars -- Returns the names of the variables .def text reads as $name or ${name}.
proc ::fivax::mom::TemplateVars {text} {
    set names {}
    foreach {- name} [regexp -all -inline {\$([A-Za-z0-9_]+)} $text] {lappend names $name}
    foreach {- name} [regexp -all -inline {\$\{([^\}]*)\}} $text] {lappend names $name}
    return $names
}

# ::fivax::mom::ArcFrame --
#	Returns {axis sense plane} of an arc about axis turning by sense (1:
#	counter-clockwise about it, -1 clockwise) as NX hands it to the post:
#	in a principal plane (plane XY, YZ or ZX) about that plane's positive
#	normal, the sense turned with it (a post writes G2 for CLW), else as
#	it is (plane OTHER).
proc ::fivax::mom::ArcFrame {axis sense} {
    set u [::fivax::vec::unit $axis]
    foreach c [list [lindex $u 2] [lindex $u 0] [lindex $u 1]] plane {XY YZ ZX} {
        if {abs($c) > 1.0 - 1e-9} {
            if {$c < 0} {return [list [::fivax::vec::scale -1.0 $axis] [expr {-$sense}] $plane]}
            return [list $axis $sense $plane]
        }
    }
    list $axis $sense OTHER
}

# ::fivax::mom::Where -- Returns FILE:LINE of record rec.
proc ::fivax::mom::Where {rec} {
    return "[dict get $rec file]:[dict get $rec line]"
}

# ::fivax::mom::Stub -- A MOM_* command NX has and replay does not need.
proc ::fivax::mom::Stub {args} {
    return ""
}


oo::class create ::fivax::mom::Runtime {
    # S: the options (post def channel listing globals autopath), the
    # post interpreter, the nc Writer and .def of MOM_do_template, and the
    # replay state (see the constructor).
    variable S

    constructor {opts} {
        dict for {opt value} $opts {set S([string range $opt 1 end]) $value}
        array set S {
            ops {} ready 0 records 0 blocks 0 warnings 0 events 0 pathOpen 0
            headerPending 0 rapid 0 circle {} cycle {} axis {0.0 0.0 1.0}
            point {} tool {} toolKey {} prevToolKey {} toolChanged 0 firstMove 1
            toolNames {} msysPending 0 unknown {} udes {}
            scale 1.0 clUnit MM outUnit MM unitsSeen 0 firstUnit MM nurbs {}
            files {} machineTime 0.0 cuttingTime 0.0 fpm 0.0 moveLength 0.0
            modeFired 0 contact {} contactOn 0 retractPos {}
        }
        set my [namespace which my]
        set S(nc) [::fivax::nc::create -sequence 0 -overflow [list $my SequenceOverflow] \
            -warn [list $my Warn]]
        if {$S(def) ne ""} {
            set S(defDict) [::fivax::def::load $S(def)]
            ::fivax::def::configure $S(nc) $S(defDict)
        } else {
            set S(defDict) {blocks {}}
        }
        set S(interp) [interp create]
        set child $S(interp)
        $child eval {namespace eval ::fivax::mom::runtime {variable event ""}}
        $child eval [list proc ::fivax::mom::runtime::Dispatch {ops} $::fivax::mom::dispatch]
        $child eval {namespace eval ::fivax::mom::runtime {variable hook 0; variable busy 0}}
        foreach proc {::fivax::mom::runtime::Output ::MOM_output_text} {
            $child eval [list proc $proc {text args} $::fivax::mom::output]
        }
        $child eval {
            proc ::MOM_output_literal {text args} {
                ::fivax::mom::runtime::Output [::fivax::mom::runtime::Line $text]
            }
        }
        foreach {cmd method} {Write Write Line Line Block TemplateBlock} {
            $child alias ::fivax::mom::runtime::$cmd [namespace which my] $method
        }
        $child eval [list proc ::MOM_do_template {name {mode ""}} $::fivax::mom::doTemplate]
        $child eval [::fivax::mom::TemplateScript $S(defDict)]
        if {[llength $S(autopath)]} {
            $child eval [list set ::auto_path $S(autopath)]
        }
        # The MOM_* commands call this object's Cmd_* methods.
        foreach cmd $::fivax::mom::commands {
            $child alias $cmd $my Cmd[string range $cmd 3 end]
        }
        foreach cmd $::fivax::mom::stubs {
            $child alias $cmd ::fivax::mom::Stub
        }
        dict for {name value} [dict merge [my NxGlobals] $S(globals)] {
            $child eval [list set ::$name $value]
        }
        set S(outputs) [expr {$S(channel) eq "" ? {} : [list $S(channel)]}]
        set S(mainFile) [expr {[dict exists $S(globals) mom_output_file_full_name]
            ? [dict get $S(globals) mom_output_file_full_name] : ""}]
        if {$S(post) ne ""} {
            $child eval [list source $S(post)]
        }
        # NX converts the CL data to the post's output unit.
        set unit [string toupper [my PostVar mom_kin_output_unit MM]]
        set S(outUnit) [expr {$unit in {IN INCH INCHES} ? "IN" : "MM"}]
        set S(rapidFeed) [my PostVar mom_kin_rapid_feed_rate \
            [expr {$S(outUnit) eq "IN" ? 400.0 : 10000.0}]]
        # (known now: Has would run waiting handlers from inside one)
        $child eval [list set ::fivax::mom::runtime::hook [my Has MOM_before_output]]
        my Has MOM_catch_warning
    }

    # NxGlobals --
    #	Returns the globals NX sets before it sources the post (name/value
    #	pairs): the post's files, the .def's SEQUENCE (mom_def_sequence_*),
    #	and those a Post Builder post reads on any event without asking
    #	whether they exist: the axes beyond three (0 on a three-axis
    #	machine), the output mode, the spindle axis of cycles (Z), the
    #	update flag of tool data, the times (minutes) and the warning text.
    method NxGlobals {} {
        set pairs [list mom_definition_file_name $S(def) mom_event_handler_file_name $S(post) \
            mom_update_post_cmds_from_tool 0 mom_warning_info "" mom_output_mode ABSOLUTE \
            mom_cycle_spindle_axis 2 mom_machine_time 0.0 mom_cutting_time 0.0 mom_seqnum 0 \
            mom_pos(3) 0.0 mom_pos(4) 0.0 mom_prev_pos(3) 0.0 mom_prev_pos(4) 0.0]
        set seq [expr {[dict exists $S(defDict) sequence] ? [dict get $S(defDict) sequence] : {}}]
        if {[llength $seq]} {
            foreach {key name} {start start incr increment freq frequency max maximum} {
                lappend pairs mom_def_sequence_$name [dict get $seq $key]
            }
        }
        return $pairs
    }

    destructor {
        if {[info exists S(interp)] && [interp exists $S(interp)]} {interp delete $S(interp)}
        if {[info exists S(files)]} {
            dict for {path chan} $S(files) {close $chan}
        }
        if {[info exists S(nc)]} {$S(nc) destroy}
    }

    # interp -- Returns the post interpreter (the globals set so far in it).
    method interp {} {
        my Flush
        return $S(interp)
    }

    # stats -- Returns a dict of counters: records, events, blocks, warnings.
    method stats {} {
        dict create records $S(records) events $S(events) blocks $S(blocks) \
            warnings $S(warnings)
    }

    # run --
    #	Replays the CLSF file path ("-": standard input) through the post:
    #	start of program, every record as its NX events, end of program.
    #	Errors: {FIVAX MOM EMPTY} for a file without records, {FIVAX MOM
    #	END} for one whose last record is no end of a CL file (see
    #	::fivax::clsf::ends): it was cut short. Both name the file's last line.
    method run {path} {
        if {$path eq "-"} {
            set reader [::fivax::clsf::channel stdin <stdin>]
        } else {
            set S(firstUnit) [::fivax::mom::FirstUnit $path]
            set reader [::fivax::clsf::open $path]
        }
        set batch $::fivax::mom::batch
        try {
            my Start $path
            # (dict size: ne "" would make each record's string)
            set last {}
            while {[dict size [set rec [$reader next]]]} {
                incr S(records)
                my Record $rec
                if {[llength $S(ops)] >= $batch} {my Flush}
                set last $rec
            }
            my CheckEnd [expr {$path eq "-" ? "<stdin>" : $path}] $last \
                [lindex [$reader position] 0]
            my Finish
            my Flush
        } on error {msg opts} {
            # what one crossing per record would have done before the error
            my FlushReady
            return -options $opts $msg
        } finally {
            $reader destroy
        }
        my stats
    }

    # CheckEnd --
    #	Raises the error of the CL file named file that ends at line lineNo
    #	after the record last ({} when it had none) without an end: empty,
    #	or cut short (the post would write what it read as a whole program).
    method CheckEnd {file last lineNo} {
        set where "$file:[expr {max($lineNo, 1)}]"
        if {![dict size $last]} {
            ::fivax::Fail MOM EMPTY "$where: the CL file has no records (empty, or only\
                comments and blank lines): no program to post"
        }
        if {![::fivax::clsf::ends $last]} {
            set what [dict get $last kind]
            if {$what eq "UNKNOWN"} {set what [dict get $last major]}
            ::fivax::Fail MOM END "$where: the CL file ends after $what (line\
                [dict get $last line]) without END-OF-PATH or FINI: it was cut short\
                (NX CLSF ends each operation with END-OF-PATH, APT ends with FINI)"
        }
    }

    # Start --
    #	Sets program-level globals and fires MOM_start_of_program, then
    #	MOM_start_of_group of the one program group (PROGRAM).
    method Start {path} {
        if {$path eq "-"} {
            set name PART
            set path <stdin>
        } else {
            set name [file rootname [file tail $path]]
        }
        my Globals [list mom_part_name $name mom_date [clock format [clock seconds]] \
            mom_logname fivax mom_ug_version fivax-replay mom_machine_mode MILL \
            mom_cl_file $path]
        my SetUnit $S(firstUnit)
        my Fire start_of_program
        my Globals {mom_group_name PROGRAM}
        my Fire start_of_group
    }

    # Finish -- Closes an open path and fires MOM_end_of_group and MOM_end_of_program.
    method Finish {} {
        if {[llength $S(nurbs)]} {my Nurbs}
        my FlushHeader
        if {$S(pathOpen)} {my EndPath}
        my Fire end_of_group
        my Fire end_of_program
        my UnknownTotals
    }

    # Globals -- Sets the globals of a flat name/value list in the post interp (see Flush).
    method Globals {pairs} {
        foreach {name value} $pairs {
            lappend S(ops) v ::$name $value
        }
    }

    # Array -- Sets global array name(0..n-1) from the list values (see Flush).
    method Array {name values} {
        set pairs {}
        set i 0
        foreach v $values {lappend pairs $i $v; incr i}
        lappend S(ops) a $name $pairs
    }

    # Fire --
    #	Calls MOM_<event> in the post if the post defines it (as NX does),
    #	after the globals set before it; MOM_abort_event leaves the handler
    #	quietly. The call waits in the batch (see Flush); the operations up
    #	to it are ready (S(ready): those a crossing per record would have
    #	done by now), with now 0 they wait for the next Fire (the handlers
    #	of one motion are ready together). Returns 1 if the post has the
    #	handler.
    method Fire {event {now 1}} {
        set ops [my Fires $event]
        if {[llength $ops]} {
            incr S(events)
            lappend S(ops) {*}$ops
        }
        if {$now} {set S(ready) [llength $S(ops)]}
        expr {[llength $ops] > 0}
    }

    # Fires --
    #	Returns the operation that calls MOM_<event> (see Fire): none when
    #	the post does not define it.
    method Fires {event} {
        if {![my Has MOM_$event]} {return {}}
        list e $event {}
    }

    # Flush --
    #	Does the waiting operations (globals, arrays, handlers) in the post
    #	interpreter, in order, in one call (see dispatch). They wait in a
    #	batch of records (see run) until the runtime reads the post
    #	interpreter (Child, interp), reports a line (Listing) or stops on an
    #	error, or the batch is full: the post sees the same globals at each
    #	event and runs the same events in the same order as with a crossing
    #	per record.
    method Flush {} {
        if {![llength $S(ops)]} return
        set ops $S(ops)
        set S(ops) {}
        set S(ready) 0
        $S(interp) eval [list ::fivax::mom::runtime::Dispatch $ops]
    }

    # FlushReady --
    #	Does the ready operations (see Fire) in the post interpreter; the
    #	others keep waiting.
    method FlushReady {} {
        if {!$S(ready)} return
        set rest [lrange $S(ops) $S(ready) end]
        set S(ops) [lrange $S(ops) 0 $S(ready)-1]
        try {
            my Flush
        } finally {
            lappend S(ops) {*}$rest
        }
    }

    # Child -- Returns the result of script in the post interpreter, the waiting operations done first.
    method Child {script} {
        my Flush
        $S(interp) eval $script
    }

    # Listing -- Passes one line to the listing command, if any, after the ready handlers ran.
    method Listing {text} {
        my FlushReady
        if {[llength $S(listing)]} {{*}$S(listing) $text}
    }

    # Warn -- Lists a warning of the runtime, prefixed as the post's are ("fivax: warning: ").
    method Warn {text} {
        my Listing "fivax: warning: $text"
    }

    # Record -- Maps one CLSF record to globals and events.
    method Record {rec} {
        set kind [dict get $rec kind]
        lappend S(ops) v mom_cl_line [dict get $rec line]
        if {$S(headerPending) && $kind ni $::fivax::mom::headerKinds} {my FlushHeader}
        if {$S(scale) != 1.0} {set rec [my Scale $rec]}
        if {[llength $S(nurbs)] && $kind ni {KNOT CNTRL}} {my Nurbs}
        switch -- $kind {
            GOTO      {my Motion $rec}
            RAPID     {set S(rapid) 1}
            FEDRAT    {my Feed $rec}
            CIRCLE    {set S(circle) $rec}
            TOOLPATH  {my ToolPath $rec}
            TLDATA    {my ToolData $rec}
            CUTTER    {my ToolData $rec}
            MSYS      {my Msys $rec}
            LOAD      {my Load $rec}
            SELECT    {
                my Globals [list mom_tool_preselect_number [dict get $rec tool] \
                    mom_next_tool_number [dict get $rec tool]]
                my Event tool_preselect
            }
            SPINDL    {my Spindle $rec}
            COOLNT    {my Coolant $rec}
            CUTCOM    {my Cutcom $rec}
            CONTACT   {my Contact $rec}
            FROM      {my FromHome $rec from}
            GOHOME    {my FromHome $rec gohome}
            TLAXIS    {set S(axis) [dict get $rec axis]}
            PPRINT    {my Globals [list mom_pprint [dict get $rec text]]; my Fire pprint}
            INSERT    {my Globals [list mom_Instruction [dict get $rec text]]; my Fire insert}
            PARTNO    {my Globals [list mom_part_name [dict get $rec text]]}
            END_OF_PATH {my ContactDone $rec; if {$S(pathOpen)} {my EndPath}}
            STOP      {my EnsurePath; my Fire stop}
            OPSTOP    {my EnsurePath; my Fire opstop}
            DELAY     {my Delay $rec}
            CYCLE     {my Cycle $rec}
            NURBS     {set S(nurbs) [dict create rec $rec knots {} cntrl {}]}
            KNOT - CNTRL {my NurbsData $rec}
            UNITS     {my Units $rec}
            MULTAX - FINI - END {}
            default   {my Unknown $rec}
        }
    }

    # Event --
    #	Fires a control event of the operation: gathered while the header is
    #	read (it fires after the tool change, as NX fires the operation's
    #	user-defined events), at once otherwise.
    method Event {event} {
        if {$S(headerPending)} {
            lappend S(udes) $event
        } else {
            my EnsurePath
            my Fire $event
        }
    }

    # ToolPath -- Starts gathering a new operation's header.
    method ToolPath {rec} {
        if {$S(pathOpen)} {my EndPath}
        set name [dict get $rec name]
        my Globals [list mom_path_name $name mom_operation_name $name \
            mom_tool_name [dict get $rec tool]]
        set S(toolKey) [list name [dict get $rec tool]]
        set S(headerPending) 1
    }

    # ToolData --
    #	Sets mom_tool_* from a TLDATA or CUTTER record. A CUTTER has no
    #	gauge length: mom_tool_length 0 (none), not the previous tool's.
    method ToolData {rec} {
        set pairs [list mom_tool_diameter [dict get $rec diameter] \
            mom_tool_corner1_radius [dict get $rec corner1_radius] \
            mom_tool_length [expr {[dict exists $rec length] ? [dict get $rec length] : 0.0}]]
        foreach {key var} {taper_angle mom_tool_taper_angle tip_angle mom_tool_tip_angle
            flute_length mom_tool_flute_length} {
            if {[dict exists $rec $key]} {lappend pairs $var [dict get $rec $key]}
        }
        if {[dict exists $rec type]} {
            lappend pairs mom_tool_type [expr {[dict get $rec type] eq "DRILL"
                ? "Drilling Tool" : "Milling Tool"}]
        }
        my Globals $pairs
        if {!$S(headerPending)} {my EnsurePath}
    }

    # Msys --
    #	Sets mom_msys_origin and mom_msys_matrix (X, Y, Z axis rows); MOM_msys
    #	fires at once, or right after MOM_start_of_path inside a header.
    method Msys {rec} {
        set x [dict get $rec xaxis]
        set y [dict get $rec yaxis]
        my Array mom_msys_origin [dict get $rec origin]
        my Array mom_msys_matrix [concat $x $y [::fivax::vec::cross $x $y]]
        if {$S(headerPending)} {
            set S(msysPending) 1
        } else {
            my Fire msys
        }
    }

    # Load -- LOAD/TOOL: sets the tool number and adjust register.
    method Load {rec} {
        set n [dict get $rec tool]
        set adjust [dict get $rec adjust]
        if {$adjust eq ""} {set adjust $n}
        my Globals [list mom_tool_number $n mom_tool_adjust_register $adjust \
            mom_tool_length_adjust_register $adjust mom_next_tool_number $n]
        set S(toolKey) [list number $n]
        set S(toolNumbered) 1
        if {!$S(headerPending)} {
            my EnsurePath
            my Fire load_tool
            my ToolChange
        }
    }

    # EnsurePath --
    #	Opens an implicit operation for CL files without TOOL PATH records
    #	(APT, Creo, Makino), so every event happens inside a path.
    method EnsurePath {} {
        if {$S(pathOpen) || $S(headerPending)} {
            if {$S(headerPending)} {my FlushHeader}
            return
        }
        my Globals [list mom_path_name [my Child {set ::mom_part_name}]]
        set S(headerPending) 1
        my FlushHeader
    }

    # FlushHeader --
    #	Fires MOM_machine_mode before the first operation (NX fires it when
    #	the mode changes: replay's operations are all MILL), then
    #	MOM_start_of_path with the gathered header (tool, spindle and
    #	coolant globals set; tool and spindle globals the CL never gave at
    #	NX's defaults: 0, CLW, RPM), MOM_msys, the tool event when the tool differs
    #	from the previous operation's, then the gathered control events.
    method FlushHeader {} {
        if {!$S(headerPending)} return
        set S(headerPending) 0
        set S(pathOpen) 1
        set S(firstMove) 1
        set S(toolChanged) 0
        # no TOOL PATH nor LOAD yet (an implicit operation): no tool to change to
        set toolKnown [expr {$S(toolKey) ne ""}]
        if {$toolKnown && ![info exists S(toolNumbered)]} {
            # No LOAD/TOOL: number tools by first appearance of their names.
            set key $S(toolKey)
            set idx [lsearch -exact $S(toolNames) $key]
            if {$idx < 0} {lappend S(toolNames) $key; set idx [expr {[llength $S(toolNames)] - 1}]}
            set n [expr {$idx + 1}]
            my Globals [list mom_tool_number $n mom_tool_adjust_register $n \
                mom_tool_length_adjust_register $n]
        }
        foreach {var default} {mom_tool_length 0.0 mom_tool_diameter 0.0
            mom_tool_corner1_radius 0.0 mom_tool_name "" mom_spindle_speed 0.0
            mom_spindle_direction CLW mom_spindle_mode RPM mom_fixture_offset_value 0
            mom_stock_part 0.0 mom_stock_floor 0.0} {
            if {![my Child [list info exists ::$var]]} {
                my Globals [list $var $default]
            }
        }
        if {!$S(modeFired)} {
            # the mode of every operation replay posts (MILL) is set at the start
            set S(modeFired) 1
            my Fire machine_mode
        }
        my Fire start_of_path
        if {$S(msysPending)} {
            set S(msysPending) 0
            my Fire msys
        }
        if {$toolKnown} {my ToolChange}
        set udes $S(udes)
        set S(udes) {}
        foreach event $udes {my Fire $event}
    }

    # ToolChange --
    #	Fires MOM_first_tool for the program's first tool, MOM_tool_change when
    #	the tool differs from the last one, nothing otherwise (tools come
    #	from the CL only: TOOL PATH, LOAD, LOADTL).
    method ToolChange {} {
        set key [list [my Child {set ::mom_tool_number}] $S(toolKey)]
        if {$key eq $S(prevToolKey)} return
        set first [expr {$S(prevToolKey) eq ""}]
        set S(prevToolKey) $key
        set S(toolChanged) 1
        my Globals [list mom_tool_change_type AUTO]
        my Fire [expr {$first ? "first_tool" : "tool_change"}]
    }

    # EndPath -- Fires MOM_end_of_path and resets per-path state.
    method EndPath {} {
        my Fire end_of_path
        set S(pathOpen) 0
        set S(rapid) 0
        set S(circle) {}
        set S(cycle) {}
        unset -nocomplain S(toolNumbered)
    }

    # Feed --
    #	FEDRAT: sets the programmed feed and its mode. IPM or IPR before any
    #	motion and UNITS record makes the CL's unit inch (NX's CLSF has no
    #	UNITS record: the feed's unit tells); after motion taken as mm it is
    #	an error.
    #	Errors: {FIVAX MOM UNITS}.
    method Feed {rec} {
        set value [dict get $rec value]
        set word [dict get $rec unit]
        if {$word in {IPM IPR} && $S(clUnit) ne "IN"} {
            if {$S(point) ne "" || $S(unitsSeen)} {
                ::fivax::Fail MOM UNITS "[::fivax::mom::Where $rec]: FEDRAT: $word, but the CL's\
                    lengths are in mm (UNITS/INCHES missing before the motion?)"
            }
            set old $S(scale)
            my SetUnit IN
            set value [expr {$value / $old * $S(scale)}]
        }
        # the value is in the output unit now
        set perRev [expr {$word in {MMPR IPR PERREV}}]
        set mode [lindex [expr {$S(outUnit) eq "IN" ? {IPM IPR} : {MMPM MMPR}}] $perRev]
        my Globals [list mom_feed_rate_mode $mode mom_programmed_feed_rate $value \
            mom_feed_cut_value $value]
        set S(feed) $value
        set S(perRev) $perRev
        my PerMinute
        my Globals [list mom_feed_rate $S(fpm)]
        if {$perRev} {my Globals [list mom_feed_rate_per_rev $value]}
    }

    # PerMinute --
    #	Sets S(fpm), the programmed feed per minute: a feed per revolution
    #	times the spindle speed of the moment (mom_spindle_speed).
    method PerMinute {} {
        set S(fpm) $S(feed)
        if {$S(perRev)} {
            set rpm [my Child {expr {[info exists ::mom_spindle_speed] ? $::mom_spindle_speed : 0.0}}]
            set S(fpm) [expr {$S(feed) * $rpm}]
        }
    }

    # Motion --
    #	GOTO: fires the motion it completes (rapid, linear, arc pieces, or a
    #	cycle hole), each preceded by MOM_before_motion; the first motion of
    #	a path goes out through MOM_initial_move / MOM_first_move.
    method Motion {rec} {
        if {!$S(pathOpen) || $S(headerPending)} {my EnsurePath}
        if {[llength [dict get $rec axis]]} {set S(axis) [dict get $rec axis]}
        if {[llength $S(contact)] || $S(contactOn)} {my ContactGlobals}
        set point [dict get $rec point]
        if {[llength $S(circle)] && ($S(rapid) || [llength $S(cycle)])} {
            ::fivax::Fail MOM ARC "[::fivax::mom::Where $S(circle)]: CIRCLE: the next GOTO\
                (line [dict get $rec line]) is [expr {$S(rapid) ? "a rapid move" : "a cycle's hole"}],\
                not the arc's end"
        }
        if {[llength $S(cycle)]} {
            my Hole $rec $point
            return
        }
        if {$S(rapid)} {
            set S(rapid) 0
            my Globals [list mom_motion_type RAPID mom_programmed_feed_rate 0 \
                mom_feed_rate $S(rapidFeed)]
            my SetPosition $point $S(axis)
            my Move rapid_move
        } elseif {[llength $S(circle)]} {
            set circle $S(circle)
            set S(circle) {}
            my Arc $rec $circle $point
        } else {
            my FeedGlobals $rec
            my SetPosition $point $S(axis)
            my Move linear_move
        }
    }

    # FeedGlobals --
    #	Sets the globals of a cutting move at the programmed feed:
    #	mom_feed_rate per minute (as Post Builder's FEEDRATE_SET reads it;
    #	a feed per revolution at the spindle speed of the moment).
    #	Errors: {FIVAX MOM FEED} before any FEDRAT.
    method FeedGlobals {rec} {
        if {![info exists S(feed)]} {
            ::fivax::Fail MOM FEED "[::fivax::mom::Where $rec]: GOTO: feed move before any FEDRAT"
        }
        if {$S(perRev)} {my PerMinute}
        lappend S(ops) v mom_motion_type CUT v mom_programmed_feed_rate $S(feed) \
            v mom_feed_rate $S(fpm)
    }

    # Move --
    #	Fires MOM_before_motion and the motion event (its name also in
    #	mom_motion_event); the first motion of a path fires MOM_initial_move
    #	after a tool change, else MOM_first_move, in place of the motion's
    #	event, mom_motion_event as MotionEvent says (as NX does, inferred
    #	from Post Builder's posts: their MOM_first_move calls
    #	MOM_$mom_motion_event, their MOM_initial_move MOM_rapid_move or
    #	MOM_linear_move by mom_programmed_feed_rate; were the motion's own
    #	event fired after either, they would write every first move twice).
    #	mom_machine_time and mom_cutting_time (minutes) grow by the move's
    #	length (see SetPosition) at its feed per minute, a rapid's at
    #	mom_kin_rapid_feed_rate (machine time only).
    #	(The operations of a motion are the same each time, Has answering
    #	once per name: MoveOps makes them at the first, S(move:...) keeps
    #	them with the number of handlers among them.)
    method Move {event} {
        set final $event
        if {$S(firstMove)} {
            set S(firstMove) 0
            set final [expr {$S(toolChanged) ? "initial_move" : "first_move"}]
        }
        set key move:$event,$final
        if {![info exists S($key)]} {set S($key) [my MoveOps $event $final]}
        lassign $S($key) ops handlers
        set feed [expr {$event eq "rapid_move" ? $S(rapidFeed) : $S(fpm)}]
        if {$feed > 0} {
            set t [expr {$S(moveLength) / $feed}]
            set S(machineTime) [expr {$S(machineTime) + $t}]
            if {$event ne "rapid_move"} {set S(cuttingTime) [expr {$S(cuttingTime) + $t}]}
        }
        lappend S(ops) v ::mom_machine_time $S(machineTime) v ::mom_cutting_time $S(cuttingTime) \
            {*}$ops
        incr S(events) $handlers
        set S(ready) [llength $S(ops)]
    }

    # MoveOps --
    #	Returns the operations of a motion (see Move) whose event is event
    #	and whose handler is MOM_<final> (also in mom_current_motion), and
    #	the number of handlers among them.
    method MoveOps {event final} {
        set before [my Fires before_motion]
        set handler [my Fires $final]
        set ops [list v mom_motion_event [my MotionEvent $event $final] v ::mom_current_motion $final \
            {*}$before {*}$handler]
        list $ops [expr {([llength $before] + [llength $handler]) / 3}]
    }

    # MotionEvent --
    #	Returns mom_motion_event for a motion whose own event is event and
    #	whose handler is MOM_<final>: initial_move for a rapid or straight
    #	first motion after a tool change (NX's event dictionary lists
    #	initial_move among mom_motion_event's values and first_move not;
    #	Post Builder's MOM_initial_move picks MOM_rapid_move or
    #	MOM_linear_move by mom_programmed_feed_rate, its MOM_first_move
    #	calls MOM_$mom_motion_event, and ugpost_base's RAPID_SET forces X Y
    #	on an initial_move), else the motion's own event. Inferred: a curve
    #	(arc, helix, NURBS) keeps its own name, which NX does not document;
    #	a straight move in its place would cut a chord.
    method MotionEvent {event final} {
        expr {$final eq "initial_move" && $event in {rapid_move linear_move}
            ? "initial_move" : $event}
    }

    # SetPosition --
    #	Sets mom_mcs_goto, mom_tool_axis (3-vectors) and their mom_prev_*
    #	copies (the last position is kept for them: S(position), the point
    #	and axis in one list), and the move's length (S(moveLength), for
    #	the times). mom_pos and mom_prev_pos (0-2) mirror mom_mcs_goto and
    #	mom_prev_mcs_goto: the replay runtime does no kinematics. mom_last_pos
    #	is where the tool was: mom_prev_pos, but the retract position of
    #	the last hole after a cycle's (NX's dictionary: "The previous tool
    #	position. Not the same mom_prev_pos. The retracto position will be
    #	used following canned cycles"; Post Builder's RAPID_SET orders a
    #	rapid's spindle-axis and traverse blocks by it).
    method SetPosition {point axis} {
        # (list: concat makes the strings of the axis's numbers)
        set position [list {*}$point {*}$axis]
        # (llength: eq would make the previous point's string for nothing)
        if {![llength $S(point)]} {set S(position) $position}
        lassign $S(position) x0 y0 z0
        lassign $point x y z
        set S(moveLength) [expr {sqrt(($x - $x0) ** 2 + ($y - $y0) ** 2 + ($z - $z0) ** 2)}]
        lappend S(ops) p $S(position) $position
        if {[llength $S(retractPos)]} {
            my Array mom_last_pos $S(retractPos)
            set S(retractPos) {}
        }
        set S(point) $point
        set S(position) $position
    }

    # Arc --
    #	CIRCLE + GOTO: fires the arc in pieces as NX does by the post's
    #	output modes (a helix: mom_kin_helical_arc_output_mode, else
    #	mom_kin_arc_output_mode): FULL_CIRCLE at most 360 degrees a piece,
    #	QUADRANT at most 90, END_POINT the whole arc, LINEAR as linear
    #	moves within the arc's tolerance (0.002 mm when the CIRCLE has
    #	none), as also an arc beyond the post's limits (ArcBeyondPost)
    #	and a helix when the post has no MOM_helix_move. Inferred from
    #	Post Builder's PB_CMD_init_helix, which "enables your post to output
    #	helix" by setting mom_kin_helical_arc_output_mode and defining
    #	MOM_helix_move: a post without it has no block for the rise (its
    #	CIRCLE_SET suppresses the coordinate along the arc's axis), so that
    #	a helix given to its MOM_circular_move would be cut flat.
    #	mom_arc_direction is the turning sense about mom_arc_axis: NX-style
    #	CIRCLEs (11 numbers: NX, Makino) turn clockwise about their vector,
    #	the short APT form (6 or 7 numbers: Creo, SolidWorks CAM)
    #	counter-clockwise (nx-conventions.md 5.4); an arc in a principal
    #	plane is about that plane's positive normal (see ArcFrame), with
    #	mom_pos_arc_center, _axis and _plane. An arc with no position
    #	before it has no start: its end is reached by a linear move, with
    #	a warning (a post would take an arc from its end to its end for a
    #	full circle).
    method Arc {rec circle end} {
        namespace upvar ::fivax::num pi pi
        if {$S(point) eq ""} {
            incr S(warnings)
            my Warn "[::fivax::mom::Where $circle]: CIRCLE with no position before it:\
                the arc has no start, its end is reached by a linear move"
            my FeedGlobals $rec
            my SetPosition $end $S(axis)
            my Move linear_move
            return
        }
        set start $S(point)
        set center [dict get $circle center]
        set axis [dict get $circle axis]
        my ArcRadius $circle $start $end
        set sense [expr {[llength [dict get $circle numbers]] >= 11 ? -1 : 1}]
        set times [dict get $circle times]
        set helix [expr {$times > 0 || abs([::fivax::vec::dot [::fivax::vec::sub $end $start] \
            [::fivax::vec::unit $axis]]) > 1e-6}]
        set mode [my PostVar [expr {$helix ? "mom_kin_helical_arc_output_mode"
            : "mom_kin_arc_output_mode"}] FULL_CIRCLE]
        my FeedGlobals $rec
        if {$mode ne "LINEAR" && !($helix && ![my Has MOM_helix_move])} {
            set max [dict get {FULL_CIRCLE 360.0 QUADRANT 90.0 END_POINT Inf} $mode]
            set pieces {}
            set total 0.0
            set from $start
            foreach piece [my Curve $circle ARC CIRCLE arcSplit $start $end $center $axis $sense \
                    $times [expr {$max * $pi / 180.0}]] {
                lassign $piece p sweep
                set length [my ArcLength $from $p $center $axis $sweep]
                lappend pieces [list $p $sweep $length]
                set total [expr {$total + $length}]
                set from $p
            }
            if {[my ArcBeyondPost [::fivax::curve::radius $start $center $axis] $total]} {
                set mode LINEAR
            }
        } else {
            set mode LINEAR
        }
        if {$mode eq "LINEAR"} {
            set tol [expr {[dict exists $circle tolerance] && [dict get $circle tolerance] > 0
                ? [dict get $circle tolerance] : 0.002}]
            foreach p [my Curve $circle ARC CIRCLE arc $start $end $center $axis $sense $times $tol] {
                my SetPosition $p $S(axis)
                my Move linear_move
            }
            return
        }
        lassign [::fivax::mom::ArcFrame $axis $sense] nxAxis nxSense plane
        set pairs [list mom_arc_radius [dict get $circle radius] \
            mom_arc_direction [expr {$nxSense < 0 ? "CLW" : "CCLW"}]]
        foreach key {tolerance intol tool_diameter tool_radius} {
            if {[dict exists $circle $key]} {
                lappend pairs mom_arc_[string map {intol intol_fraction} $key] [dict get $circle $key]
            }
        }
        my Array mom_arc_center $center
        my Array mom_arc_axis $nxAxis
        my Array mom_pos_arc_center $center
        my Array mom_pos_arc_axis $nxAxis
        my Globals [list mom_pos_arc_plane $plane]
        set event [expr {$helix ? "helix_move" : "circular_move"}]
        set from $start
        foreach piece $pieces {
            lassign $piece p sweep length
            # a piece turns at most once: no extra turns
            my Globals [concat $pairs [list mom_arc_times 0 \
                mom_arc_angle [::fivax::num::deg $sweep] \
                mom_helix_pitch [my Pitch $from $p $axis $sweep]]]
            set from $p
            my SetPosition $p $S(axis)
            set S(moveLength) $length
            my Move $event
        }
    }

    # ArcBeyondPost --
    #	Returns 1 when an arc of radius r and length (mm, output unit) is
    #	shorter than the post's mom_kin_min_arc_length or its radius lies
    #	outside mom_kin_min_arc_radius .. mom_kin_max_arc_radius (each
    #	where the post sets a number): NX then writes it as linear gotos
    #	(NX's event dictionary: "Any arc with a radius larger than the
    #	maximum will output as linear gotos"; the shortest arc "before the
    #	post defaults to linear interpolation").
    method ArcBeyondPost {r length} {
        set limits {}
        foreach {name default} {mom_kin_min_arc_radius 0 mom_kin_max_arc_radius Inf
                mom_kin_min_arc_length 0} {
            set value [my PostVar $name $default]
            lappend limits [expr {[string is double -strict $value] ? $value : $default}]
        }
        lassign $limits minR maxR minL
        expr {$r < $minR || $r > $maxR || $length < $minL}
    }

    # ArcRadius --
    #	Checks that the arc's start and end lie on its CIRCLE's radius
    #	(when given) within arcRadiusTol mm (NX writes 4 decimals: 0.0002
    #	mm in the corpus).
    #	Errors: {FIVAX MOM ARC}.
    method ArcRadius {circle start end} {
        set radius [dict get $circle radius]
        if {$radius eq ""} return
        set tol [expr {$::fivax::mom::arcRadiusTol / ($S(outUnit) eq "IN" ? 25.4 : 1.0)}]
        set center [dict get $circle center]
        set axis [dict get $circle axis]
        foreach p [list $start $end] what {start end} {
            set r [::fivax::curve::radius $p $center $axis]
            # (a point beyond the curve's reach is the arc's own error)
            if {!($r <= $::fivax::num::reach)} continue
            if {!(abs($r - $radius) <= $tol)} {
                ::fivax::Fail MOM ARC [::format "%s: CIRCLE: the arc's %s lies %.4f mm from its axis,\
                    its radius is %g mm" [::fivax::mom::Where $circle] $what $r $radius]
            }
        }
    }

    # NurbsData --
    #	KNOT or CNTRL: adds the record's knots or control point to the open
    #	NURBS. Errors: {FIVAX MOM NURBS} outside a NURBS.
    method NurbsData {rec} {
        set kind [dict get $rec kind]
        if {![llength $S(nurbs)]} {
            ::fivax::Fail MOM NURBS "[::fivax::mom::Where $rec]: $kind outside a NURBS"
        }
        if {$kind eq "KNOT"} {
            dict lappend S(nurbs) knots {*}[dict get $rec knots]
        } else {
            dict lappend S(nurbs) cntrl [dict get $rec point]
        }
    }

    # Nurbs --
    #	Fires the open NURBS as MOM_nurbs_move with mom_nurbs_order,
    #	mom_nurbs_knot_count and mom_nurbs_knots(i) (the full, clamped knot
    #	vector), mom_nurbs_point_count and mom_nurbs_points(i,0..2) (the
    #	control points, the current position first), mom_nurbs_weights(i)
    #	(all 1) and mom_mcs_goto at the curve's end (see the CLSF
    #	convention in lib/curve.tcl; NX's own layout of these globals is
    #	inferred from Post Builder posts that read them). A post without
    #	MOM_nurbs_move gets the curve as linear moves within 0.002 mm, as
    #	NX linearises for a post that does not take NURBS.
    #	Errors: {FIVAX MOM NURBS} "FILE:LINE: NURBS: what".
    method Nurbs {} {
        set data $S(nurbs)
        set S(nurbs) {}
        set rec [dict get $data rec]
        my EnsurePath
        if {$S(point) eq ""} {
            ::fivax::Fail MOM NURBS "[::fivax::mom::Where $rec]: NURBS: no position before the curve"
        }
        set curve [my Curve $rec NURBS NURBS clsfNurbs $S(point) [dict get $data knots] \
            [dict get $data cntrl]]
        my FeedGlobals $rec
        if {![my Has MOM_nurbs_move]} {
            foreach p [::fivax::curve::nurbsPoints $curve 0.002] {
                my SetPosition $p $S(axis)
                my Move linear_move
            }
            return
        }
        set knots [dict get $curve knots]
        set points [dict get $curve points]
        my Globals [list mom_nurbs_order [expr {[dict get $curve degree] + 1}] \
            mom_nurbs_knot_count [llength $knots] mom_nurbs_point_count [llength $points]]
        my Array mom_nurbs_knots $knots
        my Array mom_nurbs_weights [dict get $curve weights]
        set pairs {}
        set i 0
        foreach p $points {
            foreach j {0 1 2} c $p {lappend pairs $i,$j $c}
            incr i
        }
        lappend S(ops) a mom_nurbs_points $pairs
        my SetPosition [lindex $points end] $S(axis)
        my Move nurbs_move
    }

    # Curve --
    #	Returns the result of ::fivax::curve with args, its {FIVAX CURVE}
    #	errors raised as {FIVAX MOM detail} "FILE:LINE: word: message" of
    #	CL record rec (the CIRCLE or NURBS the curve comes from).
    method Curve {rec detail word args} {
        try {
            ::fivax::curve {*}$args
        } trap {FIVAX CURVE} {msg} {
            ::fivax::Fail MOM $detail "[::fivax::mom::Where $rec]: $word: $msg"
        }
    }

    # ArcLength -- Returns the length of the arc piece from a to b about center and axis sweeping sweep (rad).
    method ArcLength {a b center axis sweep} {
        set r [::fivax::curve::radius $a $center $axis]
        set rise [::fivax::vec::dot [::fivax::vec::sub $b $a] [::fivax::vec::unit $axis]]
        expr {hypot($r * $sweep, $rise)}
    }

    # Pitch -- Returns the axial rise per turn of the arc piece from a to b sweeping sweep (rad).
    method Pitch {a b axis sweep} {
        namespace upvar ::fivax::num pi pi
        if {$sweep <= 0} {return 0.0}
        set rise [::fivax::vec::dot [::fivax::vec::sub $b $a] [::fivax::vec::unit $axis]]
        expr {$rise * 2.0 * $pi / $sweep}
    }

    # Has -- Returns 1 when the post defines the command name.
    method Has {name} {
        if {![info exists S(has:$name)]} {
            # the handlers ready before this answer run first (they may define name)
            my FlushReady
            set S(has:$name) [llength [$S(interp) eval [list info commands ::$name]]]
        }
        return $S(has:$name)
    }

    # PostVar -- Returns the post's global name, or default when it is not set.
    method PostVar {name default} {
        if {[my Child [list info exists ::$name]]} {
            return [my Child [list set ::$name]]
        }
        return $default
    }

    # FromHome --
    #	FROM and GOHOME: set the position and fire the event, named in
    #	mom_motion_event and mom_current_motion (NX's dictionary: "Same as
    #	mom_motion_event"; Post Builder's RAPID_SET, which MOM_from_move
    #	calls, reads it).
    method FromHome {rec which} {
        my EnsurePath
        if {[llength [dict get $rec axis]]} {set S(axis) [dict get $rec axis]}
        my Array mom_${which}_pos [dict get $rec point]
        if {$which eq "from"} {
            my Array mom_from_ref_pos [dict get $rec point]
            my SetPosition [dict get $rec point] $S(axis)
            my Globals [list mom_motion_type FROM mom_motion_event from_move \
                mom_current_motion from_move]
            my Fire from_move
        } else {
            my SetPosition [dict get $rec point] $S(axis)
            my Globals [list mom_motion_type GOHOME mom_motion_event gohome_move \
                mom_current_motion gohome_move mom_programmed_feed_rate 0 \
                mom_feed_rate $S(rapidFeed)]
            my Fire before_motion 0
            my Fire gohome_move
        }
        set S(rapid) 0
    }

    # Spindle --
    #	SPINDL: sets mom_spindle_* and fires MOM_spindle_rpm (see Event), or
    #	MOM_spindle_off.
    method Spindle {rec} {
        if {[dict get $rec state] eq "OFF"} {
            my Globals [list mom_spindle_status OFF]
            my Event spindle_off
            return
        }
        set pairs [list mom_spindle_status ON mom_spindle_mode [dict get $rec mode]]
        if {[dict get $rec speed] ne ""} {
            lappend pairs mom_spindle_speed [dict get $rec speed] mom_spindle_rpm [dict get $rec speed]
        }
        if {[dict get $rec direction] ne ""} {
            lappend pairs mom_spindle_direction [dict get $rec direction]
        }
        my Globals $pairs
        my Event spindle_rpm
    }

    # Coolant -- COOLNT: sets mom_coolant_* and fires MOM_coolant_on or _off (see Event).
    method Coolant {rec} {
        set mode [dict get $rec mode]
        my Globals [list mom_coolant_mode $mode mom_coolant_status [expr {$mode eq "OFF" ? "OFF" : "ON"}]]
        my Event [expr {$mode eq "OFF" ? "coolant_off" : "coolant_on"}]
    }

    # Cutcom --
    #	CUTCOM: fires MOM_cutcom_on or MOM_cutcom_off. The plane is
    #	mom_cutcom_plane XY, YZ or ZX (as NX gives it: Post Builder posts
    #	index mom_sys_cutcom_plane_code by it), the register
    #	mom_cutcom_adjust_register (NX's dictionary: "The value of the
    #	cutcom adjust register in CUTCOM UDE"; Post Builder's linear_move
    #	block writes D from it) and mom_cutcom_register (the operation's
    #	register in the dictionary, which the CL does not tell apart;
    #	fivax's post reads it); a record without them leaves them as they
    #	were. A CUTCOM without register gives no register: NX would take
    #	the tool's (mom_tool_cutcom_register), which the CL does not carry,
    #	and ugpost_base's TOOL_SET copies it only for posts that call it in
    #	MOM_cutcom_on.
    method Cutcom {rec} {
        my EnsurePath
        set mode [dict get $rec mode]
        set pairs [list mom_cutcom_mode $mode mom_cutcom_status [expr {$mode eq "OFF" ? "OFF" : "ON"}]]
        if {[dict get $rec plane] ne ""} {
            lappend pairs mom_cutcom_plane [string range [dict get $rec plane] 0 1]
        }
        if {[dict get $rec register] ne ""} {
            lappend pairs mom_cutcom_register [dict get $rec register] \
                mom_cutcom_adjust_register [dict get $rec register]
        }
        my Globals $pairs
        my Fire [expr {$mode eq "OFF" ? "cutcom_off" : "cutcom_on"}]
    }

    # Contact -- CONTACT: keeps the contact data for the GOTO that follows it.
    method Contact {rec} {
        my ContactDone $rec
        set S(contact) $rec
    }

    # ContactDone --
    #	Errors {FIVAX MOM CONTACT} when a CONTACT is still waiting for its
    #	GOTO at rec (another CONTACT, or the end of the path).
    method ContactDone {rec} {
        if {![llength $S(contact)]} return
        set what [expr {[dict get $rec kind] eq "CONTACT" ? "another CONTACT" : "the end of the path"}]
        set at [::fivax::mom::Where $S(contact)]
        set S(contact) {}
        ::fivax::Fail MOM CONTACT "$at: CONTACT: no GOTO follows it before $what\
            (line [dict get $rec line]): contact data belong to the next GOTO"
    }

    # ContactGlobals --
    #	Sets NX's contact variables for the motion of the GOTO being read:
    #	mom_contact_status ON with mom_contact_point(3) and
    #	mom_contact_normal(3) when a CONTACT came before it, else OFF.
    method ContactGlobals {} {
        if {[llength $S(contact)]} {
            my Globals {mom_contact_status ON}
            my Array mom_contact_point [dict get $S(contact) point]
            my Array mom_contact_normal [dict get $S(contact) normal]
            set S(contact) {}
            set S(contactOn) 1
        } else {
            my Globals {mom_contact_status OFF}
            set S(contactOn) 0
        }
    }

    # Delay -- DELAY: fires MOM_delay with mom_delay_value (seconds) or mom_delay_revs.
    method Delay {rec} {
        my EnsurePath
        if {[dict get $rec revs] ne ""} {
            my Globals [list mom_delay_revs [dict get $rec revs] mom_delay_mode REVOLUTIONS]
        } else {
            my Globals [list mom_delay_value [dict get $rec value] mom_delay_mode SECONDS]
        }
        my Fire delay
    }

    # Units --
    #	UNITS: the CL's length unit; lengths from here on are converted to
    #	the post's output unit (mom_kin_output_unit).
    method Units {rec} {
        set S(unitsSeen) 1
        my SetUnit [expr {[dict get $rec value] eq "INCH" ? "IN" : "MM"}]
    }

    # SetUnit --
    #	Sets the CL's unit (MM or IN): mom_part_unit, the scale to the
    #	output unit, and mom_feed_rate_output_mode (IPM or MMPM) of it.
    method SetUnit {unit} {
        namespace upvar ::fivax::mom unitLength unitLength
        set S(clUnit) $unit
        set S(scale) [expr {[dict get $unitLength $unit] / [dict get $unitLength $S(outUnit)]}]
        my Globals [list mom_part_unit $unit mom_output_unit $S(outUnit) \
            mom_feed_rate_output_mode [expr {$S(outUnit) eq "IN" ? "IPM" : "MMPM"}]]
    }

    # Scale --
    #	Returns record rec with its lengths (points, centres, radii, tool
    #	sizes, feeds, cycle distances) converted by the unit scale.
    method Scale {rec} {
        set k $S(scale)
        foreach key {point center origin} {
            if {[dict exists $rec $key]} {
                dict set rec $key [::fivax::vec::scale $k [dict get $rec $key]]
            }
        }
        foreach key {radius tolerance tool_diameter tool_radius diameter corner1_radius
            length flute_length value} {
            if {[dict exists $rec $key] && [dict get $rec $key] ne ""
                    && !([dict get $rec kind] in {DELAY UNITS})} {
                dict set rec $key [expr {[dict get $rec $key] * $k}]
            }
        }
        return $rec
    }

    # Cycle --
    #	CYCLE/<type>: sets the mom_cycle_* of the cycle (see CycleParams)
    #	and fires its activation event (MOM_drill, MOM_drill_deep, ...);
    #	each following GOTO is a hole (see Hole); CYCLE/OFF fires
    #	MOM_cycle_off.
    #	Errors: {FIVAX MOM CYCLE} for a cycle the runtime cannot read.
    method Cycle {rec} {
        my EnsurePath
        if {[string toupper [dict get $rec type]] eq "OFF"} {
            set S(cycle) {}
            my Fire cycle_off
            return
        }
        lassign [::fivax::mom::CycleParams $rec $S(scale)] event params
        my Globals [concat [list mom_cycle_event $event] $params]
        set S(cycle) [dict create event $event params $params src [::fivax::mom::Where $rec]]
        my Fire $event
    }

    # Hole --
    #	A GOTO in a cycle: the hole top at point on the current tool axis.
    #	Sets mom_cycle_rapid_to_pos, _feed_to_pos and _retract_to_pos and
    #	fires MOM_<cycle>_move; the first motion of a path first fires
    #	MOM_initial_move / MOM_first_move at mom_cycle_rapid_to_pos (the
    #	event dictionary says so of NX), a rapid positioning: mom_motion_type
    #	CYCLE, mom_motion_event initial_move or rapid_move (inferred: Post Builder's
    #	MOM_first_move calls MOM_$mom_motion_event, which would drill the
    #	hole twice were it the hole's event). mom_current_motion is the
    #	hole's event, as mom_motion_event (the dictionary: "Same as
    #	mom_motion_event"); the tool stays at the hole's retract position
    #	(mom_last_pos of the next motion, see SetPosition).
    method Hole {rec point} {
        set params [dict get $S(cycle) params]
        set t [::fivax::vec::unit $S(axis)]
        foreach {key var} {rapid mom_cycle_rapid_to feed mom_cycle_feed_to retract mom_cycle_retract_to} {
            set pos($key) [::fivax::vec::add $point [::fivax::vec::scale [dict get $params $var] $t]]
            my Array ${var}_pos $pos($key)
        }
        my Globals [list mom_motion_type CYCLE mom_programmed_feed_rate 0]
        if {$S(firstMove)} {
            my SetPosition $pos(rapid) $S(axis)
            my Move rapid_move
        }
        my SetPosition $point $S(axis)
        set event [dict get $S(cycle) event]_move
        my Globals [list mom_motion_event $event mom_current_motion $event]
        my Fire before_motion 0
        if {![my Fire $event]} {
            ::fivax::Fail MOM CYCLE "[::fivax::mom::Where $rec]: the post has no MOM_$event:\
                the holes of this cycle cannot be output"
        }
        set S(retractPos) $pos(retract)
    }

    # Unknown --
    #	A record the runtime does not pass to the post: a warning with
    #	FILE:LINE (the first five of each word; Finish counts the rest).
    #	CL words never name a handler: only the records above reach the post.
    method Unknown {rec} {
        set major [dict get $rec major]
        incr S(warnings)
        dict incr S(unknown) $major
        if {[dict get $S(unknown) $major] <= 5} {
            my Warn "[::fivax::mom::Where $rec]: unknown record '$major' ignored"
        }
    }

    # UnknownTotals -- Lists how many unknown records of each word went unreported.
    method UnknownTotals {} {
        dict for {major count} $S(unknown) {
            if {$count > 5} {
                my Warn "[expr {$count - 5}] more '$major' records ignored ($count in all)"
            }
        }
    }

    # Write --
    #	The end of every output line (see the output variable): text, when
    #	not empty, to the output channel and the files the post opened;
    #	returns it.
    method Write {text} {
        if {$text ne ""} {
            incr S(blocks)
            foreach chan $S(outputs) {puts $chan $text}
        }
        return $text
    }

    # Line -- Returns text as one block of MOM_output_literal, numbered when sequencing is on.
    method Line {text} {
        $S(nc) line $text
    }

    # MOM_open_output_file path: every line from here on also goes to the
    # file path (created anew), until MOM_close_output_file; the output
    # file NX named (mom_output_file_full_name) reopens as it was.
    method Cmd_open_output_file {path args} {
        if {[my IsMainFile $path]} {
            if {$S(channel) ni $S(outputs)} {set S(outputs) [linsert $S(outputs) 0 $S(channel)]}
        } elseif {![dict exists $S(files) $path]} {
            set chan [open $path w]
            chan configure $chan -translation lf
            dict set S(files) $path $chan
            lappend S(outputs) $chan
        }
        return ""
    }

    # MOM_close_output_file path: no more lines to the file path (the
    # output file NX named included: the post may reopen it).
    method Cmd_close_output_file {path args} {
        if {[my IsMainFile $path]} {
            set chan $S(channel)
        } elseif {[dict exists $S(files) $path]} {
            set chan [dict get $S(files) $path]
            dict unset S(files) $path
            close $chan
        } else {
            return ""
        }
        set S(outputs) [lsearch -all -inline -exact -not $S(outputs) $chan]
        return ""
    }

    # MOM_remove_file path: removes the file (Post Builder's base file
    # removes an earlier run's output before it reopens the output file).
    method Cmd_remove_file {path args} {
        file delete -- $path
        return ""
    }

    # IsMainFile -- Returns 1 when path names the output file NX named to the post.
    method IsMainFile {path} {
        expr {$S(mainFile) ne "" && $S(channel) ne ""
            && [file normalize $path] eq [file normalize $S(mainFile)]}
    }

    # SequenceOverflow --
    #	The next sequence number n passed the .def's maximum: NX's warning
    #	(mom_warning_info names mom_seqnum) goes to the post's
    #	MOM_catch_warning, which may restart the numbering (Post Builder's
    #	base file does); else numbering stops with the runtime's warning.
    method SequenceOverflow {n} {
        if {![my Has MOM_catch_warning]} return
        set max [dict get $S(defDict) sequence max]
        $S(interp) eval [list set ::mom_seqnum $n]
        $S(interp) eval [list set ::mom_warning_info "mom_seqnum $n exceeds the maximum $max\
            of the .def's SEQUENCE"]
        $S(interp) eval ::MOM_catch_warning
    }

    # TemplateBlock --
    #	The block of MOM_do_template (see ::fivax::mom::TemplateScript):
    #	sets the leaders that changed (flat address/text list leaders) and
    #	returns the words (flat address/value list, "" for a literal)
    #	formatted as a block.
    method TemplateBlock {leaders words} {
        foreach {addr text} $leaders {
            $S(nc) address $addr -leader $text
        }
        $S(nc) block $words
    }

    # MOM_force Always|Once|Off addr...
    method Cmd_force {mode args} {
        $S(nc) force [string tolower $mode] $args
    }

    # MOM_suppress Always|Once|Off addr...
    method Cmd_suppress {mode args} {
        $S(nc) suppress [string tolower $mode] $args
    }

    # MOM_set_seq_on: returns the previous state.
    method Cmd_set_seq_on {} {
        $S(nc) sequence on
    }

    # MOM_set_seq_off: returns the previous state.
    method Cmd_set_seq_off {} {
        $S(nc) sequence off
    }

    # MOM_reset_sequence start incr ?freq?
    method Cmd_reset_sequence {start incr args} {
        $S(nc) resetSequence $start $incr
    }

    # MOM_abort msg: ends posting with an error.
    method Cmd_abort {{msg "MOM_abort"}} {
        ::fivax::Fail MOM ABORT $msg
    }

    # MOM_abort_event: leaves the current handler.
    method Cmd_abort_event {{msg ""}} {
        return -code error -errorcode {FIVAX MOM ABORT_EVENT} $msg
    }

    # MOM_output_to_listing_device text
    method Cmd_output_to_listing_device {text} {
        my Listing $text
    }

    # MOM_log_message text
    method Cmd_log_message {text args} {
        my Listing $text
    }

    # MOM_display_message msg title type ?buttons?: batch answer is button 1.
    method Cmd_display_message {msg args} {
        my Listing $msg
        return 1
    }

    # MOM_reload_variable ?-a? var: the replay generator reads the post's globals directly.
    method Cmd_reload_variable {args} {
        return ""
    }

    # MOM_reload_kinematics: kinematics live in the post's library here.
    method Cmd_reload_kinematics {} {
        return ""
    }

    # MOM_update_kinematics: no legacy names to map in replay.
    method Cmd_update_kinematics {} {
        return ""
    }

    # MOM_ask_event_type: the current event's handler name (MOM_first_move),
    # "" outside one (Post Builder's RAPID_SET compares it with
    # "MOM_first_move", ugpost_base's warnings print it beside MOM_<motion>).
    method Cmd_ask_event_type {} {
        set event [$S(interp) eval {set ::fivax::mom::runtime::event}]
        expr {$event eq "" ? "" : "MOM_$event"}
    }

    # MOM_ask_env_var name: value of an environment variable, or "";
    # unset, NX's own: UGII_CAM_POST_DIR is the post's directory (with its
    # separator: posts source ${UGII_CAM_POST_DIR}ugpost_base.tcl beside
    # them), UGII_TMP_DIR the temporary directory (TMPDIR, else /tmp).
    method Cmd_ask_env_var {name} {
        if {[info exists ::env($name)]} {return $::env($name)}
        switch -- $name {
            UGII_CAM_POST_DIR {
                if {$S(post) ne ""} {return [file dirname [file normalize $S(post)]]/}
            }
            UGII_TMP_DIR {
                return [expr {[info exists ::env(TMPDIR)] ? $::env(TMPDIR) : "/tmp"}]
            }
        }
        return ""
    }

    # MOM_ask_address_value addr
    method Cmd_ask_address_value {addr} {
        $S(nc) value $addr
    }

    # MOM_set_address_format addr format
    method Cmd_set_address_format {addr format} {
        if {[dict exists $S(defDict) formats $format]} {
            set format [dict get $S(defDict) formats $format]
        }
        $S(nc) address $addr -format $format
    }

    # MOM_validate_machine_model: replay has no machine model to validate.
    method Cmd_validate_machine_model {args} {
        return TRUE
    }

    # MOM_has_definition_element BLOCK|ADDRESS|FORMAT name
    method Cmd_has_definition_element {type name} {
        set key [dict get {BLOCK blocks ADDRESS addresses FORMAT formats} [string toupper $type]]
        expr {[dict exists $S(defDict) $key $name] ? 1 : 0}
    }
}
