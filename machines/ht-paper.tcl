# ht-paper -- head-table: B on the head about +Y through the pivot point,
# C on the table about +Z through the origin (the head-table paper's
# machine, kinematics.md section 4: pivot 125 + TLDATA tool length 275).
# Example machine, no real machine's data (the head-table paper's geometry);
# its travel is an example value: describe your machine before posting for
# it.
name        ht-paper
description {Head B, table C (paper geometry, pivot 125)}
units       mm
family      chain
pivot       125
tool_length 0
# Linear travel of X Y Z (machine coordinates, mm): example values, wide
# enough for the samples and the real CL files; set your machine's. A value
# outside is refused with FILE:LINE, never written.
travel      {X {-3000 3000} Y {-3000 3000} Z {-2000 2000}}
axes {
    B {side head direction {0 1 0} point {0 0 0} sense 1 min -90 max 90 prefer negative}
    C {side table direction {0 0 1} point {0 0 0} sense -1 min 0 max 360 continuous 0 prefer none}
}
