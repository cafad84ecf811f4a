# hh-paper-fig5.tcl -- fivax post for the machine hh-paper (machines/hh-paper.tcl)
#	in the print format of the head-head paper's figure 5: a copy of
#	post/hh-paper.tcl as a shop makes one, kept with the tests (post/
#	ships one .def); the format is all in its .def, hh-paper-fig5.def.
#	Add settings to the list below (keys are the replay options with their
#	dash; the figure's blocks are posted with -tol 0 -feed direct). Run it
#	with tclsh tools/replay.tcl -post tests/data/fig5/hh-paper-fig5.tcl.
set fivax_post_here [file dirname [file normalize [info script]]]
set fivax_root [file join $fivax_post_here .. .. ..]
set fivax_settings [list -machine [file join $fivax_root machines hh-paper.tcl]]
source [file join $fivax_root post fivax.tcl]
