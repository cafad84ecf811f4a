# verify.tcl --
#	Checks written NC blocks against the CL data they stand for: reads the
#	axis words back from the block text (so output rounding counts), runs
#	the forward kinematics (never the inverse) and measures the tip and axis
#	deviation at each CL point and, for cutting moves, at the quarter points
#	of the controller's linear joint interpolation against the straight CL
#	segment and the great circle of the tool axis (spec section 7), and
#	refuses a written value outside the machine's travel or rotary limits
#	(machine checkLimits). It knows nothing of how the planner chose the
#	blocks: it depends on kin and the machine dict only.

namespace eval ::fivax::verify {
    namespace export create
    namespace ensemble create -prefixes 0
    namespace upvar ::fivax::num pi pi
    variable Options {
        {-table-offset {maybe vec3} {} "X Y Z"
            "workpiece-frame position of the table reference point (default: the machine's table_offset)"}
    }
}

# ::fivax::verify::create --
#	Returns a new Checker object for machine (a fivax::machine dict);
#	options as in the Options table. Destroy it with "$checker destroy".
proc ::fivax::verify::create {machine args} {
    variable Options
    Checker new $machine [::fivax::opts::parse $Options $args "verify create"]
}

oo::class create ::fivax::verify::Checker {
    # S: machine, tableOffset, names, rollover, model, the modal
    # axis values X Y Z q1 q2, prev (the last checked block) and the
    # statistics (see summary).
    variable S

    constructor {machine opts} {
        set S(machine) $machine
        set S(tableOffset) [dict get $opts -table-offset]
        set chain [dict get $machine chain]
        set S(names) [lmap axis $chain {dict get $axis name}]
        set S(rollover) [lmap axis $chain {dict get $axis rollover}]
        array set S {X {} Y {} Z {} q1 {} q2 {} prev {} checked 0 segments 0
            maxPos 0.0 maxAng 0.0 maxMidPos 0.0 maxMidAng 0.0 limitViolations 0
            worst {} worstMid {}}
        my setTool [dict get $machine tool_length]
    }

    # Switches the checker to a tool of length len (mm).
    method setTool {len} {
        set S(model) [::fivax::kin::model $S(machine) $len $S(tableOffset)]
        set S(prev) {}
    }

    # Reads the axis words of the NC line, updates the modal machine
    # state, and when move (a motion move record) carries a CL target
    # (P, t) measures the deviation. A written value outside the travel or
    # the rotary limits is counted and raises {FIVAX MACHINE LIMIT} with
    # the move's FILE:LINE.
    method block {line move} {
        namespace upvar ::fivax::num pi pi
        set text [regsub -all {\([^)]*\)} $line ""]
        set written {}
        # (a flat pattern: nested groups with -all -inline cost 30 times more)
        foreach word [regexp -all -inline {[A-Z][-+.0-9]+} $text] {
            set letter [string index $word 0]
            set value [string range $word 1 end]
            if {![string is double -strict $value]} continue
            if {$letter in {X Y Z}} {
                set S($letter) $value
                lappend written $letter $value
            } elseif {[set i [lsearch -exact $S(names) $letter]] >= 0} {
                set q [::fivax::num::rad $value]
                lappend written $letter $q
                set S(q[expr {$i + 1}]) $q
            }
        }
        if {[llength [::fivax::machine::outside $S(machine) $written]]} {
            incr S(limitViolations)
            set where [dict get $move src]
            if {$where eq ""} {set where "NC block '$line'"}
            ::fivax::machine::checkLimits $S(machine) $written $where
        }
        set P [dict get $move P]
        if {$P eq "" || $S(X) eq "" || $S(Y) eq "" || $S(Z) eq "" || $S(q1) eq "" || $S(q2) eq ""} {
            if {$P eq ""} {set S(prev) {}}
            return
        }
        set t [dict get $move t]
        set joints [list $S(X) $S(Y) $S(Z) $S(q1) $S(q2)]
        lassign [::fivax::kin::forward $S(model) $joints] Pm tm
        set dp [::fivax::vec::norm [::fivax::vec::sub $Pm $P]]
        set da [::fivax::num::deg [::fivax::vec::angle $tm $t]]
        incr S(checked)
        if {$dp > $S(maxPos)} {set S(maxPos) $dp; set S(worst) [dict get $move src]}
        if {$da > $S(maxAng)} {set S(maxAng) $da}
        if {[dict get $move kind] eq "feed" && $S(prev) ne ""} {
            my Segment $S(prev) $joints $P $t [dict get $move src]
        }
        set S(prev) [list $joints $P $t]
    }

    # Measures the tip and axis at the quarter points of the linear joint
    # interpolation from the previous checked block to joints; a rotary
    # that rolls over turns the shortest way.
    method Segment {prev joints P t src} {
        namespace upvar ::fivax::num pi pi
        lassign $prev j0 P0 t0
        foreach i {3 4} roll $S(rollover) {
            if {$roll} {
                set a [lindex $j0 $i]
                set d [expr {[lindex $joints $i] - $a}]
                lset joints $i [expr {$a + $d - 2.0 * $pi * round($d / (2.0 * $pi))}]
            }
        }
        incr S(segments)
        lassign [::fivax::kin::interpolationError $S(model) $j0 $joints $P0 $P $t0 $t] dp da
        set da [::fivax::num::deg $da]
        if {$dp > $S(maxMidPos)} {set S(maxMidPos) $dp; set S(worstMid) $src}
        if {$da > $S(maxMidAng)} {set S(maxMidAng) $da}
    }

    # Returns a dict: checked (CL points), segments, maxPos (mm), maxAng
    # (deg) at the CL points, maxMidPos (mm), maxMidAng (deg) inside
    # cutting moves, limitViolations, worst and worstMid (FILE:LINE of the
    # largest errors).
    method summary {} {
        dict create checked $S(checked) segments $S(segments) maxPos $S(maxPos) \
            maxAng $S(maxAng) maxMidPos $S(maxMidPos) maxMidAng $S(maxMidAng) \
            limitViolations $S(limitViolations) worst $S(worst) worstMid $S(worstMid)
    }
}
