# tt-ac -- A-C trunnion table: A (outer) about +X through (0, 0, -59.793),
# C (carried by A) about +Z through the origin. XYZ do not depend on the
# tool length on a table-table machine.
# Example machine, no real machine's data (round numbers); its travel is an
# example value: describe your machine before posting for it.
name        tt-ac
description {A-C trunnion table}
units       mm
family      chain
# Linear travel of X Y Z (machine coordinates, mm): example values, wide
# enough for the samples and the real CL files; set your machine's. A value
# outside is refused with FILE:LINE, never written.
travel      {X {-3000 3000} Y {-3000 3000} Z {-2000 2000}}
axes {
    A {side table direction {1 0 0} point {0 0 -59.793} sense 1 min -110 max 110}
    C {side table direction {0 0 1} point {0 0 0} sense 1 continuous 1}
}
