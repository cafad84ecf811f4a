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

::fivax::dialect::define sinumerik {
    syntax gcode program {} percent 0 comment semicolon semicolon 1
    safety {G_cutcom 40} reset {TRAFOOF CYCLE800()} units {71 70}
    length D machineZ SUPA inverse 1
    tcp {on {TRAORI ORIWKS ORIAXES} off {TRAFOOF}} plane cycle800
    arcs {planes {17 18 19} helix 1}
    dwell F_dwell
    cycles {}
    letters {G M F S T D P Q R I J K L}
    active {}
    ends {{2 17 30} {{\mRET\M}}}
    cutcom G
    cutcom3d {block {} code 41 register {} words CUT3DF normal {A5= B5= C5=} axis {}
        sign 1 format %.7f rotaries 1}
} {
    comment {;(.*)$}
    skip {^\s*$}
    word {[A-Z][-+.0-9]+}
    tcpG {43.4}
    syntax sinumerik
    cutcom3d {drop {\m(?:CUT3DF|CUT3DC|[ABC][45]=[-+.0-9]+)(?=\s|$)}}
}
