# num.tcl --
#	The one place for numbers at the edges: reading a decimal number from
#	text (CL files, machine files, options), writing a fixed-point decimal
#	that never shows "-0", and angle units (degrees outside, radians
#	inside). Every module reads and writes numbers through these.

namespace eval ::fivax::num {
    namespace export parse int fixed rad deg
    namespace ensemble create -prefixes 0
    # The double nearest pi (equal to acos(-1.0)); modules link to it with
    # [namespace upvar ::fivax::num pi pi].
    variable pi 3.141592653589793
    # The largest size (mm) of a CL point's coordinates (GOTO points, arc
    # centres, NURBS control points): no machine reaches farther, and
    # squared distances stay far from overflow (CL values go up to
    # 1.8e308); modules link to it as to pi.
    variable reach 1e9
}

# ::fivax::num::parse --
#	Returns the finite double written in tok, or "" when tok is not one.
#	Decimal only: accepts 100. and .5 and 017 (= 17) with white space
#	around; refuses nan, Inf, 1e400, hex and trailing junk.
proc ::fivax::num::parse {tok} {
    set tok [string trim $tok]
    if {[scan $tok %lf%c v junk] != 1} {return ""}
    if {!(abs($v) < Inf)} {return ""}
    # scan reads nothing but decimal syntax from the characters 0-9 . e E +
    # - (it stops at the x of 0x10); any other character gets the pattern
    if {[string trim $tok 0123456789.eE+-] ne ""
            && ![regexp {^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$} $tok]} {
        return ""
    }
    return [expr {double($v)}]
}

# ::fivax::num::int --
#	Returns the decimal integer written in tok (optional sign, digits only:
#	017 is 17), or "" when tok is not one or does not fit in 64 bits.
proc ::fivax::num::int {tok} {
    if {![regexp {^\s*([-+]?)0*(\d+)\s*$} $tok -> sign digits]} {return ""}
    if {[string length $digits] > 19} {return ""}
    scan $sign$digits %lld n
    if {$n > 9223372036854775807 || $n < -9223372036854775808} {return ""}
    return $n
}

# ::fivax::num::fixed --
#	Returns the finite double x with the given number of decimals, never
#	as a negative zero ("-0.000" becomes "0.000").
proc ::fivax::num::fixed {x decimals} {
    set s [format %.*f $decimals $x]
    if {[string index $s 0] eq "-" && ![string match {*[1-9]*} $s]} {
        return [string range $s 1 end]
    }
    return $s
}

# ::fivax::num::rad -- Returns the angle a (degrees) in radians.
proc ::fivax::num::rad {a} {
    # (pi as a literal: the variable's link costs more than the product)
    expr {$a * 3.141592653589793 / 180.0}
}

# ::fivax::num::deg -- Returns the angle a (radians) in degrees.
proc ::fivax::num::deg {a} {
    expr {$a * 180.0 / 3.141592653589793}
}
