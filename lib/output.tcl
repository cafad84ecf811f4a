# output.tcl --
#	The output layer: turns the planner's neutral move records and the
#	post's program events (start, tool change, spindle, coolant, comments,
#	end) into NC blocks of one controller dialect. It alone knows address
#	names, G and M codes, inverse-time F and where length compensation
#	goes; the blocks are built by an nc Writer (lib/nc.tcl). Returns text
#	only: the host writes it.
#
#	The post's .def is the one source of formats: every address this layer
#	writes is defined there (FORMAT, ADDRESS with FORCE, MIN/MAX, LEADER),
#	and so are the word separator, end of line and sequence numbers. A
#	LEADER may be a bracketed [$mom_sys_leader(NAME)] (X Y Z N, and
#	fourth_axis / fifth_axis: the machine's rotary letters); the machine
#	file's 'output' keys and the options below override decimals and
#	numbering.
#
#	Dialects are data (the Dialects table): what differs between
#	controllers is looked up there, not written as a copy of the code.
#	Errors: {FIVAX OPTION ...}, {FIVAX OUTPUT <DETAIL>}.

namespace eval ::fivax::output {
    namespace export create
    namespace ensemble create -prefixes 0

    variable Options {
        {-def any {} DICT "the post's .def as read by fivax::def (required)"}
        {-controller {enum fanuc linuxcnc} fanuc NAME "controller dialect"}
        {-decimals {maybe int min 0 max 9} {} N "decimals of X Y Z (default: the .def's)"}
        {-angle-decimals {maybe int min 0 max 9} {} N "decimals of the rotary axes (default: the .def's)"}
        {-feed-decimals {maybe int min 0 max 9} {} N "decimals of F in mm/min (default: the .def's)"}
        {-inverse-decimals {maybe int min 0 max 9} {} N
            "decimals of F in inverse time, G93 (default: the .def's)"}
        {-sequence {maybe bool} {} "0|1" "write N sequence numbers (default: when the .def has a SEQUENCE)"}
        {-seq-start {maybe int min 0} {} N "first sequence number (default: the .def's)"}
        {-seq-incr {maybe int min 1} {} N "sequence number step (default: the .def's)"}
        {-program {int min 0} 1000 N "program number"}
        {-insert {enum checked verbatim} checked MODE
            "INSERT text: written when it reads as NC words of the dialect, else as a comment with a warning (checked), or as it is (verbatim)"}
        {-warn any {} CMD "command prefix called with each warning (a MIN/MAX Warning of the .def, INSERT text not written)"}
    }
    # The addresses this layer writes: every one must be in the .def.
    variable Addresses {G_motion G_feed G_plane G_mode G_units G_length G_cycle
        G_cutcom G_wcs G_machine G_return G_dwell X Y Z R Q P_ms P_s fourth_axis fifth_axis F F_inv S T H
        M_spindle M_coolant M N}

    # Per dialect:
    #   program    the program-number line format ("" for none: the program
    #              comment stands alone, "(PROGRAM n)" when empty)
    #   active     comment words the controller would act on (defused)
    #   dwell      the address of a dwell time (G4 and cycles): P_ms
    #              (milliseconds) or P_s (seconds)
    #   cycles     canned cycle G codes by NX cycle event; a cycle the
    #              control lacks is expanded into moves by the planner
    #   letters    word letters an INSERT may use besides the machine's
    #              axes (N and O are the post's)
    variable Dialects {
        fanuc {
            program O%04d
            active {}
            dwell P_ms
            cycles {drill 81 drill_dwell 82 drill_deep 83 drill_break_chip 73 tap 84
                bore 85 bore_drag 86 bore_no_drag 76 bore_back 87 bore_manual 88 bore_dwell 89}
            letters {G M F S T H D P Q R I J K L}
        }
        linuxcnc {
            program {}
            active {MSG DEBUG PRINT LOG LOGOPEN LOGAPPEND LOGCLOSE PROBEOPEN PROBECLOSE
                ABORT PY PYRUN PYRELOAD}
            dwell P_s
            cycles {drill 81 drill_dwell 82 drill_deep 83 drill_break_chip 73 tap 84
                bore 85 bore_drag 86 bore_back 87 bore_manual 88 bore_dwell 89}
            letters {G M F S T H D P Q R I J K L}
        }
    }
}

# ::fivax::output::create --
#	Returns a new output Writer for machine (a fivax::machine dict). The
#	machine file's 'output' dict gives defaults (its keys are the option
#	names with _ for -: angle_decimals), the options override them.
#	Errors: {FIVAX OUTPUT KEY} "<file>: output: unknown key 'x'" for a
#	bad key of the machine file, {FIVAX OUTPUT VALUE} for a bad value.
proc ::fivax::output::create {machine args} {
    variable Options
    set src [dict get $machine file]
    set fromMachine {}
    dict for {key value} [dict get $machine output] {
        set opt -[string map {_ -} $key]
        if {[string first - $key] >= 0 || $opt ni [::fivax::opts::names $Options]
                || $opt in {-controller -def -warn}} {
            ::fivax::Fail OUTPUT KEY "$src: output: unknown key '$key'"
        }
        try {
            ::fivax::opts::check $Options $opt $value
        } trap {FIVAX OPTION} {msg} {
            ::fivax::Fail OUTPUT VALUE "$src: output: $key: [regsub {^bad [^ ]+ } $msg {}]"
        }
        lappend fromMachine $opt $value
    }
    set controller [dict get $machine controller]
    if {![dict exists $::fivax::output::Dialects $controller]} {
        ::fivax::Fail OUTPUT VALUE "$src: controller: unknown dialect '$controller': must be\
            [join [dict keys $::fivax::output::Dialects] {, }]"
    }
    lappend fromMachine -controller $controller
    set opts [::fivax::opts::parse $Options [concat $fromMachine $args] "output create"]
    if {![dict size [dict get $opts -def]]} {
        ::fivax::Fail OPTION MISSING "output create: -def (the post's .def) is required"
    }
    Writer new $machine $opts
}

oo::class create ::fivax::output::Writer {
    # nc: the block Writer; cfg: options; dialect: its table entry;
    # rotaries: {name chainIndex rollover} in output order (the 4th axis
    # word first); length: the H register to activate with the next Z
    # move (0: none); feedMode: inverse or direct of the last feed block;
    # cycle: the G code of the active canned cycle (0: none). After G80
    # Z and the motion code are written again: the tool stands at the
    # initial level, and the motion mode is stated afresh.
    variable nc cfg dialect machine rotaries length feedMode cycle

    constructor {aMachine opts} {
        set machine $aMachine
        set cfg $opts
        set dialect [dict get $::fivax::output::Dialects [dict get $cfg -controller]]
        set names [::fivax::machine::rotaryNames $machine]
        set rotaries {}
        set i 0
        foreach axis [dict get $machine chain] {
            set slot [lsearch -exact $names [dict get $axis name]]
            lset names $slot [list [dict get $axis name] $i [dict get $axis rollover]]
            incr i
        }
        set rotaries $names
        set length 0
        set feedMode direct
        set cycle 0
        set nc [::fivax::nc::create -sequence 0 -warn [dict get $cfg -warn]]
        my Define [dict get $cfg -def]
    }

    destructor {
        if {[info exists nc]} {$nc destroy}
    }

    # Defines the addresses of the .def def on the block writer, resolves
    # their leaders and applies the decimal and numbering options.
    method Define {def} {
        set defined [::fivax::def::configure $nc $def]
        foreach name $::fivax::output::Addresses {
            if {$name ni $defined} {
                ::fivax::Fail OUTPUT DEF "the post's .def has no ADDRESS $name"
            }
        }
        lassign [lmap r $rotaries {lindex $r 0}] r4 r5
        set leaders [dict create X X Y Y Z Z N N fourth_axis $r4 fifth_axis $r5]
        dict for {name a} [dict get $def addresses] {
            if {[dict get $a leader_expr] eq ""} continue
            if {![regexp {^\s*\$mom_sys_leader\((\w+)\)\s*$} [dict get $a leader_expr] -> key]
                    || ![dict exists $leaders $key]} {
                ::fivax::Fail OUTPUT DEF "the post's .def: ADDRESS $name: unsupported LEADER\
                    \[[dict get $a leader_expr]\] (the output layer knows\
                    \[\$mom_sys_leader(NAME)\] for [join [dict keys $leaders] {, }])"
            }
            $nc address $name -leader [dict get $leaders $key]
        }
        foreach {opt addresses} {-decimals {X Y Z} -angle-decimals {fourth_axis fifth_axis}
            -feed-decimals F -inverse-decimals F_inv} {
            set d [dict get $cfg $opt]
            if {$d eq ""} continue
            foreach name $addresses {$nc address $name -format %.${d}f}
        }
        set seq [dict get $def sequence]
        set on [dict get $cfg -sequence]
        if {$on eq ""} {set on [expr {[llength $seq] > 0}]}
        $nc sequence [expr {$on ? "on" : "off"}]
        foreach opt {-seq-start -seq-incr} {
            if {[dict get $cfg $opt] ne ""} {$nc configure $opt [dict get $cfg $opt]}
        }
    }

    # Returns the rotary output resolution (degrees) the planner rounds
    # to: one unit of the last decimal of the fourth axis's format.
    method angleStep {} {
        expr {10.0 ** -[$nc decimals fourth_axis]}
    }

    # Returns the program-start lines: the dialect's program header
    # carrying comment, the safety line (no cutter, length or cycle
    # compensation active), units, absolute mode, feed mode and plane,
    # then the machine's work offset.
    method start {comment} {
        set lines [list %]
        set program [dict get $dialect program]
        set number [dict get $cfg -program]
        set text [my Sanitise $comment]
        if {$program ne ""} {
            set line [format $program $number]
            if {$text ne ""} {append line " ($text)"}
            lappend lines $line
        } else {
            if {$text eq ""} {set text "PROGRAM $number"}
            lappend lines ($text)
        }
        lappend lines [$nc block {G_cutcom 40 G_length 49 G_cycle 80}] \
            [$nc block [list G_units [expr {[dict get $machine units] eq "inch" ? 20 : 21}] \
                G_mode 90 G_feed 94 G_plane 17]] \
            [$nc block [list G_wcs [dict get $machine work_offset]]]
    }

    # Returns text as a comment line in the dialect's style, never numbered.
    method comment {text} {
        return ([my Sanitise $text])
    }

    # Returns the tool change blocks for tool number: Z up to the
    # tool-change height (see safeZ), then T M6; arms the length
    # compensation register adjust (0: none) for the next Z move. Modal
    # memory is reset: everything is written again after a tool change.
    method toolChange {number adjust} {
        set lines [my safeZ]
        lappend lines [$nc block [list T $number M 6]]
        $nc reset
        set length $adjust
        return $lines
    }

    # Returns the blocks that take the spindle up to the machine's
    # tool-change height with length compensation cancelled (G0 G49 G53
    # Z<tool_change_z>: machine coordinates), ending an active cycle
    # first. The written Z is forgotten: the next Z is in the work frame.
    method safeZ {} {
        set lines [my CycleOff]
        set length 0
        $nc force once {G_motion Z}
        lappend lines [$nc block [list G_motion 0 G_length 49 G_machine 53 \
            Z [dict get $machine tool_change_z]]]
        $nc reset Z
        return $lines
    }

    # Returns the spindle-on block: speed (rpm), direction CLW or CCLW.
    method spindle {speed direction} {
        concat [my CycleOff] [list [$nc block [list S [expr {round($speed)}] M_spindle \
            [expr {$direction eq "CCLW" ? 4 : 3}]]]]
    }

    # Returns the spindle-off block.
    method spindleOff {} {
        concat [my CycleOff] [list [$nc block {M_spindle 5}]]
    }

    # Returns the coolant-on block for mode (MIST: M7, else M8).
    method coolant {mode} {
        list [$nc block [list M_coolant [expr {$mode eq "MIST" ? 7 : 8}]]]
    }

    # Returns the coolant-off block.
    method coolantOff {} {
        list [$nc block {M_coolant 9}]
    }

    # Returns the program stop block (optional: M1, else M0).
    method stop {optional} {
        concat [my CycleOff] [list [$nc block [list M [expr {$optional ? 1 : 0}]]]]
    }

    # Returns the dwell block for seconds (G4 P in the dialect's unit).
    method dwell {seconds} {
        concat [my CycleOff] [list [$nc block [concat {G_dwell 4} [my DwellWords $seconds]]]]
    }

    # Returns the words of a dwell time of seconds in the dialect's unit.
    method DwellWords {seconds} {
        set addr [dict get $dialect dwell]
        list $addr [expr {$addr eq "P_ms" ? $seconds * 1000.0 : $seconds}]
    }

    # Returns 1 when the dialect has the canned cycle of NX cycle event.
    method canCycle {event} {
        dict exists $dialect cycles $event
    }

    # Returns the canned-cycle cancel block (G80) when a cycle is active.
    method cycleOff {} {
        my CycleOff
    }

    # Returns {G80 block} and forgets the active cycle, or {} when none is
    # active. After a canned cycle the tool stands at the initial level,
    # not at the last written Z: Z is written again.
    method CycleOff {} {
        if {!$cycle} {return {}}
        set cycle 0
        $nc reset {Z G_motion}
        list [$nc block {G_cycle 80}]
    }

    # Returns the block of a hole record (kind cycle, see ::fivax::motion
    # hole): the first of a cycle with G98, the cycle's G code, X Y, Z at
    # the bottom, R, Q (peck) or P (dwell), F; the next ones of the same
    # cycle with what changed.
    method Cycle {rec} {
        set axes [dict get $rec axes]
        set event [dict get $rec event]
        # a deep or chip-breaking drill without a peck depth drills in one go
        if {$event in {drill_deep drill_break_chip} && [dict get $rec step] <= 0} {
            set event drill
        }
        set code [dict get $dialect cycles $event]
        set lines {}
        if {$code != $cycle} {
            set lines [my CycleOff]
            set cycle $code
            $nc force once {G_cycle G_return Z R F Q}
        }
        set words [list G_return 98 G_cycle $code]
        if {$feedMode eq "inverse"} {
            lappend words G_feed 94
            set feedMode direct
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
        lappend lines [$nc block $words]
    }

    # Returns INSERT text as an NC line when it reads as NC words of the
    # dialect (see NotWords) or -insert is verbatim; else as a comment,
    # with a warning.
    method literal {text} {
        if {[dict get $cfg -insert] eq "verbatim"} {return [list $text]}
        set why [my NotWords $text]
        if {$why eq ""} {return [list $text]}
        set warn [dict get $cfg -warn]
        if {[llength $warn]} {
            {*}$warn "INSERT text written as a comment: $why (-insert verbatim writes it as it is)"
        }
        list [my comment $text]
    }

    # Returns what keeps text from being a line of NC words ("" when it
    # is one): after its ( ) comments, whitespace-separated words of an
    # upper-case letter and a number, the letter one of the machine's
    # axes or the dialect's letters.
    method NotWords {text} {
        set letters [concat {X Y Z} [lmap r $rotaries {lindex $r 0}] [dict get $dialect letters]]
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

    # Returns the block of the move record rec (see ::fivax::motion
    # flush): G0 or G1, length compensation with the first Z move after a
    # tool change, G93/G94 and F for feed moves, and the axes in its
    # write list in machine units and degrees (a rotary that rolls over
    # written in [0, 360)).
    method move {rec} {
        switch -- [dict get $rec kind] {
            cycle {return [my Cycle $rec]}
            dwell {return [my dwell [dict get $rec seconds]]}
        }
        set lines [my CycleOff]
        set isFeed [expr {[dict get $rec kind] eq "feed"}]
        set write [dict get $rec write]
        set axes [dict get $rec axes]
        set words [list G_motion $isFeed]
        if {$length && "Z" in $write} {
            lappend words G_length 43 H $length
            set length 0
        }
        if {$isFeed} {
            set mode [dict get $rec mode]
            set inverse [expr {$mode eq "inverse"}]
            lappend words G_feed [expr {$inverse ? 93 : 94}]
            if {!$inverse && $feedMode eq "inverse"} {$nc force once F}
            set feedMode [expr {$inverse ? "inverse" : "direct"}]
        }
        foreach name {X Y Z} {
            if {$name in $write} {lappend words $name [dict get $axes $name]}
        }
        foreach r $rotaries addr {fourth_axis fifth_axis} {
            lassign $r name - roll
            if {$name ni $write} continue
            set deg [::fivax::num::deg [dict get $axes $name]]
            if {$roll} {
                # wrap the written value (rounded first, so 359.9996 is 0.000)
                set step [expr {10.0 ** -[$nc decimals $addr]}]
                set deg [expr {round($deg / $step) * $step}]
                set deg [expr {fmod(fmod($deg, 360.0) + 360.0, 360.0)}]
            }
            lappend words $addr $deg
        }
        if {$isFeed} {
            lappend words [expr {$inverse ? "F_inv" : "F"}] [dict get $rec rate]
        }
        lappend lines [$nc block $words]
    }

    # Returns the program-end lines: Z up to the tool-change height, the
    # rotaries to 0 when the machine's home_rotaries is 1, spindle and
    # coolant off, M30, %.
    method end {} {
        set lines [my safeZ]
        if {[dict get $machine home_rotaries]} {
            set words {G_motion 0}
            foreach r $rotaries addr {fourth_axis fifth_axis} {
                lappend words $addr 0.0
            }
            $nc force once {G_motion fourth_axis fifth_axis}
            lappend lines [$nc block $words]
        }
        concat $lines [list [$nc block {M_spindle 5 M_coolant 9}] [$nc line M30] %]
    }

    # Returns text made safe for the inside of a ( ) comment: parentheses
    # become [ ], line breaks and control characters spaces, % becomes _,
    # and a leading word the controller would act on (with or without its
    # comma) is defused with _.
    method Sanitise {text} {
        set text [string map {( [ ) ] % _ \r " " \n " " \t " "} $text]
        regsub -all {[\x00-\x1f\x7f]} $text " " text
        set active [dict get $dialect active]
        if {[llength $active]
                && [regexp -nocase "^\\s*([join $active |])(\[^A-Za-z0-9_\]|\$)" $text]} {
            set text _[string trimleft $text]
        }
        return $text
    }
}
