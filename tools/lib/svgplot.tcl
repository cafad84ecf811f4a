# svgplot.tcl --
#	A small SVG writer for the tools' plots: line charts (series against a
#	common x, titled axes with units, ticks, legend, an optional
#	horizontal limit line, marked points such as the worst NC lines), one
#	panel or several stacked on a common x (one unit per y axis), and the
#	XY / XZ / YZ projections of a tool path with tool-axis whiskers, cuts
#	solid and rapids dashed. Self-contained SVG 1.1: no scripts, no
#	external fonts or style sheets, so any browser shows it offline.
#	Every series is one <path class="series" data-name=.. data-count=..>
#	(data-count: its points, one per value; a break in the line is a new
#	subpath, "M") so that a test can count what was drawn; tick labels
#	are <text class="xtick"> and "ytick", marks <g class="mark"
#	data-x=..>, panels <g class="panel">. Pure Tcl; numbers formatted
#	with fivax::num.

namespace eval ::fivax::svgplot {
    namespace export chart panels projections worst write
    namespace ensemble create -prefixes 0
    # Series colours, in order.
    variable Colours {#1f77b4 #d62728 #2ca02c #9467bd #ff7f0e #8c564b}
    # The options of a chart's panel (chart takes them as its own).
    variable PanelOptions {
        {-ylabel text "" T "y axis title"} {-series any {} LIST "series {{name xs ys} ...}"}
        {-limit any {} "VALUE LABEL" "horizontal limit line"}
        {-marks any {} LIST "marked points {{x y label} ...}"}
        {-wrap {real min 0} 0 DEG "angle series: break the line where neighbours differ by more than half of it (0: off)"}
        {-zero bool 1 "" "the y axis includes 0"}
    }
}

# ::fivax::svgplot::chart --
#	Returns the SVG text of a line chart. Options:
#	  -title T -xlabel T -ylabel T   texts (labels name their units)
#	  -series {{name xs ys} ...}      each a list of x and of y values
#	  -limit {value label}            a dashed horizontal line (or {})
#	  -marks {{x y label} ...}        points marked and labelled (see worst)
#	  -wrap DEG                       the values are angles that wrap
#	                                  (360): the line breaks where two
#	                                  neighbours differ by more than DEG/2
#	                                  instead of drawing the wrap across
#	  -width 900 -height 420          pixels
#	  -zero 1                         the y axis includes 0
proc ::fivax::svgplot::chart {args} {
    variable PanelOptions
    set o [::fivax::opts::parse [concat {
        {-title text "" T "title"} {-xlabel text "" T "x axis title"}
        {-width {int min 200} 900 PX "width"} {-height {int min 150} 420 PX "height"}
    } $PanelOptions] $args "svgplot chart"]
    set panel [dict filter $o key {*}[lmap e $PanelOptions {lindex $e 0}]]
    Panels [dict get $o -title] [dict get $o -xlabel] [dict get $o -width] [dict get $o -height] \
        [list $panel]
}

# ::fivax::svgplot::panels --
#	Returns the SVG text of charts stacked on one common x axis, one y
#	axis (and unit) each. Options: -title T, -xlabel T, -width 900,
#	-height 640, -panels {panel ...}, each panel a list of chart's
#	-ylabel -series -limit -marks -wrap -zero options.
proc ::fivax::svgplot::panels {args} {
    variable PanelOptions
    set o [::fivax::opts::parse {
        {-title text "" T "title"} {-xlabel text "" T "x axis title"}
        {-panels any {} LIST "panels"}
        {-width {int min 200} 900 PX "width"} {-height {int min 150} 640 PX "height"}
    } $args "svgplot panels"]
    set panels [lmap p [dict get $o -panels] {::fivax::opts::parse $PanelOptions $p "svgplot panels"}]
    Panels [dict get $o -title] [dict get $o -xlabel] [dict get $o -width] [dict get $o -height] $panels
}

# ::fivax::svgplot::worst --
#	Returns the marks {x y label} of the n largest of the values ys at xs,
#	largest first, each labelled prefix and its x; each more than a
#	twentieth of the x range from those before it (the worst places, not
#	the neighbours of the worst one).
proc ::fivax::svgplot::worst {xs ys n prefix} {
    lassign [Range $xs] lo hi
    set apart [expr {($hi - $lo) / 20.0}]
    set out {}
    foreach i [lsort -real -decreasing -indices $ys] {
        if {[llength $out] >= $n} break
        set x [lindex $xs $i]
        set near 0
        foreach m $out {
            if {abs($x - [lindex $m 0]) <= $apart} {set near 1}
        }
        if {!$near} {lappend out [list $x [lindex $ys $i] $prefix$x]}
    }
    return $out
}

# ::fivax::svgplot::Panels --
#	Returns the SVG document of the panels (option dicts, see chart)
#	stacked on one x axis (its range: all their series), with title and
#	x axis title xlabel under the lowest, in width x height pixels.
proc ::fivax::svgplot::Panels {title xlabel width height panels} {
    set xs {}
    foreach p $panels {
        foreach s [dict get $p -series] {lappend xs {*}[lindex $s 1]}
    }
    set xr [Range $xs]
    set n [llength $panels]
    # (above each box its legend's row)
    set top 56
    set gap 52
    set h [expr {($height - $top - 60 - $gap * ($n - 1)) / double($n)}]
    set body ""
    set colour 0
    set k 0
    foreach p $panels {
        set y0 [expr {$top + $k * ($h + $gap)}]
        set box [list 70 [expr {round($y0)}] [expr {$width - 20}] [expr {round($y0 + $h)}]]
        incr k
        lassign [Panel $p $box $xr [expr {$k == $n ? $xlabel : ""}] $colour] svg colour
        append body $svg
    }
    Document $width $height $title $body
}

# ::fivax::svgplot::Panel --
#	Returns {svg colour}: panel p (an option dict, see chart) drawn in
#	box {x0 y0 x1 y1} over the x range xr (x axis title xlabel, "" for
#	none), its series coloured from the colour index colour on, and the
#	next colour index; the legend is a row above the box.
proc ::fivax::svgplot::Panel {p box xr xlabel colour} {
    variable Colours
    set ys {}
    foreach s [dict get $p -series] {lappend ys {*}[lindex $s 2]}
    if {[llength [dict get $p -limit]]} {lappend ys [lindex [dict get $p -limit] 0]}
    if {[dict get $p -zero]} {lappend ys 0.0}
    set yr [Range $ys]
    if {[llength [dict get $p -marks]]} {
        # (room above the marks for their labels)
        lset yr 1 [expr {[lindex $yr 1] + 0.12 * ([lindex $yr 1] - [lindex $yr 0])}]
    }
    set fx [Scale $xr [lindex $box 0] [lindex $box 2]]
    set fy [Scale $yr [lindex $box 3] [lindex $box 1]]
    set body "<g class=\"panel\">\n[Frame $box $fx $fy $xlabel [dict get $p -ylabel]]"
    set legend {}
    foreach s [dict get $p -series] {
        lassign $s name sx sy
        set c [lindex $Colours [expr {$colour % [llength $Colours]}]]
        incr colour
        set px [Map $fx $sx]
        set py [Map $fy $sy]
        set breaks [expr {[dict get $p -wrap] > 0 ? [Wraps $sy [dict get $p -wrap]] : {}}]
        append body [Path series $name $c $px $py $breaks]
        lappend legend $name $c solid
    }
    if {[llength [dict get $p -limit]]} {
        lassign [dict get $p -limit] value label
        set y [Fmt [Apply $fy $value]]
        append body "<line class=\"limit\" x1=\"[lindex $box 0]\" y1=\"$y\" x2=\"[lindex $box 2]\"\
            y2=\"$y\" stroke=\"#000\" stroke-dasharray=\"6,4\"/>\n"
        lappend legend $label #000 dashed
    }
    append body [Legend $legend [lindex $box 2] [expr {[lindex $box 1] - 6}]]
    foreach m [dict get $p -marks] {
        lassign $m x y label
        append body [Mark $label $x [Apply $fx $x] [Apply $fy $y] [lindex $box 2]]
    }
    list "$body</g>\n" $colour
}

# ::fivax::svgplot::Wraps --
#	Returns the indices i of the angles values (degrees) where values i-1
#	and i differ by more than half a turn of turn degrees: a wrap (359
#	to 1), where the line breaks.
proc ::fivax::svgplot::Wraps {values turn} {
    set out {}
    set i 0
    set last ""
    foreach v $values {
        if {$last ne "" && abs($v - $last) > $turn / 2.0} {lappend out $i}
        set last $v
        incr i
    }
    return $out
}

# ::fivax::svgplot::Mark --
#	Returns a marked point at pixel px, py: a circle and its label, on
#	its right, or its left near the plot's right edge right (data x: the
#	point's x value).
proc ::fivax::svgplot::Mark {label x px py right} {
    set left [expr {$px > $right - 80}]
    set tx [Fmt [expr {$left ? $px - 6 : $px + 6}]]
    set px [Fmt $px]
    set py [Fmt $py]
    return "<g class=\"mark\" data-x=\"[Esc $x]\"><circle cx=\"$px\" cy=\"$py\" r=\"4\" fill=\"none\"\
        stroke=\"#000\" stroke-width=\"1.5\"/><text x=\"$tx\" y=\"[Fmt [expr {$py - 6}]]\"\
        text-anchor=\"[expr {$left ? "end" : "start"}]\" font-size=\"11\">[Esc $label]</text></g>\n"
}

# ::fivax::svgplot::projections --
#	Returns the SVG text of the XY, XZ and YZ projections of a tool path.
#	Options: -title T, -points {P ...} (tips), -axes {t ...} (unit tool
#	axes, one per point, or {}), -rapids {0|1 ...} (1: the point is
#	reached by a rapid, drawn dashed apart from the cuts; {}: none),
#	-whisker MM (drawn length of an axis), -every N (a whisker every N
#	points), -width, -height.
proc ::fivax::svgplot::projections {args} {
    variable Colours
    set o [::fivax::opts::parse {
        {-title text "" T "title"} {-points any {} LIST "tips"} {-axes any {} LIST "axes"}
        {-rapids any {} LIST "1 where a point is reached by a rapid"}
        {-whisker {real min 0} 10 MM "whisker length"} {-every {int min 1} 10 N "whisker step"}
        {-width {int min 300} 1200 PX "width"} {-height {int min 150} 440 PX "height"}
    } $args "svgplot projections"]
    dict with o {}
    set panelW [expr {(${-width} - 40) / 3.0}]
    set rapids [lsearch -all -exact ${-rapids} 1]
    set body ""
    set k 0
    foreach {name a b} {XY 0 1 XZ 0 2 YZ 1 2} {
        set x0 [expr {20 + $k * $panelW}]
        set box [list [expr {$x0 + 55}] 80 [expr {$x0 + $panelW - 10}] [expr {${-height} - 60}]]
        set us [lmap p ${-points} {lindex $p $a}]
        set vs [lmap p ${-points} {lindex $p $b}]
        set ws {}
        set wt {}
        set i 0
        foreach p ${-points} t ${-axes} {
            if {$t ne "" && $i % ${-every} == 0} {
                set e [::fivax::vec::add $p [::fivax::vec::scale ${-whisker} $t]]
                lappend ws [list [lindex $p $a] [lindex $p $b] [lindex $e $a] [lindex $e $b]]
                lappend wt [lindex $e $a] [lindex $e $b]
            }
            incr i
        }
        set all [concat $us [lmap {u v} $wt {set u}]]
        set allv [concat $vs [lmap {u v} $wt {set v}]]
        lassign [Equal [Range $all] [Range $allv] $box] ru rv
        set fx [Scale $ru [lindex $box 0] [lindex $box 2]]
        set fy [Scale $rv [lindex $box 3] [lindex $box 1]]
        set la [string index $name 0]
        set lb [string index $name 1]
        append body [Frame $box $fx $fy "$la (mm)" "$lb (mm)"]
        append body "<text x=\"[Fmt [expr {([lindex $box 0] + [lindex $box 2]) / 2.0}]]\" y=\"74\"\
            text-anchor=\"middle\" font-size=\"13\">$name</text>\n"
        append body "<g class=\"whiskers\" data-name=\"axis $name\" data-count=\"[llength $ws]\"\
            stroke=\"[lindex $Colours 1]\" stroke-width=\"0.6\">\n"
        foreach w $ws {
            lassign $w p1 q1 p2 q2
            append body "<line x1=\"[Fmt [Apply $fx $p1]]\" y1=\"[Fmt [Apply $fy $q1]]\"\
                x2=\"[Fmt [Apply $fx $p2]]\" y2=\"[Fmt [Apply $fy $q2]]\"/>\n"
        }
        append body "</g>\n"
        set px [Map $fx $us]
        set py [Map $fy $vs]
        append body [Path series "tip $name" [lindex $Colours 0] $px $py $rapids]
        if {[llength $rapids]} {append body [Rapids "rapid $name" [lindex $Colours 4] $px $py $rapids]}
        incr k
    }
    set legend [list "tool tip path[expr {[llength $rapids] ? " (cutting)" : ""}]" [lindex $Colours 0] solid \
        "tool axis (every ${-every}th point, [Fmt ${-whisker}] mm)" [lindex $Colours 1] solid]
    if {[llength $rapids]} {lappend legend "rapid (G0)" [lindex $Colours 4] dashed}
    append body [Legend $legend [expr {${-width} - 20}] 44]
    Document ${-width} ${-height} ${-title} $body
}

# ::fivax::svgplot::write --
#	Writes text to path through a temporary file beside it (renamed at
#	the end, so a failed run leaves no file). Returns path.
proc ::fivax::svgplot::write {path text} {
    set tmp [file join [file dirname [file normalize $path]] .[file tail $path].[pid].tmp]
    set chan [open $tmp w]
    try {
        chan configure $chan -translation lf -encoding utf-8
        puts -nonewline $chan $text
    } on error {msg opts} {
        close $chan
        file delete -force $tmp
        return -options $opts $msg
    }
    close $chan
    file rename -force $tmp $path
    return $path
}

# ::fivax::svgplot::Document -- Returns the SVG document of body with a title.
proc ::fivax::svgplot::Document {width height title body} {
    set t [Esc $title]
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"\
        version=\"1.1\" width=\"$width\" height=\"$height\" viewBox=\"0 0 $width $height\"\
        font-family=\"sans-serif\">\n<title>$t</title>\n<rect width=\"100%\" height=\"100%\"\
        fill=\"#fff\"/>\n<text x=\"[expr {$width / 2}]\" y=\"20\" text-anchor=\"middle\"\
        font-size=\"15\" font-weight=\"bold\">$t</text>\n$body</svg>\n"
}

# ::fivax::svgplot::Range -- Returns {min max} of the numbers in values (never empty).
proc ::fivax::svgplot::Range {values} {
    if {![llength $values]} {return {0.0 1.0}}
    set lo [expr {double([::tcl::mathfunc::min {*}$values])}]
    set hi [expr {double([::tcl::mathfunc::max {*}$values])}]
    if {$hi - $lo < 1e-12 * max(1.0, abs($hi))} {
        set pad [expr {max(1e-6, abs($hi) * 0.05)}]
        return [list [expr {$lo - $pad}] [expr {$hi + $pad}]]
    }
    list $lo $hi
}

# ::fivax::svgplot::Equal --
#	Returns the ranges ru and rv widened so that one unit is as long on
#	both axes of box (true shape in a projection).
proc ::fivax::svgplot::Equal {ru rv box} {
    lassign $box x0 y0 x1 y1
    lassign $ru a b
    lassign $rv c d
    set k [expr {max(($b - $a) / ($x1 - $x0), ($d - $c) / ($y1 - $y0))}]
    set mu [expr {($a + $b) / 2.0}]
    set mv [expr {($c + $d) / 2.0}]
    list [list [expr {$mu - $k * ($x1 - $x0) / 2.0}] [expr {$mu + $k * ($x1 - $x0) / 2.0}]] \
        [list [expr {$mv - $k * ($y1 - $y0) / 2.0}] [expr {$mv + $k * ($y1 - $y0) / 2.0}]]
}

# ::fivax::svgplot::Scale -- Returns the map {lo hi p0 p1} of range onto pixels p0..p1.
proc ::fivax::svgplot::Scale {range p0 p1} {
    list {*}$range $p0 $p1
}

# ::fivax::svgplot::Apply -- Returns the pixel of value v under map f.
proc ::fivax::svgplot::Apply {f v} {
    lassign $f lo hi p0 p1
    expr {$p0 + ($v - $lo) * double($p1 - $p0) / ($hi - $lo)}
}

# ::fivax::svgplot::Map -- Returns the pixels of the values under map f.
proc ::fivax::svgplot::Map {f values} {
    lassign $f lo hi p0 p1
    set k [expr {($p1 - $p0) / double($hi - $lo)}]
    lmap v $values {expr {$p0 + ($v - $lo) * $k}}
}

# ::fivax::svgplot::Fmt -- Returns x with two decimals.
proc ::fivax::svgplot::Fmt {x} {
    ::fivax::num::fixed $x 2
}

# ::fivax::svgplot::Esc -- Returns text escaped for XML.
proc ::fivax::svgplot::Esc {text} {
    string map {& &amp; < &lt; > &gt; \" &quot;} $text
}

# ::fivax::svgplot::Path --
#	Returns one series of class cls as a path through the pixel lists px,
#	py, not drawn into the points at the indices breaks (a new subpath
#	starts there).
proc ::fivax::svgplot::Path {cls name colour px py breaks} {
    set pen [dict create 0 M]
    foreach i $breaks {dict set pen $i M}
    set d {}
    set i 0
    foreach x $px y $py {
        lappend d [expr {[dict exists $pen $i] ? "M" : "L"}][Fmt $x],[Fmt $y]
        incr i
    }
    return "<path class=\"$cls\" data-name=\"[Esc $name]\" data-count=\"[llength $px]\"\
        fill=\"none\" stroke=\"$colour\" stroke-width=\"1.2\" d=\"[join $d " "]\"/>\n"
}

# ::fivax::svgplot::Rapids --
#	Returns the rapids of a path through pixel lists px, py (the moves
#	into the points at the indices rapids) as one dashed path of class
#	rapids (data-count: the moves).
proc ::fivax::svgplot::Rapids {name colour px py rapids} {
    set d {}
    foreach i $rapids {
        if {$i == 0} continue
        set j [expr {$i - 1}]
        lappend d M[Fmt [lindex $px $j]],[Fmt [lindex $py $j]] L[Fmt [lindex $px $i]],[Fmt [lindex $py $i]]
    }
    return "<path class=\"rapids\" data-name=\"[Esc $name]\" data-count=\"[expr {[llength $d] / 2}]\"\
        fill=\"none\" stroke=\"$colour\" stroke-width=\"1\" stroke-dasharray=\"5,3\" d=\"[join $d " "]\"/>\n"
}

# ::fivax::svgplot::Ticks -- Returns about n round tick values covering {lo hi}.
proc ::fivax::svgplot::Ticks {lo hi {n 6}} {
    set span [expr {double($hi) - $lo}]
    set raw [expr {$span / $n}]
    set mag [expr {10.0 ** floor(log10($raw))}]
    foreach m {1 2 5 10} {
        set step [expr {$m * $mag}]
        if {$step >= $raw} break
    }
    set out {}
    for {set v [expr {ceil($lo / $step) * $step}]} {$v <= $hi + 1e-9 * $span} \
        {set v [expr {$v + $step}]} {
        lappend out [expr {abs($v) < 1e-12 * $step ? 0.0 : $v}]
    }
    list $out $step
}

# ::fivax::svgplot::Label -- Returns tick value v as short text for tick step.
proc ::fivax::svgplot::Label {v step} {
    set d [expr {$step >= 1 ? 0 : int(ceil(-log10($step) - 1e-9))}]
    if {abs($v) >= 1e5 || ($v != 0 && abs($v) < 1e-4)} {return [format %.2g $v]}
    ::fivax::num::fixed $v $d
}

# ::fivax::svgplot::Frame --
#	Returns the plot frame of box {x0 y0 x1 y1}: border, ticks and grid
#	of maps fx, fy, and the axis titles (no x title when xlabel is "").
proc ::fivax::svgplot::Frame {box fx fy xlabel ylabel} {
    lassign $box x0 y0 x1 y1
    set out "<rect x=\"$x0\" y=\"$y0\" width=\"[Fmt [expr {$x1 - $x0}]]\"\
        height=\"[Fmt [expr {$y1 - $y0}]]\" fill=\"none\" stroke=\"#444\"/>\n<g font-size=\"11\">\n"
    lassign [Ticks {*}[lrange $fx 0 1]] ticks step
    foreach v $ticks {
        set x [Fmt [Apply $fx $v]]
        append out "<line x1=\"$x\" y1=\"$y0\" x2=\"$x\" y2=\"$y1\" stroke=\"#ddd\"/>"
        append out "<text class=\"xtick\" x=\"$x\" y=\"[expr {$y1 + 15}]\" text-anchor=\"middle\">[Label $v $step]</text>\n"
    }
    lassign [Ticks {*}[lrange $fy 0 1] 5] ticks step
    foreach v $ticks {
        set y [Fmt [Apply $fy $v]]
        append out "<line x1=\"$x0\" y1=\"$y\" x2=\"$x1\" y2=\"$y\" stroke=\"#ddd\"/>"
        append out "<text class=\"ytick\" x=\"[expr {$x0 - 5}]\" y=\"$y\" text-anchor=\"end\"\
            dominant-baseline=\"middle\">[Label $v $step]</text>\n"
    }
    set xm [Fmt [expr {($x0 + $x1) / 2.0}]]
    set ym [Fmt [expr {($y0 + $y1) / 2.0}]]
    append out "</g>\n"
    if {$xlabel ne ""} {
        append out "<text class=\"xlabel\" x=\"$xm\" y=\"[expr {$y1 + 35}]\" text-anchor=\"middle\"\
            font-size=\"12\">[Esc $xlabel]</text>\n"
    }
    append out "<text class=\"ylabel\" x=\"[expr {$x0 - 50}]\" y=\"$ym\" text-anchor=\"middle\"\
        font-size=\"12\" transform=\"rotate(-90 [expr {$x0 - 50}] $ym)\">[Esc $ylabel]</text>\n"
}

# ::fivax::svgplot::Legend --
#	Returns a legend of the flat list of {name colour style} items as one
#	row ending at x, its text on the baseline y (above a plot, never over
#	its data).
proc ::fivax::svgplot::Legend {items x y} {
    set w 0
    foreach {name - -} $items {incr w [ItemWidth $name]}
    set x [expr {$x - $w}]
    set out "<g class=\"legend\" font-size=\"11\">\n"
    foreach {name colour style} $items {
        set dash [expr {$style eq "dashed" ? " stroke-dasharray=\"6,4\"" : ""}]
        append out "<line x1=\"$x\" y1=\"[expr {$y - 4}]\" x2=\"[expr {$x + 24}]\"\
            y2=\"[expr {$y - 4}]\" stroke=\"$colour\" stroke-width=\"2\"$dash/>"
        append out "<text x=\"[expr {$x + 30}]\" y=\"$y\">[Esc $name]</text>\n"
        incr x [ItemWidth $name]
    }
    append out "</g>\n"
}

# ::fivax::svgplot::ItemWidth -- Returns the pixel width of a legend item named name, with the space after it.
proc ::fivax::svgplot::ItemWidth {name} {
    expr {30 + 6 * [string length $name] + 16}
}
