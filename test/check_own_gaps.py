#!/usr/bin/python3
"""Each fastener's own clearance (the fastener table's column `gap`, docs/scenes.md "Per-joint
parameters") is the one the frictional law used, on a whole junction run.

Requirement: a joint with its own gap bears exactly when its bolt has crossed that clearance. The
frictional law's slip w is the bolt's position in its hole (docs/joint-laws.md; no offset here), and
the bolt bears on the hole once |w| exceeds the gap j. So at every step, for every joint with a gap
in the table: bearing == (|w| > j). Rows within 1e-9 mm of the boundary are not judged. The check
also counts the rows where the type's gap (summary.json's identified types) would give the other
answer, and asks for at least one: where none exists, the run could not tell the two apart.
Usage: check_own_gaps.py RESULTS_DIR SCENE.joints.csv
"""
import csv
import json
import math
import sys


def main():
    res, table = sys.argv[1], sys.argv[2]
    own, types = {}, {}
    for r in csv.DictReader(open(table)):
        if (r.get("gap") or "").strip():
            own[r["id"]] = float(r["gap"])
            types[r["id"]] = r["type"]
    if not own:
        sys.exit(f"{table} has no joint with its own gap")
    ident = json.load(open(res + "/summary.json")).get("identified_joint_types", {})
    rows = bad = telling = 0
    for r in csv.DictReader(open(res + "/joints.csv")):
        j = r["joint"]
        if j not in own:
            continue
        w = math.hypot(float(r["slip_t1"]), float(r["slip_t2"]))
        if abs(w - own[j]) < 1e-9:
            continue
        rows += 1
        bears = r["bearing"] == "1"
        if bears != (w > own[j]):
            bad += 1
            if bad <= 5:
                print(f"step {r['step']} joint {j}: slip {w:.6g} mm, own gap {own[j]:.6g} mm, bearing {r['bearing']}")
        tg = ident.get(types[j], {}).get("gap")
        if tg is not None and (w > tg) != (w > own[j]):
            telling += 1
    print(f"{rows} rows of {len(own)} joints with their own gap: {bad} disagree with bearing == (|slip| > own gap); "
          f"in {telling} the type's gap would give the other answer")
    return 0 if bad == 0 and telling > 0 and rows > 0 else 1


if __name__ == "__main__":
    sys.exit(main())
