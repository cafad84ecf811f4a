# haas.tcl --
#	Haas NGC (Next Generation Control) mill, five-axis trunnions such as
#	the UMC-750: ISO G code. Sources: Haas NGC Mill
#	Operator's Manual, online edition (haascnc.com "Next Generation
#	Control Mill Operator's Manual"), G-code chapter:
#	  - G234 Tool Center Point Control (TCPC) (Group 08): X Y Z are the
#	    tip in the work-offset frame, which "remains fixed relative to the
#	    table; when the rotary axes rotate, the linear coordinate system
#	    rotates with them". Written as a TCP G code: in the first X Y Z
#	    block after the rotaries are positioned, with the length register
#	    H (G234 shares G43's group 08, so it takes the H that G43 would);
#	    cancelled by G49 in a block of its own before the Z up.
#	  - G254 Dynamic Work Offset (DWO) (Group 23), cancelled by G255: for
#	    3+2 positioning only ("Cancel G254 with G255 immediately after use
#	    and before ANY rotary motion", the UMC-750 operator's manual's DWO
#	    notes). Not written (yet): fivax has no work-plane form whose X Y Z
#	    stay in the workpiece frame while the rotaries stand still. A 3+2
#	    operation is written in joint mode as rotary positioning plus
#	    machine coordinates, and with -tcp 1 as G234
#	    blocks whose rotaries do not move, which is what DWO does.
#	  - G93 inverse time feed (Group 05), F on every G1/G2/G3 block; G94.
#	  - canned cycles G73 G76 G81 G82 G83 G84 G85 G86 G89 with G98/G99
#	    and R (Haas's G74 reverse tap and G77 back bore are not written:
#	    the back bore is expanded into moves by the planner).
#	  - G04 P: with no decimal point P is milliseconds (P_ms, integer).
#	  - M30 ends the program; % opens and closes it; O number of 5 digits.
#	  - G41/G42 D n, G40: 2D cutter compensation (cutcom GD); on
#	    fivax's tool centre paths the D offset holds the wear only.
#	  - G141 3D+ Cutter Compensation (Group 07), -cutcom3d control: G141
#	    X Y Z I J K F D starts it, then G01 X Y Z I J K F blocks; I J K "the
#	    normal direction, relative to the center of the tool, to the
#	    contact point", a unit vector: written as the surface normal
#	    reversed (fivax's normal points out of the material, towards the
#	    tool centre), 7 decimals; D selects the wear offset; G40 cancels.
#	Writer keys: lib/output.tcl (Dialects); reader keys: lib/verify.tcl.

::fivax::dialect::define haas {
    default 0
    syntax gcode program O%05d percent 1 comment paren semicolon 0
    safety {G_cutcom 40 G_length 49 G_cycle 80} reset {} units {21 20}
    methods {} inverse 1
    tcp {on G234 off G49} plane {} arcs {planes {17 18 19} helix 1}
    dwell P_ms
    cycles {drill 81 drill_dwell 82 drill_deep 83 drill_break_chip 73 tap 84
        bore 85 bore_drag 86 bore_no_drag 76 bore_dwell 89}
    letters {G M F S T H D P Q R I J K L}
    active {}
    ends {{2 30 99} {%}}
    cutcom GD
    form {first {^%$} close {^%$} start {\mG2[01] G90\M} end {\mM(30|0?2)\M}
        dwell {\mG0?4\M} free {\mG234\M}}
    words {G234 haas Haas}
    cutcom3d {block {} code 141 register D words {} normal {I J K} axis {}
        sign -1 format %.7f rotaries 1}
} {
    comment {\(([^)]*)\)}
    skip {^\s*(%|O\d+\s*(\(.*\))?\s*)$}
    word {[A-Z][-+.0-9]+}
    tcpG {234}
    plane {}
    methods {}
    plain 1
    end {} endName {}
    callComp 0
    cutcom3d {ijk 1 codes 141}
}
