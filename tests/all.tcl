# all.tcl --
#	Runs every tests/*.test file. Exits non-zero when any test fails, any
#	file errors or any file is left behind in the temporary directory,
#	and prints "N passed, N failed, N skipped" as its last line.

package require tcltest 2.5
namespace import ::tcltest::*

set ::fileErrors 0
set here [file dirname [file normalize [info script]]]
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
