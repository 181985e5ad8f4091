#!/usr/bin/python3
"""Checks fig3b: four bolts with growing clearances come into bearing one after the other.

Requirement (paper figure 3b): under growing compression, the bolt with the smallest
clearance bears first, then the next, in order, and all four bear at the end; and at every step the
four bolts together carry the applied load (equilibrium of plate B in x: sum of f_t1 = load, to the
round-off of the solve, rtol 1e-7).
Usage: check_fig3b.py joints.csv joint-ids-in-clearance-order (e.g. 1,2,3,4)
"""
import collections
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
order = [j for j in sys.argv[2].split(",")]
steps = collections.defaultdict(list)
for r in rows:
    steps[int(r["step"])].append(r)
first = {}
for s in sorted(steps):
    total = sum(float(r["f_t1"]) for r in steps[s])
    load = float(steps[s][0]["load"])
    if abs(total - load) > 1e-7 * abs(load):
        print(f"step {s}: the bolts carry {total}, the load is {load}")
        sys.exit(1)
    for r in steps[s]:
        if r["state"] == "contact" and r["joint"] not in first:
            first[r["joint"]] = s
onsets = [first.get(j) for j in order]
print(f"{len(steps)} steps in equilibrium; first step in bearing per bolt {dict(zip(order, onsets))}")
if None in onsets:
    print("not every bolt came into bearing")
    sys.exit(1)
if any(a >= b for a, b in zip(onsets, onsets[1:])):
    print("the bolts did not come into bearing one after the other in the order of their clearances")
    sys.exit(1)
