# fanuc.tcl --
#	Fanuc 30i style ISO G code (the default controller): % lines, O
#	number, ( ) comments, G43 H length compensation, G53 machine Z, G93
#	inverse time, TCP G43.4 H (in the first X Y Z block) cancelled by
#	G49, work plane G68.2 + G53.1 (Euler Z-X'-Z''), G4 P in milliseconds,
#	canned cycles G73 G76 G81..G89, end M30. Spec dialects.md section 1.
#	3D cutter compensation (-cutcom3d control): FANUC Series 30i/300i/
#	300is-MODEL A Descriptions (B-63942EN/02), 8 "Tool function / tool
#	compensation function", "Three-dimensional cutter compensation":
#	G41 X Y Z I J K D starts it (the offset space is that of the axis
#	addresses of the start block), the blocks after it carry X Y Z I J K,
#	G40 cancels; the tool centre is offset by the D value along (I, J, K)
#	(the surface normal, out of the material), written with 7 decimals.
#	With G43.4 the D register holds the delta to the programmed cutter.
#	(G41.2/G42.2, the 5-axis tool-side offset, takes no normal: not used.)
#	Writer keys: lib/output.tcl (Dialects); reader keys: lib/verify.tcl.

namespace eval ::fivax::dialect::fanuc {}

# The writer's forms of this control (mixed into ::fivax::output::Writer).
oo::class create ::fivax::dialect::fanuc::Writer {
    variable S

    # Returns the work plane's blocks: G68.2 X Y Z (the origin) I J K
    # (Euler Z-X'-Z'' angles) and G53.1 (the tool along its Z).
    method PlaneLines {angles rec} {
        lassign [dict get $rec origin] ox oy oz
        lassign $angles i j k
        list [$S(nc) block [list G_rot 68.2 X $ox Y $oy Z $oz E_i $i E_j $j E_k $k]] \
            [$S(nc) block {G_tilt 53.1}]
    }

    # Returns the block that ends the work plane: G69.
    method PlaneOffLines {} {
        list [$S(nc) block {G_rot 69}]
    }
}

::fivax::dialect::define fanuc {
    default 1
    syntax gcode program O%04d percent 1 comment paren semicolon 0
    safety {G_cutcom 40 G_length 49 G_cycle 80} reset {G69} units {21 20}
    methods ::fivax::dialect::fanuc::Writer inverse 1
    tcp {on G43.4 off G49} plane zxz arcs {planes {17 18 19} helix 1}
    dwell P_ms
    cycles {drill 81 drill_dwell 82 drill_deep 83 drill_break_chip 73 tap 84
        bore 85 bore_drag 86 bore_no_drag 76 bore_back 87 bore_manual 88 bore_dwell 89}
    letters {G M F S T H D P Q R I J K L}
    active {}
    ends {{2 30 99} {%}}
    cutcom GD
    form {first {^%$} close {^%$} start {\mG2[01] G90\M} end {\mM(30|0?2)\M}
        dwell {\mG0?4\M} free {G68\.2|G43\.4}}
    words {G43.4 G68.2 G53.1 fanuc Fanuc}
    cutcom3d {block {} code 41 register D words {} normal {I J K} axis {}
        sign 1 format %.7f rotaries 1}
} {
    comment {\(([^)]*)\)}
    skip {^\s*(%|O\d+\s*(\(.*\))?\s*)$}
    word {[A-Z][-+.0-9]+}
    tcpG {43.4}
    plane {68.2 53.1 zxz}
    methods {}
    plain 1
    end {} endName {}
    callComp 0
    cutcom3d {ijk 1}
}
