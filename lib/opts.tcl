# opts.tcl --
#	The one option parser. Every command with options (each module's
#	create, the post's settings, tools/replay.tcl) declares them in a table
#	and hands its arguments to parse (name value pairs) or argv (a command
#	line), so each option has one spelling, is checked at the door with a
#	message naming it, and -help text comes from the same table.
#
#	A table is a list of entries {name type default arg doc}:
#	    name     the option, with its dash: -tol
#	    type     how the value is checked and converted:
#	               bool                   0 or 1 (any Tcl boolean); on a
#	                                      command line a switch without value
#	               {real ?min A? ?gt A? ?max B?}   a finite decimal number
#	               {int ?min A? ?max B?}  a decimal integer
#	               {enum a b ...}         one of the words
#	               vec3                   three numbers "x y z"
#	               {reals N ?gt A?}       N numbers
#	               word                   one word of [A-Za-z0-9_.-]
#	               text                   any text on one line
#	               any                    any text
#	               {maybe TYPE...}        TYPE, or "" (meaning: not set)
#	               {many TYPE...}         repeatable: each occurrence adds
#	                                      a TYPE value to a list (default
#	                                      and value without any: {})
#	    default  the value when the option is not given (checked too)
#	    arg      the value's name in help text (MM, DEG, FILE), "" for bool
#	    doc      one line for the help text
#	Numbers are read with ::fivax::num::parse (decimal; nan, Inf refused).
#	Errors: {FIVAX OPTION UNKNOWN|VALUE|MISSING} with a message naming
#	the option, e.g. bad -tol "abc": must be a number >= 0.

namespace eval ::fivax::opts {
    namespace export parse argv given help check names drop
    namespace ensemble create -prefixes 0
}

# ::fivax::opts::parse --
#	Returns the dict name -> value of every option of table: the defaults,
#	overridden by the name value pairs in argList, each checked and
#	converted. who (e.g. "motion create") prefixes error messages.
proc ::fivax::opts::parse {table argList {who ""}} {
    set out [Defaults $table]
    if {[llength $argList] % 2} {
        Fail MISSING $who "option [lindex $argList end] needs a value"
    }
    foreach {name value} $argList {
        set entry [Entry $table $name $who]
        if {[lindex $entry 1 0] eq "many"} {
            dict lappend out $name [Check $entry $value $who]
        } else {
            dict set out $name [Check $entry $value $who]
        }
    }
    return $out
}

# ::fivax::opts::argv --
#	Returns {dict rest}: the options of a command line (bool options are
#	switches without value, the others take the next word), checked, with
#	defaults for those not given, and the words after the options (after
#	"--" or the first word that does not start with "-"). Where table has
#	-help, -h and --help are -help.
proc ::fivax::opts::argv {table words {who ""}} {
    lassign [given $table $words $who] out rest
    list [dict merge [Defaults $table] $out] $rest
}

# ::fivax::opts::given --
#	Returns {dict rest} as argv does, the dict holding only the options
#	the words give (for settings added on top of others).
proc ::fivax::opts::given {table words {who ""}} {
    set out [dict create]
    set help [expr {[lsearch -exact -index 0 $table -help] >= 0 ? {-h -help --help -help} : {}}]
    set i 0
    set n [llength $words]
    while {$i < $n} {
        set w [lindex $words $i]
        if {$w eq "--"} {incr i; break}
        if {[string index $w 0] ne "-" || $w eq "-"} break
        if {[dict exists $help $w]} {set w [dict get $help $w]}
        set entry [Entry $table $w $who]
        if {[lindex $entry 1] eq "bool"} {
            dict set out $w 1
            incr i
            continue
        }
        if {$i + 1 >= $n} {Fail MISSING $who "option $w needs a value"}
        if {[lindex $entry 1 0] eq "many"} {
            dict lappend out $w [Check $entry [lindex $words $i+1] $who]
        } else {
            dict set out $w [Check $entry [lindex $words $i+1] $who]
        }
        incr i 2
    }
    list $out [lrange $words $i end]
}

# ::fivax::opts::check --
#	Returns value checked and converted for option name of table.
proc ::fivax::opts::check {table name value {who ""}} {
    Check [Entry $table $name $who] $value $who
}

# ::fivax::opts::help --
#	Returns the help text of table: one line per option, "-name ARG  doc
#	(default ...)"; -help with its other spellings (argv).
proc ::fivax::opts::help {table} {
    set lines {}
    foreach entry $table {
        lassign $entry name type default arg doc
        set left [expr {$name eq "-help" ? "-help, -h, --help" : [string trim "$name $arg"]}]
        if {$type ne "bool" && $default ne ""} {append doc " (default $default)"}
        if {[lindex $type 0] eq "many"} {append doc " (repeatable)"}
        lappend lines [format "  %-22s %s" $left $doc]
    }
    join $lines \n
}

# ::fivax::opts::names -- Returns the option names of table.
proc ::fivax::opts::names {table} {
    lmap entry $table {lindex $entry 0}
}

# ::fivax::opts::drop -- Returns the entries of table not named in names.
proc ::fivax::opts::drop {table names} {
    lmap entry $table {
        if {[lindex $entry 0] in $names} continue
        set entry
    }
}

# ::fivax::opts::Defaults -- Returns the dict of table's default values (checked).
proc ::fivax::opts::Defaults {table} {
    set out [dict create]
    foreach entry $table {
        if {[lindex $entry 1 0] eq "many"} {
            dict set out [lindex $entry 0] {}
            continue
        }
        dict set out [lindex $entry 0] [Check $entry [lindex $entry 2] "default"]
    }
    return $out
}

# ::fivax::opts::Entry -- Returns the entry of option name, or fails UNKNOWN.
proc ::fivax::opts::Entry {table name who} {
    foreach entry $table {
        if {[lindex $entry 0] eq $name} {return $entry}
    }
    Fail UNKNOWN $who "unknown option \"$name\": must be one of [join [names $table] {, }]"
}

# ::fivax::opts::Fail -- Raises {FIVAX OPTION detail} with msg, prefixed with "who: ".
proc ::fivax::opts::Fail {detail who msg} {
    if {$who ne ""} {set msg "$who: $msg"}
    return -code error -level 2 -errorcode [list FIVAX OPTION $detail] $msg
}

# ::fivax::opts::Check -- Returns value checked against entry's type, or fails VALUE.
proc ::fivax::opts::Check {entry value who} {
    lassign $entry name type
    set v [Convert $type $value]
    if {[lindex $v 0]} {return [lindex $v 1]}
    Fail VALUE $who "bad $name \"$value\": must be [Describe $type]"
}

# ::fivax::opts::Convert --
#	Returns {1 converted} when value fits type, else {0 {}}.
proc ::fivax::opts::Convert {type value} {
    set kind [lindex $type 0]
    set spec [lrange $type 1 end]
    switch -- $kind {
        maybe {
            if {$value eq ""} {return {1 {}}}
            return [Convert $spec $value]
        }
        many {return [Convert $spec $value]}
        bool {
            if {![string is boolean -strict $value]} {return {0 {}}}
            return [list 1 [expr {$value ? 1 : 0}]]
        }
        real {
            set x [::fivax::num::parse $value]
            if {$x eq "" || ![InRange $x $spec]} {return {0 {}}}
            return [list 1 $x]
        }
        int {
            set x [::fivax::num::int $value]
            if {$x eq "" || ![InRange $x $spec]} {return {0 {}}}
            return [list 1 $x]
        }
        enum {
            if {$value ni $spec} {return {0 {}}}
            return [list 1 $value]
        }
        vec3 - reals {
            set n [expr {$kind eq "vec3" ? 3 : [lindex $spec 0]}]
            set limits [expr {$kind eq "vec3" ? {} : [lrange $spec 1 end]}]
            if {![string is list $value] || [llength $value] != $n} {return {0 {}}}
            set out {}
            foreach c $value {
                set x [::fivax::num::parse $c]
                if {$x eq "" || ![InRange $x $limits]} {return {0 {}}}
                lappend out $x
            }
            return [list 1 $out]
        }
        word {
            if {![regexp {^[A-Za-z0-9_.-]+$} $value]} {return {0 {}}}
            return [list 1 $value]
        }
        text {
            if {[regexp {[\r\n]} $value]} {return {0 {}}}
            return [list 1 $value]
        }
        any {return [list 1 $value]}
    }
    error "opts: unknown option type \"$type\""
}

# ::fivax::opts::InRange -- Returns 1 when x meets the min/gt/max limits of spec.
proc ::fivax::opts::InRange {x spec} {
    foreach {key limit} $spec {
        switch -- $key {
            min {if {$x < $limit} {return 0}}
            gt  {if {$x <= $limit} {return 0}}
            max {if {$x > $limit} {return 0}}
        }
    }
    return 1
}

# ::fivax::opts::Describe -- Returns what a value of type must be, for messages.
proc ::fivax::opts::Describe {type} {
    set kind [lindex $type 0]
    set spec [lrange $type 1 end]
    switch -- $kind {
        maybe {return "[Describe $spec], or empty"}
        many {return [Describe $spec]}
        bool {return "a boolean (0 or 1)"}
        real {return "a number[Limits $spec]"}
        int {return "an integer[Limits $spec]"}
        enum {
            if {[llength $spec] == 1} {return [lindex $spec 0]}
            return "one of [join $spec {, }]"
        }
        vec3 {return "three numbers \"x y z\""}
        reals {return "[lindex $spec 0] numbers[Limits [lrange $spec 1 end]]"}
        word {return "one word (letters, digits, _ . -)"}
        text {return "text on one line"}
        any {return "text"}
    }
    return $kind
}

# ::fivax::opts::Limits -- Returns the limits of spec as text (" >= 0", " from 2 to 9").
proc ::fivax::opts::Limits {spec} {
    if {[dict exists $spec min] && [dict exists $spec max]} {
        return " from [dict get $spec min] to [dict get $spec max]"
    }
    set parts {}
    foreach {key op} {min ">=" gt ">" max "<="} {
        if {[dict exists $spec $key]} {lappend parts "$op [dict get $spec $key]"}
    }
    if {![llength $parts]} {return ""}
    return " [join $parts { and }]"
}
