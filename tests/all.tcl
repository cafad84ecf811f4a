# all.tcl --
#	Runs every tests/*.test file (matrix.test in a child run beside the
#	others when no argument is given). Exits non-zero when any test fails, any
#	file errors or any file is left behind in the temporary directory,
#	and prints "N passed, N failed, N skipped" as its last line.

package require tcltest 2.5
namespace import ::tcltest::*

set ::fileErrors 0
set here [file dirname [file normalize [info script]]]

# The safety matrix (matrix.test, most of an hour of one processor) runs
# beside the other files: a whole run (no arguments) starts it as a child
# run of its own (its own temporary directory; two cases at a time, so
# that it takes both processors once the rest is done), runs the rest
# here, then waits for it and counts its tests with these.
set ::matrixChild ""
if {![llength $argv]} {
    set matrixLog [file join $here matrix.log]
    set env(FIVAX_MATRIX) 1
    set env(FIVAX_MATRIX_JOBS) 2
    # (its report goes to the log; the pipe is only for waiting on it)
    set ::matrixChild [open |[list [info nameofexecutable] [file join $here all.tcl] \
        -file matrix.test -tmpdir [file join $here tmp-matrix] >& $matrixLog] w]
    unset env(FIVAX_MATRIX) env(FIVAX_MATRIX_JOBS)
    lappend argv -notfile {l.*.test matrix.test}
}

configure -testdir $here -tmpdir [file join $here tmp] -singleproc 1 {*}$argv
file delete -force [temporaryDirectory]
file mkdir [temporaryDirectory]

# Count files that error out, from tcltest's own report line.
proc CountFileErrors {cmd op} {
    if {[string match "*Test file error:*" [lindex $cmd end]]} {incr ::fileErrors}
}
trace add execution ::puts enter CountFileErrors

set ::totals {Total 0 Passed 0 Skipped 0 Failed 0}
proc ::tcltest::cleanupTestsHook {} {
    variable numTests
    # singleproc: the last call (runAllTests' own) carries the whole run
    foreach key {Total Passed Skipped Failed} {
        dict set ::totals $key $numTests($key)
    }
}
set status [runAllTests]
trace remove execution ::puts enter CountFileErrors
dict with ::totals {}
set failed [expr {$Failed + $::fileErrors}]
if {$::matrixChild ne ""} {
    # the child's report (its failures), then its counts with ours
    catch {close $::matrixChild}
    set f [open $matrixLog]
    set report [string trimright [read $f]]
    close $f
    file delete $matrixLog
    puts "matrix.test (beside the others):\n$report"
    if {[regexp {(\d+) passed, (\d+) failed, (\d+) skipped$} $report -> p f k]} {
        incr Passed $p
        incr failed $f
        incr Skipped $k
    } else {
        puts "matrix.test: no counts in its report"
        incr failed
    }
}
set left [glob -nocomplain -tails -directory [temporaryDirectory] -types {f d l p s hidden} *]
lappend left {*}[glob -nocomplain -tails -directory [temporaryDirectory] *]
set left [lsort -unique [lsearch -all -inline -not -regexp $left {^\.\.?$}]]
if {[llength $left]} {
    puts "files left behind in [temporaryDirectory]: [join $left {, }]"
    incr failed
}
file delete -force [temporaryDirectory]
puts "$Passed passed, $failed failed, $Skipped skipped"
exit [expr {$status || $failed > 0}]
