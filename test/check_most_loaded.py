#!/usr/bin/python3
"""summary.json's most loaded joint against joints.csv, ties left out (docs/scenes.md, "Ties").

Requirement: the run reports the most loaded fastener: the joint with the largest in-plane force
hypot(f_t1, f_t2) over all steps (the smallest id among equals), leaving out ties, the joints whose
fastener-table row names a footprint node set (modelling devices that carry whole loads into parts).
The reference is recomputed here from joints.csv and the scene's fastener table. The check also
asks that at least one tie carries more than the reported joint, so that leaving ties out matters.
Usage: check_most_loaded.py DIR SCENE.joints.csv
"""
import csv
import json
import math
import sys


def main():
    out, table = sys.argv[1], sys.argv[2]
    ties = set()
    with open(table) as f:
        for r in csv.DictReader(line for line in f if not line.startswith("#")):
            if (r.get("footprint") or "").strip():
                ties.add(int(r["id"]))
    best, tie_best = None, 0.0
    for r in csv.DictReader(open(out + "/joints.csv")):
        j, f = int(r["joint"]), math.hypot(float(r["f_t1"]), float(r["f_t2"]))
        if j in ties:
            tie_best = max(tie_best, f)
        elif best is None or f > best[0] or (f == best[0] and j < best[1]):
            best = (f, j, int(r["step"]))
    s = json.load(open(out + "/summary.json"))["most_loaded_joint"]
    print(f"summary: joint {s['joint']} at step {s['step']}, {s['in_plane_force']:.6g} N; joints.csv without the {len(ties)} ties: "
          f"joint {best[1]} at step {best[2]}, {best[0]:.6g} N; the most loaded tie {tie_best:.6g} N")
    ok = s["joint"] == best[1] and s["step"] == best[2] and abs(s["in_plane_force"] - best[0]) <= 1e-12 * best[0]
    return 0 if ok and ties and tie_best > best[0] else 1


if __name__ == "__main__":
    sys.exit(main())
