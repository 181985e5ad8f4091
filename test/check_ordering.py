#!/usr/bin/python3
"""Checks boltnet's choice of MUMPS's ordering for the interface (-interface_choose_ordering, docs/solver.md).

  check_ordering.py OUTDIR SCENE [--] CMD...

CMD is the driver with its launcher (e.g. mpiexec -n 2 build/bin/boltnet). The reference is MUMPS's
own analysis with each ordering given by the user (-mat_mumps_icntl_7 7, 6 and 2, runs in which
boltnet makes no choice): each gives the flops MUMPS estimates for the interface's factorisation
(-info's "-interface_solve auto" line). The default run must
  - have estimated each candidate at the flops of the user's run with that ordering,
  - pick the cheapest of them, if it is estimated at most 0.9 of MUMPS's own choice (7), else 7,
  - factor with it: its own estimate is the picked run's, and its joints.csv is that run's to 1e-12,
and a run given -mat_mumps_icntl_7 must make no choice.
"""
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CANDIDATES = (7, 6, 2)
TRIAL = re.compile(r"^\[0\] <mat> ChooseOrdering\(\): ICNTL\(7\) = (\d+) \(MUMPS used (\d+)\): the factorisation estimated at (\S+) flops")
PICK = re.compile(r"^\[0\] <mat> ChooseOrdering\(\): the interface's ordering: ICNTL\(7\) = (\d+)")
AUTO = re.compile(r"^\[0\] <mat> ChooseInterfaceSolve\(\): -interface_solve auto: \w+ \(MUMPS estimates (\S+) flops")


def run(cmd, scene, out, extra):
    args = cmd + ["-scene", scene, "-output_dir", out, "-output_fields", "false", "-info", ":mat"] + extra
    p = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        sys.exit(f"FAIL: {' '.join(args)} exited {p.returncode}:\n{p.stdout[-3000:]}")
    lines = p.stdout.splitlines()
    trials = {int(m.group(1)): float(m.group(3)) for m in map(TRIAL.match, lines) if m}
    picks = [int(m.group(1)) for m in map(PICK.match, lines) if m]
    autos = [float(m.group(1)) for m in map(AUTO.match, lines) if m]
    return trials, picks, autos


def same(a, b):
    return abs(a - b) <= 1e-5 * max(abs(a), abs(b))  # both printed with 6 significant digits


def main():
    args = [a for a in sys.argv[1:] if a != "--"]
    if len(args) < 3:
        sys.exit(__doc__)
    outdir, scene, cmd = args[0], args[1], args[2:]
    bad = []
    ref = {}
    for c in CANDIDATES:
        trials, picks, autos = run(cmd, scene, os.path.join(outdir, f"icntl7_{c}"), ["-mat_mumps_icntl_7", str(c)])
        if trials or picks:
            bad.append(f"-mat_mumps_icntl_7 {c}: boltnet still chose an ordering")
        if not autos:
            sys.exit(f"FAIL: -mat_mumps_icntl_7 {c}: no -interface_solve auto line in -info")
        ref[c] = autos[0]
        print(f"-mat_mumps_icntl_7 {c}: MUMPS estimates {ref[c]:.6g} flops")
    trials, picks, autos = run(cmd, scene, os.path.join(outdir, "chosen"), [])
    if sorted(trials) != sorted(CANDIDATES) or len(picks) != 1 or not autos:
        sys.exit(f"FAIL: the default run tried {sorted(trials)} and picked {picks} (one pick of {list(CANDIDATES)} expected)")
    for c in CANDIDATES:
        if not same(trials[c], ref[c]):
            bad.append(f"ICNTL(7) = {c}: the trial estimated {trials[c]:.6g} flops, the user's run {ref[c]:.6g}")
    cheapest = min(CANDIDATES, key=lambda c: (ref[c], CANDIDATES.index(c)))
    best = cheapest if ref[cheapest] <= 0.9 * ref[7] else 7
    print(f"picked ICNTL(7) = {picks[0]}, the cheapest is {cheapest} ({ref[cheapest] / ref[7]:.3f} of MUMPS's own choice): {best} expected; "
          f"the factorisation estimated at {autos[0]:.6g} flops")
    if picks[0] != best:
        bad.append(f"picked {picks[0]}, not {best}")
    if not same(autos[0], ref[best]):
        bad.append(f"the factorisation was estimated at {autos[0]:.6g} flops, not the {ref[best]:.6g} of ICNTL(7) = {best}")
    cmp = subprocess.run([sys.executable, os.path.join(HERE, "compare_csv.py"), os.path.join(outdir, f"icntl7_{best}", "joints.csv"),
                          os.path.join(outdir, "chosen", "joints.csv"), "1e-12"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(cmp.stdout.strip())
    if cmp.returncode != 0:
        bad.append(f"joints.csv differs from the run with -mat_mumps_icntl_7 {best}")
    if bad:
        sys.exit("FAIL: " + "; ".join(bad))
    print("the ordering of least estimated flops is chosen and used")


if __name__ == "__main__":
    main()
