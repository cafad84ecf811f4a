# dmu125p -- DMU 125 P (DMG) head-table machine on a Heidenhain control:
# the milling head swivels about B, inclined 45 deg in the YZ plane through
# the pivot point (the 45-degree head: B = 0 spindle vertical, B = 180
# spindle horizontal), the rotary table C about +Z through the origin. The
# control has TCP (FUNCTION TCPM), so programs are written in TCP mode by
# default: X Y Z are the tool tip, and neither tool length nor pivot enters
# the program.
# Source of the figures: the project's seed paper on the DMU 125 P: linear
# travel X 1250, Y 1250, Z 1000 mm; B -15..180, C 0..360 deg (not endless).
# Assumptions (set your machine's values): each stroke centred on the
# workpiece origin at the C table's centre (the travel is checked in the
# coordinates of the work offset); the pivot length 265 mm (spindle nose
# to the pivot point).
name        dmu125p
description {DMU 125 P: 45 deg B head, C table, Heidenhain TNC, TCP}
units       mm
family      chain
controller  heidenhain
tcp         1
pivot       265
tool_length 0
# Linear travel of X Y Z (mm): the strokes 1250, 1250, 1000 centred on the
# workpiece origin. A value outside is refused with FILE:LINE, never written.
travel      {X {-625 625} Y {-625 625} Z {-500 500}}
axes {
    B {side head direction {0 0.70710678118654757 0.70710678118654757} point {0 0 0}
       sense 1 min -15 max 180 prefer none}
    C {side table direction {0 0 1} point {0 0 0} sense 1 min 0 max 360}
}
