# output.tcl --
#	The output layer: turns the planner's neutral move records and the
#	post's program events (start, tool change, spindle, coolant, comments,
#	end) into NC blocks of one controller dialect. It alone knows address
#	names, G and M codes, inverse-time F and where length compensation
#	goes; the blocks are built by an nc Writer (lib/nc.tcl). Returns text
#	only: the host writes it.
#
#	Dialects are data (the Dialects table): what differs between
#	controllers is looked up there, not written as a copy of the code.
#	Errors: {FIVAX OPTION ...}, {FIVAX OUTPUT <DETAIL>}.

namespace eval ::fivax::output {
    namespace export create
    namespace ensemble create -prefixes 0

    variable Options {
        {-controller {enum fanuc linuxcnc} fanuc NAME "controller dialect"}
        {-decimals {int min 0 max 9} 3 N "decimals of X Y Z"}
        {-angle-decimals {int min 0 max 9} 3 N "decimals of the rotary axes"}
        {-feed-decimals {int min 0 max 9} 1 N "decimals of F in mm/min"}
        {-inverse-decimals {int min 0 max 9} 3 N "decimals of F in inverse time (G93)"}
        {-sequence bool 1 "" "write N sequence numbers"}
        {-seq-start {int min 0} 10 N "first sequence number"}
        {-seq-incr {int min 1} 10 N "sequence number step"}
        {-program {int min 0} 1000 N "program number"}
    }

    # Per dialect:
    #   program    the program-number line format ("" for none: the program
    #              comment stands alone, "(PROGRAM n)" when empty)
    #   active     comment words the controller would act on (defused)
    #   dwell      the unit of G4 P: ms or s
    variable Dialects {
        fanuc {
            program O%04d
            active {}
            dwell ms
        }
        linuxcnc {
            program {}
            active {MSG DEBUG PRINT LOG LOGOPEN LOGAPPEND LOGCLOSE PROBEOPEN PROBECLOSE
                ABORT PY PYRUN PYRELOAD}
            dwell s
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
                || $opt eq "-controller"} {
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
    Writer new $machine [::fivax::opts::parse $Options [concat $fromMachine $args] "output create"]
}

oo::class create ::fivax::output::Writer {
    # nc: the block Writer; cfg: options; dialect: its table entry;
    # rotaries: {name chainIndex rollover} in output order (the 4th axis
    # word first); length: the H register to activate with the next Z
    # move (0: none); feedMode: inverse or direct of the last feed block.
    variable nc cfg dialect machine rotaries length feedMode

    constructor {aMachine opts} {
        set machine $aMachine
        set cfg $opts
        set dialect [dict get $::fivax::output::Dialects [dict get $cfg -controller]]
        set nc [::fivax::nc::create -sequence [dict get $cfg -sequence] \
            -seq-start [dict get $cfg -seq-start] -seq-incr [dict get $cfg -seq-incr]]
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
        my Addresses
    }

    destructor {
        if {[info exists nc]} {$nc destroy}
    }

    # Defines the addresses of the blocks this layer writes.
    method Addresses {} {
        set dec %.[dict get $cfg -decimals]f
        set ang %.[dict get $cfg -angle-decimals]f
        set feed %.[dict get $cfg -feed-decimals]f
        set inv %.[dict get $cfg -inverse-decimals]f
        lassign [lmap r $rotaries {lindex $r 0}] r4 r5
        foreach {name leader fmt force} [list \
            G_motion G %g off  G_feed G %g off  G_plane G %g off \
            G_mode G %g off  G_units G %g off  G_length G %g off \
            X X $dec off  Y Y $dec off  Z Z $dec off \
            fourth_axis $r4 $ang off  fifth_axis $r5 $ang off \
            F F $feed off  F_inv F $inv always  S S %d off  T T %d always  H H %d off \
            M_spindle M %g off  M_coolant M %g off  M M %g always] {
            $nc address $name -leader $leader -format $fmt -force $force
        }
    }

    # Returns the rotary output resolution (degrees) the planner rounds to.
    method angleStep {} {
        expr {10.0 ** -[dict get $cfg -angle-decimals]}
    }

    # Returns the program-start lines: the dialect's program header
    # carrying comment, then units, absolute mode, feed mode and plane.
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
        lappend lines [$nc block [list G_units \
            [expr {[dict get $machine units] eq "inch" ? 20 : 21}] G_mode 90 G_feed 94 G_plane 17]]
    }

    # Returns text as a comment line in the dialect's style, never numbered.
    method comment {text} {
        return ([my Sanitise $text])
    }

    # Returns the tool change block for tool number, and arms the length
    # compensation register adjust (0: none) for the next Z move. Modal
    # memory is reset: everything is written again after a tool change.
    method toolChange {number adjust} {
        set line [$nc block [list T $number M 6]]
        $nc reset
        set length $adjust
        return [list $line]
    }

    # Returns the spindle-on block: speed (rpm), direction CLW or CCLW.
    method spindle {speed direction} {
        list [$nc block [list S [expr {round($speed)}] M_spindle \
            [expr {$direction eq "CCLW" ? 4 : 3}]]]
    }

    # Returns the spindle-off block.
    method spindleOff {} {
        list [$nc block {M_spindle 5}]
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
        list [$nc block [list M [expr {$optional ? 1 : 0}]]]
    }

    # Returns the dwell block for seconds (G4 P in the dialect's unit).
    method dwell {seconds} {
        if {[dict get $dialect dwell] eq "s"} {
            return [list [$nc line "G4 P[::fivax::num::fixed $seconds 3]"]]
        }
        list [$nc line [format "G4 P%d" [expr {round($seconds * 1000)}]]]
    }

    # Returns text as an NC line as it is.
    method literal {text} {
        list $text
    }

    # Returns the block of the move record rec (see ::fivax::motion
    # flush): G0 or G1, length compensation with the first Z move after a
    # tool change, G93/G94 and F for feed moves, and the axes in its
    # write list in machine units and degrees (a rotary that rolls over
    # written in [0, 360)).
    method move {rec} {
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
                set step [my angleStep]
                set deg [expr {round($deg / $step) * $step}]
                set deg [expr {fmod(fmod($deg, 360.0) + 360.0, 360.0)}]
            }
            lappend words $addr $deg
        }
        if {$isFeed} {
            lappend words [expr {$inverse ? "F_inv" : "F"}] [dict get $rec rate]
        }
        list [$nc block $words]
    }

    # Returns the program-end lines: spindle and coolant off, M30, %.
    method end {} {
        list [$nc block {M_spindle 5 M_coolant 9}] [$nc line M30] %
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
