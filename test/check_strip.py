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
With --held MODE=VALUE (a load case that continues another, docs/scenes.md "Held loads"), that
load's state at the load factor VALUE is added at every step: the elements are linear, so the
exact solution of two loads is the sum of theirs. The differences are then judged against the
largest expected value over the case, not the step's: where the path's load is back at 0, what is
left is the held load's state, and the round-off of unloading the path's (which can be hundreds of
times larger) shows against it.

usage: check_strip.py DIR tension|bending|inplane E w t [RTOL] [--held MODE=VALUE]
"""
import sys

import h5py
import numpy as np


def exact(mode, lam, x, y, E, w, t, shape):
    """Every node's six dof under one load at load factor lam."""
    EI = E * w * t**3 / 12
    EIz = E * t * w**3 / 12
    want = np.zeros(shape)
    if mode == "tension":
        want[:, 0] = lam * x / (E * w * t)
    elif mode == "bending":
        want[:, 2] = -lam * x**2 / (2 * EI)
        want[:, 4] = lam * x / EI
    else:
        want[:, 0] = -lam * x * (y - w / 2) / EIz
        want[:, 1] = lam * x**2 / (2 * EIz)
        want[:, 5] = lam * x / EIz
    return want


def main():
    argv = sys.argv[1:]
    held = None
    if "--held" in argv:
        i = argv.index("--held")
        hmode, _, hval = argv[i + 1].partition("=")
        held = (hmode, float(hval))
        del argv[i:i + 2]
    out, mode = argv[0], argv[1]
    E, w, t = (float(v) for v in argv[2:5])
    rtol = float(argv[5]) if len(argv) > 5 else 1e-8
    for m in (mode,) + ((held[0],) if held else ()):
        if m not in ("tension", "bending", "inplane"):
            sys.exit(f"check_strip.py: mode '{m}' is none of tension, bending, inplane")
    h5 = h5py.File(out + "/fields.h5", "r")
    x = h5["/shells/coordinates"][:][:, 0]
    y = h5["/shells/coordinates"][:][:, 1]
    worst, nsteps, steps = 0.0, 0, []
    for name, g in h5["/steps"].items():
        lam = float(g.attrs["load"])
        u = np.hstack([g["shells/displacement"][:], g["shells/rotation"][:]])
        want = exact(mode, lam, x, y, E, w, t, u.shape)
        if held:
            want += exact(held[0], held[1], x, y, E, w, t, u.shape)
        steps.append((u, want))
    case_scale = max(np.abs(want).max() for _, want in steps) if steps else 0.0
    for u, want in steps:
        scale = case_scale if held else np.abs(want).max()
        worst = max(worst, np.abs(u - want).max() / scale)
        nsteps += 1
    print(f"check_strip: {mode}{f' with {held[0]} {held[1]:g} held' if held else ''}, {len(x)} nodes, {nsteps} steps: largest difference from the exact solution {worst:.2e} of its largest value (rtol {rtol:g})")
    return 0 if nsteps > 0 and worst <= rtol else 1


if __name__ == "__main__":
    sys.exit(main())
