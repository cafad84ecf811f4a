# mkcl.tcl --
#	Regenerates the bundled synthetic CL samples in tests/data/ from
#	tools/lib/toolpath.tcl, and prints one summary line per file (points, largest
#	tool-axis angle off +Z).
#
#	tclsh tools/mkcl.tcl ?outdir?     (default: tests/data of this checkout; -help)

package require Tcl 8.6

set root [file dirname [file dirname [file normalize [info script]]]]
set auto_path [linsert $auto_path 0 [file join $root lib]]
package require fivax 0.1
foreach f {nctool.tcl toolpath.tcl} {
    source [file join $root tools lib $f]
}

namespace eval ::mkcl {
    variable Options {
        {-help bool 0 "" "print this help"}
    }
    # Sample files: name, path generator command, clsf options.
    variable samples {
        demo-5ax.cls {
            raster -D 16 -r 4 -lead 10 -tilt 15 -passes 20 -step 100
        } {-op VARIABLE_CONTOUR -tool MILL_D16_R4 -D 16 -r 4 -length 75}
        sweep-60.cls {
            sweep -shape circle -R 50 -z 0 -tilt 60 -from 0 -to 360 -n 720
        } {-op SWEEP_TILT60 -tool MILL_D16_R4 -D 16 -r 4 -length 75}
        wind-600.cls {
            sweep -shape circle -R 50 -z 0 -tilt 30 -from 0 -to 600 -n 600
        } {-op WIND_600 -tool MILL_D16_R4 -D 16 -r 4 -length 75}
        pole.cls {
            sweep -shape line -R 50 -z 0 -tilt 40 -from 0 -through-singular 1 -n 200
        } {-op POLE_CROSSING -tool MILL_D16_R4 -D 16 -r 4 -length 75}
    }
}

# ::mkcl::WriteLines --
#	Writes lines to path with LF endings, through a temporary file.
proc ::mkcl::WriteLines {path lines} {
    set tmp $path.tmp
    set chan [open $tmp w]
    try {
        chan configure $chan -translation lf -encoding utf-8
        puts $chan [join $lines \n]
    } finally {
        close $chan
    }
    file rename -force $tmp $path
}

# ::mkcl::MaxTilt -- Returns the largest angle (deg) between +Z and an axis in pts.
proc ::mkcl::MaxTilt {pts} {
    set max 0.0
    foreach pt $pts {
        set a [::fivax::vec angle {0 0 1} [lindex $pt 1]]
        if {$a > $max} {set max $a}
    }
    ::fivax::num::deg $max
}

# main -- Writes every sample into argv's directory (default tests/data).
proc main {argv} {
    set usage "tclsh tools/mkcl.tcl ?outdir?"
    lassign [::fivax::nctool args $::mkcl::Options $argv mkcl $usage \
        "Regenerates the synthetic CL samples (default: in tests/data)."] - rest
    if {[llength $rest] > 1} {::fivax::nctool die "usage: $usage (-help for the options)"}
    set dir [file join $::root tests data]
    if {[llength $rest] == 1} {set dir [lindex $rest 0]}
    file mkdir $dir
    foreach {name gen opts} $::mkcl::samples {
        set pts [::fivax::toolpath {*}$gen]
        ::mkcl::WriteLines [file join $dir $name] [::fivax::toolpath clsf $pts {*}$opts]
        puts [format "%-14s %5d points, max axis angle off +Z %.4f deg" \
                  $name [llength $pts] [::mkcl::MaxTilt $pts]]
    }
}

main $argv
