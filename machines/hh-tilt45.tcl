# hh-tilt45 -- head-head, B tilted 45 deg (nutating head); paper geometry.
# Reachable tool axes: K >= -cos(2 alpha) = 0.
# Example machine, no real machine's data (the head-head paper's geometry
# with alpha 45); its travel is an example value: describe your machine
# before posting for it.
name        hh-tilt45
description {Head-head, B tilted 45 deg}
units       mm
family      headhead
alpha       45
y_H         12.929
pivot       390
tool_length 0
# Linear travel of X Y Z (machine coordinates, mm): example values, wide
# enough for the samples and the real CL files; set your machine's. A value
# outside is refused with FILE:LINE, never written.
travel      {X {-3000 3000} Y {-3000 3000} Z {-2000 2000}}
axes {
    C {side head sense -1 min 0 max 360 continuous 0 prefer none}
    B {side head sense 1 min 0 max 180 continuous 0 prefer positive}
}
