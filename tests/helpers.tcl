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

# Where the real CL files live (outside the repo, never copied into it):
# FIVAX_CORPUS, else ../shared/data/cl beside the checkout.
if {[info exists ::env(FIVAX_CORPUS)] && $::env(FIVAX_CORPUS) ne ""} {
    set ::clCorpus [file normalize $::env(FIVAX_CORPUS)]
} else {
    set ::clCorpus [file normalize [file join $::fivaxRoot .. shared data cl]]
}
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
#	standard output and error together). Every NC file a successful run
#	writes (-o) is then checked by tools/verify.tcl against the CL file
#	with the same machine, frame and tolerances (verifyReplayOutput): when
#	that check fails, the code is 2 and verify's report ends the output,
#	so that the test fails showing it.
proc runReplay {args} {
    set code [catch {exec [info nameofexecutable] [file join $::fivaxRoot tools replay.tcl] \
        {*}$args 2>@1} out]
    set out [regsub {\n?child process exited abnormally$} $out ""]
    if {!$code} {
        lassign [verifyReplayOutput $args] vcode vout
        if {$vcode} {
            set code 2
            append out "\ntools/verify.tcl on the written file failed:\n$vout"
        }
    }
    list $code $out
}

# verifyReplayOutput --
#	Runs tools/verify.tcl on the NC file a replay with command line args
#	wrote (-o), against its CL file (the last word), with the replay's
#	-machine, -msys, -table-offset, -controller and -arc-tol; inside
#	blocks with the replay's -tol and -atol plus 0.001 of output rounding
#	(-tol 0: not linearised, -atol 0: axis not linearised; not checked). Returns {code output}; {0 {}}
#	when nothing was written.
proc verifyReplayOutput {argList} {
    set opts [dict create -machine [file join $::fivaxRoot machines hh-tilt45.tcl]]
    set switches {-msys -quiet -help}
    set cl [lindex $argList end]
    for {set i 0} {$i < [llength $argList] - 1} {incr i} {
        set w [lindex $argList $i]
        if {$w in $switches} {
            dict set opts $w 1
        } else {
            dict set opts $w [lindex $argList [incr i]]
        }
    }
    if {![dict exists $opts -o] || ![file isfile [dict get $opts -o]] || $cl eq "-"} {
        return {0 {}}
    }
    set vargs [list -quiet -machine [dict get $opts -machine] -cl $cl]
    if {[dict exists $opts -msys]} {lappend vargs -msys}
    foreach key {-table-offset -controller -arc-tol} {
        if {[dict exists $opts $key]} {lappend vargs $key [dict get $opts $key]}
    }
    # inside blocks: the replay's tolerances (0: not linearised) plus
    # the output rounding of the block ends (as e2eSpec: 0.001 mm)
    set tol [expr {[dict exists $opts -tol] ? [dict get $opts -tol] : 0.01}]
    set atol [expr {[dict exists $opts -atol] ? [dict get $opts -atol] : 0.05}]
    if {$tol == 0} {
        # no linearisation at all
        lappend vargs -mid-tol 1e9 -mid-atol 1e9
    } else {
        lappend vargs -mid-tol [expr {$tol + 0.001}] -mid-atol [expr {$atol == 0 ? 1e9 : $atol + 0.001}]
    }
    set code [catch {exec [info nameofexecutable] [file join $::fivaxRoot tools verify.tcl] \
        {*}$vargs [dict get $opts -o] 2>@1} out]
    list $code [regsub {\n?child process exited abnormally$} $out ""]
}
