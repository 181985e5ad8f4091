#!/usr/bin/python3
"""Two runs' nodal displacements and rotations (fields.h5) against each other, step by step.

    compare_nodal_fields.py DIR_A DIR_B RTOL

Nodes are matched by their coordinates (the order of the nodes depends on the number of ranks and on
the parts), and every component of every node must agree to RTOL of the largest value of the step.
Used where a run has an independent reference run: the same model by another route (an RBE3 against
the forces it stands for) or on another number of ranks.
"""
import sys

import h5py
import numpy as np


def load(d):
    h5 = h5py.File(d + "/fields.h5", "r")
    x = h5["/shells/coordinates"][:]
    order = np.lexsort((x[:, 2].round(9), x[:, 1].round(9), x[:, 0].round(9)))
    steps = {}
    for name, g in h5["/steps"].items():
        steps[name] = np.hstack([g["shells/displacement"][:], g["shells/rotation"][:]])[order]
    return x[order], steps


def main():
    a, b, rtol = sys.argv[1], sys.argv[2], float(sys.argv[3])
    xa, sa = load(a)
    xb, sb = load(b)
    if xa.shape != xb.shape or np.abs(xa - xb).max() > 1e-9 * max(1.0, np.abs(xa).max()):
        sys.exit(f"compare_nodal_fields: the two runs have different nodes ({len(xa)} and {len(xb)})")
    if sorted(sa) != sorted(sb) or not sa:
        sys.exit(f"compare_nodal_fields: different steps: {sorted(sa)} and {sorted(sb)}")
    worst = 0.0
    for name in sa:
        scale = max(np.abs(sa[name]).max(), np.abs(sb[name]).max())
        worst = max(worst, np.abs(sa[name] - sb[name]).max() / scale)
    print(f"compare_nodal_fields: {len(xa)} nodes, {len(sa)} steps: largest difference {worst:.2e} of the largest value (rtol {rtol:g})")
    return 0 if worst <= rtol else 1


if __name__ == "__main__":
    sys.exit(main())
