# mkpost.tcl --
#	Writes one NX post per shipped machine: post/<machine>.tcl, a small
#	wrapper that sets the machine and sources the shared post/fivax.tcl;
#	every wrapper's template_post.dat line names the one post/fivax.def.
#	Prints the template_post.dat line of every post in post/:
#	post/fivax.tcl itself (FIVAX: the machine of the settings), then the
#	others by name, the machines' and any made by hand (README.md lists
#	them; a test checks it). A post with a
#	.def of its own (post/<name>.def, nctool postDef) names that one.
#
#	tclsh tools/mkpost.tcl ?-check? ?-def MACHINE?
#	-check writes nothing and exits 1 when a post file differs from what
#	would be written (the test suite runs it). -def MACHINE copies
#	post/fivax.def to post/MACHINE.def (MACHINE line set) for a format of
#	that machine's own, and its wrapper's line names the copy.

package require Tcl 8.6

set root [file dirname [file dirname [file normalize [info script]]]]
set auto_path [linsert $auto_path 0 [file join $root lib]]
package require fivax 0.1
source [file join $root tools lib nctool.tcl]

namespace eval ::mkpost {
    variable options {
        {-check bool 0 "" "write nothing; exit 1 when a post file is out of date"}
        {-def {maybe word} {} MACHINE "copy post/fivax.def to post/MACHINE.def, the machine's own .def"}
        {-help bool 0 "" "print this help"}
    }
}

# ::mkpost::Line --
#	Returns the template_post.dat line of the post post/name.tcl (name
#	fivax: the shared post, FIVAX; else FIVAX_<NAME>), with the .def
#	nctool postDef finds for it.
proc ::mkpost::Line {name} {
    variable ::root
    set key [expr {$name eq "fivax" ? "FIVAX" : [string toupper FIVAX_$name]}]
    set def [file tail [::fivax::nctool postDef [file join $root post $name.tcl]]]
    return "$key,\${UGII_CAM_POST_DIR}fivax/post/$name.tcl,\${UGII_CAM_POST_DIR}fivax/post/$def"
}

# ::mkpost::Wrapper -- Returns the text of the wrapper post for machine name.
proc ::mkpost::Wrapper {name} {
    return [string map [list @NAME@ $name @LINE@ [Line $name]] {# @NAME@.tcl -- fivax post for the machine @NAME@ (machines/@NAME@.tcl).
#	Written by tools/mkpost.tcl. Add settings to the list below (keys are
#	the replay options with their dash, e.g. -tol 0.005 -on-limit error).
#	NX template_post.dat line:
#	@LINE@
set fivax_post_here [file dirname [file normalize [info script]]]
set fivax_settings [list -machine [file join $fivax_post_here .. machines @NAME@.tcl]]
source [file join $fivax_post_here fivax.tcl]
}]
}

# ::mkpost::Def -- Returns the .def text of machine name's own copy of the base .def text.
proc ::mkpost::Def {name base} {
    if {![regsub -line {^MACHINE\s+\S+$} $base "MACHINE $name" text]} {
        error "the base .def has no MACHINE line"
    }
    return "# $name.def -- the .def of the fivax post for $name: a copy of post/fivax.def\n# (tools/mkpost.tcl -def $name), to be edited for this machine's own format.\n$text"
}

# ::mkpost::Read -- Returns the contents of file path ("" when absent).
proc ::mkpost::Read {path} {
    if {![file exists $path]} {return ""}
    set chan [open $path r]
    try {
        fconfigure $chan -translation lf -encoding utf-8
        return [read $chan]
    } finally {
        close $chan
    }
}

# ::mkpost::Write -- Writes text to path (LF line ends) through a temporary file.
proc ::mkpost::Write {path text} {
    set chan [open $path.tmp w]
    try {
        fconfigure $chan -translation lf -encoding utf-8
        puts -nonewline $chan $text
    } finally {
        close $chan
    }
    file rename -force $path.tmp $path
}

# ::mkpost::main --
#	Writes (or checks) the post pair of every machine file, then prints
#	the template_post.dat line of every post in post/.
proc ::mkpost::main {argv} {
    variable options
    variable ::root
    try {
        lassign [::fivax::opts argv $options $argv mkpost] opts rest
    } trap {FIVAX OPTION} {msg} {
        puts stderr $msg
        exit 1
    }
    if {[dict get $opts -help] || [llength $rest]} {
        puts "usage: tclsh tools/mkpost.tcl ?-check? ?-def MACHINE?\n[::fivax::opts help $options]"
        exit [expr {[llength $rest] > 0}]
    }
    set copy [dict get $opts -def]
    if {$copy ne "" && ![dict get $opts -check]} {
        Write [file join $root post $copy.def] [Def $copy [Read [file join $root post fivax.def]]]
    }
    set stale {}
    foreach file [lsort [glob -directory [file join $root machines] *.tcl]] {
        set name [dict get [::fivax::machine load $file] name]
        set path [file join $root post $name.tcl]
        set text [Wrapper $name]
        if {[Read $path] eq $text} continue
        if {[dict get $opts -check]} {
            lappend stale [file tail $path]
        } else {
            Write $path $text
        }
    }
    set names [lmap f [glob -directory [file join $root post] *.tcl] {file rootname [file tail $f]}]
    foreach name [concat fivax [lsort [lsearch -all -inline -not -exact $names fivax]]] {
        puts [Line $name]
    }
    if {[llength $stale]} {
        puts stderr "mkpost: out of date: [join $stale {, }] (run tclsh tools/mkpost.tcl)"
        exit 1
    }
}

::mkpost::main $argv
