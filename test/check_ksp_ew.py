#!/usr/bin/python3
"""Checks that -snes_ksp_ew (Eisenstat-Walker) set the tolerance of every linear solve of a run.

  check_ksp_ew.py INFO_LOG SUMMARY_JSON RTOL0 [RTOLMAX]
  check_ksp_ew.py INFO_LOG SUMMARY_JSON none

With "none": the run converged and no solve had an Eisenstat-Walker tolerance (summary.json's
ksp_ew false, no line reported), as when -ksp_rtol or -snes_ksp_ew false is given.

INFO_LOG holds rank 0's lines under -info NAME:snes, which PETSc writes to NAME.0 (a file of
its own, where no other rank's output can cut a line in two: info_files.py). PETSc's
KSPPreSolve_SNESEW, the KSP pre-solve hook that SNESGetKSP installs, reports each tolerance it
sets ("iter k, Eisenstat-Walker (version v) KSP rtol=r"). The reference is PETSc's definition of the method
(SNESKSPSetParametersEW): the first solve of each SNESSolve uses rtol_0 (-snes_ksp_ew_rtol0, given
here as RTOL0), and every tolerance lies in (0, rtol_max], RTOLMAX (PETSc's default 0.9 unless given). A KSP whose
hooks were replaced without calling PETSc's would report nothing, and fail here.
"""
import json
import re
import sys


def main():
    log, summary = sys.argv[1], sys.argv[2]
    none = sys.argv[3] == "none"
    rtol0 = None if none else float(sys.argv[3])
    rtolmax = float(sys.argv[4]) if len(sys.argv) > 4 else 0.9
    line = re.compile(r"^\[0\] <snes> KSPPreSolve_SNESEW\(\): iter (\d+), Eisenstat-Walker \(version \d+\) KSP rtol=([0-9.eE+-]+)")
    sets = []
    with open(log) as f:
        for text in f:
            m = line.match(text)
            if m:
                sets.append((int(m.group(1)), float(m.group(2))))
    with open(summary) as f:
        s = json.load(f)
    bad = []
    if s.get("status") != "converged":
        bad.append(f"the run did not converge: {s.get('status')}")
    if s.get("ksp_ew") is not (not none):
        bad.append(f"summary.json's ksp_ew is {s.get('ksp_ew')}")
    if none:
        if sets:
            bad.append(f"{len(sets)} Eisenstat-Walker tolerances where none was expected")
        if bad:
            sys.exit("FAIL: " + "; ".join(bad))
        print(f"{s.get('linear_solves')} linear solves, none with an Eisenstat-Walker tolerance")
        return
    solves = s.get("linear_solves", 0)
    if len(sets) != solves or solves == 0:
        bad.append(f"{len(sets)} Eisenstat-Walker tolerances for {solves} linear solves")
    firsts = [r for it, r in sets if it == 0]
    if not firsts:
        bad.append("no first iteration's tolerance")
    if any(abs(r - rtol0) > 1e-12 * rtol0 for r in firsts):
        bad.append(f"first iterations' tolerances {sorted(set(firsts))}, expected -snes_ksp_ew_rtol0 {rtol0}")
    if any(not (0 < r <= rtolmax * (1 + 1e-12)) for _, r in sets):
        bad.append(f"a tolerance outside (0, {rtolmax}]: {max(r for _, r in sets)}")
    if bad:
        sys.exit("FAIL: " + "; ".join(bad))
    print(f"{len(sets)} linear solves, each with its Eisenstat-Walker tolerance ({min(r for _, r in sets):.3g} to {max(r for _, r in sets):.3g}); {len(firsts)} first iterations at {rtol0}")


if __name__ == "__main__":
    main()
