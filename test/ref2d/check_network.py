#!/usr/bin/python3
"""Compares boltnet's joints.csv on a network of rigid patches with the independent reference
(network.py), step by step.

Requirement (docs/joint-laws.md, docs/solver.md; standards): the frictional macroelement in the
joint plane (radial return on the Coulomb circle, circular clearance, bearing, clamp coupling,
offset) and the load stepping (commit only converged steps) give, in a statically indeterminate
network where several joints share the load and the slip directions turn, the solution the
documents define, on any number of ranks.

What is checked, each against a reference that shares no code with boltnet:
1. the load factors of boltnet's steps are the scene's load path, possibly with steps cut back in
   between (the reference then takes the same steps: the law is path dependent);
2. every row's jumps, forces and slips against the reference's, relative to each quantity's scale
   (the largest |du|, |f| or |slip| of the whole run, as test/compare_csv.py does), within --rtol;
3. every row's state and bearing flag equal; a different state is accepted only where the reference
   finds the joint on a threshold (| |F_tr| - G | or | r - j | within 10 rtol of the force or length
   scale), and each such case is printed with its distance: it is never skipped silently;
4. the law alone: the reference law applied to boltnet's own jump and boltnet's own previous slip
   gives boltnet's force, slip and state (a round-off check of the constitutive law, separate from
   the solves);
5. equilibrium alone: boltnet's joint forces balance the applied loads at every free translation
   dof (reported; the solver's stopping test bounds it);
6. --planar: the scene is in the plane (every bolt axis z, no out-of-plane load) and boltnet's
   out-of-plane jump and force stay zero (to 1e-12 of their scales);
7. --min-turn DEG: some frictional joint's slip increment turns by at least DEG degrees between
   successive sliding steps (reversals, turns above 150 degrees, not counted), so that the scene
   does exercise the 2D slip (the turns are printed in any case).

The default tolerance, 1e-8 of each quantity's scale, is the error boltnet's stopping test allows, not a
margin: a step stops when ||F|| <= 100 eps ||J||_inf ||x||_inf (docs/solver.md); with kr = 1e9 N mm/rad
in the rows of the rotations that bound is about 100 eps 4 kr |u| ~ 1e-5 N here, 1e-9 to 9e-9 of the
forces, and the softest sliding directions (kg ~ ke/100) turn it into jumps of the same relative
size (measured at most 5.6e-9 over 24 scenes). With kr = 1e5 (rotations are decoupled from the
compared quantities on rigid patches) and -snes_rtol 1e-14 a scene agrees to 3.5e-13, which a ctest
checks at 1e-10. The reference solves to 1e-13 of the forces or to the round-off of each row.
Usage: check_network.py boltnet/joints.csv scene.yaml [--rtol R] [--planar] [--min-turn DEG]
                        [-option value ...]   (options given to boltnet on its command line)
"""
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import laws  # noqa: E402
from network import Network  # noqa: E402
from scene import Scene  # noqa: E402

FAMILIES = {"du": ("du_n", "du_t1", "du_t2"), "f": ("f_n", "f_t1", "f_t2"), "slip": ("slip_t1", "slip_t2")}


def read_rows(path):
    steps = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            steps.setdefault(int(row["step"]), {})[int(row["joint"])] = row
    return [steps[s] for s in sorted(steps)]


def subsequence(nominal, got):
    """True when every nominal load factor appears in order among got and got ends on the last."""
    k = 0
    for g in got:
        if k < len(nominal) and abs(g - nominal[k]) <= 1e-12 * max(1.0, abs(nominal[k])):
            k += 1
    return k == len(nominal) and abs(got[-1] - nominal[-1]) <= 1e-12 * max(1.0, abs(nominal[-1]))


def vec(row, names):
    return np.array([float(row[c]) for c in names])


def threshold_note(jt, o, band_f, band_l):
    """Why a state may legitimately differ: the reference's distances to the thresholds."""
    m, notes = o["margins"], []
    if "slip" in m and abs(m["slip"]) <= band_f:
        notes.append(f"|F_tr| - G = {m['slip']:.2e} N (band {band_f:.1e})")
    if "gap" in m and abs(m["gap"]) <= band_l:
        notes.append(f"r - j = {m['gap']:.2e} mm (band {band_l:.1e})")
    return "; ".join(notes)


def turns(net, rows):
    """Angles (degrees) between the slip increments of successive sliding steps of each joint."""
    out = []
    for k, jt in enumerate(net.joints):
        if jt["p"]["law"] != "friction":
            continue
        prev_w, prev_d = np.zeros(2), None
        for step in rows:
            r = step[jt["id"]]
            w = vec(r, FAMILIES["slip"])
            if r["state"] in ("slide", "contact"):
                d = w - prev_w
                if prev_d is not None and np.linalg.norm(d) > 0 and np.linalg.norm(prev_d) > 0:
                    c = d @ prev_d / (np.linalg.norm(d) * np.linalg.norm(prev_d))
                    out.append((np.degrees(np.arccos(np.clip(c, -1, 1))), jt["id"]))
                prev_d = d
            prev_w = w
    return out


def main(argv):
    rtol, planar, min_turn, rest = 1e-8, False, None, []
    it = iter(argv)
    for a in it:
        if a == "--rtol":
            rtol = float(next(it))
        elif a == "--planar":
            planar = True
        elif a == "--min-turn":
            min_turn = float(next(it))
        else:
            rest.append(a)
    path, scene_path, options = rest[0], rest[1], rest[2:]
    rows = read_rows(path)
    scene = Scene(scene_path, options)
    net = Network(scene)
    fails = []

    # 1. The load factors.
    loads = [float(next(iter(step.values()))["load"]) for step in rows]
    nominal = scene.load_factors()
    if not subsequence(nominal, loads):
        print(f"FAIL: the load factors of {path} are not the scene's load path {nominal} (with cut-backs)")
        return 1
    ref = net.run(loads)

    # 2. and 3. Row by row against the reference.
    scale = {fam: max(max(np.max(np.abs(o[key][:len(cols)])) for st in ref for o in st["joints"]) for key in [{"du": "du", "f": "f", "slip": "w"}[fam]])
             for fam, cols in FAMILIES.items()}
    scale = {fam: v if v > 0 else 1.0 for fam, v in scale.items()}
    band_f, band_l = 10 * rtol * scale["f"], 10 * rtol * max(scale["du"], scale["slip"])
    worst = {fam: (0.0, None) for fam in FAMILIES}
    states, thresholds, on_threshold = {}, 0, 0
    for s, (step, st) in enumerate(zip(rows, ref), start=1):
        if sorted(step) != [jt["id"] for jt in net.joints]:
            fails.append(f"step {s}: joints {sorted(step)} are not the scene's")
            continue
        for jt, o in zip(net.joints, st["joints"]):
            r = step[jt["id"]]
            mine = {"du": o["du"], "f": o["f"], "slip": o["w"]}
            for fam, cols in FAMILIES.items():
                d = np.max(np.abs(vec(r, cols) - mine[fam])) / scale[fam]
                if d > worst[fam][0]:
                    worst[fam] = (d, (s, jt["id"]))
                if d > rtol:
                    fails.append(f"step {s} (load {r['load']}) joint {jt['id']}: {fam} {vec(r, cols)} against the reference's {mine[fam]} ({d:.2e} of the scale)")
            states[r["state"]] = states.get(r["state"], 0) + 1
            note = threshold_note(jt, o, band_f, band_l)
            on_threshold += bool(note)
            if r["state"] != o["state"] or int(r["bearing"]) != o["bearing"]:
                what = f"step {s} joint {jt['id']}: boltnet {r['state']} (bearing {r['bearing']}), reference {o['state']} (bearing {o['bearing']})"
                if note:
                    thresholds += 1
                    print(f"threshold: {what}: the joint sits on a threshold, {note}")
                else:
                    fails.append(what + f", away from any threshold ({o['margins']})")

    # 4. The law alone, from boltnet's own jumps and previous slips.
    law_worst = 0.0
    prev = {jt["id"]: np.zeros(2) for jt in net.joints}
    for s, step in enumerate(rows, start=1):
        for jt in net.joints:
            r = step[jt["id"]]
            f, _, w, state, bearing, m = laws.evaluate(jt["p"], prev[jt["id"]], vec(r, FAMILIES["du"]))
            d = max(np.max(np.abs(f - vec(r, FAMILIES["f"]))) / scale["f"], np.max(np.abs(w - vec(r, FAMILIES["slip"]))) / scale["slip"])
            law_worst = max(law_worst, d)
            if d > 1e-12 or (state != r["state"] and not threshold_note(jt, {"margins": m}, band_f, band_l)):
                fails.append(f"step {s} joint {jt['id']}: the law applied to boltnet's jump gives {state} {f} {w}, boltnet wrote {r['state']} {vec(r, FAMILIES['f'])} {vec(r, FAMILIES['slip'])}")
            prev[jt["id"]] = vec(r, FAMILIES["slip"])

    # 5. Equilibrium of boltnet's joint forces at the free translation dof.
    free_t = [g for g in net.free if g % 6 < 3]
    eq_worst = 0.0
    for step in rows:
        f = np.zeros(net.ndof)
        for jt in net.joints:
            fg = jt["R"].T @ vec(step[jt["id"]], FAMILIES["f"])
            f[6 * jt["b"]:6 * jt["b"] + 3] += fg
            f[6 * jt["a"]:6 * jt["a"] + 3] -= fg
        lam = float(next(iter(step.values()))["load"])
        eq_worst = max(eq_worst, np.max(np.abs(f - lam * scene.force)[free_t]) / scale["f"])

    # 6. In the plane.
    if planar:
        if any(abs(jt["R"][0][2]) != 1.0 for jt in net.joints) or np.any(scene.force[2::6]) or np.any(scene.force[3::6]) or np.any(scene.force[4::6]):
            fails.append("--planar: the scene is not planar")
        oop = max(max(abs(float(r["du_n"])) / scale["du"], abs(float(r["f_n"])) / scale["f"]) for step in rows for r in step.values())
        print(f"out of plane: largest |du_n| and |f_n| are {oop:.1e} of their scales")
        if oop > 1e-12:
            fails.append(f"--planar: boltnet's out-of-plane jump or force reaches {oop:.1e} of its scale")

    # 7. The slip turns.
    tl = turns(net, rows)
    turning = [t for t in tl if t[0] <= 150]
    top = max(turning, default=(0.0, None))
    print(f"slip turns: {len(tl)} pairs of successive sliding steps, {sum(t[0] > 150 for t in tl)} reversals, "
          f"{sum(10 < t[0] <= 150 for t in tl)} turns over 10 degrees, largest {top[0]:.1f} degrees (joint {top[1]})")
    if min_turn is not None and top[0] < min_turn:
        fails.append(f"no slip direction turns by {min_turn} degrees (largest {top[0]:.1f}): the scene does not exercise the 2D law")

    print(f"{len(rows)} steps ({len(rows) - len(nominal)} from cut-backs), {len(net.joints)} joints, states "
          + ", ".join(f"{k} {v}" for k, v in sorted(states.items())))
    for fam, (d, where) in worst.items():
        print(f"largest difference in {fam}: {d:.2e} of its scale {scale[fam]:.4g} (step, joint {where})")
    print(f"the law on boltnet's own jumps: {law_worst:.1e}; boltnet's equilibrium residual: {eq_worst:.1e} of the force scale;"
          f" reference residual {max(st['residual'] for st in ref):.1e}")
    print(f"rows on a threshold: {on_threshold}, of which {thresholds} with another state in boltnet (printed above)")
    for f in fails[:20]:
        print("FAIL:", f)
    if fails:
        print(f"check_network.py: {len(fails)} failures (tolerance {rtol:g} of each quantity's scale)")
        return 1
    print(f"check_network.py: boltnet agrees with the reference within {rtol:g} of each quantity's scale")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
