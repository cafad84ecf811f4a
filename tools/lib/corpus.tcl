# corpus.tcl --
#	Where the real CL files live (outside the repository, never copied into
#	it): FIVAX_CORPUS, else ../shared/data/cl beside the checkout. Sourced
#	by tests/helpers.tcl and tools/fuzz.tcl.

# ::fivax::corpusDir -- Returns the real CL file directory for the checkout at root.
proc ::fivax::corpusDir {root} {
    if {[info exists ::env(FIVAX_CORPUS)] && $::env(FIVAX_CORPUS) ne ""} {
        return [file normalize $::env(FIVAX_CORPUS)]
    }
    file normalize [file join $root .. shared data cl]
}
