# nxhost.tcl --
#	An NX-like host for the tests, independent of lib/mom.tcl: it installs
#	the post as a user would (post/, lib/, machines/ copied under a post
#	directory), sources a machine's wrapper post by its absolute path into
#	a fresh interpreter that holds only core Tcl and the MOM_* commands a
#	post calls, from an unrelated working directory, and fires events the
#	way NX's MOM variable/event dictionary and Siemens' Post Builder posts
#	describe them: globals first, then MOM_<event> if the post defines it;
#	the first motion of an operation as MOM_initial_move / MOM_first_move
#	with mom_motion_event naming that event.

namespace eval ::nxhost {
    variable count 0
}

# ::nxhost::templateDef --
#	Returns the .def of the wrapper post file post as NX takes it: the
#	one its template_post.dat line (in the wrapper's header) names, in
#	the post's directory (every machine's wrapper names post/fivax.def).
proc ::nxhost::templateDef {post} {
    set f [open $post]
    set text [read $f]
    close $f
    if {![regexp -line {^#\s*FIVAX[^,]*,[^,]+,\$\{UGII_CAM_POST_DIR\}fivax/post/(\S+\.def)$} \
            $text -> def]} {
        error "$post: no template_post.dat line"
    }
    file join [file dirname $post] $def
}

# ::nxhost::install --
#	Copies the post, the library and the machine files into dir/fivax (as
#	under ${UGII_CAM_POST_DIR}fivax); returns that directory.
proc ::nxhost::install {dir} {
    set to [file join $dir fivax]
    file mkdir $to
    foreach sub {post lib machines} {
        file copy [file join $::fivaxRoot $sub] $to
    }
    return $to
}

# ::nxhost::session --
#	Returns a new session: a fresh interpreter with the MOM_* commands,
#	into which the post file is sourced from the directory cwd, with the
#	NX globals of its .def and output file set first, and the script prep
#	run in it before the post.
proc ::nxhost::session {post def cwd output {prep {}}} {
    variable count
    set s ::nxhost::s[incr count]
    upvar #0 $s S
    array set S {lines {} listing {} event {}}
    set i [interp create]
    set S(interp) $i
    foreach cmd {MOM_output_text MOM_output_literal} {
        interp alias $i $cmd {} ::nxhost::Output $s
    }
    interp alias $i MOM_output_to_listing_device {} ::nxhost::Listing $s
    interp alias $i MOM_log_message {} ::nxhost::Listing $s
    interp alias $i MOM_abort {} ::nxhost::Abort
    interp alias $i MOM_ask_event_type {} ::nxhost::EventType $s
    interp alias $i MOM_ask_env_var {} ::nxhost::Env
    foreach cmd {MOM_reload_variable MOM_reload_kinematics MOM_set_seq_on MOM_set_seq_off
        MOM_force MOM_suppress} {
        interp alias $i $cmd {} ::nxhost::Nothing
    }
    vars $s [list mom_definition_file_name $def mom_event_handler_file_name $post \
        mom_output_file_full_name $output \
        mom_output_file_directory [file dirname $output]/ \
        mom_output_file_basename [file rootname [file tail $output]] \
        mom_output_file_suffix [string trimleft [file extension $output] .] \
        mom_output_unit MM mom_part_unit MM]
    $i eval $prep
    set here [pwd]
    cd $cwd
    try {
        $i eval [list source $post]
    } finally {
        cd $here
    }
    return $s
}

# ::nxhost::vars -- Sets the globals of the name/value list pairs in session s.
proc ::nxhost::vars {s pairs} {
    upvar #0 $s S
    foreach {name value} $pairs {
        $S(interp) eval [list set ::$name $value]
    }
}

# ::nxhost::globalArray -- Sets global array name(0..) of session s from the list values.
proc ::nxhost::globalArray {s name values} {
    upvar #0 $s S
    set i 0
    foreach v $values {
        $S(interp) eval [list set ::${name}($i) $v]
        incr i
    }
}

# ::nxhost::fire -- Calls MOM_<event> in session s when the post defines it.
proc ::nxhost::fire {s event} {
    upvar #0 $s S
    set S(event) $event
    if {[llength [$S(interp) eval [list info commands ::MOM_$event]]]} {
        $S(interp) eval [list MOM_$event]
    }
    set S(event) ""
}

# ::nxhost::motion --
#	Fires one motion of session s: the tip point P and axis t (the MCS),
#	type (RAPID, CUT, CYCLE ...), programmed feed (0: rapid), event (the
#	motion's event; for the first motion of an operation initial_move or
#	first_move), named what goes into mom_motion_event (default: event;
#	for a first motion NX may name the motion's own event there, e.g.
#	drill_move, circular_move, nurbs_move). Sets the mom_prev_* of the
#	previous motion first, then MOM_before_motion.
proc ::nxhost::motion {s event type P t feed {named ""}} {
    upvar #0 $s S
    if {[info exists S(P)]} {
        globalArray $s mom_prev_mcs_goto $S(P)
        globalArray $s mom_prev_tool_axis $S(t)
    }
    set S(P) $P
    set S(t) $t
    globalArray $s mom_mcs_goto $P
    globalArray $s mom_pos $P
    globalArray $s mom_tool_axis $t
    if {$named eq ""} {set named $event}
    vars $s [list mom_motion_event $named mom_motion_type $type \
        mom_programmed_feed_rate $feed mom_feed_rate $feed]
    fire $s before_motion
    fire $s $event
}

# ::nxhost::again --
#	Fires the motion's own event (MOM_before_motion, then MOM_<event>,
#	event also in mom_motion_event) with the globals of the motion just
#	fired unchanged: the order in which a first motion's MOM_initial_move
#	or MOM_first_move is followed by the motion's event, as Post Builder
#	posts' MOM_initial_move (a positioning move only) expect.
proc ::nxhost::again {s event} {
    vars $s [list mom_motion_event $event]
    fire $s before_motion
    fire $s $event
}

# ::nxhost::query -- Returns the result of script run in session s's interpreter.
proc ::nxhost::query {s script} {
    upvar #0 $s S
    $S(interp) eval $script
}

# ::nxhost::lines -- Returns the NC lines written in session s.
proc ::nxhost::lines {s} {
    upvar #0 $s S
    return $S(lines)
}

# ::nxhost::finish -- Deletes session s.
proc ::nxhost::finish {s} {
    upvar #0 $s S
    interp delete $S(interp)
    unset S
}

# ::nxhost::Output -- MOM_output_text / _literal: keeps the line.
proc ::nxhost::Output {s text args} {
    upvar #0 $s S
    lappend S(lines) $text
    return $text
}

# ::nxhost::Listing -- MOM_output_to_listing_device: keeps the line.
proc ::nxhost::Listing {s text args} {
    upvar #0 $s S
    lappend S(listing) $text
}

# ::nxhost::Abort -- MOM_abort: ends posting with the message.
proc ::nxhost::Abort {msg} {
    return -code error -errorcode {NXHOST ABORT} $msg
}

# ::nxhost::EventType -- MOM_ask_event_type.
proc ::nxhost::EventType {s} {
    upvar #0 $s S
    return $S(event)
}

# ::nxhost::Env -- MOM_ask_env_var: the environment variable, or "".
proc ::nxhost::Env {name} {
    if {[info exists ::env($name)]} {return $::env($name)}
    return ""
}

# ::nxhost::Nothing -- A MOM_* command the post may call that needs no host work here.
proc ::nxhost::Nothing {args} {
    return ""
}
