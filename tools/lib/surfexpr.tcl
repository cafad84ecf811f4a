# surfexpr.tcl --
#	User surfaces S(u,v) for tools/surfpath.tcl: a file of three
#	expressions in u and v, read as data. A small tokenizer and
#	recursive-descent parser turn each expression into a tree, which is
#	evaluated one operation at a time with braced expr: the text is never
#	handed to expr, eval, subst or source. Allowed: decimal numbers, u, v,
#	pi, + - * / ** (right-associative, binding as in Tcl's expr: unary
#	minus first, so -2**2 is 4), parentheses and the math functions of
#	the Functions table. Anything else is refused with FILE:LINE.
#
#	File format: lines "x = EXPR", "y = EXPR", "z = EXPR" (each once, in
#	any order); blank lines and lines starting with # are ignored.
#	Errors: {FIVAX SURFACE <detail>} with "FILE:LINE: what is wrong":
#	  OPEN    the file cannot be read
#	  SYNTAX  a line that is not NAME = EXPR, a token or construct that is
#	          not allowed, a name other than u, v, pi and the functions
#	  MISSING x, y or z not given; DUPLICATE given twice
#	  EVAL    a value that is not a finite number at some (u, v)

namespace eval ::fivax::surfexpr {
    namespace export load parse value
    namespace ensemble create -prefixes 0
    # Function name -> number of arguments.
    variable Functions {
        sin 1 cos 1 tan 1 asin 1 acos 1 atan 1 atan2 2 sinh 1 cosh 1 tanh 1
        exp 1 log 1 log10 1 sqrt 1 pow 2 abs 1 hypot 2
    }
}

# ::fivax::surfexpr::load --
#	Returns the surface dict {file F x TREE y TREE z TREE lines {x L y L z L}}
#	of the file at path.
proc ::fivax::surfexpr::load {path} {
    try {
        set chan [open $path r]
        chan configure $chan -encoding utf-8 -translation auto
        set text [read $chan]
    } trap {POSIX} {msg opts} {
        ::fivax::Fail SURFACE OPEN "$path: cannot read: [lindex [dict get $opts -errorcode] end]"
    } finally {
        if {[info exists chan]} {close $chan}
    }
    set surf [dict create file $path lines {}]
    set n 0
    set last 1
    foreach line [split $text \n] {
        incr n
        set s [string trim $line]
        if {$s eq "" || [string index $s 0] eq "#"} continue
        set last $n
        if {![regexp {^([A-Za-z_][A-Za-z0-9_]*)\s*=(.*)$} $s -> name rhs]} {
            ::fivax::Fail SURFACE SYNTAX "$path:$n: expected \"x = EXPR\", \"y = EXPR\" or \"z = EXPR\""
        }
        if {$name ni {x y z}} {
            ::fivax::Fail SURFACE SYNTAX "$path:$n: unknown coordinate '$name': must be x, y or z"
        }
        if {[dict exists $surf $name]} {
            ::fivax::Fail SURFACE DUPLICATE "$path:$n: $name given twice (first at line\
                [dict get $surf lines $name])"
        }
        dict set surf $name [parse $rhs "$path:$n"]
        dict set surf lines $name $n
    }
    foreach name {x y z} {
        if {![dict exists $surf $name]} {
            ::fivax::Fail SURFACE MISSING "$path:$last: no line \"$name = EXPR\" in the file"
        }
    }
    return $surf
}

# ::fivax::surfexpr::parse --
#	Returns the tree of the expression text; where (FILE:LINE) prefixes
#	error messages. Trees: {num V} {var u|v} {neg T} {op O A B}
#	{call F ARGS}.
proc ::fivax::surfexpr::parse {text where} {
    set toks [Tokens $text $where]
    set pos 0
    set tree [Sum $toks pos $where]
    if {$pos < [llength $toks]} {
        ::fivax::Fail SURFACE SYNTAX "$where: unexpected '[lindex $toks $pos 1]' after a complete expression"
    }
    return $tree
}

# ::fivax::surfexpr::Tokens --
#	Returns the tokens of text as {kind text} pairs: num, name, op
#	(+ - * / **), ( ) and comma. Anything else fails naming it.
proc ::fivax::surfexpr::Tokens {text where} {
    set out {}
    set i 0
    set n [string length $text]
    while {$i < $n} {
        set c [string index $text $i]
        if {[string is space $c]} {incr i; continue}
        if {[regexp -start $i {\A(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?} $text m]} {
            set v [::fivax::num::parse $m]
            if {$v eq ""} {::fivax::Fail SURFACE SYNTAX "$where: bad number '$m'"}
            if {[regexp -start [expr {$i + [string length $m]}] {\A[A-Za-z_.]} $text]} {
                ::fivax::Fail SURFACE SYNTAX "$where: bad number '$m' followed by a letter"
            }
            lappend out [list num $v]
            incr i [string length $m]
        } elseif {[regexp -start $i {\A[A-Za-z_][A-Za-z0-9_]*} $text m]} {
            lappend out [list name $m]
            incr i [string length $m]
        } elseif {[string range $text $i $i+1] eq "**"} {
            lappend out {op **}
            incr i 2
        } elseif {$c in {+ - * /}} {
            lappend out [list op $c]
            incr i
        } elseif {$c in {( ) ,}} {
            lappend out [list $c $c]
            incr i
        } else {
            ::fivax::Fail SURFACE SYNTAX "$where: character '$c' is not allowed: only numbers, u, v,\
                pi, + - * / **, parentheses and math functions"
        }
    }
    if {![llength $out]} {::fivax::Fail SURFACE SYNTAX "$where: empty expression"}
    return $out
}

# ::fivax::surfexpr::Peek -- Returns the text of token pos of toks ("" at the end).
proc ::fivax::surfexpr::Peek {toks pos} {
    lindex $toks $pos 1
}

# ::fivax::surfexpr::Sum -- Parses term (+|- term)* at posVar.
proc ::fivax::surfexpr::Sum {toks posVar where} {
    upvar 1 $posVar pos
    set a [Product $toks pos $where]
    while {[Peek $toks $pos] in {+ -} && [lindex $toks $pos 0] eq "op"} {
        set o [Peek $toks $pos]
        incr pos
        set a [list op $o $a [Product $toks pos $where]]
    }
    return $a
}

# ::fivax::surfexpr::Product -- Parses power (*|/ power)* at posVar.
proc ::fivax::surfexpr::Product {toks posVar where} {
    upvar 1 $posVar pos
    set a [Power $toks pos $where]
    while {[Peek $toks $pos] in {* /}} {
        set o [Peek $toks $pos]
        incr pos
        set a [list op $o $a [Power $toks pos $where]]
    }
    return $a
}

# ::fivax::surfexpr::Power -- Parses unary (** power)? at posVar (right-associative).
proc ::fivax::surfexpr::Power {toks posVar where} {
    upvar 1 $posVar pos
    set a [Unary $toks pos $where]
    if {[Peek $toks $pos] eq "**"} {
        incr pos
        set a [list op ** $a [Power $toks pos $where]]
    }
    return $a
}

# ::fivax::surfexpr::Unary -- Parses (+|-)* primary at posVar.
proc ::fivax::surfexpr::Unary {toks posVar where} {
    upvar 1 $posVar pos
    set o [Peek $toks $pos]
    if {$o in {+ -} && [lindex $toks $pos 0] eq "op"} {
        incr pos
        set a [Unary $toks pos $where]
        return [expr {$o eq "-" ? [list neg $a] : $a}]
    }
    Primary $toks pos $where
}

# ::fivax::surfexpr::Primary -- Parses a number, u, v, pi, f(args) or (expr) at posVar.
proc ::fivax::surfexpr::Primary {toks posVar where} {
    variable Functions
    upvar 1 $posVar pos
    if {$pos >= [llength $toks]} {
        ::fivax::Fail SURFACE SYNTAX "$where: the expression ends where a value is expected"
    }
    lassign [lindex $toks $pos] kind text
    incr pos
    switch -exact -- $kind {
        num {return [list num $text]}
        ( {
            set a [Sum $toks pos $where]
            Expect $toks pos ) $where
            return $a
        }
        name {
            if {$text in {u v}} {return [list var $text]}
            if {$text eq "pi"} {return [list num 3.141592653589793]}
            if {![dict exists $Functions $text]} {
                ::fivax::Fail SURFACE SYNTAX "$where: unknown name '$text': only u, v, pi and\
                    the functions [join [dict keys $Functions] {, }] are allowed"
            }
            Expect $toks pos ( $where
            set args [list [Sum $toks pos $where]]
            while {[Peek $toks $pos] eq ","} {
                incr pos
                lappend args [Sum $toks pos $where]
            }
            Expect $toks pos ) $where
            set want [dict get $Functions $text]
            if {[llength $args] != $want} {
                ::fivax::Fail SURFACE SYNTAX "$where: $text takes $want argument[expr {$want > 1 ? "s" : ""}],\
                    not [llength $args]"
            }
            return [list call $text $args]
        }
    }
    ::fivax::Fail SURFACE SYNTAX "$where: unexpected '$text' where a value is expected"
}

# ::fivax::surfexpr::Expect -- Consumes token text at posVar or fails.
proc ::fivax::surfexpr::Expect {toks posVar text where} {
    upvar 1 $posVar pos
    if {[Peek $toks $pos] ne $text} {
        set got [expr {$pos < [llength $toks] ? "'[Peek $toks $pos]'" : "the end"}]
        ::fivax::Fail SURFACE SYNTAX "$where: expected '$text', found $got"
    }
    incr pos
}

# ::fivax::surfexpr::value --
#	Returns the value of tree at (u, v), each operation a braced expr.
#	Errors: {FIVAX SURFACE EVAL} (domain errors, division by zero,
#	non-finite results) naming u and v; where prefixes the message.
proc ::fivax::surfexpr::value {tree u v {where ""}} {
    try {
        set x [Eval $tree $u $v]
    } trap {ARITH} {msg} {
        ::fivax::Fail SURFACE EVAL "${where}cannot evaluate at u = $u, v = $v: $msg"
    }
    if {!(abs($x) < Inf)} {
        ::fivax::Fail SURFACE EVAL "${where}value at u = $u, v = $v is not a finite number: $x"
    }
    return $x
}

# ::fivax::surfexpr::Eval -- Returns the value of tree at (u, v).
proc ::fivax::surfexpr::Eval {tree u v} {
    switch -exact -- [lindex $tree 0] {
        num {return [lindex $tree 1]}
        var {return [expr {[lindex $tree 1] eq "u" ? $u : $v}]}
        neg {return [expr {-[Eval [lindex $tree 1] $u $v]}]}
        op {
            lassign $tree - o ta tb
            set a [Eval $ta $u $v]
            set b [Eval $tb $u $v]
            switch -exact -- $o {
                + {return [expr {$a + $b}]}
                - {return [expr {$a - $b}]}
                * {return [expr {$a * $b}]}
                / {return [expr {$a / double($b)}]}
                ** {return [expr {double($a) ** $b}]}
            }
        }
        call {
            lassign $tree - f targs
            set xs [lmap t $targs {Eval $t $u $v}]
            lassign $xs a b
            switch -exact -- $f {
                sin {return [expr {sin($a)}]}
                cos {return [expr {cos($a)}]}
                tan {return [expr {tan($a)}]}
                asin {return [expr {asin($a)}]}
                acos {return [expr {acos($a)}]}
                atan {return [expr {atan($a)}]}
                atan2 {return [expr {atan2($a, $b)}]}
                sinh {return [expr {sinh($a)}]}
                cosh {return [expr {cosh($a)}]}
                tanh {return [expr {tanh($a)}]}
                exp {return [expr {exp($a)}]}
                log {return [expr {log($a)}]}
                log10 {return [expr {log10($a)}]}
                sqrt {return [expr {sqrt($a)}]}
                pow {return [expr {pow($a, $b)}]}
                abs {return [expr {abs($a)}]}
                hypot {return [expr {hypot($a, $b)}]}
            }
        }
    }
    error "surfexpr: bad tree node [lindex $tree 0]"
}
