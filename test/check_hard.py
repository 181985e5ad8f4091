#!/usr/bin/python3
"""Closed-form checks of the hard-on-purpose cases of the robustness matrix.

force1d: every joint of joints.csv carries `share` of the applied force F (the load factor, N) along
  t1 and follows the 1D frictional law's force-first closed form (check_fig3c.py's reference, with the
  state at each step); with --equal all joints' rows must agree to round-off (symmetric joints).
disp1d: the jump du_t1 is prescribed (the load factor, mm) and the force follows the displacement-first
  closed form: trial q = ke (du - w); stick if |q| <= G, F = h(w) + q; otherwise the slip w' = du - G s/ke
  and F = G s + h(w') (s = sign q). With kg = 0 this is pure Coulomb: the force saturates at G exactly
  while the bolt crosses its clearance.
--states a,b,...: the path must reach these states (and no others when --only is given).
Usage: check_hard.py force1d|disp1d joints.csv ke kg kc gap G [--share S] [--equal] [--rtol R] [--states ...] [--only]
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_fig3c import force_first_step, h  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("mode", choices=["force1d", "disp1d"])
ap.add_argument("csv")
ap.add_argument("ke", type=float)
ap.add_argument("kg", type=float)
ap.add_argument("kc", type=float)
ap.add_argument("gap", type=float)
ap.add_argument("G", type=float)
ap.add_argument("--share", type=float, default=1.0)
ap.add_argument("--equal", action="store_true")
ap.add_argument("--rtol", type=float, default=1e-9)
ap.add_argument("--states", default="")
ap.add_argument("--only", action="store_true")
a = ap.parse_args()
ke, kg, kc, j, G = a.ke, a.kg, a.kc, a.gap, a.G

rows = list(csv.DictReader(open(a.csv)))
if not rows:
    sys.exit(f"{a.csv}: no rows")
by_joint = {}
for r in rows:
    by_joint.setdefault(r["joint"], []).append(r)
fail = 0
seen = set()
worst = 0.0
for jid, jr in by_joint.items():
    w = 0.0
    for r in jr:
        load = float(r["load"])
        if a.mode == "force1d":
            F = a.share * load
            du, w, state = force_first_step(F, w, ke, kg, kc, j, G)
        else:
            du = load
            q = ke * (du - w)
            if abs(q) <= G * (1 + 1e-9):
                F, state = h(w, kg, kc, j) + q, "stick"
            else:
                s = 1.0 if q > 0 else -1.0
                w = du - G * s / ke
                F = G * s + h(w, kg, kc, j)
                state = "contact" if abs(w) > j * (1 + 1e-12) else "slide"
        got_du, got_f = float(r["du_t1"]), float(r["f_t1"])
        e_du = abs(got_du - du) / max(abs(du), 1e-3 * j)
        e_f = abs(got_f - F) / max(abs(F), G)
        worst = max(worst, e_du, e_f)
        if e_du > a.rtol or e_f > a.rtol or r["state"] != state:
            print(f"joint {jid} step {r['step']} load {load}: expected du {du!r} f {F!r} {state}, "
                  f"got du {got_du!r} f {got_f!r} {r['state']}")
            fail = 1
            break
        seen.add(r["state"])
if a.equal and len(by_joint) > 1:
    ids = sorted(by_joint)
    scale = max(abs(float(r[k])) for r in rows for k in ("f_t1", "f_t2")) or 1.0
    dscale = max(abs(float(r[k])) for r in rows for k in ("du_t1", "du_t2")) or 1.0
    for other in ids[1:]:
        for r0, r1 in zip(by_joint[ids[0]], by_joint[other]):
            df = max(abs(float(r0[k]) - float(r1[k])) for k in ("f_n", "f_t1", "f_t2")) / scale
            dd = max(abs(float(r0[k]) - float(r1[k])) for k in ("du_n", "du_t1", "du_t2")) / dscale
            if df > 1e-12 or dd > 1e-12 or r0["state"] != r1["state"]:
                print(f"step {r0['step']}: joints {ids[0]} and {other} differ (force {df:.1e}, jump {dd:.1e} of scale; "
                      f"states {r0['state']} {r1['state']})")
                fail = 1
                break
want = {s for s in a.states.split(",") if s}
if want - seen:
    print(f"the path never reached {sorted(want - seen)} (seen {sorted(seen)})")
    fail = 1
if a.only and seen - want:
    print(f"the path reached {sorted(seen - want)}, expected only {sorted(want)}")
    fail = 1
if not fail:
    print(f"{len(rows)} rows of {len(by_joint)} joint(s) match the {a.mode} closed form (worst relative error "
          f"{worst:.2e}); states seen {sorted(seen)}")
sys.exit(fail)
