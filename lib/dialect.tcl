# dialect.tcl --
#	The controllers fivax writes and reads back. Each controller is one
#	file in lib/dialect/ (<name>.tcl, shipped code of this library) that
#	calls define once with what the output layer writes (its writer
#	table, see lib/output.tcl) and what the checker accepts (its reader
#	table, see lib/verify.tcl); what the control writes or reads beyond
#	the generic ISO G code is in the same file, as the methods of its
#	Writer and Reader classes (::fivax::dialect::<name>::Writer, ...)
#	that the tables' methods key names. The list of controllers is the
#	list of those files: removing one removes its controller from every
#	option list, help text, the checker and the dialect tests. The files
#	are found beside this library (never in the working directory).
#	Errors: {FIVAX OPTION VALUE} for a name that is no controller.

namespace eval ::fivax::dialect {
    namespace export names writer reader check default
    namespace ensemble create -prefixes 0
    # name -> {writer dict reader dict}, in the order of the file names
    variable Registry {}
}

# ::fivax::dialect::define --
#	Registers controller name with its writer and reader tables (called
#	by the files of lib/dialect/ as they load).
proc ::fivax::dialect::define {name writer reader} {
    variable Registry
    dict set Registry $name [dict create writer $writer reader $reader]
}

# ::fivax::dialect::names -- Returns the names of the registered controllers.
proc ::fivax::dialect::names {} {
    variable Registry
    dict keys $Registry
}

# ::fivax::dialect::default --
#	Returns the controller of a machine file without 'controller': the
#	one whose writer table says default 1, or "" when no file does.
proc ::fivax::dialect::default {} {
    variable Registry
    dict for {name entry} $Registry {
        if {[dict get $entry writer default]} {return $name}
    }
    return ""
}

# ::fivax::dialect::writer -- Returns the writer table of controller name (see check).
proc ::fivax::dialect::writer {name {who controller}} {
    variable Registry
    check $name $who
    dict get $Registry $name writer
}

# ::fivax::dialect::reader -- Returns the reader table of controller name (see check).
proc ::fivax::dialect::reader {name {who controller}} {
    variable Registry
    check $name $who
    dict get $Registry $name reader
}

# ::fivax::dialect::check --
#	Returns name when it is a registered controller.
#	Errors: {FIVAX OPTION VALUE} "<who>: unknown controller 'x': must be
#	one of a, b, c" otherwise.
proc ::fivax::dialect::check {name {who controller}} {
    variable Registry
    if {![dict exists $Registry $name]} {
        ::fivax::Fail OPTION VALUE "$who: unknown controller '$name': must be one of\
            [join [dict keys $Registry] {, }]"
    }
    return $name
}

# ::fivax::dialect::Load -- Sources the controller files of directory dir in name order.
proc ::fivax::dialect::Load {dir} {
    foreach file [lsort [glob -nocomplain -types f -directory $dir *.tcl]] {
        source $file
    }
}

::fivax::dialect::Load [file join $::fivax::home dialect]
