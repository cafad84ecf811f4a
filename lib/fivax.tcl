# fivax.tcl --
#	Package loader for fivax, a five-axis postprocessor library in pure Tcl.
#	Holds the shared error and number helpers every module uses.

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

# ::fivax::parseReal --
#	Returns the finite double written in tok, or "" when tok is not one.
#	Accepts 100. and .5; refuses nan, Inf, 1e400, hex and trailing junk.
proc ::fivax::parseReal {tok} {
    if {[scan $tok %lf%c v junk] != 1} {return ""}
    if {!(abs($v) < Inf)} {return ""}
    if {![regexp {^\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*$} $tok]} {return ""}
    return [expr {double($v)}]
}

# ::fivax::isReal --
#	Returns 1 when tok is a finite decimal number as parseReal accepts it.
proc ::fivax::isReal {tok} {
    expr {[parseReal $tok] ne ""}
}

foreach ::fivax::File {vec.tcl clsf.tcl machine.tcl kin.tcl motion.tcl nc.tcl def.tcl
        mom.tcl verify.tcl toolpath.tcl} {
    source [file join $::fivax::home $::fivax::File]
}
unset ::fivax::File

## Ready
package provide fivax 0.1
