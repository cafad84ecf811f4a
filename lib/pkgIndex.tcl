if {![package vsatisfies [package provide Tcl] 8.6]} {return}
package ifneeded fivax 0.1 [list source [file join $dir fivax.tcl]]
package ifneeded fivax::host 0.1 [list source [file join $dir host.tcl]]
