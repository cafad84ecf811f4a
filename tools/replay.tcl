# replay.tcl --
#	Replays a CLSF file through the fivax post (post/fivax.tcl) outside NX,
#	emulating NX's MOM runtime, and writes the NC program.
#
#	tclsh tools/replay.tcl ?options? part.cls     ("-" reads standard input)
#	Run with -help for the options: the posting job's settings
#	([fivax::settings table], the same table the post reads) plus -o and
#	-quiet.

package require Tcl 8.6

set root [file dirname [file dirname [file normalize [info script]]]]
set auto_path [linsert $auto_path 0 [file join $root lib]]
package require fivax 0.1

namespace eval ::replay {
    # Options of the command line only; the others are the job settings.
    variable cliOptions {
        {-o text {} FILE "output NC file (default: standard output)"}
        {-quiet bool 0 "" "no summary on standard error"}
        {-help bool 0 "" "print this help"}
    }
}

# ::replay::Die -- Prints msg on standard error and exits with status 1.
proc ::replay::Die {msg} {
    puts stderr $msg
    exit 1
}

# ::replay::Table -- Returns the command line's option table.
proc ::replay::Table {} {
    variable cliOptions
    concat [::fivax::settings table] $cliOptions
}

# ::replay::ParseArgs -- Returns the option dict and the CLSF path from argv.
proc ::replay::ParseArgs {argv} {
    try {
        lassign [::fivax::opts argv [Table] $argv replay] opts rest
    } trap {FIVAX OPTION} {msg} {
        Die $msg
    }
    if {[dict get $opts -help]} {
        puts "usage: tclsh tools/replay.tcl ?options? part.cls\n\nReplays an NX CLSF file through the fivax post.\nOptions:\n[::fivax::opts help [Table]]"
        exit 0
    }
    if {[llength $rest] != 1} {
        Die "usage: tclsh tools/replay.tcl ?options? part.cls (-help for the options)"
    }
    list $opts [lindex $rest 0]
}

# ::replay::Listing -- Prints a listing line of the post on stderr (the summary is printed apart).
proc ::replay::Listing {text} {
    if {![string match "fivax summary:*" $text]} {puts stderr $text}
}

# ::replay::Post --
#	Runs the post on clsf with the job settings, writing NC text to
#	channel chan. Returns the runtime statistics merged with the post's
#	summary.
proc ::replay::Post {settings clsf chan out} {
    variable ::root
    set globals [dict create fivax_settings $settings]
    if {$out ne ""} {
        # the output file as NX names it to the post
        set out [file normalize $out]
        dict set globals mom_output_file_full_name $out
        dict set globals mom_output_file_directory [file dirname $out]
        dict set globals mom_output_file_basename [file rootname [file tail $out]]
        dict set globals mom_output_file_suffix [string trimleft [file extension $out] .]
    }
    set rt [::fivax::mom create -post [file join $root post fivax.tcl] \
        -def [file join $root post fivax.def] -channel $chan \
        -listing ::replay::Listing -globals $globals \
        -autopath [list [file join $root lib] [info library]]]
    try {
        set stats [$rt run $clsf]
        set child [$rt interp]
        if {[$child eval {info exists ::fivax_summary}]} {
            set stats [dict merge $stats [$child eval {set ::fivax_summary}]]
        }
        return $stats
    } finally {
        $rt destroy
    }
}

# ::replay::Summary -- Prints the run's figures on standard error.
proc ::replay::Summary {stats} {
    dict with stats {}
    puts stderr [format "fivax: %d records read, %d blocks written, %d warnings" \
        $records $blocks $warnings]
    if {[info exists checked]} {
        puts stderr [format "fivax: %d CL points checked by forward kinematics: max deviation %.6f mm, %.6f deg" \
            $checked $maxPos $maxAng]
        puts stderr [format "fivax: %d cutting moves checked at quarter points: max deviation %.6f mm, %.6f deg; %d rotary values outside limits" \
            $segments $maxMidPos $maxMidAng $limitViolations]
    }
    if {[info exists inserted]} {
        puts stderr [format "fivax: %d points inserted, %d retracts, rotary travel %.3f deg; %d azimuth holds, %d singular swings, %d moves left out of tolerance" \
            $inserted $retracts $travel $holds $swings $unresolved]
        puts stderr [format "fivax: %d tool changes; %d dwell swings (rotaries turning %.3f deg with the tip in place); %d inverse-time feeds clamped at the machine's maximum (worst %.2f times slower than programmed)" \
            $toolChanges $dwells $dwellTurn $clamps $slowdown]
    }
}

# ::replay::main -- Parses argv, posts the file, and renames the output into place.
proc ::replay::main {argv} {
    variable ::root
    lassign [ParseArgs $argv] opts clsf
    set settings [dict filter $opts key {*}[::fivax::opts names [::fivax::settings table]]]
    set machine [dict get $settings -machine]
    if {$machine eq ""} {
        set machine [file join $root machines hh-tilt45.tcl]
        dict set settings -machine $machine
    }
    if {![file readable $machine]} {Die "$machine: machine file not found"}
    if {$clsf ne "-" && ![file readable $clsf]} {Die "$clsf: cannot read CL file"}
    puts stderr "fivax: posting for machine [file normalize $machine]"
    set out [dict get $opts -o]
    if {$out ne "" && [file isdirectory $out]} {Die "replay: -o $out: is a directory"}
    set dir [expr {$out eq "" ? [pwd] : [file dirname [file normalize $out]]}]
    set tmp [file join $dir .fivax-[pid]-[clock clicks].tmp]
    try {
        set chan [open $tmp w]
    } trap {POSIX} {msg} {
        Die "replay: cannot write [expr {$out eq "" ? "in [pwd]" : $out}]: [lindex [split $msg :] end]"
    }
    fconfigure $chan -translation lf -encoding utf-8
    # the post's log (warnings, retracts, errors) goes beside the NC file
    # under the same rule: a temporary name, kept only when the run succeeds
    set log ""
    if {$out ne "" && [dict get $settings -log] eq ""} {
        set log [file rootname [file normalize $out]].log
        dict set settings -log $tmp.log
    }
    try {
        set stats [Post $settings $clsf $chan $out]
        close $chan
        if {[dict exists $stats limitViolations] && [dict get $stats limitViolations] > 0} {
            # A safety net: the planner never writes such a value.
            error "[dict get $stats limitViolations] rotary values outside the machine's limits; no NC file written"
        }
    } on error {msg} {
        if {$chan in [chan names]} {close $chan}
        file delete -force $tmp $tmp.log
        Die $msg
    }
    if {$log ne "" && [file exists $tmp.log]} {file rename -force $tmp.log $log}
    if {$out eq ""} {
        set in [open $tmp r]
        fconfigure stdout -translation lf
        fcopy $in stdout
        close $in
        file delete $tmp
    } else {
        file rename -force $tmp $out
    }
    if {![dict get $opts -quiet]} {Summary $stats}
}

::replay::main $argv
