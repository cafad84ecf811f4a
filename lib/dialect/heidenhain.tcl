# heidenhain.tcl --
#	Heidenhain Klartext (iTNC 530 / TNC 640): no G codes, every line
#	numbered from 0, L / CC / C blocks with signed words, TOOL CALL, M91
#	machine Z, no inverse time, TCP FUNCTION TCPM / FUNCTION RESET TCPM,
#	work plane PLANE SPATIAL / PLANE RESET STAY, dwell cycle 9, drill
#	cycles expanded into moves, end M30 and END PGM. Spec dialects.md
#	section 3. Writer keys: lib/output.tcl (Dialects); reader keys:
#	lib/verify.tcl.
#	3D tool compensation (-cutcom3d control): Heidenhain TNC 640 User's
#	Manual Conversational Programming (34059x-01), 11.6 "Three-Dimensional
#	Tool Compensation (Software Option 2)" (iTNC 530: 12.6; TNC 620
#	81760x: 12.6, option 9), "Block format with surface-normal vectors
#	and tool orientation": LN X Y Z NX NY NZ TX TY TZ F, with M128 or
#	FUNCTION TCPM active; NX NY NZ the components of the surface-normal
#	vector, TX TY TZ of the normalised tool orientation, written as the
#	manual's examples with 7 decimals (coarse normals make the control
#	slow down). The rotary positions are the control's (from TX TY TZ):
#	an LN block writes none, the next L block all of them. The control
#	offsets by the tool table's delta values DL, DR, DR2 along the normal.

namespace eval ::fivax::dialect::heidenhain {}

# The writer's forms of this control (mixed into ::fivax::output::Writer):
# a tool change is a TOOL CALL that waits for its spindle speed (or the
# first move), moves are L (FMAX or F) and CC / C lines with the radius
# word RL / RR / R0, M codes go in L lines.
oo::class create ::fivax::dialect::heidenhain::Writer {
    variable S

    # Returns the program-start lines: BEGIN PGM name unit, the comment,
    # the resets (see Resets).
    method start {comment {name PART}} {
        set S(program) [regsub -all {[^A-Za-z0-9_]} $name _]
        if {$S(program) eq ""} {set S(program) PART}
        concat [list [$S(nc) line "BEGIN PGM $S(program) [my Unit]"] [my comment $comment]] \
            [my Resets]
    }

    # Returns the last lines: the M words off in an L line, L M30, END PGM.
    method EndLines {off end} {
        concat [my MLine $off] [list [$S(nc) line "L $end"] \
            [$S(nc) line "END PGM $S(program) [my Unit]"]]
    }

    # Defers the change of tool number to its TOOL CALL (see ToolCall,
    # spindle): no lines now.
    method ChangeTool {number} {
        set S(pendingTool) $number
        return {}
    }

    # Returns the length register: none (TOOL CALL compensates).
    method Register {adjust} {
        return 0
    }

    # Returns the waiting TOOL CALL (without a speed), or nothing.
    method ToolCall {} {
        if {$S(pendingTool) eq ""} {return {}}
        set line [$S(nc) line "TOOL CALL $S(pendingTool) Z"]
        set S(pendingTool) ""
        list $line
    }

    # Returns the L line of a Z move to z in machine coordinates (M91).
    method MachineZ {z off} {
        $S(nc) force once KZ
        list [$S(nc) block [list KZ $z] 1 {"L " " R0 FMAX M91"}]
    }

    # Returns the rapid L line that turns both rotaries home (see Home).
    method HomeRotaries {} {
        set home [my Home]
        $S(nc) force once [dict keys $home]
        list [$S(nc) block $home 1 {"L " " R0 FMAX"}]
    }

    # Returns the spindle-on lines: the waiting TOOL CALL with S, or
    # TOOL CALL Z S, then M3 / M4.
    method spindle {speed direction} {
        set m [my Code spindle_direction_code([expr {$direction eq "CCLW" ? "CCLW" : "CLW"}])]
        # the S of TOOL CALL is text: the .def's MIN/MAX of S bound it here
        set speed [expr {round([$S(nc) limit S [expr {round($speed)}]])}]
        set call [expr {$S(pendingTool) ne "" ? "TOOL CALL $S(pendingTool) Z" : "TOOL CALL Z"}]
        set S(pendingTool) ""
        concat [list [$S(nc) line "$call S$speed"]] [my MLine [list M_spindle $m]]
    }

    # Returns the spindle-off line.
    method spindleOff {} {
        my MLine [list M_spindle [my Code spindle_direction_code(OFF)]]
    }

    # Returns the coolant-on line for mode (MIST: M7, else M8).
    method coolant {mode} {
        my MLine [list M_coolant [my Code coolant_code([expr {$mode eq "MIST" ? "MIST" : "ON"}])]]
    }

    # Returns the coolant-off line.
    method coolantOff {} {
        my MLine [list M_coolant [my Code coolant_code(OFF)]]
    }

    # Returns the program stop line (optional: L M1, else STOP).
    method stop {optional} {
        list [$S(nc) line [expr {$optional ? "L M[my Code optional_stop_code]" : "STOP"}]]
    }

    # Returns the dwell cycle 9 lines for seconds.
    method dwell {seconds} {
        # the time is text: bounded by the MIN/MAX of the seconds address P_s
        list [$S(nc) line "CYCL DEF 9.0 DWELL TIME"] \
            [$S(nc) line "CYCL DEF 9.1 DWELL [::fivax::num::fixed [$S(nc) limit P_s $seconds] 3]"]
    }

    # Returns the L line of the straight move record rec: the changed
    # axes, the radius word, and FMAX or F (mm/min; a feed block after a
    # rapid states F again); the waiting TOOL CALL first.
    method Motion {rec isFeed} {
        set lines [my ToolCall]
        if {[dict exists $rec normal]} {return [concat $lines [my Cutcom3dBlock $rec]]}
        set S(c3dOn) 0
        set words [::fivax::output::AxisWords {} $rec $S(xyzAddr) $S(rotAddr)]
        set radius [my Radius [my CutcomStep $rec $isFeed]]
        if {$isFeed} {
            if {$S(feedMode) ne "feed"} {$S(nc) force once KF}
            set S(feedMode) feed
            set tail [string trimright "$radius [$S(nc) block [list KF [dict get $rec rate]] 0]"]
        } else {
            set S(feedMode) rapid
            set tail "$radius FMAX"
        }
        lappend lines [$S(nc) block $words 1 [list "L " " $tail"]]
    }

    # Returns the 3D compensation's block of move record rec with a
    # normal: LN with X Y Z, the normal and tool axis words (see the
    # writer table's cutcom3d), F.
    method Cutcom3dBlock {rec} {
        set form [dict get $S(dialect) cutcom3d]
        set S(c3dOn) 1
        set S(atSafe) 0
        $S(nc) force once {KX KY KZ}
        if {![dict get $form rotaries]} {
            dict set rec write {X Y Z}
            # (the control turns the rotaries: the next L block writes them)
            $S(nc) reset [lmap {- addr -} $S(rotAddr) {set addr}]
        }
        set words [::fivax::output::AxisWords {} $rec $S(xyzAddr) $S(rotAddr)]
        lappend words {*}[my Cutcom3dWords $rec]
        if {$S(feedMode) ne "feed"} {$S(nc) force once KF}
        set S(feedMode) feed
        lappend words KF [dict get $rec rate]
        list [$S(nc) block $words 1 [list "[dict get $form block] " ""]]
    }


    # Returns the lines of arc record rec: CC (the centre) and C (the end,
    # DR- clockwise / DR+, the radius word, F).
    method ArcLines {rec} {
        lassign [dict get $rec center] cx cy
        set lines [list [$S(nc) line "CC [$S(nc) block [list KCX $cx KCY $cy] 0]"]]
        if {$S(feedMode) ne "feed"} {$S(nc) force once KF}
        set S(feedMode) feed
        $S(nc) force once {KX KY}
        set xy [$S(nc) block [list KX [dict get $rec axes X] KY [dict get $rec axes Y]] 0]
        set words [list C $xy DR[expr {[dict get $rec dir] == 2 ? "-" : "+"}] \
            [my Radius $S(cutcomOn)] [$S(nc) block [list KF [dict get $rec rate]] 0]]
        lappend lines [$S(nc) line [join [lsearch -all -inline -not -exact $words ""]]]
    }

    # Returns the work plane's line: PLANE SPATIAL SPA SPB SPC (angles)
    # TURN MB MAX FMAX and the direction SEQ of rec's seq.
    method PlaneLines {angles rec} {
        lassign $angles a b c
        list [$S(nc) line "PLANE SPATIAL [$S(nc) block [list SPA $a SPB $b SPC $c] 0] TURN MB MAX FMAX SEQ[expr {[dict get $rec seq] < 0 ? "-" : "+"}]"]
    }

    # Returns the line that ends the work plane: PLANE RESET STAY.
    method PlaneOffLines {} {
        list [$S(nc) line "PLANE RESET STAY"]
    }

    # Returns the radius word of side: RL, RR or R0.
    method Radius {side} {
        dict get {LEFT RL RIGHT RR {} R0} $side
    }

    # Returns the line "L M.." of the M words (through the modal memory:
    # nothing when they are in effect already).
    method MLine {words} {
        set text [$S(nc) block $words 0]
        if {$text eq ""} {return {}}
        # (the tool comes first: M8 before its TOOL CALL would run the
        # coolant through the tool change)
        set lines [my ToolCall]
        lappend lines [$S(nc) line "L $text"]
    }
}

::fivax::dialect::define heidenhain {
    default 0
    syntax klartext program {} percent 0 comment numbered semicolon 1
    safety {} reset {{FUNCTION RESET TCPM} {PLANE RESET STAY}} units {MM INCH}
    methods ::fivax::dialect::heidenhain::Writer inverse 0
    tcp {on {{FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS}} off {{FUNCTION RESET TCPM}}}
    plane spatial arcs {planes {17} helix 0}
    dwell {}
    cycles {}
    letters {}
    active {}
    ends {{2 30} {{\mEND\s+PGM\M}}}
    cutcom R
    form {first {^0 BEGIN PGM } close {^\d+ END PGM } start {BEGIN PGM}
        end {\mM(30|0?2)\M} dwell {CYCL DEF 9\.} free {PLANE SPATIAL|TCPM}}
    words {{TOOL CALL} {CYCL DEF} {PLANE SPATIAL} {PLANE RESET} TCPM {BEGIN PGM} {END PGM}
        FMAX M91 heidenhain Heidenhain}
    cutcom3d {block LN code {} register {} words {} normal {NX NY NZ} axis {TX TY TZ}
        sign 1 format %+.7f rotaries 0}
} {
    comment {;(.*)$}
    skip {^\s*$}
    word {[A-Z][-+.0-9]+}
    tcpG {43.4}
    plane {}
    methods ::fivax::dialect::heidenhain::Reader
    plain 0
    end {^\s*(\d+\s+)?END PGM\M} endName {END PGM}
    callComp 1
    cutcom3d {block LN normal {NX NY NZ} axis {TX TY TZ}}
}

# The reader's forms of this control (mixed into ::fivax::verify::Checker).
oo::class create ::fivax::dialect::heidenhain::Reader {
    variable S

    # Returns the tokens of a 3D-compensation block (LN, read as L) but
    # those of the normal and the tool axis; sets the tool axis, which
    # stands for the rotaries (the control's: unknown) in TCP mode.
    method Cutcom3dTokens {tokens} {
        set axis {}
        set rest {}
        foreach tok $tokens {
            regexp {^([A-Z]+)(.*)$} $tok -> prefix value
            if {$prefix in [dict get $S(c3d) axis]} {
                lappend axis [::fivax::verify::Number $value]
            } elseif {$prefix ni [dict get $S(c3d) normal]} {
                lappend rest $tok
            }
        }
        if {[llength $axis] == 3 && "" ni $axis} {
            set S(toolAxis) [::fivax::vec::unit $axis]
            set S(q1) ""
            set S(q2) ""
        }
        return $rest
    }

    # Returns the Klartext line as the ISO words the reader follows: L
    # (FMAX: G0, else G1, M91: G53, R0 left out), C with DR-/DR+ (G2/G3,
    # the centre from the last CC as I J), TOOL CALL (T M6, S), FUNCTION
    # TCPM (the reader's tcpG) and FUNCTION RESET TCPM (G49), STOP (M0), LN
    # (the 3D compensation's block: an L whose normal and tool axis are
    # read by Cutcom3dTokens), BEGIN PGM's
    # units (G21 MM, G20 INCH); CC, PLANE SPATIAL and PLANE RESET set the
    # state and give no block; END PGM and cycle 9 are no blocks (read
    # tells the program's end); a comment "; text" stays one.
    method Translate {line} {
        if {[regexp {^\d+ L(?: \S+)*$} $line]} {
            # numbered, single spaces (every L line fivax writes): the
            # tokens are split at the spaces, as the general way finds them
            set tokens [lrange [split $line " "] 2 end]
        } else {
            set body [string trim $line]
            regexp {^\d+\s+(.*)$} $body -> body
            if {[regexp {^L(\s.*)?$} $body -> rest]} {
                set tokens [regexp -all -inline {\S+} $rest]
            } elseif {[dict get $S(c3d) block] ne ""
                    && [regexp {^(\S+)\s+(.*)$} $body -> keyword rest]
                    && $keyword eq [dict get $S(c3d) block]} {
                set tokens [my Cutcom3dTokens [regexp -all -inline {\S+} $rest]]
            }
        }
        if {[info exists tokens]} {
            # (an L line is a straight move: FMAX makes it rapid for this
            # block only, else it feeds at the modal F)
            set iso [expr {"FMAX" in $tokens ? {} : {G1}}]
            foreach tok $tokens {
                if {$tok eq "FMAX"} {
                    set iso [linsert $iso 0 G0]
                } elseif {$tok in {R0 RL RR}} {
                } elseif {$tok eq "M91"} {
                    set iso [linsert $iso 0 G0 G53]
                } elseif {[string match F* $tok] && [regexp {^F[0-9.]+$} $tok]} {
                    lappend iso $tok
                } else {
                    lappend iso $tok
                }
            }
            return [join $iso]
        }
        set pl {[-+]?[0-9.]+}
        if {[regexp {^BEGIN PGM\s+\S+\s+(MM|INCH)\s*$} $body -> units]} {
            return [dict get {MM G21 INCH G20} $units]
        }
        if {[regexp {^;} $body] || [regexp {^(BEGIN|END) PGM\M} $body]
                || [regexp {^CYCL DEF 9\.} $body]} {
            return [expr {[string index $body 0] eq ";" ? $body : ""}]
        }
        if {[regexp "^CC\\s+(.*)$" $body -> rest]} {
            foreach tok [regexp -all -inline {\S+} $rest] {
                if {[regexp "^(\[XYZ\])($pl)$" $tok -> axis value]} {dict set S(cc) $axis $value}
            }
            return ""
        }
        if {[regexp {^C\s+(.*)$} $body -> rest]} {
            set iso {}
            foreach tok [regexp -all -inline {\S+} $rest] {
                if {$tok in {DR- DR+}} {
                    set iso [linsert $iso 0 G17 [expr {$tok eq "DR-" ? "G2" : "G3"}]]
                } elseif {$tok ni {R0 RL RR}} {
                    lappend iso $tok
                }
            }
            foreach {axis letter} {X I Y J} {
                if {[dict exists $S(cc) $axis] && $S($axis) ne ""} {
                    lappend iso $letter[expr {[dict get $S(cc) $axis] - $S($axis)}]
                }
            }
            return [join $iso]
        }
        if {[regexp {^TOOL CALL\s*(\d*)\s*[XYZ]?\s*(S\d+)?} $body -> tool speed]} {
            # (a tool change: T with M6, as in ISO)
            return [string trim "[expr {$tool ne "" ? "T$tool M6" : ""}] $speed"]
        }
        if {[regexp {^FUNCTION TCPM\M} $body]} {return G[lindex $S(tcpG) 0]}
        if {[regexp {^FUNCTION RESET TCPM\M} $body]} {return G49}
        if {[regexp "^PLANE SPATIAL SPA($pl) SPB($pl) SPC($pl)" $body -> a b c]} {
            my SetFrame spatial [list $a $b $c] {0.0 0.0 0.0}
            return ""
        }
        if {[regexp {^PLANE RESET\M} $body]} {
            my EndFrame
            return ""
        }
        if {$body eq "STOP"} {return M0}
        return $body
    }
}
