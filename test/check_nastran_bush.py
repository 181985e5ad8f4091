#!/usr/bin/python3
"""The lap of scripts/make-nastran-strips (lap-bush45.bdf) against its closed form.

Requirement: a CBUSH keeps its whole stiffness (its element axes turned 45 degrees in the plane,
K2 != K3: neither k2 nor k3 along the load, nor their mean), and its spring sits at S = 0.5 of GA-GB
with a rigid lever from each grid (Nastran's CBUSH), or at the grids without lever
(-nastran_bush_offsets false).

Strip A (x in [0, 60], z = 0) is clamped at x = 0; strip B (x in [40, 100], z = L = t) carries
F along x at its end x = 100 (consistent nodal forces); a row of bushes joins them at x = a = 50,
the edge bushes half as stiff, so that with nu = 0 every strip is in a one-dimensional state
(constant strain, constant curvature, rigid motions) that the elements represent exactly, and the
row acts as four whole bushes in parallel.

The bush: element x = GA -> GB = z, y = (1, 1, 0)/sqrt2 (X = (1, 1, 0)), z = (-1, 1, 0)/sqrt2, so
its in-plane compliance (translations) is C = sum a_i a_i^T / k_i:
    C_xx = (1/k2 + 1/k3) / 2,   C_yx = (1/k2 - 1/k3) / 2.
B is free in y, so the row's jump is C F / 4 (no y force): along x (1/k2 + 1/k3) F / 8, and B
moves rigidly in y by C_yx F / 4.

Without lever: A carries F (no bending), B carries F from the row to its end:
    ux(B end) = F (a + b) / (E w t) + C_xx F / 4,  uy = C_yx F / 4,  uz = 0    (b = 50).
With the lever (spring at z = L/2): the spring pulls B back by -F at L/2, a moment F L/2 about
y on B's node, which B (its end force on its own mid-surface) cannot carry: the rotational spring
takes it, exerting -kr dtheta on B, so dtheta_y = theta_B - theta_A = F L / (2 * 4 kr); A's node
receives F at L/2 (the moment F L/2) and kr dtheta = F L/2 from the rotational spring, M = F L
(the couple of F at B's mid-surface about A's, as the clamp sees it): A bends, theta_A = M a / EI, w_A = -M a^2 / (2 EI) (EI = E w t^3/12,
the shell's convention: ry > 0 turns x towards -z). The spring point moves with each node,
u_x + theta_y dz, so
    ux(B end) = F (a + b) / (E w t) + (L/2) (2 theta_A + dtheta) + C_xx F / 4,
    uy = C_yx F / 4,  uz(B end) = w_A - (theta_A + dtheta) b.
Every node of B's end (x = 100) must agree to RTOL of |ux|.

usage: check_nastran_bush.py DIR lever|nolever [RTOL]
"""
import sys

import h5py
import numpy as np

E, t, w, a, b, F = 72000.0, 2.0, 20.0, 50.0, 50.0, 1000.0
k2, k3, kr = 5000.0, 500.0, 1e6


def main():
    out, mode = sys.argv[1], sys.argv[2]
    rtol = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-8
    if mode not in ("lever", "nolever"):
        sys.exit(f"check_nastran_bush.py: mode '{mode}' is neither lever nor nolever")
    L = t
    cxx, cyx = (1 / k2 + 1 / k3) / 2, (1 / k2 - 1 / k3) / 2
    ux = F * (a + b) / (E * w * t) + cxx * F / 4
    uy = cyx * F / 4
    uz = 0.0
    if mode == "lever":
        EI = E * w * t**3 / 12
        M = F * L
        theta_a = M * a / EI
        dtheta = F * L / (2 * 4 * kr)
        ux += L / 2 * (2 * theta_a + dtheta)
        uz = -M * a**2 / (2 * EI) - (theta_a + dtheta) * b
    h5 = h5py.File(out + "/fields.h5", "r")
    x = h5["/shells/coordinates"][:]
    g = h5["/steps/" + sorted(h5["/steps"].keys())[-1]]
    u = g["shells/displacement"][:]
    end = (np.abs(x[:, 0] - 100) < 1e-9) & (np.abs(x[:, 2] - t) < 1e-9)
    if end.sum() != 5:
        sys.exit(f"check_nastran_bush.py: {end.sum()} nodes at B's end (x = 100), expected 5")
    want = np.array([ux, uy, uz])
    err = np.abs(u[end] - want).max() / abs(ux)
    print(f"B's end: boltnet {u[end].mean(axis=0)}, closed form {want}; largest difference {err:.2e} of |ux| (rtol {rtol:g})")
    print(f"  (an isotropic kt = (k2 + k3)/2 would give ux {F * (a + b) / (E * w * t) + F / (4 * (k2 + k3) / 2):.6g} without lever)")
    sys.exit(0 if err <= rtol else 1)


if __name__ == "__main__":
    main()
