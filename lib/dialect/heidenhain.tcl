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
    cutcom3d {block LN code {} register {} words {} normal {NX NY NZ} axis {TX TY TZ}
        sign 1 format %+.7f rotaries 0}
} {
    comment {;(.*)$}
    skip {^\s*$}
    word {[A-Z][-+.0-9]+}
    tcpG {43.4}
    syntax klartext
    cutcom3d {block LN normal {NX NY NZ} axis {TX TY TZ}}
}
