#!/usr/bin/python3
"""Equilibrium of each outer wing box of a junction scene (scripts/make-wing-fuselage), at every step.

Requirement: the side-of-body joint carries the wing's loads: the outer box (its two skins and its
substructure) is held only by the fasteners of the joint, so the forces and moments those fasteners
apply to it must balance the loads applied at its tip, at every converged step of the load path:

    sum_j F_j + lambda F_tip = 0,   sum_j ((x_j - O) x F_j + M_j) + lambda M_tip = 0

F_tip, M_tip: the resultant of the tip's node-set forces about the side-of-body point O, computed by
the generator from the node positions (NAME.model.json); lambda the load factor. F_j = the joint's
force on the box's side in global axes, from joints.csv or joints.h5 (force f on node B in the joint frame n, t1,
t2: the joint pulls node A with +f and node B with -f); M_j = kr (theta_B - theta_A), the rotational
spring's moment, with each node's rotation read in fields.h5 at its footprint (exact coupling: every
footprint node turns with the joint node) and kr from summary.json (identified types) or the scene
(spring types). Joints with both sides in the box (the attachments, and with --tip-load rigid the ties
of the rigid patch that carries the tip load) cancel.

Tolerance: the driver accepts a step when its out-of-balance force is below -load_equilibrium_rtol
(1e-6) of the problem's force scale, the largest of the applied loads, the reactions and the joint
forces (lib/solver/stepper.cpp), and Newton's last iteration usually lands far below it. Measured
with the global factorisation (-patch_condense false): 1.7e-8 (tiny), 2.2e-10 (linear springs) of
the applied resultant. 1e-6 keeps the driver's own bound, and is still three orders below a
modelling error (a lost node force, a misplaced set: 1e-3 and above). With the condensed patches
(the default) this scene balances to 1.5e-5 to 4.5e-5 only; the ctests use the global factorisation.

With --no-tip-load (the cabin pressure's load case, which loads the fuselage skin alone) the tip
load is zero: the box's fasteners must then balance each other, to RTOL of the sum of their forces'
magnitudes.

With --whole-box (a scene of both wings, --both-sides) the free body is instead every part but the
fuselage, with both wings' tip loads (their resultants moved to one point): the wing boxes, their
splices and the centre box, held by the fuselage alone, through the lap on the tee's stem and the
spar frames' fasteners. (A half model's centre box is also held by its symmetry plane.)

usage: check_junction_equilibrium.py RESULTS_DIR SCENE.yaml [RTOL] [--no-tip-load] [--whole-box]
"""
import csv
import json
import os
import sys

import h5py
import numpy as np


def joint_rows(res):
    """joints.csv's rows, or the same fields from the joint table joints.h5 that a model of 10,000
    joints or more writes instead (docs/output.md, "The joint table")."""
    path = os.path.join(res, "joints.csv")
    if os.path.exists(path):
        yield from csv.DictReader(open(path))
        return
    with h5py.File(os.path.join(res, "joints.h5"), "r") as f:
        step, load, ids, force = f["step"][()], f["load"][()], f["joint"][()], f["force"][()]
    for s in range(len(step)):
        for k, j in enumerate(ids):
            yield {"step": step[s], "load": load[s], "joint": j, "f_n": force[s, k, 0], "f_t1": force[s, k, 1], "f_t2": force[s, k, 2]}


def main():
    tip = 0.0 if "--no-tip-load" in sys.argv else 1.0
    whole = "--whole-box" in sys.argv
    args = [a for a in sys.argv[1:] if a not in ("--no-tip-load", "--whole-box")]
    res, scene = args[0], args[1]
    rtol = float(args[2]) if len(args) > 2 else 1e-6
    base = scene[:-5]
    model = json.load(open(base + ".model.json"))
    summary = json.load(open(os.path.join(res, "summary.json")))
    if summary["status"] != "converged":
        sys.exit(f"{res}: the run did not converge")
    kr = {t: p["kr"] for t, p in summary.get("identified_joint_types", {}).items()}
    for t, p in model["joint_types"].items():
        if p["law"] == "spring":
            kr[t] = p["kr"]
    pid = {}
    for r in csv.DictReader(l for l in open(base + ".patches.csv") if not l.startswith("#")):
        pid[r["part"]] = int(r["id"])
    table = {int(r["id"]): r for r in csv.DictReader(open(base + ".joints.csv"))}
    h5 = h5py.File(os.path.join(res, "fields.h5"), "r")
    X = h5["shells/coordinates"][:]
    Q = h5["shells/cells"][:]  # quadrilaterals: the junction is meshed in them
    qpart = h5["shells/part"][:, 0]
    cent = X[Q].mean(axis=1)

    def footprint_node(part, x, n):
        """The nodes of the element of `part` that holds the fastener at x, as boltnet finds it
        (lib/mesh/search.cpp): among the elements that contain x seen along the axis n, the nearest
        along it. (A fastener at an element's centre is also nearest its centroid; one off-centre,
        such as a spar frame's on the web, need not be.)"""
        idx = np.flatnonzero(qpart == part)
        e1 = np.cross(n, [1.0, 0, 0] if abs(n[0]) < 0.9 else [0, 1.0, 0])
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(n, e1)
        c = np.stack([(X[Q[idx]] - x) @ e1, (X[Q[idx]] - x) @ e2], axis=-1)   # (k, 4, 2), x at the origin
        cr = c[:, :, 0] * np.roll(c[:, :, 1], -1, axis=1) - c[:, :, 1] * np.roll(c[:, :, 0], -1, axis=1)
        inside = ~((cr > 1e-12).any(axis=1) & (cr < -1e-12).any(axis=1))
        if not inside.any():
            sys.exit(f"no element of part {part} holds the fastener at {x}")
        cand = idx[inside]
        return Q[cand[np.argmin(np.abs((cent[cand] - x) @ n))]]

    frames, nodes = {}, {}
    for j, r in table.items():
        n = np.array([float(r[k]) for k in ("nx", "ny", "nz")])
        n /= np.linalg.norm(n)
        t1 = np.array([float(r[k]) for k in ("t1x", "t1y", "t1z")])
        t1 -= n * (t1 @ n)
        t1 /= np.linalg.norm(t1)
        x = np.array([float(r[k]) for k in ("x", "y", "z")])
        frames[j] = (n, t1, np.cross(n, t1), x)
        if r["type"] != "tie":   # a tie joins a rigid patch to the box: inside the free body, never read
            nodes[j] = (footprint_node(int(r["patch_a"]), x, n), footprint_node(int(r["patch_b"]), x, n))
    steps = {}
    for r in joint_rows(res):
        steps.setdefault(int(r["step"]), []).append(r)
    worst = 0.0
    bodies = []
    for wing in model["wings"]:
        # With --tip-load rigid the rigid patch that carries the tip load belongs to the free body: its
        # ties to the box are internal, the load on it external.
        box = {pid[p] for p in wing["parts"]} | ({model["rigid_patches"][wing["rigid"]]} if "rigid" in wing else set())
        bodies.append((wing["side"] + " wing", box, np.array(wing["origin"]), np.array(wing["force"]), np.array(wing["moment"])))
    if whole:
        if not model["both_sides"]:
            sys.exit("--whole-box needs a scene of both wings: a half model's centre box is also held by its symmetry plane")
        O = np.zeros(3)
        box = set(pid.values()) - {pid["fuselage"]} | set(model.get("rigid_patches", {}).values())
        Ft = sum(F for _, _, _, F, _ in bodies)
        Mt = sum(M + np.cross(Ow - O, F) for _, _, Ow, F, M in bodies)
        bodies = [("whole wing box (every part but the fuselage)", box, O, Ft, Mt)]
    for name, box, O, Ft, Mt in bodies:
        Ft, Mt = tip * Ft, tip * Mt
        for step, rows in sorted(steps.items()):
            lam = float(rows[0]["load"])
            rot = h5[f"steps/{step:06d}/shells/rotation"][:]
            F, M = np.zeros(3), np.zeros(3)
            fsum, msum = 0.0, 0.0   # the magnitudes the box's fasteners apply (the scale without a tip load)
            for r in rows:
                j = int(r["joint"])
                ra, rb = int(table[j]["patch_a"]), int(table[j]["patch_b"])
                sign = (ra in box) - (rb in box)   # +1: the box is A, -1: the box is B, 0: both or neither
                if sign == 0:
                    continue
                n, t1, t2, x = frames[j]
                f = float(r["f_n"]) * n + float(r["f_t1"]) * t1 + float(r["f_t2"]) * t2
                na, nb = nodes[j]
                tha, thb = rot[na], rot[nb]
                # Exact coupling: the footprint turns rigidly (a check of the reading of fields.h5).
                spread = max(np.ptp(tha, axis=0).max(), np.ptp(thb, axis=0).max())
                if spread > 1e-9 * max(1e-12, np.abs(rot).max()):
                    sys.exit(f"joint {j}: its footprint nodes do not share one rotation ({spread:.2e})")
                m = np.cross(x - O, f) + kr[table[j]["type"]] * (thb[0] - tha[0])
                F += sign * f
                M += sign * m
                fsum, msum = fsum + np.linalg.norm(f), msum + np.linalg.norm(m)
            if abs(lam) < 1e-14:
                continue
            if tip:
                ef = np.linalg.norm(F + lam * Ft) / (abs(lam) * np.linalg.norm(Ft))
                em = np.linalg.norm(M + lam * Mt) / (abs(lam) * np.linalg.norm(Mt))
            else:
                ef, em = np.linalg.norm(F) / max(fsum, 1e-300), np.linalg.norm(M) / max(msum, 1e-300)
            worst = max(worst, ef, em)
            if ef > rtol or em > rtol:
                print(f"{name}, step {step} (load {lam:g}): joints apply F {F} and M {M}; the tip load is "
                      f"{-lam * Ft} and {-lam * Mt}: relative error {ef:.2e} (force), {em:.2e} (moment) > {rtol:g}")
                return 1
        if tip:
            print(f"{name}: the fasteners that hold it balance the tip load (V {Ft[2]:.6g} N, moment {np.linalg.norm(Mt):.6g} N mm "
                  f"per g) at {len(steps)} steps")
        else:
            print(f"{name}: no tip load; the fasteners that hold it balance each other at {len(steps)} steps")
    print(f"worst relative error {worst:.2e} (rtol {rtol:g})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
