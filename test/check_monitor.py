#!/usr/bin/python3
"""Checks -joint_monitor against joints.csv.

Requirement: per Newton iteration the
monitor prints the joints in each state, summed over ranks. At the last iteration of each load step
those counts must equal the states joints.csv records for that step (written from the converged
point by a different path: records gathered to rank 0), and every line must count every joint.
Usage: check_monitor.py monitor-output.txt joints.csv
"""
import collections
import csv
import re
import sys

pat = re.compile(r"^\s*(\d+) joints: stick (\d+) slide (\d+) contact (\d+) open (\d+) linear (\d+) \| changed (\d+)")
# Joints solved as linear springs that the full law sends out of stick are released, and the same
# step solves on (-joint_stuck_linear, docs/solver.md): that solve continues the step's.
released = re.compile(r"^\s*step \d+: \d+ joints solved as linear springs would leave")
solves, current, go_on = [], None, False
for line in open(sys.argv[1]):
    if released.match(line):
        go_on = True
        continue
    m = pat.match(line)
    if not m:
        continue
    it, *counts = map(int, m.groups())
    if it == 0 and not go_on:
        current = []
        solves.append(current)
    go_on = False
    current.append(counts)
rows = list(csv.DictReader(open(sys.argv[2])))
steps = collections.defaultdict(collections.Counter)
for r in rows:
    steps[int(r["step"])][r["state"]] += 1
njoints = len({r["joint"] for r in rows})
if len(solves) != len(steps):
    print(f"{len(solves)} monitored solves for {len(steps)} steps")
    sys.exit(1)
for k, (solve, step) in enumerate(zip(solves, sorted(steps)), start=1):
    for counts in solve:
        if sum(counts[:5]) != njoints:
            print(f"solve {k}: a monitor line counts {sum(counts[:5])} joints, not {njoints}")
            sys.exit(1)
    last = dict(zip(["stick", "slide", "contact", "open", "linear"], solve[-1][:5]))
    want = {s: steps[step].get(s, 0) for s in last}
    if last != want:
        print(f"step {step}: monitor {last}, joints.csv {want}")
        sys.exit(1)
print(f"{len(solves)} steps: the monitor's final counts match joints.csv ({njoints} joints)")
