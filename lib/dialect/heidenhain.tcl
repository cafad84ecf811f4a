# heidenhain.tcl --
#	Heidenhain Klartext (iTNC 530 / TNC 640): no G codes, every line
#	numbered from 0, L / CC / C blocks with signed words, TOOL CALL, M91
#	machine Z, no inverse time, TCP FUNCTION TCPM / FUNCTION RESET TCPM,
#	work plane PLANE SPATIAL / PLANE RESET STAY, dwell cycle 9, drill
#	cycles expanded into moves, end M30 and END PGM. Spec dialects.md
#	section 3. Writer keys: lib/output.tcl (Dialects); reader keys:
#	lib/verify.tcl.

::fivax::dialect::define heidenhain {
    syntax klartext program {} percent 0 comment numbered semicolon 1
    safety {} reset {{FUNCTION RESET TCPM} {PLANE RESET STAY}} units {MM INCH}
    length call machineZ M91 inverse 0
    tcp {on {{FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS}} off {{FUNCTION RESET TCPM}}}
    plane spatial arcs {planes {17} helix 0}
    dwell cycl9
    cycles {}
    letters {}
    active {}
    ends {{2 30} {{\mEND\s+PGM\M}}}
    cutcom R
} {
    comment {;(.*)$}
    skip {^\s*$}
    word {[A-Z][-+.0-9]+}
    tcpG {43.4}
    syntax klartext
}
