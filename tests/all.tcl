# all.tcl --
#	Runs every tests/*.test file. Exits non-zero when any test fails or any
#	file errors, and prints "N passed, N failed, N skipped" as its last line.

package require tcltest 2.5
namespace import ::tcltest::*

set ::fileErrors 0
configure -testdir [file dirname [file normalize [info script]]] \
    -tmpdir [file join [file dirname [file normalize [info script]]] tmp] \
    -singleproc 1 {*}$argv
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
file delete -force [temporaryDirectory]
puts "$Passed passed, $failed failed, $Skipped skipped"
exit [expr {$status || $failed > 0}]
