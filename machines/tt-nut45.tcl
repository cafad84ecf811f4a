# tt-nut45 -- nutating table: B (outer) at 45 deg in the YZ plane through
# (0, 0, -120), C (carried by B) about +Z through the origin.
# Reachable tool axes: K >= 0 (cos B = 2K - 1).
# Example machine, no real machine's data (round numbers); its travel is an
# example value: describe your machine before posting for it.
name        tt-nut45
description {Nutating 45 deg table, B-C}
units       mm
family      chain
# Linear travel of X Y Z (machine coordinates, mm): example values, wide
# enough for the samples and the real CL files; set your machine's. A value
# outside is refused with FILE:LINE, never written.
travel      {X {-3000 3000} Y {-3000 3000} Z {-2000 2000}}
axes {
    B {side table direction {0 0.70710678118654757 0.70710678118654757}
       point {0 0 -120} sense 1 min 0 max 180}
    C {side table direction {0 0 1} point {0 0 0} sense 1 continuous 1}
}
