#!/usr/bin/python3
"""Checks that boltnet's BoltnetInterfaceSolve event holds each Newton iteration's whole linear solve.

  check_interface_event.py LOG_VIEW_FILE

Reads the event tables of a -log_view file (every stage's, summed; the time column is the largest
over the ranks) and checks the event against PETSc's own events, which are the reference: it is
begun by KSP's pre-solve hook, which KSPSolve calls before KSPSetUp, and ended by the post-solve
hook, so that it counts one call per KSPSolve and its time covers the factorisation (PCSetUp, of
which MatLUFactorNum is the numeric part) as well as the solve itself (PETSc's KSPSolve event,
which begins after KSPSetUp). A hook that missed the factorisation or a call would fail here.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from log_view import summed  # noqa: E402


def main():
    ev = summed(sys.argv[1])
    bad = []
    for name in ("BoltnetInterfaceSolve", "KSPSolve", "PCSetUp", "MatLUFactorNum"):
        if name not in ev:
            bad.append(f"no {name} in the event tables")
    if bad:
        sys.exit("FAIL: " + "; ".join(bad))
    isv, ksp, pcs, lu = ev["BoltnetInterfaceSolve"], ev["KSPSolve"], ev["PCSetUp"], ev["MatLUFactorNum"]
    print(f"BoltnetInterfaceSolve {isv[0]} calls {isv[1]:.4g} s; KSPSolve {ksp[0]} calls {ksp[1]:.4g} s; "
          f"PCSetUp {pcs[0]} calls {pcs[1]:.4g} s; MatLUFactorNum {lu[0]} calls {lu[1]:.4g} s")
    if isv[0] != ksp[0] or isv[0] == 0:
        bad.append(f"{isv[0]} interface solves against {ksp[0]} KSPSolve calls")
    # The event encloses PCSetUp and PETSc's KSPSolve, which do not overlap: its time is at least
    # their sum, but for the timers' resolution (1 ms in all).
    if isv[1] < pcs[1] + ksp[1] - 1e-3:
        bad.append(f"the interface solve took {isv[1]:.4g} s, less than PCSetUp and KSPSolve together ({pcs[1] + ksp[1]:.4g} s): the factorisation is not inside it")
    if bad:
        sys.exit("FAIL: " + "; ".join(bad))
    print("the interface solve's event holds every linear solve and its factorisation")


if __name__ == "__main__":
    main()
