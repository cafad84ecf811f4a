# sinumerik.tcl --
#	Siemens Sinumerik 840D sl: ; comments, no % or O header, G71 mm, D1
#	length compensation with the tool change, SUPA Z D0 machine Z, G93
#	inverse time, TCP TRAORI ORIWKS ORIAXES / TRAFOOF, work plane
#	CYCLE800 (mode 57), G4 F in seconds, drill cycles expanded into moves,
#	end M30. Spec dialects.md section 2.
#	3D tool radius compensation (-cutcom3d control): SINUMERIK 840D
#	Manual "5-axis machining", reference section 7.1 "Tool radius
#	compensation" (and the Programming Manual Job Planning, "3D tool
#	radius compensation"): CUT3DF face milling, 5-axis with variable tool
#	orientation (the orientation from the rotaries under TRAORI, which
#	fivax writes in TCP mode), switched on by G41 with CUT3DF and off by
#	G40; the surface normal at each block's end as A5= B5= C5= (the start
#	vector A4= B4= C4= left out: the control takes the previous block's
#	end vector), 7 decimals. CUT3DC (circumferential milling, with ISD)
#	is not written: the CL's contact data describe the face contact. The
#	tool's D1 holds the delta to the programmed cutter.
#	Writer keys: lib/output.tcl (Dialects); reader keys: lib/verify.tcl.

namespace eval ::fivax::dialect::sinumerik {}

# The writer's forms of this control (mixed into ::fivax::output::Writer).
oo::class create ::fivax::dialect::sinumerik::Writer {
    variable S

    # Returns the length register of a tool: D1, its first edge.
    method Register {adjust} {
        return 1
    }

    # Returns the words that switch the armed length compensation on in a
    # block with a Z move: D<n>.
    method LengthWords {} {
        set n $S(length)
        set S(length) 0
        list D $n
    }

    # Returns the block of a Z move to z in machine coordinates: G0 SUPA
    # Z D0 (off: the TCP-off lines, written before it).
    method MachineZ {z off} {
        $S(nc) force once {G_motion Z}
        list [$S(nc) block [list G_motion [my Code rapid_code] "" SUPA Z $z D 0]]
    }

    # Returns the work plane's line: CYCLE800 mode 57 (rotations about X,
    # Y', Z'') with the origin, the machine's swivel record and the
    # direction of rec's seq.
    method PlaneLines {angles rec} {
        lassign [dict get $rec origin] ox oy oz
        set a [lmap v [concat [list $ox $oy $oz] $angles] {::fivax::num::fixed $v 4}]
        lassign $a x y z aa bb cc
        list [$S(nc) line "CYCLE800(1,\"[dict get $S(machine) swivel_record]\",0,57,$x,$y,$z,$aa,$bb,$cc,0,0,0,[dict get $rec seq],100,1)"]
    }

    # Returns the line that ends the work plane: CYCLE800().
    method PlaneOffLines {} {
        list [$S(nc) line "CYCLE800()"]
    }
}

::fivax::dialect::define sinumerik {
    default 0
    syntax gcode program {} percent 0 comment semicolon semicolon 1
    safety {G_cutcom 40} reset {TRAFOOF CYCLE800()} units {71 70}
    methods ::fivax::dialect::sinumerik::Writer inverse 1
    tcp {on {TRAORI ORIWKS ORIAXES} off {TRAFOOF}} plane xyz
    arcs {planes {17 18 19} helix 1}
    dwell F_dwell
    cycles {}
    letters {G M F S T D P Q R I J K L}
    active {}
    ends {{2 17 30} {{\mRET\M}}}
    cutcom G
    form {first {} close {} start {\mG7[01] G90\M} end {\mM(30|0?2)\M}
        dwell {\mG0?4\M} free {CYCLE800|TRAORI}}
    words {TRAORI TRAFOOF ORIWKS ORIAXES CYCLE800 SUPA sinumerik Sinumerik}
    cutcom3d {block {} code 41 register {} words CUT3DF normal {A5= B5= C5=} axis {}
        sign 1 format %.7f rotaries 1}
} {
    comment {;(.*)$}
    skip {^\s*$}
    word {[A-Z][-+.0-9]+}
    tcpG {43.4}
    plane {}
    methods ::fivax::dialect::sinumerik::Reader
    plain 1
    end {} endName {}
    callComp 0
    cutcom3d {drop {\m(?:CUT3DF|CUT3DC|[ABC][45]=[-+.0-9]+)(?=\s|$)}}
}

# The reader's forms of this control (mixed into ::fivax::verify::Checker).
oo::class create ::fivax::dialect::sinumerik::Reader {
    variable S

    # Returns the line with its keywords read: SUPA as G53,
    # TRAORI / TRAFOOF switching TCP, ORIWKS / ORIAXES (the defaults the
    # reader assumes) dropped, CYCLE800(..) setting the work plane (mode
    # 57: rotations about X, Y', Z'') and CYCLE800() ending it.
    method Translate {line} {
        set text $line
        if {[string first ";" $text] >= 0} {
            set comment [string range $text [string first ";" $text] end]
            set text [string range $text 0 [string first ";" $text]-1]
        } else {
            set comment ""
        }
        regsub -all {\mSUPA\M} $text G53 text
        if {[regsub -all {\mTRAORI\M} $text "" text]} {my SetTcp 1}
        if {[regsub -all {\mTRAFOOF\M} $text "" text]} {my SetTcp 0}
        regsub -all {\m(ORIWKS|ORIAXES)\M} $text "" text
        if {[regexp {\mCYCLE800\(([^)]*)\)} $text -> args]} {
            set v [split $args ,]
            if {[string trim $args] eq ""} {
                my EndFrame
            } elseif {[llength $v] >= 10 && [string trim [lindex $v 3]] eq "57"} {
                my SetFrame xyz [lmap x [lrange $v 7 9] {string trim $x}] \
                    [lmap x [lrange $v 4 6] {string trim $x}]
            }
            regsub {\mCYCLE800\([^)]*\)} $text "" text
        }
        return "$text$comment"
    }
}
