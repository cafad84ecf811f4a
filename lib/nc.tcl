# nc.tcl --
#	The block engine under the output layer: addresses (leader, format,
#	trailer), modal suppression of unchanged words, NX-style force and
#	suppress, and sequence numbers, as NX's MOM writes blocks from a .def.
#	It knows no dialect and no address but N (the sequence number): the
#	output layer (lib/output.tcl) and the .def define the others. Pure:
#	every method returns text; nothing here writes a file.
#
#	A Writer keeps per address one list {mode kind spec leader trailer lo
#	hi limits format base forceAlways suppressAlways once}:
#	    mode  m = modal (written when its text changes), w = always written,
#	          s = suppressed, W = forced once, S = suppressed once;
#	    kind  f = printf real, F = printf real with a + flag, d = printf
#	          integer (value rounded), s = string, a = NX &abcdef code,
#	          t = literal text (the nameless address);
#	    spec  the printf string, or the parsed &abcdef fields;
#	    lo hi the bounds of limits as numbers, the largest finite
#	          doubles where there is none, so one test (x >= lo && x <=
#	          hi) passes every finite value within them, and no Inf or NaN;
#	    limits {} or {min minAction max maxAction} (NX's MIN/MAX with
#	          abort, warning or truncate; "" for no bound);
#	    format the format string as given (printf or &abcdef);
#	    base forceAlways suppressAlways once: the flags (base off or
#	          always, the -force of the address; forceAlways and
#	          suppressAlways 0 or 1; once "", force or suppress).
#	The mode is derived from the flags by Mode, so the hot path reads one
#	element.
#
#	Note: this namespace defines a command called "format"; every core
#	format call in here is written ::format.

namespace eval ::fivax::nc {
    namespace export create format
    namespace ensemble create -prefixes 0

    # FmtCache(F): {kind spec} for every format string parsed so far.
    variable FmtCache
    array set FmtCache {}
    # Plain: the Writer of format, with PlainAddress(F) its always-written
    # address without leader in format F.
    variable Plain
    variable PlainAddress
    array set PlainAddress {}

    variable Options {
        {-sequence bool 1 "" "write N sequence numbers"}
        {-seq-start {int min 0} 10 N "first sequence number"}
        {-seq-incr {int min 1} 10 N "sequence number step"}
        {-seq-max {int min 1} 99999 N "largest sequence number: numbering stops after it, with a warning"}
        {-separator text " " TEXT "text between words"}
        {-eol any "" TEXT "text at the end of every block"}
        {-warn any "" CMD "command prefix called with the message of a MIN/MAX Warning, or when numbering stops"}
        {-overflow any "" CMD "command prefix called with the next sequence number when it passes -seq-max: numbering goes on when it restarts the sequence"}
    }
}

# ::fivax::nc::create --
#	Returns a new Writer object with the sequence-number address N (format
#	%d, always written) and the options of the Options table. Destroy it
#	with "$writer destroy".
proc ::fivax::nc::create {args} {
    variable Options
    Writer new [::fivax::opts::parse $Options $args "nc create"]
}

oo::class create ::fivax::nc::Writer {
    # Addr($name) (see the file header), Mem($name) (the modal memory:
    # {text value} of the last word written, {text value 1} when the
    # value was within the limits and the format has not changed since:
    # the same value writes the same text); the rest in S (few declared
    # variables: TclOO resolves every local of a method against each
    # declared name on every call): S(cfg) the option dict, S(names) the
    # address names in definition order; S(sep), S(eol), S(seqOn),
    # S(seqNext), S(seqIncr), S(seqMax): the options and the numbering
    # state, out of S(cfg) for the hot path.
    variable S Addr Mem

    constructor {opts} {
        set S(cfg) $opts
        set S(names) {}
        array set Addr {}
        my Apply $S(cfg)
        # The nameless address: literal text (template "strings"), always written.
        set Addr() {w t {} {} {} -1.7976931348623157e308 1.7976931348623157e308 {} {} always 0 0 {}}
        set Mem() {{} {}}
        my address N -leader N -format %d -force always
    }

    # Changes options after creation; with none, returns the option dict.
    # Numbering restarts at -seq-start when it is given.
    method configure {args} {
        if {![llength $args]} {return $S(cfg)}
        set table $::fivax::nc::Options
        if {[llength $args] % 2} {
            ::fivax::opts::check $table [lindex $args end] "" "nc configure"
            ::fivax::Fail OPTION MISSING "nc configure: option [lindex $args end] needs a value"
        }
        set given {}
        foreach {opt value} $args {
            dict set given $opt [::fivax::opts::check $table $opt $value "nc configure"]
        }
        set S(cfg) [dict merge $S(cfg) $given]
        my Apply $given
        return $S(cfg)
    }

    # Adds or changes address name. Options: -leader L (default for a new
    # address: its name), -format F (printf %d/%.3f/%s... or an NX &abcdef
    # code; default %s), -force off|always|once (once: force it once now),
    # -trailer T, -min and -max {value action} (NX's MIN/MAX: a value
    # beyond is aborted with {FIVAX NC RANGE}, written with a warning, or
    # truncated to the bound; action "" is truncate; {} removes the bound).
    # Modal memory of an existing address is kept.
    method address {name args} {
        if {[llength $args] % 2} {
            ::fivax::Fail NC OPTION "wrong # args: should be \"address name ?-option value ...?\""
        }
        if {[info exists Addr($name)]} {
            lassign $Addr($name) mode kind spec leader trailer - - limits fmt base fa sa once
            # (its format or limits may change: the last value is no longer known to format as then)
            set Mem($name) [lrange $Mem($name) 0 1]
        } else {
            if {$name eq "" || [regexp {[\s,]} $name]} {
                ::fivax::Fail NC ADDRESS "bad address name \"$name\""
            }
            set leader $name
            set trailer ""
            set limits {}
            set fmt %s
            lassign {off 0 0 {}} base fa sa once
            set Mem($name) {{} {}}
            lappend S(names) $name
        }
        foreach {opt v} $args {
            switch -- $opt {
                -leader {set leader $v}
                -trailer {set trailer $v}
                -format {set fmt $v}
                -min - -max {set limits [::fivax::nc::Limit $limits $opt $v]}
                -force {
                    switch -- $v {
                        off - always {set base $v}
                        once {set once force}
                        default {::fivax::Fail NC VALUE "bad -force \"$v\": must be off, always, or once"}
                    }
                }
                default {
                    ::fivax::Fail NC OPTION "bad option \"$opt\": must be -leader, -format, -force, -trailer, -min, or -max"
                }
            }
        }
        lassign [::fivax::nc::ParseFormat $fmt] kind spec
        lassign $limits lo - hi
        if {$lo eq ""} {set lo -1.7976931348623157e308}
        if {$hi eq ""} {set hi 1.7976931348623157e308}
        set Addr($name) [list [::fivax::nc::Mode $base $fa $sa $once] $kind $spec $leader \
            $trailer $lo $hi $limits $fmt $base $fa $sa $once]
        return $name
    }

    # Returns 1 when address name is defined.
    method has {name} {
        info exists Addr($name)
    }

    # Returns the number of decimals address name writes (0 for integer
    # and string formats).
    method decimals {name} {
        if {![info exists Addr($name)]} {
            ::fivax::Fail NC ADDRESS "unknown address \"$name\""
        }
        lassign $Addr($name) mode kind spec
        switch -- $kind {
            a {return [lindex $spec 4]}
            f - F {
                if {[regexp {%[-+ 0#]*[0-9]*\.([0-9]+)[fFeEgG]} $spec -> d]} {
                    scan $d %d d
                    return $d
                }
                return 6
            }
        }
        return 0
    }

    # Returns the block for words (flat list name value ...), in that
    # order, prefixed with N<seq> when numbering is on and numbered is 1
    # (numbered 0: the words of a line built around them, never numbered);
    # "" when every word was left out (unchanged modal word, suppressed,
    # or empty value). around {before after}: text around the words,
    # within the number (as "L <words> R0 F.."), when there are
    # any. Only words written update the modal memory, after the last
    # word: a block that fails changes none of it. The empty name ""
    # stands for literal text, written as it is every time.
    # Numbering: N<seq> first while numbering is on and the number within
    # -seq-max (then the number advances); past -seq-max the -overflow
    # command may restart it, else numbering stops with one warning:
    # never a number past -seq-max.
    # Errors: {FIVAX NC ADDRESS} for an undefined address name.
    method block {words {numbered 1} {around {}}} {
        set out ""
        set sep ""
        set upd {}
        set once {}
        # (an undefined name is found by its failed read: no test per word)
        try {
            foreach {name v} $words {
                lassign $Addr($name) mode kind spec leader trailer lo hi
                switch -- $mode {
                    s continue
                    S {lappend once $name; continue}
                    m {
                        # the value last written, within the limits, formats
                        # as then: a modal word left out unformatted
                        lassign $Mem($name) - last within
                        if {$within ne "" && $last eq $v} continue
                    }
                }
                set within 1
                # Number in, decimal: Tcl reads "017" as octal, so integers and
                # strings go through scan; plain doubles are used as they are
                # (x is v itself, or what scan read: a second conversion, the
                # junk after the number, makes the count 2).
                if {$kind eq "s"} {
                    set t $v
                    if {[string match -* $t] && [string is double -strict $t] && $t == 0} {
                        set t [string range $t 1 end]
                    }
                } elseif {$kind eq "t"} {
                    set t $v
                } elseif {[string is double -strict [set x $v]] && ![string is entier -strict $v]
                        || [scan $v %lf%c x x] == 1} {
                    if {!($x >= $lo && $x <= $hi)} {
                        # beyond a MIN/MAX, or not finite
                        set within 0
                        set x [my Bound $name $x]
                        if {!($x > -Inf && $x < Inf)} {
                            ::fivax::Fail NC VALUE "address $name: value is not finite: $v"
                        }
                    }
                    switch -- $kind {
                        d {set t [::format $spec [expr {round($x)}]]}
                        a {set t [::fivax::nc::Amp $spec $x]}
                        default {
                            # printf reals, never -0 (the text of a number
                            # beyond -1..1 has a digit 1-9: no text test)
                            set t [::format $spec $x]
                            if {$x > -1 && $x < 1 && [string match -* $t]
                                    && ![string match {*[1-9]*} $t]} {
                                set t [expr {$kind eq "F" ? "+" : ""}][string range $t 1 end]
                            }
                        }
                    }
                } elseif {$v eq ""} {
                    continue
                } else {
                    # not a number: an already formatted code
                    set t $v
                }
                if {$mode eq "m"} {
                    if {$t eq [lindex $Mem($name) 0]} continue
                } elseif {$mode eq "W"} {
                    lappend once $name
                }
                # (single-value lappends and append are bytecode; join is not)
                append out $sep$leader$t$trailer
                set sep $S(sep)
                lappend upd $name
                lappend upd [expr {$within ? [list $t $v 1] : [list $t $v]}]
            }
        } trap {TCL READ VARNAME} {msg opts} {
            if {[info exists Addr($name)]} {return -options $opts $msg}
            ::fivax::Fail NC ADDRESS "unknown address \"$name\""
        }
        array set Mem $upd
        if {[llength $once]} {my ConsumeOnce $once}
        if {![llength $upd]} {return ""}
        if {[llength $around]} {set out [lindex $around 0]$out[lindex $around 1]}
        if {!$numbered || !$S(seqOn)} {return $out$S(eol)}
        if {$S(seqNext) > $S(seqMax) && ![my Overflow]} {
            return $out$S(eol)
        }
        lassign $Addr(N) mode kind spec leader trailer
        if {$spec eq "%d"} {
            # (the number is a decimal integer within 64 bits: as %d writes it)
            set t $S(seqNext)
        } elseif {$kind eq "d"} {
            set t [::format $spec $S(seqNext)]
        } elseif {$kind eq "a"} {
            set t [::fivax::nc::Amp $spec $S(seqNext)]
        } else {
            set t [::fivax::nc::format [lindex $Addr(N) 8] $S(seqNext)]
        }
        incr S(seqNext) $S(seqIncr)
        return $leader$t$trailer$S(sep)$out$S(eol)
    }

    # Returns text as one block, prefixed with N<seq> when numbering is on.
    method line {text} {
        my block [list "" $text]
    }

    # Forces the named addresses out (once, always) whatever their
    # modality, or cancels that (off: back to the address's own -force).
    # Suppress-always beats force; between force-once and suppress-once the
    # last call wins.
    method force {how addresses} {
        my ForceSuppress force $how $addresses
    }

    # Keeps the named addresses out of the next block that has them
    # (once), of every block (always), or cancels that (off).
    method suppress {how addresses} {
        my ForceSuppress suppress $how $addresses
    }

    # Turns numbering on or off; returns the previous state "on"/"off".
    method sequence {state} {
        switch -- $state {
            on {set new 1}
            off {set new 0}
            default {::fivax::Fail NC VALUE "bad state \"$state\": must be on or off"}
        }
        set old [expr {$S(seqOn) ? "on" : "off"}]
        set S(seqOn) $new
        dict set S(cfg) -sequence $new
        return $old
    }

    # Restarts numbering at start, stepping by incr.
    method resetSequence {start incr} {
        my configure -seq-start $start -seq-incr $incr
        return
    }

    # Returns number x within address name's MIN/MAX as a block would
    # write it (truncated, or after a warning as it is; {FIVAX NC RANGE}
    # for abort): for text that goes out without a block.
    method limit {name x} {
        if {![info exists Addr($name)]} {
            ::fivax::Fail NC ADDRESS "unknown address \"$name\""
        }
        lassign $Addr($name) - - - - - lo hi
        if {!($x >= $lo && $x <= $hi)} {return [my Bound $name $x]}
        return $x
    }

    # Returns the last value written for address name ("" if none).
    method value {name} {
        if {![info exists Mem($name)]} {
            ::fivax::Fail NC ADDRESS "unknown address \"$name\""
        }
        lindex $Mem($name) 1
    }

    # Forgets the modal memory of all addresses, or of the named ones, so
    # the next block writes them again.
    method reset {{which *}} {
        if {$which eq "*"} {set which $S(names)}
        foreach name $which {
            if {![info exists Mem($name)]} {
                ::fivax::Fail NC ADDRESS "unknown address \"$name\""
            }
        }
        foreach name $which {
            set Mem($name) {{} {}}
        }
        return
    }

    # Returns x as address name's limits {min minAction max maxAction}
    # say: as it is within them (or when it is NaN), else truncated to the
    # bound, or as it is after a warning, or an error {FIVAX NC RANGE} for
    # abort. (The callers call it for x outside the address's lo..hi.)
    method Bound {name x} {
        lassign $Addr($name) - - - - - - - limits
        lassign $limits min minAct max maxAct
        if {$min ne "" && $x < $min} {
            set bound $min
            set act $minAct
        } elseif {$max ne "" && $x > $max} {
            set bound $max
            set act $maxAct
        } else {
            return $x
        }
        switch -- $act {
            abort {
                ::fivax::Fail NC RANGE "address $name: $x is beyond its limit $bound"
            }
            warning {
                set warn [dict get $S(cfg) -warn]
                if {[llength $warn]} {{*}$warn "address $name: $x is beyond its limit $bound"}
                return $x
            }
        }
        return $bound
    }

    # Copies the separator/eol/sequence options in opts to the state.
    method Apply {opts} {
        dict for {opt v} $opts {
            switch -- $opt {
                -separator {set S(sep) $v}
                -eol {set S(eol) $v}
                -sequence {set S(seqOn) $v}
                -seq-start {set S(seqNext) $v}
                -seq-incr {set S(seqIncr) $v}
                -seq-max {set S(seqMax) $v}
            }
        }
    }

    # Overflow --
    #	The next number passed -seq-max: returns 1 when the -overflow
    #	command restarted the numbering within it, else stops numbering
    #	(with a warning) and returns 0.
    method Overflow {} {
        set cmd [dict get $S(cfg) -overflow]
        if {[llength $cmd]} {{*}$cmd $S(seqNext)}
        if {$S(seqOn) && $S(seqNext) <= $S(seqMax)} {return 1}
        my StopNumbering
        return 0
    }

    # Stops numbering past -seq-max, with a warning.
    method StopNumbering {} {
        set S(seqOn) 0
        set warn [dict get $S(cfg) -warn]
        if {[llength $warn]} {
            {*}$warn "sequence numbers past [dict get $S(cfg) -seq-max] (the largest the\
                .def's SEQUENCE allows): the rest of the program is not numbered"
        }
    }

    # Clears the once requests of the addresses (names) used by a block.
    method ConsumeOnce {names} {
        foreach name $names {
            lset Addr($name) 12 {}
            lset Addr($name) 0 [::fivax::nc::Mode {*}[lrange $Addr($name) 9 12]]
        }
    }

    # Shared body of force and suppress.
    method ForceSuppress {what how addresses} {
        if {$how ni {once always off}} {
            ::fivax::Fail NC VALUE "bad mode \"$how\": must be once, always, or off"
        }
        foreach name $addresses {
            if {![info exists Addr($name)]} {
                ::fivax::Fail NC ADDRESS "unknown address \"$name\""
            }
        }
        set slot [expr {$what eq "force" ? 10 : 11}]
        foreach name $addresses {
            set once [lindex $Addr($name) 12]
            switch -- $how {
                once {set once $what}
                always {lset Addr($name) $slot 1; set once [expr {$once eq $what ? "" : $once}]}
                off {lset Addr($name) $slot 0; set once [expr {$once eq $what ? "" : $once}]}
            }
            lset Addr($name) 12 $once
            lset Addr($name) 0 [::fivax::nc::Mode {*}[lrange $Addr($name) 9 12]]
        }
        return
    }
}

# ::fivax::nc::format --
#	Returns value written in format F (printf or &abcdef), without leader:
#	the word of a Writer's always-written address (see block). Never
#	returns -0. A non-numeric value under a numeric format is returned
#	unchanged (an already formatted code).
#	Errors: {FIVAX NC FORMAT} for a bad format, {FIVAX NC VALUE} for Inf/NaN.
proc ::fivax::nc::format {F value} {
    variable Plain
    variable PlainAddress
    if {![info exists PlainAddress($F)]} {
        ParseFormat $F
        if {![info exists Plain]} {set Plain [create -sequence 0]}
        set PlainAddress($F) [$Plain address f[array size PlainAddress] -leader "" \
            -force always -format $F]
    }
    try {
        $Plain block [list $PlainAddress($F) $value] 0
    } trap {FIVAX NC VALUE} {} {
        ::fivax::Fail NC VALUE "value is not finite: $value"
    }
}

# ::fivax::nc::Limit --
#	Returns the limits list {min minAction max maxAction} with the -min or
#	-max option set to v: {value action} ("" action: truncate) or {} for
#	none. Errors {FIVAX NC VALUE} for a bad value or action.
proc ::fivax::nc::Limit {limits opt v} {
    if {![llength $limits]} {set limits {{} {} {} {}}}
    set i [expr {$opt eq "-min" ? 0 : 2}]
    if {![llength $v]} {
        lset limits $i {}
        lset limits $i+1 {}
    } else {
        lassign $v value action
        set x [::fivax::num::parse $value]
        set action [string tolower $action]
        if {$action eq ""} {set action truncate}
        if {$x eq "" || $action ni {abort warning truncate}} {
            ::fivax::Fail NC VALUE "bad $opt \"$v\": must be {number ?abort|warning|truncate?}"
        }
        lset limits $i $x
        lset limits $i+1 $action
    }
    if {[lindex $limits 0] eq "" && [lindex $limits 2] eq ""} {return {}}
    return $limits
}

# ::fivax::nc::Mode -- Returns the one-letter mode for the flags (see the file header).
proc ::fivax::nc::Mode {base fa sa once} {
    if {$sa} {return s}
    if {$once eq "suppress"} {return S}
    if {$once eq "force"} {return W}
    if {$fa || $base eq "always"} {return w}
    return m
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
