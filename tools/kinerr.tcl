# kinerr.tcl --
#	Rotary-axis error analysis of an NC program on any machine: for given
#	angular errors of the rotaries (constant, or signed by each axis's
#	direction of motion), the tool tip error (vector in the workpiece
#	frame and its length) and the tool axis orientation error (degrees)
#	at every cutting block (G1): max, mean and where; optionally a CSV
#	(line,dx,dy,dz,dpos,dangle) and an SVG plot of both along the path.
#
#	tclsh tools/kinerr.tcl -machine M.tcl -d B=0.01 -d C=0.02 ?options? part.nc   (-help)

package require Tcl 8.6

set root [file dirname [file dirname [file normalize [info script]]]]
set auto_path [linsert $auto_path 0 [file join $root lib]]
package require fivax 0.1
foreach f {nctool.tcl svgplot.tcl rotaryerr.tcl} {
    source [file join $root tools lib $f]
}

namespace eval ::kinerrtool {
    variable Options {
        {-machine text {} FILE "machine file, or a shipped machine's name: dmu125p is machines/dmu125p.tcl (required)"}
        {-d {many text} {} AXIS=DEG "angular error of a rotary axis, e.g. -d B=0.01"}
        {-mode {enum constant direction} constant MODE "errors constant, or signed by each axis's direction of motion"}
        {-controller {maybe word} {} NAME "dialect of the NC text (default: the machine's controller)"}
        {-tool-length {maybe real} {} MM "tool length (default: the machine's tool_length)"}
        {-table-offset {maybe vec3} {} "X Y Z" "workpiece-frame position of the table reference point"}
        {-csv text {} FILE "write line,dx,dy,dz,dpos,dangle per cutting block"}
        {-svg text {} FILE "write the error curves as SVG"}
        {-quiet bool 0 "" "print nothing but errors"}
        {-help bool 0 "" "print this help"}
    }
}

# ::kinerrtool::ParseArgs -- Returns {opts ncPath} from argv.
proc ::kinerrtool::ParseArgs {argv} {
    variable Options
    lassign [::fivax::nctool args $Options $argv kinerr \
        "tclsh tools/kinerr.tcl -machine M.tcl -d AXIS=DEG ... ?options? part.nc" \
        "Tip and axis error of rotary-axis errors along an NC program." 1 -machine] opts rest
    list $opts [lindex $rest 0]
}

# ::kinerrtool::Errors --
#	Returns {e1 e2}: the rotary errors (radians, chain order) of the -d
#	values for machine. Unknown axes and bad numbers exit with a message.
proc ::kinerrtool::Errors {machine items} {
    set names [lmap a [dict get $machine chain] {dict get $a name}]
    set errors {0.0 0.0}
    foreach item $items {
        if {![regexp {^\s*([A-Za-z][A-Za-z0-9_]*)\s*=\s*(\S+)\s*$} $item -> name value]
                || [set v [::fivax::num::parse $value]] eq ""} {
            ::fivax::nctool die "kinerr: bad -d \"$item\": must be AXIS=DEG, e.g. B=0.01"
        }
        set i [lsearch -exact $names $name]
        if {$i < 0} {
            ::fivax::nctool die "kinerr: bad -d \"$item\": [dict get $machine name] has no rotary axis $name\
                (axes: [join $names {, }])"
        }
        lset errors $i [::fivax::num::rad $v]
    }
    if {![llength $items]} {::fivax::nctool die "kinerr: give at least one -d AXIS=DEG"}
    return $errors
}

# ::kinerrtool::Blocks --
#	Returns {lines jointsList}: the NC line numbers and joint vectors of
#	the cutting blocks (G1 with axis words) of the file at path.
proc ::kinerrtool::Blocks {checker path} {
    set lines {}
    set joints {}
    set warned {}
    set n 0
    set chan [::fivax::nctool open $path]
    try {
        while {[gets $chan line] >= 0} {
            incr n
            set blk [$checker read $line]
            foreach {kind word} [dict get $blk unknown] {
                if {$kind ni $warned} {
                    puts stderr "kinerr: warning: $path:$n: $kind not understood ($word); read as if absent"
                    lappend warned $kind
                }
            }
            if {[dict get $blk motion] eq "1" && [llength [dict get $blk moved]]
                    && [dict get $blk joints] ne ""} {
                lappend lines $n
                lappend joints [dict get $blk joints]
            }
        }
    } finally {
        close $chan
    }
    list $lines $joints
}

# ::kinerrtool::main -- Parses argv, computes and reports the errors.
proc ::kinerrtool::main {argv} {
    lassign [ParseArgs $argv] opts path
    try {
        set machine [::fivax::machine load [dict get $opts -machine]]
        set errors [Errors $machine [dict get $opts -d]]
        set checker [::fivax::verify create $machine -table-offset [dict get $opts -table-offset] \
            -controller [dict get $opts -controller]]
        $checker setTool [dict get $opts -tool-length]
        lassign [Blocks $checker $path] lines joints
        set rows [::fivax::kinerr path [$checker model] $joints $errors [dict get $opts -mode]]
        $checker destroy
    } trap {FIVAX} {msg} {
        ::fivax::nctool die "kinerr: $msg"
    }
    if {![llength $rows]} {::fivax::nctool die "kinerr: $path: no cutting blocks (G1 with axis words)"}
    set names [lmap a [dict get $machine chain] {dict get $a name}]
    set sum {0.0 0.0}
    set max {-1 -1}
    set at {{} {}}
    foreach row $rows line $lines {
        foreach k {0 1} v [lrange $row 3 4] {
            lset sum $k [expr {[lindex $sum $k] + $v}]
            if {$v > [lindex $max $k]} {lset max $k $v; lset at $k $path:$line}
        }
    }
    set n [llength $rows]
    if {![dict get $opts -quiet]} {
        puts [format "kinerr: %s on %s, %s %s deg, %s %s deg (%s): %d cutting blocks" \
            [file tail $path] [dict get $machine name] [lindex $names 0] \
            [::fivax::num::deg [lindex $errors 0]] [lindex $names 1] \
            [::fivax::num::deg [lindex $errors 1]] [dict get $opts -mode] $n]
        puts [format "kinerr: tip error max %.6f mm at %s, mean %.6f mm" [lindex $max 0] \
            [lindex $at 0] [expr {[lindex $sum 0] / $n}]]
        puts [format "kinerr: axis error max %.6f deg at %s, mean %.6f deg" [lindex $max 1] \
            [lindex $at 1] [expr {[lindex $sum 1] / $n}]]
    }
    try {
        if {[dict get $opts -csv] ne ""} {
            set out {line,dx,dy,dz,dpos,dangle}
            foreach row $rows line $lines {
                lappend out [join [concat $line [lmap v $row {format %.6f $v}]] ,]
            }
            ::fivax::nctool writeLines [dict get $opts -csv] $out
            if {![dict get $opts -quiet]} {puts "kinerr: wrote [dict get $opts -csv]"}
        }
        if {[dict get $opts -svg] ne ""} {
            set idx [lsearch -all $rows *]
            set svg [::fivax::svgplot chart \
                -title [format "Rotary-axis error on %s: %s %g deg, %s %g deg (%s)" \
                    [dict get $machine name] [lindex $names 0] [::fivax::num::deg [lindex $errors 0]] \
                    [lindex $names 1] [::fivax::num::deg [lindex $errors 1]] [dict get $opts -mode]] \
                -xlabel "cutting block (G1, in file order)" -ylabel "error (tip: mm, axis: deg)" \
                -series [list [list "tip error dpos (mm)" $idx [lmap r $rows {lindex $r 3}]] \
                             [list "axis error dangle (deg)" $idx [lmap r $rows {lindex $r 4}]]]]
            ::fivax::svgplot write [dict get $opts -svg] $svg
            if {![dict get $opts -quiet]} {puts "kinerr: wrote [dict get $opts -svg]"}
        }
    } trap {POSIX} {msg} {
        ::fivax::nctool die "kinerr: cannot write: $msg"
    }
}

::kinerrtool::main $argv
