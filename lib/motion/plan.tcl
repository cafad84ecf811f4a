# plan.tcl --
#	The motion planner (spec/kinematics.md sections 6 to 8): turns CL
#	points (tool tip and axis in the workpiece frame) into neutral machine
#	move records (their contract: record.tcl). One namespace,
#	::fivax::motion, over the files of lib/motion/ (record.tcl aside):
#	    plan.tcl        the Planner API, whole-path choice and windows
#	    candidates.tcl  candidate rotary values: a pure function of the
#	                    planning context (model, limits), tool axis and
#	                    references
#	    moves.tcl       move records: approach, transfer, retract
#	    linearise.tcl   splitting moves until the joint interpolation
#	                    stays within tolerance
#	    feeds.tcl       feed clamp and the feed of each cutting move
#	    holes.tcl       drilling: canned cycle records or expanded moves
#	    frames.tcl      the output frame: native arcs, tilted work planes
#
#	Choice. A cutting move may go from one candidate to the next when both
#	lie on the same branch (or one is in the singular cone, where branches
#	meet) and no axis turns more than the machine's max_swing; otherwise it
#	needs a retract. Cost = w1 |dq1| + w2 |dq2| (radians, -weights) plus
#	retractCost per retract, so the fewest retracts win, then the least
#	weighted travel. 'optimal' (default) picks the whole sequence by dynamic
#	programming over the candidate graph; 'greedy' takes at each point the
#	candidate with the smallest tilt change, then azimuth change.
#
#	Windows. The optimiser keeps at most -window CL points. When the buffer
#	is full it writes the prefix up to the point where the best paths to all
#	current candidates merge: any whole-operation optimum passes through one
#	of those candidates, so that prefix is exactly the one the optimum has.
#	If they have not merged over half the window (two configurations cost
#	the same all along, e.g. the two branches on a continuous azimuth), it
#	writes the first half along the best path, still with at least half a
#	window of look-ahead, and restarts the tables from there. Either way
#	every written move is checked against the limits and continues from the
#	last written state, and memory stays bounded by the window.
#
#	Angles in radians inside; options and statistics in degrees.
#	Errors: {FIVAX OPTION ...} for options, {FIVAX MOTION <DETAIL>}.

namespace eval ::fivax::motion {
    namespace export create
    namespace ensemble create -prefixes 0
    namespace upvar ::fivax::num pi pi
    # Cost of one retract (radian-equivalents of travel): far more than the
    # travel of any window (a few turns per point at most, 100000 points),
    # so the optimiser first minimises retracts, then travel.
    variable retractCost 1e6
    # Tie-breaks at the first point of a path: per violated sign
    # preference, and per radian away from zero (smallest values first).
    variable preferCost 1e-6
    variable zeroCost 1e-9
    # Linearisation splits a cutting move at most this many levels deep,
    # into at most about maxPieces pieces (a full turn of a rotary 500 mm
    # from the tip at the default tolerance takes about 500).
    variable maxDepth 12
    variable maxPieces 10000
    # CL axes of a cutting move within this angle (rad) of opposite ones
    # have no defined great circle between them (see CheckFlip).
    variable flipSlack 1e-6
    # The planner's options (see ::fivax::opts).
    variable Options {
        {-table-offset {maybe vec3} {} "X Y Z"
            "workpiece-frame position of the table reference point (default: the machine's table_offset)"}
        {-msys bool 0 "" "express the CL data in the frame of the MSYS record"}
        {-feed {enum inverse direct dpm} inverse MODE
            "feed on moves with rotary motion: inverse (G93 inverse time), direct (mm/min) or dpm (degrees per minute)"}
        {-rotary {enum optimal greedy} optimal CHOICE
            "rotary solution choice: optimal (whole path) or greedy (point by point)"}
        {-on-limit {enum retract error} retract ACTION
            "no in-limit continuation: retract (retract, reposition, re-engage) or error"}
        {-tol {real min 0} 0.01 MM "linearisation tolerance of the tool tip (0: no linearisation)"}
        {-atol {real min 0} 0.05 DEG "linearisation tolerance of the tool axis (0: not checked)"}
        {-cone {real min 0} 0.0001 DEG "half-angle of the singular cone, where the azimuth is held"}
        {-swing {real min 0} 10 DEG "azimuth swing threshold counted as a singular swing"}
        {-clearance {maybe real min 0} {} MM
            "retract distance along the tool axis (default: the machine's clearance)"}
        {-weights {reals 2 gt 0} {1 1} "W1 W2" "travel weights of the tilt and azimuth axes"}
        {-window {int min 2 max 100000} 4000 N
            "CL points the optimiser holds at most (about 1.5 kB each)"}
        {-tcp {maybe bool} {} "0|1"
            "TCP mode: X Y Z are the tool tip, feeds the tip feed (G94), no linearisation: the control keeps the tip on the path (default: the machine's tcp)"}
        {-arcs {enum native points} native MODE
            "CL arcs: native (G2/G3 or the control's own arc lines, where the control has them in the output frame's plane) or points"}
        {-workplane {enum auto on off} auto MODE
            "an operation with a fixed tool axis off Z: in a tilted work plane (auto: where the control has one; on: an error where it has none) or as five-axis blocks (off)"}
        {-output any {} DICT "what the output dialect writes (the output Writer's capabilities)"}
        {-angle-step {real min 0} 0 DEG
            "output resolution of the rotary words: rotaries are rounded to it before X Y Z are computed (0: exact)"}
        {-length-step {real min 0} 0 MM
            "output resolution of the X Y Z words, a power of ten: the linearisation measures X Y Z rounded to it, as written (0: exact)"}
    }
}

# ::fivax::motion::create --
#	Returns a new Planner object for machine (a fivax::machine dict);
#	options as in the Options table. Destroy it with "$planner destroy".
proc ::fivax::motion::create {machine args} {
    variable Options
    Planner new $machine [::fivax::opts::parse $Options $args "motion create"]
}

oo::class create ::fivax::motion::Planner {
    # S: the planner's state; the keys are listed in the constructor (n1,
    # n2: the names of the tilt and azimuth axes).
    variable S

    # Sets up the planner for machine with the parsed option dict opts.
    constructor {machine opts} {
        namespace upvar ::fivax::motion pi pi
        set S(machine) $machine
        set S(name) [dict get $machine name]
        dict for {opt value} $opts {set S([string range $opt 1 end]) $value}
        if {$S(clearance) eq ""} {set S(clearance) [dict get $machine clearance]}
        if {$S(tcp) eq ""} {set S(tcp) [dict get $machine tcp]}
        set S(output) [dict merge {controller "" inverse 1 plane 0 arcPlanes {} helix 0} $S(output)]
        if {$S(workplane) eq "on" && ![dict get $S(output) plane]} {
            ::fivax::Fail OPTION VALUE "-workplane on: the [dict get $S(output) controller]\
                control [expr {$S(tcp) ? {in TCP mode } : {}}]has no tilted work plane:\
                use -workplane auto (rotaries positioned, X Y Z transformed) or off"
        }
        if {$S(feed) eq "inverse" && ![dict get $S(output) inverse]} {
            # a writer without inverse time (Klartext): F is the feed of
            # all axes together, degrees counted as mm, which keeps the
            # tip feed
            set S(feed) dpm
        }
        if {$S(tcp)} {
            # the control interpolates the tip: no linearisation, tip feed
            set S(tol) 0.0
            set S(atol) 0.0
            set S(feed) direct
        }
        foreach {key name} {feedMin feed_min feedMax feed_max itMax inverse_time_max
            safeZ safe_z} {
            set S($key) [dict get $machine $name]
        }
        # -atol 0: no check of the tool axis between blocks
        set S(atolCheck) [expr {$S(atol) > 0 ? [::fivax::num::rad $S(atol)] : Inf}]
        set S(swingRad) [::fivax::num::rad $S(swing)]
        my WrittenResolution
        # the cost of a retract (see Relax)
        namespace upvar ::fivax::motion retractCost retractCost
        set S(retractCost) $retractCost
        lassign $S(weights) S(w1) S(w2)
        # Per-axis data in chain order (tilt, azimuth) for the candidates.
        set S(axes) {}
        foreach axis [dict get $machine chain] {
            set ms [dict get $machine max_swing]
            if {[dict get $axis rollover]} {set ms [expr {min($ms, $pi - 1e-9)}]}
            set min [dict get $axis min]
            set max [dict get $axis max]
            set cont [dict get $axis continuous]
            lappend S(axes) [dict create name [dict get $axis name] min $min max $max \
                continuous $cont unlimited [expr {$cont && $max - $min > 1e299}] \
                rollover [dict get $axis rollover] prefer [dict get $axis prefer] swing $ms]
        }
        lassign [lmap axis $S(axes) {dict get $axis name}] S(n1) S(n2)
        set S(frame) {}
        array set S {buf {} pathStart 1 points 0 moves 0 travel 0.0
            inserted 0 retracts 0 holds 0 swings 0 unresolved 0 forced 0 dwells 0
            dwellTurn 0.0 clamps 0 slowdown 0.0
            held "" heldAxis "" plane "" wp off clampIn -Inf clampOut ""}
        my Reached "" "" ""
        set S(entryFeed) [dict get $machine entry_feed]
        my setTool [dict get $machine tool_length]
    }

    # Rebuilds the kinematic model for a tool of length len (mm). Call
    # flush first: points still held would be posted for the new tool.
    # Errors: {FIVAX MOTION STATE} while points are held.
    # The tool then stands at the tool-change position: the next point is
    # approached as a first point (see First).
    method setTool {len} {
        if {[llength $S(buf)]} {
            ::fivax::Fail MOTION STATE "setTool with [llength $S(buf)] CL points held: flush first"
        }
        my Unknown
        set model [::fivax::kin::model $S(machine) $len $S(table-offset)]
        set S(toolLength) $len
        set S(ctx) [::fivax::motion::Context $model $S(name) $S(axes) $S(cone) $S(angle-step)]
        set S(model) $model
        # per-machine constants of the per-point path: the axes' max_swing,
        # and the axis error of a point record (see Linearise)
        lassign [dict get $S(ctx) swing] S(ms1) S(ms2)
        set S(actError) [expr {[dict get $S(ctx) step] + 1e-7}]
    }

    # Sets the MSYS frame (origin and unit X, Y axes of the MCS in absolute
    # coordinates); CL data are mapped through it when -msys is on.
    method setFrame {origin xaxis yaxis} {
        if {!$S(msys)} return
        set S(frame) [list $origin $xaxis $yaxis [::fivax::vec::cross $xaxis $yaxis]]
    }

    # Marks the start of an operation: its first point follows the
    # machine's sign preference where that costs nothing. Returns the moves
    # still held (as flush).
    method startPath {} {
        set moves [my endPath]
        set S(pathStart) 1
        my HoldPlane
        return $moves
    }

    # Adds one CL point: kind rapid|feed, tip P and axis t (CL frame), feed
    # (mm/min, ignored for rapids), src (FILE:LINE for messages). Returns
    # the move records ready to be written, possibly none while the
    # optimiser's window fills (see flush).
    # Errors: {FIVAX MOTION UNREACHABLE}, {FIVAX MOTION LIMIT}.
    method add {kind P t feed src} {
        set pre {}
        if {$S(wp) ne "off"} {
            lassign [my Route [list add $kind $P $t $feed $src] $t] done pre
            if {$done} {return $pre}
        }
        if {$S(frame) ne ""} {lassign [my ToWork $P $t] P t}
        list {*}$pre {*}[my AddWork $kind $P [::fivax::vec::unit $t] $feed $src]
    }

    # Returns every move record still held (every kind, its fields and
    # their units: lib/motion/record.tcl, the move-record contract). A
    # held work-plane segment (see frames.tcl) is posted: in its plane
    # when it cuts.
    method flush {} {
        if {$S(wp) eq "hold"} {
            if {[my HeldCuts]} {return [my StartPlane]}
            return [my ReleaseHeld free]
        }
        if {![llength $S(buf)]} {return {}}
        my Commit 1
    }

    # Returns a dict: points, moves, travel (deg of rotary travel
    # written), inserted (linearisation points), retracts, holds (CL
    # points posted with the azimuth held in the singular cone), swings
    # (azimuth swings above -swing between close points), unresolved
    # (cutting moves whose quarter points, X Y Z as written, are still
    # beyond -tol or -atol after the deepest split), forced
    # (window commits before the merge).
    # dwells (cutting moves that only turn the rotaries with the tip at
    # rest) and dwellTurn (deg), clamps (inverse-time feeds of moves of the
    # tip clamped at the machine's inverse_time_max) and slowdown (the
    # worst factor by which a clamped move runs slower than programmed).
    method stats {} {
        set d [dict create travel [::fivax::num::deg $S(travel)] \
            dwellTurn [::fivax::num::deg $S(dwellTurn)]]
        foreach key {points moves inserted retracts holds swings unresolved forced dwells
            clamps slowdown} {
            dict set d $key $S($key)
        }
        return $d
    }

    # Returns the moves that end the program: those still held, then a
    # retract along the tool axis by the clearance when the last move cut.
    # The position is unknown afterwards (the host sends the tool home).
    method finish {} {
        set moves [my flush]
        if {$S(last) ne "" && $S(lastKind) eq "feed"} {
            set up [my Above $S(last)]
            lassign $up joints P - act
            set move [my Move rapid $joints {X Y Z} $P $act {} $S(lastSrc)]
            my Travel [list $move]
            lappend moves $move
        }
        my Unknown
        return $moves
    }

    # Returns the direction v (a CL vector, e.g. a contact's surface
    # normal) in the workpiece frame: mapped through the MSYS frame when
    # enabled.
    method workVector {v} {
        if {$S(frame) eq ""} {return $v}
        lassign $S(frame) o x y z
        ::fivax::motion::FrameApply $x $y $z $v
    }

    # Returns {P t} mapped through the MSYS frame when enabled (S(frame)
    # is set only then).
    method ToWork {P t} {
        if {$S(frame) eq ""} {return [list $P $t]}
        lassign $S(frame) o x y z
        list [::fivax::vec::add $o [::fivax::motion::FrameApply $x $y $z $P]] [my workVector $t]
    }

    # Returns 1 when the next point may take any configuration: nothing
    # written yet, or an operation's first point reached by a rapid.
    method Fresh {kind} {
        expr {$S(last) eq "" || ($S(pathStart) && $kind eq "rapid")}
    }

    # Returns {q1 q2 branch} of the last written point, or {}.
    method LastRefs {} {
        if {$S(last) eq ""} {return {}}
        lassign $S(last) joints - - - lab
        list [lindex $joints 3] [lindex $joints 4] $lab
    }

    # Posts one CL point with the greedy choice: the preferred candidate
    # at a fresh start, else the nearest one that needs no retract (the
    # nearest of all, with a retract, when none does).
    method Greedy {kind P t feed src} {
        set ctx $S(ctx)
        set refs [my LastRefs]
        set cone [::fivax::motion::InCone $ctx $t]
        set cands [::fivax::motion::Candidates $ctx $t $cone $refs $src]
        if {[my Fresh $kind]} {
            set choice [::fivax::motion::Preferred $ctx $cands]
        } else {
            lassign $refs a1 a2 al
            set ms1 $S(ms1)
            set ms2 $S(ms2)
            set isFeed [expr {$kind eq "feed"}]
            set ok {}
            foreach {b1 b2 bl} $cands {
                if {!$isFeed || [::fivax::motion::Continues $ms1 $ms2 $a1 $a2 $al $b1 $b2 $bl]} {
                    lappend ok $b1 $b2 $bl
                }
            }
            if {![llength $ok]} {
                if {$S(on-limit) eq "error"} {::fivax::motion::LimitError $ctx $a1 $a2 $t $src}
                set ok $cands
            }
            set choice [::fivax::motion::Nearest [list $a1 $a2] $ok]
        }
        set S(pathStart) 0
        my Emit $kind $P $t $feed $src $cone {*}$choice
    }

    # Adds CL point P, t (already in the workpiece frame) as add does:
    # greedy, or to the optimiser's buffer as a layer
    # {kind P t feed src states cone}, states being the flat list
    # {q1 q2 branch cost back ...}: cost of the best path from the last
    # written point (normalised to a minimum of 0), back the index of its
    # predecessor in the previous layer (-1 for the first layer); cone is
    # InCone of t. Returns the moves of a full window's settled part.
    method AddWork {kind P t feed src} {
        incr S(points)
        if {$S(rotary) eq "greedy"} {
            return [my Greedy $kind $P $t $feed $src]
        }
        set ctx $S(ctx)
        if {[llength $S(buf)]} {
            set prev [lindex $S(buf) end 5]
            set fresh 0
        } else {
            set prev [expr {$S(last) ne "" ? [list {*}[my LastRefs] 0.0 -1] : {}}]
            set fresh [my Fresh $kind]
        }
        set refs {}
        foreach {a b lab - -} $prev {lappend refs $a $b $lab}
        set cone [::fivax::motion::InCone $ctx $t]
        set cands [::fivax::motion::Candidates $ctx $t $cone $refs $src]
        set S(pathStart) 0
        if {![llength $prev]} {
            namespace upvar ::fivax::motion zeroCost zeroCost
            set states {}
            foreach {b1 b2 bl} $cands {
                lappend states $b1 $b2 $bl [expr {[::fivax::motion::PreferCost $ctx $b1 $b2]
                    + $zeroCost * (abs($b1) + abs($b2))}] -1
            }
        } else {
            set states [my Relax $prev $cands [expr {$kind eq "feed"}] $t $src]
            if {$fresh} {
                set i 3
                foreach {b1 b2 - c -} $states {
                    lset states $i [expr {$c + [::fivax::motion::PreferCost $ctx $b1 $b2]}]
                    incr i 5
                }
            }
        }
        lappend S(buf) [list $kind $P $t $feed $src $states $cone]
        if {[llength $S(buf)] < $S(window)} {return {}}
        my Commit 0
    }

    # Returns the states (see AddWork) of the candidate triples cands reached
    # from the states prev by a move of the given kind (isFeed 1: cutting),
    # the cost of a move being its weighted travel plus retractCost when a
    # cutting move cannot go continuously (see Continues). With -on-limit
    # error, moves needing a retract are excluded and a
    # layer left unreachable raises {FIVAX MOTION LIMIT} naming src. States
    # equal mod 360 deg on unlimited continuous axes have the same future;
    # only the cheaper is kept.
    method Relax {prev cands isFeed t src} {
        if {[llength $cands] == 3 && [llength $prev] == 5 && $S(on-limit) ne "error"} {
            # one candidate reached from one state, a retract allowed: that
            # state is its predecessor, its normalised cost 0
            return [list {*}$cands 0.0 0]
        }
        set ms1 $S(ms1)
        set ms2 $S(ms2)
        set w1 $S(w1)
        set w2 $S(w2)
        set err [expr {$S(on-limit) eq "error"}]
        set states {}
        set low Inf
        foreach {b1 b2 bl} $cands {
            set best Inf
            set arg -1
            set i 0
            foreach {a1 a2 al ac -} $prev {
                # (as abs(), see Continues)
                set c [expr {$w1 * ($b1 > $a1 ? $b1 - $a1 : $a1 - $b1)
                    + $w2 * ($b2 > $a2 ? $b2 - $a2 : $a2 - $b2)}]
                if {$isFeed && ![::fivax::motion::Continues $ms1 $ms2 $a1 $a2 $al $b1 $b2 $bl]} {
                    set c [expr {$c + $S(retractCost)}]
                }
                if {!($err && $c >= $S(retractCost)) && $ac + $c < $best} {
                    set best [expr {$ac + $c}]
                    set arg $i
                }
                incr i
            }
            lappend states $b1 $b2 $bl $best $arg
            if {$best < $low} {set low $best}
        }
        if {$low == Inf} {
            set i [::fivax::motion::BestState $prev]
            ::fivax::motion::LimitError $S(ctx) [lindex $prev [expr {5 * $i}]] \
                [lindex $prev [expr {5 * $i + 1}]] $t $src
        }
        set i 3
        foreach {- - - c -} $states {
            lset states $i [expr {$c - $low}]
            incr i 5
        }
        if {[llength $states] > 5} {set states [::fivax::motion::Fold $S(axes) $states]}
        return $states
    }

    # Writes the settled part of the buffer and returns its moves: all of
    # it along the best path when all is 1; else the prefix up to the
    # merge point when it covers half the window, or else the first half
    # along the best path, the rest being re-rooted at the last written
    # point.
    method Commit {all} {
        set n [llength $S(buf)]
        set path [::fivax::motion::Trace $S(buf) \
            [::fivax::motion::BestState [lindex $S(buf) end 5]]]
        set k $n
        set forced 0
        if {!$all} {
            set m [::fivax::motion::Merge $S(buf)]
            set k [expr {$m >= $n / 2 - 1 ? $m + 1 : $n / 2}]
            set forced [expr {$m < $n / 2 - 1}]
        }
        set moves {}
        foreach layer [lrange $S(buf) 0 [expr {$k - 1}]] i [lrange $path 0 [expr {$k - 1}]] \
                az [my Departures $path $k] {
            lassign $layer kind P t feed src states cone
            lassign [lrange $states [expr {5 * $i}] [expr {5 * $i + 2}]] q1 q2 lab
            if {$az ne ""} {
                set q2 $az
                set q1 [::fivax::motion::HoldTilt $S(ctx) $t $q1 $q2]
            }
            lappend moves {*}[my Emit $kind $P $t $feed $src $cone $q1 $q2 $lab]
        }
        set S(buf) [lrange $S(buf) $k end]
        if {$forced} {
            incr S(forced)
            my Reroot
        }
        return $moves
    }

    # Returns the azimuths of layers 0 .. k-1 that the approach sets (q2,
    # "" where the path's own stays):
    # where a rapid reaches the singular cone (the azimuth free there) and
    # the path then leaves the cone, the rapid and the cone points after it
    # take the azimuth the path leaves with (Departure: its limit at the
    # cone), so the azimuth turns during the approach and not with the tool
    # at cutting depth. Only runs that end
    # before layer k of the best path (the written prefix) and whose tilt
    # stays within the limits at that azimuth.
    method Departures {path k} {
        set ctx $S(ctx)
        set out [lrepeat $k ""]
        set n [llength $path]
        # (the held rapids, and after a run the first layer past it)
        set next 0
        foreach j [lsearch -all -exact -index 0 $S(buf) rapid] {
            if {$j >= $k} break
            if {$j < $next || ![lindex $S(buf) $j 6]} continue
            set e $j
            while {$e < $n && [lindex $S(buf) $e 6]} {incr e}
            if {$e >= $n} break
            # the azimuth the path leaves the cone with (as Split sees it)
            set q2 [lindex [::fivax::motion::Quantize [dict get $ctx step] \
                [::fivax::motion::Departure $ctx [my PathRecord $path [expr {$e - 1}]] \
                [my PathRecord $path $e] [lindex $S(buf) $e 4]]] 0]
            set ok 1
            for {set i $j} {$i < $e} {incr i} {
                set q1 [lindex $S(buf) $i 5 [expr {5 * [lindex $path $i]}]]
                if {[::fivax::motion::HoldTilt $ctx [lindex $S(buf) $i 2] $q1 $q2] eq ""} {set ok 0}
            }
            if {$ok && $e < $k} {
                for {set i $j} {$i < $e} {incr i} {lset out $i $q2}
            }
            set next $e
        }
        return $out
    }

    # Returns the point record (see Split) of held layer i on the path.
    method PathRecord {path i} {
        lassign [lindex $S(buf) $i] - P t - - states
        lassign [lrange $states [expr {5 * [lindex $path $i]}] end] q1 q2 lab
        list [list 0.0 0.0 0.0 $q1 $q2] $P $t {} $lab
    }

    # Recomputes the costs of the held layers from the last written point.
    method Reroot {} {
        set prev [list {*}[my LastRefs] 0.0 -1]
        set buf {}
        foreach layer $S(buf) {
            lassign $layer kind P t feed src states
            set cands {}
            foreach {a b lab - -} $states {lappend cands $a $b $lab}
            set states [my Relax $prev $cands [expr {$kind eq "feed"}] $t $src]
            lappend buf [lreplace $layer 5 5 $states]
            set prev $states
        }
        set S(buf) $buf
    }
}

# ::fivax::motion::FrameApply -- Returns v.x X + v.y Y + v.z Z.
proc ::fivax::motion::FrameApply {x y z v} {
    lassign $v a b c
    ::fivax::vec::add [::fivax::vec::add [::fivax::vec::scale $a $x] \
        [::fivax::vec::scale $b $y]] [::fivax::vec::scale $c $z]
}

# ::fivax::motion::Fold --
#	Returns the flat states with those equal mod 360 deg on the unlimited
#	continuous axes (axes: the planner's per-axis dicts) merged into the
#	cheapest of them; states unchanged when no axis is unlimited.
proc ::fivax::motion::Fold {axes states} {
    variable pi
    lassign [lmap axis $axes {dict get $axis unlimited}] u1 u2
    if {!$u1 && !$u2} {return $states}
    set twoPi [expr {2.0 * $pi}]
    set keep [dict create]
    foreach {a b lab c back} $states {
        set ka [expr {$u1 ? $a - $twoPi * floor($a / $twoPi + 1e-9) : $a}]
        set kb [expr {$u2 ? $b - $twoPi * floor($b / $twoPi + 1e-9) : $b}]
        set key [format "%.7f %.7f %d" $ka $kb $lab]
        if {![dict exists $keep $key] || $c < [lindex [dict get $keep $key] 3]} {
            dict set keep $key [list $a $b $lab $c $back]
        }
    }
    concat {*}[dict values $keep]
}

# ::fivax::motion::BestState -- Returns the index of the cheapest of the flat states.
proc ::fivax::motion::BestState {states} {
    set best -1
    set bc Inf
    set i 0
    foreach {- - - c -} $states {
        if {$c < $bc} {set bc $c; set best $i}
        incr i
    }
    return $best
}

# ::fivax::motion::Trace --
#	Returns the state index of every layer of buf on the best path ending
#	in state index last of the last layer.
proc ::fivax::motion::Trace {buf last} {
    set path [list $last]
    foreach layer [lreverse [lrange $buf 1 end]] {
        lappend path [set last [lindex $layer 5 [expr {5 * $last + 4}]]]
    }
    lreverse $path
}

# ::fivax::motion::Merge --
#	Returns the index of the last layer of buf where the best paths to all
#	reachable states of the last layer pass through one state, or -1.
proc ::fivax::motion::Merge {buf} {
    set live [dict create]
    set i 0
    foreach {- - - c -} [lindex $buf end 5] {
        if {$c < Inf} {dict set live $i 1}
        incr i
    }
    for {set j [expr {[llength $buf] - 1}]} {$j > 0} {incr j -1} {
        if {[dict size $live] == 1} {return $j}
        set states [lindex $buf $j 5]
        set next [dict create]
        foreach s [dict keys $live] {dict set next [lindex $states [expr {5 * $s + 4}]] 1}
        set live $next
    }
    expr {[dict size $live] == 1 ? 0 : -1}
}
