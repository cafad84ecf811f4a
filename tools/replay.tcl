# replay.tcl --
#	Replays a CLSF file through the fivax post (post/fivax.tcl) outside NX,
#	emulating NX's MOM runtime, and writes the NC program.
#
#	tclsh tools/replay.tcl ?options? part.cls
#	Run with -help for the options.

package require Tcl 8.6

set root [file dirname [file dirname [file normalize [info script]]]]
set auto_path [linsert $auto_path 0 [file join $root lib]]
package require fivax 0.1
package require cmdline

namespace eval ::replay {
    variable options {
        {machine.arg      "" "machine file (default machines/hh-tilt45.tcl)"}
        {o.arg            "" "output NC file (default: standard output)"}
        {controller.arg   "" "controller dialect: fanuc or linuxcnc (default: the machine's)"}
        {table-offset.arg "" "workpiece origin for the table axes: \"x y z\" in mm (default: the machine's)"}
        {msys                "express the CL data in the frame of the file's MSYS record"}
        {feed.arg  inverse   "feed on rotary moves: inverse (G93), direct (mm/min) or dpm (degrees per minute)"}
        {rotary.arg optimal  "rotary solution choice: optimal (whole path) or greedy"}
        {on-limit.arg retract "no in-limit continuation: retract (retract, reposition, re-engage) or error"}
        {tol.arg   0.01      "linearisation tolerance of the tool tip, mm (0: no linearisation)"}
        {clearance.arg ""    "retract distance along the tool axis, mm (default: the machine's)"}
        {quiet               "no summary on standard error"}
    }
    variable usage "?options? part.cls\n\nReplays an NX CLSF file through the fivax post.\nOptions:"
}

# ::replay::Die -- Prints msg on standard error and exits with status 1.
proc ::replay::Die {msg} {
    puts stderr $msg
    exit 1
}

# ::replay::ParseArgs -- Returns the option dict and the CLSF path from argv.
proc ::replay::ParseArgs {argv} {
    variable options
    variable usage
    try {
        set opts [::cmdline::getoptions argv $options $usage]
    } trap {CMDLINE USAGE} {msg} {
        puts $msg
        exit 0
    } trap {CMDLINE} {msg} {
        Die $msg
    }
    if {[llength $argv] != 1} {
        Die "usage: tclsh tools/replay.tcl [::cmdline::usage $options $usage]"
    }
    list $opts [lindex $argv 0]
}

# ::replay::Settings -- Returns the post settings dict from the validated options.
proc ::replay::Settings {opts} {
    variable ::root
    set machine [dict get $opts machine]
    if {$machine eq ""} {
        set machine [file join $root machines hh-tilt45.tcl]
    }
    set offset [dict get $opts table-offset]
    if {$offset ne ""} {
        if {![string is list $offset] || [llength $offset] != 3} {
            Die "-table-offset: expected three numbers \"x y z\", got '$offset'"
        }
        set offset [lmap v $offset {
            set x [::fivax::parseReal $v]
            if {$x eq ""} {Die "-table-offset: '$v' is not a number"}
            set x
        }]
    }
    set controller [dict get $opts controller]
    if {$controller ni {"" fanuc linuxcnc}} {
        Die "-controller: unknown controller '$controller': must be fanuc or linuxcnc"
    }
    foreach {key choices} {feed {inverse direct dpm} rotary {optimal greedy}
        on-limit {retract error}} {
        if {[dict get $opts $key] ni $choices} {
            Die "-$key: '[dict get $opts $key]': must be [join $choices { or }]"
        }
    }
    foreach key {tol clearance} {
        set v [dict get $opts $key]
        if {$v ne "" && ([::fivax::parseReal $v] eq "" || [::fivax::parseReal $v] < 0)} {
            Die "-$key: '$v' is not a number >= 0"
        }
    }
    dict create machine $machine controller $controller table_offset $offset \
        msys [dict get $opts msys] feed_mode [dict get $opts feed] \
        rotary [dict get $opts rotary] on_limit [dict get $opts on-limit] \
        tol [dict get $opts tol] clearance [dict get $opts clearance]
}

# ::replay::Listing -- Prints a listing line of the post on stderr (the summary is printed apart).
proc ::replay::Listing {text} {
    if {![string match "fivax summary:*" $text]} {puts stderr $text}
}

# ::replay::Post --
#	Runs the post on clsf, writing NC text to channel chan. Returns the
#	runtime statistics merged with the post's summary.
proc ::replay::Post {settings clsf chan} {
    variable ::root
    set rt [::fivax::mom::create -post [file join $root post fivax.tcl] \
        -def [file join $root post fivax.def] -channel $chan \
        -listing ::replay::Listing \
        -globals [dict create fivax_settings $settings] \
        -autopath [list [file join $root lib] [info library]]]
    try {
        set stats [::fivax::mom::run $rt $clsf]
        set child [::fivax::mom::postInterp $rt]
        if {[$child eval {info exists ::fivax_summary}]} {
            set stats [dict merge $stats [$child eval {set ::fivax_summary}]]
        }
        return $stats
    } finally {
        ::fivax::mom::destroy $rt
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
    }
}

# ::replay::main -- Parses argv, posts the file, and renames the output into place.
proc ::replay::main {argv} {
    lassign [ParseArgs $argv] opts clsf
    set settings [Settings $opts]
    set machine [dict get $settings machine]
    if {![file readable $machine]} {Die "$machine: machine file not found"}
    if {![file readable $clsf]} {Die "$clsf: cannot read CL file"}
    puts stderr "fivax: posting for machine [file normalize $machine]"
    set out [dict get $opts o]
    set dir [expr {$out eq "" ? [pwd] : [file dirname [file normalize $out]]}]
    set tmp [file join $dir .fivax-[pid]-[clock clicks].tmp]
    set chan [open $tmp w]
    fconfigure $chan -translation lf -encoding utf-8
    try {
        set stats [Post $settings $clsf $chan]
        close $chan
        if {[dict exists $stats limitViolations] && [dict get $stats limitViolations] > 0} {
            # A safety net: the planner never writes such a value.
            error "[dict get $stats limitViolations] rotary values outside the machine's limits; no NC file written"
        }
    } on error {msg} {
        if {$chan in [chan names]} {close $chan}
        file delete -force $tmp
        Die $msg
    }
    if {$out eq ""} {
        set in [open $tmp r]
        fconfigure stdout -translation lf
        fcopy $in stdout
        close $in
        file delete $tmp
    } else {
        file rename -force $tmp $out
    }
    if {![dict get $opts quiet]} {Summary $stats}
}

::replay::main $argv
