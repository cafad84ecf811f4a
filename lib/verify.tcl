# verify.tcl --
#	Checks NC blocks by forward kinematics (never the inverse). A Checker
#	reads the words of each block from the NC text (so output rounding
#	counts), keeps the controller's modal state (axis values, G0/G1,
#	G93/G94, F), counts rotary values outside the machine's limits, and
#	measures the tool tip and axis: at a block end against a CL target,
#	and at the quarter points of the controller's linear joint
#	interpolation against a straight segment and the great circle of the
#	tool axis (spec section 7). Two hosts share this code: the post checks
#	each block it writes (method block, with the planner's CL target), and
#	tools/verify.tcl checks whole NC files of any post (methods read, tip,
#	deviation, interior, drillOff); in the post's blocks a value outside the
#	machine's travel or rotary limits is refused with the CL record's
#	FILE:LINE (machine checkLimits). It knows nothing of how the planner
#	chose the blocks: it depends on kin and the machine's limits only.
#
#	Dialects: the text of a block is turned into address words by the
#	controller's reader table (lib/dialect/: comments, lines that are no
#	blocks, the word pattern; a controller without a file is an error);
#	what the words mean is the ISO meaning common to the G-code controls
#	(G0 G1 G2 G3 G93 G94, X Y Z, the machine's
#	rotary letters, F), with the canned cycles (G73 G76 G81..G89 with
#	G98/G99 and R: the tool goes to X Y, down to Z, and back to the
#	initial level or the R plane; G80 or a motion code ends them) and G53
#	(its axis words are machine coordinates: those axes are unknown until
#	written again). A controller's keywords and lines of another syntax
#	are first turned into those terms by the Translate method of its
#	file's reader class (the reader table's methods key).
#
#	Three spaces a block's X Y Z can be in: joint (machine values: the
#	tip by forward kinematics), TCP (the reader's tcpG, a keyword its
#	Translate reads, or the machine's tcp_codes: X Y Z are the tip in the
#	workpiece frame, the axis comes from the rotaries) and a tilted work
#	plane (the reader's plane G code, or a keyword: X Y Z are plane
#	coordinates, the tool axis is the plane's Z; see lib/plane.tcl). A
#	block's pose {P t} is the tip and axis in the workpiece frame in each.

namespace eval ::fivax::verify {
    namespace export create reader
    namespace ensemble create -prefixes 0
    variable Options {
        {-table-offset {maybe vec3} {} "X Y Z"
            "workpiece-frame position of the table reference point (default: the machine's table_offset)"}
        {-controller {maybe word} {} NAME
            "dialect of the NC text (default: the machine's controller; one of lib/dialect/)"}
    }

    # How the words of a block are found: the reader table of each
    # controller (lib/dialect/<name>.tcl, see lib/dialect.tcl) has the keys:
    #   comment  regexp of comment text, removed before reading words; the
    #            text of each (the first capture group) is returned
    #   skip     regexp of whole lines that are not blocks (% and O1000);
    #            of the lines of plain words (lineRe) it may match only
    #            those of one word (it is not tried on the others)
    #   word     regexp of one address word, matched with -all -inline
    #            (one flat pattern: capture groups cost 30 times more)
    #   tcpG     the G codes that switch TCP on (G49 switches it off)
    #   plane    {} or {G code tilt angles}: the G code of a block whose X
    #            Y Z I J K set a work plane (its origin and its angles in
    #            convention angles, see lib/plane.tcl; G69 ends it), and
    #            the G code that follows it (the tool along the plane's Z)
    #   methods  "" or the class mixed into the Checker whose method
    #            Translate returns a line of text as the ISO words read
    #            here (keywords read, lines of another syntax translated)
    #   plain    1: a line of words of the word pattern alone needs no
    #            Translate (the keywords are no such words)
    #   end      "" or a regexp of a line that ends the program (besides
    #            M2 and M30)
    #   endName  what end finds, in words ("" none)
    #   callComp 1: a tool call switches length compensation on (the dry
    #            run's lengthcomp)
    #   cutcom3d the words of the control's 3D tool-radius compensation
    #            (the path is the tip all the same), a dict of: drop (a
    #            regexp of the words removed before reading: keywords and
    #            normal), ijk (1: I J K in a linear block are its normal),
    #            codes (its G codes besides G40 G41 G42),
    #            block, normal, axis (Klartext: the keyword of its block,
    #            read as L, with the prefixes of the normal's words,
    #            skipped, and of the tool axis's, which then gives the axis
    #            in TCP mode while the rotaries are the control's)
    # G codes whose meaning the checker follows (with the reader's plane
    # codes); others are reported.
    variable KnownG {0 1 2 3 4 17 18 19 20 21 40 41 42 43 49 53 54 55 56 57 58 59 69
        70 71 73 76 80 81 82 83 84 85 86 87 88 89 90 93 94 98 99}
    # Canned cycles.
    variable CycleG {73 76 81 82 83 84 85 86 87 88 89}
    # Letters understood besides X Y Z and the rotaries (and R, Q in a
    # canned cycle).
    variable KnownLetters {N G F S T M H O P D}
    # Largest angle (deg) between a canned cycle's drilling direction and
    # the tool axis in the post's blocks (the written rotaries' rounding of
    # 0.001 deg passes, a tilted tool does not).
    variable drillTol 0.01
}

# ::fivax::verify::create --
#	Returns a new Checker object for machine (a fivax::machine dict);
#	options as in the Options table. Destroy it with "$checker destroy".
proc ::fivax::verify::create {machine args} {
    variable Options
    Checker new $machine [::fivax::opts::parse $Options $args "verify create"]
}

# ::fivax::verify::reader --
#	Returns a new Checker in this interpreter, as create does (a host may
#	route create to a check process: tools/lib/checkproc.tcl); the dry
#	run reads with it.
proc ::fivax::verify::reader {machine args} {
    variable Options
    Checker new $machine [::fivax::opts::parse $Options $args "verify reader"]
}

# ::fivax::verify::Number --
#	Returns the number of a word's text x, or "" when it is none; leading
#	zeros are decimal (N0080, G01), never Tcl's octal.
proc ::fivax::verify::Number {x} {
    if {[string match {0[0-9]*} $x] || [string match {[-+]0[0-9]*} $x]} {
        return [::fivax::num::parse $x]
    }
    if {[string is double -strict $x]} {return $x}
    return ""
}

# ::fivax::verify::RadiusCentre --
#	Returns the centre of an R-form arc from start to end in plane (17,
#	18, 19: normal +Z, +Y, +X) turning dir (2 clockwise, 3
#	counter-clockwise about the normal) with radius r (negative: more
#	than 180 degrees), as the controls define it; "" while the start is
#	unknown. The centre lies on the chord's bisector, r^2 - (c/2)^2 from
#	the chord's middle, left of the chord (seen along -n) for a short
#	counter-clockwise or a long clockwise arc.
proc ::fivax::verify::RadiusCentre {start end r plane dir} {
    if {"" in $start || "" in $end} {return ""}
    set n [dict get {17 {0 0 1} 18 {0 1 0} 19 {1 0 0}} $plane]
    set chord [::fivax::vec::sub $end $start]
    set half [expr {[::fivax::vec::norm $chord] / 2.0}]
    if {$half < 1e-12} {return ""}
    set left [::fivax::vec::unit [::fivax::vec::cross $n $chord]]
    set d [expr {sqrt(max(0.0, $r * $r - $half * $half))}]
    if {($dir == 3) != ($r > 0)} {set d [expr {-$d}]}
    ::fivax::vec::add [::fivax::vec::scale 0.5 [::fivax::vec::add $start $end]] \
        [::fivax::vec::scale $d $left]
}

# ::fivax::verify::LineRe --
#	Returns the regexp of a line of words of pattern re separated by
#	single spaces when re is one bracket expression then another one
#	repeated with + ({[A-Z][-+.0-9]+}), neither with a space (so that
#	such a line split at its spaces gives the words re finds); else "".
proc ::fivax::verify::LineRe {re} {
    if {![regexp {^\[[^]\\^[ ]+\]\[[^]\\^[ ]+\]\+$} $re]} {return ""}
    return "^${re}( ${re})*\$"
}

oo::class create ::fivax::verify::Checker {
    # S: machine, tableOffset, the dialect's comment skip word syntax tcpG
    # (its table entry), lineRe, plainText, pi, the tables CycleG KnownG
    # KnownLetters, rolling, rotaries (the chain's names), axis:NAME,
    # Xlo Xhi Ylo Yhi Zlo Zhi (the travel's bounds), model, the modal
    # state X Y Z q1 q2 motion (0/1) mode (direct/inverse) F, prev (the last checked
    # block) and the statistics (see summary).
    variable S

    constructor {machine opts} {
        set S(machine) $machine
        set S(tableOffset) [dict get $opts -table-offset]
        set name [dict get $opts -controller]
        if {$name eq ""} {set name [dict get $machine controller]}
        set dialect [::fivax::dialect reader $name -controller]
        foreach key {comment skip word tcpG end} {set S($key) [dict get $dialect $key]}
        if {[dict get $dialect methods] ne ""} {
            oo::objdefine [self] mixin [dict get $dialect methods]
        }
        set S(c3d) [dict merge {drop {} ijk 0 codes {} block {} normal {} axis {}} \
            [dict get $dialect cutcom3d]]
        set S(lineRe) [::fivax::verify::LineRe $S(word)]
        # a line of plain words holds no comment and no keyword: it needs
        # no reading but split
        set S(plainText) [expr {$S(lineRe) ne "" && [dict get $dialect plain]}]
        set S(pi) $::fivax::num::pi
        foreach key {CycleG KnownG KnownLetters} {set S($key) [set ::fivax::verify::$key]}
        lassign [dict get $dialect plane] S(planeG) - S(planeAngles)
        lappend S(KnownG) {*}[lrange [dict get $dialect plane] 0 1]
        lappend S(KnownG) {*}[dict get $S(c3d) codes]
        set chain [dict get $machine chain]
        set names [lmap axis $chain {dict get $axis name}]
        set S(tcpCodes) [dict get $machine tcp_codes]
        # rolling: the indices in a joint vector of the rotaries that roll over
        set S(rolling) {}
        foreach axis $chain i {3 4} {
            if {[dict get $axis rollover]} {lappend S(rolling) $i}
        }
        # axis:NAME -> {key lo hi}: the rotary's modal value (q1, q2) and
        # its bounds (radians: the limits widened by machine outside's slack)
        set S(rotaries) $names
        set bounds [dict get $machine bounds]
        foreach name $names key {q1 q2} {
            set S(axis:$name) [list $key {*}[dict get $bounds $name]]
        }
        # Xlo Xhi .. Zhi: the bounds of the machine's travel (as machine
        # outside takes them)
        foreach axis {X Y Z} {
            lassign [dict get $bounds $axis] S(${axis}lo) S(${axis}hi)
        }
        array set S {X {} Y {} Z {} q1 {} q2 {} motion {} mode direct F {} prev {}
            cycle 0 return 98 initial {} bottom {} R {} tcp 0 frame {} plane 17 cc {} toolAxis {}
            checked 0 segments 0 maxPos 0.0 maxAng 0.0 maxMidPos 0.0 maxMidAng 0.0
            limitViolations 0 worst {} worstMid {} lastMotion {} rapidsAfterCut 0}
        my setTool [dict get $machine tool_length]
    }

    # Switches the checker to a tool of length len (mm).
    method setTool {len} {
        set S(model) [::fivax::kin::model $S(machine) $len $S(tableOffset)]
        set S(prev) {}
    }

    # Returns the kin model in use.
    method model {} {
        return $S(model)
    }

    # Reads one NC line and updates the modal state. Returns a dict:
    #   block    1 when the line is a block (not %, O1000 or empty)
    #   motion   0 (G0), 1 (G1), 2 or 3 (G2/G3 arcs) or "" (no motion
    #            mode yet): modal
    #   moved    the axis names written in this block (X Y Z and rotaries)
    #   joints   {X Y Z q1 q2} (rotaries in radians, chain order) after
    #            the block, or "" while an axis is unknown (in a work
    #            plane the rotaries are the control's: always "")
    #   pose     {P t}: the tip and unit tool axis in the workpiece frame
    #            after the block, or "" while unknown
    #   space    joint, tcp or plane: what X Y Z are (see the file header)
    #   arc      for an arc block, {start centre plane dir} in the space's
    #            coordinates (dir 2 clockwise, 3 counter-clockwise about
    #            the normal of plane 17, 18 or 19); else ""
    #   mode     direct (G94) or inverse (G93): modal
    #   F        the F word of this block ("" if none); feed: modal F
    #   words    the words of the block, {letter value} pairs
    #   comments the comment texts
    #   limit    the rotary names whose written value is outside limits
    #   unknown  {kind word} pairs: words the checker does not follow
    #            (kind: "letter E", "G2", "text")
    #   hole     1 when the block drills a hole of a canned cycle: joints
    #            are then at the hole's bottom, and the modal Z afterwards
    #            is the level the cycle returns to
    #   end      1 when the line ends the program (M2, M30, the reader's end)
    method read {line} {
        lassign [my Read $line 1] joints pose space limit arc hole block moved F pairs comments unknown
        set end [expr {$S(end) ne "" && [regexp -- $S(end) $line]}]
        foreach {letter value} $pairs {
            if {$letter eq "M" && ($value == 2 || $value == 30)} {set end 1}
        }
        dict create block $block motion $S(motion) moved $moved joints $joints pose $pose \
            space $space arc $arc mode $S(mode) F $F feed $S(F) words $pairs \
            comments $comments limit $limit unknown $unknown hole $hole end $end
    }

    # Reads one NC line as read does (see there) and returns the values of
    # its dict as a list: joints pose space limit arc hole block moved F
    # words comments unknown (the post's check takes the first six, and
    # words are gathered only when wantPairs is 1). Three phases: the
    # line's words (Words), the modal state they change (GModes, then
    # each word), the block's results (Arc, the hole's end state).
    method Read {line wantPairs} {
        lassign [my Words $line] skip words comments unknown
        if {$skip} {
            return [list {*}[my State] {} {} 0 0 {} "" {} $comments {}]
        }
        lassign [my GModes $words] machineFrame planeSet dwell
        if {$planeSet} {
            my PlaneWords $words
            return [list {*}[my State] {} {} 0 1 {} "" {} $comments {}]
        }
        set pairs {}
        set moved {}
        set limit {}
        set F ""
        set hole 0
        set start [list $S(X) $S(Y) $S(Z)]
        set ijk {I 0.0 J 0.0 K 0.0}
        set radius ""
        set centreGiven 0
        set arcMode [expr {$S(motion) in {2 3}}]
        set cycle $S(cycle)
        foreach word $words {
            set letter [string index $word 0]
            set x [::fivax::verify::Number [string range $word 1 end]]
            if {$x eq ""} {
                lappend unknown text $word
                continue
            }
            if {$wantPairs} {lappend pairs $letter $x}
            # the letters with a meaning of their own first (their order
            # decides where a rotary's name is also one of them)
            switch -exact -- $letter {
                X - Y - Z {
                    if {$machineFrame} {
                        set S($letter) ""
                    } elseif {$cycle && $letter eq "Z"} {
                        # in a canned cycle Z is the hole's bottom
                        set S(bottom) $x
                    } else {
                        set S($letter) $x
                    }
                    if {$cycle} {set hole 1}
                    lappend moved $letter
                    continue
                }
                R {
                    if {$cycle} {
                        set S(R) $x
                        set hole 1
                        continue
                    }
                    if {$arcMode} {
                        set radius $x
                        set centreGiven 1
                        continue
                    }
                }
                Q {
                    # the peck depth: the hole ends at its bottom all the same
                    if {$cycle} continue
                }
                I - J - K {
                    if {$arcMode} {
                        dict set ijk $letter $x
                        set centreGiven 1
                        continue
                    }
                    # (a 3D cutter compensation's normal: the path is the tip)
                    if {[dict get $S(c3d) ijk]} continue
                }
            }
            if {$letter in $S(rotaries)} {
                if {[my Rotary $letter $x]} {lappend limit $letter}
                lappend moved $letter
                continue
            }
            switch -exact -- $letter {
                G {
                    lappend unknown {*}[my GWord $x $word]
                    set arcMode [expr {$S(motion) in {2 3}}]
                }
                F {
                    # (G4 F: a dwell time in seconds, no feed)
                    if {!$dwell} {
                        set S(F) $x
                        set F $x
                    }
                }
                M {
                    if {[llength $S(tcpCodes)]
                            && [set k [lsearch -exact $S(tcpCodes) [expr {int($x)}]]] >= 0} {
                        set S(tcp) [expr {$k == 0}]
                    }
                }
                default {
                    if {$letter ni $S(KnownLetters)} {
                        lappend unknown "letter $letter" $word
                    }
                }
            }
        }
        set arc {}
        if {$arcMode && [llength $moved]} {
            if {!$centreGiven} {lappend unknown "arc without I J K or R" G$S(motion)}
            set arc [my Arc $start $radius $ijk]
        }
        if {$hole} {
            set z $S(Z)
            set S(Z) $S(bottom)
            set state [my State]
            # back to the initial level (G98) or the R plane (G99)
            set S(Z) [expr {$S(return) == 99 ? $S(R) : $z}]
        } else {
            set state [my State]
        }
        list {*}$state $limit $arc $hole 1 $moved $F $pairs $comments $unknown
    }

    # Returns {skip words comments unknown} of NC line: skip 1 for a line
    # that is no block (the reader's skip, nothing but comments), its
    # words (the text split, after the controller's Translate and with
    # its comments removed), the comment texts, and {text rest} in
    # unknown for text that is no word.
    method Words {line} {
        set comments {}
        if {$S(plainText) && [regexp -- $S(lineRe) $line]} {
            # plain words (every ISO block fivax writes): no comment, no keyword
            set skip [expr {[string first " " $line] < 0 && [regexp -- $S(skip) $line]}]
            return [list $skip [split $line " "] {} {}]
        }
        set text $line
        if {[dict get $S(c3d) drop] ne ""} {regsub -all -- [dict get $S(c3d) drop] $text "" text}
        set text [my Translate $text]
        if {[string first ( $text] >= 0 || [string first ";" $text] >= 0} {
            foreach {- a b} [regexp -all -inline -- $S(comment) $text] {
                lappend comments [expr {$a ne "" ? $a : $b}]
            }
            regsub -all -- $S(comment) $text "" text
        }
        # a line of plain words is split at its spaces
        set plain [expr {$S(lineRe) ne "" && [regexp -- $S(lineRe) $text]}]
        set skip [expr {(!$plain && [string trim $text] eq "") || [regexp -- $S(skip) $line]}]
        if {$plain} {return [list $skip [split $text " "] $comments {}]}
        set unknown {}
        set rest [string trim [regsub -all -- $S(word) $text ""]]
        if {$rest ne ""} {lappend unknown text $rest}
        list $skip [regexp -all -inline -- $S(word) $text] $comments $unknown
    }

    # Returns {machineFrame planeSet dwell} of a block's words: its G codes
    # first (they decide what the axis words mean; most blocks have
    # none): G53 (machine coordinates), the reader's plane G code, G4;
    # canned cycles start (the initial level kept), G98/G99 set the
    # return level, a motion code or G80 ends a cycle.
    method GModes {words} {
        set machineFrame 0
        set planeSet 0
        set dwell 0
        foreach word [lsearch -all -inline -glob $words G*] {
            set value [::fivax::verify::Number [string range $word 1 end]]
            if {$value eq ""} continue
            set g [expr {$value == round($value) ? int($value) : $value}]
            if {$g in $S(CycleG)} {
                if {!$S(cycle)} {
                    set S(initial) $S(Z)
                    set S(bottom) $S(Z)
                }
                set S(cycle) 1
            } elseif {$g in {98 99}} {
                set S(return) $g
            } elseif {$g in {0 1 2 3 80}} {
                set S(cycle) 0
            } elseif {$g == 53} {
                set machineFrame 1
            } elseif {$g == $S(planeG)} {
                set planeSet 1
            } elseif {$g == 4} {
                set dwell 1
            }
        }
        list $machineFrame $planeSet $dwell
    }

    # Sets rotary letter to x (deg, kept in radians); returns 1 when the
    # value is outside its limits (counted).
    method Rotary {letter x} {
        lassign $S(axis:$letter) key lo hi
        # the value in radians (num rad, written out) against the limits
        set q [expr {$x * $S(pi) / 180.0}]
        set S($key) $q
        if {$q < $lo || $q > $hi} {
            incr S(limitViolations)
            return 1
        }
        return 0
    }

    # Follows the G code x (the word word) in the modal state: motion,
    # plane, TCP, frame and feed mode; returns {G<x> word} for a G code
    # the checker does not follow, else {}.
    method GWord {x word} {
        set g [expr {$x == round($x) ? int($x) : $x}]
        switch -exact -- $g {
            0 {set S(motion) 0}
            1 {set S(motion) 1}
            2 - 3 {set S(motion) $g}
            17 - 18 - 19 {set S(plane) $g}
            49 {set S(tcp) 0}
            69 {set S(frame) {}}
            93 {set S(mode) inverse}
            94 {set S(mode) direct}
            default {
                if {[lsearch -exact -real $S(tcpG) $g] >= 0} {
                    set S(tcp) 1
                } elseif {$g ni $S(KnownG)} {
                    return [list G$g $word]
                }
            }
        }
        return {}
    }

    # Returns the arc {start centre plane dir} of an arc block from start
    # (the modal X Y Z before it) to the modal X Y Z: the centre by the
    # radius (not "") or the start plus ijk (I J K offsets).
    method Arc {start radius ijk} {
        if {$radius ne ""} {
            set centre [::fivax::verify::RadiusCentre $start [list $S(X) $S(Y) $S(Z)] \
                $radius $S(plane) $S(motion)]
        } else {
            # the centre from the start by I J K (incremental)
            set centre [lmap c $start d [dict values $ijk] {
                expr {$c eq "" ? "" : $c + $d}
            }]
        }
        list $start $centre $S(plane) $S(motion)
    }

    # Reads a block of the reader's plane G code (words): the work plane's
    # origin X Y Z and its angles I J K (in the reader's convention). X Y
    # Z are forgotten (the next ones are in the plane).
    method PlaneWords {words} {
        set v {X 0.0 Y 0.0 Z 0.0 I 0.0 J 0.0 K 0.0}
        foreach word $words {
            set letter [string index $word 0]
            set value [::fivax::verify::Number [string range $word 1 end]]
            if {[dict exists $v $letter] && $value ne ""} {
                dict set v $letter $value
            }
        }
        my SetFrame $S(planeAngles) [list [dict get $v I] [dict get $v J] [dict get $v K]] \
            [list [dict get $v X] [dict get $v Y] [dict get $v Z]]
    }

    # Sets the work plane of angles (deg) in convention at origin; the
    # written X Y Z and the rotaries are forgotten (the control turns
    # them).
    method SetFrame {convention angles origin} {
        set S(frame) [list [::fivax::plane::matrix $convention $angles] $origin]
        foreach key {X Y Z q1 q2} {set S($key) ""}
    }

    # Returns the line as the ISO words read (a controller's reader class
    # reads its keywords here): as it is.
    method Translate {line} {
        return $line
    }

    # Ends the work plane: the rotaries are forgotten (the control turns
    # them back).
    method EndFrame {} {
        set S(frame) {}
        foreach key {q1 q2} {set S($key) ""}
    }

    # Sets the TCP mode: on 1 or 0.
    method SetTcp {on} {
        set S(tcp) $on
    }

    # Returns {P t}: the tip and axis in the workpiece frame of the point
    # xyz of the current space with the current rotaries (the inside of an
    # arc), or "" while they are unknown.
    method poseAt {xyz} {
        set saved [list $S(X) $S(Y) $S(Z)]
        lassign $xyz S(X) S(Y) S(Z)
        try {
            return [lindex [my State] 1]
        } finally {
            lassign $saved S(X) S(Y) S(Z)
        }
    }

    # Returns {joints pose space} of the modal X Y Z and rotaries: the
    # joint vector {X Y Z q1 q2} (in TCP mode the machine X Y Z that put
    # the tip on the written X Y Z; always "" in a work plane, whose
    # rotaries are the control's), the pose {P t} (tip and axis in the
    # workpiece frame) and what X Y Z are (plane, tcp or joint); joints
    # and pose are "" while an axis they need is unknown.
    method State {} {
        set joints [list $S(X) $S(Y) $S(Z) $S(q1) $S(q2)]
        if {$S(frame) ne ""} {
            set xyz [lrange $joints 0 2]
            if {"" in $xyz} {return {{} {} plane}}
            lassign $S(frame) R O
            return [list "" [list [::fivax::plane::fromPlane $R $O $xyz] \
                [lmap row $R {lindex $row 2}]] plane]
        }
        if {"" in $joints} {
            if {$S(tcp) && $S(toolAxis) ne "" && "" ni [lrange $joints 0 2]} {
                # (after a Klartext LN block the control's rotaries hold
                # the tool axis it gave)
                return [list "" [list [lrange $joints 0 2] $S(toolAxis)] tcp]
            }
            return [list "" "" [expr {$S(tcp) ? "tcp" : "joint"}]]
        }
        if {!$S(tcp)} {
            return [list $joints [::fivax::kin::forward $S(model) $joints] joint]
        }
        set xyz [lrange $joints 0 2]
        set q [lrange $joints 3 4]
        set t [lindex [::fivax::kin::forward $S(model) [list 0.0 0.0 0.0 {*}$q]] 1]
        list [concat [::fivax::kin::position $S(model) $xyz $q] $q] [list $xyz $t] tcp
    }

    # Returns the tool axis of the work plane in effect (its Z in the
    # workpiece frame), or "" outside a work plane.
    method planeAxis {} {
        if {$S(frame) eq ""} {return ""}
        lmap row [lindex $S(frame) 0] {lindex $row 2}
    }

    # Returns {R bottom return}: the R plane, the bottom and the level the
    # tool returns to of the last canned-cycle hole read, as Z values of
    # its space (the cycle drills along that Z).
    method cycleLevels {} {
        list $S(R) $S(bottom) $S(Z)
    }

    # Returns {P t}: tool tip and axis (workpiece frame) at joints.
    method tip {joints} {
        ::fivax::kin::forward $S(model) $joints
    }

    # Returns {dp da}: the distance (mm) and angle (deg) of the tool tip and
    # axis at joints from tip P and unit axis t.
    method deviation {joints P t} {
        lassign [::fivax::kin::forward $S(model) $joints] Pm tm
        list [::fivax::vec::dist $Pm $P] \
            [::fivax::num::deg [::fivax::vec::angle $tm $t]]
    }

    # Returns {dp da}: the largest distance (mm) of the tool tip from the
    # segment P0-P1 and angle (deg) of the axis from the great circle
    # t0-t1 at the quarter points of the controller's linear joint
    # interpolation from j0 to j1; a rotary that rolls over turns the
    # shortest way.
    method interior {j0 j1 P0 P1 t0 t1} {
        if {$S(rolling) ne ""} {set j1 [my Rolled $j0 $j1]}
        lassign [::fivax::kin::interpolationError $S(model) $j0 $j1 $P0 $P1 $t0 $t1] dp da
        list $dp [::fivax::num::deg $da]
    }

    # Returns joints j1 with each rotary that rolls over moved to the
    # value nearest its value in j0 (the way the controller turns it).
    method Rolled {j0 j1} {
        foreach i $S(rolling) {
            set a [lindex $j0 $i]
            set d [expr {[lindex $j1 $i] - $a}]
            lset j1 $i [expr {$a + $d - 2.0 * $S(pi) * round($d / (2.0 * $S(pi)))}]
        }
        return $j1
    }

    # Returns the angle (deg) between the tool axis t and the direction
    # a canned cycle's hole (read as joints and pose {P t} in space) is
    # drilled along when it exceeds drillTol, else "": the control feeds
    # along the Z of the space, which in joint space moves the tip by
    # forward kinematics of a unit Z joint move, in TCP space along the
    # workpiece Z (a work plane's Z is the tool axis: always "").
    method drillOff {joints pose space} {
        lassign $pose P t
        switch -- $space {
            plane {return ""}
            tcp {set along {0.0 0.0 1.0}}
            joint {
                lassign $joints x y z q1 q2
                set along [::fivax::vec::sub \
                    [lindex [::fivax::kin::forward $S(model) [list $x $y [expr {$z + 1.0}] $q1 $q2]] 0] $P]
            }
        }
        set off [::fivax::num::deg [::fivax::vec::angle $along $t]]
        expr {$off <= $::fivax::verify::drillTol ? "" : $off}
    }

    # Raises {FIVAX VERIFY DRILL} with the move's FILE:LINE when a canned
    # cycle's hole (read as joints and pose {P t} in space) is not drilled
    # along the tool axis (drillOff).
    method CheckDrill {joints pose space line move} {
        set off [my drillOff $joints $pose $space]
        if {$off eq ""} return
        set where [dict get $move src]
        if {$where eq ""} {set where "NC block '$line'"}
        ::fivax::Fail VERIFY DRILL [format "%s: the canned cycle drills along Z with the\
            tool axis %.3f deg off it" $where $off]
    }

    # Reads the NC line (the post's own block), refuses it with the
    # move's FILE:LINE when it leaves the machine's travel or a rotary's
    # limits (machine checkLimits) or, in a canned cycle, drills off the
    # tool axis (CheckDrill), and, when move (a motion move record)
    # carries a CL target (P, t), measures the deviation of the block's
    # pose at its end and, for joint-space cutting moves (the
    # control interpolates the joints linearly), inside the block. In TCP
    # mode and in a work plane the control keeps the tip on the line (or
    # arc) itself: the end is what is checked. Inside the block the
    # quarter points are measured unless kin interpolationBound, from the
    # same written values and the errors at both ends, proves that they
    # cannot exceed the largest deviation found so far (which is all the
    # summary keeps).
    method block {line move} {
        lassign [my Read $line 0] joints pose space limit arc hole - moved
        my countRapid $pose $moved $hole
        # the machine X Y Z (when known) and the rotaries read outside
        # their limits (the usual block, within the travel's bounds and
        # the rotaries' limits, needs no machine checkLimits)
        lassign $joints x y z
        if {$limit ne "" || ($joints ne "" && !($x >= $S(Xlo) && $x <= $S(Xhi)
                && $y >= $S(Ylo) && $y <= $S(Yhi) && $z >= $S(Zlo) && $z <= $S(Zhi)))} {
            set values [expr {$joints eq "" ? {} : [list X $x Y $y Z $z]}]
            foreach axis $limit {
                dict set values $axis $S([lindex $S(axis:$axis) 0])
            }
            set where [dict get $move src]
            if {$where eq ""} {set where "NC block '$line'"}
            ::fivax::machine::checkLimits $S(machine) $values $where
        }
        if {$hole && $pose ne ""} {my CheckDrill $joints $pose $space $line $move}
        set P [dict get $move P]
        if {$P eq "" || $pose eq ""} {
            if {$P eq ""} {set S(prev) {}}
            return
        }
        set t [dict get $move t]
        lassign $pose Pm tm
        set dp [::fivax::vec::dist $Pm $P]
        set angle [::fivax::vec::angle $tm $t]
        # in degrees (num deg, written out)
        set da [expr {$angle * 180.0 / $S(pi)}]
        incr S(checked)
        if {$dp > $S(maxPos)} {set S(maxPos) $dp; set S(worst) [dict get $move src]}
        if {$da > $S(maxAng)} {set S(maxAng) $da}
        if {$space ne "joint" || $arc ne ""} {
            set S(prev) {}
            return
        }
        # the axis error as a chord (at most the angle), with a rounding margin
        set ea [expr {$angle + 1e-12}]
        if {[dict get $move kind] eq "feed" && $S(prev) ne ""} {
            lassign $S(prev) j0 P0 t0 ep0 ea0
            incr S(segments)
            set j1 $joints
            if {$S(rolling) ne ""} {set j1 [my Rolled $j0 $joints]}
            lassign [::fivax::kin::interpolationBound $S(model) $j0 $j1 $P0 $P $t0 $t \
                [expr {$ep0 > $dp ? $ep0 : $dp}] [expr {$ea0 > $ea ? $ea0 : $ea}]] bp ba
            if {$bp > $S(maxMidPos) || $ba * 180.0 / $S(pi) > $S(maxMidAng)} {
                lassign [my interior $j0 $joints $P0 $P $t0 $t] dp2 da2
                if {$dp2 > $S(maxMidPos)} {set S(maxMidPos) $dp2; set S(worstMid) [dict get $move src]}
                if {$da2 > $S(maxMidAng)} {set S(maxMidAng) $da2}
            }
        }
        set S(prev) [list $joints $P $t $dp $ea]
    }

    # Counts the block just read (its pose, moved axes and hole, see read)
    # when it is a rapid after cutting: a G0 block moving an axis right
    # after a cutting block (G1 G2 G3; a canned cycle's hole is none).
    # Blocks that move no axis or end at an unknown pose neither count nor
    # end the run. The post's check and tools/verify.tcl both count so.
    # Returns 1 when counted.
    method countRapid {pose moved hole} {
        if {$pose eq "" || ![llength $moved]} {return 0}
        set counted [expr {$S(motion) eq "0" && $S(lastMotion) in {1 2 3}}]
        incr S(rapidsAfterCut) $counted
        set S(lastMotion) [expr {$hole ? 0 : $S(motion)}]
        return $counted
    }

    # Returns a dict: checked (CL points), segments, maxPos (mm), maxAng
    # (deg) at the CL points, maxMidPos (mm), maxMidAng (deg) inside
    # cutting moves, limitViolations, worst and worstMid (FILE:LINE of the
    # largest errors), rapidsAfterCut (see countRapid).
    method summary {} {
        dict create checked $S(checked) segments $S(segments) maxPos $S(maxPos) \
            maxAng $S(maxAng) maxMidPos $S(maxMidPos) maxMidAng $S(maxMidAng) \
            limitViolations $S(limitViolations) worst $S(worst) worstMid $S(worstMid) \
            rapidsAfterCut $S(rapidsAfterCut)
    }
}
