# clsf.tcl --
#	Streaming reader for CLSF / APT CL files (NX CLSF_STANDARD, Creo,
#	SolidWorks CAM, Makino FFCAM). Reads one logical record at a time with
#	gets and returns it as a dict; file text is data and is never evaluated.
#
#	A reader is an object (open, channel; "$reader next", "$reader
#	destroy"). Every record dict has kind, file, line (first physical
#	line) and the kind's fields; see ::fivax::clsf::parse. PAINT records
#	are skipped.
#	Errors are {FIVAX CLSF <detail>} with the message "FILE:LINE: MAJOR: what":
#	  OPEN    the file or channel cannot be read
#	  NUMBER  malformed or non-finite number, or non-integer where one is needed
#	  COUNT   wrong number of numbers for the record
#	  AXIS    a direction whose length differs from 1 by more than 1e-3
#	  WORD    missing, unknown or misplaced minor word
#	  RANGE   a value outside its range (KNOT values in (0,1], ascending;
#	          CIRCLE TIMES 0 to 1000)
#	  TEXT    a control character (NUL included) or bytes that are not UTF-8
#	  LINE    a physical line or a record longer than 65536 characters

namespace eval ::fivax::clsf {
    namespace export open channel parse progress ends
    namespace ensemble create -prefixes 0
    namespace upvar ::fivax::num reach reach
}

# ::fivax::clsf::open --
#	Returns a Reader object on the CL file at path; destroying it closes
#	the file.
#	Errors: {FIVAX CLSF OPEN} "PATH: cannot open: REASON".
proc ::fivax::clsf::open {path} {
    if {[file isdirectory $path]} {
        ::fivax::Fail CLSF OPEN "$path: cannot open: is a directory"
    }
    try {
        set chan [::open $path r]
    } trap {POSIX} {msg opts} {
        ::fivax::Fail CLSF OPEN \
            "$path: cannot open: [lindex [dict get $opts -errorcode] end]"
    } on error {msg} {
        ::fivax::Fail CLSF OPEN "$path: cannot open: $msg"
    }
    Reader new $chan $path 1
}

# ::fivax::clsf::channel --
#	Returns a Reader object on the open channel chan; name is the file name
#	used in records and messages. The reader reads the channel as bytes
#	(UTF-8, any line ends) and without blocking; destroying it restores the
#	channel's configuration and leaves it open.
proc ::fivax::clsf::channel {chan name} {
    if {$chan ni [chan names]} {
        ::fivax::Fail CLSF OPEN "$name: cannot open: no channel named \"$chan\""
    }
    Reader new $chan $name 0
}

oo::class create ::fivax::clsf::Reader {
    # chan, name (for messages), line (last physical line handed out), own
    # (1: close chan on destroy), saved (the channel's configuration to
    # restore), lines and idx (the decoded physical lines of the current
    # chunk, ended by the sentinel NUL, and the next one to hand out; a
    # refused line is NUL, the error detail, a space and the reason), carry
    # (bytes after the chunk's last line end), bytes (bytes read so far),
    # eof, skip (1: dropping the rest of an over-long line), partStart and
    # partBytes (where the chunk starts in the input, and its length in
    # bytes), count (records handed out up to the last progress call),
    # progress (the progress command when the reader was made), every and
    # tick (the records between two progress calls, and how many are left
    # to the next one: never reached without a command).
    # (Only those of next are the class's variables: each costs on every
    # call of every method; the other methods link the rest with "my
    # variable".)
    variable name line lines idx tick

    constructor {aChan aName aOwn} {
        my variable chan own saved carry bytes eof skip partStart partBytes count progress every
        set chan $aChan
        set name $aName
        set line 0
        set own $aOwn
        set saved [dict filter [chan configure $chan] key -blocking -translation -encoding]
        chan configure $chan -translation binary -blocking 0
        set lines [list \0]
        set idx 0
        set carry ""
        set bytes 0
        set eof 0
        set skip 0
        set partStart 0
        set partBytes 0
        set count 0
        set progress $::fivax::clsf::progress
        set every [expr {$progress eq "" ? 1 << 62 : $::fivax::clsf::progressEvery}]
        set tick $every
    }

    destructor {
        my variable chan own saved
        if {$chan ni [chan names]} return
        if {$own} {
            ::close $chan
        } else {
            catch {chan configure $chan {*}$saved}
        }
    }

    # Returns {line bytes}: the last physical line handed out and about
    # how many bytes of the input it ends at (for progress reports).
    method position {} {
        my variable bytes carry partStart partBytes
        set n [expr {[llength $lines] - 1}]
        if {$n <= 0} {return [list $line [expr {$bytes - [string length $carry]}]]}
        list $line [expr {$partStart + $partBytes * min($idx, $n) / $n}]
    }

    # Returns the next record dict, or {} at end of file. Joins "$"
    # continuations, drops "$$" comments, blank lines and PAINT. After an
    # error the reader stays usable: the bad record is consumed. A line
    # that is a plain GOTO record (PlainGoto) is read at once; any other
    # goes through parse.
    method next {} {
        set n $line
        while {1} {
            set text [lindex $lines $idx]
            incr idx
            set first [incr n]
            if {[string match GOTO/* $text]} {
                set rec [::fivax::clsf::PlainGoto $text $name $first]
                if {[dict size $rec]} break
            }
            if {[string index $text 0] eq "\0"} {
                # the end of the chunk, or a refused line
                if {$text eq "\0"} {
                    incr n -1
                    if {[my Fill]} continue
                    set line $n
                    return {}
                }
                set line $n
                my Refuse $text $n
            }
            if {[string first "\$" $text] >= 0} {
                set text [my Join $text $first n]
            }
            set text [string trim $text]
            if {$text eq ""} {continue}
            set line $n
            set rec [::fivax::clsf::parse $text $name $first]
            if {[dict size $rec]} break
        }
        set line $n
        if {[incr tick -1] <= 0} {my Progress}
        return $rec
    }

    # Calls the progress command (every records handed out since the
    # last call) and sets the count to the next call.
    method Progress {} {
        my variable count every progress
        incr count $every
        set every $::fivax::clsf::progressEvery
        set tick $every
        {*}$progress $count {*}[my position]
    }

    # Returns text (the first physical line of a record, at line first)
    # joined with the lines it continues to: a single trailing $ continues
    # the record (comments included); drops a "$$" comment. nVar names the
    # caller's line counter, advanced over the lines joined.
    method Join {text first nVar} {
        upvar 1 $nVar n
        set maxRecord $::fivax::clsf::maxRecord
        set text [string trimright $text]
        while {[string index $text end] eq "\$" && [string index $text end-1] ne "\$"} {
            set text [string range $text 0 end-1]
            if {![my Physical more]} break
            incr n
            if {[string index $more 0] eq "\0"} {
                set line $n
                my Refuse $more $n
            }
            append text " " [string trimright $more]
            if {[string length $text] > $maxRecord} {
                set line [my SkipContinuations $more $n]
                ::fivax::Fail CLSF LINE "$name:$first: record longer than\
                    $maxRecord characters (continued to line $n)"
            }
        }
        set c [string first "\$\$" $text]
        if {$c >= 0} {set text [string range $text 0 [expr {$c - 1}]]}
        return $text
    }

    # Sets the caller's variable var to the next physical line (a refusal
    # included); returns 0 at the end of the input.
    method Physical {var} {
        upvar 1 $var text
        while {1} {
            set text [lindex $lines $idx]
            incr idx
            if {$text ne "\0"} {return 1}
            if {![my Fill]} {return 0}
        }
    }

    # Raises the error of the refused physical line lineNo (text: NUL, the
    # error detail, a space and the reason; see ::fivax::clsf::Decode).
    method Refuse {text lineNo} {
        regexp {^\0(\S+) (.*)$} $text -> detail why
        ::fivax::Fail CLSF $detail "$name:$lineNo: $why"
    }

    # Consumes the rest of a continuation chain whose last line so far
    # (line lineNo) is text, without keeping it; returns the last line number.
    method SkipContinuations {text lineNo} {
        while {[string index $text end] eq "\$" && [string index $text end-1] ne "\$"} {
            if {![my Physical text]} break
            set text [string trimright $text]
            incr lineNo
        }
        return $lineNo
    }

    # Reads the next chunk of complete lines into lines (decoded, line ends
    # removed, the sentinel after them); returns 0 at end of input. Memory
    # stays bounded: a line over maxLine characters is replaced by a
    # refusal, and the rest of one that has no end yet is skipped.
    method Fill {} {
        my variable eof carry partStart bytes partBytes chan skip
        namespace upvar ::fivax::clsf chunk chunk maxLine maxLine
        while {1} {
            if {$eof} {
                if {$carry eq ""} {
                    set lines [list \0]
                    set idx 0
                    return 0
                }
                set part $carry
                set partStart [expr {$bytes - [string length $carry]}]
                set partBytes [string length $carry]
                set carry ""
            } else {
                set data [read $chan $chunk]
                if {$data eq ""} {
                    if {[eof $chan]} {
                        set eof 1
                        continue
                    }
                    # Nothing there yet (a pipe): wait for one byte, then
                    # take what has come.
                    chan configure $chan -blocking 1
                    set data [read $chan 1]
                    chan configure $chan -blocking 0
                    append data [read $chan [expr {$chunk - 1}]]
                    if {$data eq ""} continue
                }
                if {$bytes == 0 && [string range $data 0 2] eq "\xEF\xBB\xBF"} {
                    set data [string range $data 3 end]
                    set bytes 3
                }
                incr bytes [string length $data]
                if {$skip} {
                    set nl [string first \n $data]
                    if {$nl < 0} continue
                    set data [string range $data [expr {$nl + 1}] end]
                    set skip 0
                }
                append carry $data
                # Cut after the last line end: \n, or a lone \r that is
                # not the last byte (its \n may follow in the next read).
                set cut [string last \n $carry]
                set cr [string last \r $carry end-1]
                if {$cr > $cut} {set cut $cr}
                if {$cut < 0} {
                    if {[string length $carry] > $maxLine} {
                        set skip 1
                        set why [::fivax::clsf::Control [string range $carry 0 $maxLine]]
                        if {$why eq ""} {set why "LINE line longer than $maxLine characters"}
                        set lines [list "\0$why" \0]
                        set carry ""
                        set idx 0
                        return 1
                    }
                    continue
                }
                set partStart [expr {$bytes - [string length $carry]}]
                set partBytes [expr {$cut + 1}]
                set part [string range $carry 0 [expr {$cut - 1}]]
                if {[string index $part end] eq "\r" && [string index $carry $cut] eq "\n"} {
                    # the \r of the \r\n the cut ends with
                    set part [string range $part 0 end-1]
                }
                set carry [string range $carry [expr {$cut + 1}] end]
            }
            set lines [::fivax::clsf::Decode $part]
            if {[string length $part] > $maxLine} {
                set lines [lmap text $lines {
                    if {[string length $text] > $maxLine} {
                        set text "\0LINE line longer than $maxLine characters"
                    }
                    set text
                }]
            }
            lappend lines \0
            set idx 0
            if {[llength $lines] > 1} {return 1}
        }
    }
}

namespace eval ::fivax::clsf {
    # Longest physical line and longest record ($ continuations joined),
    # in characters; bytes read per chunk.
    variable maxLine 65536
    variable maxRecord 65536
    variable chunk 60000
    # Most extra turns of a helix (CIRCLE ... TIMES n): each turn is at
    # least one arc piece, and its points at the arc tolerance (a few
    # hundred a turn) go through the planner. A single-point thread mill
    # cutting 100 mm of thread at 0.2 mm pitch turns 500 times, a helical
    # ramp 50 mm down at 0.5 mm a turn 100 times; 2147483647 ran until
    # killed.
    variable maxTurns 1000
    # The progress command (see progress) and how many records apart it runs.
    variable progress ""
    variable progressEvery 256
}

# ::fivax::clsf::progress --
#	Sets the command prefix that readers made from now on call every 256
#	records with the records read, the line and about the bytes read to it
#	(for a progress display); "" (the default) turns it off. Returns the
#	previous one.
proc ::fivax::clsf::progress {cmd} {
    variable progress
    set old $progress
    set progress $cmd
    return $old
}

# ::fivax::clsf::ends --
#	Returns 1 when record rec may be the last of a complete CL file: NX's
#	END-OF-PATH (each operation ends with one; NX writes no FINI), APT's
#	FINI (Creo, SolidWorks CAM), or Makino FFCAM's closing section
#	PPRINT/END-SECTION,PROCESS-END-PATH (its files have neither). A file
#	whose last record is anything else was cut short.
proc ::fivax::clsf::ends {rec} {
    switch -- [dict get $rec kind] {
        END_OF_PATH - FINI {return 1}
        PPRINT {
            return [expr {[string toupper [string map {" " ""} [dict get $rec text]]]
                eq "END-SECTION,PROCESS-END-PATH"}]
        }
    }
    return 0
}

# ::fivax::clsf::Decode --
#	Returns the physical lines of part (bytes, line ends \n, \r\n or \r)
#	as UTF-8 decoded strings. A line holding a control character other
#	than tab (NUL included) or bytes that are not UTF-8 is replaced by a
#	refusal: NUL, "TEXT", a space and the reason (a decoded line never
#	holds NUL).
proc ::fivax::clsf::Decode {part} {
    # printable ASCII, tabs and \n only (the common case): one scan
    if {![regexp {[^\t\n\x20-\x7e]} $part]} {return [split $part \n]}
    if {[string first \r $part] >= 0} {set part [string map {\r\n \n \r \n} $part]}
    set lines [split $part \n]
    if {[string is ascii $part] && ![regexp {[\x00-\x08\x0b-\x1f\x7f]} $part]} {
        return $lines
    }
    lmap text $lines {
        set why [Control $text]
        if {$why ne ""} {
            set text "\0$why"
        } elseif {![string is ascii $text]} {
            set decoded [encoding convertfrom utf-8 $text]
            if {[encoding convertto utf-8 $decoded] ne $text} {
                set text "\0TEXT bytes that are not UTF-8 text"
            } else {
                set text $decoded
            }
        }
        set text
    }
}

# ::fivax::clsf::Control --
#	Returns "TEXT control character 0xNN in column N" for the first
#	control character in text other than tab, \n and \r (NUL included),
#	or "".
proc ::fivax::clsf::Control {text} {
    if {![regexp -indices {[\x00-\x08\x0b\x0c\x0e-\x1f\x7f]} $text at]} {return ""}
    set col [lindex $at 0]
    scan [string index $text $col] %c code
    format "TEXT control character 0x%02X in column %d" $code [expr {$col + 1}]
}

# ::fivax::clsf::parse --
#	Returns the record dict for one logical record text (joined, without
#	comments) found at file:line, or {} for PAINT. Never evaluates text.
proc ::fivax::clsf::parse {text file line} {
    set slash [string first / $text]
    if {$slash >= 0} {
        set major [string toupper [string trim [string range $text 0 [expr {$slash - 1}]]]]
        set rest [string range $text [expr {$slash + 1}] end]
    } else {
        set major [string toupper [string trim $text]]
        set rest ""
    }
    if {![string is wordchar $major]} {set major [regsub -all {\s+} $major " "]}
    switch -exact -- $major {
        GOTO - FROM - GOHOME {
            # Plain NX tokens need no trimming.
            set toks [split $rest ,]
            if {![string is graph $rest]} {
                set toks [lmap t $toks {string trim $t}]
            }
            set cnt [llength $toks]
            if {$cnt != 3 && $cnt != 6} {
                if {[string trim $rest] eq ""} {set cnt 0}
                ::fivax::Fail CLSF COUNT \
                    "$file:$line: $major: expected 3 or 6 numbers, got $cnt"
            }
            lassign $toks a b c i j k
            set x [::fivax::num::parse $a]
            if {$x eq ""} {BadNumber $a $file $line $major}
            set y [::fivax::num::parse $b]
            if {$y eq ""} {BadNumber $b $file $line $major}
            set z [::fivax::num::parse $c]
            if {$z eq ""} {BadNumber $c $file $line $major}
            Reach [list $x $y $z] $file $line $major
            set axis {}
            if {$cnt == 6} {set axis [Axis $i $j $k $file $line $major "tool axis"]}
            return [dict create kind $major file $file line $line \
                        point [list $x $y $z] axis $axis]
        }
        PAINT       {return {}}
        RAPID       {return [ParseRapid $rest $file $line]}
        CIRCLE      {return [ParseCircle $rest $file $line]}
        FEDRAT      {return [ParseFedrat $rest $file $line]}
        CUTCOM      {return [ParseCutcom $rest $file $line]}
        CONTACT     {return [ParseContact $rest $file $line]}
        PPRINT - INSERT - PARTNO {
            return [dict create kind $major file $file line $line \
                        text [string trim $rest]]
        }
        {TOOL PATH} {return [ParseToolPath $rest $file $line]}
        TLDATA      {return [ParseTldata $rest $file $line]}
        CUTTER      {return [ParseCutter $rest $file $line]}
        MSYS        {return [ParseMsys $rest $file $line]}
        LOAD - LOADTL {return [ParseLoad $major $rest $file $line]}
        SELECT      {return [ParseSelect $rest $file $line]}
        SPINDL      {return [ParseSpindl $rest $file $line]}
        COOLNT      {return [ParseCoolnt $rest $file $line]}
        TLAXIS      {return [ParseTlaxis $rest $file $line]}
        END-OF-PATH {return [dict create kind END_OF_PATH file $file line $line]}
        STOP - OPSTOP - FINI - END {
            return [dict create kind $major file $file line $line]
        }
        DELAY       {return [ParseDelay $rest $file $line]}
        CYCLE       {return [ParseCycle $rest $file $line]}
        UNITS - UNIT {return [ParseUnits $major $rest $file $line]}
        MULTAX      {return [ParseMultax $rest $file $line]}
        NURBS       {return [ParseNurbs $rest $file $line]}
        KNOT        {return [ParseKnot $rest $file $line]}
        CNTRL       {return [ParseCntrl $rest $file $line]}
        default     {return [ParseOther $major $text $rest $file $line]}
    }
}

# ::fivax::clsf::PlainGoto --
#	The fast path of a physical line "GOTO/rest" as NX writes it (the
#	reader's next tries it first): returns its record when rest is exactly
#	3 or 6 finite decimal numbers and the axis is a unit vector, else {}
#	(the line then goes through parse, which reads it token by token,
#	with the errors). The numbers scan reads are those of num::parse:
#	hex, binary, octal and nan stop it, Inf fails the finite test, the
#	white space it skips before a number is white space string trim
#	removes, and %n proves nothing is left over (no "$", no comment, no
#	white space at the end).
proc ::fivax::clsf::PlainGoto {text file line} {
    if {[scan $text GOTO/%lf,%lf,%lf,%lf,%lf,%lf%n x y z i j k end] == 7} {
        set axis [Unit $i $j $k]
        # (llength: eq would make the list's string for nothing)
        if {![llength $axis]} {return {}}
    } elseif {[scan $text GOTO/%lf,%lf,%lf%n x y z end] == 4} {
        set axis {}
    } else {
        return {}
    }
    # (within reach, so finite; abs() is a command call in expr)
    variable reach
    if {$end != [string length $text] || !($x <= $reach && $x >= -$reach
            && $y <= $reach && $y >= -$reach && $z <= $reach && $z >= -$reach)} {
        return {}
    }
    dict create kind GOTO file $file line $line point [list $x $y $z] axis $axis
}

# ::fivax::clsf::Reach --
#	Raises RANGE when a coordinate of point lies beyond reach (no machine
#	goes there; the planner's sums would overflow).
proc ::fivax::clsf::Reach {point file line major} {
    variable reach
    foreach c $point axis {X Y Z} {
        if {!(abs($c) <= $reach)} {
            ::fivax::Fail CLSF RANGE "$file:$line: $major: $axis [::format %g $c] lies beyond\
                [::format %g $reach] mm of the origin (no machine reaches it)"
        }
    }
}

# ::fivax::clsf::Tokens -- Returns the trimmed comma-separated tokens of rest.
proc ::fivax::clsf::Tokens {rest} {
    if {[string trim $rest] eq ""} {return {}}
    lmap t [split $rest ,] {string trim $t}
}

# ::fivax::clsf::Quote -- Returns tok in single quotes, cut to 40 characters.
proc ::fivax::clsf::Quote {tok} {
    if {[string length $tok] > 40} {set tok "[string range $tok 0 36]..."}
    return '$tok'
}

# ::fivax::clsf::BadNumber -- Raises {FIVAX CLSF NUMBER} for token tok.
proc ::fivax::clsf::BadNumber {tok file line major} {
    ::fivax::Fail CLSF NUMBER "$file:$line: $major: [Quote $tok] is not a number"
}

# ::fivax::clsf::Num -- Returns token tok as a double, or raises NUMBER.
proc ::fivax::clsf::Num {tok file line major} {
    set v [::fivax::num::parse $tok]
    if {$v eq ""} {BadNumber $tok $file $line $major}
    return $v
}

# ::fivax::clsf::Int --
#	Returns the integer in token tok (2, 2.0 or 2.), or raises NUMBER.
proc ::fivax::clsf::Int {tok file line major} {
    set v [Num $tok $file $line $major]
    if {$v != floor($v) || abs($v) >= 2147483648.0} {
        ::fivax::Fail CLSF NUMBER \
            "$file:$line: $major: [Quote $tok] is not an integer"
    }
    return [expr {int($v)}]
}

# ::fivax::clsf::Nums -- Returns the list of doubles in the token list toks.
proc ::fivax::clsf::Nums {toks file line major} {
    lmap t $toks {Num $t $file $line $major}
}

# ::fivax::clsf::Axis --
#	Returns {i j k} from the tokens i j k, normalised; raises AXIS when the
#	length differs from 1 by more than 1e-3 (label names it in the message).
proc ::fivax::clsf::Axis {i j k file line major label} {
    set axis [Unit [Num $i $file $line $major] [Num $j $file $line $major] \
        [Num $k $file $line $major]]
    if {$axis eq ""} {
        ::fivax::Fail CLSF AXIS \
            "$file:$line: $major: $label ($i,$j,$k) is not a unit vector"
    }
    return $axis
}

# ::fivax::clsf::Unit --
#	Returns {u v w} normalised, or "" when its length differs from 1 by
#	more than 1e-3 (or is not finite).
proc ::fivax::clsf::Unit {u v w} {
    set len [expr {sqrt($u * $u + $v * $v + $w * $w)}]
    # (|len - 1| <= 1e-3 as two comparisons: abs() is a command call in expr)
    set off [expr {$len - 1.0}]
    if {!($off <= 1e-3 && $off >= -1e-3)} {return ""}
    if {$len != 1.0} {
        return [list [expr {$u / $len}] [expr {$v / $len}] [expr {$w / $len}]]
    }
    list $u $v $w
}

# ::fivax::clsf::Words --
#	Returns a flat list of {N double} / {W UPPERWORD} pairs for the tokens
#	of rest. A token that starts like a number, or that Tcl reads as one
#	(nan, Inf, 0x10), must be a decimal number (NUMBER).
proc ::fivax::clsf::Words {rest file line major} {
    set out {}
    foreach t [Tokens $rest] {
        set v [::fivax::num::parse $t]
        if {$v ne ""} {
            lappend out N $v
        } elseif {[string match {[-+.0-9]*} $t] || [string is double -strict $t]} {
            BadNumber $t $file $line $major
        } else {
            lappend out W [string toupper $t]
        }
    }
    return $out
}

# ::fivax::clsf::BadWord -- Raises {FIVAX CLSF WORD} for word w.
proc ::fivax::clsf::BadWord {w file line major} {
    ::fivax::Fail CLSF WORD "$file:$line: $major: unexpected word [Quote $w]"
}

# ::fivax::clsf::ParseRapid -- Returns a RAPID record; RAPID/ takes no arguments.
proc ::fivax::clsf::ParseRapid {rest file line} {
    if {[string trim $rest] ne ""} {
        ::fivax::Fail CLSF WORD \
            "$file:$line: RAPID: unexpected arguments [Quote [string trim $rest]]"
    }
    dict create kind RAPID file $file line $line
}

# ::fivax::clsf::ParseCircle --
#	Returns a CIRCLE record: center, axis, radius ("" with 6 numbers),
#	numbers, times, and tolerance intol tool_diameter tool_radius with 11+.
proc ::fivax::clsf::ParseCircle {rest file line} {
    set nums {}
    set raw {}
    set times 0
    set toks [Tokens $rest]
    for {set p 0} {$p < [llength $toks]} {incr p} {
        set t [lindex $toks $p]
        set v [::fivax::num::parse $t]
        if {$v ne ""} {
            lappend nums $v
            lappend raw $t
        } elseif {[string toupper $t] eq "TIMES"} {
            incr p
            if {$p >= [llength $toks]} {
                ::fivax::Fail CLSF COUNT "$file:$line: CIRCLE: TIMES needs a number"
            }
            set times [Int [lindex $toks $p] $file $line CIRCLE]
            if {$times < 0 || $times > $::fivax::clsf::maxTurns} {
                ::fivax::Fail CLSF RANGE "$file:$line: CIRCLE: TIMES [Quote [lindex $toks $p]] is\
                    not a number of extra turns from 0 to $::fivax::clsf::maxTurns"
            }
        } elseif {[string match {[-+.0-9]*} $t]} {
            BadNumber $t $file $line CIRCLE
        } else {
            BadWord $t $file $line CIRCLE
        }
    }
    set cnt [llength $nums]
    if {$cnt < 6} {
        ::fivax::Fail CLSF COUNT \
            "$file:$line: CIRCLE: expected at least 6 numbers, got $cnt"
    }
    lassign $raw - - - i j k
    set rec [dict create kind CIRCLE file $file line $line \
                 center [lrange $nums 0 2] \
                 axis [Axis $i $j $k $file $line CIRCLE axis] \
                 radius [expr {$cnt > 6 ? [lindex $nums 6] : ""}] \
                 numbers $nums times $times]
    if {$cnt >= 11} {
        lassign [lrange $nums 7 10] tol intol dia rad
        dict set rec tolerance $tol
        dict set rec intol $intol
        dict set rec tool_diameter $dia
        dict set rec tool_radius $rad
    }
    return $rec
}

# ::fivax::clsf::ParseFedrat --
#	Returns a FEDRAT record: value and unit (the raw word MMPM IPM MMPR IPR
#	PERMIN PERREV, or "" when only a number is given).
proc ::fivax::clsf::ParseFedrat {rest file line} {
    set vals {}
    set unit ""
    foreach {t v} [Words $rest $file $line FEDRAT] {
        if {$t eq "N"} {
            lappend vals $v
        } elseif {$v in {MMPM IPM MMPR IPR PERMIN PERREV} && $unit eq ""} {
            set unit $v
        } else {
            BadWord $v $file $line FEDRAT
        }
    }
    if {[llength $vals] != 1} {
        ::fivax::Fail CLSF COUNT \
            "$file:$line: FEDRAT: expected 1 number, got [llength $vals]"
    }
    dict create kind FEDRAT file $file line $line value [lindex $vals 0] unit $unit
}

# ::fivax::clsf::ParseCutcom --
#	Returns a CUTCOM record: mode LEFT|RIGHT|ON|OFF, plane, register.
proc ::fivax::clsf::ParseCutcom {rest file line} {
    set mode ""
    set plane ""
    set reg ""
    foreach {t v} [Words $rest $file $line CUTCOM] {
        if {$t eq "N"} {
            if {$reg ne ""} {
                ::fivax::Fail CLSF COUNT "$file:$line: CUTCOM: more than one register"
            }
            set reg [Int $v $file $line CUTCOM]
        } elseif {$v in {LEFT RIGHT ON OFF} && $mode eq ""} {
            set mode $v
        } elseif {$v in {XYPLAN YZPLAN ZXPLAN} && $plane eq ""} {
            set plane $v
        } else {
            BadWord $v $file $line CUTCOM
        }
    }
    if {$mode eq ""} {
        ::fivax::Fail CLSF WORD "$file:$line: CUTCOM: expected LEFT, RIGHT, ON or OFF"
    }
    dict create kind CUTCOM file $file line $line mode $mode plane $plane register $reg
}

# ::fivax::clsf::ParseContact --
#	Returns a CONTACT record: point (the contact point, MCS) and normal
#	(the unit surface normal there, pointing out of the material) from
#	CONTACT/x,y,z,i,j,k. It belongs to the GOTO that follows it (the
#	contact data of that CL point: NX's mom_contact_point and
#	mom_contact_normal; a record before the motion it describes, as
#	SprutCAM's TLContact). NX documents the variables, not the CLSF text
#	of its "Output Contact Data": this form is fivax's (README, Contact
#	data).
proc ::fivax::clsf::ParseContact {rest file line} {
    set toks [Tokens $rest]
    if {[llength $toks] != 6} {
        ::fivax::Fail CLSF COUNT "$file:$line: CONTACT: expected 6 numbers (contact point and\
            surface normal), got [llength $toks]"
    }
    lassign $toks x y z i j k
    set point [Nums [list $x $y $z] $file $line CONTACT]
    Reach $point $file $line CONTACT
    dict create kind CONTACT file $file line $line point $point \
        normal [Axis $i $j $k $file $line CONTACT "surface normal"]
}

# ::fivax::clsf::ParseToolPath --
#	Returns a TOOLPATH record from TOOL PATH/name,TOOL,tool (names as written).
proc ::fivax::clsf::ParseToolPath {rest file line} {
    set toks [Tokens $rest]
    set tool ""
    set p [lsearch -exact [lmap t [lrange $toks 1 end] {string toupper $t}] TOOL]
    if {$p >= 0} {set tool [lindex $toks [expr {$p + 2}]]}
    dict create kind TOOLPATH file $file line $line name [lindex $toks 0] tool $tool
}

# ::fivax::clsf::ParseTldata --
#	Returns a TLDATA record: type MILL|DRILL, numbers and the named fields
#	(MILL 5, 7 or 10 numbers; DRILL[,MILL] 5 numbers).
proc ::fivax::clsf::ParseTldata {rest file line} {
    set toks [Tokens $rest]
    set type [string toupper [lindex $toks 0]]
    set toks [lrange $toks 1 end]
    switch -exact -- $type {
        MILL {
            set names {diameter corner1_radius length taper_angle tip_angle
                x_corner1 y_corner1 corner2_radius x_corner2 y_corner2}
            set allowed {5 7 10}
        }
        DRILL {
            if {[string toupper [lindex $toks 0]] eq "MILL"} {set toks [lrange $toks 1 end]}
            set names {diameter corner1_radius length tip_angle flute_length}
            set allowed {5}
        }
        default {
            ::fivax::Fail CLSF WORD \
                "$file:$line: TLDATA: unsupported tool type [Quote $type]"
        }
    }
    set nums [Nums $toks $file $line TLDATA]
    set cnt [llength $nums]
    if {$cnt ni $allowed} {
        set want [expr {$type eq "MILL" ? "5, 7 or 10" : "5"}]
        ::fivax::Fail CLSF COUNT \
            "$file:$line: TLDATA: expected $want numbers for $type, got $cnt"
    }
    set rec [dict create kind TLDATA file $file line $line type $type numbers $nums]
    foreach key [lrange $names 0 [expr {$cnt - 1}]] v $nums {
        dict set rec $key $v
    }
    return $rec
}

# ::fivax::clsf::ParseCutter --
#	Returns a CUTTER record: diameter, corner1_radius (0 if absent), numbers.
proc ::fivax::clsf::ParseCutter {rest file line} {
    set nums [Nums [Tokens $rest] $file $line CUTTER]
    if {[llength $nums] < 1} {
        ::fivax::Fail CLSF COUNT "$file:$line: CUTTER: expected at least 1 number, got 0"
    }
    set r [expr {[llength $nums] > 1 ? [lindex $nums 1] : 0.0}]
    dict create kind CUTTER file $file line $line \
        diameter [lindex $nums 0] corner1_radius $r numbers $nums
}

# ::fivax::clsf::ParseMsys --
#	Returns an MSYS record: origin, and unit xaxis and yaxis (normalised).
proc ::fivax::clsf::ParseMsys {rest file line} {
    set toks [Tokens $rest]
    set nums [Nums $toks $file $line MSYS]
    if {[llength $nums] != 9} {
        ::fivax::Fail CLSF COUNT \
            "$file:$line: MSYS: expected 9 numbers, got [llength $nums]"
    }
    lassign $toks - - - x1 x2 x3 y1 y2 y3
    dict create kind MSYS file $file line $line origin [lrange $nums 0 2] \
        xaxis [Axis $x1 $x2 $x3 $file $line MSYS "x axis"] \
        yaxis [Axis $y1 $y2 $y3 $file $line MSYS "y axis"]
}

# ::fivax::clsf::ParseLoad --
#	Returns a LOAD record (tool, adjust) from LOAD/TOOL,n[,ADJUST,m] or
#	LOADTL/n[,ADJUST,m].
proc ::fivax::clsf::ParseLoad {major rest file line} {
    set toks [Tokens $rest]
    if {$major eq "LOAD"} {
        if {[string toupper [lindex $toks 0]] ne "TOOL"} {
            ::fivax::Fail CLSF WORD "$file:$line: LOAD: expected TOOL"
        }
        set toks [lrange $toks 1 end]
    }
    if {![llength $toks]} {
        ::fivax::Fail CLSF COUNT "$file:$line: $major: expected a tool number"
    }
    set tool [Int [lindex $toks 0] $file $line $major]
    set adjust ""
    set toks [lrange $toks 1 end]
    if {[llength $toks]} {
        if {[string toupper [lindex $toks 0]] ne "ADJUST"} {
            BadWord [lindex $toks 0] $file $line $major
        }
        if {[llength $toks] != 2} {
            ::fivax::Fail CLSF COUNT "$file:$line: $major: ADJUST needs one number"
        }
        set adjust [Int [lindex $toks 1] $file $line $major]
    }
    dict create kind LOAD file $file line $line tool $tool adjust $adjust
}

# ::fivax::clsf::ParseSelect -- Returns a SELECT record (tool) from SELECT/TOOL,n.
proc ::fivax::clsf::ParseSelect {rest file line} {
    set toks [Tokens $rest]
    if {[string toupper [lindex $toks 0]] ne "TOOL"} {
        ::fivax::Fail CLSF WORD "$file:$line: SELECT: expected TOOL"
    }
    if {[llength $toks] != 2} {
        ::fivax::Fail CLSF COUNT \
            "$file:$line: SELECT: expected TOOL and one number, got [llength $toks] tokens"
    }
    dict create kind SELECT file $file line $line \
        tool [Int [lindex $toks 1] $file $line SELECT]
}

# ::fivax::clsf::ParseSpindl --
#	Returns a SPINDL record: state ON|OFF, speed, mode RPM|SFM|SMM,
#	direction CLW|CCLW; words and the speed may come in any order.
proc ::fivax::clsf::ParseSpindl {rest file line} {
    set state ON
    set speed ""
    set mode RPM
    set dir ""
    foreach {t v} [Words $rest $file $line SPINDL] {
        if {$t eq "N"} {
            if {$speed ne ""} {
                ::fivax::Fail CLSF COUNT "$file:$line: SPINDL: more than one speed"
            }
            set speed $v
        } elseif {$v in {ON OFF}} {
            set state $v
        } elseif {$v in {RPM SFM SMM}} {
            set mode $v
        } elseif {$v in {CLW CCLW}} {
            set dir $v
        } else {
            BadWord $v $file $line SPINDL
        }
    }
    dict create kind SPINDL file $file line $line \
        state $state speed $speed mode $mode direction $dir
}

# ::fivax::clsf::ParseCoolnt --
#	Returns a COOLNT record: mode ON|OFF|FLOOD|MIST|THRU|TAP (OFF wins; a
#	medium wins over ON).
proc ::fivax::clsf::ParseCoolnt {rest file line} {
    set words {}
    foreach {t v} [Words $rest $file $line COOLNT] {
        if {$t eq "N" || $v ni {ON OFF FLOOD MIST THRU TAP}} {
            BadWord $v $file $line COOLNT
        }
        lappend words $v
    }
    set mode ""
    foreach v $words {
        if {$v eq "OFF"} {
            set mode OFF
            break
        }
        if {$mode eq "" || $mode eq "ON"} {set mode $v}
    }
    if {$mode eq ""} {
        ::fivax::Fail CLSF WORD "$file:$line: COOLNT: expected ON, OFF, FLOOD, MIST, THRU or TAP"
    }
    dict create kind COOLNT file $file line $line mode $mode
}

# ::fivax::clsf::ParseTlaxis -- Returns a TLAXIS record (unit axis) from TLAXIS/i,j,k.
proc ::fivax::clsf::ParseTlaxis {rest file line} {
    set toks [Tokens $rest]
    if {[llength $toks] != 3} {
        ::fivax::Fail CLSF COUNT \
            "$file:$line: TLAXIS: expected 3 numbers, got [llength $toks]"
    }
    lassign $toks i j k
    dict create kind TLAXIS file $file line $line \
        axis [Axis $i $j $k $file $line TLAXIS "tool axis"]
}

# ::fivax::clsf::ParseDelay --
#	Returns a DELAY record: value in seconds, or revs for DELAY/REV,n
#	(the other field is "").
proc ::fivax::clsf::ParseDelay {rest file line} {
    set vals {}
    set rev 0
    foreach {t v} [Words $rest $file $line DELAY] {
        if {$t eq "N"} {
            lappend vals $v
        } elseif {$v in {REV REVS}} {
            set rev 1
        } elseif {$v ni {SEC SECS}} {
            BadWord $v $file $line DELAY
        }
    }
    if {[llength $vals] != 1} {
        ::fivax::Fail CLSF COUNT \
            "$file:$line: DELAY: expected 1 number, got [llength $vals]"
    }
    set v [lindex $vals 0]
    if {$rev} {
        return [dict create kind DELAY file $file line $line value "" revs $v]
    }
    dict create kind DELAY file $file line $line value $v revs ""
}

# ::fivax::clsf::ParseCycle --
#	Returns a CYCLE record: type (first word) and args (numbers as doubles,
#	words uppercased).
proc ::fivax::clsf::ParseCycle {rest file line} {
    set items [Words $rest $file $line CYCLE]
    lassign $items t type
    if {$t ne "W" || $type eq ""} {
        ::fivax::Fail CLSF WORD "$file:$line: CYCLE: expected a cycle type"
    }
    set args {}
    foreach {t v} [lrange $items 2 end] {lappend args $v}
    dict create kind CYCLE file $file line $line type $type args $args
}

# ::fivax::clsf::ParseUnits -- Returns a UNITS record: value MM|INCH.
proc ::fivax::clsf::ParseUnits {major rest file line} {
    set w [string toupper [string trim $rest]]
    switch -exact -- $w {
        MM - MILLIMETERS - MILLIMETRES {set v MM}
        INCH - INCHES - IN {set v INCH}
        default {
            ::fivax::Fail CLSF WORD "$file:$line: $major: expected MM or INCHES, got [Quote $w]"
        }
    }
    dict create kind UNITS file $file line $line value $v
}

# ::fivax::clsf::ParseMultax -- Returns a MULTAX record: state ON|OFF (bare MULTAX is ON).
proc ::fivax::clsf::ParseMultax {rest file line} {
    set w [string toupper [string trim $rest]]
    if {$w eq ""} {set w ON}
    if {$w ni {ON OFF}} {
        ::fivax::Fail CLSF WORD "$file:$line: MULTAX: expected ON or OFF, got [Quote $w]"
    }
    dict create kind MULTAX file $file line $line state $w
}

# NX spline moves: NURBS/ starts one, then KNOT/ records (the knot values)
# and CNTRL/ records (the control points) follow; ::fivax::curve::clsfNurbs
# documents how they make a curve with the current position.

# ::fivax::clsf::ParseNurbs -- Returns a NURBS record; NURBS/ takes no arguments.
proc ::fivax::clsf::ParseNurbs {rest file line} {
    if {[string trim $rest] ne ""} {
        ::fivax::Fail CLSF COUNT \
            "$file:$line: NURBS: expected no arguments, got [Quote [string trim $rest]]"
    }
    dict create kind NURBS file $file line $line
}

# ::fivax::clsf::ParseKnot --
#	Returns a KNOT record: knots, the list of its values (at least one,
#	each in (0,1], ascending or equal).
proc ::fivax::clsf::ParseKnot {rest file line} {
    set toks [Tokens $rest]
    if {![llength $toks]} {
        ::fivax::Fail CLSF COUNT "$file:$line: KNOT: expected at least 1 number, got 0"
    }
    set knots [Nums $toks $file $line KNOT]
    set prev 0.0
    foreach k $knots t $toks {
        if {!($k > 0.0 && $k <= 1.0)} {
            ::fivax::Fail CLSF RANGE "$file:$line: KNOT: [Quote $t] is not in (0,1]"
        }
        if {$k < $prev} {
            ::fivax::Fail CLSF RANGE "$file:$line: KNOT: [Quote $t] is less than the value before it"
        }
        set prev $k
    }
    dict create kind KNOT file $file line $line knots $knots
}

# ::fivax::clsf::ParseCntrl -- Returns a CNTRL record (point) from CNTRL/x,y,z.
proc ::fivax::clsf::ParseCntrl {rest file line} {
    set toks [Tokens $rest]
    if {[llength $toks] != 3} {
        ::fivax::Fail CLSF COUNT \
            "$file:$line: CNTRL: expected 3 numbers, got [llength $toks]"
    }
    dict create kind CNTRL file $file line $line point [Nums $toks $file $line CNTRL]
}

# ::fivax::clsf::ParseOther --
#	Returns an UNKNOWN record (major, raw trimmed args), or a PPRINT, INSERT
#	or PARTNO record written APT-style without "/" (PPRINT some text).
proc ::fivax::clsf::ParseOther {major text rest file line} {
    set sp [string first " " $major]
    if {$sp > 0} {
        set word [string range $major 0 [expr {$sp - 1}]]
        if {$word in {PPRINT INSERT PARTNO}} {
            regexp {^\s*\S+\s(.*)$} $text -> tail
            return [dict create kind $word file $file line $line \
                        text [string trim $tail]]
        }
    }
    dict create kind UNKNOWN file $file line $line major $major args [Tokens $rest]
}

## Ready
