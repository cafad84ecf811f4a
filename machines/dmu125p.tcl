# dmu125p -- DMU 125 P style head-table machine on a Heidenhain control: the
# milling head swivels about B, inclined 45 deg in the YZ plane through the
# pivot point (the 45-degree head: B = 0 spindle vertical, B = 180 spindle
# horizontal), the rotary table C about +Z through the origin. Limits as
# the survey seed gives them: B -15..180, C 0..360 (not endless). Pivot
# length 265 mm (spindle nose to the pivot point; an assumption: set the
# machine's value). The control has TCP (FUNCTION TCPM), so programs are
# written in TCP mode by default: X Y Z are the tool tip, and neither tool
# length nor pivot enters the program.
name        dmu125p
description {DMU 125 P style: 45 deg B head, C table, Heidenhain TNC, TCP}
units       mm
family      chain
controller  heidenhain
tcp         1
pivot       265
tool_length 0
# Linear travel of X Y Z (machine coordinates, mm): example values, wide
# enough for the samples and the real CL files; set your machine's. A value
# outside is refused with FILE:LINE, never written.
travel      {X {-3000 3000} Y {-3000 3000} Z {-2000 2000}}
axes {
    B {side head direction {0 0.70710678118654757 0.70710678118654757} point {0 0 0}
       sense 1 min -15 max 180 prefer none}
    C {side table direction {0 0 1} point {0 0 0} sense 1 min 0 max 360}
}
