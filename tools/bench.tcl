# bench.tcl --
#	End-to-end speed of tools/replay.tcl on generated 5-axis CL files of
#	several sizes, beside a minimal loop of ours that does the least any
#	post must: read each GOTO, solve the inverse kinematics, write a
#	block. Each run is a child process; the table gives CL records per
#	second, wall time and peak resident memory (VmHWM).
#
#	tclsh tools/bench.tcl ?-sizes "50000 200000 1000000"? ?-machine FILE?
#
#	Rows per size:
#	  replay     tools/replay.tcl with the default settings (the block
#	             check in a second process: -check-process auto, as these
#	             files are over 1 MB)
#	  one process        the same with -check-process off
#	  -tol 0, no check   linearisation off (-tol 0) and the block check
#	             left out (the checker's block method replaced by a no-op
#	             in the post interpreter: a bench-only measure, no option)
#	  fused floor        every step of the default on these plain GOTOs
#	             fused into two loops (::bench::Fused): the most pure Tcl
#	             can reach with the post's work and no post structure
#	  minimal    the minimal loop (::bench::Loop): scan, kin orientations
#	             and position (first solution), format, write
#	  stock-style post   tools/replay.tcl -post tests/data/pbstyle/pbstyle.tcl:
#	             a Post Builder-shaped three-axis post (MOM_do_template
#	             with a .def, MOM_before_output) on the same runtime and
#	             file, beside "one process" (fivax's own post)
#	The file is a zig-zag raster over the example surface
#	(tools/lib/toolpath.tcl), 1000 points a pass, at most 200 passes
#	(generated once), repeated to the size. Nothing is asserted: the
#	figures are for reading, and make test times nothing.
#
#	Three internal modes run the child processes:
#	  tclsh tools/bench.tcl -loop MACHINE CL OUT
#	  tclsh tools/bench.tcl -nocheck ?replay options? CL
#	  tclsh tools/bench.tcl -fused MACHINE CL OUT

package require Tcl 8.6

set root [file dirname [file dirname [file normalize [info script]]]]
set auto_path [linsert $auto_path 0 [file join $root lib]]
package require fivax::host 0.1

namespace eval ::bench {
    variable options {
        {-sizes any {50000 200000 1000000} "N ..." "CL points of the generated files (multiples of 1000)"}
        {-machine text "" FILE "machine file, or a shipped machine's name (default hh-tilt45)"}
        {-help bool 0 "" "print this help"}
    }
    # Points a pass, and the passes generated at most.
    variable pass 1000
    variable maxPasses 200
}

# ::bench::Generate --
#	Writes CLSF files of each size in sizes (points) into dir; returns a
#	dict size -> path.
proc ::bench::Generate {sizes dir} {
    variable pass
    variable maxPasses
    variable ::root
    source [file join $root tools lib toolpath.tcl]
    set most [tcl::mathfunc::max {*}$sizes]
    set passes [expr {min($maxPasses, max(1, $most / $pass))}]
    set pts [::fivax::toolpath raster -passes $passes -step $pass -D 16 -r 4 -lead 10 -tilt 15]
    set lines [::fivax::toolpath clsf $pts -op BENCH_RASTER -D 16 -r 4 -length 75]
    # the header up to the first feed, the points, the retract and end
    set head [lrange $lines 0 9]
    set body [lrange $lines 10 end-3]
    set tail [lrange $lines end-2 end]
    # each copy starts with its full tool axis (the first GOTO left it out)
    set first {}
    lassign [lindex $pts 0] p t
    lset body 0 [::fivax::toolpath goto $p $t first]
    set files [dict create]
    foreach n $sizes {
        set path [file join $dir bench-$n.cls]
        set chan [open $path w]
        try {
            chan configure $chan -translation lf -buffersize 1048576
            puts $chan [join $head \n]
            for {set left $n} {$left > 0} {incr left -[llength $body]} {
                puts $chan [join [lrange $body 0 [expr {min($left, [llength $body]) - 1}]] \n]
            }
            puts $chan [join $tail \n]
        } finally {
            close $chan
        }
        dict set files $n $path
    }
    return $files
}

# ::bench::Run --
#	Runs the command words as a child process; returns {wall rssMB stderr}:
#	seconds, peak resident set (MB, from /usr/bin/time or VmHWM polled
#	every 50 ms) and the child's standard error.
proc ::bench::Run {words} {
    set errFile [file join [file dirname [lindex $words end]] bench-[pid].err]
    set timeFile $errFile.time
    set timer [expr {[file executable /usr/bin/time]
        ? [list /usr/bin/time -f %M -o $timeFile] : {}}]
    set t0 [clock milliseconds]
    set pid [exec {*}$timer {*}$words 2> $errFile &]
    set hwm 0
    while {[ProcState $pid] ne "Z"} {
        if {![llength $timer]} {set hwm [expr {max($hwm, [VmHWM $pid])}]}
        after 50
    }
    set wall [expr {([clock milliseconds] - $t0) / 1000.0}]
    set chan [open $errFile r]
    set err [read $chan]
    close $chan
    if {[llength $timer]} {
        set chan [open $timeFile r]
        set hwm [lindex [split [string trim [read $chan]] \n] end]
        close $chan
    }
    file delete $errFile $timeFile
    list $wall [expr {$hwm / 1024.0}] $err
}

# ::bench::VmHWM -- Returns the peak resident set (kB) of process pid, 0 when gone.
proc ::bench::VmHWM {pid} {
    if {[catch {open /proc/$pid/status r} chan]} {return 0}
    set text [read $chan]
    close $chan
    if {[regexp {VmHWM:\s+(\d+)} $text -> kb]} {return $kb}
    return 0
}

# ::bench::ProcState -- Returns the state letter of process pid ("Z" when gone).
proc ::bench::ProcState {pid} {
    if {[catch {open /proc/$pid/stat r} chan]} {return Z}
    set text [read $chan]
    close $chan
    lindex [string range $text [string last ) $text]+2 end] 0
}

# ::bench::Records -- Returns the CL records replay read, from its summary text err.
proc ::bench::Records {err} {
    if {![regexp {fivax: (\d+) records read} $err -> n]} {
        error "replay failed:\n$err"
    }
    return $n
}

# ::bench::Loop --
#	The minimal loop: reads the GOTO records of CL file cl (scan), takes
#	the first inverse solution (kin orientations, position) on machine
#	file machineFile and writes one G1 block a point to out.
proc ::bench::Loop {machineFile cl out} {
    set model [::fivax::kin::model [::fivax::machine::load $machineFile] 75]
    namespace upvar ::fivax::num pi pi
    set toDeg [expr {180.0 / $pi}]
    set in [open $cl r]
    set o [open $out w]
    chan configure $o -translation lf -buffersize 1048576
    set t {0.0 0.0 1.0}
    set n 0
    while {[gets $in line] >= 0} {
        if {[string range $line 0 4] ne "GOTO/"} continue
        set k [scan [string range $line 5 end] %f,%f,%f,%f,%f,%f x y z i j kk]
        if {$k == 6} {set t [list $i $j $kk]}
        set q [lindex [::fivax::kin::orientations $model $t] 1 0]
        lassign [::fivax::kin::position $model [list $x $y $z] $q] X Y Z
        lassign $q b c
        puts $o [format "G1 X%.3f Y%.3f Z%.3f B%.3f C%.3f" $X $Y $Z \
            [expr {$b * $toDeg}] [expr {$c * $toDeg}]]
        incr n
    }
    close $in
    close $o
    puts stderr "fivax: $n records read"
}

# ::bench::Fused --
#	The fused floor: every step the default post takes on a plain feed
#	GOTO, in two straight loops with no post structure (no MOM runtime, no
#	handlers, no move records), to show what pure Tcl can reach at best.
#	Post (FusedPost) then check (FusedCheck), one process; the time of
#	each on stderr.
proc ::bench::Fused {machineFile cl out} {
    set machine [::fivax::machine::load $machineFile]
    set model [::fivax::kin::model $machine 75]
    set t0 [clock microseconds]
    lassign [FusedPost $model $machine $cl $out] n over
    set t1 [clock microseconds]
    set bad [FusedCheck $model $cl $out]
    set t2 [clock microseconds]
    puts stderr [format "fivax: %d records read; post %.2f s (%d moves over the tolerance), check %.2f s (%d blocks off)" \
        $n [expr {($t1 - $t0) / 1e6}] $over [expr {($t2 - $t1) / 1e6}] $bad]
}

# ::bench::FusedPost --
#	The posting half of the fused floor: scan each GOTO of cl; both
#	inverse solutions, each solution's aliases nearest the last rotaries,
#	the nearest pair within the limits (else the nearest) rounded to
#	0.001 deg; X Y Z; the interpolation bound of the move; its
#	inverse-time feed; the changed words with a sequence number, and F;
#	written to out. Returns {GOTOs read, moves the bound puts over 0.01 mm
#	or 0.05 deg} (the post would split those).
proc ::bench::FusedPost {model machine cl out} {
    lassign [lmap a [dict get $machine chain] {list [dict get $a min] [dict get $a max]}] l1 l2
    lassign $l1 min1 max1
    lassign $l2 min2 max2
    namespace upvar ::fivax::num pi pi
    set toDeg [expr {180.0 / $pi}]
    set step [expr {0.001 / $toDeg}]
    set atol [expr {0.05 / $toDeg}]
    set over 0
    set in [open $cl r]
    set o [open $out w]
    chan configure $o -translation lf -buffersize 1048576
    array set last {X "" Y "" Z "" B "" C ""}
    set t {0.0 0.0 1.0}
    set feed 1000.0
    set g1 0.0
    set g2 0.0
    set J {0.0 0.0 0.0 0.0 0.0}
    set P {0.0 0.0 0.0}
    set T $t
    set n 0
    set seq 0
    while {[gets $in line] >= 0} {
        if {[string range $line 0 4] ne "GOTO/"} {
            scan $line FEDRAT/MMPM,%f feed
            continue
        }
        if {[scan [string range $line 5 end] %f,%f,%f,%f,%f,%f x y z i j k] == 6} {
            set t [list $i $j $k]
        }
        set best {}
        set any {}
        set bd Inf
        set ad Inf
        # (the planner's own alias and rounding procs)
        foreach sol [lindex [::fivax::kin::orientations $model $t] 1] {
            lassign $sol a b
            set a [::fivax::motion::Near $a $g1]
            set b [::fivax::motion::Near $b $g2]
            set d [expr {($a > $g1 ? $a - $g1 : $g1 - $a) + ($b > $g2 ? $b - $g2 : $g2 - $b)}]
            if {$a >= $min1 && $a <= $max1 && $b >= $min2 && $b <= $max2} {
                if {$d < $bd} {set bd $d; set best [list $a $b]}
            } elseif {$d < $ad} {
                set ad $d
                set any [list $a $b]
            }
        }
        if {$best eq ""} {set best $any}
        # rotaries at the output resolution (0.001 deg) before X Y Z
        set best [::fivax::motion::Quantize $step {*}$best]
        lassign $best g1 g2
        set P0 $P
        set P [list $x $y $z]
        lassign [::fivax::kin::position $model $P $best] X Y Z
        set J0 $J
        set J [list $X $Y $Z $g1 $g2]
        lassign [::fivax::kin::interpolationBound $model $J0 $J $P0 $P $T $t 5e-4 1e-5] bp ba
        if {$bp > 0.01 || $ba > $atol} {incr over}
        set T $t
        lassign $P0 x0 y0 z0
        set len [expr {sqrt(($x - $x0) ** 2 + ($y - $y0) ** 2 + ($z - $z0) ** 2)}]
        set F [expr {$len > 0.0 ? $feed / $len : $feed}]
        set words N[incr seq 10]
        foreach a {X Y Z B C} v [list $X $Y $Z [expr {$g1 * $toDeg}] [expr {$g2 * $toDeg}]] {
            set s [format %.3f $v]
            if {$s ne $last($a)} {
                set last($a) $s
                append words " " $a $s
            }
        }
        # (inverse time: F in every block)
        puts $o [format "%s F%.3f" $words $F]
        incr n
    }
    close $in
    close $o
    list $n $over
}

# ::bench::FusedCheck --
#	The checking half of the fused floor: reads each block of out back
#	(scan), beside its GOTO of cl; forward kinematics of the written
#	values against the CL point and axis (0.01 mm, 0.05 deg) and the
#	interpolation bound of the written move. Returns the blocks off in
#	either.
proc ::bench::FusedCheck {model cl out} {
    namespace upvar ::fivax::num pi pi
    set toRad [expr {$pi / 180.0}]
    set atol [expr {0.05 * $toRad}]
    set in [open $cl r]
    set nc [open $out r]
    set j {0.0 0.0 0.0 0.0 0.0}
    set t {0.0 0.0 1.0}
    set P {0.0 0.0 0.0}
    set T $t
    set J $j
    set bad 0
    while {[gets $nc block] >= 0} {
        while {[gets $in line] >= 0 && [string range $line 0 4] ne "GOTO/"} {}
        if {[scan [string range $line 5 end] %f,%f,%f,%f,%f,%f x y z i k l] == 6} {
            set t [list $i $k $l]
        }
        foreach word [split $block " "] {
            scan $word %c%f letter value
            switch -- $letter {
                88 {lset j 0 $value}
                89 {lset j 1 $value}
                90 {lset j 2 $value}
                66 {lset j 3 [expr {$value * $toRad}]}
                67 {lset j 4 [expr {$value * $toRad}]}
            }
        }
        lassign [::fivax::kin::forward $model $j] fP fT
        lassign $fP a b c
        lassign $fT u v w
        lassign $t p q r
        # (0.99999961923 is cos 0.05 deg)
        if {($a - $x) ** 2 + ($b - $y) ** 2 + ($c - $z) ** 2 > 1e-4
                || $u * $p + $v * $q + $w * $r < 0.99999961923} {
            incr bad
        }
        set P0 $P
        set P [list $x $y $z]
        set J0 $J
        set J $j
        lassign [::fivax::kin::interpolationBound $model $J0 $J $P0 $P $T $t 5e-4 1e-5] bp ba
        if {$bp > 0.01 || $ba > $atol} {incr bad}
        set T $t
    }
    close $in
    close $nc
    return $bad
}

# ::bench::NoCheck --
#	Runs tools/replay.tcl with the command line words, the post's block
#	check replaced by a no-op in the post interpreter.
proc ::bench::NoCheck {words} {
    variable ::root
    rename ::fivax::mom::create ::fivax::mom::BenchCreate
    proc ::fivax::mom::create {args} {
        set rt [::fivax::mom::BenchCreate {*}$args]
        [$rt interp] eval {oo::define ::fivax::verify::Checker method block {line move} {}}
        return $rt
    }
    uplevel #0 [list source [file join $root tools replay.tcl]]
    ::replay::main $words
}

# ::bench::Mb -- Returns megabytes mb printed for the table.
proc ::bench::Mb {mb} {
    format %.0f $mb
}

# ::bench::main -- Generates the files, runs every row, prints the table.
proc ::bench::main {argv} {
    variable options
    variable ::root
    switch -- [lindex $argv 0] {
        -loop {return [Loop {*}[lrange $argv 1 end]]}
        -nocheck {return [NoCheck [lrange $argv 1 end]]}
        -fused {return [Fused {*}[lrange $argv 1 end]]}
    }
    try {
        lassign [::fivax::opts argv $options $argv bench] opts rest
    } trap {FIVAX OPTION} {msg} {
        puts stderr $msg
        exit 1
    }
    if {[dict get $opts -help] || [llength $rest]} {
        puts "usage: tclsh tools/bench.tcl ?options?\n\nEnd-to-end replay speed on generated CL files.\nOptions:\n[::fivax::opts help $options]"
        exit [expr {[llength $rest] > 0}]
    }
    set sizes [dict get $opts -sizes]
    foreach n $sizes {
        if {![string is entier -strict $n] || $n < 1000} {
            puts stderr "bench: bad -sizes \"$sizes\": must be numbers of points >= 1000"
            exit 1
        }
    }
    try {
        set machineFile [::fivax::machine find [dict get $opts -machine]]
        if {$machineFile eq ""} {set machineFile [file join $root machines hh-tilt45.tcl]}
        set machineFile [file normalize $machineFile]
        set name [dict get [::fivax::machine load $machineFile] name]
    } trap {FIVAX MACHINE} {msg} {
        puts stderr "bench: $msg"
        exit 1
    }
    set dir [file join [expr {[info exists ::env(TMPDIR)] ? $::env(TMPDIR) : "/tmp"}] \
        fivax-bench-[pid]]
    file mkdir $dir
    set tclsh [info nameofexecutable]
    set replay [file join $root tools replay.tcl]
    set bench [file join $root tools bench.tcl]
    set stock [file join $root tests data pbstyle pbstyle.tcl]
    try {
        set t0 [clock milliseconds]
        set files [Generate $sizes $dir]
        puts [format "bench: %s; files generated in %.1f s; Tcl %s, %s, %s" $name \
            [expr {([clock milliseconds] - $t0) / 1000.0}] [info patchlevel] \
            [exec uname -m] [clock format [clock seconds] -format %Y-%m-%d]]
        puts [format "%-9s %-18s %9s %12s %9s %8s" points run records records/s "wall s" "RSS MB"]
        foreach n $sizes {
            set cl [dict get $files $n]
            set out [file join $dir bench.nc]
            set rows [list \
                replay [list $tclsh $replay -machine $machineFile -o $out $cl] \
                "one process" [list $tclsh $replay -machine $machineFile -check-process off -o $out $cl] \
                "-tol 0, no check" [list $tclsh $bench -nocheck -machine $machineFile -tol 0 \
                    -check-process off -o $out $cl] \
                "fused floor" [list $tclsh $bench -fused $machineFile $cl $out] \
                minimal [list $tclsh $bench -loop $machineFile $cl $out] \
                "stock-style post" [list $tclsh $replay -post $stock -o $out $cl]]
            set rates {}
            foreach {label words} $rows {
                lassign [Run $words] wall mb err
                set records [Records $err]
                set rate [expr {$records / $wall}]
                lappend rates $rate
                puts [format "%-9d %-18s %9d %12.0f %9.2f %8s" $n $label $records $rate $wall [Mb $mb]]
                file delete $out [file rootname $out].log
            }
            lassign $rates replayRate oneRate nocheckRate floorRate minimalRate stockRate
            puts [format "%-9s %-18s %.1f (%.1f in one process)" "" "floor / replay" \
                [expr {$floorRate / $replayRate}] [expr {$floorRate / $oneRate}]]
            puts [format "%-9s %-18s %s" "" "minimal / replay" \
                [format "%.1f (%.1f in one process, %.1f without linearisation and check)" \
                    [expr {$minimalRate / $replayRate}] [expr {$minimalRate / $oneRate}] \
                    [expr {$minimalRate / $nocheckRate}]]]
            puts [format "%-9s %-18s %.2f" "" "stock / one proc." [expr {$stockRate / $oneRate}]]
        }
    } finally {
        file delete -force $dir
    }
}

::bench::main $argv
