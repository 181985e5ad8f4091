#!/usr/bin/python3
"""Load shares of the side-of-body skin splices' rows against the spring chain of docs/lap-rows.md.

Requirement: where the chain's assumptions hold, the rows of a splice share the load as the chain
says. Each side of a skin splice (the outer or centre skin on the tee's flange or the strap) is a
lap of two sheets with n rows of fasteners across the load: the skin ends at the butt (row 1) and
the splice plate carries the load on across it. Tate & Rosenfeld's chain (NACA TN 1051; for two
identical sheets test/check_lap_rows.py) with sheets of their own stiffness: between rows i and
i + 1 (row spacing s) the skin carries S_i = F_1 + ... + F_i and the plate P - S_i, and the slips
delta_i = F_i / kf satisfy

    delta_{i+1} - delta_i = s (S_i / (E_skin t_skin w) - (P - S_i) / (E_plate t_plate w)),  sum F_i = P

for a strip of width w (the pitch along the row) and kf the fastener's shear stiffness (the type's
identified kt, summary.json). The assumptions: a load along the span, the same at every chord
station (a pure bending moment: the wing_small_moment scenes), straight sheets without secondary
bending, point fasteners. Checked in the middle half of the chord, away from the spars and their
fittings; the spanwise force of each fastener is its joint force projected on the span (joints.csv
in the joint's frame, the frame from NAME.joints.csv).

Tolerance: 0.02 of the load on every share. What the chain leaves out moves the shares by that much
on the lap-rows specimens (1.8 to 1.9 points: secondary bending, the sheets' local flexibility;
docs/lap-rows.md), and the junction's footprints are one element, not a point.

usage: check_junction_chain.py RESULTS_DIR SCENE.yaml [TOL]
"""
import csv
import json
import sys

import numpy as np


def chain_shares(n, kf, s, EA_skin, EA_plate):
    """F_1..F_n for P = 1, row 1 where the skin ends."""
    A, b = np.zeros((n, n)), np.zeros(n)
    for i in range(n - 1):  # (F_{i+1} - F_i)/kf - s (S_i/EA_skin - (1 - S_i)/EA_plate) = 0
        A[i, i + 1] += 1 / kf
        A[i, i] -= 1 / kf
        A[i, :i + 1] -= s * (1 / EA_skin + 1 / EA_plate)
        b[i] = -s / EA_plate
    A[n - 1, :] = 1.0
    b[n - 1] = 1.0
    return list(np.linalg.solve(A, b))


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    res, scene = sys.argv[1], sys.argv[2]
    tol = float(sys.argv[3]) if len(sys.argv) > 3 else 0.02
    base = scene[:-5]
    model = json.load(open(base + ".model.json"))
    y_butt = model["geometry"]["y_butt"]
    types = model["joint_types"]
    kts = {k: v["kt"] for k, v in json.load(open(res + "/summary.json"))["identified_joint_types"].items()}
    frames = {int(r["id"]): r for r in csv.DictReader(open(base + ".joints.csv"))}
    rows = list(csv.DictReader(open(res + "/joints.csv")))
    last = max(int(r["step"]) for r in rows)
    forces = {int(r["joint"]): r for r in rows if int(r["step"]) == last}
    splices = {}
    for f in csv.DictReader(open(base + ".fasteners.csv")):
        if f["splice"] in ("upper_outer", "upper_centre", "lower_outer", "lower_centre"):
            splices.setdefault((f["splice"], f["side"]), []).append(f)
    if not splices:
        sys.exit(f"{base}.fasteners.csv has no skin splice fasteners")
    worst, bad, lines = 0.0, [], []
    for (splice, side), fs in sorted(splices.items()):
        stations = {}
        for f in fs:
            j = int(f["joint"])
            fr, fo = frames[j], forces[j]
            n = [float(fr[k]) for k in ("nx", "ny", "nz")]
            t1 = [float(fr[k]) for k in ("t1x", "t1y", "t1z")]
            t2y = n[2] * t1[0] - n[0] * t1[2]  # (n x t1)_y
            fy = float(fo["f_t1"]) * t1[1] + float(fo["f_t2"]) * t2y
            stations.setdefault(int(f["index"]), []).append((abs(float(fr["y"]) - y_butt), float(fr["y"]), fy, f))
        pos = sorted(float(st[0][3]["position"]) for st in stations.values())
        lo, hi = pos[0] + 0.25 * (pos[-1] - pos[0]), pos[0] + 0.75 * (pos[-1] - pos[0])
        nrows = max(len(st) for st in stations.values())
        pitch = (pos[-1] - pos[0]) / (len(pos) - 1)
        for index, st in sorted(stations.items()):
            p = float(st[0][3]["position"])
            if not lo <= p <= hi or len(st) != nrows:
                continue
            st.sort(key=lambda e: e[0])  # row 1 at the butt
            typ = types[st[0][3]["type"]]
            kf = kts[st[0][3]["type"]]
            s = abs(st[1][1] - st[0][1]) if nrows > 1 else 1.0
            # part_a is the joint type's sheet 1 (t1, E1; scripts/wingfus/scene.py): the skin or the plate
            skin_is_a = not st[0][3]["part_a"].startswith(("upper_tee", "lower_strap"))
            EA1, EA2 = typ["E1"] * typ["t1"] * pitch, typ["E2"] * typ["t2"] * pitch
            EA_skin, EA_plate = (EA1, EA2) if skin_is_a else (EA2, EA1)
            total = sum(e[2] for e in st)
            model_shares = [e[2] / total for e in st]
            ref = chain_shares(nrows, kf, s, EA_skin, EA_plate)
            diff = max(abs(m - r) for m, r in zip(model_shares, ref))
            worst = max(worst, diff)
            lines.append(f"{splice} ({side}) station {index}: model " + " ".join(f"{m:.4f}" for m in model_shares)
                         + ", chain " + " ".join(f"{r:.4f}" for r in ref) + f", worst {diff:.4f}")
            if diff > tol:
                bad.append(lines[-1])
    print("\n".join(lines))
    if not lines:
        sys.exit("no chord station in the middle half of a splice has all its rows")
    if bad:
        sys.exit(f"{len(bad)} station(s) depart from the spring chain by more than {tol} of the load:\n" + "\n".join(bad))
    print(f"{len(lines)} stations of {len(splices)} splice sides: the rows' shares within {worst:.4f} of the spring chain's (tolerance {tol})")


if __name__ == "__main__":
    main()
