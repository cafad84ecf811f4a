# nctool.tcl --
#	Helpers the command-line tools share: the command line (options by
#	fivax::opts, -help from the same table, errors on standard error with
#	exit 1), opening an NC or data file for reading with a clear error,
#	writing lines through a temporary file beside the target (renamed at
#	the end: a failed run leaves no partial file), CSV quoting, reading
#	a tool table file and the .def of a post. Needs the fivax package
#	(opts, Fail, dryrun).

namespace eval ::fivax::nctool {
    namespace export args die open writeLines csvField toolTable postDef
    namespace ensemble create -prefixes 0
}

# ::fivax::nctool::postDef --
#	Returns the .def of the post whose .tcl file is tcl: its own copy
#	<name>.def beside it when there is one (a format of its own, as
#	a shop's copy), else the one shared post/fivax.def beside it (what
#	every wrapper tools/mkpost.tcl writes names in its template_post.dat
#	line).
proc ::fivax::nctool::postDef {tcl} {
    set own [file rootname $tcl].def
    if {[file exists $own]} {return $own}
    file join [file dirname $tcl] fivax.def
}

# ::fivax::nctool::die -- Prints msg on standard error and exits with status 1.
proc ::fivax::nctool::die {msg} {
    puts stderr $msg
    exit 1
}

# ::fivax::nctool::args --
#	Returns {opts rest}: the options of the command line argv by table
#	(fivax::opts argv; who names the tool in messages) and the words
#	after them. A bad option exits 1 with its message; -help prints
#	"usage: USAGE", the summary and the option list and exits 0. With
#	count >= 0, exactly count words must follow the options; every option
#	named in required must be given.
proc ::fivax::nctool::args {table argv who usage summary {count -1} {required {}}} {
    try {
        lassign [::fivax::opts::argv $table $argv $who] opts rest
    } trap {FIVAX OPTION} {msg} {
        die $msg
    }
    if {[dict exists $opts -help] && [dict get $opts -help]} {
        # (a reader that stops early, as head or less, is no error)
        catch {puts "usage: $usage\n\n$summary\nOptions:\n[::fivax::opts::help $table]"}
        exit 0
    }
    if {$count >= 0 && [llength $rest] != $count} {
        die "usage: $usage (-help for the options)"
    }
    foreach name $required {
        if {[dict get $opts $name] eq ""} {die "$who: $name is required"}
    }
    list $opts $rest
}

# ::fivax::nctool::open --
#	Returns a channel reading the text file at path (any line ends).
#	Errors: {FIVAX TOOL OPEN} "PATH: cannot read: REASON".
proc ::fivax::nctool::open {path} {
    if {[file isdirectory $path]} {::fivax::Fail TOOL OPEN "$path: cannot read: is a directory"}
    try {
        set chan [::open $path r]
    } trap {POSIX} {msg opts} {
        ::fivax::Fail TOOL OPEN "$path: cannot read: [lindex [dict get $opts -errorcode] end]"
    }
    chan configure $chan -translation auto -encoding utf-8
    return $chan
}

# ::fivax::nctool::writeLines --
#	Writes lines (LF line ends) to path through a temporary file in the
#	same directory, renamed onto path at the end. Returns path.
proc ::fivax::nctool::writeLines {path lines} {
    set tmp [file join [file dirname [file normalize $path]] .[file tail $path].[pid].tmp]
    set chan [::open $tmp w]
    try {
        chan configure $chan -translation lf -encoding utf-8
        foreach line $lines {puts $chan $line}
        close $chan
    } on error {msg opts} {
        catch {close $chan}
        file delete -force $tmp
        return -options $opts $msg
    }
    file rename -force $tmp $path
    return $path
}

# ::fivax::nctool::csvField -- Returns text quoted for a CSV field when it needs it.
proc ::fivax::nctool::csvField {text} {
    if {[regexp {[",\n\r]} $text]} {return "\"[string map {\" \"\"} $text]\""}
    return $text
}

# ::fivax::nctool::toolTable --
#	Returns the tool table of the file at path (fivax::dryrun tools: tool
#	number -> {length L radius R}), {} for path "". Errors: {FIVAX TOOL
#	OPEN}, {FIVAX DRYRUN TOOLS} (FILE:LINE).
proc ::fivax::nctool::toolTable {path} {
    if {$path eq ""} {return {}}
    set chan [open $path]
    try {
        ::fivax::dryrun::tools [read $chan] $path
    } finally {
        close $chan
    }
}
