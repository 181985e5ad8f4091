#!/usr/bin/python3
"""The frictional joint of test/scenes/fig3c-held.yaml pushed across a held force: the isotropic
Coulomb cone (docs/scenes.md, "Held loads"; the friction law of docs/mission.md).

Requirement: a load held by a case that another continues stays applied, at its value, while the
other's load follows its path. The joint carries a held force F0 along t1 and the path's load lambda
along t2 (a rigid patch: the joint's force is the applied force). Independent reference, at every
row:
  - the force is (F0, lambda) (equilibrium of the rigid patch);
  - the joint sticks while hypot(F0, lambda) <= G, with du = f / ke and no slip;
  - beyond, it slides: the friction force ke (du - slip) has magnitude G, and the slip's increment
    since the row before points along it (the radial return of an isotropic cone). The force is
    then ke (du - slip) + kg slip (the law's regularisation while sliding).
Usage: check_held_cone.py joints.csv F0 ke kg G [rtol]
"""
import csv
import math
import sys


def main():
    path = sys.argv[1]
    F0, ke, kg, G = map(float, sys.argv[2:6])
    rtol = float(sys.argv[6]) if len(sys.argv) > 6 else 1e-9
    rows = list(csv.DictReader(open(path)))
    assert rows, f"{path}: no rows"
    seen, slip0 = set(), (0.0, 0.0)
    for r in rows:
        lam = float(r["load"])
        du = (float(r["du_t1"]), float(r["du_t2"]))
        f = (float(r["f_t1"]), float(r["f_t2"]))
        s = (float(r["slip_t1"]), float(r["slip_t2"]))
        bad = []
        if math.hypot(f[0] - F0, f[1] - lam) > rtol * G:
            bad.append(f"force {f}, applied ({F0}, {lam})")
        want = "stick" if math.hypot(F0, lam) <= G * (1 + 1e-12) else "slide"
        if r["state"] != want:
            bad.append(f"state {r['state']}, expected {want} (|F| = {math.hypot(F0, lam):.6g}, G = {G:g})")
        elif want == "stick":
            if math.hypot(du[0] - F0 / ke, du[1] - lam / ke) > rtol * G / ke or math.hypot(*s) > rtol * G / ke:
                bad.append(f"stick: du {du}, slip {s}; expected du ({F0 / ke}, {lam / ke}), no slip")
        else:
            fr = (ke * (du[0] - s[0]), ke * (du[1] - s[1]))
            ds = (s[0] - slip0[0], s[1] - slip0[1])
            cross = (fr[0] * ds[1] - fr[1] * ds[0]) / (G * max(math.hypot(*ds), 1e-300))
            if abs(math.hypot(*fr) - G) > rtol * G or abs(cross) > 1e-7 or fr[0] * ds[0] + fr[1] * ds[1] <= 0:
                bad.append(f"slide: friction force {fr} (|.| {math.hypot(*fr):.12g}, G {G:g}), slip increment {ds}")
            if math.hypot(fr[0] + kg * s[0] - f[0], fr[1] + kg * s[1] - f[1]) > rtol * G:
                bad.append(f"slide: force {f} is not ke (du - slip) + kg slip")
        if bad:
            print(f"step {r['step']} load {lam}: " + "; ".join(bad))
            return 1
        seen.add(want)
        slip0 = s
    if seen != {"stick", "slide"}:
        print(f"the path saw {sorted(seen)}, not both stick and slide")
        return 1
    onset = math.sqrt(G * G - F0 * F0)
    print(f"{len(rows)} rows: the force ({F0:g}, load) held and applied, stick below lambda = {onset:.6g} and slide on the cone above it")
    return 0


if __name__ == "__main__":
    sys.exit(main())
