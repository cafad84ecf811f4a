# hh-paper-fig5.tcl -- fivax post for the machine hh-paper (machines/hh-paper.tcl)
#	in the print format of the head-head paper's figure 5: a copy of
#	post/hh-paper.tcl as a shop makes one (not written by tools/mkpost.tcl);
#	the format is all in its .def, hh-paper-fig5.def. Add settings to the
#	list below (keys are the replay options with their dash; the figure's
#	blocks are posted with -tol 0 -feed direct).
#	NX template_post.dat line:
#	FIVAX_HH-PAPER-FIG5,${UGII_CAM_POST_DIR}fivax/post/hh-paper-fig5.tcl,${UGII_CAM_POST_DIR}fivax/post/hh-paper-fig5.def
set fivax_post_here [file dirname [file normalize [info script]]]
set fivax_settings [list -machine [file join $fivax_post_here .. machines hh-paper.tcl]]
source [file join $fivax_post_here fivax.tcl]
