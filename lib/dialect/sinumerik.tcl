# sinumerik.tcl --
#	Siemens Sinumerik 840D sl: ; comments, no % or O header, G71 mm, D1
#	length compensation with the tool change, SUPA Z D0 machine Z, G93
#	inverse time, TCP TRAORI ORIWKS ORIAXES / TRAFOOF, work plane
#	CYCLE800 (mode 57), G4 F in seconds, drill cycles expanded into moves,
#	end M30. Spec dialects.md section 2.
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
} {
    comment {;(.*)$}
    skip {^\s*$}
    word {[A-Z][-+.0-9]+}
    tcpG {43.4}
    syntax sinumerik
}
