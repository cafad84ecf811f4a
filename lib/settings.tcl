# settings.tcl --
#	The settings of a posting job, in one option table for the post (the
#	global dict fivax_settings, keys with their dash: -tol) and the command
#	line (tools/replay.tcl): the job's own options (machine, controller,
#	arc tolerance) and those of the planner, each spelt once.

namespace eval ::fivax::settings {
    namespace export table parse pick
    namespace ensemble create -prefixes 0
    variable Job {
        {-machine text {} FILE "machine file (default: the post's machine, machines/hh-tilt45.tcl)"}
        {-arc-tol {real gt 0} 0.002 MM "chord tolerance of arcs written as points"}
        {-log text {} FILE
            "file for warnings, retracts and errors (default: <output>.log beside the NC file when the host names it)"}
    }
}

# ::fivax::settings::table --
#	Returns the option table of a posting job: -machine, -controller (the
#	output layer's dialects; default: the machine's), -arc-tol, -log, the
#	output layer's -insert and the planner's options but -angle-step and
#	-output (set from the output layer: its resolution and what it writes).
proc ::fivax::settings::table {} {
    variable Job
    set controllers [dict keys $::fivax::output::Dialects]
    concat [lrange $Job 0 0] \
        [list [list -controller [list maybe enum {*}$controllers] {} NAME \
            "controller dialect: [join $controllers {, }] (default: the machine's)"]] \
        [lrange $Job 1 end] [list [lsearch -inline -index 0 $::fivax::output::Options -insert]] \
        [::fivax::opts::drop $::fivax::motion::Options {-angle-step -output}]
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
