# record.tcl --
#	The move-record contract: what the planner (::fivax::motion, its
#	add, arc, hole, flush, startPath, endPath, endPlane and finish
#	methods) hands the output layer (::fivax::output's move method), in
#	the way a canonical machining interface defines what an interpreter
#	hands the motion layer. This file is the one place that defines it:
#	every record kind, its fields, their types and units, as data
#	(Fields, Kinds), and check, which tests a record against it
#	(tests/record.test checks every record the planner emits).
#
#	A move record is a dict; its kind names the fields it has, all of
#	them and no other. Lengths in mm, angles inside the records in
#	radians (the rotaries' joint values), times in seconds, feeds per
#	minute. X Y Z are those of the output frame: the machine's (joint
#	mode), the tool tip's in the workpiece frame (TCP) or the tip's in a
#	work plane's frame (between a plane and a planeOff record).
#
#	Writer decisions. Three fields are the planner's requests to the
#	writer, made from the writer's capabilities (::fivax::output
#	capabilities, the planner's -output): write (which axes a block
#	names: the planner sequences a transfer as Z up, rotate, X Y, down,
#	which is path safety, not vocabulary), mode and rate (the feed word:
#	the planner has the tip path length, the joint travel and the
#	machine's feed limits they need, and counts the clamped moves in its
#	statistics; a writer without inverse time gets dpm: see the planner's
#	-output). How the request is spelled (G93/G94 and F, or a control's own feed words) is the
#	writer's alone.

namespace eval ::fivax::record {
    namespace export check kinds fields
    namespace ensemble create -prefixes 0
    # Every field of any record: name {type unit meaning}. Types (see
    # Problem): kind, real, real+ (>= 0), enum:a|b (a "" choice is written
    # as an empty alternative), point (3 reals), point? (a point or
    # empty), axis? (a unit 3-vector or empty), axes, names (keys of
    # axes), matrix (3 points), text.
    variable Fields {
        kind    {kind - "the record kind: a key of Kinds"}
        axes    {axes "mm, rad" "the joint values by axis name: X Y Z (output frame) then the two rotaries in chain order (tilt, azimuth), the planner's continuous values (not rolled over)"}
        write   {names - "the axes this block names (keys of axes, {}: none; the planner's request, see the header); in a work plane never a rotary"}
        feed    {real+ mm/min "the programmed tool-tip feed, clamped to the machine's feed_min..feed_max; 0 for rapid, retract and dwell"}
        mode    {enum:direct|inverse|dpm - "the feed word (the planner's request): direct (mm/min of the tip), inverse (inverse time, 1/min) or dpm (combined feed of all axes, mm and degrees per minute)"}
        rate    {real+ "mm/min, 1/min or (mm, deg)/min" "the F value in that mode; 0 for rapid, retract and dwell"}
        tip     {real+ mm "the tool-tip path length of the move in the workpiece frame (0 where not a cutting move of the path)"}
        P       {point? mm "the CL target in the workpiece frame (interpolated for linearisation points, on the tool axis line for retract and approach points); empty for positioning moves and markers"}
        t       {axis? - "the CL tool axis (unit, workpiece frame) at P; empty where P is"}
        src     {text - "FILE:LINE of the CL record the move comes from (\"\" where none)"}
        tag     {enum:|inserted|reengage|approach - "\"\", inserted (a linearisation point), reengage (down the tool axis onto the path), approach (the clearance point above a first point)"}
        note    {text - "the reason of a retract; else empty"}
        seconds {real+ s "the dwell time"}
        event   {text - "NX's cycle event: drill, drill_dwell, drill_deep, drill_break_chip, tap, bore, bore_dwell, ..."}
        r       {real mm "the output Z of the cycle's R plane"}
        initial {real mm "the output Z of the cycle's initial level (where G98 returns)"}
        step    {real+ mm "the peck depth (0: none)"}
        delay   {real+ s "the dwell at the hole's bottom (0: none)"}
        start   {point mm "the arc's start (output frame)"}
        center  {point mm "the arc's center (output frame)"}
        plane   {enum:17|18|19 - "the arc's plane: 17 XY, 18 ZX, 19 YZ of the output frame"}
        dir     {enum:2|3 - "2 clockwise, 3 counter-clockwise about the plane's normal"}
        matrix  {matrix - "the work plane's frame R, three rows: its columns are the plane's X' Y' Z' (unit vectors, workpiece frame)"}
        origin  {point mm "the work plane's origin (workpiece frame)"}
        seq     {enum:-1|1 - "the sign of the tilt the control should take"}
        normal  {axis? - "the unit surface normal at the move's contact (workpiece frame, out of the material): added by the post to a cutting move for the control's own 3D tool-radius compensation (-cutcom3d control)"}
    }
    # The fields a kind may have besides its own (Kinds): kind {name ...}.
    variable Optional {feed normal}
    # The record kinds: kind {fields meaning}. The fields of a move (the
    # planner's Move) come first in every kind that moves an axis.
    variable Kinds {
        rapid {{kind axes write feed mode rate tip P t src tag note}
            "positioning at rapid to axes"}
        feed {{kind axes write feed mode rate tip P t src tag note}
            "a cutting move to axes at the feed word mode, rate"}
        retract {{kind axes write feed mode rate tip P t src tag note}
            "away from the part along the tool axis by the clearance, at rapid (note: why)"}
        dwell {{kind axes write feed mode rate tip P t src tag note seconds}
            "a pause of seconds at axes (an expanded cycle's dwell at the bottom)"}
        cycle {{kind axes write feed mode rate tip P t src tag note event r initial step delay}
            "one hole of the control's canned cycle: axes at the bottom, rate the feed (mm/min)"}
        arc {{kind axes write feed mode rate tip P t src tag note start center plane dir}
            "a circular (or helical) cutting move from start to axes about center, rotaries unchanged; tip its length"}
        plane {{kind matrix origin seq P t src tag note}
            "the tilted work plane on: X Y Z of the next records are in its frame, the rotaries the control's"}
        planeOff {{kind P t src tag note}
            "the work plane off (the position is unknown afterwards)"}
    }
}

# ::fivax::record::kinds -- Returns the record kinds.
proc ::fivax::record::kinds {} {
    variable Kinds
    dict keys $Kinds
}

# ::fivax::record::fields --
#	Returns the fields of a record of kind, each {name type unit meaning}.
proc ::fivax::record::fields {kind} {
    variable Kinds
    variable Fields
    lmap name [lindex [dict get $Kinds $kind] 0] {list $name {*}[dict get $Fields $name]}
}

# ::fivax::record::check --
#	Returns rec when it keeps the contract (its kind's fields, and no
#	other but those Optional allows it); else raises {FIVAX RECORD
#	INVALID} with "src: what is wrong" (every problem, "; " between).
proc ::fivax::record::check {rec} {
    variable Kinds
    variable Fields
    variable Optional
    if {[catch {dict size $rec}]} {
        ::fivax::Fail RECORD INVALID "a move record is no dict: $rec"
    }
    set where [expr {[dict exists $rec src] && [dict get $rec src] ne "" ? [dict get $rec src] : "record"}]
    if {![dict exists $rec kind] || ![dict exists $Kinds [dict get $rec kind]]} {
        ::fivax::Fail RECORD INVALID "$where: no record kind of [join [dict keys $Kinds] {, }]: $rec"
    }
    set kind [dict get $rec kind]
    set want [lindex [dict get $Kinds $kind] 0]
    set problems {}
    foreach name $want {
        if {![dict exists $rec $name]} {
            lappend problems "field $name missing"
        } elseif {[set why [Problem [lindex [dict get $Fields $name] 0] [dict get $rec $name] $rec]] ne ""} {
            lappend problems "field $name: $why"
        }
    }
    set may [expr {[dict exists $Optional $kind] ? [dict get $Optional $kind] : {}}]
    foreach name [dict keys $rec] {
        if {$name in $want} continue
        if {$name ni $may} {
            lappend problems "field $name is not one of a $kind record"
        } elseif {[set why [Problem [lindex [dict get $Fields $name] 0] [dict get $rec $name] $rec]] ne ""} {
            lappend problems "field $name: $why"
        }
    }
    if {[llength $problems]} {
        ::fivax::Fail RECORD INVALID "$where: $kind record: [join $problems {; }]"
    }
    return $rec
}

# ::fivax::record::Problem --
#	Returns what is wrong with value as a field of type (see Fields) in
#	record rec, "" when nothing.
proc ::fivax::record::Problem {type value rec} {
    switch -glob -- $type {
        kind {
            # (check has tested it)
            return ""
        }
        real {return [expr {[Real $value] ? "" : "not a number: $value"}]}
        real+ {return [expr {[Real $value] && $value >= 0 ? "" : "not a number >= 0: $value"}]}
        enum:* {
            set choices [split [string range $type 5 end] |]
            return [expr {$value in $choices ? "" : "\"$value\" is not one of [join $choices {, }]"}]
        }
        point {return [expr {[Point $value] ? "" : "not 3 numbers: $value"}]}
        point? {return [expr {$value eq "" || [Point $value] ? "" : "not 3 numbers or empty: $value"}]}
        axis? {
            if {$value eq ""} {return ""}
            if {![Point $value] || abs([::fivax::vec::norm $value] - 1.0) > 1e-6} {
                return "not a unit 3-vector or empty: $value"
            }
            return ""
        }
        axes {return [AxesProblem $value]}
        names {
            if {![dict exists $rec axes] || [AxesProblem [dict get $rec axes]] ne ""} {return ""}
            foreach name $value {
                if {![dict exists [dict get $rec axes] $name]} {return "$name is no axis of axes"}
            }
            return ""
        }
        matrix {
            if {[catch {llength $value} n] || $n != 3} {return "not 3 rows: $value"}
            foreach row $value {
                if {![Point $row]} {return "a row is not 3 numbers: $value"}
            }
            return ""
        }
        text {return ""}
    }
    error "record type $type is unknown"
}

# ::fivax::record::AxesProblem --
#	Returns what is wrong with value as the axes field (X Y Z then two
#	rotaries, each a number), "" when nothing.
proc ::fivax::record::AxesProblem {value} {
    if {[catch {dict size $value} n] || $n != 5 || [llength $value] != 10} {
        return "not 5 axis names with values: $value"
    }
    if {[lrange [dict keys $value] 0 2] ne {X Y Z}} {return "X Y Z not first: $value"}
    foreach v [dict values $value] {
        if {![Real $v]} {return "a value is not a number: $value"}
    }
    return ""
}

# ::fivax::record::Real -- Returns 1 when value is one finite number.
proc ::fivax::record::Real {value} {
    if {![string is double -strict $value]} {return 0}
    # (NaN is no operand of expr)
    if {[catch {expr {abs($value) < Inf}} finite]} {return 0}
    return $finite
}

# ::fivax::record::Point -- Returns 1 when value is a list of 3 finite numbers.
proc ::fivax::record::Point {value} {
    if {[catch {llength $value} n] || $n != 3} {return 0}
    foreach v $value {
        if {![Real $v]} {return 0}
    }
    return 1
}
