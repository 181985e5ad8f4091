#!/usr/bin/python3
"""The strip of test/scenes/strip.yaml against its exact solution, at every node and every step.

Requirement: shell parts of quadrilaterals, triangles or both, through the whole driver (scene,
layout, cut into patches and seams on several ranks, condensation, solve, recovery of the interior,
fields.h5), reproduce the two states the elements represent exactly. A strip of length L, width w,
thickness t, E and nu = 0, clamped at x = 0, loaded at its free end through a rigid end edge by the
load factor lambda:
  tension, a force F = lambda along x:      ux = F x / (E w t),                 the rest 0
  bending, a moment M = lambda about y:     uz = -M x^2 / (2 E I), ry = M x / (E I),  the rest 0
  inplane, a moment M = lambda about z:     uy = M x^2 / (2 E Iz), rz = M x / (E Iz),
                                            ux = -M x (y - w/2) / (E Iz),  the rest 0
with I = w t^3 / 12 and Iz = t w^3 / 12 (beam theory, exact for nu = 0: the strip bends
cylindrically, or in its plane with a linear stress across the width). Constant curvature and
constant strain are patch tests the elements pass exactly; in-plane bending they reproduce to their
discretization error only (the membrane's drilling penalty, docs/shell.md), so inplane needs an RTOL
that the caller justifies. The sign follows the shell's convention: a rotation ry > 0 turns the x
axis towards -z; rz > 0 turns x towards y.
Every dof of every node must agree to RTOL of the largest expected value.

usage: check_strip.py DIR tension|bending|inplane E w t [RTOL]
"""
import sys

import h5py
import numpy as np


def main():
    out, mode = sys.argv[1], sys.argv[2]
    E, w, t = (float(v) for v in sys.argv[3:6])
    rtol = float(sys.argv[6]) if len(sys.argv) > 6 else 1e-8
    if mode not in ("tension", "bending", "inplane"):
        sys.exit(f"check_strip.py: mode '{mode}' is none of tension, bending, inplane")
    h5 = h5py.File(out + "/fields.h5", "r")
    x = h5["/shells/coordinates"][:][:, 0]
    y = h5["/shells/coordinates"][:][:, 1]
    EI = E * w * t**3 / 12
    EIz = E * t * w**3 / 12
    worst, nsteps = 0.0, 0
    for name, g in h5["/steps"].items():
        lam = float(g.attrs["load"])
        u = np.hstack([g["shells/displacement"][:], g["shells/rotation"][:]])
        want = np.zeros_like(u)
        if mode == "tension":
            want[:, 0] = lam * x / (E * w * t)
        elif mode == "bending":
            want[:, 2] = -lam * x**2 / (2 * EI)
            want[:, 4] = lam * x / EI
        else:
            want[:, 0] = -lam * x * (y - w / 2) / EIz
            want[:, 1] = lam * x**2 / (2 * EIz)
            want[:, 5] = lam * x / EIz
        scale = np.abs(want).max()
        err = np.abs(u - want).max() / scale
        worst = max(worst, err)
        nsteps += 1
    print(f"check_strip: {mode}, {len(x)} nodes, {nsteps} steps: largest difference from the exact solution {worst:.2e} of its largest value (rtol {rtol:g})")
    return 0 if nsteps > 0 and worst <= rtol else 1


if __name__ == "__main__":
    sys.exit(main())
