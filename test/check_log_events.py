#!/usr/bin/python3
"""Checks how many times PETSc log events ran, from a -log_view file (ascii, the default format).

  check_log_events.py LOG NAME=N ... NAME+ ...

NAME=N: the event ran exactly N times on the rank that ran it most (the "Count Max" column; an
event that never ran may be left out of the table: count 0). NAME+: it ran at least once.
Used to check that a code path is or is not taken (test/joint_table_tests.cmake).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from log_view import largest_counts  # noqa: E402


def main():
    c = largest_counts(sys.argv[1], "Boltnet")
    bad = []
    for spec in sys.argv[2:]:
        if spec.endswith("+"):
            name = spec[:-1]
            if c.get(name, 0) < 1:
                bad.append(f"{name} never ran")
        else:
            name, n = spec.split("=")
            if c.get(name, 0) != int(n):
                bad.append(f"{name} ran {c.get(name, 0)} times, expected {n}")
    for b in bad:
        print(f"check_log_events: FAIL: {b}")
    if not bad:
        print("check_log_events: " + ", ".join(f"{k} {v}" for k, v in sorted(c.items()) if any(s.split("=")[0].rstrip("+") == k for s in sys.argv[2:])))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
