# dryrun.tcl --
#	A machine dry run of an NC program (any dialect the verify Checker
#	reads): the program is read block by block with the Checker, which
#	gives the words, the motion and the tool's pose in the workpiece frame,
#	and the machine state around it is kept here: units, work offset, the
#	tool in the spindle (number, length, radius), length compensation,
#	TCP, the tilted work plane, spindle and speed, coolant, feed mode and
#	the program's end. What a machinist would stop the machine for is an
#	event {lineNo kind what}:
#	    spindle     a cutting move (G1 G2 G3, a canned-cycle hole) with
#	                the spindle off or S0
#	    rapid       a rapid whose cutter passes below the stock's surface
#	    collision   shank, holder or spindle nose through the stock, or a
#	                body below the table's top
#	    lengthcomp  G43 / TCP (the reader's tcpG) with H in a block with no move along Z
#	    mode        TCP or a work plane switched with the tool at cutting
#	                depth (tip below the stock's top, less than depthClear
#	                above its surface)
#	    toollength  the program's tool length (its FIVAX TOOL comment)
#	                differs from the tool table's
#	    end         blocks after M2/M30 (or the reader's end); a program that never ends
#	    unreadable  a word or block the Checker cannot interpret
#
#	The stock is a height map over the x-y of the workpiece frame. With
#	-stock it is that box, lowered where the cutter passes at feed, move
#	by move. Without it the dry run knows only what the program cuts: the
#	box of the tips of its cutting moves (feed moves that do not back out
#	along the tool axis, and hole bottoms), and in it the part as the
#	program leaves it: each cell lowered by every cut, the cells no cut
#	reaches that are enclosed by cuts (a boss) at the highest cut near
#	them (tool axis within 60 deg of +Z), those reached from the box's
#	edge air. The table's top is the machine's table_top, else with
#	-stock the stock's bottom, else unknown (no table check).
#
#	Bodies are cylinders along the tool axis from the tip: the cutter
#	(fluteRadii tool radii long, the tool's radius), the shank (up to the
#	tool's own length, the same radius), the holder above it and the
#	spindle nose above that (the machine's holder and spindle_nose
#	{diameter length}). A body is taken as flat discs across the map at
#	samples along its axis, their rims dipping by the tilt: exact for a
#	vertical tool, conservative by at most a radius when tilted.
#	Moves are sampled as the control moves: joint-space moves by forward
#	kinematics of the linearly interpolated joints (a body swing is seen),
#	TCP and work-plane moves straight in the workpiece frame, arcs at
#	their points. A move from an unknown position (after G53, a new work
#	plane) is seen at its end only.

namespace eval ::fivax::dryrun {
    namespace export run format tools tooling toolStep progress
    namespace ensemble create -prefixes 0
    variable Options {
        {-controller {maybe word} {} NAME "dialect of the NC text (default: the machine's controller)"}
        {-stock {maybe reals 6} {} "X0 Y0 Z0 X1 Y1 Z1"
            "stock box in the workpiece frame (default: the box of the cutting moves' tips grown by the tool radius)"}
        {-tools any {} DICT "tool table: tool number -> {length L radius R} (see tools)"}
        {-table-offset {maybe vec3} {} "X Y Z" "workpiece-frame position of the table reference point"}
        {-tool-length {maybe real} {} MM
            "tool length for the kinematics (default: the tool table's, else the program's FIVAX TOOL comment, else the machine's tool_length)"}
    }
    # Cells of the height map along the stock's longer side, and the
    # smallest cell (mm): 2.5 mm on a 300 mm part.
    variable cells 120
    # The default stock's top near a cut is the highest cut within about
    # this many cells (20 to 40 mm on a 300 mm part).
    variable nearCells 8
    variable minCell 0.25
    # The side (cells) of the blocks whose highest cell is kept (a quick
    # test that a body stays above all of a region).
    variable blockCells 8
    # Poses of a move tested at once for a tool well clear (see Clear).
    variable chunk 16
    # The height of a cell with no stock.
    variable air -1e9
    # How far (mm) a body may dip below the stock's surface or the table
    # before it counts (the written words' rounding).
    variable eps 0.05
    # The cutter's length in tool radii: the flutes cut, the shank above
    # them does not.
    variable fluteRadii 4
    # Most samples along one move, and the largest rotary step (rad)
    # between two samples of a joint-space move.
    variable maxSamples 2000
    variable rotaryStep 0.0175
    # The tip is at cutting depth (for switching TCP or a work plane)
    # below the stock's top and less than this (mm) above its surface.
    variable depthClear 1.0
    # Two tool lengths differ when they differ by more than this (mm).
    variable lengthTol 0.0005
    # The progress command (see progress) and how many lines or moves
    # apart it runs.
    variable progress ""
    variable progressEvery 256
    # R: the state of one run (see run).
    variable R
}

# ::fivax::dryrun::run --
#	Returns the events of a dry run of the NC program lines (a list of
#	lines) on machine (a fivax::machine dict), each {lineNo kind what}
#	(lineNo 1-based), in line order; options as in the Options table.
proc ::fivax::dryrun::run {machine lines args} {
    variable Options
    variable R
    variable progress
    variable progressEvery
    set opts [::fivax::opts::parse $Options $args "dryrun run"]
    CheckTools [dict get $opts -tools]
    array unset R
    set controller [dict get $opts -controller]
    if {$controller eq ""} {set controller [dict get $machine controller]}
    array set R [list machine $machine opts $opts events {} moves {} \
        callComp [dict get [::fivax::dialect reader $controller -controller] callComp] \
        endName [dict get [::fivax::dialect reader $controller -controller] endName] \
        tcpG [dict get [::fivax::dialect reader $controller -controller] tcpG] units [dict get $machine units] \
        offset "" length [dict get $machine tool_length] radius 0.0 \
        comp 0 spindle 0 speed "" coolant 0 spindleSaid 0 end 0 endSaid 0 \
        pose "" joints "" space joint model "" progress $progress \
        every [expr {$progress eq "" ? 1 << 62 : $progressEvery}] followed 0 toFollow 0]
    set checker [::fivax::verify reader $machine -table-offset [dict get $opts -table-offset] \
        -controller $controller]
    set R(tooling) [tooling [dict get $opts -tools] [dict get $opts -tool-length]]
    if {[dict get $opts -tool-length] ne ""} {set R(length) [dict get $opts -tool-length]}
    try {
        SetLength $checker $R(length)
        set n 0
        set total [llength $lines]
        foreach line $lines {
            incr n
            ReadLine $checker $line $n
            if {$n % $R(every) == 0} {{*}$progress "lines read" $n $total}
        }
    } finally {
        $checker destroy
    }
    if {!$R(end)} {Event $n end "the program never ends (no [join [concat M2 M30 $R(endName)] {, }])"}
    Geometry
    lsort -integer -index 0 $R(events)
}

# ::fivax::dryrun::progress --
#	Sets the command prefix that runs from now on call with what ("lines
#	read", then "moves followed"), how many so far and of how many, every
#	256 lines or moves (for a progress display: the moves, followed
#	through the stock once the program is read, take most of the time);
#	"" (the default) turns it off. Returns the previous one.
proc ::fivax::dryrun::progress {cmd} {
    variable progress
    set old $progress
    set progress $cmd
    return $old
}

# ::fivax::dryrun::Followed --
#	Counts one more move followed through the stock; calls the progress
#	command every R(every) moves.
proc ::fivax::dryrun::Followed {} {
    variable R
    if {[incr R(followed)] % $R(every) == 0} {
        {*}$R(progress) "moves followed" $R(followed) $R(toFollow)
    }
}

# ::fivax::dryrun::format -- Returns the events as lines "FILE:LINE: kind: what".
proc ::fivax::dryrun::format {events file} {
    lmap e $events {
        lassign $e n kind what
        string cat $file : $n ": " $kind ": " $what
    }
}

# ::fivax::dryrun::tools --
#	Returns the tool table (tool number -> {length L radius R}) of text,
#	lines "T<n> LENGTH <L> ?RADIUS <R>?" (mm, the machine's units), blank
#	lines and lines starting with # ignored; src names the text in errors
#	(FILE:LINE, {FIVAX DRYRUN TOOLS}). The text is data: never evaluated.
proc ::fivax::dryrun::tools {text src} {
    set out {}
    set n 0
    foreach line [split $text \n] {
        incr n
        set line [string trim $line]
        if {$line eq "" || [string index $line 0] eq "#"} continue
        if {![regexp {^T(\d+)\s+LENGTH\s+(\S+)(?:\s+RADIUS\s+(\S+))?$} $line -> tool len rad]} {
            ::fivax::Fail DRYRUN TOOLS "$src:$n: not a tool line \"T<n> LENGTH <L> ?RADIUS <R>?\": $line"
        }
        set tool [scan $tool %d]
        if {[dict exists $out $tool]} {
            ::fivax::Fail DRYRUN TOOLS "$src:$n: tool $tool given twice"
        }
        set entry {}
        foreach key {length radius} v [list $len $rad] {
            if {$v eq ""} continue
            set x [::fivax::num::parse $v]
            if {$x eq "" || $x < 0 || $x > $::fivax::machine::maxLength} {
                ::fivax::Fail DRYRUN TOOLS "$src:$n: bad $key \"$v\": must be a number from 0 to\
                    [::format %g $::fivax::machine::maxLength]"
            }
            dict set entry $key $x
        }
        dict set out $tool $entry
    }
    return $out
}

# ::fivax::dryrun::CheckTools -- Fails unless tools is a tool table dict as tools returns.
proc ::fivax::dryrun::CheckTools {tools} {
    if {![string is list $tools] || [llength $tools] % 2} {
        ::fivax::Fail OPTION VALUE "dryrun run: bad -tools: not a dict of tool number -> {length L radius R}"
    }
    dict for {tool entry} $tools {
        if {![string is entier -strict $tool] || ![string is list $entry] || [llength $entry] % 2} {
            ::fivax::Fail OPTION VALUE "dryrun run: bad -tools entry \"$tool\": not tool number -> {length L radius R}"
        }
        dict for {key v} $entry {
            if {$key ni {length radius} || ![string is double -strict $v]} {
                ::fivax::Fail OPTION VALUE "dryrun run: bad -tools entry $tool: $key $v"
            }
        }
    }
}

# ::fivax::dryrun::Event -- Adds the event {n kind what}.
proc ::fivax::dryrun::Event {n kind what} {
    variable R
    lappend R(events) [list $n $kind $what]
}

# ::fivax::dryrun::ReadLine --
#	Reads line n with checker and follows the machine state it sets;
#	notes its move (Geometry looks at the moves once the stock is known).
proc ::fivax::dryrun::ReadLine {checker line n} {
    variable R
    set blk [$checker read $line]
    # (the tool follower changes at T and M words and comments only)
    if {[llength [dict get $blk comments]] || [string first T $line] >= 0
            || [string first M $line] >= 0} {
        set R(tooling) [toolStep $R(tooling) $blk]
        Tool $checker $n
    }
    if {![dict get $blk block]} {
        if {[dict get $blk end] && !$R(end)} {set R(end) $n}
        return
    }
    if {$R(end) && !$R(endSaid)} {
        Event $n end "block after the program's end at line $R(end)"
        set R(endSaid) 1
    }
    foreach {kind word} [dict get $blk unknown] {
        Event $n unreadable "$kind not understood: $word"
    }
    set moved [dict get $blk moved]
    Words [dict get $blk words] $moved $n
    if {[dict get $blk end] && !$R(end)} {set R(end) $n}
    set space [dict get $blk space]
    if {$space ne $R(space)} {
        # TCP or a work plane switched: where the tip was (Geometry)
        if {$R(pose) ne ""} {lappend R(moves) [list switch $n $R(pose) "$R(space) to $space"]}
        set R(space) $space
    }
    if {![llength $moved]} return
    set motion [dict get $blk motion]
    set hole [dict get $blk hole]
    if {($hole || $motion in {1 2 3}) && !($R(spindle) && $R(speed) ne "" && $R(speed) > 0)} {
        if {!$R(spindleSaid)} {
            set why [expr {$R(spindle) ? "S[expr {$R(speed) eq "" ? "" : $R(speed)}] (no speed)" : "the spindle off"}]
            Event $n spindle "[expr {$hole ? "a canned-cycle hole" : "G$motion"}] with $why"
            set R(spindleSaid) 1
        }
    }
    set pose [dict get $blk pose]
    if {$pose eq "" && $space eq "plane" && "Z" ni $moved && ("X" in $moved || "Y" in $moved)} {
        AcrossPlane $checker $n
    }
    if {$pose ne ""} {
        # (from an unknown position: the end only)
        set from [expr {$R(pose) eq "" ? $pose : $R(pose)}]
        set j0 [expr {$R(pose) eq "" ? [dict get $blk joints] : $R(joints)}]
        set kind [expr {$hole ? "hole" : ($motion == 0 ? "rapid" : "cut")}]
        set path {}
        if {[dict get $blk arc] ne ""} {
            set path [ArcPoses $checker [dict get $blk arc] [dict get $blk words] $pose]
        }
        if {$hole} {
            # (path: the poses at the R plane and at the return level)
            set path [HoleLevels $pose [$checker cycleLevels]]
        }
        lappend R(moves) [list $kind $n $from $pose $j0 [dict get $blk joints] \
            $space $R(model) [list $R(length) $R(radius)] $path]
        if {$hole} {
            # the tool ends at the return level above the hole
            set R(pose) [lindex $path 1]
            set R(joints) ""
            return
        }
    }
    set R(pose) $pose
    set R(joints) [dict get $blk joints]
}

# ::fivax::dryrun::HoleLevels --
#	Returns the poses {R return} of a canned-cycle hole whose bottom is at
#	pose {P t}, levels {R bottom return} (Z values of the block's space,
#	along the tool axis when the hole is drilled along it: verify's
#	drillOff checks that).
proc ::fivax::dryrun::HoleLevels {pose levels} {
    lassign $pose P t
    lassign $levels r bottom ret
    lmap z [list $r $ret] {
        list [::fivax::vec::add $P [::fivax::vec::scale [expr {$z - $bottom}] $t]] $t
    }
}

# ::fivax::dryrun::AcrossPlane --
#	A move across a tilted work plane at line n before its Z is known: on
#	a machine that tilts its head the plane's X Y are not level, so the
#	head goes down (or sideways) by an unknown amount; the approach must
#	reach the plane's Z along the tool axis first.
proc ::fivax::dryrun::AcrossPlane {checker n} {
    variable R
    if {[dict get $R(machine) kind] eq "tabletable"} return
    set axis [$checker planeAxis]
    if {$axis eq "" || [lindex $axis 2] > 0.99985} return
    Event $n rapid "move across the tilted work plane (tool axis [::format {%.3f %.3f %.3f} {*}$axis])\
        before its Z is known: the head moves down by an unknown amount (approach along the tool axis first)"
}

# ::fivax::dryrun::ArcPoses --
#	Returns the poses at the points of the arc {start centre plane dir}
#	(in the space's coordinates) of the block of words that ends at pose,
#	read by checker.
proc ::fivax::dryrun::ArcPoses {checker arc words pose} {
    lassign $arc start centre plane dir
    if {"" in $start || "" in $centre} {return {}}
    set end [lmap c {X Y Z} s $start {
        expr {[dict exists $words $c] ? [dict get $words $c] : $s}
    }]
    set normal [dict get {17 {0 0 1} 18 {0 1 0} 19 {1 0 0}} $plane]
    set out [lmap q [::fivax::curve::arc $start $end $centre $normal \
            [expr {$dir == 3 ? 1 : -1}] 0 0.05] {
        $checker poseAt $q
    }]
    lset out end $pose
    return $out
}

# ::fivax::dryrun::Words --
#	Follows the state words of a block (words: {letter value} pairs;
#	moved: its axis letters) at line n: units, work offset, length
#	compensation, spindle, coolant (tool changes: Tool).
proc ::fivax::dryrun::Words {words moved n} {
    variable R
    set h 0
    set on ""
    foreach {letter v} $words {
        switch -exact -- $letter {
            G {
                if {$v == 20 || $v == 70} {set R(units) inch}
                if {$v == 21 || $v == 71} {set R(units) mm}
                if {$v >= 54 && $v <= 59 && $v == round($v)} {set R(offset) [expr {int($v)}]}
                if {$v == 43 || [lsearch -exact -real $R(tcpG) $v] >= 0} {
                    set on G[expr {$v == 43 ? 43 : $v}]
                }
                if {$v == 49} {set R(comp) 0}
            }
            H {set h 1}
            D {set R(comp) [expr {$v != 0}]}
            S {
                if {$R(speed) ne $v} {set R(spindleSaid) 0}
                set R(speed) $v
            }
            M {
                switch -exact -- [expr {int($v)}] {
                    3 - 4 {set R(spindle) 1; set R(spindleSaid) 0}
                    5 {set R(spindle) 0}
                    7 - 8 {set R(coolant) 1}
                    9 {set R(coolant) 0}
                }
            }
        }
    }
    if {$R(units) ne [dict get $R(machine) units]} {
        Event $n mode "program in $R(units) on a [dict get $R(machine) units] machine"
        set R(units) [dict get $R(machine) units]
    }
    if {$on ne "" && $h} {
        set R(comp) 1
        if {"Z" ni $moved} {
            Event $n lengthcomp "$on H switched on in a block with no Z move"
        }
    }
}

# ::fivax::dryrun::Tool --
#	Follows the tool the follower R(tooling) saw at line n: its notes as
#	events, a tool call (the spindle stops; where the reader's callComp
#	is 1 it switches length compensation on), its length and radius.
proc ::fivax::dryrun::Tool {checker n} {
    variable R
    foreach note [dict get $R(tooling) notes] {Event $n {*}$note}
    if {[dict get $R(tooling) called]} {
        set R(spindle) 0
        set R(spindleSaid) 0
        if {$R(callComp)} {set R(comp) 1}
    }
    set len [dict get $R(tooling) length]
    if {$len ne "" && $len != $R(length)} {SetLength $checker $len}
    set rad [dict get $R(tooling) radius]
    if {$rad ne ""} {set R(radius) $rad}
}

# ::fivax::dryrun::SetLength -- Reads on with a tool of length len (mm).
proc ::fivax::dryrun::SetLength {checker len} {
    variable R
    set R(length) $len
    $checker setTool $len
    set R(model) [$checker model]
}

# ::fivax::dryrun::tooling --
#	Returns a new tool follower (a dict, see toolStep) for the tool table
#	tools (as tools returns) and override (a tool length that wins over
#	both the table and the program, or ""). The dry run,
#	tools/verify.tcl and tools/kinerr.tcl follow the tool in the spindle
#	with it.
proc ::fivax::dryrun::tooling {tools override} {
    dict create tools $tools override $override pending "" tool "" length $override radius "" \
        corner "" called 0 notes {}
}

# ::fivax::dryrun::toolStep --
#	Returns the follower state after one NC line read by a verify Checker
#	(blk: its read dict): its tool calls (M6 calls the last T; a
#	Checker's Translate reads a tool call of another syntax as T n M6), then
#	its comments "FIVAX TOOL n LENGTH L ?RADIUS R ?CORNER r??" (the tool
#	the program's X Y Z were computed for; CORNER: a program compensated
#	for that cutter, -cutcom3d post). Keys:
#	  tool    the tool in the spindle: the last called or commented (""
#	          before any)
#	  length  the tool length to compute with: the override, else the
#	          tool table's length of the tool called or commented, else
#	          the comment's; "" while none is known (keep the last one)
#	  radius  the tool table's radius, else the comment's; "" likewise
#	  corner  the corner radius of the last comment, "" when it gives none
#	  called  1 when the line called a tool into the spindle
#	  notes   this line's {kind what}: "unreadable" (a FIVAX TOOL comment
#	          not understood), "toollength" (the comment's length differs
#	          from the tool table's)
proc ::fivax::dryrun::toolStep {state blk} {
    variable lengthTol
    dict set state notes {}
    dict set state called 0
    set tools [dict get $state tools]
    set override [dict get $state override]
    foreach {letter v} [dict get $blk words] {
        if {$letter eq "T" && [set t [::fivax::num::parse $v]] ne ""} {
            dict set state pending [expr {int($t)}]
        }
        if {$letter eq "M" && $v == 6} {
            dict set state called 1
            dict set state tool [dict get $state pending]
            set entry [TableEntry $tools [dict get $state pending]]
            if {[dict exists $entry radius]} {dict set state radius [dict get $entry radius]}
            if {[dict exists $entry length] && $override eq ""} {
                dict set state length [dict get $entry length]
            }
        }
    }
    set num {([-+]?[0-9]*\.?[0-9]+)}
    foreach c [dict get $blk comments] {
        if {![regexp {^\s*FIVAX TOOL\M} $c]} continue
        if {![regexp "^\\s*FIVAX TOOL (\\d+) LENGTH ${num}(?: RADIUS ${num}(?: CORNER ${num})?)?\\s*\$" \
                $c -> tool len rad corner]} {
            dict lappend state notes [list unreadable "tool comment not understood: $c"]
            continue
        }
        set tool [scan $tool %d]
        dict set state tool $tool
        set entry [TableEntry $tools $tool]
        set x [::fivax::num::parse $len]
        if {[dict exists $entry length] && abs([dict get $entry length] - $x) > $lengthTol} {
            dict lappend state notes [list toollength "tool $tool: the program was computed for length\
                $len, the tool table has [dict get $entry length]"]
        }
        if {$rad ne "" && ![dict exists $entry radius]} {dict set state radius [::fivax::num::parse $rad]}
        dict set state corner [expr {$corner eq "" ? "" : [::fivax::num::parse $corner]}]
        if {![dict exists $entry length] && $override eq ""} {dict set state length $x}
    }
    return $state
}

# ::fivax::dryrun::TableEntry -- Returns the tool table's entry of tool ("" or a number), {} when none.
proc ::fivax::dryrun::TableEntry {tools tool} {
    if {$tool ne "" && [dict exists $tools $tool]} {return [dict get $tools $tool]}
    return {}
}

# ::fivax::dryrun::Geometry --
#	Builds the stock and follows the moves through it (rapid, collision
#	and mode events).
proc ::fivax::dryrun::Geometry {} {
    variable R
    variable eps
    variable depthClear
    set box [dict get $R(opts) -stock]
    set tableGiven [expr {[dict get $R(machine) table_top] ne "" || $box ne ""}]
    set R(estimated) [expr {$box eq ""}]
    if {$box eq ""} {
        set tips [CutTips]
        set box [CutBox $tips]
    }
    if {$box eq ""} return
    lassign $box x0 y0 z0 x1 y1 z1
    # (no table_top and no -stock: where the part sits is unknown, and a
    # tilted head's nose rightly passes below the lowest cut)
    set R(table) [dict get $R(machine) table_top]
    if {$R(table) eq ""} {set R(table) [expr {$tableGiven ? min($z0, $z1) : -Inf}]}
    set radius 0.0
    foreach move $R(moves) {
        if {[lindex $move 0] ne "switch"} {set radius [expr {max($radius, [lindex $move 8 1])}]}
    }
    Grid [expr {min($x0, $x1)}] [expr {min($y0, $y1)}] [expr {max($x0, $x1)}] \
        [expr {max($y0, $y1)}] [expr {max($z0, $z1)}] $radius
    set R(cutterToTable) $tableGiven
    set R(silent) 0
    set R(final) 0
    # (the moves to follow: every one, and without -stock the cuts first)
    set R(toFollow) [llength $R(moves)]
    if {$R(estimated)} {
        # the part as the program leaves it: every cut first, then the
        # uncut cells reached from the map's edge are air, those enclosed
        # by cuts (a boss) the highest near cut's level
        foreach move $R(moves) {
            if {[lindex $move 0] in {cut hole}} {incr R(toFollow)}
        }
        LocalTops $tips
        set R(H0) $R(H)
        set R(silent) 1
        foreach move $R(moves) {
            if {[lindex $move 0] in {cut hole}} {
                Followed
                Move $move
            }
        }
        set R(silent) 0
        set R(final) 1
        Outside
    }
    Blocks
    foreach move $R(moves) {
        Followed
        set kind [lindex $move 0]
        if {$kind eq "switch"} {
            lassign $move - n pose what
            lassign [lindex $pose 0] x y z
            set h [Surface $x $y]
            if {$h ne "" && $z < $R(top) - $eps && $z < $h + $depthClear} {
                Event $n mode [::format "%s switched with the tip at cutting depth: Z%.3f, the stock's\
                    surface there Z%.3f, its top Z%.3f" $what $z $h $R(top)]
            }
            continue
        }
        Move $move
    }
}

# ::fivax::dryrun::Surface --
#	Returns the height of the stock's surface at x y (its map cell), ""
#	outside the map or where there is no stock.
proc ::fivax::dryrun::Surface {x y} {
    variable R
    variable air
    lassign [Cell $x $y] i j
    if {$i < 0 || $j < 0 || $i >= $R(nx) || $j >= $R(ny)} {return ""}
    set h [lindex $R(H) [expr {$j * $R(nx) + $i}]]
    expr {$h == $air ? "" : $h}
}

# ::fivax::dryrun::Outside --
#	Sets the cells of the height map that no cut lowered (still at their
#	height in H0) and that are reached from the map's edge through such
#	cells to air.
proc ::fivax::dryrun::Outside {} {
    variable R
    variable air
    set queue {}
    for {set i 0} {$i < $R(nx)} {incr i} {lappend queue $i 0 $i [expr {$R(ny) - 1}]}
    for {set j 0} {$j < $R(ny)} {incr j} {lappend queue 0 $j [expr {$R(nx) - 1}] $j}
    while {[llength $queue]} {
        set next {}
        foreach {i j} $queue {
            if {$i < 0 || $j < 0 || $i >= $R(nx) || $j >= $R(ny)} continue
            set k [expr {$j * $R(nx) + $i}]
            set h [lindex $R(H) $k]
            if {$h == $air || $h != [lindex $R(H0) $k]} continue
            lset R(H) $k $air
            lappend next [expr {$i + 1}] $j [expr {$i - 1}] $j $i [expr {$j + 1}] $i [expr {$j - 1}]
        }
        set queue $next
    }
}

# ::fivax::dryrun::CutTips --
#	Returns {x y z up ...}: the tips of the cutting moves (feed moves
#	that do not back out along the tool axis, arcs at their points, hole
#	bottoms), up 1 when the tool axis is within 60 deg
#	of +Z (a tip that tells the stock's top: a side cut with a level tool
#	often starts in the air above the part).
proc ::fivax::dryrun::CutTips {} {
    variable R
    set out {}
    foreach move $R(moves) {
        lassign $move kind n from to - - - - tool path
        if {$kind ni {cut hole}} continue
        lassign $from P0
        lassign $to P t
        set d [::fivax::vec::sub $P $P0]
        if {$kind eq "cut" && [::fivax::vec::dot $d $t] > 0.5 * [::fivax::vec::norm $d]} continue
        set up [expr {[lindex $t 2] >= 0.5}]
        # (a hole's path holds its R plane and return level: no cuts)
        if {$kind eq "hole"} {set path {}}
        foreach q [concat [lmap pose $path {lindex $pose 0}] [list $P]] {
            lappend out {*}$q $up
        }
    }
    return $out
}

# ::fivax::dryrun::CutBox --
#	Returns the box {x0 y0 z0 x1 y1 z1} of the tips {x y z up ...}, its
#	top the highest tip with up 1 (the highest of all when none has), or
#	"" when there are none. (Not grown by the tool radius: a facing pass
#	runs over the part's edge and a profile's tips are a radius outside
#	it already, so that a grown box swallows the approach points beside
#	the part.)
proc ::fivax::dryrun::CutBox {tips} {
    if {![llength $tips]} {return ""}
    lassign $tips x y z
    set box [list $x $y $z $x $y $z]
    set top ""
    foreach {x y z up} $tips {
        lassign $box a b c d e f
        set box [list [expr {min($a, $x)}] [expr {min($b, $y)}] [expr {min($c, $z)}] \
            [expr {max($d, $x)}] [expr {max($e, $y)}] [expr {max($f, $z)}]]
        if {$up && ($top eq "" || $z > $top)} {set top $z}
    }
    if {$top ne ""} {lset box 5 $top}
    return $box
}

# ::fivax::dryrun::LocalTops --
#	Lowers each cell of the height map to the highest of the tips {x y z
#	up ...} with up 1 in its block of nearCells cells and the 8
#	blocks around: the program tells the stock's top near where it cuts
#	(a second pocket deeper than the first has its own top); a cell with
#	no such cut near keeps the box's top.
proc ::fivax::dryrun::LocalTops {tips} {
    variable R
    variable nearCells
    set b [expr {$R(cell) * $nearCells}]
    foreach {x y z up} $tips {
        if {!$up} continue
        set key [expr {int(floor(($x - $R(gx0)) / $b))}],[expr {int(floor(($y - $R(gy0)) / $b))}]
        if {![info exists high($key)] || $high($key) < $z} {set high($key) $z}
    }
    for {set j 0} {$j < $R(ny)} {incr j} {
        set bj [expr {$j / $nearCells}]
        for {set i 0} {$i < $R(nx)} {incr i} {
            set bi [expr {$i / $nearCells}]
            set top ""
            foreach {di dj} {-1 -1 0 -1 1 -1 -1 0 0 0 1 0 -1 1 0 1 1 1} {
                set key [expr {$bi + $di}],[expr {$bj + $dj}]
                if {[info exists high($key)] && ($top eq "" || $high($key) > $top)} {set top $high($key)}
            }
            set k [expr {$j * $R(nx) + $i}]
            if {$top ne "" && $top < [lindex $R(H) $k]} {lset R(H) $k $top}
        }
    }
}

# ::fivax::dryrun::Grid --
#	Sets up the height map over x0..x1, y0..y1, every cell at top: cells
#	of a cells'th of the longer side, at least a quarter of the largest
#	tool radius (a sphere then covers some 80 cells).
proc ::fivax::dryrun::Grid {x0 y0 x1 y1 top radius} {
    variable R
    variable air
    variable cells
    variable minCell
    set c [expr {max($minCell, $radius / 4.0, max($x1 - $x0, $y1 - $y0) / double($cells))}]
    set R(cell) $c
    set R(nx) [expr {max(1, int(ceil(($x1 - $x0) / $c)))}]
    set R(ny) [expr {max(1, int(ceil(($y1 - $y0) / $c)))}]
    lassign [list $x0 $y0 $x1 $y1 $top] R(gx0) R(gy0) R(gx1) R(gy1) R(top)
    # (the cells whose centres lie beyond the box are air)
    set row [lmap i [lrepeat $R(nx) 0] {
        expr {$x0 + ([incr k] - 0.5) * $c > $x1 ? $air : double($top)}
    }]
    set R(H) {}
    for {set j 0} {$j < $R(ny)} {incr j} {
        lappend R(H) {*}[expr {$y0 + ($j + 0.5) * $c > $y1 ? [lrepeat $R(nx) $air] : $row}]
    }
}

# ::fivax::dryrun::Move --
#	Follows one move {kind n from to j0 j1 space model tool path}
#	through the stock: a rapid's bodies must stay out of it, a cut
#	lowers it under the cutter and its other bodies must stay out; a hole
#	is a rapid to above its bottom and a cut down to it.
proc ::fivax::dryrun::Move {move} {
    lassign $move kind n from to j0 j1 space model tool path
    if {$kind eq "hole"} {
        # the control's cycle: a rapid across at the level the tool comes
        # from to above the hole, down to the R plane, the feed to the
        # bottom (and back out along the axis: nothing new)
        lassign $to P t
        set rplane [lindex $path 0]
        set above [::fivax::vec::add $P [::fivax::vec::scale \
            [::fivax::vec::dot [::fivax::vec::sub [lindex $from 0] $P] $t] $t]]
        foreach {a b} [list $from [list $above $t] [list $above $t] $rplane] {
            if {[Follow rapid $n [Samples $a $b {} {} plane {} {} {*}[Step rapid $tool]] $tool]} return
        }
        Follow cut $n [Samples $rplane $to {} {} plane {} {} {*}[Step cut $tool]] $tool
        return
    }
    if {$kind eq "rapid" && [Backing $from $to]} {set kind back}
    Follow $kind $n [Samples $from $to $j0 $j1 $space $model $path {*}[Step $kind $tool]] $tool
}

# ::fivax::dryrun::Backing --
#	Returns 1 when the move from pose from to pose to backs the tool out
#	along its axis (the axis kept, the tip within a degree of it): the
#	cutter then only passes where the shank was.
proc ::fivax::dryrun::Backing {from to} {
    lassign $from P0 t0
    lassign $to P1 t1
    set d [::fivax::vec::sub $P1 $P0]
    set n [::fivax::vec::norm $d]
    expr {$n > 0 && [::fivax::vec::dot $t0 $t1] > 1.0 - 1e-9
        && [::fivax::vec::dot $d $t1] > 0.99985 * $n}
}

# ::fivax::dryrun::Step --
#	Returns {len step}: the tool's length and the sampling step of a move
#	of kind (rapid, back: a cell; cut: up to the tool radius).
proc ::fivax::dryrun::Step {kind tool} {
    variable R
    lassign $tool len r
    set c $R(cell)
    # (a cut's samples this far apart still lower every cell its sweep
    # reaches into: Lower's discs reach half a cell's diagonal further)
    list $len [expr {$kind eq "cut" ? max($c, min($r, 2.0 * sqrt(1.42 * $c * $r))) : $c}]
}

# ::fivax::dryrun::Samples --
#	Returns the poses {P t} along a move from pose from to pose to, the
#	way the control moves (see the file header), at most step apart at
#	the tip and at the tool's far end (len from the tip; and a rotaryStep
#	apart in joint space); path: an arc's poses (the samples then).
proc ::fivax::dryrun::Samples {from to j0 j1 space model path len step} {
    variable R
    variable maxSamples
    variable rotaryStep
    if {[llength $path]} {return $path}
    lassign $from P0 t0
    lassign $to P1 t1
    set far [::fivax::vec::dist [::fivax::vec::add $P0 [::fivax::vec::scale $len $t0]] \
        [::fivax::vec::add $P1 [::fivax::vec::scale $len $t1]]]
    set d [expr {max([::fivax::vec::dist $P0 $P1], $far) / $step}]
    set joint [expr {$space eq "joint" && $j0 ne "" && $j1 ne ""}]
    if {$joint} {
        # (a rotary that rolls over turns the shortest way)
        foreach i {3 4} axis [dict get $R(machine) chain] {
            if {![dict get $axis rollover]} continue
            set d [expr {[lindex $j1 $i] - [lindex $j0 $i]}]
            lset j1 $i [expr {[lindex $j0 $i] + $d - 2.0 * $::fivax::num::pi * round($d / (2.0 * $::fivax::num::pi))}]
        }
        set d [expr {max($d, abs([lindex $j1 3] - [lindex $j0 3]) / $rotaryStep,
            abs([lindex $j1 4] - [lindex $j0 4]) / $rotaryStep)}]
    }
    set count [expr {min($maxSamples, max(1, int(ceil($d))))}]
    set out {}
    for {set i 1} {$i < $count} {incr i} {
        set s [expr {double($i) / $count}]
        if {$joint} {
            lappend out [::fivax::kin::forward $model [lmap a $j0 b $j1 {expr {$a + $s * ($b - $a)}}]]
        } else {
            lappend out [list [::fivax::vec::lerp $P0 $P1 $s] [::fivax::vec::unit [::fivax::vec::lerp $t0 $t1 $s]]]
        }
    }
    lappend out $to
}

# ::fivax::dryrun::Follow --
#	Follows the tool {length radius} of a move of kind (rapid; back: a
#	rapid backing out along the tool axis; cut) at line n through the
#	poses; returns 1 when it raised an event (one per move). While
#	R(silent) a cut only lowers the stock; once R(final) (the map is the
#	finished part) it does not.
proc ::fivax::dryrun::Follow {kind n poses tool} {
    variable R
    variable eps
    lassign $tool len r
    variable chunk
    set last [lindex $poses end]
    set seen ""
    set i 0
    foreach pose $poses {
        if {$i % $chunk == 0} {
            set clear [expr {!$R(silent) && [Clear $kind [lrange $poses $i [expr {$i + $chunk - 1}]] $tool]}]
        }
        incr i
        if {$kind eq "cut" && !$R(final)} {
            # (the cutter's end: the flutes above it follow it down, or
            # cut only where it passed)
            lassign $pose P t
            Lower $P [Along $P $t 1.0] $r
        }
        if {$R(silent) || $clear} continue
        if {$kind eq "cut"} {
            # a cut's other bodies: every tool diameter and at its end
            if {$pose ne $last && $seen ne ""
                    && [::fivax::vec::dist [lindex $pose 0] $seen] < 2.0 * $r} continue
            set seen [lindex $pose 0]
        }
        foreach body [Bodies $pose $len $r] {
            lassign $body name a b rr
            if {$name ne "cutter" || $kind eq "rapid"} {
                set z [Below $a $b $rr]
                if {$z ne ""} {
                    lassign [lindex $pose 0] x y tz
                    Event $n [expr {$name eq "cutter" ? "rapid" : "collision"}] [::format \
                        "%s through the stock%s at X%.3f Y%.3f Z%.3f (its surface there: Z%.3f)" \
                        $name [expr {$kind eq "cut" ? " at feed" : ""}] {*}[lrange $z 0 2] [lindex $z 3]]
                    return 1
                }
            }
            if {$name ne "cutter" || $R(cutterToTable)} {
                set low [expr {min([lindex $a 2], [lindex $b 2]) - $rr}]
                if {$low < $R(table) - $eps} {
                    Event $n collision [::format "%s below the table's top Z%.3f (at Z%.3f)" \
                        $name $R(table) $low]
                    return 1
                }
            }
        }
    }
    return 0
}

# ::fivax::dryrun::Bodies --
#	Returns the bodies {name a b radius} (from a up to b along the tool
#	axis) of a tool of length len and radius r at pose {P t} (see Shapes).
proc ::fivax::dryrun::Bodies {pose len r} {
    lassign $pose P t
    lmap {name s0 s1 rr} [Shapes $len $r] {
        list $name [Along $P $t $s0] [Along $P $t $s1] $rr
    }
}

# ::fivax::dryrun::Shapes --
#	Returns {name s0 s1 radius ...}: the bodies of a tool of length len
#	(its own length: tip to holder) and radius r, each from s0 to s1 mm
#	along the tool axis from the tip: cutter (fluteRadii radii long),
#	and, when the length is known (longer than the cutter), the shank up
#	to the length, the holder above it and the spindle nose above that
#	(machine keys holder and spindle_nose).
proc ::fivax::dryrun::Shapes {len r} {
    variable R
    variable fluteRadii
    if {[info exists R(shapes,$len,$r)]} {return $R(shapes,$len,$r)}
    set flute [expr {max($fluteRadii * $r, $R(cell))}]
    lassign [dict get $R(machine) holder] hd hl
    lassign [dict get $R(machine) spindle_nose] nd nl
    set out [list cutter 0.0 $flute $r]
    if {$len ne "" && $len > $flute} {
        set nose [expr {$len + $hl}]
        lappend out shank $flute $len $r
        # (a holder is never narrower than its tool: diameter 0 is the tool's)
        if {$hl > 0} {lappend out holder $len $nose [expr {max($hd / 2.0, $r)}]}
        if {$nl > 0} {lappend out "spindle nose" $nose [expr {$nose + $nl}] [expr {$nd / 2.0}]}
    }
    set R(shapes,$len,$r) $out
}

# ::fivax::dryrun::Clear --
#	Returns 1 when at every one of the poses the tool {length radius} of
#	a move of kind stays above the stock and the table by more than eps
#	(see Follow: what it checks), taking its bodies as one cylinder as
#	wide as the widest (a quick test before Follow's body by body).
proc ::fivax::dryrun::Clear {kind poses tool} {
    variable R
    variable eps
    lassign $tool len r
    set shapes [Shapes $len $r]
    set top [lindex $shapes end-1]
    set wide 0.0
    foreach {- - - rr} $shapes {set wide [expr {max($wide, $rr)}]}
    # (the stock: the cutter only on a rapid; the table: the cutter only
    # when the cutter's own table check is on)
    set fromStock [expr {$kind eq "rapid" ? 0.0 : [lindex $shapes 2]}]
    set fromTable [expr {$R(cutterToTable) ? 0.0 : [lindex $shapes 2]}]
    set zStock Inf
    set zTable Inf
    set xs {}
    set ys {}
    foreach pose $poses {
        lassign $pose P t
        lassign [Along $P $t $top] bx by bz
        lassign [Along $P $t $fromTable] - - az
        set zTable [expr {min($zTable, $az, $bz)}]
        lassign [Along $P $t $fromStock] ax ay az
        set zStock [expr {min($zStock, $az, $bz)}]
        lappend xs $ax $bx
        lappend ys $ay $by
    }
    if {$zTable - $wide < $R(table) - $eps} {return 0}
    if {$fromStock >= $top} {return 1}
    set n [expr {int(ceil($wide / $R(cell)))}]
    lassign [Cell [tcl::mathfunc::min {*}$xs] [tcl::mathfunc::min {*}$ys]] i0 j0
    lassign [Cell [tcl::mathfunc::max {*}$xs] [tcl::mathfunc::max {*}$ys]] i1 j1
    expr {[Highest [expr {$i0 - $n}] [expr {$j0 - $n}] [expr {$i1 + $n}] [expr {$j1 + $n}]]
        <= $zStock - $wide + $eps}
}

# ::fivax::dryrun::Along -- Returns P + s t.
proc ::fivax::dryrun::Along {P t s} {
    lassign $P x y z
    lassign $t i j k
    list [expr {$x + $s * $i}] [expr {$y + $s * $j}] [expr {$z + $s * $k}]
}

# ::fivax::dryrun::Discs --
#	Returns the points x y z a cell apart along the segment a-b (a body's
#	axis from its lower end), those below the stock's top; of a vertical
#	axis only the lowest (the discs above it cover the same cells).
proc ::fivax::dryrun::Discs {a b} {
    variable R
    lassign $a ax ay az
    lassign $b bx by bz
    set top $R(top)
    if {$az >= $top && $bz >= $top} {return {}}
    set len [expr {sqrt(($bx - $ax) ** 2 + ($by - $ay) ** 2 + ($bz - $az) ** 2)}]
    if {$len == 0 || abs($bz - $az) > 0.9995 * $len} {
        return [expr {$az <= $bz ? [list $ax $ay $az] : [list $bx $by $bz]}]
    }
    # the part below the top: s in [s0, s1] of a + s (b - a)
    set s0 0.0
    set s1 1.0
    if {$az != $bz} {
        set sTop [expr {($top - $az) / ($bz - $az)}]
        if {$az >= $top} {set s0 $sTop} elseif {$bz >= $top} {set s1 $sTop}
    }
    set count [expr {max(1, int(ceil($len * ($s1 - $s0) / $R(cell))))}]
    set out {}
    for {set i 0} {$i <= $count} {incr i} {
        set s [expr {$s0 + ($s1 - $s0) * $i / double($count)}]
        lappend out [expr {$ax + $s * ($bx - $ax)}] [expr {$ay + $s * ($by - $ay)}] \
            [expr {$az + $s * ($bz - $az)}]
    }
    return $out
}

# ::fivax::dryrun::Slope --
#	Returns how far the rim of a disc across the axis a-b dips per unit
#	of horizontal distance from its centre (0 for a vertical axis).
proc ::fivax::dryrun::Slope {a b} {
    set d [::fivax::vec::sub $b $a]
    set n [::fivax::vec::norm $d]
    set k [expr {$n > 0 ? abs([lindex $d 2]) / $n : 1.0}]
    expr {$k > 0.1 ? sqrt(max(0.0, 1.0 - $k * $k)) / $k : 10.0}
}

# ::fivax::dryrun::Below --
#	Returns {x y z h}: the first point of the body of radius r along the
#	segment a-b (flat discs across its axis, their rims dipping by the
#	tilt, at most r) that is below the stock's surface h there by more
#	than eps and the cells' own uncertainty, or "".
proc ::fivax::dryrun::Below {a b r} {
    variable R
    variable eps
    set slope [Slope $a $b]
    # (the discs are centred on cells, here and in Lower: a tilted rim's
    # height at a cell is known to a cell's diagonal times its slope)
    set tol [expr {$eps + min($r, 1.42 * $R(cell) * $slope)}]
    set stencil [Stencil $r 0]
    set n [lindex $stencil 0]
    # (no disc dips lower than its centre less r, nor than its rim)
    set dip [expr {min($r, $r * $slope)}]
    set low [expr {min([lindex $a 2], [lindex $b 2]) - $dip + $tol}]
    # (no cell is above the stock's top)
    if {$low >= $R(top)} {return ""}
    lassign [Cell [expr {min([lindex $a 0], [lindex $b 0])}] [expr {min([lindex $a 1], [lindex $b 1])}]] i0 j0
    lassign [Cell [expr {max([lindex $a 0], [lindex $b 0])}] [expr {max([lindex $a 1], [lindex $b 1])}]] i1 j1
    if {[Highest [expr {$i0 - $n}] [expr {$j0 - $n}] [expr {$i1 + $n}] [expr {$j1 + $n}]]
            <= $low} {
        return ""
    }
    set stencil [lrange $stencil 1 end]
    foreach {x y z} [Discs $a $b] {
        lassign [Cell $x $y] ci cj
        if {[Highest [expr {$ci - $n}] [expr {$cj - $n}] [expr {$ci + $n}] [expr {$cj + $n}]]
                <= $z - $dip + $tol} continue
        foreach {di dj d -} $stencil {
            set i [expr {$ci + $di}]
            set j [expr {$cj + $dj}]
            if {$i < 0 || $j < 0 || $i >= $R(nx) || $j >= $R(ny)} continue
            set k [expr {$j * $R(nx) + $i}]
            set h [lindex $R(H) $k]
            set low [expr {$z - min($r, $d * $slope)}]
            if {$h > $low + $tol} {return [list $x $y $low $h]}
        }
    }
    return ""
}

# ::fivax::dryrun::Highest --
#	Returns a height no cell of the map in columns i0..i1, rows j0..j1
#	exceeds (air when none is in the map): the largest of the maxima of
#	the blocks of blockCells x blockCells cells they lie in, each
#	recomputed when a cut lowered a cell of it since (see Lowered).
proc ::fivax::dryrun::Highest {i0 j0 i1 j1} {
    variable R
    variable air
    variable blockCells
    set i0 [expr {max(0, $i0) / $blockCells}]
    set j0 [expr {max(0, $j0) / $blockCells}]
    set i1 [expr {min($R(nx) - 1, $i1)}]
    set j1 [expr {min($R(ny) - 1, $j1)}]
    if {$i1 < 0 || $j1 < 0} {return $air}
    set i1 [expr {$i1 / $blockCells}]
    set j1 [expr {$j1 / $blockCells}]
    set top $air
    for {set bj $j0} {$bj <= $j1} {incr bj} {
        for {set bi $i0} {$bi <= $i1} {incr bi} {
            set k [expr {$bj * $R(bx) + $bi}]
            if {[info exists R(dirty,$k)]} {
                unset R(dirty,$k)
                lset R(B) $k [BlockTop $bi $bj]
            }
            set top [expr {max($top, [lindex $R(B) $k])}]
        }
    }
    return $top
}

# ::fivax::dryrun::Blocks -- Sets the maxima of the map's blocks (see Highest) from its cells.
proc ::fivax::dryrun::Blocks {} {
    variable R
    variable blockCells
    array unset R dirty,*
    set R(bx) [expr {($R(nx) + $blockCells - 1) / $blockCells}]
    set R(by) [expr {($R(ny) + $blockCells - 1) / $blockCells}]
    set R(B) {}
    for {set bj 0} {$bj < $R(by)} {incr bj} {
        for {set bi 0} {$bi < $R(bx)} {incr bi} {lappend R(B) [BlockTop $bi $bj]}
    }
}

# ::fivax::dryrun::BlockTop -- Returns the highest cell of block bi bj.
proc ::fivax::dryrun::BlockTop {bi bj} {
    variable R
    variable air
    variable blockCells
    set top $air
    set i0 [expr {$bi * $blockCells}]
    set i1 [expr {min($R(nx), $i0 + $blockCells) - 1}]
    set j1 [expr {min($R(ny), ($bj + 1) * $blockCells)}]
    for {set j [expr {$bj * $blockCells}]} {$j < $j1} {incr j} {
        set k [expr {$j * $R(nx)}]
        foreach h [lrange $R(H) [expr {$k + $i0}] [expr {$k + $i1}]] {
            if {$h > $top} {set top $h}
        }
    }
    return $top
}

# ::fivax::dryrun::Lowered --
#	Marks the blocks of the cells within n of cell ci cj for Highest to
#	recompute (a cut lowered cells there).
proc ::fivax::dryrun::Lowered {ci cj n} {
    variable R
    variable blockCells
    if {![info exists R(B)]} return
    set i0 [expr {max(0, $ci - $n) / $blockCells}]
    set j0 [expr {max(0, $cj - $n) / $blockCells}]
    set i1 [expr {min($R(nx) - 1, $ci + $n) / $blockCells}]
    set j1 [expr {min($R(ny) - 1, $cj + $n) / $blockCells}]
    for {set bj $j0} {$bj <= $j1} {incr bj} {
        for {set bi $i0} {$bi <= $i1} {incr bi} {set R(dirty,[expr {$bj * $R(bx) + $bi}]) 1}
    }
}

# ::fivax::dryrun::Lower --
#	Lowers the stock to the cutter's end, the disc of radius r at a
#	across the axis a-b.
proc ::fivax::dryrun::Lower {a b r} {
    variable R
    upvar 0 R(H) H
    lassign $a x y z
    if {$z - $r >= $R(top)} return
    set slope [Slope $a $b]
    lassign [Cell $x $y] ci cj
    set stencil [Stencil $r 1]
    set n [lindex $stencil 0]
    Lowered $ci $cj $n
    set k0 [expr {$cj * $R(nx) + $ci}]
    if {$ci >= $n && $cj >= $n && $ci + $n < $R(nx) && $cj + $n < $R(ny)} {
        # (inside the map: no cell to skip; a vertical tool's disc is flat)
        if {$slope == 0} {
            foreach {- - - off} [lrange $stencil 1 end] {
                set k [expr {$k0 + $off}]
                if {[lindex $H $k] > $z} {lset H $k $z}
            }
            return
        }
        foreach {- - d off} [lrange $stencil 1 end] {
            set k [expr {$k0 + $off}]
            set low [expr {$z - min($r, $d * $slope)}]
            if {[lindex $H $k] > $low} {lset H $k $low}
        }
        return
    }
    foreach {di dj d -} [lrange $stencil 1 end] {
        set i [expr {$ci + $di}]
        set j [expr {$cj + $dj}]
        if {$i < 0 || $j < 0 || $i >= $R(nx) || $j >= $R(ny)} continue
        set k [expr {$j * $R(nx) + $i}]
        set low [expr {$z - min($r, $d * $slope)}]
        if {[lindex $H $k] > $low} {lset H $k $low}
    }
}

# ::fivax::dryrun::Cell -- Returns {i j}: the cell under x y (may lie outside the map).
proc ::fivax::dryrun::Cell {x y} {
    variable R
    list [expr {int(floor(($x - $R(gx0)) / $R(cell)))}] [expr {int(floor(($y - $R(gy0)) / $R(cell)))}]
}

# ::fivax::dryrun::Stencil --
#	Returns {n di dj d off ...}: the cells about a disc's centre cell
#	that a disc of radius r covers (their centres within r of the centre
#	cell's centre; grown 1: within r plus half a cell's diagonal, the
#	cells it reaches into), their distance from it and their offset in
#	the map's list, all within n cells of it.
proc ::fivax::dryrun::Stencil {r grown} {
    variable R
    if {[info exists R(stencil,$r,$grown)]} {return $R(stencil,$r,$grown)}
    set c $R(cell)
    set reach [expr {$grown ? $r + 0.71 * $c : $r}]
    set n [expr {int(ceil($reach / $c))}]
    set out [list $n]
    for {set dj -$n} {$dj <= $n} {incr dj} {
        for {set di -$n} {$di <= $n} {incr di} {
            set d2 [expr {($di * $c) ** 2 + ($dj * $c) ** 2}]
            if {$d2 > $reach * $reach && ($di || $dj)} continue
            lappend out $di $dj [expr {sqrt($d2)}] [expr {$dj * $R(nx) + $di}]
        }
    }
    set R(stencil,$r,$grown) $out
}
