# kinerr.tcl --
#	Rotary-axis error analysis of an NC program on any machine: for given
#	angular errors of the rotaries (constant, or signed by each axis's
#	direction of motion), the tool tip error (vector in the workpiece
#	frame and its length) and the tool axis orientation error (degrees)
#	at every cutting block (G1): max, mean and where, for the program and
#	for each tool (each tool's length from the program's FIVAX TOOL
#	comments or a tool table, as the dry run takes it); optionally a CSV
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
        {-tool-length {maybe real} {} MM "tool length of every tool (default: each tool's from -tools, else the program's FIVAX TOOL comments, else the machine's tool_length)"}
        {-tools text {} FILE "tool table: lines \"T<n> LENGTH <L> ?RADIUS <R>?\" (# comments)"}
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
#	Returns {lines jointsList models tools}: the NC line numbers, joint
#	vectors, kin models and tools {number length} of the cutting blocks
#	(G1 with axis words) of the file at path, read by checker with the
#	tool lengths the follower tooling (fivax::dryrun tooling) finds ("":
#	the machine's). Errors: {FIVAX TOOL COMMENT} at a FIVAX TOOL comment
#	it cannot read.
proc ::kinerrtool::Blocks {checker path tooling} {
    set lines {}
    set joints {}
    set models {}
    set tools {}
    set warned {}
    set length ""
    set n 0
    set chan [::fivax::nctool open $path]
    try {
        while {[gets $chan line] >= 0} {
            incr n
            set blk [$checker read $line]
            set tooling [::fivax::dryrun toolStep $tooling $blk]
            foreach note [dict get $tooling notes] {
                lassign $note kind what
                if {$kind eq "unreadable"} {::fivax::Fail TOOL COMMENT "$path:$n: $what"}
                puts stderr "kinerr: $path:$n: warning: $what; computed with [dict get $tooling length]"
            }
            if {[dict get $tooling length] ne $length} {
                set length [dict get $tooling length]
                $checker setTool $length
            }
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
                lappend models [$checker model]
                lappend tools [list [dict get $tooling tool] [dict get [$checker model] toolLength]]
            }
        }
    } finally {
        close $chan
    }
    list $lines $joints $models $tools
}

# ::kinerrtool::Report --
#	Prints the tip and axis error figures (max and where, mean) of rows
#	(as kinerr path returns) at NC lines of the file at path, after the
#	text what.
proc ::kinerrtool::Report {what path rows lines} {
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
    puts [format "kinerr: %stip error max %.6f mm at %s, mean %.6f mm" $what [lindex $max 0] \
        [lindex $at 0] [expr {[lindex $sum 0] / $n}]]
    puts [format "kinerr: %saxis error max %.6f deg at %s, mean %.6f deg" $what [lindex $max 1] \
        [lindex $at 1] [expr {[lindex $sum 1] / $n}]]
}

# ::kinerrtool::ReportTools --
#	Prints the figures of each tool {number length} of toolOf (one per
#	row) apart, in the order they come, when there are several.
proc ::kinerrtool::ReportTools {path rows lines toolOf} {
    set groups {}
    foreach tool $toolOf {
        if {$tool ni $groups} {lappend groups $tool}
    }
    if {[llength $groups] < 2} return
    foreach tool $groups {
        lassign $tool number length
        set idx [lsearch -all -exact $toolOf $tool]
        Report [format "tool %s (length %s, %d blocks): " [expr {$number eq "" ? "?" : $number}] \
            [::fivax::num::fixed $length 3] [llength $idx]] \
            $path [lmap i $idx {lindex $rows $i}] [lmap i $idx {lindex $lines $i}]
    }
}

# ::kinerrtool::Plot --
#	Returns the SVG of the rows at NC lines of the file at path: the tip
#	error (mm) and the axis error (deg) each in its own panel, along the
#	NC lines, the worst lines marked.
proc ::kinerrtool::Plot {title path rows lines} {
    set panels {}
    foreach k {3 4} what {"tip error dpos" "axis error dangle"} unit {mm deg} {
        set ys [lmap r $rows {lindex $r $k}]
        lappend panels [list -ylabel "$what ($unit)" -series [list [list "$what ($unit)" $lines $ys]] \
            -marks [::fivax::svgplot worst $lines $ys 3 "line "]]
    }
    ::fivax::svgplot panels -title $title -xlabel "NC line of the cutting block ([file tail $path])" \
        -panels $panels
}

# ::kinerrtool::main -- Parses argv, computes and reports the errors.
proc ::kinerrtool::main {argv} {
    lassign [ParseArgs $argv] opts path
    try {
        set machine [::fivax::machine load [dict get $opts -machine]]
        set errors [Errors $machine [dict get $opts -d]]
        set tools [::fivax::nctool toolTable [dict get $opts -tools]]
        set checker [::fivax::verify create $machine -table-offset [dict get $opts -table-offset] \
            -controller [dict get $opts -controller]]
        lassign [Blocks $checker $path [::fivax::dryrun tooling $tools [dict get $opts -tool-length]]] \
            lines joints models toolOf
        set rows [::fivax::kinerr path $models $joints $errors [dict get $opts -mode]]
        $checker destroy
    } trap {FIVAX} {msg} {
        ::fivax::nctool die "kinerr: $msg"
    }
    if {![llength $rows]} {::fivax::nctool die "kinerr: $path: no cutting blocks (G1 with axis words)"}
    set names [lmap a [dict get $machine chain] {dict get $a name}]
    if {![dict get $opts -quiet]} {
        puts [format "kinerr: %s on %s, %s %s deg, %s %s deg (%s): %d cutting blocks" \
            [file tail $path] [dict get $machine name] [lindex $names 0] \
            [::fivax::num::deg [lindex $errors 0]] [lindex $names 1] \
            [::fivax::num::deg [lindex $errors 1]] [dict get $opts -mode] [llength $rows]]
        Report "" $path $rows $lines
        ReportTools $path $rows $lines $toolOf
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
            set title [format "Rotary-axis error on %s: %s %g deg, %s %g deg (%s)" \
                [dict get $machine name] [lindex $names 0] [::fivax::num::deg [lindex $errors 0]] \
                [lindex $names 1] [::fivax::num::deg [lindex $errors 1]] [dict get $opts -mode]]
            ::fivax::svgplot write [dict get $opts -svg] [Plot $title $path $rows $lines]
            if {![dict get $opts -quiet]} {puts "kinerr: wrote [dict get $opts -svg]"}
        }
    } trap {POSIX} {msg} {
        ::fivax::nctool die "kinerr: cannot write: $msg"
    }
}

::kinerrtool::main $argv
