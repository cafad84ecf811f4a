# def.tcl --
#	Reader for NX Post Builder definition (.def) files: MACHINE, INCLUDE
#	and the FORMATTING block (WORD_SEPARATOR, END_OF_LINE, SEQUENCE,
#	FORMAT, ADDRESS, BLOCK_TEMPLATE) become a plain dict, and configure
#	copies the ADDRESSes onto an nc Writer.
#
#	The .def text is data: nothing here evals, substs or exprs it. Bracketed
#	Tcl (template word expressions, LEADER [$mom_sys_leader(X)]) is kept as
#	text for the runtime, which evaluates it in the post's interpreter.
#
#	Result of parse/load:
#	    machine NAME  includes {PATH ...}  word_separator " "  end_of_line ""
#	    sequence {template T start N incr N freq N max N}   (empty if none)
#	    formats {NAME CODE ...}
#	    addresses {NAME {format FMTNAME force off|always|once
#	        leader TEXT leader_expr EXPR trailer TEXT trailer_expr EXPR
#	        max NUM max_action ACT min NUM min_action ACT
#	        zero_format FMTNAME incremental on|off} ...}
#	    blocks {NAME {WORD ...} ...}, each WORD either
#	        {address A expr E opt 0|1 nows 0|1 ?leader L? ?trailer T?}
#	        or {literal TEXT ?nows 1?}
#	A missing LEADER means the address name; leader_expr is the text inside
#	[...] when the LEADER is bracketed (then leader is ""). Unset numbers
#	and names are "".

namespace eval ::fivax::def {
    namespace export parse load configure textAddress
    namespace ensemble create -prefixes 0
}

# ::fivax::def::load --
#	Returns the dict of the .def file at path (see parse).
#	Errors: {FIVAX DEF FILE} when the file cannot be read, else as parse.
proc ::fivax::def::load {path} {
    try {
        set ch [open $path r]
    } trap {POSIX} {msg} {
        ::fivax::Fail DEF FILE "cannot read $path: $msg"
    }
    try {
        fconfigure $ch -encoding utf-8
        set text [read $ch]
    } finally {
        close $ch
    }
    parse $text $path
}

# ::fivax::def::parse --
#	Returns the dict for .def text (layout in the file header); name is
#	used in error messages. Errors: {FIVAX DEF SYNTAX} "name:line: what".
proc ::fivax::def::parse {text {name <def>}} {
    set parser [Parser new $name]
    try {
        $parser parse $text
    } finally {
        $parser destroy
    }
}

# ::fivax::def::configure --
#	Defines every ADDRESS of defDict on the nc Writer writer (format resolved through
#	FORMATs; MIN/MAX with their actions; plain LEADER/TRAILER strings copied,
#	bracketed ones left for the runtime), and copies the word separator, end of line and SEQUENCE
#	numbers. Returns the address names configured.
#	Errors: {FIVAX DEF FORMAT} when an address names an unknown FORMAT.
proc ::fivax::def::configure {writer defDict} {
    set formats [DictOr $defDict formats {}]
    set opts {}
    if {[dict exists $defDict word_separator]} {
        lappend opts -separator [dict get $defDict word_separator]
    }
    if {[dict exists $defDict end_of_line]} {
        lappend opts -eol [dict get $defDict end_of_line]
    }
    set seq [DictOr $defDict sequence {}]
    if {[llength $seq]} {
        lappend opts -seq-start [dict get $seq start] -seq-incr [dict get $seq incr] \
            -seq-max [dict get $seq max]
    }
    if {[llength $opts]} {$writer configure {*}$opts}
    set names {}
    dict for {addr a} [DictOr $defDict addresses {}] {
        set fname [DictOr $a format ""]
        if {![dict exists $formats $fname]} {
            ::fivax::Fail DEF FORMAT "address $addr: unknown FORMAT \"$fname\""
        }
        set args [list -format [dict get $formats $fname]]
        set force [string tolower [DictOr $a force off]]
        lappend args -force [expr {$force eq "always" ? "always" : "off"}]
        foreach key {min max} {
            set v [DictOr $a $key ""]
            lappend args -$key [expr {$v eq "" ? {} : [list $v [DictOr $a ${key}_action ""]]}]
        }
        set isNew [expr {![$writer has $addr]}]
        foreach {key opt} {leader -leader trailer -trailer} {
            if {[DictOr $a ${key}_expr ""] eq ""} {
                lappend args $opt [DictOr $a $key ""]
            } elseif {$isNew} {
                # the runtime evaluates the expression and sets the text
                lappend args $opt ""
            }
        }
        $writer address $addr {*}$args
        if {$force eq "once"} {$writer force once [list $addr]}
        lappend names $addr
    }
    return $names
}

# ::fivax::def::textAddress --
#	Returns 1 when address addr of defDict writes text: its FORMAT is a
#	string format (%s, as Post Builder's String), whose template words
#	(Text[%]) are text with the post's variables in it, not expressions.
proc ::fivax::def::textAddress {defDict addr} {
    set code [dict get $defDict formats [dict get $defDict addresses $addr format]]
    regexp {^%-?[0-9]*s$} $code
}

# ---------------------------------------------------------------------------
# Private helpers.

# ::fivax::def::DictOr -- Returns dict value d(key), or dflt when it is missing.
proc ::fivax::def::DictOr {d key dflt} {
    if {[dict exists $d $key]} {return [dict get $d $key]}
    return $dflt
}


oo::class create ::fivax::def::Parser {
    # Source: the name used in messages; Tokens: the token list, each
    # {type text line} with type one of LB RB STR WORD; Cursor: the next
    # token's index.
    variable Source Tokens Cursor

    constructor {name} {
        set Source $name
        set Tokens {}
        set Cursor 0
    }

    # Returns the def dict of text.
    method parse {text} {
        set Tokens [my Lex $text]
        set Cursor 0
        my ParseTop
    }

    # Error -- Raises {FIVAX DEF SYNTAX} "name:line: msg".
    method Error {line msg} {
        ::fivax::Fail DEF SYNTAX "$Source:$line: $msg"
    }

    # Lex --
    #	Returns the token list of text: braces, "strings" (unescaped), words
    #	(bare text, [bracketed] parts kept whole, across lines if need be).
    #	A # at the start of a token comments out the rest of the line.
    method Lex {text} {
        set toks {}
        set line 1
        set i 0
        set n [string length $text]
        while {$i < $n} {
            if {[regexp -start $i -indices {\A[ \t\r\f\v]+} $text m]} {
                set i [expr {[lindex $m 1] + 1}]
                continue
            }
            set c [string index $text $i]
            switch -- $c {
                "\n" {incr line; incr i; continue}
                " " - "\t" - "\r" - "\f" - "\v" {incr i; continue}
                "#" {
                    set e [string first "\n" $text $i]
                    set i [expr {$e < 0 ? $n : $e}]
                    continue
                }
                "\{" {lappend toks [list LB "\{" $line]; incr i; continue}
                "\}" {lappend toks [list RB "\}" $line]; incr i; continue}
                "\"" {
                    lassign [my QuotedEnd $text $i $line] e
                    lappend toks [list STR [my Unescape [string range $text [expr {$i + 1}] [expr {$e - 1}]]] $line]
                    set i [expr {$e + 1}]
                    continue
                }
            }
            # a word: up to white space or a brace outside [ ]
            set start $i
            set first $line
            while {$i < $n} {
                if {[regexp -start $i -indices {\A[^\s\{\}\[\]"\\]+} $text m]} {
                    set i [expr {[lindex $m 1] + 1}]
                    if {$i >= $n} break
                }
                set c [string index $text $i]
                if {[string is space $c] || $c eq "\{" || $c eq "\}"} break
                switch -- $c {
                    "\[" {
                        set e [my BracketEnd $text $i $line]
                        incr line [my CountLines $text $i $e]
                        set i [expr {$e + 1}]
                    }
                    "\"" {
                        lassign [my QuotedEnd $text $i $line] e
                        set i [expr {$e + 1}]
                    }
                    "\\" {incr i 2}
                    default {incr i}
                }
            }
            lappend toks [list WORD [string range $text $start [expr {$i - 1}]] $first]
        }
        return $toks
    }

    # CountLines -- Returns the number of newlines in text between indices a and b.
    method CountLines {text a b} {
        regexp -all {\n} [string range $text $a $b]
    }

    # QuotedEnd --
    #	Returns {index} of the " closing the string opened at index i (same line).
    method QuotedEnd {text i line} {
        set n [string length $text]
        for {set j [expr {$i + 1}]} {$j < $n} {incr j} {
            set c [string index $text $j]
            if {$c eq "\\"} {incr j; continue}
            if {$c eq "\""} {return [list $j]}
            if {$c eq "\n"} break
        }
        my Error $line "unterminated string"
    }

    # BracketEnd --
    #	Returns the index of the ] matching the [ at index i; nested [ ],
    #	{ } groups, "strings" and backslash escapes inside are skipped whole.
    method BracketEnd {text i line} {
        set n [string length $text]
        set depth 0
        set braces 0
        for {set j $i} {$j < $n} {incr j} {
            set c [string index $text $j]
            switch -- $c {
                "\\" {incr j}
                "\{" {incr braces}
                "\}" {if {$braces > 0} {incr braces -1}}
                "\"" {
                    if {$braces == 0} {
                        lassign [my QuotedEnd $text $j $line] j
                    }
                }
                "\[" {if {$braces == 0} {incr depth}}
                "\]" {
                    if {$braces == 0 && [incr depth -1] == 0} {return $j}
                }
            }
        }
        my Error $line "missing \] for \[ opened here"
    }

    # Unescape --
    #	Returns the text of a "string" body: \ooo octal, \\, \" and \n, \t, \r
    #	are replaced; any other backslash stays as written.
    method Unescape {s} {
        if {[string first "\\" $s] < 0} {return $s}
        set out ""
        set n [string length $s]
        for {set i 0} {$i < $n} {incr i} {
            set c [string index $s $i]
            if {$c ne "\\" || $i == $n - 1} {append out $c; continue}
            set d [string index $s [incr i]]
            if {[regexp {^[0-7]{1,3}} [string range $s $i [expr {$i + 2}]] oct]} {
                scan $oct %o code
                append out [::format %c $code]
                incr i [expr {[string length $oct] - 1}]
                continue
            }
            switch -- $d {
                n {append out "\n"}
                t {append out "\t"}
                r {append out "\r"}
                "\\" - "\"" {append out $d}
                default {append out "\\$d"}
            }
        }
        return $out
    }

    # Next -- Returns the next token ({} at the end) and moves past it.
    method Next {} {
        set t [lindex $Tokens $Cursor]
        incr Cursor
        return $t
    }

    # Peek -- Returns the next token ({} at the end) without moving.
    method Peek {} {
        lindex $Tokens $Cursor
    }

    # LastLine -- Returns the line of the last token (for end-of-text messages).
    method LastLine {} {
        set t [lindex $Tokens end]
        if {$t eq ""} {return 1}
        lindex $t 2
    }

    # Expect --
    #	Returns the text of the next token, which must have one of the types;
    #	what describes it for the message.
    method Expect {types what after} {
        set t [my Next]
        if {$t eq ""} {my Error [my LastLine] "missing $what after $after"}
        lassign $t type text line
        if {$type ni $types} {my Error $line "expected $what after $after, got \"$text\""}
        return $text
    }

    # SameLine --
    #	Returns the texts of the WORD/STR tokens that follow on line (moves past them).
    method SameLine {line} {
        set out {}
        while {[set t [my Peek]] ne ""} {
            lassign $t type text l
            if {$l != $line || $type ni {WORD STR}} break
            lappend out $text
            my Next
        }
        return $out
    }

    # ParseTop -- Parses the whole token list; returns the def dict.
    method ParseTop {} {
        set d [dict create machine "" includes {} word_separator " " end_of_line "" \
            sequence {} formats {} addresses {} blocks {}]
        set lines [dict create addresses {} blocks {}]
        while {[set t [my Next]] ne ""} {
            lassign $t type text line
            if {$type ne "WORD"} {my Error $line "unexpected \"$text\""}
            switch -- $text {
                MACHINE {
                    set rest [my SameLine $line]
                    if {[llength $rest] != 1} {my Error $line "MACHINE wants one name"}
                    dict set d machine [lindex $rest 0]
                }
                INCLUDE {
                    if {[lindex [my Peek] 0] eq "LB"} {
                        my Next
                        while {1} {
                            set t [my Next]
                            if {$t eq ""} {my Error $line "missing \} for INCLUDE"}
                            lassign $t ty tx
                            if {$ty eq "RB"} break
                            if {$ty eq "LB"} {my Error [lindex $t 2] "unexpected \{ in INCLUDE"}
                            dict lappend d includes $tx
                        }
                    } else {
                        set rest [my SameLine $line]
                        if {![llength $rest]} {my Error $line "INCLUDE wants a file"}
                        dict lappend d includes {*}$rest
                    }
                }
                FORMATTING {
                    my Expect LB "\{" FORMATTING
                    set d [my ParseFormatting $d $line lines]
                }
                default {my Error $line "unexpected \"$text\""}
            }
        }
        my Check $d $lines
        return $d
    }

    # ParseFormatting --
    #	Parses FORMATTING entries up to the closing brace; returns d updated.
    #	linesVar collects definition lines for the final check.
    method ParseFormatting {d open linesVar} {
        upvar 1 $linesVar lines
        while {1} {
            set t [my Next]
            if {$t eq ""} {my Error $open "missing \} for FORMATTING"}
            lassign $t type text line
            if {$type eq "RB"} {return $d}
            if {$type ne "WORD"} {my Error $line "unexpected \"$text\" in FORMATTING"}
            switch -- $text {
                WORD_SEPARATOR - END_OF_LINE {
                    set rest [my SameLine $line]
                    if {[llength $rest] != 1} {my Error $line "$text wants one string"}
                    dict set d [string tolower $text] [lindex $rest 0]
                }
                SEQUENCE {
                    set rest [my SameLine $line]
                    if {[llength $rest] < 3 || [llength $rest] > 5} {
                        my Error $line "SEQUENCE wants: template start incr ?freq? ?max?"
                    }
                    lassign $rest tpl start incr freq max
                    if {$freq eq ""} {set freq 1}
                    if {$max eq ""} {set max 9999}
                    foreach v [list $start $incr $freq $max] {
                        if {![string is digit -strict $v]} {my Error $line "SEQUENCE: bad number \"$v\""}
                    }
                    # decimal, whatever the leading zeros
                    foreach v {start incr freq max} {scan [set $v] %d $v}
                    if {$incr < 1 || $max < 1} {my Error $line "SEQUENCE: incr and max must be positive"}
                    dict set d sequence [dict create template $tpl start $start incr $incr \
                        freq $freq max $max]
                    dict set lines sequence $line
                }
                FORMAT {
                    set rest [my SameLine $line]
                    if {[llength $rest] != 2} {my Error $line "FORMAT wants a name and a code"}
                    lassign $rest fname code
                    try {
                        ::fivax::nc::format $code 0
                    } trap {FIVAX NC FORMAT} {msg} {
                        my Error $line "FORMAT $fname: $msg"
                    }
                    dict set d formats $fname $code
                }
                ADDRESS {
                    set aname [my Expect WORD "an address name" ADDRESS]
                    my Expect LB "\{" "ADDRESS $aname"
                    dict set d addresses $aname [my ParseAddress $aname $line]
                    dict set lines addresses $aname $line
                }
                BLOCK_TEMPLATE {
                    set bname [my Expect WORD "a template name" BLOCK_TEMPLATE]
                    my Expect LB "\{" "BLOCK_TEMPLATE $bname"
                    lassign [my ParseBlock $bname $line] words wlines
                    dict set d blocks $bname $words
                    dict set lines blocks $bname $wlines
                }
                default {my Error $line "unknown FORMATTING entry \"$text\""}
            }
        }
    }

    # ParseAddress --
    #	Parses one ADDRESS body (entries KEY value, any layout); returns its dict.
    method ParseAddress {aname open} {
        set a [dict create format "" force off leader $aname leader_expr "" \
            trailer "" trailer_expr "" max "" max_action "" min "" min_action "" \
            zero_format "" incremental off]
        while {1} {
            set t [my Next]
            if {$t eq ""} {my Error $open "missing \} for ADDRESS $aname"}
            lassign $t type key line
            if {$type eq "RB"} break
            if {$type ne "WORD"} {my Error $line "unexpected \"$key\" in ADDRESS $aname"}
            if {$key ni {FORMAT ZERO_FORMAT FORCE INCREMENTAL MAX MIN LEADER TRAILER}} {
                my Error $line "unknown ADDRESS entry \"$key\" in $aname"
            }
            lassign [my Next] vtype v vline
            if {$vtype ni {WORD STR}} {my Error $line "$key wants a value"}
            switch -- $key {
                FORMAT - ZERO_FORMAT {
                    dict set a [string tolower $key] $v
                }
                FORCE {
                    set v [string tolower $v]
                    if {$v ni {off always once}} {my Error $line "FORCE wants Off, Always or Once"}
                    dict set a force $v
                }
                INCREMENTAL {
                    set v [string tolower $v]
                    if {$v ni {on off}} {my Error $line "INCREMENTAL wants ON or OFF"}
                    dict set a incremental $v
                }
                MAX - MIN {
                    if {[::fivax::num::parse $v] eq ""} {my Error $line "$key: bad number \"$v\""}
                    set k [string tolower $key]
                    dict set a $k $v
                    set act ""
                    lassign [my Peek] ntype ntext
                    if {$ntype eq "WORD" && [string tolower $ntext] in {abort warning truncate}} {
                        set act $ntext
                        my Next
                    }
                    dict set a ${k}_action $act
                }
                LEADER - TRAILER {
                    # the raw token decides: a bracketed value is an expression
                    set k [string tolower $key]
                    if {$vtype eq "WORD" && [string index $v 0] eq "\["} {
                        if {[my BracketEnd $v 0 $vline] != [string length $v] - 1} {
                            my Error $vline "$key: text after \[expression\]"
                        }
                        dict set a $k ""
                        dict set a ${k}_expr [string range $v 1 end-1]
                    } else {
                        dict set a $k $v
                        dict set a ${k}_expr ""
                    }
                }
            }
        }
        if {[dict get $a format] eq ""} {my Error $open "ADDRESS $aname has no FORMAT"}
        return $a
    }

    # ParseBlock --
    #	Parses one BLOCK_TEMPLATE body; returns {words lines} (lines: the
    #	source line of each word, for the final check).
    method ParseBlock {bname open} {
        set words {}
        set wlines {}
        while {1} {
            set t [my Next]
            if {$t eq ""} {my Error $open "missing \} for BLOCK_TEMPLATE $bname"}
            lassign $t type text line
            switch -- $type {
                RB {return [list $words $wlines]}
                LB {my Error $line "unexpected \{ in BLOCK_TEMPLATE $bname"}
                STR {
                    lappend words [list literal $text]
                    lappend wlines $line
                }
                WORD {
                    if {[string index $text 0] eq "\\"} {
                        # switches after a "literal"
                        if {![llength $words] || [lindex $words end 0] ne "literal"} {
                            my Error $line "switch \"$text\" without a word"
                        }
                        set w [my Switches [lindex $words end] $text $line]
                        lset words end $w
                    } else {
                        lappend words [my Word $text $line]
                        lappend wlines $line
                    }
                }
            }
        }
    }

    # Word --
    #	Returns the entry {address A expr E opt 0|1 nows 0|1 ...} of a template
    #	word such as X[$mom_pos(0)]\opt.
    method Word {text line} {
        set b [string first "\[" $text]
        if {$b < 0} {my Error $line "template word \"$text\" has no \[expression\]"}
        set addr [string range $text 0 [expr {$b - 1}]]
        if {![regexp {^[A-Za-z_][A-Za-z0-9_]*$} $addr]} {
            my Error $line "bad address name in template word \"$text\""
        }
        set e [my BracketEnd $text $b $line]
        set expr [string range $text [expr {$b + 1}] [expr {$e - 1}]]
        if {[string trim $expr] eq ""} {my Error $line "empty expression in \"$text\""}
        set w [dict create address $addr expr $expr opt 0 nows 0]
        my Switches $w [string range $text [expr {$e + 1}] end] $line
    }

    # Switches --
    #	Returns word entry w with the switches in text (\opt \nows \ldr=X
    #	\trlr=X, written one after another) applied.
    method Switches {w text line} {
        if {$text eq ""} {return $w}
        if {[string index $text 0] ne "\\"} {my Error $line "unexpected \"$text\" after \[expression\]"}
        foreach s [lrange [split $text "\\"] 1 end] {
            switch -glob -- $s {
                opt {
                    if {[dict exists $w literal]} {my Error $line "\\opt on a literal"}
                    dict set w opt 1
                }
                nows {dict set w nows 1}
                ldr=* {dict set w leader [string range $s 4 end]}
                trlr=* {dict set w trailer [string range $s 5 end]}
                default {my Error $line "unknown switch \"\\$s\""}
            }
        }
        return $w
    }

    # Check --
    #	Errors unless every ADDRESS names a known FORMAT/ZERO_FORMAT, every
    #	template word a known ADDRESS, and SEQUENCE a known BLOCK_TEMPLATE.
    method Check {d lines} {
        set formats [dict get $d formats]
        dict for {aname a} [dict get $d addresses] {
            set line [dict get $lines addresses $aname]
            foreach key {format zero_format} {
                set f [dict get $a $key]
                if {$f ne "" && ![dict exists $formats $f]} {
                    my Error $line "ADDRESS $aname: unknown [string toupper $key] \"$f\""
                }
            }
        }
        set addresses [dict get $d addresses]
        dict for {bname words} [dict get $d blocks] {
            foreach w $words line [dict get $lines blocks $bname] {
                if {[dict exists $w address] && ![dict exists $addresses [dict get $w address]]} {
                    my Error $line "BLOCK_TEMPLATE $bname: unknown address \"[dict get $w address]\""
                }
            }
        }
        set seq [dict get $d sequence]
        if {[llength $seq] && ![dict exists $d blocks [dict get $seq template]]} {
            my Error [dict get $lines sequence] "SEQUENCE names unknown BLOCK_TEMPLATE \"[dict get $seq template]\""
        }
    }
}
