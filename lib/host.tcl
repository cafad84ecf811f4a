# host.tcl --
#	Package loader for fivax::host, the replay host: what runs around the
#	post outside NX (tools/replay.tcl, the tools and tests that read CL
#	files), on top of the post's package fivax.
#
#	    clsf               CL file reader
#	    mom                NX's MOM runtime: CL records to events, mom_*
#	                       globals, MOM_* commands

package require Tcl 8.6
package require fivax 0.1

foreach ::fivax::File {clsf.tcl mom.tcl} {
    source [file join $::fivax::home $::fivax::File]
}
unset ::fivax::File

package provide fivax::host 0.1
