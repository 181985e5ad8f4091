#!/usr/bin/python3
"""A held load against superposition (docs/scenes.md, "Held loads").

Requirement: a case that continues another keeps that case's loads applied at their final values
while its own follow its path. For a linear model (every joint a linear spring) the independent
reference is superposition: at each step k of the continuing case, every joint's jump and force are
those of its own loads alone at step k (a case from the unloaded state with the same path) plus
those of the held case at its last step.
Usage: check_superposition.py HELD/joints.csv ALONE/joints.csv BEFORE/joints.csv RTOL
  HELD: the continuing case; ALONE: its loads from the unloaded state; BEFORE: the case it continues.
Each quantity is judged against its largest magnitude in HELD.
"""
import csv
import sys

Q = ["du_n", "du_t1", "du_t2", "f_n", "f_t1", "f_t2"]


def read(path):
    rows = list(csv.DictReader(open(path)))
    if not rows:
        sys.exit(f"check_superposition: {path} has no rows")
    return rows


def main():
    held, alone, before = (read(p) for p in sys.argv[1:4])
    rtol = float(sys.argv[4])
    last = max(int(r["step"]) for r in before)
    base = {r["joint"]: r for r in before if int(r["step"]) == last}
    ref = {(r["step"], r["joint"]): r for r in alone}
    scale = {q: max(abs(float(r[q])) for r in held) or 1.0 for q in Q}
    worst, where = 0.0, ""
    for r in held:
        a = ref.get((r["step"], r["joint"]))
        if a is None or r["joint"] not in base:
            sys.exit(f"check_superposition: step {r['step']} joint {r['joint']} is missing from the references")
        if float(a["load"]) != float(r["load"]):
            sys.exit(f"check_superposition: step {r['step']}: load {r['load']} here, {a['load']} alone: not the same path")
        for q in Q:
            err = abs(float(r[q]) - float(a[q]) - float(base[r["joint"]][q])) / scale[q]
            if err > worst:
                worst, where = err, f"step {r['step']} joint {r['joint']} {q}"
    print(f"check_superposition: {len(held)} rows; largest departure from the sum {worst:.2e} of each quantity's largest ({where}); rtol {rtol:g}")
    return 0 if worst <= rtol else 1


if __name__ == "__main__":
    sys.exit(main())
