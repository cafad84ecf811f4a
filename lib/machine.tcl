# machine.tcl --
#	Loads and validates fivax machine files. A machine file is data: a Tcl
#	list of key/value pairs, read with open/read and checked with
#	[string is list] and dict access; it is never sourced or evaluated.
#	Lengths stay in the file's units; angles are turned into radians.
#	Also the one check of axis values against the machine's travel and
#	rotary limits (outside, checkLimits), for whoever writes or reads them:
#	a value within its axis's bounds (key 'bounds': the 'limits' widened
#	by limitSlack, once per machine) is inside.
#
#	A machine is named by its file, or by the name of a shipped machine
#	(machines/NAME.tcl beside lib/: find, shipped).
#
#	Errors: {FIVAX MACHINE <DETAIL>} with a message "<file>: <what>", where
#	DETAIL is one of
#	    NOFILE     the file cannot be read, or no file and no shipped
#	               machine has the name given
#	    NOTLIST    the text (comments removed) is not a valid Tcl list
#	    ODD        a key/value list of odd length (top level or axis)
#	    DUPLICATE  a key or an axis name given twice
#	    UNKNOWN    an unknown key
#	    MISSING    a required key is absent
#	    VALUE      a value is malformed or out of range
#	    AXES       wrong number or arrangement of rotary axes
#	    GEOMETRY   degenerate axis geometry (parallel axes, tilt along Z)
#	    LIMIT      (checkLimits) an axis value outside the travel or limits

namespace eval ::fivax::machine {
    namespace export load find shipped parse rotaryNames outside checkLimits
    namespace ensemble create -prefixes 0

    # The shipped machine files (machines/ beside lib/).
    variable shippedDir [file join [file dirname $::fivax::home] machines]

    # Top-level keys and their defaults ("" default with required = 1).
    variable topDefaults {
        name {} description {} units mm family chain alpha 0 y_H 0 pivot 0
        tool_length 0 table_offset {0 0 0} axes {} controller {} output {}
        clearance 50 safe_z {} feed_min 1 feed_max 20000
        inverse_time_max 9999 max_swing 180 work_offset 54 tool_change_z 0
        home_rotaries 0 entry_feed {} tcp 0 tcp_codes {} swivel_record TC1
        travel {} default_rpm {} holder {0 40} spindle_nose {80 60} table_top {}
    }
    variable topRequired {name axes}
    variable axisKeys {side direction point sense min max continuous prefer rollover offset}
    # Stand-in for an unlimited continuous axis (radians).
    variable unlimited 1e300
    # Largest magnitude of a length (file units), a rotary limit (deg) and a
    # feed: beyond them a value is a typing error, not a machine.
    variable maxLength 1e5
    variable maxAngle 1e6
    # Widest range (deg) of a limited axis and of a continuous axis with
    # limits: each turn in the range is a candidate for the planner at
    # every CL point, so a wider range multiplies the work (ten turns
    # already triple it).
    variable maxSpan {limited 720 continuous 3600}
    variable maxFeed 1e7
    # Largest spindle speed (rpm) of 'default_rpm'.
    variable maxRpm 1e6
    # Values within this of a limit (mm, rad) are inside it.
    variable limitSlack 1e-9
}

# ::fivax::machine::load --
#	Returns the machine dict read from the machine file at path, or of the
#	shipped machine path names (find).
#	Errors: {FIVAX MACHINE NOFILE} and those of find and parse.
proc ::fivax::machine::load {path} {
    set path [find $path]
    if {![file isfile $path] || ![file readable $path]} {
        ::fivax::Fail MACHINE NOFILE "$path: cannot read machine file"
    }
    try {
        set chan [open $path r]
        fconfigure $chan -encoding utf-8
        set text [read $chan]
    } trap {POSIX} {msg} {
        ::fivax::Fail MACHINE NOFILE "$path: cannot read machine file: $msg"
    } finally {
        if {[info exists chan]} {close $chan}
    }
    parse $text $path
}

# ::fivax::machine::find --
#	Returns the machine file name gives: name itself when it exists or is
#	no bare name (it has a directory, an extension or other characters
#	than letters, digits, _ and -), else the shipped machine of that name
#	(dmu125p: machines/dmu125p.tcl). Errors: {FIVAX MACHINE NOFILE} for a
#	bare name that is neither, listing the shipped machines.
proc ::fivax::machine::find {name} {
    variable shippedDir
    if {[file exists $name] || ![regexp {^[A-Za-z0-9_-]+$} $name]} {return $name}
    set path [file join $shippedDir $name.tcl]
    if {[file isfile $path]} {return $path}
    ::fivax::Fail MACHINE NOFILE "$name: machine file not found, and no shipped machine\
        has that name (shipped machines: [join [shipped] {, }])"
}

# ::fivax::machine::shipped -- Returns the names of the shipped machines (machines/*.tcl), sorted.
proc ::fivax::machine::shipped {} {
    variable shippedDir
    lsort [lmap path [glob -nocomplain -types f -directory $shippedDir *.tcl] {
        file rootname [file tail $path]
    }]
}

# ::fivax::machine::parse --
#	Returns the machine dict described by text (the contents of a machine
#	file); sourceName names the text in error messages and in key 'file'.
proc ::fivax::machine::parse {text sourceName} {
    variable topDefaults
    variable topRequired
    set src $sourceName

    # Whole-line comments: first non-blank character '#'.
    set kept {}
    foreach line [split $text \n] {
        if {[string index [string trimleft $line] 0] ne "#"} {lappend kept $line}
    }
    set body [join $kept \n]
    if {![string is list $body]} {
        ::fivax::Fail MACHINE NOTLIST "$src: not a valid Tcl list of key/value pairs"
    }
    if {[llength $body] % 2} {
        ::fivax::Fail MACHINE ODD "$src: odd number of words (keys without values)"
    }
    set raw [dict create]
    foreach {key value} $body {
        if {![dict exists $topDefaults $key]} {
            ::fivax::Fail MACHINE UNKNOWN "$src: unknown key '$key'"
        }
        if {[dict exists $raw $key]} {
            ::fivax::Fail MACHINE DUPLICATE "$src: key '$key' given twice"
        }
        dict set raw $key $value
    }
    foreach key $topRequired {
        if {![dict exists $raw $key]} {
            ::fivax::Fail MACHINE MISSING "$src: missing key '$key'"
        }
    }

    set m [dict create file $sourceName]
    # name, description, units, family, controller
    set name [dict get $raw name]
    if {[string trim $name] eq ""} {
        ::fivax::Fail MACHINE VALUE "$src: 'name' is empty"
    }
    dict set m name $name
    dict set m description [Get $raw description]
    dict set m units [Choice $src units [Get $raw units] {mm inch}]
    set family [Choice $src family [Get $raw family] {headhead chain}]
    dict set m family $family
    set controller [Get $raw controller]
    if {$controller eq ""} {set controller [DefaultController $src]}
    if {![regexp {^[A-Za-z0-9_.-]+$} $controller]} {
        ::fivax::Fail MACHINE VALUE "$src: 'controller' is not a single word: $controller"
    }
    dict set m controller $controller

    # Head-head only keys.
    foreach key {alpha y_H} {
        if {$family ne "headhead" && [dict exists $raw $key]} {
            ::fivax::Fail MACHINE VALUE "$src: '$key' is only allowed with 'family headhead'"
        }
    }
    set alphaDeg [Real $src alpha [Get $raw alpha]]
    if {!(abs($alphaDeg) < 90.0)} {
        ::fivax::Fail MACHINE VALUE "$src: 'alpha' must lie strictly between -90 and 90: $alphaDeg"
    }
    set alpha [::fivax::num::rad $alphaDeg]
    dict set m alpha $alpha
    set yH [Length $src y_H [Get $raw y_H]]
    dict set m y_H $yH

    # Plain numbers.
    dict set m pivot [Length $src pivot [Get $raw pivot]]
    dict set m tool_length [Length $src tool_length [Get $raw tool_length]]
    dict set m table_offset [Vector $src table_offset [Get $raw table_offset]]
    set v [Length $src clearance [Get $raw clearance]]
    if {$v < 0} {::fivax::Fail MACHINE VALUE "$src: 'clearance' is negative: $v"}
    dict set m clearance $v
    set v [Get $raw safe_z]
    if {$v ne ""} {set v [Length $src safe_z $v]}
    dict set m safe_z $v
    variable maxFeed
    foreach key {feed_min feed_max inverse_time_max max_swing} {
        set v [Real $src $key [Get $raw $key]]
        if {$v <= 0} {::fivax::Fail MACHINE VALUE "$src: '$key' must be positive: $v"}
        if {$v > $maxFeed} {
            ::fivax::Fail MACHINE VALUE "$src: '$key' is out of range (at most $maxFeed): $v"
        }
        dict set m $key $v
    }
    if {[dict get $m feed_min] > [dict get $m feed_max]} {
        ::fivax::Fail MACHINE VALUE "$src: 'feed_min' exceeds 'feed_max'"
    }
    dict set m max_swing [::fivax::num::rad [dict get $m max_swing]]
    set v [Get $raw work_offset]
    if {$v ni {54 55 56 57 58 59}} {
        ::fivax::Fail MACHINE VALUE "$src: 'work_offset' must be 54 to 59 (G54..G59): $v"
    }
    dict set m work_offset $v
    dict set m tool_change_z [Real $src tool_change_z [Get $raw tool_change_z]]
    set v [Get $raw home_rotaries]
    if {$v ni {0 1}} {::fivax::Fail MACHINE VALUE "$src: 'home_rotaries' must be 0 or 1: $v"}
    dict set m home_rotaries $v
    set v [Get $raw entry_feed]
    if {$v ne ""} {
        set v [Real $src entry_feed $v]
        if {$v <= 0} {::fivax::Fail MACHINE VALUE "$src: 'entry_feed' must be positive: $v"}
    }
    dict set m entry_feed $v
    dict set m default_rpm [DefaultRpm $src [Get $raw default_rpm]]
    set v [Get $raw tcp]
    if {$v ni {0 1}} {::fivax::Fail MACHINE VALUE "$src: 'tcp' must be 0 or 1: $v"}
    dict set m tcp $v
    set v [Get $raw tcp_codes]
    if {!([string is list $v] && ([llength $v] == 0 || ([llength $v] == 2
            && [string is entier -strict [lindex $v 0]] && [string is entier -strict [lindex $v 1]])))} {
        ::fivax::Fail MACHINE VALUE "$src: 'tcp_codes' must be {} or two M code numbers {on off}: $v"
    }
    dict set m tcp_codes $v
    set v [Get $raw swivel_record]
    if {![regexp {^[A-Za-z0-9_]+$} $v]} {
        ::fivax::Fail MACHINE VALUE "$src: 'swivel_record' must be one word of letters, digits and _: $v"
    }
    dict set m swivel_record $v

    set output [Get $raw output]
    if {![string is list $output] || [llength $output] % 2} {
        ::fivax::Fail MACHINE VALUE "$src: 'output' is not a key/value list"
    }
    dict set m output [dict create {*}$output]

    # Axes.
    set axes [ParseAxes $src $family [dict get $raw axes] $alpha $yH]
    dict set m axes $axes
    dict set m travel [Travel $src [Get $raw travel]]
    foreach key {holder spindle_nose} {
        dict set m $key [Body $src $key [Get $raw $key]]
    }
    set v [Get $raw table_top]
    if {$v ne ""} {set v [Length $src table_top $v]}
    dict set m table_top $v
    set heads [lmap a $axes {if {[dict get $a side] eq "head"} {set a} else continue}]
    set tables [lmap a $axes {if {[dict get $a side] eq "table"} {set a} else continue}]
    dict set m kind [dict get {
        2,0 headhead 1,1 headtable 0,2 tabletable
    } "[llength $heads],[llength $tables]"]
    set chain [concat [lreverse $heads] $tables]
    dict set m chain $chain
    CheckGeometry $src $chain
    dict set m limits [Limits $m]
    dict set m bounds [Bounds [dict get $m limits]]
    return $m
}

# ::fivax::machine::DefaultController --
#	Returns the controller of a machine file src without one: the
#	registered default (see ::fivax::dialect default).
#	Errors: {FIVAX MACHINE MISSING} when no controller file declares one.
proc ::fivax::machine::DefaultController {src} {
    set name [::fivax::dialect default]
    if {$name eq ""} {
        ::fivax::Fail MACHINE MISSING "$src: missing key 'controller' (one of\
            [join [::fivax::dialect names] {, }])"
    }
    return $name
}

# ::fivax::machine::Get -- Returns raw's value for key, or its default.
proc ::fivax::machine::Get {raw key} {
    variable topDefaults
    if {[dict exists $raw $key]} {return [dict get $raw $key]}
    dict get $topDefaults $key
}

# ::fivax::machine::Real -- Returns value as a finite double or fails naming key.
proc ::fivax::machine::Real {src key value {what ""}} {
    set v [::fivax::num::parse $value]
    if {$v eq ""} {
        ::fivax::Fail MACHINE VALUE "$src: ${what}'$key' is not a number: $value"
    }
    return $v
}

# ::fivax::machine::CheckSpan --
#	Fails naming the axis (what) unless the limits min..max (radians) of
#	a limited (continuous 0) or a continuous axis lie within maxSpan.
proc ::fivax::machine::CheckSpan {src what continuous min max} {
    variable maxSpan
    set kind [expr {$continuous ? "continuous" : "limited"}]
    set most [dict get $maxSpan $kind]
    set span [::fivax::num::deg [expr {$max - $min}]]
    if {$span <= $most + 1e-9} return
    set hint [expr {$continuous
        ? "leave out 'min' and 'max' for an unlimited axis"
        : "a multi-turn axis is 'continuous 1'"}]
    ::fivax::Fail MACHINE VALUE "$src: ${what}'min'..'max' spans [format %g $span] deg:\
        a $kind axis spans at most $most deg ($hint)"
}

# ::fivax::machine::Length --
#	Returns value as a finite double of magnitude at most maxLength, or
#	fails naming key.
proc ::fivax::machine::Length {src key value {what ""}} {
    variable maxLength
    set v [Real $src $key $value $what]
    if {abs($v) > $maxLength} {
        ::fivax::Fail MACHINE VALUE "$src: ${what}'$key' is out of range (at most $maxLength in magnitude): $value"
    }
    return $v
}

# ::fivax::machine::DefaultRpm --
#	Returns the value of 'default_rpm' (the spindle speed of cutting
#	moves whose CL gives none): "" (none: such a move is an error) or a
#	number from 1 to maxRpm.
proc ::fivax::machine::DefaultRpm {src value} {
    variable maxRpm
    if {$value eq ""} {return ""}
    set v [Real $src default_rpm $value]
    if {$v < 1 || $v > $maxRpm} {
        ::fivax::Fail MACHINE VALUE "$src: 'default_rpm' must be {} or 1 to [format %g $maxRpm] rpm: $value"
    }
    return $v
}

# ::fivax::machine::Choice -- Returns value when it is one of choices, else fails.
proc ::fivax::machine::Choice {src key value choices {what ""}} {
    if {$value ni $choices} {
        ::fivax::Fail MACHINE VALUE \
            "$src: ${what}'$key' must be one of [join $choices {, }]: $value"
    }
    return $value
}

# ::fivax::machine::Vector -- Returns value as a list of 3 doubles or fails.
proc ::fivax::machine::Vector {src key value {what ""}} {
    if {![string is list $value] || [llength $value] != 3} {
        ::fivax::Fail MACHINE VALUE "$src: ${what}'$key' is not a list of 3 numbers: $value"
    }
    lmap c $value {Length $src $key $c $what}
}

# ::fivax::machine::Body --
#	Returns the {diameter length} of a body along the tool axis (key
#	holder or spindle_nose: the dry run's collision capsules), each a
#	length >= 0, or fails naming key.
proc ::fivax::machine::Body {src key value} {
    if {![string is list $value] || [llength $value] != 2} {
        ::fivax::Fail MACHINE VALUE "$src: '$key' is not a list {diameter length}: $value"
    }
    lmap c $value what {diameter length} {
        set v [Length $src $key $c "$what of "]
        if {$v < 0} {::fivax::Fail MACHINE VALUE "$src: $what of '$key' is negative: $c"}
        set v
    }
}

# ::fivax::machine::Travel --
#	Returns the linear travel {X {min max} Y {min max} Z {min max}} of the
#	'travel' value (any of X Y Z, each {min max} in file units); an axis
#	not given travels -maxLength..maxLength, the largest length a machine
#	file may hold.
proc ::fivax::machine::Travel {src value} {
    variable maxLength
    if {![string is list $value] || [llength $value] % 2} {
        ::fivax::Fail MACHINE VALUE "$src: 'travel' is not a list of axis {min max} pairs: $value"
    }
    set out [dict create X [list -$maxLength $maxLength] Y [list -$maxLength $maxLength] \
        Z [list -$maxLength $maxLength]]
    set seen {}
    foreach {axis range} $value {
        if {$axis ni {X Y Z}} {
            ::fivax::Fail MACHINE UNKNOWN "$src: travel: unknown axis '$axis' (X, Y or Z)"
        }
        if {$axis in $seen} {
            ::fivax::Fail MACHINE DUPLICATE "$src: travel: axis '$axis' given twice"
        }
        lappend seen $axis
        if {![string is list $range] || [llength $range] != 2} {
            ::fivax::Fail MACHINE VALUE "$src: travel: $axis is not {min max}: $range"
        }
        lassign $range lo hi
        set lo [Length $src min $lo "travel $axis: "]
        set hi [Length $src max $hi "travel $axis: "]
        if {$lo > $hi} {
            ::fivax::Fail MACHINE VALUE "$src: travel $axis: 'min' exceeds 'max': $lo > $hi"
        }
        dict set out $axis [list $lo $hi]
    }
    return $out
}

# ::fivax::machine::Limits --
#	Returns {X {min max} Y .. Z .. <rotary> {min max} ..}: the travel (file
#	units) and the rotary limits (radians; an axis that rolls over is
#	unlimited: its written values wrap) of the machine dict m.
proc ::fivax::machine::Limits {m} {
    variable unlimited
    set out [dict get $m travel]
    foreach axis [dict get $m axes] {
        if {[dict get $axis continuous] && [dict get $axis rollover]} {
            dict set out [dict get $axis name] [list -$unlimited $unlimited]
        } else {
            dict set out [dict get $axis name] [list [dict get $axis min] [dict get $axis max]]
        }
    }
    return $out
}

# ::fivax::machine::Bounds --
#	Returns the limits dict (as Limits returns it) with each range widened
#	by limitSlack: a value within its axis's bounds is inside (outside).
proc ::fivax::machine::Bounds {limits} {
    variable limitSlack
    dict map {axis range} $limits {
        lassign $range lo hi
        list [expr {$lo - $limitSlack}] [expr {$hi + $limitSlack}]
    }
}

# ::fivax::machine::ParseAxes --
#	Returns the list of axis dicts (file order) for the axes value; head-head
#	machines get their directions and points from alpha and yH (radians, mm).
proc ::fivax::machine::ParseAxes {src family axesText alpha yH} {
    variable axisKeys
    variable unlimited
    if {![string is list $axesText] || [llength $axesText] % 2} {
        ::fivax::Fail MACHINE ODD "$src: 'axes' is not a list of name/properties pairs"
    }
    set names {}
    set axes {}
    foreach {name props} $axesText {
        set what "axis $name: "
        if {![regexp {^[A-Za-z][A-Za-z0-9_]*$} $name] || [string toupper $name] in {X Y Z}} {
            ::fivax::Fail MACHINE VALUE "$src: bad axis name '$name'"
        }
        if {$name in $names} {
            ::fivax::Fail MACHINE DUPLICATE "$src: axis '$name' given twice"
        }
        lappend names $name
        if {![string is list $props] || [llength $props] % 2} {
            ::fivax::Fail MACHINE ODD "$src: ${what}properties are not a key/value list"
        }
        set p [dict create]
        foreach {key value} $props {
            if {$key ni $axisKeys} {
                ::fivax::Fail MACHINE UNKNOWN "$src: ${what}unknown key '$key'"
            }
            if {[dict exists $p $key]} {
                ::fivax::Fail MACHINE DUPLICATE "$src: ${what}key '$key' given twice"
            }
            dict set p $key $value
        }
        foreach key {side sense} {
            if {![dict exists $p $key]} {
                ::fivax::Fail MACHINE MISSING "$src: ${what}missing key '$key'"
            }
        }
        set side [Choice $src side [dict get $p side] {head table} $what]
        set sense [Real $src sense [dict get $p sense] $what]
        if {$sense != 1.0 && $sense != -1.0} {
            ::fivax::Fail MACHINE VALUE "$src: ${what}'sense' must be 1 or -1: [dict get $p sense]"
        }
        set flags {}
        foreach key {continuous rollover} {
            set v 0
            if {[dict exists $p $key]} {set v [dict get $p $key]}
            if {$v ni {0 1}} {
                ::fivax::Fail MACHINE VALUE "$src: ${what}'$key' must be 0 or 1: $v"
            }
            dict set flags $key $v
        }
        set continuous [dict get $flags continuous]
        set rollover [dict get $flags rollover]
        if {$rollover && !$continuous} {
            ::fivax::Fail MACHINE VALUE "$src: ${what}'rollover 1' needs 'continuous 1'"
        }
        set prefer none
        if {[dict exists $p prefer]} {
            set prefer [Choice $src prefer [dict get $p prefer] {positive negative none} $what]
        }
        set offset 0.0
        if {[dict exists $p offset]} {
            set offset [::fivax::num::rad [Real $src offset [dict get $p offset] $what]]
            if {!(abs($offset) <= [::fivax::num::rad 360.0])} {
                ::fivax::Fail MACHINE VALUE \
                    "$src: ${what}'offset' must lie within -360..360: [dict get $p offset]"
            }
        }
        set lim {}
        variable maxAngle
        foreach key {min max} sign {-1 1} {
            if {[dict exists $p $key]} {
                set deg [Real $src $key [dict get $p $key] $what]
                if {abs($deg) > $maxAngle} {
                    ::fivax::Fail MACHINE VALUE "$src: ${what}'$key' is out of range (at most $maxAngle deg in magnitude): $deg"
                }
                dict set lim $key [::fivax::num::rad $deg]
            } elseif {$continuous} {
                dict set lim $key [expr {$sign * $unlimited}]
            } else {
                ::fivax::Fail MACHINE MISSING \
                    "$src: ${what}missing key '$key' (required unless continuous)"
            }
        }
        if {[dict get $lim min] > [dict get $lim max]} {
            ::fivax::Fail MACHINE VALUE "$src: ${what}'min' exceeds 'max': [dict get $p min] > [dict get $p max]"
        }
        if {[dict exists $p min] != [dict exists $p max]} {
            set key [expr {[dict exists $p min] ? "max" : "min"}]
            ::fivax::Fail MACHINE MISSING \
                "$src: ${what}missing key '$key' (a continuous axis has both limits or none)"
        }
        if {[dict exists $p min]} {
            CheckSpan $src $what $continuous [dict get $lim min] [dict get $lim max]
        }
        if {$family eq "headhead"} {
            foreach key {direction point} {
                if {[dict exists $p $key]} {
                    ::fivax::Fail MACHINE VALUE \
                        "$src: ${what}'$key' is not allowed with 'family headhead' (derived from alpha, y_H)"
                }
            }
            set dir {}
            set point {}
        } else {
            if {![dict exists $p direction]} {
                ::fivax::Fail MACHINE MISSING "$src: ${what}missing key 'direction'"
            }
            lassign [Vector $src direction [dict get $p direction] $what] dx dy dz
            set n [expr {sqrt($dx * $dx + $dy * $dy + $dz * $dz)}]
            if {$n < 1e-12} {
                ::fivax::Fail MACHINE VALUE "$src: ${what}'direction' is a zero vector"
            }
            set dir [list [expr {$dx / $n}] [expr {$dy / $n}] [expr {$dz / $n}]]
            set point {0.0 0.0 0.0}
            if {[dict exists $p point]} {
                set point [Vector $src point [dict get $p point] $what]
            }
        }
        lappend axes [dict create name $name side $side dir $dir point $point \
                          sense [expr {int($sense)}] min [dict get $lim min] \
                          max [dict get $lim max] continuous $continuous \
                          prefer [dict get {positive 1 negative -1 none 0} $prefer] \
                          rollover $rollover offset $offset]
    }
    if {[llength $axes] != 2} {
        ::fivax::Fail MACHINE AXES \
            "$src: a five-axis machine has exactly two rotary axes, not [llength $axes]"
    }
    if {$family eq "headhead"} {
        foreach a $axes {
            if {[dict get $a side] ne "head"} {
                ::fivax::Fail MACHINE AXES \
                    "$src: 'family headhead' needs two head axes; [dict get $a name] is on the table"
            }
        }
        set ca [expr {cos($alpha)}]
        set sa [expr {sin($alpha)}]
        lset axes 0 [dict replace [lindex $axes 0] dir {0.0 0.0 1.0} \
                         point [list 0.0 [expr {$yH * $ca}] 0.0]]
        lset axes 1 [dict replace [lindex $axes 1] dir [list 0.0 $ca $sa] \
                         point {0.0 0.0 0.0}]
    }
    return $axes
}

# ::fivax::machine::CheckGeometry --
#	Fails unless the chain (forward order) can orient the tool: the tilt axis
#	must not be parallel to the tool (Z) nor to the azimuth axis.
proc ::fivax::machine::CheckGeometry {src chain} {
    lassign $chain a1 a2
    lassign [dict get $a1 dir] x1 y1 z1
    lassign [dict get $a2 dir] x2 y2 z2
    if {hypot($x1, $y1) < 1e-9} {
        ::fivax::Fail MACHINE GEOMETRY \
            "$src: axis [dict get $a1 name]: direction is parallel to the tool axis"
    }
    set cx [expr {$y1 * $z2 - $z1 * $y2}]
    set cy [expr {$z1 * $x2 - $x1 * $z2}]
    set cz [expr {$x1 * $y2 - $y1 * $x2}]
    if {sqrt($cx * $cx + $cy * $cy + $cz * $cz) < 1e-9} {
        ::fivax::Fail MACHINE GEOMETRY \
            "$src: axes [dict get $a1 name] and [dict get $a2 name] are parallel"
    }
}

# ::fivax::machine::rotaryNames --
#	Returns the rotary axis names of machine in output order (alphabetical:
#	the 4th axis word, then the 5th).
proc ::fivax::machine::rotaryNames {machine} {
    lsort [lmap axis [dict get $machine chain] {dict get $axis name}]
}

# ::fivax::machine::outside --
#	Returns {axis value min max} for the first value of values (a dict
#	axis -> value: X Y Z in the machine's units, rotaries in radians, as in
#	a move record's axes) outside the machine's travel or rotary limits,
#	or {} when all are inside (axes the machine does not have are ignored;
#	a value that is not a finite number is outside). Inside: within the
#	machine's bounds (Bounds).
proc ::fivax::machine::outside {machine values} {
    set bounds [dict get $machine bounds]
    dict for {axis v} $values {
        if {![dict exists $bounds $axis]} continue
        lassign [dict get $bounds $axis] lo hi
        if {!([string is double -strict $v] && $v >= $lo && $v <= $hi)} {
            return [list $axis $v {*}[dict get $machine limits $axis]]
        }
    }
    return {}
}

# ::fivax::machine::checkLimits --
#	Raises {FIVAX MACHINE LIMIT} "WHERE: Z 1000000.000 is outside the
#	travel of NAME (-500..500)" when a value of values (as for outside)
#	lies outside the machine's travel or rotary limits (where: FILE:LINE).
proc ::fivax::machine::checkLimits {machine values where} {
    set bad [outside $machine $values]
    if {![llength $bad]} return
    lassign $bad axis v lo hi
    set name [dict get $machine name]
    if {$axis in {X Y Z}} {
        set what "the travel of $name ([format %g $lo]..[format %g $hi])"
        set shown $v
    } else {
        set what "the limits of $axis on $name ([format %g [::fivax::num::deg $lo]]..[format %g [::fivax::num::deg $hi]] deg)"
        set shown [expr {[string is double -strict $v] ? [::fivax::num::deg $v] : $v}]
    }
    if {[string is double -strict $shown] && abs($shown) < 1e15} {
        set shown [::fivax::num::fixed $shown 3]
    }
    ::fivax::Fail MACHINE LIMIT "$where: $axis $shown is outside $what"
}
