# bench.tcl --
#	Measures the cost of the rotary optimisation and the linearisation on
#	a large synthetic CL file and prints the figures next to a stored
#	baseline of our own earlier figures (tools/bench-baseline.txt). The
#	file (a zig-zag raster over the example surface, lib/toolpath.tcl) is
#	generated into a temporary directory and deleted afterwards.
#
#	tclsh tools/bench.tcl ?-points 200000? ?-machine FILE? ?-noreplay? ?-save?
#
#	Rows, in microseconds per CL point (GOTO), each including the reading:
#	  read       the CLSF reader alone
#	  greedy     reader + planner, -rotary greedy -tol 0
#	  optimal    reader + planner, -rotary optimal -tol 0
#	  optimal+lin  reader + planner, -rotary optimal -tol 0.01 (the default)
#	  replay     tools/replay.tcl end to end (post, NC writer, verification)
#	No timing is asserted anywhere: the figures are for reading.

package require Tcl 8.6

set root [file dirname [file dirname [file normalize [info script]]]]
set auto_path [linsert $auto_path 0 [file join $root lib]]
package require fivax 0.1
source [file join $root tools lib toolpath.tcl]

namespace eval ::bench {
    variable options {
        {-points {int min 1000} 200000 N "CL points in the generated file (passes of 1000)"}
        {-machine text "" FILE "machine file (default machines/hh-tilt45.tcl)"}
        {-noreplay bool 0 "" "skip the end-to-end replay row"}
        {-save bool 0 "" "store the figures as the new baseline"}
        {-help bool 0 "" "print this help"}
    }
    # Figures in table order: key, label.
    variable rows {
        points       "CL points"
        generate_s   "generate the CL file (s)"
        read_us      "read only (us/point)"
        greedy_us    "greedy, no linearisation (us/point)"
        optimal_us   "optimal, no linearisation (us/point)"
        lin_us       "optimal + linearisation (us/point)"
        replay_us    "replay end to end (us/point)"
        inserted     "points inserted"
        retracts     "retracts (optimal)"
        travel_greedy  "rotary travel, greedy (deg)"
        travel_optimal "rotary travel, optimal (deg)"
    }
}

# ::bench::Generate --
#	Writes a raster of n points (passes of 1000) as CLSF to path; returns
#	the number of points.
proc ::bench::Generate {n path} {
    set passes [expr {max(1, $n / 1000)}]
    set pts [::fivax::toolpath raster -passes $passes -step 1000 -D 16 -r 4 -lead 10 -tilt 15]
    set chan [open $path w]
    try {
        chan configure $chan -translation lf
        puts $chan [join [::fivax::toolpath clsf $pts -op BENCH_RASTER -D 16 -r 4 -length 75] \n]
    } finally {
        close $chan
    }
    llength $pts
}

# ::bench::Read -- Returns the number of GOTO records of the CLSF file path.
proc ::bench::Read {path} {
    set r [::fivax::clsf open $path]
    set n 0
    try {
        while {[set rec [$r next]] ne ""} {
            if {[dict get $rec kind] eq "GOTO"} {incr n}
        }
    } finally {
        $r destroy
    }
    return $n
}

# ::bench::Plan --
#	Feeds the CLSF file path through a planner for machine with options;
#	returns the planner's stats.
proc ::bench::Plan {machine path args} {
    set h [::fivax::motion create $machine -msys 1 {*}$args]
    set r [::fivax::clsf open $path]
    set rapid 0
    set feed 0.0
    set axis {0 0 1}
    try {
        while {[set rec [$r next]] ne ""} {
            switch -- [dict get $rec kind] {
                RAPID {set rapid 1}
                FEDRAT {set feed [dict get $rec value]}
                TLDATA {
                    $h flush
                    $h setTool [dict get $rec length]
                }
                MSYS {
                    $h setFrame [dict get $rec origin] [dict get $rec xaxis] [dict get $rec yaxis]
                }
                GOTO {
                    if {[llength [dict get $rec axis]]} {set axis [dict get $rec axis]}
                    $h add [expr {$rapid ? "rapid" : "feed"}] \
                        [dict get $rec point] $axis $feed [dict get $rec line]
                    set rapid 0
                }
            }
        }
        $h flush
        return [$h stats]
    } finally {
        $r destroy
        $h destroy
    }
}

# ::bench::Replay -- Runs tools/replay.tcl on path for machineFile into a temporary NC file.
proc ::bench::Replay {machineFile path} {
    variable ::root
    set out [file rootname $path].nc
    exec [info nameofexecutable] [file join $root tools replay.tcl] -quiet \
        -machine $machineFile -o $out $path 2>@1
    file delete $out
}

# ::bench::Us -- Returns the microseconds per point of running script at the caller's level.
proc ::bench::Us {n script} {
    set t0 [clock microseconds]
    uplevel 1 $script
    expr {([clock microseconds] - $t0) / double($n)}
}

# ::bench::Baseline -- Returns the dict stored in file path ({} when absent).
proc ::bench::Baseline {path} {
    if {![file readable $path]} {return {}}
    set chan [open $path r]
    try {
        set d [dict create]
        foreach line [split [read $chan] \n] {
            set line [string trim $line]
            if {$line eq "" || [string index $line 0] eq "#"} continue
            dict set d [lindex $line 0] [lindex $line 1]
        }
        return $d
    } finally {
        close $chan
    }
}

# ::bench::Save -- Writes figures to path with a header naming the run.
proc ::bench::Save {path figures header} {
    variable rows
    set chan [open $path w]
    try {
        chan configure $chan -translation lf
        puts $chan "# fivax bench baseline (tclsh tools/bench.tcl -save): $header"
        foreach {key label} $rows {
            if {[dict exists $figures $key]} {puts $chan "$key [dict get $figures $key]"}
        }
    } finally {
        close $chan
    }
}

# ::bench::Fmt -- Returns value v printed for the table ("-" when absent).
proc ::bench::Fmt {v} {
    if {$v eq ""} {return -}
    if {[string is entier -strict $v]} {return $v}
    format %.1f $v
}

# ::bench::main -- Generates the file, measures every row, prints the table.
proc ::bench::main {argv} {
    variable options
    variable rows
    variable ::root
    try {
        lassign [::fivax::opts argv $options $argv bench] opts rest
    } trap {FIVAX OPTION} {msg} {
        puts stderr $msg
        exit 1
    }
    if {[dict get $opts -help] || [llength $rest]} {
        puts "usage: tclsh tools/bench.tcl ?options?\n\nMeasures planner speed on a generated CL file.\nOptions:\n[::fivax::opts help $options]"
        exit [expr {[llength $rest] > 0}]
    }
    set machineFile [dict get $opts -machine]
    if {$machineFile eq ""} {set machineFile [file join $root machines hh-tilt45.tcl]}
    set machine [::fivax::machine load $machineFile]
    set dir [file join [expr {[info exists ::env(TMPDIR)] ? $::env(TMPDIR) : "/tmp"}] \
        fivax-bench-[pid]]
    file mkdir $dir
    set cl [file join $dir raster.cls]
    set f [dict create]
    try {
        set t0 [clock microseconds]
        set n [Generate [dict get $opts -points] $cl]
        dict set f points $n
        dict set f generate_s [expr {([clock microseconds] - $t0) / 1e6}]
        puts stderr "bench: $n points on [dict get $machine name] ([format %.1f [dict get $f generate_s]] s to generate)"
        dict set f read_us [Us $n {Read $cl}]
        dict set f greedy_us [Us $n {set g [Plan $machine $cl -rotary greedy -tol 0]}]
        dict set f optimal_us [Us $n {set o [Plan $machine $cl -rotary optimal -tol 0]}]
        dict set f lin_us [Us $n {set l [Plan $machine $cl -rotary optimal]}]
        if {![dict get $opts -noreplay]} {
            dict set f replay_us [Us $n {Replay $machineFile $cl}]
        }
        dict set f inserted [dict get $l inserted]
        dict set f retracts [dict get $o retracts]
        dict set f travel_greedy [dict get $g travel]
        dict set f travel_optimal [dict get $o travel]
    } finally {
        file delete -force $dir
    }
    set baseFile [file join $root tools bench-baseline.txt]
    set base [Baseline $baseFile]
    puts [format "%-40s %12s %12s" figure now baseline]
    foreach {key label} $rows {
        set now [expr {[dict exists $f $key] ? [dict get $f $key] : ""}]
        set was [expr {[dict exists $base $key] ? [dict get $base $key] : ""}]
        puts [format "%-40s %12s %12s" $label [Fmt $now] [Fmt $was]]
    }
    if {[dict get $opts -save]} {
        Save $baseFile $f "$n points, [dict get $machine name], Tcl [info patchlevel],\
            [clock format [clock seconds] -format %Y-%m-%d]"
        puts stderr "bench: baseline saved to $baseFile"
    }
}

::bench::main $argv
