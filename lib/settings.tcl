# settings.tcl --
#	The settings of a posting job, in one option table for the post (the
#	global dict fivax_settings, keys with their dash: -tol) and the command
#	line (tools/replay.tcl): the job's own options (machine, controller,
#	arc tolerance) and those of the planner, each spelt once.

namespace eval ::fivax::settings {
    namespace export table parse complete pick check output cutter
    namespace ensemble create -prefixes 0
    # The machine of a job that names none.
    variable defaultMachine [file join $::fivax::machine::shippedDir hh-tilt45.tcl]
    variable Job {
        {-machine text {} FILE "machine file, or a shipped machine's name: dmu125p is machines/dmu125p.tcl (default: the post's machine, hh-tilt45)"}
        {-arc-tol {real gt 0} 0.002 MM "chord tolerance of arcs written as points"}
        {-tool-length {maybe real gt 0} {} MM
            "tool length (gauge length) of the tools the CL gives none (no TLDATA); a CL length wins. Required in joint mode on a head machine"}
        {-log text {} FILE
            "file for warnings, retracts and errors (default: <output>.log beside the NC file when the host names it)"}
        {-dryrun {enum on off} on WHEN
            "machine dry run of the written program at its end (lib/dryrun.tcl): any event ends posting with an error"}
        {-cutcom3d {enum off post control} off MODE
            "3D tool-radius compensation: off, post (every cutting move with contact data (CONTACT records) moved for the cutter -tool-diameter, -tool-corner-radius) or control (the control's own, where the controller has one: the surface normal written with each such move, TCP mode)"}
        {-tool-diameter {maybe real gt 0} {} MM "diameter of the cutter in the spindle, for -cutcom3d post"}
        {-tool-corner-radius {maybe real min 0} {} MM
            "corner radius of the cutter in the spindle, for -cutcom3d post (default: the CL cutter's, at most half the diameter)"}
    }
}

# ::fivax::settings::table --
#	Returns the option table of a posting job: -machine, -controller (the
#	output layer's dialects; default: the machine's), -arc-tol,
#	-tool-length, -log, the output layer's -arc-words and -insert and the
#	planner's options but -angle-step, -length-step and -output (set from
#	the output layer: its resolution and what it writes).
proc ::fivax::settings::table {} {
    variable Job
    set controllers [::fivax::dialect names]
    concat [lrange $Job 0 0] \
        [list [list -controller [list maybe enum {*}$controllers] {} NAME \
            "controller dialect: [join $controllers {, }] (default: the machine's)"]] \
        [lrange $Job 1 end] \
        [lmap opt {-arc-words -insert} {lsearch -inline -index 0 $::fivax::output::Options $opt}] \
        [::fivax::opts::drop $::fivax::motion::Options {-angle-step -length-step -output}]
}

# ::fivax::settings::parse --
#	Returns the full settings dict (defaults filled in) of the settings
#	dict given, each value checked.
proc ::fivax::settings::parse {given} {
    if {![string is list $given] || [llength $given] % 2} {
        ::fivax::Fail OPTION VALUE "fivax_settings: not a dict of option value pairs"
    }
    ::fivax::opts::parse [table] $given fivax_settings
}

# ::fivax::settings::complete --
#	Returns settings (a parsed settings dict) with what the installation
#	gives filled in: -machine is the machine file (fivax::machine find: a
#	shipped machine's name becomes its file), when empty the default
#	machine (machines/hh-tilt45.tcl beside lib/). Errors: those of find.
proc ::fivax::settings::complete {settings} {
    variable defaultMachine
    set machine [dict get $settings -machine]
    dict set settings -machine [expr {$machine eq "" ? $defaultMachine
        : [::fivax::machine::find $machine]}]
    return $settings
}

# ::fivax::settings::pick --
#	Returns the option value pairs of settings that module's create takes
#	(module: motion or verify).
proc ::fivax::settings::pick {settings module} {
    set names [::fivax::opts::names [set ::fivax::${module}::Options]]
    set out {}
    dict for {name value} $settings {
        if {$name in $names} {lappend out $name $value}
    }
    return $out
}

# ::fivax::settings::check --
#	Checks the settings (a parsed settings dict) that depend on machine (a
#	fivax::machine dict) and on resolution ({length angle}, the output
#	layer's resolution of X Y Z and of the rotaries): -tol and -atol are 0
#	(off) or at least that resolution, -arc-tol at least that of X Y Z (a
#	finer tolerance can never be met, and chasing it multiplies the work
#	without bound); -table-offset, -clearance and -tool-length are
#	lengths the machine file could hold. who prefixes messages. Errors:
#	{FIVAX OPTION VALUE} naming the option.
proc ::fivax::settings::check {settings machine resolution {who fivax_settings}} {
    lassign $resolution mm deg
    foreach {opt res unit what} [list -tol $mm "" "X Y Z" -atol $deg " deg" "the rotary axes" \
            -arc-tol $mm "" "X Y Z"] {
        set v [dict get $settings $opt]
        if {$v != 0 && $v < $res} {
            set off [expr {$opt eq "-arc-tol" ? "" : "0 (off) or "}]
            ::fivax::Fail OPTION VALUE "$who: bad $opt \"$v\": must be ${off}at least\
                $res$unit, the output resolution of $what on [dict get $machine name]"
        }
    }
    cutter $settings $who
    set max $::fivax::machine::maxLength
    foreach opt {-table-offset -clearance -tool-length -tool-diameter -tool-corner-radius} {
        foreach v [dict get $settings $opt] {
            if {abs($v) > $max} {
                ::fivax::Fail OPTION VALUE "$who: bad $opt \"[dict get $settings $opt]\":\
                    must be at most [format %g $max] in magnitude"
            }
        }
    }
}

# ::fivax::settings::cutter --
#	Checks the cutter of -cutcom3d post in the options dict settings (the
#	post's, tools/verify.tcl's): -tool-diameter given with it (and only
#	with it, like -tool-corner-radius), the corner radius at most half the
#	diameter. who prefixes messages. Errors: {FIVAX OPTION VALUE}.
proc ::fivax::settings::cutter {settings who} {
    set D [dict get $settings -tool-diameter]
    set r [dict get $settings -tool-corner-radius]
    if {[dict get $settings -cutcom3d] ne "post"} {
        if {$D ne "" || $r ne ""} {
            ::fivax::Fail OPTION VALUE "$who: -tool-diameter and -tool-corner-radius describe\
                the cutter of -cutcom3d post: give -cutcom3d post with them"
        }
        return
    }
    if {$D eq ""} {
        ::fivax::Fail OPTION VALUE "$who: -cutcom3d post needs the cutter in the spindle:\
            give -tool-diameter MM (and -tool-corner-radius MM)"
    }
    if {$r ne "" && $r > $D / 2.0} {
        ::fivax::Fail OPTION VALUE "$who: bad -tool-corner-radius \"$r\": must be at most\
            half the -tool-diameter, [expr {$D / 2.0}]"
    }
}

# ::fivax::settings::output --
#	Returns a new output Writer (fivax::output create) for machine (a
#	fivax::machine dict) with the .def file defFile and the output
#	settings of settings (-controller and -tcp when set, else the
#	machine's; -arc-words, -insert), plus the output options args (e.g.
#	-warn cmd); first checks settings against its resolution (check, with
#	who). Errors: those of fivax::def load, fivax::output create and check.
proc ::fivax::settings::output {settings machine defFile who args} {
    set options [list -def [::fivax::def load $defFile]]
    foreach key {-arc-words -insert -controller -tcp} {
        if {[dict get $settings $key] ne ""} {
            lappend options $key [dict get $settings $key]
        }
    }
    set out [::fivax::output create $machine {*}$options {*}$args]
    try {
        check $settings $machine [$out resolution] $who
    } on error {msg opts} {
        $out destroy
        return -options $opts $msg
    }
    return $out
}
