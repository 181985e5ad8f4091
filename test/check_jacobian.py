#!/usr/bin/python3
"""Reads the output of a run with -snes_test_jacobian -snes_monitor and checks the Jacobian.

Requirement: the joint tangents agree with finite differences of the forces,
through PETSc's -snes_test_jacobian. The joint laws are piecewise smooth and the first iterate of a
load step is the previous converged point (the test runs with -load_predictor false), where a
sliding joint sits exactly on its friction threshold: there PETSc's differencing step crosses the
kink and measures it, not the tangent. Those iteration-0 comparisons are reported but not judged; every other one must agree to 1e-8 (they agree
to about 1e-11). The paper's state-switched tangent fails this on 2D paths, as it should.
Usage: check_jacobian.py output.txt
"""
import re
import sys

it = None
judged, skipped = [], []
for line in open(sys.argv[1]):
    m = re.match(r"\s*(\d+) SNES Function norm", line)
    if m:
        it = int(m.group(1))
    m = re.search(r"\|\|J - Jfd\|\|_F/\|\|J\|\|_F = ([0-9.eE+-]+)", line)
    if m:
        (skipped if it == 0 else judged).append(float(m.group(1)))
if len(judged) < 5:
    print(f"only {len(judged)} Jacobian comparisons past iteration 0 (run with -snes_test_jacobian -snes_monitor)")
    sys.exit(1)
worst = max(judged)
print(f"{len(judged)} comparisons past iteration 0: worst ||J - Jfd||/||J|| = {worst:.2e}; "
      f"{len(skipped)} at iteration 0 (on state boundaries), worst {max(skipped, default=0):.2e}")
sys.exit(0 if worst < 1e-8 else 1)
