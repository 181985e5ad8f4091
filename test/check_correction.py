#!/usr/bin/python3
"""The shell correction of the fastener formula (docs/identify.md, "Stiffness already
in the shells").

  check_correction.py coupon IDENTIFY
      The coupon compliance C_c from boltnet-identify (Huth, riveted lap of docs/coupling.md, exact
      coupling) at h = 4, 2, 1 mm: finite, small against 1/kf (|C_c kf| < 0.1), positive on these meshes,
      and converging as h decreases (each refinement changes it less than the one before).
  check_correction.py scene BOLTNET IDENTIFY WORKDIR H TOL
      The flat 1-row lap of scripts/study-correction (150 mm sheets, longer than the 80 mm coupon) on
      an H mm mesh with the corrected rivet: the stiffness the structure sees, 1/(delta/F - C_b), equals
      the formula's kf within TOL (relative); and at H = 2 (the same 2 x 2 mm elements) the scene's C_c
      in summary.json equals the one boltnet-identify prints for -fastener_shell_h 2 (1e-6).
"""
import importlib.machinery
import importlib.util
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
loader = importlib.machinery.SourceFileLoader("study_correction", os.path.join(ROOT, "scripts", "study-correction"))
spec = importlib.util.spec_from_loader("study_correction", loader)
study = importlib.util.module_from_spec(spec)
loader.exec_module(study)

GEOM = sum(([f"-fastener_{k}", str(v)] for k, v in study.FASTENER.items()), [])


def coupon(identify, h):
    out = subprocess.run([identify] + GEOM + ["-fastener_shell_correction", "-fastener_shell_h", str(h)], capture_output=True, text=True)
    print(out.stdout + out.stderr)
    if out.returncode != 0:
        sys.exit(f"boltnet-identify failed at h = {h}")
    cc = float(re.search(r"C_c = ([-0-9.eE+]+)", out.stdout).group(1))
    kf = float(re.search(r"compliance C = [-0-9.eE+]+, kc = 1/C = ([-0-9.eE+]+)", out.stdout).group(1))
    return cc, kf


def main():
    mode = sys.argv[1]
    if mode == "coupon":
        cs = {}
        for h in [4, 2, 1]:
            cs[h], kf = coupon(sys.argv[2], h)
            print(f"h {h}: C_c = {cs[h]:.6e} mm/N = {cs[h] * kf:+.4f} / kf")
        ok = all(abs(c) < 1e300 and c > 0 and abs(c * kf) < 0.1 for c in cs.values())
        ok = ok and abs(cs[1] - cs[2]) < abs(cs[2] - cs[4])
        print("coupon compliance finite, positive, small and converging" if ok else "FAILED")
        sys.exit(0 if ok else 1)
    boltnet, identify, work, h, tol = sys.argv[2], sys.argv[3], sys.argv[4], float(sys.argv[5]), float(sys.argv[6])
    study.BOLTNET = boltnet
    d = os.path.join(work, f"flat-h{sys.argv[5]}")
    study.write_scene(d, h, 0.0)
    F, ident = study.run(d, h, True)
    kf = ident["shell_correction"]["kc_formula"]
    seen = 1 / (study.DELTA / F - study.C_B)
    cc = ident["shell_correction"]["C_c"]
    print(f"h {h}: C_c {cc:.6e} mm/N ({cc * kf:+.4f} / kf), corrected kc {ident['kc']:.2f}, k_seen {seen:.2f} = {seen / kf:.4f} kf (tolerance {tol})")
    ok = abs(seen / kf - 1) <= tol
    if h == 2:
        ci, _ = coupon(identify, 2)
        print(f"boltnet-identify -fastener_shell_h 2: C_c {ci:.9e}; the scene's {cc:.9e}")
        ok = ok and abs(ci - cc) <= 1e-6 * abs(cc)
    print("as expected" if ok else "FAILED")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
