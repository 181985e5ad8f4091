#!/usr/bin/python3
"""Element results in fields.h5 against the closed forms of a cantilever strip (docs/output.md).

  check_stresses.py DIR --length L --width W --thickness T [--fz FZ] [--fx FX] [--my MY] [--rtol R]

test/scenes/strip-cantilever.yaml (and strip.yaml): a strip clamped at x = 0, loaded at x = L by FX
along x, FZ along z and a moment MY about y (times each step's load factor). With nu = 0 beam theory
is exact for it: at every element
centroid x_c, in the material frame (global here) and in the element frame (where it is the global one:
every quadrilateral of this mesh, the triangles whose first side runs along x),
  N_xx = FX / W,  M_xx = (MY - FZ (L - x_c)) / W (M = D kappa, kappa = d theta_y / dx),
  Q_xz = FZ / W,  sigma_xx top/bottom = N_xx / T +- 6 M_xx / T^2, every other component 0.
The solve is exact up to round-off: R (default 1e-8) of each quantity's scale. Quadrilaterals
represent all of it exactly; triangles (MITC3+, linear membrane) the constant N and M of tension and
pure bending only.
"""
import argparse
import sys

import h5py
import numpy as np


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    for k in ("length", "width", "thickness"):
        ap.add_argument("--" + k, type=float, required=True)
    for k in ("fz", "fx", "my"):
        ap.add_argument("--" + k, type=float, default=0.0)
    ap.add_argument("--rtol", type=float, default=1e-8)
    a = ap.parse_args()
    h5 = h5py.File(f"{a.dir}/fields.h5", "r")
    x, cells = h5["/shells/coordinates"][:], h5["/shells/cells"][:]
    valid = cells >= 0  # a triangle's fourth slot is -1
    xc = (x[np.where(valid, cells, 0), 0] * valid).sum(axis=1) / valid.sum(axis=1)
    # The element frame is the global one where the element's x axis is (a triangle's runs along its
    # first side): the element-frame results are compared there.
    along = np.abs(h5["/shells/element_axis"][:, 0] - 1) < 1e-12
    fails, worst, nsteps = [], 0.0, 0
    for name, g in h5["steps"].items():
        lam = float(np.ravel(g.attrs["load"])[0])
        s = g["shells"]
        N, M = a.fx * lam / a.width, (a.my - a.fz * (a.length - xc)) * lam / a.width
        Q, Mmax = a.fz * lam / a.width, (abs(a.my) + abs(a.fz) * a.length) * abs(lam) / a.width
        sig = lambda sign: N / a.thickness + sign * 6 * M / a.thickness**2
        smax = abs(N) / a.thickness + 6 * Mmax / a.thickness**2
        zero = np.zeros_like(xc)
        # Each quantity against its own largest value; one the load leaves zero against the stress
        # scale turned into that quantity (N, Q: smax T; M: smax T^2 / 6).
        sN, sQ, sM = (v if v > 0 else r for v, r in ((abs(N), smax * a.thickness), (abs(Q), smax * a.thickness), (Mmax, smax * a.thickness**2 / 6)))
        expect = {
            "N": (np.stack([N + zero, zero, zero], 1), sN),
            "M": (np.stack([M + zero, zero, zero], 1), sM),
            "Q": (np.stack([Q + zero, zero], 1), sQ),
            "stress_top": (np.stack([sig(1), zero, zero], 1), smax),
            "stress_bottom": (np.stack([sig(-1), zero, zero], 1), smax),
        }
        for k, (ref, scale) in list(expect.items()):
            if k in ("N", "M", "Q"):
                expect[k + "_element"] = (ref, scale)
        for k, (ref, scale) in expect.items():
            rows = along if k.endswith("_element") else slice(None)
            d = np.abs(s[k][:][rows] - ref[rows]).max() / scale if len(ref[rows]) else 0.0
            worst = max(worst, d)
            if d > a.rtol:
                fails.append(f"step {name} {k}: differs from the closed form by {d:.3g} of {scale:g}")
        nsteps += 1
    for f in fails:
        print("FAIL:", f)
    print(f"check_stresses: {len(xc)} elements, {nsteps} steps: N, M, Q and surface stresses against the cantilever's closed forms, largest difference {worst:.2g} of the scale")
    print("check_stresses: PASS" if not fails and nsteps else "check_stresses: FAIL")
    return 1 if fails or not nsteps else 0


if __name__ == "__main__":
    sys.exit(main())
