# dmu70v -- EXAMPLE MACHINE, no real machine's data: a DMU 70 V style
# nutating table on a Sinumerik 840D. The outer table axis B is inclined
# 45 deg in the YZ plane and passes through (0, 0, -100), the round table
# C (carried by B) turns about +Z through the origin. B 0..180 (B = 180:
# the table face vertical), C endless. The DMU 70 V was sold with a
# Heidenhain or a Siemens control; this file takes the Sinumerik (TRAORI,
# CYCLE800), dmu125p the Heidenhain. Reachable tool axes: K >= 0.
# Not the maker's figures: no published data of the DMU 70 (V or eVo) was
# found for this file, so its travel is the example value of the other
# example machines (it takes programs no DMU 70 could run) and the axis
# point and limits are assumptions: set your machine's values.
name        dmu70v
description {Example machine, DMU 70 V style: 45 deg nutating B table, C table, Sinumerik 840D}
units       mm
family      chain
controller  sinumerik
# Linear travel of X Y Z (machine coordinates, mm): example values, wide
# enough for the samples and the real CL files; set your machine's. A value
# outside is refused with FILE:LINE, never written.
travel      {X {-3000 3000} Y {-3000 3000} Z {-2000 2000}}
axes {
    B {side table direction {0 0.70710678118654757 0.70710678118654757}
       point {0 0 -100} sense 1 min 0 max 180}
    C {side table direction {0 0 1} point {0 0 0} sense 1 continuous 1}
}
