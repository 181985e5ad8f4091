#!/usr/bin/python3
"""The bypass strip of a junction scene (scripts/make-wing-fuselage): its width is the scene's.

Requirement: the generator gives the strip width of the bypass loads in the scene's output:
section (the skin splices' pitch along a row: each fastener's bypass is the load in its strip,
docs/output.md "Bypass"), and the driver reads the output's options after the scene's, so that the
scene sets them and the command line still wins. The reference is the scene file itself, read
here (or WIDTH, the value given on the command line): every row of bypass.csv has that width, and
every skin splice fastener's bypass load on its skin is a number at every step. With the default
strip, 6 coupling radii, narrower than the one element of a footprint, no element outside the
footprint lies in it and every bypass load is NaN, as on the scenes written before.

usage: check_junction_bypass.py RESULTS_DIR SCENE.yaml [WIDTH]
"""
import csv
import math
import re
import sys


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    res, scene = sys.argv[1], sys.argv[2]
    if len(sys.argv) > 3:
        width = float(sys.argv[3])
    else:
        m = re.search(r"^output:\s*\n(?:\s+.*\n)*?\s+bypass_width:\s*([0-9.eE+-]+)", open(scene).read(), re.M)
        if not m:
            sys.exit(f"{scene} has no output: bypass_width")
        width = float(m.group(1))
    meta = {r["joint"]: r for r in csv.DictReader(open(scene[:-5] + ".fasteners.csv"))}
    rows = list(csv.DictReader(open(res + "/bypass.csv")))
    bad = [r for r in rows if abs(float(r["width"]) - width) > 1e-9 * width]
    if bad:
        sys.exit(f"{len(bad)} of {len(rows)} rows of bypass.csv have another width than {width:g} (first: {bad[0]['width']})")
    skin = [r for r in rows if meta[r["joint"]]["splice"] in ("upper_outer", "upper_centre", "lower_outer", "lower_centre")
            and meta[r["joint"]]["part_" + r["sheet"]].startswith(("outer_", "centre_"))]
    nan = [r for r in skin if not math.isfinite(float(r["bypass_load"]))]
    if not skin or nan:
        sys.exit(f"{len(nan)} of {len(skin)} skin-side bypass loads of the skin splices are not numbers")
    print(f"bypass.csv: {len(rows)} rows of width {width:g} mm; {len(skin)} skin-side bypass loads of the skin splices, every one a number")


if __name__ == "__main__":
    main()
