"""Parameters of the junction generator: defaults for a single-aisle transport, and the sizes.

Every default is a representative public figure or a stated engineering estimate, not data of a
particular aircraft; the help text (make-wing-fuselage --help) and docs/wing-fuselage.md give the
source or the reasoning of each.
"""

# Size presets: mesh density, rows and bays. The same geometry and loads in every size.
#   nx: elements along the box chord (front to rear spar; a multiple of 6 x rib and fuselage coarsening)
#   nz: elements over the web height; rows: fastener rows on each side of each skin splice
#   fuselage_rows: rows in the fuselage skin's lap on the tee's stem
SIZES = {
    "tiny": dict(nx=24, nz=6, rows=1, fuselage_rows=1, fuselage_bays=1, rib_bays=1, coarse=160.0,
                 fuselage_h=260.0, fuselage_sub=1, stringer_pitch=380.0, rib_coarsening=1, fuselage_coarsening=1,
                 row_spacing_skin=80.0, row_spacing_fuselage=80.0, cap_width=60.0, foot_width=60.0,
                 attach_pitch=260.0, both_sides=False),
    "small": dict(nx=36, nz=8, rows=2, fuselage_rows=1, fuselage_bays=2, rib_bays=2, coarse=160.0,
                  fuselage_h=240.0, fuselage_sub=1, stringer_pitch=190.0, rib_coarsening=1, fuselage_coarsening=1,
                  row_spacing_skin=4.5 * 7.94, row_spacing_fuselage=4.5 * 4.8, cap_width=50.0, foot_width=50.0,
                  attach_pitch=200.0, both_sides=False),
    "medium": dict(nx=288, nz=52, rows=4, fuselage_rows=2, fuselage_bays=3, rib_bays=3, coarse=40.0,
                   fuselage_h=60.0, fuselage_sub=3, stringer_pitch=190.0, rib_coarsening=3, fuselage_coarsening=1,
                   row_spacing_skin=4.5 * 7.94, row_spacing_fuselage=4.5 * 4.8, cap_width=50.0, foot_width=50.0,
                   attach_pitch=4.5 * 6.35, both_sides=False),
    "full": dict(nx=504, nz=78, rows=6, fuselage_rows=4, fuselage_bays=3, rib_bays=3, coarse=20.0,
                 fuselage_h=30.0, fuselage_sub=6, stringer_pitch=190.0, rib_coarsening=3, fuselage_coarsening=1,
                 row_spacing_skin=4.5 * 7.94, row_spacing_fuselage=4.5 * 4.8, cap_width=50.0, foot_width=50.0,
                 attach_pitch=4.5 * 6.35, both_sides=True),
}
