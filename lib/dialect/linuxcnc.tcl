# linuxcnc.tcl --
#	LinuxCNC 2.9 (rs274ngc): ISO G code with ( ) and ; comments, no O
#	number, G4 P in seconds, no work plane (3+2 as rotary positioning and
#	machine coordinates) and no TCP G code (the machine file's tcp_codes
#	M codes of a switchable-kinematics configuration), comment words the
#	interpreter acts on (MSG, DEBUG, ...) defused, end M30 and %. No 2D
#	cutter compensation on tool centre paths (cutcom) and no 3D tool-radius
#	compensation (cutcom3d; -cutcom3d control is an error). Spec
#	dialects.md section 4. Writer keys: lib/output.tcl (Dialects); reader
#	keys: lib/verify.tcl.

::fivax::dialect::define linuxcnc {
    default 0
    syntax gcode program {} percent 1 comment paren semicolon 1
    safety {G_cutcom 40 G_length 49 G_cycle 80} reset {} units {21 20}
    methods {} inverse 1
    tcp {} plane {} arcs {planes {17 18 19} helix 1}
    dwell P_s
    cycles {drill 81 drill_dwell 82 drill_deep 83 drill_break_chip 73 tap 84
        bore 85 bore_drag 86 bore_back 87 bore_manual 88 bore_dwell 89}
    letters {G M F S T H D P Q R I J K L}
    active {MSG DEBUG PRINT LOG LOGOPEN LOGAPPEND LOGCLOSE PROBEOPEN PROBECLOSE
        ABORT PY PYRUN PYRELOAD}
    ends {{2 30 99} {%}}
    cutcom {}
    form {first {^%$} close {^%$} start {\mG2[01] G90\M} end {\mM(30|0?2)\M}
        dwell {\mG0?4\M} free {}}
    words {LOGOPEN PYRELOAD linuxcnc LinuxCNC}
    cutcom3d {}
} {
    comment {\(([^)]*)\)|;(.*)$}
    skip {^\s*%\s*$}
    word {[A-Z][-+.0-9]+}
    tcpG {43.4}
    plane {}
    methods {}
    plain 1
    end {} endName {}
    callComp 0
    cutcom3d {}
}
