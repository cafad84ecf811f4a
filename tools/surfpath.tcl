# surfpath.tcl --
#	Parallel tool paths for a toroidal end mill (diameter D, corner radius
#	r) on a parametric surface S(u,v), u and v in [0, 1]: passes at equal
#	distances across, points at equal distances along, lead and tilt
#	angles in the local frame of the feed direction (kinematics.md
#	section 11), the tool tip as the CL point. Writes an NX-style CLSF
#	(TOOL PATH, TLDATA/MILL, FEDRAT, GOTO x,y,z,i,j,k, END-OF-PATH; with
#	-contact a CONTACT record of contact point and normal before each
#	cutting GOTO) that
#	replays through the post. Surfaces: paper, plane, cylinder, sphere or
#	a file of three expressions in u and v ("x = ...", "y = ...",
#	"z = ...": numbers, u, v, pi, + - * / **, parentheses and math
#	functions only; anything else is refused with FILE:LINE).
#
#	tclsh tools/surfpath.tcl -surface paper -D 6 -r 2 -lead 25 -tilt 5 \
#	    -stepover 5 -step 1 -along v -o out.cls                 (-help)

package require Tcl 8.6

set root [file dirname [file dirname [file normalize [info script]]]]
set auto_path [linsert $auto_path 0 [file join $root lib]]
package require fivax 0.1
foreach f {toolpath.tcl surfexpr.tcl nctool.tcl gouge.tcl svgplot.tcl} {
    source [file join $root tools lib $f]
}

namespace eval ::surfpath {
    variable Options {
        {-surface text paper NAME|FILE "paper, plane, cylinder, sphere, or a file of three expressions in u and v"}
        {-D {real gt 0} 6 MM "cutter diameter"}
        {-r {real min 0} 2 MM "corner radius (0 <= r <= D/2)"}
        {-lead {real gt -90 max 89.999} 25 DEG "lead angle (tool axis leaning back from the normal along the feed)"}
        {-tilt real 5 DEG "tilt angle (sideways, about the normal)"}
        {-stepover {real gt 0} 1 MM "distance between passes"}
        {-step {real gt 0} 1 MM "largest distance between CL points along a pass"}
        {-along {enum u v} u DIR "feed along u (passes at constant v) or along v"}
        {-feed {real gt 0} 1000 MMPM "cutting feed"}
        {-rpm {real gt 0} 8000 RPM "spindle speed"}
        {-length {real gt 0} 75 MM "tool length (TLDATA)"}
        {-clearance {real min 0} 10 MM "approach, lift and retract distance along the tool axis"}
        {-op word SURFACE_PATH NAME "operation name"}
        {-check bool 0 "" "check every CL point for contact and gouging and print the margins"}
        {-contact bool 0 "" "write the contact data: each cutting GOTO preceded by CONTACT/x,y,z,i,j,k (contact point, surface normal), for -cutcom3d post"}
        {-svg text {} FILE "also draw the path: XY, XZ, YZ projections of the tips with tool-axis whiskers"}
        {-o text {} FILE "output CLSF (required)"}
        {-help bool 0 "" "print this help"}
    }
}

# ::surfpath::ParseArgs -- Returns the option dict of argv.
proc ::surfpath::ParseArgs {argv} {
    variable Options
    lassign [::fivax::nctool args $Options $argv surfpath \
        "tclsh tools/surfpath.tcl ?options? -o out.cls" \
        "Parallel toroidal-cutter tool paths on a parametric surface." 0 -o] opts rest
    if {[dict get $opts -r] > [dict get $opts -D] / 2.0} {
        ::fivax::nctool die "surfpath: bad -r \"[dict get $opts -r]\": must be at most D/2 =\
            [expr {[dict get $opts -D] / 2.0}]"
    }
    return $opts
}

# ::surfpath::Check --
#	Returns {min max worst}: the smallest and largest contact margin (mm)
#	over the CL points of passes on surf, and the index of the smallest.
proc ::surfpath::Check {surf passes D r} {
    set lo Inf
    set hi -Inf
    set worst 0
    set hint {}
    set i 0
    foreach cl [concat {*}$passes] {
        lassign [::fivax::gouge margin $surf $cl $D $r $hint] f u v
        set hint [list $u $v]
        if {$f < $lo} {set lo $f; set worst $i}
        if {$f > $hi} {set hi $f}
        incr i
    }
    list $lo $hi $worst
}

# ::surfpath::main -- Generates the path and writes the CLSF.
proc ::surfpath::main {argv} {
    set opts [ParseArgs $argv]
    dict with opts {}
    try {
        set surf [::fivax::toolpath define ${-surface}]
        set passes [::fivax::toolpath passes $surf -D ${-D} -r ${-r} -lead ${-lead} \
            -tilt ${-tilt} -stepover ${-stepover} -step ${-step} -along ${-along}]
        set breaks {}
        set n 0
        foreach pass $passes {
            lappend breaks $n
            incr n [llength $pass]
        }
        set lines [::fivax::toolpath clsf [concat {*}$passes] -op ${-op} -D ${-D} -r ${-r} \
            -length ${-length} -rpm ${-rpm} -feed ${-feed} -clearance ${-clearance} -breaks $breaks -contact ${-contact}]
        ::fivax::nctool writeLines ${-o} $lines
    } trap {FIVAX} {msg} {
        ::fivax::nctool die "surfpath: $msg"
    } trap {POSIX} {msg} {
        ::fivax::nctool die "surfpath: cannot write ${-o}: $msg"
    }
    puts [format "surfpath: %s: %d passes, %d CL points, written to %s" [dict get $surf name] \
        [llength $passes] $n ${-o}]
    if {${-svg} ne ""} {
        set pts [concat {*}$passes]
        set svg [::fivax::svgplot projections -title [format "%s: D %g r %g, lead %g tilt %g deg,\
            stepover %g step %g mm along %s" [dict get $surf name] ${-D} ${-r} ${-lead} ${-tilt} \
            ${-stepover} ${-step} ${-along}] -points [lmap p $pts {lindex $p 0}] \
            -axes [lmap p $pts {lindex $p 1}] -every [expr {max(1, $n / 200)}] -whisker 8]
        try {
            ::fivax::svgplot write ${-svg} $svg
        } trap {POSIX} {msg} {
            ::fivax::nctool die "surfpath: cannot write ${-svg}: $msg"
        }
        puts "surfpath: wrote ${-svg}"
    }
    if {${-check}} {
        lassign [Check $surf $passes ${-D} ${-r}] lo hi worst
        puts [format "surfpath: contact check: signed distance surface-cutter from %.3g to %.3g mm\
            (negative: gouge), smallest at CL point %d" $lo $hi [expr {$worst + 1}]]
    }
}

::surfpath::main $argv
