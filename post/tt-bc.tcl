# tt-bc.tcl -- fivax post for the machine tt-bc (machines/tt-bc.tcl).
#	Written by tools/mkpost.tcl. Add settings to the list below (keys are
#	the replay options with their dash, e.g. -tol 0.005 -on-limit error).
#	NX template_post.dat line:
#	FIVAX_TT-BC,${UGII_CAM_POST_DIR}fivax/post/tt-bc.tcl,${UGII_CAM_POST_DIR}fivax/post/fivax.def
set fivax_post_here [file dirname [file normalize [info script]]]
set fivax_settings [list -machine [file join $fivax_post_here .. machines tt-bc.tcl]]
source [file join $fivax_post_here fivax.tcl]
