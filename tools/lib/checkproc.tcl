# checkproc.tcl --
#	The block check in a process of its own, for the replay driver: the
#	post's checker (lib/verify.tcl, ::fivax::verify::Checker) reads every
#	written block back and measures it by forward kinematics; here it runs
#	in a second tclsh, fed through a pipe, while the post goes on, so a
#	long program uses two processors. The checks, their order and their
#	results are the same as in the post's own process: only where they run
#	differs.
#
#	Two halves of one protocol:
#	- sourced into the post interpreter, install replaces
#	  ::fivax::verify::create by a Proxy with the checker's interface
#	  (setTool, block, summary) that writes each call to the pipe;
#	- run as a script (tclsh checkproc.tcl LIBDIR), serve answers it.
#	Messages are Tcl lists, one per line (a line break inside an element
#	continues the message until it is a complete list): new MACHINE ARGS,
#	tool LEN, b LINE CLLINE OP KIND SRC P T (the block, the CL record and
#	operation it is written in, and its move's kind, FILE:LINE and CL
#	target), summary. The checker process writes one line: ok SUMMARY after
#	summary, or at its first error error CODE MESSAGE CLLINE OP (the CL
#	record and operation the block was written in, so that the post
#	reports the error as it would have in its own process), then reads on
#	without checking. Nothing is ever evaluated: the fields are taken
#	apart with list commands.

namespace eval ::fivax::checkproc {
    # Blocks between two looks at the checker process's answer (an error
    # is reported at most this many blocks after its block was written).
    variable pollEvery 512
    # The Proxy made by create, if any.
    variable proxy ""
    # This file (the checker process's script).
    variable script [file normalize [info script]]
}

# ::fivax::checkproc::install --
#	Makes ::fivax::verify::create (in this interpreter) start a checker
#	process running tclsh on this file, with the fivax library in libdir.
proc ::fivax::checkproc::install {tclsh libdir} {
    variable script
    variable command [list $tclsh $script $libdir]
    proc ::fivax::verify::create {machine args} {
        set ::fivax::checkproc::proxy \
            [::fivax::checkproc::Proxy new $::fivax::checkproc::command $machine {*}$args]
    }
}

# ::fivax::checkproc::failure --
#	Ends the checker process, if any, after it has checked every block
#	sent; returns its error as {code message clline op}, with the CL
#	record and operation of its block set back (see Proxy Raise), or {}
#	when it found none.
proc ::fivax::checkproc::failure {} {
    variable proxy
    if {$proxy eq "" || [info object isa object $proxy] == 0} {return {}}
    $proxy finish
}

oo::class create ::fivax::checkproc::Proxy {
    # S: out (the pipe to the checker process), in (its answers), count
    # (blocks until the next look at them), failure (its error, once read).
    variable S

    constructor {command machine args} {
        lassign [chan pipe] S(in) write
        try {
            set S(out) [open |[list {*}$command >@ $write 2>@ stderr] w]
        } finally {
            close $write
        }
        chan configure $S(out) -translation lf -encoding utf-8 -buffering full -buffersize 65536
        chan configure $S(in) -translation lf -encoding utf-8 -blocking 0
        set S(count) $::fivax::checkproc::pollEvery
        set S(failure) {}
        puts $S(out) [list new $machine {*}$args]
    }

    destructor {
        catch {my finish}
    }

    # setTool -- The checker's setTool.
    method setTool {len} {
        puts $S(out) [list tool $len]
    }

    # block -- The checker's block: sends the NC line and the move's CL target.
    method block {line move} {
        if {[incr S(count) -1] <= 0} {
            set S(count) $::fivax::checkproc::pollEvery
            my Look
        }
        global mom_cl_line mom_path_name
        puts $S(out) [list b $line [expr {[info exists mom_cl_line] ? $mom_cl_line : ""}] \
            [expr {[info exists mom_path_name] ? $mom_path_name : ""}] [dict get $move kind] \
            [dict get $move src] [dict get $move P] [dict get $move t]]
    }

    # summary -- The checker's summary, once it has checked every block.
    method summary {} {
        puts $S(out) summary
        flush $S(out)
        chan configure $S(in) -blocking 1
        set reply [my Answer]
        chan configure $S(in) -blocking 0
        if {$reply eq ""} {
            ::fivax::Fail VERIFY PROCESS "the block check process ended unexpectedly"
        }
        if {[lindex $reply 0] eq "ok"} {return [lindex $reply 1]}
        my Raise $reply
    }

    # finish --
    #	Closes the pipe (the checker process checks what is left and ends);
    #	returns its error as failure describes it.
    method finish {} {
        if {[info exists S(out)]} {
            set out $S(out)
            unset S(out)
            catch {close $out}
            chan configure $S(in) -blocking 1
            set reply [my Answer]
            close $S(in)
            if {[lindex $reply 0] eq "error"} {
                set S(failure) [lrange $reply 1 end]
                my Place {*}[lrange $S(failure) 2 3]
            }
        }
        return $S(failure)
    }

    # Look -- Raises the checker process's error if it has sent one.
    method Look {} {
        set reply [my Answer]
        if {$reply ne ""} {my Raise $reply}
    }

    # Answer --
    #	Returns the checker process's next message, "" when none has come
    #	(a non-blocking pipe) or at its end. Once a message has begun, the
    #	rest of it is waited for.
    method Answer {} {
        if {[gets $S(in) text] < 0} {return ""}
        set blocking [chan configure $S(in) -blocking]
        chan configure $S(in) -blocking 1
        while {![info complete $text] && [gets $S(in) more] >= 0} {
            append text \n $more
        }
        chan configure $S(in) -blocking $blocking
        return $text
    }

    # Raise --
    #	Raises the checker process's error reply as the post's checker
    #	would have raised it: with the CL record and operation of its block.
    method Raise {reply} {
        lassign $reply - code msg clline op
        my Place $clline $op
        return -code error -errorcode $code $msg
    }

    # Place -- Sets mom_cl_line and mom_path_name back to clline and op ("": unset).
    method Place {clline op} {
        foreach name {::mom_cl_line ::mom_path_name} value [list $clline $op] {
            if {$value eq ""} {unset -nocomplain $name} else {set $name $value}
        }
    }
}

# ::fivax::checkproc::serve --
#	The checker process: answers the messages read from channel in on
#	channel out, until the end of in (a message cut off there is dropped)
#	or until the post has gone.
proc ::fivax::checkproc::serve {in out} {
    chan configure $in -translation lf -encoding utf-8 -buffersize 65536
    chan configure $out -translation lf -encoding utf-8
    set checker ""
    set failed 0
    while {[gets $in text] >= 0} {
        while {![info complete $text] && [gets $in more] >= 0} {
            append text \n $more
        }
        # a message the end of the pipe cut off (the post stopped while
        # writing it) is no block of the program
        if {[chan eof $in]} break
        if {$failed} continue
        set clline ""
        set op ""
        try {
            switch -- [lindex $text 0] {
                b {
                    lassign $text - line clline op kind src P t
                    $checker block $line [dict create kind $kind P $P t $t src $src]
                }
                tool {$checker setTool [lindex $text 1]}
                new {set checker [::fivax::verify::create {*}[lrange $text 1 end]]}
                summary {
                    if {![Reply $out [list ok [$checker summary]]]} return
                }
            }
        } on error {msg opts} {
            set failed 1
            if {![Reply $out [list error [dict get $opts -errorcode] $msg $clline $op]]} return
        }
    }
}

# ::fivax::checkproc::Reply --
#	Writes message to the post on channel out; returns 0 when the post has
#	gone (a closed pipe: nobody is left to tell), else 1.
proc ::fivax::checkproc::Reply {out message} {
    expr {![catch {puts $out $message; flush $out}]}
}

if {[info exists ::argv0] && [file normalize $::argv0] eq [file normalize [info script]]} {
    set auto_path [linsert $auto_path 0 [lindex $argv 0]]
    package require fivax 0.1
    ::fivax::checkproc::serve stdin stdout
}
