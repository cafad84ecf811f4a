# umc750 -- Haas UMC-750 on the Haas NGC control: a B-C trunnion
# (table-table). B (outer, the tilting trunnion) about +Y, C (the round
# platter, carried by B) about +Z through the table reference point.
#
# Source of the figures: Haas UMC-750 specifications, haascnc.com (the
# operator's manual's G234/G254 sections name the MRZP, not its values).
# Published:
#   travel X 30 in (762 mm), Y 20 in (508 mm), Z 20 in (508 mm);
#   tilt B +110 / -35 deg; rotation C 360 deg, continuous.
#   (Haas's published figures as the project knows them; the sheet itself
#   was not at hand to cite, so check them against your machine's.)
# Assumed (not published, set your machine's):
#   - the travels centred on the workpiece origin (as dmu125p's);
#   - the machine rotary zero point (MRZP, Haas settings 255-257: the
#     control measures it per machine): B's axis 50 mm below the table
#     reference point (the platter's top centre), C's through it, i.e.
#     the rotary zero point as data below (point of B);
#   - ISO senses on both axes; C written in unwound values (no rollover);
#   - tool-change height G53 Z0, rotaries home at the end.
name        umc750
description {Haas UMC-750: B-C trunnion, B -35..110, continuous C, Haas NGC}
units       mm
family      chain
controller  haas
table_offset {0 0 0}
travel      {X {-381 381} Y {-254 254} Z {-254 254}}
home_rotaries 1
axes {
    B {side table direction {0 1 0} point {0 0 -50} sense 1 min -35 max 110}
    C {side table direction {0 0 1} point {0 0 0} sense 1 continuous 1}
}
