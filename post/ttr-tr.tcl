# ttr-tr.tcl -- fivax post for the machine ttr-tr (machines/ttr-tr.tcl).
#	Written by tools/mkpost.tcl. Add settings to the list below (keys are
#	the replay options with their dash, e.g. -tol 0.005 -on-limit error).
#	NX template_post.dat line:
#	FIVAX_TTR-TR,${UGII_CAM_POST_DIR}fivax/post/ttr-tr.tcl,${UGII_CAM_POST_DIR}fivax/post/fivax.def
set fivax_post_here [file dirname [file normalize [info script]]]
set fivax_settings [list -machine [file join $fivax_post_here .. machines ttr-tr.tcl]]
source [file join $fivax_post_here fivax.tcl]
