#!/usr/bin/python3
"""Checks an open tube under internal pressure (test/make_tube_scene.py) against the membrane closed form.

A thin open cylinder (radius R, thickness t) under internal pressure p with free ends carries the
hoop stress pR/t and no axial stress: its radial displacement is w = p R^2 / (E t), its axial strain
-nu p R / (E t). The sensor joint at (L/2, R, 0), along y, has du_n = -w and du_t1 = -u_x(L/2), with
u_x = 0 at x = 0. The tube is faceted (48 flat quadrangles around): measured 0.21 % below the closed
form, which the tolerance given by the caller bounds.
Usage: check_tube_pressure.py joints.csv --R R --L L --t T --E E --nu NU --p P --rtol RTOL
"""
import argparse
import csv
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("joints")
    for name in ("R", "L", "t", "E", "nu", "p", "rtol"):
        ap.add_argument("--" + name, type=float, required=True)
    a = ap.parse_args()
    with open(a.joints, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["joint"] == "0"]
    if not rows:
        sys.exit(f"check_tube_pressure: {a.joints} has no row of joint 0")
    lam = float(rows[-1]["load"])
    w, ux = -float(rows[-1]["du_n"]), -float(rows[-1]["du_t1"])
    w_ref = lam * a.p * a.R**2 / (a.E * a.t)
    ux_ref = -a.nu * lam * a.p * a.R / (a.E * a.t) * a.L / 2
    ew, ex = abs(w - w_ref) / abs(w_ref), abs(ux - ux_ref) / abs(ux_ref)
    print(f"check_tube_pressure: radial displacement {w:.6g} mm (closed form {w_ref:.6g}, error {ew:.2e}); "
          f"axial at L/2 {ux:.6g} mm (closed form {ux_ref:.6g}, error {ex:.2e}); tolerance {a.rtol:g}")
    if not (ew <= a.rtol and ex <= a.rtol):
        sys.exit(1)


if __name__ == "__main__":
    main()
