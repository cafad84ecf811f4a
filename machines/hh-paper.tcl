# hh-paper -- head-head fork head (alpha 0), the head-head paper's worked
# example: L = 433.75 = pivot with a zero tool length, y_H = -5.5 mm
# (kinematics.md sections 3 and 9). Lengths in mm, angles in degrees.
# Example machine, no real machine's data (the head-head paper's geometry);
# its travel is an example value: describe your machine before posting for
# it.
name        hh-paper
description {Head-head fork head, paper geometry (alpha 0, y_H -5.5)}
units       mm
family      headhead
alpha       0
y_H         -5.5
pivot       433.75
tool_length 0
# Linear travel of X Y Z (machine coordinates, mm): example values, wide
# enough for the samples and the real CL files; set your machine's. A value
# outside is refused with FILE:LINE, never written.
travel      {X {-3000 3000} Y {-3000 3000} Z {-2000 2000}}
axes {
    # outer axis first: C carries B
    C {side head sense -1 min 0 max 360 continuous 0 prefer none}
    B {side head sense 1 min -100 max 100 continuous 0 prefer positive}
}
