#!/usr/bin/python3
"""Checks a fig3c joints.csv against an independent reference of the 1D frictional macroelement.

Requirement: stick, slide and bearing follow the paper's closed form under
monotonic loading; unloading is elastic until the force has dropped by 2G; reverse loading slides
back across the clearance and bears on the other side.

The reference is written force-first (the driver is displacement-first): for an applied force F and
the slip w committed at the previous step, the joint sticks if |F - h(w)| <= G, with
du = w + (F - h(w))/ke; otherwise it slides to the w' that solves G s + h(w') = F (h is monotone and
piecewise linear, inverted exactly), du = w' + G s/ke, with h(w) = kg w + (kc - kg) <|w| - j>+ sign(w).
The same check applies to any joint that carries the whole load along t1 (double-lap): there rtol is
1e-7, the round-off floor of solves through shell patches (docs/solver.md).
With --held F0 (a load case that continues one which brought a force F0 below G on, its loads held:
docs/scenes.md "Held loads"), the force on the joint at each row is F0 plus the row's load, and
the reference starts from the joint stuck under F0 (slip 0).
Usage: check_fig3c.py joints.csv ke kg kc gap G [rtol] [--held F0]
"""
import csv
import sys


def h(w, kg, kc, j):
    r = abs(w)
    return kg * w + (kc - kg) * max(0.0, r - j) * (1 if w > 0 else -1)


def h_inverse(y, kg, kc, j):
    """w with h(w) = y (h is odd, increasing, slope kg inside the clearance and kc beyond)."""
    s = 1.0 if y >= 0 else -1.0
    y = abs(y)
    w = y / kg if kg > 0 and y <= kg * j else j + (y - kg * j) / kc
    return s * w


def force_first_step(F, w, ke, kg, kc, j, G):
    """One step of the reference under the applied force F from the committed slip w:
    returns (du, the new slip w, state)."""
    ff = F - h(w, kg, kc, j)
    if abs(ff) <= G * (1 + 1e-9):
        return w + ff / ke, w, "stick"
    s = 1.0 if ff > 0 else -1.0
    w = h_inverse(F - G * s, kg, kc, j)
    return w + G * s / ke, w, ("contact" if abs(w) > j * (1 + 1e-12) else "slide")


def main():
    argv = sys.argv[1:]
    held = 0.0
    if "--held" in argv:
        i = argv.index("--held")
        held = float(argv[i + 1])
        del argv[i:i + 2]
    path = argv[0]
    ke, kg, kc, j, G = map(float, argv[1:6])
    rtol = float(argv[6]) if len(argv) > 6 else 1e-9
    assert abs(held) < G, "--held: the held force must leave the joint stuck (|F0| < G)"
    rows = list(csv.DictReader(open(path)))
    assert rows, f"{path}: no rows"
    w = 0.0
    worst = 0.0
    states = set()
    for row in rows:
        F = held + float(row["load"])
        du, w, state = force_first_step(F, w, ke, kg, kc, j, G)
        got_du, got_f = float(row["du_t1"]), float(row["f_t1"])
        err = abs(got_du - du) / max(abs(du), 1e-3 * j)
        worst = max(worst, err)
        # The force is judged against the larger of the load and the friction threshold G, so that a
        # step at zero load is judged at the scale of the forces of the problem.
        if err > rtol or abs(got_f - F) > rtol * max(abs(F), G) or row["state"] != state:
            print(f"step {row['step']} load {F}: expected du {du!r} {state}, got du {got_du!r} f {got_f!r} {row['state']}")
            return 1
        states.add(state)
    missing = {"stick", "slide", "contact"} - states
    if missing:
        print(f"the load path never reached {sorted(missing)}")
        return 1
    print(f"{len(rows)} rows match the closed form (worst relative error {worst:.2e}); states seen {sorted(states)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
