# nc.tcl --
#	The G-code block writer: addresses (leader, format, trailer), modal
#	suppression of unchanged words, NX-style force/suppress, sequence
#	numbers and dialect headers. Pure: every command returns text and
#	nothing here writes a file or touches a global.
#
#	State lives in namespace arrays keyed by handle ("nc1", "nc2", ...),
#	per address under "$h,$name". Each address is one list
#	{mode kind spec leader trailer}:
#	    mode  m = modal (written when its text changes), w = always written,
#	          s = suppressed, W = forced once, S = suppressed once;
#	    kind  f = printf real, F = printf real with a + flag, d = printf
#	          integer (value rounded), s = string, a = NX &abcdef code;
#	    spec  the printf string, or the parsed &abcdef fields.
#	The mode is derived from Flags($h,$name) = {base forceAlways
#	suppressAlways once} by Mode, so the hot path reads one element.
#
#	Note: this namespace defines a command called "format"; every core
#	format call in here is written ::format.

namespace eval ::fivax::nc {
    namespace export create configure address format block line comment \
        force suppress sequence resetSequence value reset header footer \
        delete blockWords
    namespace ensemble create -prefixes 0

    variable Count 0
    # Cfg($h): dict of the create options.
    variable Cfg
    # Names($h): address names in definition order.
    variable Names
    # Addr($h,$name): {mode kind spec leader trailer}; see the file header.
    variable Addr
    # Flags($h,$name): {base forceAlways suppressAlways once}.
    variable Flags
    # Last($h,$name): text of the last word written ("" for none).
    variable Last
    # Val($h,$name): value of the last word written ("" for none).
    variable Val
    # Sep($h), Eol($h): word separator and end-of-block text.
    variable Sep
    variable Eol
    # SeqOn($h) 0/1, SeqNext($h), SeqStart($h), SeqIncr($h), SeqMax($h).
    variable SeqOn
    variable SeqNext
    variable SeqStart
    variable SeqIncr
    variable SeqMax
    # FmtCache(F): {kind spec} for every format string parsed so far.
    variable FmtCache
    array set FmtCache {}

    variable Options {-dialect -units -decimals -angleDecimals -feedDecimals
        -sequence -seqStart -seqIncr -seqMax -rotaryNames -separator -eol}
    variable Defaults {-dialect fanuc -units mm -decimals 3 -angleDecimals 3
        -feedDecimals 1 -sequence 1 -seqStart 10 -seqIncr 10 -seqMax 99999
        -rotaryNames {B C} -separator " " -eol ""}
}

# ::fivax::nc::create --
#	Returns a new writer handle with the default address set (N, G_*, X Y Z,
#	fourth_axis fifth_axis, F S T H D, M_spindle M_coolant M).
#	Options: -dialect fanuc|linuxcnc, -units mm|inch, -decimals, -angleDecimals,
#	-feedDecimals (0..9), -sequence bool, -seqStart, -seqIncr, -seqMax,
#	-rotaryNames {B C}, -separator " ", -eol "".
#	Errors: {FIVAX NC OPTION} for an unknown option, {FIVAX NC VALUE} for a bad value.
proc ::fivax::nc::create {args} {
    variable Count
    variable Defaults
    variable Cfg
    variable Names
    set cfg [CheckOptions $Defaults $args]
    set h nc[incr Count]
    set Cfg($h) $cfg
    set Names($h) {}
    Apply $h $cfg
    # The nameless address: literal text (template "strings"), always written.
    variable Addr
    variable Flags
    variable Last
    variable Val
    set Addr($h,) {w s {} {} {}}
    set Flags($h,) {always 0 0 {}}
    set Last($h,) ""
    set Val($h,) ""
    dict with cfg {}
    set dec "%.${-decimals}f"
    set ang "%.${-angleDecimals}f"
    set feed "%.${-feedDecimals}f"
    lassign ${-rotaryNames} r4 r5
    foreach {name leader fmt force} [list \
        N N %d always \
        G_motion G %g off  G_feed G %g off  G_plane G %g off \
        G_mode G %g off  G_units G %g off  G_cutcom G %g off \
        G_length G %g off \
        X X $dec off  Y Y $dec off  Z Z $dec off \
        fourth_axis $r4 $ang off  fifth_axis $r5 $ang off \
        F F $feed off  S S %d off  T T %d always  H H %d off  D D %d off \
        M_spindle M %g off  M_coolant M %g off  M M %g always] {
        address $h $name -leader $leader -format $fmt -force $force
    }
    return $h
}

# ::fivax::nc::configure --
#	Changes create options of handle h after creation; with no options,
#	returns the current option dict. -rotaryNames renames the leaders of
#	fourth_axis and fifth_axis; the decimal options re-format X Y Z, the
#	rotaries and F. Numbering restarts at -seqStart when it is given.
proc ::fivax::nc::configure {h args} {
    variable Cfg
    Handle $h
    if {[llength $args] == 0} {return $Cfg($h)}
    set new [CheckOptions $Cfg($h) $args]
    set given {}
    foreach {opt v} $args {dict set given $opt [dict get $new $opt]}
    set Cfg($h) $new
    Apply $h $given
    dict with new {}
    if {[dict exists $given -decimals]} {
        foreach a {X Y Z} {address $h $a -format "%.${-decimals}f"}
    }
    if {[dict exists $given -angleDecimals]} {
        foreach a {fourth_axis fifth_axis} {address $h $a -format "%.${-angleDecimals}f"}
    }
    if {[dict exists $given -feedDecimals]} {
        address $h F -format "%.${-feedDecimals}f"
    }
    if {[dict exists $given -rotaryNames]} {
        address $h fourth_axis -leader [lindex ${-rotaryNames} 0]
        address $h fifth_axis -leader [lindex ${-rotaryNames} 1]
    }
    return $Cfg($h)
}

# ::fivax::nc::delete -- Forgets handle h and all its addresses.
proc ::fivax::nc::delete {h} {
    variable Cfg
    variable Names
    Handle $h
    foreach v {Addr Flags Last Val} {
        variable $v
        array unset $v $h,*
    }
    foreach v {Sep Eol SeqOn SeqNext SeqStart SeqIncr SeqMax} {
        variable $v
        unset -nocomplain ${v}($h)
    }
    unset Cfg($h) Names($h)
    return
}

# ::fivax::nc::address --
#	Adds or changes address name on handle h. Options: -leader L (default
#	for a new address: its name), -format F (printf %d/%.3f/%s... or an NX
#	&abcdef code; default %s), -force off|always (once = force it once now),
#	-trailer T. Modal memory of an existing address is kept.
proc ::fivax::nc::address {h name args} {
    variable Addr
    variable Flags
    variable Last
    variable Val
    variable Names
    Handle $h
    if {[llength $args] % 2} {
        ::fivax::Fail NC OPTION "wrong # args: should be \"address h name ?-option value ...?\""
    }
    set k $h,$name
    if {[info exists Addr($k)]} {
        lassign $Addr($k) mode kind spec leader trailer
        lassign $Flags($k) base fa sa once
        set fmt [lindex $spec end]
    } else {
        if {$name eq "" || [regexp {[\s,]} $name]} {
            ::fivax::Fail NC ADDRESS "bad address name \"$name\""
        }
        set leader $name
        set trailer ""
        set fmt %s
        lassign {off 0 0 {}} base fa sa once
        set Last($k) ""
        set Val($k) ""
        lappend Names($h) $name
    }
    foreach {opt v} $args {
        switch -- $opt {
            -leader {set leader $v}
            -trailer {set trailer $v}
            -format {set fmt $v}
            -force {
                switch -- $v {
                    off - always {set base $v}
                    once {set once force}
                    default {::fivax::Fail NC VALUE "bad -force \"$v\": must be off, always, or once"}
                }
            }
            default {
                ::fivax::Fail NC OPTION "bad option \"$opt\": must be -leader, -format, -force, or -trailer"
            }
        }
    }
    lassign [ParseFormat $fmt] kind spec
    set Flags($k) [list $base $fa $sa $once]
    set Addr($k) [list [Mode $base $fa $sa $once] $kind $spec $leader $trailer]
    return $name
}

# ::fivax::nc::format --
#	Returns value written in format F (printf or &abcdef), without leader.
#	Never returns -0. A non-numeric value under a numeric format is
#	returned unchanged (an already formatted code).
#	Errors: {FIVAX NC FORMAT} for a bad format, {FIVAX NC VALUE} for Inf/NaN.
proc ::fivax::nc::format {F value} {
    lassign [ParseFormat $F] kind spec
    FormatValue $kind $spec $value
}

# ::fivax::nc::block --
#	Returns the block for words (flat list name value ...), in that order,
#	prefixed with N<seq> when numbering is on; "" when every word was left
#	out (unchanged modal word, suppressed, or empty value). Only words
#	written update the modal memory.
#	The empty name "" stands for literal text, written as it is every time.
#	Errors: {FIVAX NC ADDRESS} for an undefined address name.
proc ::fivax::nc::block {h words} {
    variable Addr
    variable Last
    variable Val
    variable Sep
    variable SeqOn
    if {![info exists Sep($h)]} {Handle $h}
    set out {}
    set upd {}
    set once {}
    foreach {name v} $words {
        set k $h,$name
        if {![info exists Addr($k)]} {
            ::fivax::Fail NC ADDRESS "unknown address \"$name\" on $h"
        }
        lassign $Addr($k) mode kind spec leader trailer
        if {$mode eq "s"} continue
        if {$mode eq "S"} {lappend once $k; continue}
        # Number in, decimal: Tcl reads "017" as octal, so integers and
        # strings go through scan; plain doubles are used as they are.
        if {$kind eq "s"} {
            set t $v
            if {[string index $t 0] eq "-" && [string is double -strict $t] && $t == 0} {
                set t [string range $t 1 end]
            }
        } else {
            set num 1
            if {[string is double -strict $v] && ![string is entier -strict $v]} {
                set x $v
            } elseif {[scan $v %lf%c x junk] != 1} {
                # not a number: an already formatted code, or nothing
                if {$v eq ""} continue
                set num 0
            }
            if {!$num} {
                set t $v
            } elseif {!(abs($x) < Inf)} {
                ::fivax::Fail NC VALUE "address $name: value is not finite: $v"
            } elseif {$kind eq "f"} {
                set t [::format $spec $x]
                if {[string index $t 0] eq "-" && ![string match {*[1-9]*} $t]} {
                    set t [string range $t 1 end]
                }
            } elseif {$kind eq "d"} {
                set t [::format $spec [expr {round($x)}]]
            } else {
                set t [FormatNumber $kind $spec $x]
            }
        }
        if {$mode eq "m"} {
            if {$t eq $Last($k)} continue
        } elseif {$mode eq "W"} {
            lappend once $k
        }
        lappend out $leader$t$trailer
        lappend upd $k $t $v
    }
    foreach {k t v} $upd {
        set Last($k) $t
        set Val($k) $v
    }
    if {[llength $once]} {ConsumeOnce $once}
    if {![llength $out]} {return ""}
    variable Eol
    if {$SeqOn($h)} {
        return [SeqWord $h]$Sep($h)[join $out $Sep($h)]$Eol($h)
    }
    return [join $out $Sep($h)]$Eol($h)
}

# ::fivax::nc::line --
#	Returns text as one block, prefixed with N<seq> when numbering is on.
proc ::fivax::nc::line {h text} {
    variable Sep
    variable Eol
    variable SeqOn
    Handle $h
    if {$SeqOn($h)} {return [SeqWord $h]$Sep($h)$text$Eol($h)}
    return $text$Eol($h)
}

# ::fivax::nc::comment --
#	Returns text as one comment line in the dialect's style, never numbered.
#	Parentheses inside become [ ], line breaks and control characters
#	become spaces, % becomes _; for linuxcnc a leading MSG,/DEBUG,/PRINT,
#	/LOG... word (an active comment there) is defused with a leading _.
proc ::fivax::nc::comment {h text} {
    variable Eol
    Handle $h
    return ([Sanitise $h $text])$Eol($h)
}

# ::fivax::nc::force --
#	Forces the named addresses out (once, always) whatever their modality,
#	or cancels that (off: back to the address's own -force). Suppress-always
#	beats force; between force-once and suppress-once the last call wins.
proc ::fivax::nc::force {h how names} {
    ForceSuppress $h force $how $names
}

# ::fivax::nc::suppress --
#	Keeps the named addresses out of the next block that has them (once),
#	of every block (always), or cancels that (off).
proc ::fivax::nc::suppress {h how names} {
    ForceSuppress $h suppress $how $names
}

# ::fivax::nc::sequence -- Turns numbering on or off; returns the previous state "on"/"off".
proc ::fivax::nc::sequence {h state} {
    variable SeqOn
    variable Cfg
    Handle $h
    switch -- $state {
        on {set new 1}
        off {set new 0}
        default {::fivax::Fail NC VALUE "bad state \"$state\": must be on or off"}
    }
    set old [expr {$SeqOn($h) ? "on" : "off"}]
    set SeqOn($h) $new
    dict set Cfg($h) -sequence $new
    return $old
}

# ::fivax::nc::resetSequence -- Restarts numbering at start, stepping by incr.
proc ::fivax::nc::resetSequence {h start incr} {
    variable SeqNext
    variable SeqStart
    variable SeqIncr
    variable Cfg
    Handle $h
    set start [Int $start 0 start]
    set incr [Int $incr 1 incr]
    set SeqStart($h) $start
    set SeqNext($h) $start
    set SeqIncr($h) $incr
    dict set Cfg($h) -seqStart $start
    dict set Cfg($h) -seqIncr $incr
    return
}

# ::fivax::nc::value -- Returns the last value written for address name ("" if none).
proc ::fivax::nc::value {h name} {
    variable Val
    Handle $h
    if {![info exists Val($h,$name)]} {
        ::fivax::Fail NC ADDRESS "unknown address \"$name\" on $h"
    }
    return $Val($h,$name)
}

# ::fivax::nc::reset --
#	Forgets the modal memory of all addresses, or of the named ones, so the
#	next block writes them again.
proc ::fivax::nc::reset {h {names *}} {
    variable Names
    variable Last
    variable Val
    Handle $h
    if {$names eq "*"} {set names $Names($h)}
    foreach name $names {
        if {![info exists Last($h,$name)]} {
            ::fivax::Fail NC ADDRESS "unknown address \"$name\" on $h"
        }
    }
    foreach name $names {
        set Last($h,$name) ""
        set Val($h,$name) ""
    }
    return
}

# ::fivax::nc::header --
#	Returns the program-start lines: fanuc {% O1000 (COMMENT)}, linuxcnc
#	{% (COMMENT)} (linuxcnc has no program numbers: without a comment the
#	line reads "(PROGRAM 1000)"). Not numbered.
proc ::fivax::nc::header {h programNumber {comment ""}} {
    variable Cfg
    Handle $h
    set n [Int $programNumber 0 programNumber]
    set lines [list %]
    switch -- [dict get $Cfg($h) -dialect] {
        fanuc {
            set o [::format O%04d $n]
            if {$comment ne ""} {append o " ([Sanitise $h $comment])"}
            lappend lines $o
        }
        linuxcnc {
            if {$comment eq ""} {set comment "PROGRAM $n"}
            lappend lines ([Sanitise $h $comment])
        }
    }
    return $lines
}

# ::fivax::nc::footer -- Returns the program-end lines: M30 (numbered when numbering is on), then %.
proc ::fivax::nc::footer {h} {
    list [line $h M30] %
}

# ---------------------------------------------------------------------------
# Private helpers.

# ::fivax::nc::Handle -- Errors {FIVAX NC HANDLE} unless h is a live handle.
proc ::fivax::nc::Handle {h} {
    variable Sep
    if {![info exists Sep($h)]} {
        ::fivax::Fail NC HANDLE "unknown nc handle \"$h\""
    }
}

# ::fivax::nc::Int -- Returns tok as a decimal integer >= min, or errors {FIVAX NC VALUE}.
proc ::fivax::nc::Int {tok min what} {
    if {[scan $tok %d%c n junk] != 1 || $n < $min || ![string is entier -strict $tok]} {
        ::fivax::Fail NC VALUE "bad $what \"$tok\": must be an integer >= $min"
    }
    return $n
}

# ::fivax::nc::CheckOptions --
#	Returns the dict cfg updated with the option/value pairs in opts, each
#	checked. Errors {FIVAX NC OPTION} / {FIVAX NC VALUE}.
proc ::fivax::nc::CheckOptions {cfg opts} {
    variable Options
    if {[llength $opts] % 2} {
        ::fivax::Fail NC OPTION "missing value for option \"[lindex $opts end]\""
    }
    foreach {opt v} $opts {
        switch -- $opt {
            -dialect {
                if {$v ni {fanuc linuxcnc}} {
                    ::fivax::Fail NC VALUE "bad dialect \"$v\": must be fanuc or linuxcnc"
                }
            }
            -units {
                if {$v ni {mm inch}} {
                    ::fivax::Fail NC VALUE "bad units \"$v\": must be mm or inch"
                }
            }
            -decimals - -angleDecimals - -feedDecimals {
                set v [Int $v 0 $opt]
                if {$v > 9} {::fivax::Fail NC VALUE "bad $opt \"$v\": must be 0 to 9"}
            }
            -sequence {
                if {![string is boolean -strict $v]} {
                    ::fivax::Fail NC VALUE "bad -sequence \"$v\": must be a boolean"
                }
                set v [expr {$v ? 1 : 0}]
            }
            -seqStart {set v [Int $v 0 $opt]}
            -seqIncr - -seqMax {set v [Int $v 1 $opt]}
            -rotaryNames {
                if {![string is list $v] || [llength $v] != 2} {
                    ::fivax::Fail NC VALUE "bad -rotaryNames \"$v\": must be two leaders"
                }
            }
            -separator - -eol {}
            default {
                ::fivax::Fail NC OPTION "bad option \"$opt\": must be [join [lrange $Options 0 end-1] {, }], or [lindex $Options end]"
            }
        }
        dict set cfg $opt $v
    }
    return $cfg
}

# ::fivax::nc::Apply -- Copies the separator/eol/sequence options in opts to the handle arrays.
proc ::fivax::nc::Apply {h opts} {
    variable Sep
    variable Eol
    variable SeqOn
    variable SeqNext
    variable SeqStart
    variable SeqIncr
    variable SeqMax
    dict for {opt v} $opts {
        switch -- $opt {
            -separator {set Sep($h) $v}
            -eol {set Eol($h) $v}
            -sequence {set SeqOn($h) $v}
            -seqStart {set SeqStart($h) $v; set SeqNext($h) $v}
            -seqIncr {set SeqIncr($h) $v}
            -seqMax {set SeqMax($h) $v}
        }
    }
}

# ::fivax::nc::SeqWord -- Returns the N word for the current number and advances it (wraps past max).
proc ::fivax::nc::SeqWord {h} {
    variable Addr
    variable SeqNext
    variable SeqIncr
    variable SeqMax
    variable SeqStart
    set n $SeqNext($h)
    set next [expr {$n + $SeqIncr($h)}]
    set SeqNext($h) [expr {$next > $SeqMax($h) ? $SeqStart($h) : $next}]
    lassign $Addr($h,N) mode kind spec leader trailer
    if {$kind eq "d"} {return $leader[::format $spec $n]$trailer}
    return $leader[FormatValue $kind $spec $n]$trailer
}

# ::fivax::nc::Mode -- Returns the one-letter mode for the flags (see the file header).
proc ::fivax::nc::Mode {base fa sa once} {
    if {$sa} {return s}
    if {$once eq "suppress"} {return S}
    if {$once eq "force"} {return W}
    if {$fa || $base eq "always"} {return w}
    return m
}

# ::fivax::nc::ConsumeOnce -- Clears the once requests of the address keys used by a block.
proc ::fivax::nc::ConsumeOnce {keys} {
    variable Addr
    variable Flags
    foreach k $keys {
        lset Flags($k) 3 {}
        lset Addr($k) 0 [Mode {*}$Flags($k)]
    }
}

# ::fivax::nc::ForceSuppress -- Shared body of force and suppress.
proc ::fivax::nc::ForceSuppress {h what how names} {
    variable Addr
    variable Flags
    Handle $h
    if {$how ni {once always off}} {
        ::fivax::Fail NC VALUE "bad mode \"$how\": must be once, always, or off"
    }
    foreach name $names {
        if {![info exists Addr($h,$name)]} {
            ::fivax::Fail NC ADDRESS "unknown address \"$name\" on $h"
        }
    }
    set slot [expr {$what eq "force" ? 1 : 2}]
    foreach name $names {
        set k $h,$name
        lassign $Flags($k) base fa sa once
        switch -- $how {
            once {set once $what}
            always {lset Flags($k) $slot 1; set once [expr {$once eq $what ? "" : $once}]}
            off {lset Flags($k) $slot 0; set once [expr {$once eq $what ? "" : $once}]}
        }
        lset Flags($k) 3 $once
        lset Addr($k) 0 [Mode {*}$Flags($k)]
    }
    return
}

# ::fivax::nc::ParseFormat --
#	Returns {kind spec} for format string F (cached).
#	Errors {FIVAX NC FORMAT} for anything but one printf conversion or &abcdef.
proc ::fivax::nc::ParseFormat {F} {
    variable FmtCache
    if {[info exists FmtCache($F)]} {return $FmtCache($F)}
    if {[regexp {^&([-+_])([0_])([0-9])([._])([0-9])([0_])$} $F -> a b c d e f]} {
        set r [list a [list [expr {$a eq "+"}] [expr {$b eq "0"}] $c \
            [expr {$d eq "."}] $e [expr {$f eq "0"}] $F]]
        # Codes that printf writes the same take the fast printf path.
        set sign [expr {$a eq "+" ? "+" : ""}]
        if {$b ne "0" && $d eq "." && $f eq "0" && $e > 0} {
            set r [list [expr {$a eq "+" ? "F" : "f"}] "%$sign.${e}f"]
        } elseif {$b ne "0" && $d ne "." && $e == 0} {
            set r [list d "%${sign}d"]
        }
    } elseif {[regexp {^[^%]*%([-+ 0#]*)([0-9]*)(?:\.([0-9]+))?([diouxXfeEgGs])[^%]*$} \
            $F -> flags width prec conv]} {
        switch -- $conv {
            s {set kind s}
            d - i - o - u - x - X {set kind d}
            default {set kind [expr {[string first + $flags] >= 0 ? "F" : "f"}]}
        }
        set r [list $kind $F]
    } else {
        ::fivax::Fail NC FORMAT "bad format \"$F\": must be one printf conversion or an &abcdef code"
    }
    set FmtCache($F) $r
    return $r
}

# ::fivax::nc::FormatValue -- Returns value in the parsed format {kind spec} (slow path of block).
proc ::fivax::nc::FormatValue {kind spec v} {
    if {$kind eq "s"} {
        if {[string index $v 0] eq "-" && [string is double -strict $v] && $v == 0} {
            return [string range $v 1 end]
        }
        return $v
    }
    if {([string is double -strict $v] && ![string is entier -strict $v])
        || [scan $v %lf%c x junk] == 1} {
        if {![info exists x]} {set x $v}
        if {!(abs($x) < Inf)} {::fivax::Fail NC VALUE "value is not finite: $v"}
        if {$kind eq "d"} {return [::format $spec [expr {round($x)}]]}
        return [FormatNumber $kind $spec $x]
    }
    return $v
}

# ::fivax::nc::FormatNumber -- Returns the finite double x in format kind f, F or a; never -0.
proc ::fivax::nc::FormatNumber {kind spec x} {
    if {$kind eq "a"} {return [Amp $spec $x]}
    set t [::format $spec $x]
    if {[string index $t 0] eq "-" && ![string match {*[1-9]*} $t]} {
        set t [expr {$kind eq "F" ? "+" : ""}][string range $t 1 end]
    }
    return $t
}

# ::fivax::nc::Amp --
#	Returns x in an NX &abcdef code, spec {plus zeroFill intDigits point
#	fracDigits pad code}. Rounds to fracDigits. Without zero fill the
#	integer part loses its leading zeros but keeps one digit (0.5, not .5);
#	without pad the fraction loses trailing zeros but keeps one digit after
#	a written point (12.0), as Post Builder previews and the NX help's
#	"0.0" describe. Without a point the fraction is always padded, so the
#	implied decimal stays right (0.5 in &__3_3_ is 500). Integer digits
#	are never cut; halves round away from zero.
proc ::fivax::nc::Amp {spec x} {
    lassign $spec plus fill nint point nfrac pad
    if {$nfrac > 0} {
        set t [::format %.*f $nfrac [expr {abs($x)}]]
    } else {
        # round half away from zero, as the printf integer formats here do
        set t [::format %.0f [expr {round(abs($x))}]]
    }
    set neg [expr {$x < 0 && [string match {*[1-9]*} $t]}]
    if {$nfrac > 0} {
        lassign [split $t .] ip fp
        if {$point && !$pad} {
            set fp [string trimright $fp 0]
            if {$fp eq ""} {set fp 0}
        }
    } else {
        set ip $t
        set fp ""
    }
    set ip [string trimleft $ip 0]
    if {$fill} {
        set n [string length $ip]
        if {$n < $nint} {set ip [string repeat 0 [expr {$nint - $n}]]$ip}
    } elseif {$ip eq "" && $point} {
        set ip 0
    }
    # (not expr: it would read "0012" back as an octal number)
    if {$point} {
        set t $ip.$fp
    } else {
        set t $ip$fp
        if {!$fill} {set t [string trimleft $t 0]}
        if {$t eq ""} {set t 0}
    }
    if {$neg} {return -$t}
    if {$plus} {return +$t}
    return $t
}

# ::fivax::nc::Sanitise -- Returns text made safe for the inside of a ( ) comment.
proc ::fivax::nc::Sanitise {h text} {
    variable Cfg
    set text [string map {( [ ) ] % _ \r " " \n " " \t " "} $text]
    regsub -all {[\x00-\x1f\x7f]} $text " " text
    if {[dict get $Cfg($h) -dialect] eq "linuxcnc"
        && [regexp -nocase {^\s*(MSG|DEBUG|PRINT|LOG|LOGOPEN|LOGAPPEND|LOGCLOSE|PROBEOPEN|PROBECLOSE|ABORT)\s*,} $text]} {
        set text _[string trimleft $text]
    }
    return $text
}
