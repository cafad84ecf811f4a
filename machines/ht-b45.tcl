# ht-b45 -- head-table: B on the head at 45 deg in the YZ plane through the
# pivot point, continuous C on the table about +Z through the origin.
# Example machine, no real machine's data (a DMU 125 P-like head, round
# numbers); its travel is an example value: describe your machine before
# posting for it.
name        ht-b45
description {Head B at 45 deg, continuous table C}
units       mm
family      chain
pivot       300
tool_length 0
# Linear travel of X Y Z (machine coordinates, mm): example values, wide
# enough for the samples and the real CL files; set your machine's. A value
# outside is refused with FILE:LINE, never written.
travel      {X {-3000 3000} Y {-3000 3000} Z {-2000 2000}}
axes {
    B {side head direction {0 0.70710678118654757 0.70710678118654757} point {0 0 0}
       sense 1 min 0 max 180 prefer none}
    C {side table direction {0 0 1} point {0 0 0} sense 1 continuous 1}
}
