# output.tcl --
#	The output layer: turns the planner's neutral move records and the
#	post's program events (start, tool change, spindle, coolant, comments,
#	end) into NC blocks of one controller dialect. It alone (with the
#	controllers' files) knows address names, G and M codes, inverse-time F, where length
#	compensation and TCP go, how a tilted work plane and an arc are
#	written; the blocks are built by an nc Writer (lib/nc.tcl). Returns
#	text only: the host writes it.
#
#	The post's .def is the one source of formats: every address this layer
#	writes is defined there (FORMAT, ADDRESS with FORCE, MIN/MAX, LEADER),
#	and so are the word separator, end of line and sequence numbers. A
#	LEADER may be a bracketed [$mom_sys_leader(NAME)] (X Y Z N, and
#	fourth_axis / fifth_axis: the machine's rotary letters); the machine
#	file's 'output' keys and the options below override decimals and
#	numbering.
#
#	Dialects are data (each controller's writer table, one file per
#	controller in lib/dialect/): what differs between controllers is
#	looked up there, not written as a copy of the code; the forms of a
#	controller's own are methods of a class in its file, mixed into the
#	Writer (the table's methods key). ../shared/spec/dialects.md gives
#	what each control must receive.
#	Errors: {FIVAX OPTION ...}, {FIVAX OUTPUT <DETAIL>}.

namespace eval ::fivax::output {
    namespace export create sysVars
    namespace ensemble create -prefixes 0

    variable Options {
        {-def any {} DICT "the post's .def as read by fivax::def (required)"}
        {-controller {maybe enum} {} NAME "controller dialect (default: the machine's)"}
        {-tcp bool 0 "" "TCP mode: X Y Z are the tool tip in the workpiece frame, the control keeps the tip on the path"}
        {-decimals {maybe int min 0 max 9} {} N "decimals of X Y Z (default: the .def's)"}
        {-angle-decimals {maybe int min 0 max 9} {} N "decimals of the rotary axes (default: the .def's)"}
        {-feed-decimals {maybe int min 0 max 9} {} N "decimals of F in mm/min (default: the .def's)"}
        {-inverse-decimals {maybe int min 0 max 9} {} N
            "decimals of F in inverse time, G93 (default: the .def's)"}
        {-sequence {maybe bool} {} "0|1" "write N sequence numbers (default: when the .def has a SEQUENCE)"}
        {-seq-start {maybe int min 0} {} N "first sequence number (default: the .def's)"}
        {-seq-incr {maybe int min 1} {} N "sequence number step (default: the .def's)"}
        {-program {int min 0} 1000 N "program number"}
        {-arc-words {enum ijk r} ijk FORM
            "native arcs' centre: I J K from the start (ijk) or the radius R (r; full circles and arcs within 5 deg of 180 keep I J K)"}
        {-insert {enum checked verbatim} checked MODE
            "INSERT text: written when it reads as NC words of the dialect, else as a comment with a warning (checked), or as it is (verbatim)"}
        {-warn any {} CMD "command prefix called with each warning (a MIN/MAX Warning of the .def, INSERT text not written)"}
    }
    # (the controllers are those of lib/dialect/)
    lset Options [lsearch -index 0 $Options -controller] 1 [list maybe enum {*}[::fivax::dialect names]]
    # The addresses this layer writes: every one must be in the .def.
    variable Addresses {G_motion G_feed G_plane G_mode G_units G_length G_cycle
        G_cutcom G_wcs G_machine G_return G_dwell X Y Z R Q P_ms P_s fourth_axis fifth_axis F F_inv S T H
        M_spindle M_coolant M I J K G_rot G_tilt E_i E_j E_k D F_dwell
        KX KY KZ K4 K5 KF KCX KCY KCZ SPA SPB SPC N}

    # The writer table of each controller (lib/dialect/<name>.tcl, see
    # lib/dialect.tcl) has the keys:
    #   syntax     gcode or klartext (numbered lines from 0, no leader of
    #              N, no G codes, the axis addresses KX KY KZ K4 K5)
    #   methods    "" or the class of the controller's own forms, mixed
    #              into the Writer: it overrides the methods that write
    #              them (MachineZ, ChangeTool, Register, LengthWords,
    #              Motion, ArcLines, PlaneLines, PlaneOffLines, EndLines,
    #              ...; PlaneLines and PlaneOffLines where plane is set)
    #   program    the program-number line format ("" for none: the program
    #              comment stands alone, "(PROGRAM n)" when empty)
    #   percent    1: % lines open and close the program
    #   comment    the comment form: paren "(text)", semicolon "; text",
    #              or numbered "n ; text"
    #   semicolon  1: ";" starts a comment to the end of the line
    #   safety     the words of the safety line ({} none)
    #   reset      the lines after it that cancel a work plane and TCP a
    #              previous program may have left on
    #   units      the unit words of mm and inch
    #   inverse    1: inverse-time feed (G93) exists
    #   tcp        {on LINES off LINES} of TCP mode: one G code (on the
    #              first X Y Z block after a tool change, with H), else
    #              the lines written before that block; off: the lines
    #              before the Z up (a G49 alone: the Z up then carries no
    #              G49 of its own); {} when the control has none of its
    #              own (the machine's tcp_codes M codes)
    #   plane      tilted work plane: the angle convention of its
    #              PlaneLines (see lib/plane.tcl), or {} (none: the
    #              planner writes the rotaries and machine coordinates)
    #   arcs       the planes native arcs are written in ({} none), and
    #              helix 1 when a helix is
    #   dwell      the address of a dwell time: P_ms (milliseconds), P_s
    #              or F_dwell (seconds), {} (the methods write dwell)
    #   cycles     canned cycle G codes by NX cycle event; a cycle the
    #              control lacks is expanded into moves by the planner
    #   letters    word letters an INSERT may use besides the machine's
    #              axes (N and O are the post's); {} for none (INSERT
    #              text is always a comment unless -insert verbatim)
    #   active     comment words the controller would act on (defused)
    #   ends       what ends the program in a line of NC text: {M codes,
    #              list of regexps} (an INSERT holding one is an error, see
    #              literal)
    #   cutcom     2D cutter compensation (CUTCOM/LEFT|RIGHT|OFF, see
    #              cutcom): G41/G42/G40 with the register as D (GD), the
    #              same without D (G: the active edge's), R (the methods
    #              write it in their Motion and ArcLines), or {} none
    #   form       the shape of a program, for tools/fuzz.tcl: regexps of
    #              its first and closing lines ("" none), its block of
    #              start modes, its end block, a dwell, and of the lines
    #              after which X Y Z are no machine values (free: work
    #              plane, TCP; "" none)
    #   words      the words distinctive of the controller: they occur in
    #              its file only (tests/dialects.test checks)
    #   cutcom3d   the control's own 3D tool-radius compensation (see
    #              Cutcom3d; {} none), a dict: block (the keyword of its
    #              block in place of a straight move's; G-code: ""), code (the
    #              G_cutcom code that switches it on, "" none; G40 off),
    #              register (D: the tool's register written with it, ""
    #              none), words (literal words after the code), normal
    #              and axis (the prefixes of the surface normal's and the
    #              tool axis's words, {} none), sign (1: the normal out of
    #              the material, -1 into it), format (of those values),
    #              rotaries (0: the rotary words are left out of its
    #              blocks, the control sets them from the tool axis)
    # The G and M codes the layer writes, by the name Post Builder posts
    # keep them under (the variable mom_sys_<name>, which the templates of
    # a .def read; see sysVars): gcode those only the G-code syntax writes,
    # any those every dialect writes. The methods look them up here
    # (Code).
    variable Codes {
        gcode {
            rapid_code 0 linear_code 1 circle_code(CLW) 2 circle_code(CCLW) 3
            output_code(ABSOLUTE) 90 tool_change_code 6 program_stop_code 0
        }
        any {
            optional_stop_code 1 spindle_direction_code(CLW) 3 spindle_direction_code(CCLW) 4
            spindle_direction_code(OFF) 5 coolant_code(MIST) 7 coolant_code(ON) 8
            coolant_code(FLOOD) 8 coolant_code(OFF) 9 end_of_program_code 30
        }
    }
}

# ::fivax::output::create --
#	Returns a new output Writer for machine (a fivax::machine dict). The
#	machine file's 'output' dict gives defaults (its keys are the option
#	names with _ for -: angle_decimals), the options override them.
#	Errors: {FIVAX OUTPUT KEY} "<file>: output: unknown key 'x'" for a
#	bad key of the machine file, {FIVAX OUTPUT VALUE} for a bad value or
#	a TCP mode the control cannot take.
proc ::fivax::output::create {machine args} {
    variable Options
    set src [dict get $machine file]
    set fromMachine {}
    dict for {key value} [dict get $machine output] {
        set opt -[string map {_ -} $key]
        if {[string first - $key] >= 0 || $opt ni [::fivax::opts::names $Options]
                || $opt in {-controller -def -warn -tcp}} {
            ::fivax::Fail OUTPUT KEY "$src: output: unknown key '$key'"
        }
        try {
            ::fivax::opts::check $Options $opt $value
        } trap {FIVAX OPTION} {msg} {
            ::fivax::Fail OUTPUT VALUE "$src: output: $key: [regsub {^bad [^ ]+ } $msg {}]"
        }
        lappend fromMachine $opt $value
    }
    lappend fromMachine -controller [MachineController $machine] -tcp [dict get $machine tcp]
    set opts [::fivax::opts::parse $Options [concat $fromMachine $args] "output create"]
    if {![dict size [dict get $opts -def]]} {
        ::fivax::Fail OPTION MISSING "output create: -def (the post's .def) is required"
    }
    set dialect [::fivax::dialect writer [dict get $opts -controller]]
    if {[dict get $opts -tcp] && ![llength [dict get $dialect tcp]]
            && ![llength [dict get $machine tcp_codes]]} {
        ::fivax::Fail OUTPUT VALUE "$src: TCP mode on [dict get $opts -controller]: the control\
            switches TCP by the machine's own M codes: set tcp_codes {on off} in the machine file"
    }
    Writer new $machine $opts
}

# ::fivax::output::sysVars --
#	Returns the mom_sys_* variables a .def's LEADERs and BLOCK_TEMPLATEs
#	read, with the values the output layer for machine writes in the
#	dialect controller ("": the machine's): {name value ...}, array
#	elements named name(key). mom_sys_leader(NAME) for X Y Z N
#	fourth_axis fifth_axis (see Leaders), and mom_sys_<code> for each
#	code of the Codes table the dialect writes (mom_sys_rapid_code 0,
#	mom_sys_spindle_direction_code(CLW) 3 ...). The post sets them as
#	globals, so that a shop's own block in the .def (NX's
#	MOM_do_template) writes the words the post writes.
#	Errors: {FIVAX OUTPUT VALUE} for a machine's unknown dialect.
proc ::fivax::output::sysVars {machine {controller ""}} {
    set fromMachine [MachineController $machine]
    if {$controller eq ""} {set controller $fromMachine}
    set klartext [expr {[dict get [::fivax::dialect writer $controller] syntax] eq "klartext"}]
    set vars {}
    dict for {name leader} [Leaders $machine $klartext] {
        lappend vars mom_sys_leader($name) $leader
    }
    dict for {name code} [CodesOf $klartext] {
        lappend vars mom_sys_$name $code
    }
    return $vars
}

# ::fivax::output::MachineController --
#	Returns the dialect named by machine's controller key.
#	Errors: {FIVAX OUTPUT VALUE} "<file>: controller: unknown controller ..."
proc ::fivax::output::MachineController {machine} {
    set controller [dict get $machine controller]
    try {
        ::fivax::dialect check $controller "[dict get $machine file]: controller"
    } trap {FIVAX OPTION} {msg} {
        ::fivax::Fail OUTPUT VALUE $msg
    }
}

# ::fivax::output::Leaders --
#	Returns the leader of each word a .def's [$mom_sys_leader(NAME)] may
#	name, by NAME: X Y Z, N (none in the klartext syntax: klartext 1), and
#	fourth_axis, fifth_axis, the letters of machine's rotaries in output
#	order (the fourth axis word first).
proc ::fivax::output::Leaders {machine klartext} {
    lassign [::fivax::machine::rotaryNames $machine] r4 r5
    dict create X X Y Y Z Z N [expr {$klartext ? "" : "N"}] fourth_axis $r4 fifth_axis $r5
}

# ::fivax::output::CodesOf --
#	Returns the codes of the Codes table a dialect writes, by name: those
#	of every dialect, and those of the G-code syntax unless klartext is 1.
proc ::fivax::output::CodesOf {klartext} {
    variable Codes
    if {$klartext} {return [dict get $Codes any]}
    dict merge [dict get $Codes gcode] [dict get $Codes any]
}

oo::class create ::fivax::output::Writer {
    # The state is one array S (one declared variable: TclOO resolves every
    # local of a method against each declared name on every call). S(nc):
    # the block Writer; S(cfg): options; S(dialect): its table entry;
    # S(rotaries): {name chainIndex rollover}, the 4th axis (address
    # fourth_axis) first; S(length): the H register to activate with the
    # next Z move (0: none); S(tcpArmed): 1 when TCP comes on with the
    # next block that writes Z; S(tcpOn): TCP is active; S(loaded): a
    # tool has been changed in; S(home): the rotaries stand at 0 (known
    # so, while their modal memory is empty: see RotariesHome);
    # S(feedMode): inverse or direct of the last feed block; S(cycle): the
    # G code of the active canned cycle (0: none); S(pendingTool): a
    # tool whose change the dialect defers (see ToolCall);
    # S(planeOn): a work plane is active; S(register): the length register
    # of the tool in the spindle; S(program): the program's name (where
    # the dialect writes one);
    # S(arcPlane): the plane of the last arc; S(atSafe): nothing has moved
    # since the last Z up in machine coordinates; S(machine): the machine;
    # S(cutcomSide), S(cutcomReg): the 2D cutter compensation the CL asks
    # for (LEFT, RIGHT, "" off) and its register, S(cutcomOn): the side
    # in effect on the control (see cutcom), S(cutcomCode): its G code
    # last written (40 from the safety line), S(cutcomRot): the rotary
    # angles it came on at, S(cutcomNone): the dialect's lack of it said.
    # After G80 Z and the motion code are
    # written again: the tool stands at the initial level, and the motion
    # mode is stated afresh.
    # Fixed per writer: S(codes) (the Codes the dialect writes, see Code)
    # and, for the per-point path, S(moveCodes) (the G codes of rapid and
    # feed moves, G-code syntax), S(klartext) (the dialect's
    # syntax is klartext), S(tcpInBlock) (TCP comes on inside a motion
    # block with H: the G code S(tcpG)), S(xyzAddr) {X addr Y addr Z addr} and
    # S(rotAddr) {name addr step ...} (the rotaries in the order of their
    # words, see AxisAddresses; step:
    # the output resolution in degrees a rotary that rolls over is rounded
    # to, "" for one that does not): the addresses of the axes in the
    # dialect.
    variable S

    constructor {aMachine opts} {
        set S(machine) $aMachine
        set S(cfg) $opts
        set S(dialect) [::fivax::dialect writer [dict get $S(cfg) -controller]]
        # the controller's own forms (its file's methods class, see the table)
        if {[dict get $S(dialect) methods] ne ""} {
            oo::objdefine [self] mixin [dict get $S(dialect) methods]
        }
        set names [::fivax::machine::rotaryNames $S(machine)]
        set i 0
        foreach axis [dict get $S(machine) chain] {
            set slot [lsearch -exact $names [dict get $axis name]]
            lset names $slot [list [dict get $axis name] $i [dict get $axis rollover]]
            incr i
        }
        set S(rotaries) $names
        set S(length) 0
        set S(loaded) 0
        set S(home) 0
        set S(tcpArmed) 0
        set S(tcpOn) 0
        set S(feedMode) direct
        set S(cycle) 0
        set S(pendingTool) ""
        set S(planeOn) 0
        set S(register) 0
        set S(arcPlane) 17
        set S(atSafe) 0
        set S(program) PART
        set S(cutcomSide) ""
        set S(cutcomOn) ""
        set S(cutcomReg) 0
        set S(cutcomCode) 40
        set S(cutcomRot) {}
        set S(cutcomNone) 0
        set S(c3dOn) 0
        set S(klartext) [expr {[dict get $S(dialect) syntax] eq "klartext"}]
        set S(codes) [::fivax::output::CodesOf $S(klartext)]
        if {!$S(klartext)} {
            set S(moveCodes) [list [my Code rapid_code] [my Code linear_code]]
        }
        set tcp [dict get $S(dialect) tcp]
        # (a single G code: written with H in the block)
        set S(tcpInBlock) [expr {$tcp ne "" && [regexp {^G([0-9.]+)$} [dict get $tcp on] -> S(tcpG)]}]
        set S(nc) [::fivax::nc::create -sequence 0 -warn [dict get $S(cfg) -warn]]
        my Define [dict get $S(cfg) -def]
        my AxisAddresses [dict get $S(cfg) -def]
    }

    destructor {
        if {[info exists S(nc)]} {$S(nc) destroy}
    }

    # Defines the addresses of the .def def on the block writer, resolves
    # their leaders and applies the decimal and numbering options. The
    # klartext syntax numbers every line from 0 in steps of 1, without a leader.
    method Define {def} {
        set defined [::fivax::def::configure $S(nc) $def]
        foreach name $::fivax::output::Addresses {
            if {$name ni $defined} {
                ::fivax::Fail OUTPUT DEF "the post's .def has no ADDRESS $name"
            }
        }
        set leaders [::fivax::output::Leaders $S(machine) $S(klartext)]
        dict for {name a} [dict get $def addresses] {
            if {[dict get $a leader_expr] eq ""} continue
            if {![regexp {^\s*\$mom_sys_leader\((\w+)\)\s*$} [dict get $a leader_expr] -> key]
                    || ![dict exists $leaders $key]} {
                ::fivax::Fail OUTPUT DEF "the post's .def: ADDRESS $name: unsupported LEADER\
                    \[[dict get $a leader_expr]\] (the output layer knows\
                    \[\$mom_sys_leader(NAME)\] for [join [dict keys $leaders] {, }])"
            }
            $S(nc) address $name -leader [dict get $leaders $key]
        }
        foreach {opt addresses sign} {-decimals {X Y Z I J K} "" -decimals {KX KY KZ KCX KCY KCZ} +
                -angle-decimals {fourth_axis fifth_axis} "" -angle-decimals {K4 K5} +
                -feed-decimals {F KF} "" -inverse-decimals F_inv ""} {
            set d [dict get $S(cfg) $opt]
            if {$d eq ""} continue
            foreach name $addresses {$S(nc) address $name -format %${sign}.${d}f}
        }
        if {$S(klartext)} {
            $S(nc) address N -leader "" -max {999999999 abort}
            $S(nc) configure -seq-start 0 -seq-incr 1 -seq-max 999999999
            $S(nc) sequence on
            return
        }
        set seq [dict get $def sequence]
        set on [dict get $S(cfg) -sequence]
        if {$on eq ""} {set on [expr {[llength $seq] > 0}]}
        $S(nc) sequence [expr {$on ? "on" : "off"}]
        foreach opt {-seq-start -seq-incr} {
            if {[dict get $S(cfg) $opt] ne ""} {$S(nc) configure $opt [dict get $S(cfg) $opt]}
        }
    }

    # Returns the code called name in the Codes table (rapid_code ...).
    method Code {name} {
        dict get $S(codes) $name
    }

    # Sets S(xyzAddr) and S(rotAddr) (see the state) from the dialect, the
    # formats of the rotary addresses and the word order of the .def def.
    method AxisAddresses {def} {
        set prefix [expr {$S(klartext) ? "K" : ""}]
        set S(xyzAddr) [list X ${prefix}X Y ${prefix}Y Z ${prefix}Z]
        set S(rotAddr) {}
        foreach r $S(rotaries) addr [expr {$S(klartext) ? {K4 K5} : {fourth_axis fifth_axis}}] {
            lassign $r name - roll
            lappend S(rotAddr) $name $addr [expr {$roll ? 10.0 ** -[$S(nc) decimals $addr] : ""}]
        }
        # the rotary words in the order of the .def's linear_move template,
        # as NX writes a block: fifth_axis before fourth_axis there puts
        # the fifth axis's word first
        set order {}
        if {[dict exists $def blocks linear_move]} {
            set order [lmap word [dict get $def blocks linear_move] {
                if {![dict exists $word address]} continue
                dict get $word address
            }]
        }
        set fifth [lsearch -exact $order fifth_axis]
        if {$fifth >= 0 && $fifth < [lsearch -exact $order fourth_axis]} {
            set S(rotAddr) [concat [lrange $S(rotAddr) 3 5] [lrange $S(rotAddr) 0 2]]
        }
    }

    # Returns the rotary output resolution (degrees) the planner rounds
    # to: one unit of the last decimal of the fourth axis's format.
    method angleStep {} {
        set addr [expr {$S(klartext) ? "K4" : "fourth_axis"}]
        expr {10.0 ** -[$S(nc) decimals $addr]}
    }

    # Returns {length angle}: the output resolution of X (file units) and
    # of the rotaries (degrees), one unit of their last decimal.
    method resolution {} {
        set addr [expr {$S(klartext) ? "KX" : "X"}]
        list [expr {10.0 ** -[$S(nc) decimals $addr]}] [my angleStep]
    }

    # Returns what the dialect can write, for the planner: a dict of
    # controller, inverse (G93 exists), cutcom3d (the control has its own
    # 3D tool-radius compensation: see Cutcom3d), plane (a work plane exists), arcPlanes (the
    # planes of native arcs), helix (1: helical arcs), tcp (TCP mode on).
    method capabilities {} {
        dict create controller [dict get $S(cfg) -controller] inverse [dict get $S(dialect) inverse] \
            cutcom3d [expr {[llength [dict get $S(dialect) cutcom3d]] > 0}] \
            plane [expr {[dict get $S(dialect) plane] ne "" && ![dict get $S(cfg) -tcp]}] \
            arcPlanes [dict get $S(dialect) arcs planes] helix [dict get $S(dialect) arcs helix] \
            tcp [dict get $S(cfg) -tcp]
    }

    # Returns the program-start lines: the dialect's program header
    # carrying comment, the safety line (no cutter, length or cycle compensation active), the resets of work
    # plane and TCP (see Resets), units, absolute mode, feed mode and
    # plane, then the machine's work offset.
    method start {comment {name PART}} {
        set unit [my Unit]
        set lines {}
        if {[dict get $S(dialect) percent]} {lappend lines %}
        set format [dict get $S(dialect) program]
        set number [dict get $S(cfg) -program]
        set text [my Sanitise $comment]
        if {$format ne ""} {
            set line [format $format $number]
            if {$text ne ""} {append line " ($text)"}
            lappend lines $line
        } else {
            if {$text eq ""} {set text "PROGRAM $number"}
            lappend lines [my comment $text]
        }
        if {[llength [dict get $S(dialect) safety]]} {
            lappend lines [$S(nc) block [dict get $S(dialect) safety]]
        }
        lappend lines {*}[my Resets]
        set modes [list G_units $unit G_mode [my Code output_code(ABSOLUTE)] G_feed 94 G_plane 17]
        lappend lines [$S(nc) block $modes] \
            [$S(nc) block [list G_wcs [dict get $S(machine) work_offset]]]
    }

    # Returns the lines that cancel, at the program start, a work plane
    # and TCP a previous program may have left on: the dialect's reset
    # lines (its table's reset), and the machine's TCP-off M code where the control has no TCP
    # of its own (tcp_codes).
    method Resets {} {
        set lines [lmap text [dict get $S(dialect) reset] {$S(nc) line $text}]
        if {[dict get $S(dialect) tcp] eq "" && [llength [dict get $S(machine) tcp_codes]]} {
            lappend lines [$S(nc) line M[lindex [dict get $S(machine) tcp_codes] 1]]
        }
        return $lines
    }

    # Returns text as one comment line in the dialect's style (G-code:
    # never numbered; numbered: as every line is).
    method comment {text} {
        set text [my Sanitise $text]
        switch -exact -- [dict get $S(dialect) comment] {
            paren {return ($text)}
            semicolon {return "; $text"}
            numbered {return [$S(nc) line "; $text"]}
        }
    }

    # Returns the tool change blocks for tool number: Z up to the
    # tool-change height (see safeZ), the rotaries to 0 unless they are
    # known to stand there (see RotariesHome), then the dialect's change
    # (ChangeTool: T M6); arms the length compensation (see Register)
    # for the next Z move, and TCP mode for the
    # next X Y Z block. Modal memory is reset: everything is written
    # again after a tool change.
    method toolChange {number adjust} {
        set lines [my safeZ]
        if {![my RotariesHome]} {lappend lines {*}[my HomeRotaries]}
        lappend lines {*}[my ChangeTool $number]
        $S(nc) reset
        set S(home) 1
        set S(register) [my Register $adjust]
        set S(length) $S(register)
        set S(loaded) 1
        set S(tcpArmed) [dict get $S(cfg) -tcp]
        return $lines
    }

    # Returns the blocks that change tool number in (T M6).
    method ChangeTool {number} {
        list [$S(nc) block [list T $number M [my Code tool_change_code]]]
    }

    # Returns the length register to activate with a tool's first Z move:
    # adjust, the tool's (H).
    method Register {adjust} {
        return $adjust
    }

    # Returns 1 when both rotaries stand at home (see Home): as last
    # written, or when the modal memory has forgotten them (a tool change,
    # a work plane), S(home).
    method RotariesHome {} {
        set home 1
        foreach {addr h} [my Home] {
            set v [$S(nc) value $addr]
            if {$v eq ""} {return $S(home)}
            if {abs($v - $h) >= 0.5 * 10.0 ** -[$S(nc) decimals $addr]} {set home 0}
        }
        return $home
    }

    # Returns {address degrees ...}: the rotaries' home, 0 or the limit
    # nearest to it when 0 is outside the limits (never a value outside).
    method Home {} {
        set home {}
        foreach {name addr -} $S(rotAddr) {
            lassign [dict get $S(machine) limits $name] lo hi
            lappend home $addr [::fivax::num::deg [expr {min(max(0.0, $lo), $hi)}]]
        }
        return $home
    }

    # Returns the rapid block that turns both rotaries home (see Home).
    method HomeRotaries {} {
        set home [my Home]
        $S(nc) force once [dict keys $home]
        $S(nc) force once G_motion
        list [$S(nc) block [list G_motion [my Code rapid_code] {*}$home]]
    }

    # Returns the words that switch the armed length compensation on in a
    # block with a Z move: G43 H<register>.
    method LengthWords {} {
        set n $S(length)
        set S(length) 0
        list G_length 43 H $n
    }

    # Returns the blocks that take the spindle up to the machine's
    # tool-change height with TCP and length compensation cancelled (in
    # machine coordinates, see MachineZ), ending an active cycle first. The
    # written Z is forgotten: the next Z is in the work frame, and the
    # length compensation (and TCP mode, once a tool is loaded) come on
    # again with it. Nothing when nothing has moved since the last one.
    method safeZ {} {
        if {$S(atSafe)} {return {}}
        set S(atSafe) 1
        set lines [my Cutcom3dOff]
        set off [my TcpOff]
        lappend lines {*}[my CycleOff] {*}$off
        lappend lines {*}[my MachineZ [dict get $S(machine) tool_change_z] $off]
        $S(nc) reset [dict get $S(xyzAddr) Z]
        set S(length) $S(register)
        set S(tcpArmed) [expr {$S(loaded) && [dict get $S(cfg) -tcp]}]
        return $lines
    }

    # Returns the blocks of a Z move to z in machine coordinates, the
    # length compensation cancelled: G0 G49 G53 Z (off: the TCP-off lines
    # just written; a TCP G code of the dialect's own is cancelled by its
    # off lines, the G49 alone, and the Z up then carries no G49).
    method MachineZ {z off} {
        $S(nc) force once {G_motion Z}
        set g49 [expr {[llength $off] && [dict get $S(dialect) tcp] ne "" ? {} : {G_length 49}}]
        list [$S(nc) block [list G_motion [my Code rapid_code] {*}$g49 G_machine 53 Z $z]]
    }

    # Returns the spindle-on blocks: speed (rpm), direction CLW or CCLW.
    # A start (the spindle not turning that way) writes S too, even when
    # it is in effect already.
    method spindle {speed direction} {
        set m [my Code spindle_direction_code([expr {$direction eq "CCLW" ? "CCLW" : "CLW"}])]
        set speed [expr {round($speed)}]
        if {[$S(nc) value M_spindle] ne $m} {$S(nc) force once S}
        concat [my CycleOff] [list [$S(nc) block [list S $speed M_spindle $m]]]
    }

    # Returns the spindle-off block.
    method spindleOff {} {
        set words [list M_spindle [my Code spindle_direction_code(OFF)]]
        concat [my CycleOff] [list [$S(nc) block $words]]
    }

    # Returns the coolant-on block for mode (MIST: M7, FLOOD and any
    # other: M8).
    method coolant {mode} {
        set m [my Code coolant_code([expr {$mode eq "MIST" ? "MIST" : "ON"}])]
        list [$S(nc) block [list M_coolant $m]]
    }

    # Returns the coolant-off block.
    method coolantOff {} {
        set words [list M_coolant [my Code coolant_code(OFF)]]
        list [$S(nc) block $words]
    }

    # Returns the program stop block (optional: M1, else M0).
    method stop {optional} {
        set code [my Code [expr {$optional ? "optional_stop_code" : "program_stop_code"}]]
        concat [my CycleOff] [list [$S(nc) block [list M $code]]]
    }

    # Returns the dwell blocks for seconds (G4 P or F in the dialect's
    # unit).
    method dwell {seconds} {
        concat [my CycleOff] [list [$S(nc) block [concat {G_dwell 4} [my DwellWords $seconds]]]]
    }

    # Returns the words of a dwell time of seconds in the dialect's unit.
    method DwellWords {seconds} {
        set addr [dict get $S(dialect) dwell]
        list $addr [expr {$addr eq "P_ms" ? $seconds * 1000.0 : $seconds}]
    }

    # Returns 1 when the dialect has the canned cycle of NX cycle event.
    method canCycle {event} {
        dict exists $S(dialect) cycles $event
    }

    # Returns the canned-cycle cancel block (G80) when a cycle is active.
    method cycleOff {} {
        my CycleOff
    }

    # Returns {G80 block} and forgets the active cycle, or {} when none is
    # active. After a canned cycle the tool stands at the initial level,
    # not at the last written Z: Z is written again.
    method CycleOff {} {
        if {!$S(cycle)} {return {}}
        set S(cycle) 0
        $S(nc) reset {Z G_motion}
        list [$S(nc) block {G_cycle 80}]
    }

    # Returns the lines that end TCP mode when it is on (none for a TCP G
    # code with no off lines: the G49 of the next Z up ends it).
    method TcpOff {} {
        set S(tcpArmed) 0
        if {!$S(tcpOn)} {return {}}
        set S(tcpOn) 0
        if {[dict get $S(dialect) tcp] eq ""} {
            return [list [$S(nc) line M[lindex [dict get $S(machine) tcp_codes] 1]]]
        }
        lmap text [dict get $S(dialect) tcp off] {$S(nc) line $text}
    }

    # Returns the lines that start TCP mode before a block writing any of
    # X Y Z in axes when TCP is armed, and {} (a TCP G code goes into
    # that block itself: see Motion).
    method TcpOn {axes} {
        if {!$S(tcpArmed) || ![llength [lmap a {X Y Z} {if {$a in $axes} {set a} else continue}]]
                || $S(tcpInBlock)} {
            return {}
        }
        set S(tcpArmed) 0
        set S(tcpOn) 1
        if {[dict get $S(dialect) tcp] eq ""} {
            return [list [$S(nc) line M[lindex [dict get $S(machine) tcp_codes] 0]]]
        }
        lmap text [dict get $S(dialect) tcp on] {$S(nc) line $text}
    }

    # Returns the block of a hole record (kind cycle, see ::fivax::motion
    # hole): the first of a cycle with G98, the cycle's G code, X Y, Z at
    # the bottom, R, Q (peck) or P (dwell), F; the next ones of the same
    # cycle with what changed.
    method Cycle {rec} {
        set S(atSafe) 0
        set axes [dict get $rec axes]
        set event [dict get $rec event]
        # a deep or chip-breaking drill without a peck depth drills in one go
        if {$event in {drill_deep drill_break_chip} && [dict get $rec step] <= 0} {
            set event drill
        }
        set code [dict get $S(dialect) cycles $event]
        set lines {}
        if {$code != $S(cycle)} {
            set lines [my CycleOff]
            set S(cycle) $code
            $S(nc) force once {G_cycle G_return Z R F Q}
        }
        set words {}
        if {$S(arcPlane) != 17} {
            # after an arc in G18 or G19: the cycle drills along Z again
            lappend words G_plane 17
            set S(arcPlane) 17
        }
        lappend words G_return 98 G_cycle $code
        if {$S(feedMode) eq "inverse"} {
            lappend words G_feed 94
            set S(feedMode) direct
        }
        lappend words X [dict get $axes X] Y [dict get $axes Y] Z [dict get $axes Z] \
            R [dict get $rec r]
        if {$code in {83 73} && [dict get $rec step] > 0} {
            lappend words Q [dict get $rec step]
        }
        if {$code in {82 89}} {
            lappend words {*}[my DwellWords [dict get $rec delay]]
        }
        lappend words F [dict get $rec rate]
        lappend lines [$S(nc) block $words]
    }

    # Returns INSERT text as an NC line when it reads as NC words of the
    # dialect (see NotWords) or -insert is verbatim; else as a comment,
    # with a warning. Errors: {FIVAX OUTPUT INSERT} for an NC line that
    # ends the program (M30 ...): the control would stop there, and the
    # program's own end (Z up, spindle off) would never run.
    method literal {text} {
        set verbatim [expr {[dict get $S(cfg) -insert] eq "verbatim"}]
        set why [expr {$verbatim ? "" : [my NotWords $text]}]
        if {$why eq ""} {
            set end [my ProgramEnd $text]
            if {$end ne ""} {
                ::fivax::Fail OUTPUT INSERT "INSERT '$text' ends the program\
                    ($end) before its end: the control would stop there; take it out of\
                    the CL (the post writes the program end)"
            }
            return [list $text]
        }
        set warn [dict get $S(cfg) -warn]
        if {[llength $warn]} {
            {*}$warn "INSERT text written as a comment: $why (-insert verbatim writes it as it is)"
        }
        list [my comment $text]
    }

    # Returns what in the NC text ends the program in the dialect (the M
    # code or the line its ends patterns find), outside its comments;
    # "" when nothing does.
    method ProgramEnd {text} {
        lassign [dict get $S(dialect) ends] codes patterns
        set code [string toupper [regsub -all {\([^()]*\)} $text " "]]
        if {[dict get $S(dialect) semicolon]} {regsub {;.*$} $code "" code}
        foreach {- n} [regexp -all -inline {(?:^|[^A-Z0-9_.])M\s*0*(\d+)(?![\d.])} $code] {
            if {$n in $codes} {return M$n}
        }
        foreach re $patterns {
            if {[regexp -- $re $code word]} {return $word}
        }
        return ""
    }

    # Returns what keeps text from being a line of NC words ("" when it
    # is one): after its ( ) comments, whitespace-separated words of an
    # upper-case letter and a number, the letter one of the machine's
    # axes or the dialect's letters.
    method NotWords {text} {
        if {![llength [dict get $S(dialect) letters]]} {
            return "[dict get $S(cfg) -controller] takes no NC words from the CL"
        }
        set letters [concat {X Y Z} [lmap r $S(rotaries) {lindex $r 0}] [dict get $S(dialect) letters]]
        set words [regsub -all {\([^()]*\)} $text " "]
        if {[string first ( $words] >= 0 || [string first ) $words] >= 0} {
            return "unbalanced parentheses"
        }
        foreach word [regexp -all -inline {\S+} $words] {
            if {![regexp {^([A-Z])[-+]?(\d+\.?\d*|\.\d+)$} $word -> letter]} {
                return "'$word' is no NC word"
            }
            if {$letter ni $letters} {
                return "the letter $letter is not one of [join $letters {, }]"
            }
        }
        return ""
    }

    # Returns the blocks of the move record rec (see lib/motion/record.tcl):
    # G0 or G1 (see Motion), length compensation
    # with the first Z move after a tool change, TCP with the first X Y Z
    # move, G93/G94 and F for feed moves, and the axes in its write list
    # in machine units and degrees (a rotary that rolls over written in
    # [0, 360)); arcs, work planes, holes and dwells by their kind.
    method move {rec} {
        set kind [dict get $rec kind]
        if {$S(c3dOn) && $kind in {cycle dwell arc plane planeOff}} {
            # (the control's 3D compensation ends before a block of another kind)
            return [concat [my Cutcom3dOff] [my move $rec]]
        }
        switch -- $kind {
            cycle {return [my Cycle $rec]}
            dwell {return [my dwell [dict get $rec seconds]]}
            arc {return [my Arc $rec]}
            plane {return [my PlaneOn $rec]}
            planeOff {return [my PlaneOff]}
        }
        set write [dict get $rec write]
        if {![llength $write]} {
            # a positioning move that moves no axis here (a work plane's
            # rotaries are the control's)
            return {}
        }
        set S(atSafe) 0
        set lines {}
        if {$S(cycle)} {set lines [my CycleOff]}
        set isFeed [expr {$kind eq "feed"}]
        if {$S(tcpArmed)} {lappend lines {*}[my TcpOn $write]}
        lappend lines {*}[my Motion $rec $isFeed]
    }

    # Returns the block of the straight move record rec (a feed when
    # isFeed, else a rapid): G0 or G1, length compensation or a TCP G
    # code with the first Z move, cutter compensation, G93/G94 and F.
    method Motion {rec isFeed} {
        set write [dict get $rec write]
        set words [list G_motion [lindex $S(moveCodes) $isFeed]]
        if {$S(tcpArmed) && $S(tcpInBlock) && "Z" in $write} {
            # TCP on by a G code: it with H in the first Z block (the
            # approach's X Y Z, see ::fivax::motion First)
            lappend words G_length $S(tcpG) H $S(length)
            set S(length) 0
            set S(tcpArmed) 0
            set S(tcpOn) 1
        } elseif {$S(length) && "Z" in $write} {
            lappend words {*}[my LengthWords]
        }
        lappend words {*}[my CutcomWords [my CutcomStep $rec $isFeed]]
        set normal [expr {[dict exists $rec normal] || $S(c3dOn) ? [my Cutcom3d $rec] : {}}]
        if {[llength $normal]} {
            # (the axis words of the control's 3D compensation go after X Y Z)
            set normal [lassign $normal on]
            lappend words {*}$on
        }
        if {$isFeed} {
            # (single-value lappends, as in AxisWords)
            lappend words G_feed
            if {[dict get $rec mode] eq "inverse"} {
                lappend words 93
                set S(feedMode) inverse
                set feed F_inv
            } else {
                lappend words 94
                if {$S(feedMode) eq "inverse"} {$S(nc) force once F}
                set S(feedMode) direct
                set feed F
            }
        }
        set words [::fivax::output::AxisWords $words $rec $S(xyzAddr) $S(rotAddr)]
        lappend words {*}$normal
        if {$isFeed} {
            lappend words $feed
            lappend words [dict get $rec rate]
        }
        list [$S(nc) block $words]
    }

    # --- the control's 3D tool-radius compensation (-cutcom3d control) ---
    # A feed move record with a key normal (the unit surface normal at
    # its contact, workpiece frame, out of the material: the post adds it)
    # is written in the dialect's cutcom3d form (see the table): X Y Z the
    # programmed tip, the normal (and the tool axis) as words, the control
    # offsetting by its tool table's delta values. The first such block
    # switches the compensation on, the next block without a normal off.

    # Returns {switch normalWord...} for move record rec (G-code; called
    # with a normal or while the compensation is on): switch the words
    # that turn it on (the first block with a normal) or off (G40, the
    # first without), else {}, then the words of its normal.
    method Cutcom3d {rec} {
        set form [dict get $S(dialect) cutcom3d]
        if {![dict exists $rec normal]} {
            set S(c3dOn) 0
            return [list [list G_cutcom 40]]
        }
        set on {}
        if {!$S(c3dOn) && [dict get $form code] ne ""} {
            set on [list G_cutcom [dict get $form code]]
            if {[dict get $form register] ne ""} {
                lappend on [dict get $form register] $S(register)
            }
            foreach word [dict get $form words] {lappend on "" $word}
        }
        set S(c3dOn) 1
        list $on {*}[my Cutcom3dWords $rec]
    }

    # Returns the literal words (name "" value ...) of the normal and, when
    # the dialect names them, the tool axis of move record rec.
    method Cutcom3dWords {rec} {
        set form [dict get $S(dialect) cutcom3d]
        set words {}
        foreach key {normal axis} vec [list [dict get $rec normal] [dict get $rec t]] \
                sign [list [dict get $form sign] 1] {
            if {![llength [dict get $form $key]]} continue
            foreach prefix [dict get $form $key] v $vec {
                # (no -0.0000000)
                set v [expr {abs($v) < 5e-8 ? 0.0 : $sign * $v}]
                lappend words "" $prefix[format [dict get $form format] $v]
            }
        }
        return $words
    }

    # Returns the block that ends the control's 3D compensation (G-code
    # G40) when it is on, else nothing.
    method Cutcom3dOff {} {
        if {!$S(c3dOn)} {return {}}
        set S(c3dOn) 0
        # (a form without a code ends with the next block of another kind)
        if {[dict get $S(dialect) cutcom3d code] eq ""} {return {}}
        list [$S(nc) block {G_cutcom 40}]
    }

    # --- 2D cutter compensation (CUTCOM) ---------------------------------
    # The CL of a CUTCOM is the tool centre path (NX centerline data,
    # Creo OUTPUT_ON_CENTER, SolidWorks CAM), so the compensation written
    # is the control's correction of it: its register holds the wear (the
    # actual radius less the programmed), not the radius. It is meaningful
    # where the contour lies in the plane the control offsets in, i.e. the
    # tool stands along the Z of the written X Y Z (CutcomFits): 3-axis
    # and 3+2 work; under rotary motion or a tilted tool (simultaneous
    # five-axis) it is left off with a warning, never dropped silently.

    # Sets the 2D cutter compensation the CL asks for: side LEFT, RIGHT or
    # OFF, register the D register (0: none written). It comes on with the
    # next feed move that fits (G41/G42, or the dialect's; the control's
    # approach move) and goes off with the next move (G40, R0).
    method cutcom {side register} {
        set S(cutcomSide) [expr {$side in {LEFT RIGHT} ? $side : ""}]
        set S(cutcomReg) $register
        if {$S(cutcomSide) ne "" && [dict get $S(dialect) cutcom] eq ""} {
            set S(cutcomSide) ""
            set warn [dict get $S(cfg) -warn]
            if {[llength $warn] && !$S(cutcomNone)} {
                set S(cutcomNone) 1
                {*}$warn "CUTCOM/$side: [dict get $S(cfg) -controller] takes the cutter's whole\
                    diameter from its tool table (G41/G42), which would offset this tool centre\
                    path twice: no cutter compensation written (said once), the CL path is\
                    posted as the tool centre path"
            }
        }
    }

    # Returns the side of compensation (LEFT, RIGHT, "") in effect with
    # the move record rec (a feed move when isFeed: the compensation
    # comes on with one across the plane, X or Y changing), and warns
    # where the CL's compensation cannot be written: the tool off the Z of
    # the X Y Z (CutcomFits), or the rotaries leaving the angles it came
    # on at.
    method CutcomStep {rec isFeed} {
        set want $S(cutcomSide)
        if {$want eq "" && $S(cutcomOn) eq ""} {return ""}
        set rot [lmap r $S(rotaries) {dict get $rec axes [lindex $r 0]}]
        if {$want ne "" && $S(cutcomOn) eq "" && !($isFeed && [my MovesInPlane $rec])} {
            # (it comes on with a cut across the plane: the control's approach)
            return ""
        }
        if {$want ne "" && (![my CutcomFits $rec]
                || ($S(cutcomOn) ne "" && ![::fivax::output::SameAngles $rot $S(cutcomRot)]))} {
            set warn [dict get $S(cfg) -warn]
            if {[llength $warn]} {
                {*}$warn "CUTCOM/$want with the tool off the Z of the written X Y Z or\
                    turning (simultaneous five-axis, a tilted tool) at the move of\
                    [dict get $rec src]: no cutter compensation from there (G40, R0), the CL\
                    path is posted as the tool centre path"
            }
            set S(cutcomSide) ""
            set want ""
        }
        if {$want ne "" && $S(cutcomOn) eq ""} {set S(cutcomRot) $rot}
        set S(cutcomOn) $want
    }

    # Returns 1 when move record rec changes the written X or Y.
    method MovesInPlane {rec} {
        foreach axis {X Y} {
            set addr [dict get $S(xyzAddr) $axis]
            set last [$S(nc) value $addr]
            set half [expr {0.5 * 10.0 ** -[$S(nc) decimals $addr]}]
            if {$last eq "" || abs([dict get $rec axes $axis] - $last) >= $half} {return 1}
        }
        return 0
    }

    # Returns 1 when the tool of move record rec stands along the Z of the
    # X Y Z written (the plane G41/G42 offset in): in a work plane (the
    # plane's Z is the tool axis), with TCP when the tool axis is the
    # workpiece's Z, else when it is the machine's Z: always on a
    # table-table machine (the tool does not turn), on a head with the
    # head's rotaries at 0.
    method CutcomFits {rec} {
        if {$S(planeOn)} {return 1}
        if {$S(tcpOn) || $S(tcpArmed)} {
            set t [dict get $rec t]
            return [expr {[llength $t] == 3 && [::fivax::vec::angle $t {0.0 0.0 1.0}] < 1e-6}]
        }
        foreach axis [dict get $S(machine) chain] {
            if {[dict get $axis side] eq "head"
                    && abs([dict get $rec axes [dict get $axis name]]) > 1e-9} {return 0}
        }
        return 1
    }

    # Returns the words of a G-code block that bring the compensation to
    # side (see CutcomStep): G41/G42 (with D on a GD dialect), G40, or
    # none when the control's is that already.
    method CutcomWords {side} {
        set code [dict get {LEFT 41 RIGHT 42 {} 40} $side]
        if {$code == $S(cutcomCode)} {return {}}
        set S(cutcomCode) $code
        set words [list G_cutcom $code]
        if {$code != 40 && [dict get $S(dialect) cutcom] eq "GD" && $S(cutcomReg) > 0} {
            lappend words D $S(cutcomReg)
        }
        return $words
    }

    # Returns the lines of a tool change the dialect defers to its
    # spindle speed or first move (see ChangeTool): none here.
    method ToolCall {} {
        return {}
    }

    # Returns the blocks of an arc record (kind arc: start, end axes,
    # centre, plane 17/18/19, dir 2 clockwise / 3 counter-clockwise about
    # the plane's normal, feed), see ArcLines.
    method Arc {rec} {
        set S(atSafe) 0
        concat [my CycleOff] [my ToolCall] [my ArcLines $rec]
    }

    # Returns the block of arc record rec: G17..G19 G2/G3 with the end and
    # the centre from the start as I J K (or R, see ArcRadius).
    method ArcLines {rec} {
        set plane [dict get $rec plane]
        lassign [dict get $rec start] sx sy sz
        lassign [dict get $rec center] cx cy cz
        set dir [dict get $rec dir]
        set offsets [dict get {17 {I J} 18 {I K} 19 {J K}} $plane]
        # centre offsets from the start as written (rounded)
        set d [$S(nc) decimals X]
        set words [list G_plane $plane G_motion [my Code circle_code([expr {$dir == 2 ? "CLW" : "CCLW"}])]]
        set S(arcPlane) $plane
        if {$S(feedMode) eq "inverse"} {
            lappend words G_feed 94
            $S(nc) force once F
            set S(feedMode) direct
        }
        set words [::fivax::output::AxisWords $words $rec $S(xyzAddr) $S(rotAddr)]
        set start [lmap v [list $sx $sy $sz] {::fivax::num::fixed $v $d}]
        set radius [expr {[dict get $S(cfg) -arc-words] eq "r" ? [my ArcRadius $rec $start] : ""}]
        if {$radius ne ""} {
            $S(nc) force once R
            lappend words R $radius
        } else {
            foreach name {I J K} s $start c [list $cx $cy $cz] {
                if {$name in $offsets} {lappend words $name [expr {$c - $s}]}
            }
        }
        lappend words F [dict get $rec rate]
        list [$S(nc) block $words]
    }

    # Returns the signed radius R of arc record rec from the written start:
    # negative when the arc turns more than 180 degrees; "" (write I J K)
    # for a full circle and within 5 degrees of 180, where R leaves the
    # centre ill-defined.
    method ArcRadius {rec start} {
        set axes [dict get $rec axes]
        set c [dict get $rec center]
        set n [dict get {17 {0 0 1} 18 {0 1 0} 19 {1 0 0}} [dict get $rec plane]]
        set u [::fivax::vec::sub $start $c]
        set v [::fivax::vec::sub [list [dict get $axes X] [dict get $axes Y] [dict get $axes Z]] $c]
        # the turn about the plane's normal, counter-clockwise positive
        set turn [expr {atan2([::fivax::vec::dot $n [::fivax::vec::cross $u $v]], [::fivax::vec::dot $u $v])}]
        if {[dict get $rec dir] == 2} {set turn [expr {-$turn}]}
        set sweep [::fivax::num::deg [expr {$turn <= 1e-9 ? $turn + 2.0 * $::fivax::num::pi : $turn}]]
        if {$sweep > 355.0 || abs($sweep - 180.0) < 5.0} {return ""}
        set r [::fivax::vec::norm $u]
        expr {$sweep > 180.0 ? -$r : $r}
    }

    # Returns the blocks that tilt the work plane of a plane record
    # (matrix R: columns X' Y' Z', origin O, seq: the sign the control's
    # tilt takes): Z up, then the dialect's work plane (its methods'
    # PlaneLines, with the angles in the convention of its table's plane
    # key); the length compensation again with the next Z. The rotaries
    # turn without being written: their modal memory is cleared.
    method PlaneOn {rec} {
        set angles [::fivax::plane::angles [dict get $S(dialect) plane] [dict get $rec matrix]]
        set lines [concat [my safeZ] [my ToolCall] [my PlaneLines $angles $rec]]
        set S(planeOn) 1
        set S(home) 0
        # (the length compensation again with the plane's first Z move)
        set S(length) $S(register)
        $S(nc) reset
        return $lines
    }

    # Returns the blocks that end the work plane: Z up, then the
    # dialect's PlaneOffLines.
    method PlaneOff {} {
        if {!$S(planeOn)} {return {}}
        set S(planeOn) 0
        set lines [concat [my safeZ] [my PlaneOffLines]]
        $S(nc) reset
        return $lines
    }

    # Returns the program-end lines: the work plane ended, Z up to the
    # tool-change height, the rotaries to 0 when the machine's
    # home_rotaries is 1, then the end lines (see EndLines).
    method end {} {
        set lines [concat [my PlaneOff] [my safeZ]]
        if {[dict get $S(machine) home_rotaries]} {lappend lines {*}[my HomeRotaries]}
        set off [list M_spindle [my Code spindle_direction_code(OFF)] \
            M_coolant [my Code coolant_code(OFF)]]
        concat $lines [my EndLines $off M[my Code end_of_program_code]]
    }

    # Returns the last lines of the program: the block of the words off
    # (spindle and coolant off), the line end (M30), % where the dialect
    # has it.
    method EndLines {off end} {
        set lines [list [$S(nc) block $off] [$S(nc) line $end]]
        if {[dict get $S(dialect) percent]} {lappend lines %}
        return $lines
    }

    # Returns the unit word of the machine's units in the dialect.
    method Unit {} {
        lassign [dict get $S(dialect) units] mm inch
        expr {[dict get $S(machine) units] eq "inch" ? $inch : $mm}
    }

    # Returns text made safe for the inside of a comment: parentheses
    # become [ ], line breaks and control characters spaces, % becomes _,
    # and a leading word the controller would act on (with or without its
    # comma) is defused with _.
    method Sanitise {text} {
        set text [string map {( [ ) ] % _ \r " " \n " " \t " "} $text]
        regsub -all {[\x00-\x1f\x7f]} $text " " text
        set active [dict get $S(dialect) active]
        if {[llength $active]
                && [regexp -nocase "^\\s*([join $active |])(\[^A-Za-z0-9_\]|\$)" $text]} {
            set text _[string trimleft $text]
        }
        return $text
    }
}

# ::fivax::output::SameAngles --
#	Returns 1 when the angle lists a and b (rad) agree within 1e-9.
proc ::fivax::output::SameAngles {a b} {
    foreach x $a y $b {
        if {$x eq "" || $y eq "" || abs($x - $y) > 1e-9} {return 0}
    }
    return 1
}

# ::fivax::output::AxisWords --
#	Returns the block words words followed by the address words of the
#	axes in move record rec's write list, by a Writer's addresses xyzAddr
#	{X addr Y addr Z addr} and rotAddr {name addr step ...} (see the
#	Writer's state): X Y Z as they are, the rotaries in degrees, one that
#	rolls over (step not "") rounded to step and wrapped into [0, 360).
proc ::fivax::output::AxisWords {words rec xyzAddr rotAddr} {
    namespace upvar ::fivax::num pi pi
    set write [dict get $rec write]
    set axes [dict get $rec axes]
    # (single-value lappends: a lappend of two values builds a list first)
    foreach {name addr} $xyzAddr {
        if {$name in $write} {
            lappend words $addr
            lappend words [dict get $axes $name]
        }
    }
    foreach {name addr step} $rotAddr {
        if {$name ni $write} continue
        # (::fivax::num::deg's product, inline on the per-point path)
        set deg [expr {[dict get $axes $name] * 180.0 / $pi}]
        if {$step ne ""} {
            # wrap the written value (rounded first, so 359.9996 is 0.000)
            set deg [expr {round($deg / $step) * $step}]
            set deg [expr {fmod(fmod($deg, 360.0) + 360.0, 360.0)}]
        }
        lappend words $addr
        lappend words $deg
    }
    return $words
}
