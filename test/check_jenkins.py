#!/usr/bin/python3
"""Energy dissipated by the frictional joint over one displacement cycle, through the whole stack.

Requirement (benchmarks "Jenkins element"): with kg = 0 and the clearance
never reached, a cycle of imposed displacement between +A and -A with G/ke < A dissipates exactly
W = 4 G (A - G/ke). The run imposes 0 -> A -> -A -> A on patch 1 by prescribed displacement; the
closed cycle is A -> -A -> A. Its step size puts the stick/slide kinks on step boundaries, so the
trapezoid rule over f_t1 d(du_t1) is exact up to round-off; tolerance 1e-9 relative.
Usage: check_jenkins.py joints.csv A G ke
"""
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
A, G, ke = map(float, sys.argv[2:5])
start = min(i for i, r in enumerate(rows) if abs(float(r["load"]) - A) < 1e-12 * A)
cyc = rows[start:]
assert abs(float(cyc[-1]["load"]) - A) < 1e-12 * A, "the path must end at +A"
W = 0.0
for a, b in zip(cyc, cyc[1:]):
    W += 0.5 * (float(a["f_t1"]) + float(b["f_t1"])) * (float(b["du_t1"]) - float(a["du_t1"]))
ref = 4 * G * (A - G / ke)
states = {r["state"] for r in cyc}
print(f"W = {W!r} N mm over the cycle, closed form {ref!r}; states {sorted(states)}")
sys.exit(0 if abs(W - ref) <= 1e-9 * ref and states == {"stick", "slide"} else 1)
