#!/usr/bin/python3
"""A junction scene with both wings against its half model with the symmetry plane (both from
scripts/make-wing-fuselage, same size, linear springs, mirror-symmetric loads).

Requirement: the generator's both-sides model is the mirror image of its half model, and the half
model's symmetry conditions (u_y = r_x = r_z = 0 on y = 0) are the right ones: the full model's
solution is then symmetric and its right half is the half model's solution. Every fastener of the
half model is matched with its two images (same splice, row and index, right and left side) and their
forces must agree. A fastener's frame is mirrored with it except t2 = n x t1, which turns the other
way (a cross product of two mirrored vectors), so f_n and f_t1 agree and f_t2 changes sign on the
left. Tolerance 1e-7 of the largest fastener force: the two runs are different linear systems
(1.6 times the unknowns) solved to the driver's round-off tolerance.

usage: check_junction_symmetry.py HALF_RESULTS HALF.yaml BOTH_RESULTS BOTH.yaml [RTOL]
"""
import csv
import sys


def load(res, scene):
    meta = {r["joint"]: r for r in csv.DictReader(open(scene[:-5] + ".fasteners.csv"))}
    rows = list(csv.DictReader(open(res + "/joints.csv")))
    last = max(int(r["step"]) for r in rows)
    out = {}
    for r in rows:
        if int(r["step"]) == last:
            m = meta[r["joint"]]
            out[(m["splice"], m["side"], m["row"], m["index"])] = [float(r[k]) for k in ("f_n", "f_t1", "f_t2")]
    return out


def main():
    half, both = load(sys.argv[1], sys.argv[2]), load(sys.argv[3], sys.argv[4])
    rtol = float(sys.argv[5]) if len(sys.argv) > 5 else 1e-7
    if len(both) != 2 * len(half):
        print(f"the both-sides model has {len(both)} fasteners, not twice the half model's {len(half)}")
        return 1
    scale = max(max(abs(v) for v in f) for f in half.values())
    worst = 0.0
    for (splice, side, row, index), f in half.items():
        for s, sign in (("right", 1), ("left", -1)):
            g = both.get((splice, s, row, index))
            if g is None:
                print(f"no {s} image of fastener {splice} row {row} index {index}")
                return 1
            d = max(abs(f[0] - g[0]), abs(f[1] - g[1]), abs(f[2] - sign * g[2])) / scale
            worst = max(worst, d)
            if d > rtol:
                print(f"{splice} row {row} index {index}, {s} wing: forces {g} against the half model's {f} ({d:.2e} of the largest)")
                return 1
    print(f"{len(half)} fasteners and their {2 * len(half)} images agree: worst {worst:.2e} of the largest force {scale:.4g} N (rtol {rtol:g})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
