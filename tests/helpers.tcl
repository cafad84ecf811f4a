# helpers.tcl --
#	Shared test setup: loads fivax from this checkout (never an installed
#	copy) and the test and tool helpers (tests/kinref.tcl,
#	tools/lib/toolpath.tcl), registers the float matchers, and the
#	real-CL-corpus constraint.
#
#	Conventions for test files: procs a file defines carry its module's
#	name as a prefix (motionPlan, clsfStats) so that no two files define
#	the same name in the one interpreter; temporary files come from
#	makeFile/makeDirectory and are removed by the test that made them
#	(tests/all.tcl fails when any is left behind); errors are asserted with
#	-errorCode; results carry measured values (see customMatch le).

package require tcltest 2.5
namespace import ::tcltest::*

set ::fivaxRoot [file dirname [file dirname [file normalize [info script]]]]
set ::auto_path [linsert $::auto_path 0 [file join $::fivaxRoot lib]]
package require fivax 0.1
source [file join $::fivaxRoot tests kinref.tcl]
source [file join $::fivaxRoot tools lib toolpath.tcl]
source [file join $::fivaxRoot tools lib corpus.tcl]

# Where the real CL files live (outside the repo, never copied into it):
# FIVAX_CORPUS, else ../shared/data/cl beside the checkout.
set ::clCorpus [::fivax::corpusDir $::fivaxRoot]
testConstraint clsfCorpus [file isdirectory $::clCorpus]
if {![testConstraint clsfCorpus] && ![info exists ::corpusNoted]} {
    set ::corpusNoted 1
    puts "corpus tests skipped: $::clCorpus is not a directory (set FIVAX_CORPUS to the real CL files)"
}

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

# boundsMatch --
#	Returns 1 when got is a list as long as the list of bounds want and
#	each number of got is at most its bound (a bound "-" takes any value
#	of got as it is: a word, a count). The measured values are the
#	result, so a failure shows them beside the bounds.
proc boundsMatch {want got} {
    if {[llength $want] != [llength $got]} {return 0}
    foreach w $want g $got {
        if {$w eq "-"} continue
        if {[string is double -strict $w]} {
            if {![string is double -strict $g] || !($g <= $w)} {return 0}
        } elseif {$w ne $g} {
            return 0
        }
    }
    return 1
}
customMatch le boundsMatch

# corpusFile -- Returns the path of the named real CL file.
proc corpusFile {name} {
    file join $::clCorpus $name
}

# runReplay --
#	Runs tools/replay.tcl with args; returns {code output} (output:
#	standard output and error together).
proc runReplay {args} {
    set code [catch {exec [info nameofexecutable] [file join $::fivaxRoot tools replay.tcl] \
        {*}$args 2>@1} out]
    list $code [regsub {\n?child process exited abnormally$} $out ""]
}
