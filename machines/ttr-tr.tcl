# ttr-tr -- TTR-TR machine of the rotary-axis error study: the table moves
# in X and Y and turns about C (vertical, through the table centre); the
# head moves in Z and tilts about B (horizontal, along Y, through the pivot
# point). As in that paper the tool is horizontal at B = 0 (pointing along
# -X from tip to spindle) and vertical at B = 90: the B axis has a zero
# offset of 90 deg (the written B value where the tool points along +Z).
# C turns the part counter-clockwise seen from +Z for a positive angle
# (sense -1), which gives the paper's inverse with the quadrant restored:
#   B = asin(K) or 180 - asin(K),  C = atan2(J, -I) (+180 for the second),
#   Y = -(x sin C + y cos C)       (the paper's dy is -Y: the table moves).
# Lengths in mm, angles in degrees.
# Example machine, no real machine's data (the rotary-axis error study's
# geometry); its travel is an example value: describe your machine before
# posting for it.
name        ttr-tr
description {TTR-TR: table X Y C, head Z B (tool horizontal at B 0, vertical at B 90)}
units       mm
family      chain
pivot       150
tool_length 0
# Linear travel of X Y Z (machine coordinates, mm): example values, wide
# enough for the samples and the real CL files; set your machine's. A value
# outside is refused with FILE:LINE, never written.
travel      {X {-3000 3000} Y {-3000 3000} Z {-2000 2000}}
axes {
    B {side head direction {0 1 0} point {0 0 0} sense 1 offset 90 min -10 max 190 prefer none}
    C {side table direction {0 0 1} point {0 0 0} sense -1 continuous 1}
}
