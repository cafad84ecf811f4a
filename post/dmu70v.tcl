# dmu70v.tcl -- fivax post for the machine dmu70v (machines/dmu70v.tcl).
#	Written by tools/mkpost.tcl. Add settings to the list below (keys are
#	the replay options with their dash, e.g. -tol 0.005 -on-limit error).
#	NX template_post.dat line:
#	FIVAX_DMU70V,${UGII_CAM_POST_DIR}fivax/post/dmu70v.tcl,${UGII_CAM_POST_DIR}fivax/post/fivax.def
set fivax_post_here [file dirname [file normalize [info script]]]
set fivax_settings [list -machine [file join $fivax_post_here .. machines dmu70v.tcl]]
source [file join $fivax_post_here fivax.tcl]
