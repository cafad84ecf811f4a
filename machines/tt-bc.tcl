# tt-bc -- B-C trunnion table (worked example of the machine file format):
# B (outer) about +Y through (0, 0, -80), C (carried by B) about +Z through
# the table reference point; ISO senses; C turns without limits.
# Example machine, no real machine's data (round numbers, the machine-file
# worked example); its travel is an example value: describe your machine
# before posting for it.
name        tt-bc
description {B-C trunnion table, B -120..30, continuous C}
units       mm
family      chain
table_offset {0 0 0}
# Linear travel of X Y Z (machine coordinates, mm): example values, wide
# enough for the samples and the real CL files; set your machine's. A value
# outside is refused with FILE:LINE, never written.
travel      {X {-3000 3000} Y {-3000 3000} Z {-2000 2000}}
axes {
    B {side table direction {0 1 0} point {0 0 -80} sense 1 min -120 max 30}
    C {side table direction {0 0 1} point {0 0 0} sense 1 continuous 1}
}
