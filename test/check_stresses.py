#!/usr/bin/python3
"""Element results in fields.h5 against the closed forms of a cantilever strip (docs/output.md).

  check_stresses.py DIR --length L --width W --thickness T --fz FZ --fx FX

test/scenes/strip-cantilever.yaml: a strip clamped at x = 0, loaded at x = L by FX along x and FZ
along z (times each step's load factor). With nu = 0 beam theory is exact for it: at every element
centroid x_c, in the material frame (global here) and in the element frame (the same for this mesh),
  N_xx = FX / W,  M_xx = -FZ (L - x_c) / W (hogging: M = D kappa, kappa = d theta_y / dx),
  Q_xz = FZ / W,  sigma_xx top/bottom = N_xx / T +- 6 M_xx / T^2, every other component 0.
The solve is exact up to round-off: 1e-8 of each quantity's scale.
"""
import argparse
import sys

import h5py
import numpy as np


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    for k in ("length", "width", "thickness", "fz", "fx"):
        ap.add_argument("--" + k, type=float, required=True)
    a = ap.parse_args()
    h5 = h5py.File(f"{a.dir}/fields.h5", "r")
    x, cells = h5["/shells/coordinates"][:], h5["/shells/cells"][:]
    xc = x[cells].mean(axis=1)[:, 0]
    fails, worst, nsteps = [], 0.0, 0
    for name, g in h5["steps"].items():
        lam = float(np.ravel(g.attrs["load"])[0])
        s = g["shells"]
        N, M = a.fx * lam / a.width, -a.fz * lam * (a.length - xc) / a.width
        Q, Mmax = a.fz * lam / a.width, a.fz * lam * a.length / a.width
        sig = lambda sign: N / a.thickness + sign * 6 * M / a.thickness**2
        smax = abs(N) / a.thickness + 6 * Mmax / a.thickness**2
        zero = np.zeros_like(xc)
        expect = {
            "N": (np.stack([N + zero, zero, zero], 1), abs(N)),
            "M": (np.stack([M, zero, zero], 1), Mmax),
            "Q": (np.stack([Q + zero, zero], 1), abs(Q)),
            "stress_top": (np.stack([sig(1), zero, zero], 1), smax),
            "stress_bottom": (np.stack([sig(-1), zero, zero], 1), smax),
        }
        for k, (ref, scale) in list(expect.items()):
            if k in ("N", "M", "Q"):
                expect[k + "_element"] = (ref, scale)
        for k, (ref, scale) in expect.items():
            d = np.abs(s[k][:] - ref).max() / scale
            worst = max(worst, d)
            if d > 1e-8:
                fails.append(f"step {name} {k}: differs from the closed form by {d:.3g} of {scale:g}")
        nsteps += 1
    for f in fails:
        print("FAIL:", f)
    print(f"check_stresses: {len(xc)} elements, {nsteps} steps: N, M, Q and surface stresses against the cantilever's closed forms, largest difference {worst:.2g} of the scale")
    print("check_stresses: PASS" if not fails and nsteps else "check_stresses: FAIL")
    return 1 if fails or not nsteps else 0


if __name__ == "__main__":
    sys.exit(main())
