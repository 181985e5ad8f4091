#!/usr/bin/python3
"""The bypass loads of a junction's skin splices against the free body of a strip (docs/output.md,
"Bypass"; docs/wing-fuselage.md, "What the charts show").

A skin ends at the butt, and the splice plate (the tee's flange or the strap) takes the skin's load
out through the rows of fasteners. Take the strip of skin of one fastener pitch around one chord
station, from the butt to a cut beside the fastener of row r (row 1 at the butt): nothing else loads
it, so the load that passes that fastener in the skin, its bypass load, is the sum of the bearing
loads of the fasteners of rows 1 to r-1 at the same station. The reference is that sum, made of
joints' forces only; the bypass load is read from the elements' resultants beside the fastener.

The free body needs strips that do not shear on each other: fasteners that all behave alike (linear
springs: with clearances drawn per fastener, neighbours bear at different loads and pass load
sideways) and a running load that does not vary along the chord (a pure moment; near the spars it
does). So the check is for the middle half of the chord of a run under a pure moment with linear
springs, to RTOL (default 0.03) of the strip's whole load (the sum over its rows): on the small size
a strip is two elements wide and its bands hold the one ahead of the fastener, so they see the
chord's variation across the strip; measured 1.1 % (aluminium and carbon-epoxy skins). Steps where
the strip carries less than 1 % of the largest strip load are skipped.

usage: check_junction_strip.py RESULTS_DIR SCENE.yaml [RTOL]
"""
import csv
import sys


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    res, scene = sys.argv[1], sys.argv[2]
    rtol = float(sys.argv[3]) if len(sys.argv) > 3 else 0.03
    meta = {r["joint"]: r for r in csv.DictReader(open(scene[:-5] + ".fasteners.csv"))}
    splices = ("upper_outer", "upper_centre", "lower_outer", "lower_centre")
    by = {}  # (step, splice, index) -> {row: (bearing, |bypass|)}
    for r in csv.DictReader(open(res + "/bypass.csv")):
        m = meta[r["joint"]]
        if m["splice"] not in splices or not m["part_" + r["sheet"]].startswith(("outer_", "centre_")):
            continue  # the skin's side only: the splice plate's ends are not free
        by.setdefault((r["step"], m["splice"], int(m["index"])), {})[int(m["row"])] = (float(r["bearing"]), abs(float(r["bypass_load"])))
    if not by:
        sys.exit(f"no skin-splice rows in {res}/bypass.csv")
    count = {}
    for step, splice, i in by:
        count[(step, splice)] = max(count.get((step, splice), 0), i)
    biggest = max(sum(b for b, _ in rows.values()) for rows in by.values())
    worst, where, checked = 0.0, "", 0
    for (step, splice, i), rows in sorted(by.items()):
        n = count[(step, splice)]
        total = sum(b for b, _ in rows.values())
        if not (n / 4 < i <= 3 * n / 4) or total < 0.01 * biggest:
            continue
        for r, (bearing, bypass) in rows.items():
            behind = sum(rows[q][0] for q in rows if q < r)
            err = abs(bypass - behind) / total
            checked += 1
            if err > worst:
                worst, where = err, f"step {step}, {splice} row {r} fastener {i}: bypass {bypass:.6g}, the strip's {behind:.6g}, strip load {total:.6g}"
    print(f"check_junction_strip: {checked} skin-side bypass loads in the middle half of the chord; largest difference "
          f"{worst:.3g} of the strip's load ({where}); tolerance {rtol}")
    if checked == 0 or worst > rtol:
        print("check_junction_strip: FAIL")
        return 1
    print("check_junction_strip: PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
