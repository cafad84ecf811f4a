# fivax.tcl --
#	Package loader for fivax, the post's package: what post/fivax.tcl
#	needs inside NX, sourced in pipeline order, and the one error helper
#	every module raises its errors with. The replay host's modules (the
#	CL file reader and NX's MOM runtime) are the package fivax::host
#	(host.tcl), which NX never loads.
#
#	    num opts vec       numbers, options, 3-vectors (used by all)
#	    def                .def files (the post's formats)
#	    machine kin        machine files, kinematics
#	    curve cutcom plane motion/  CL path geometry, 3D cutter compensation,
#	                       work-plane frames, the move-record contract
#	                       (motion/record.tcl), the planner
#	    nc dialect output  blocks, the controllers (lib/dialect/), the output layer
#	    verify dryrun      checking written blocks, the machine dry run
#	    settings           the option table of a posting job

package require Tcl 8.6

namespace eval ::fivax {
    variable home [file dirname [file normalize [info script]]]
    variable version 0.1
}

# ::fivax::Fail --
#	Raises an error with errorcode {FIVAX area detail} at the caller's caller.
proc ::fivax::Fail {area detail msg} {
    return -code error -level 2 -errorcode [list FIVAX $area $detail] $msg
}

foreach ::fivax::File {
    num.tcl opts.tcl vec.tcl
    def.tcl
    machine.tcl kin.tcl
    curve.tcl cutcom.tcl plane.tcl
    motion/record.tcl motion/plan.tcl motion/candidates.tcl motion/moves.tcl
    motion/linearise.tcl motion/feeds.tcl motion/holes.tcl motion/frames.tcl
    nc.tcl dialect.tcl output.tcl
    verify.tcl dryrun.tcl
    settings.tcl
} {
    source [file join $::fivax::home $::fivax::File]
}
unset ::fivax::File

package provide fivax 0.1
