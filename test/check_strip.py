#!/usr/bin/python3
"""The strip of test/scenes/strip.yaml against its exact solution, at every node and every step.

Requirement: shell parts of quadrilaterals, triangles or both, through the whole driver (scene,
layout, cut into patches and seams on several ranks, condensation, solve, recovery of the interior,
fields.h5), reproduce the two states the elements represent exactly. A strip of length L, width w,
thickness t, E and nu = 0, clamped at x = 0, loaded at its free end through a rigid end edge by the
load factor lambda:
  tension, a force F = lambda along x:      ux = F x / (E w t),                 the rest 0
  bending, a moment M = lambda about y:     uz = -M x^2 / (2 E I), ry = M x / (E I),  the rest 0
with I = w t^3 / 12 (beam theory, exact for nu = 0: the strip bends cylindrically, and its
constant curvature and constant strain are the patch tests the elements pass; docs/shell.md). The
sign follows the shell's convention: a rotation ry > 0 turns the x axis towards -z.
Every dof of every node must agree to RTOL of the largest expected value.

usage: check_strip.py DIR tension|bending E w t [RTOL]
"""
import sys

import h5py
import numpy as np


def main():
    out, mode = sys.argv[1], sys.argv[2]
    E, w, t = (float(v) for v in sys.argv[3:6])
    rtol = float(sys.argv[6]) if len(sys.argv) > 6 else 1e-8
    if mode not in ("tension", "bending"):
        sys.exit(f"check_strip.py: mode '{mode}' is neither tension nor bending")
    h5 = h5py.File(out + "/fields.h5", "r")
    x = h5["/shells/coordinates"][:][:, 0]
    EI = E * w * t**3 / 12
    worst, nsteps = 0.0, 0
    for name, g in h5["/steps"].items():
        lam = float(g.attrs["load"])
        u = np.hstack([g["shells/displacement"][:], g["shells/rotation"][:]])
        want = np.zeros_like(u)
        if mode == "tension":
            want[:, 0] = lam * x / (E * w * t)
        else:
            want[:, 2] = -lam * x**2 / (2 * EI)
            want[:, 4] = lam * x / EI
        scale = np.abs(want).max()
        err = np.abs(u - want).max() / scale
        worst = max(worst, err)
        nsteps += 1
    print(f"check_strip: {mode}, {len(x)} nodes, {nsteps} steps: largest difference from the exact solution {worst:.2e} of its largest value (rtol {rtol:g})")
    return 0 if nsteps > 0 and worst <= rtol else 1


if __name__ == "__main__":
    sys.exit(main())
