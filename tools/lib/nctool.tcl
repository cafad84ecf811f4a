# nctool.tcl --
#	File helpers the command-line tools share: opening an NC or data file
#	for reading with a clear error, writing lines through a temporary file
#	beside the target (renamed at the end: a failed run leaves no partial
#	file), and CSV quoting. Needs the fivax package (Fail).

namespace eval ::fivax::nctool {
    namespace export open writeLines csvField
    namespace ensemble create -prefixes 0
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
