# helpers.tcl --
#	Shared test setup: loads fivax from this checkout (never an installed
#	copy), registers float matchers and the real-CL-corpus constraint.

package require tcltest 2.5
namespace import ::tcltest::*

set ::fivaxRoot [file dirname [file dirname [file normalize [info script]]]]
set ::auto_path [linsert $::auto_path 0 [file join $::fivaxRoot lib]]
package require fivax 0.1

# Where the real CL files live (outside the repo, never copied into it).
set ::clCorpus [file normalize [file join $::fivaxRoot .. shared data cl]]
testConstraint clsfCorpus [file isdirectory $::clCorpus]

# approxList --
#	Returns 1 when the flat number lists want and got have equal length and
#	agree element-wise within tol.
proc approxList {tol want got} {
    if {[llength $want] != [llength $got]} {return 0}
    foreach w $want g $got {
        if {![string is double -strict $g] || abs($w - $g) > $tol} {return 0}
    }
    return 1
}
customMatch approx {approxList 1e-9}
customMatch mm {approxList 1e-6}
customMatch coarse {approxList 1e-3}

# corpusFile -- Returns the path of the named real CL file.
proc corpusFile {name} {
    file join $::clCorpus $name
}
