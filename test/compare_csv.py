#!/usr/bin/python3
"""Compares two joints.csv files: same rows, same words, numbers equal to round-off.

Requirement (standards): results do not depend on the number of MPI ranks.
Numbers must agree to rtol relative to the largest magnitude of the quantity (default 1e-10): a
column's scale is the largest value among the columns of the same quantity (du_*, f_*, slip_*), so
a component that is zero up to round-off (du_t2 of a joint loaded along t1) is judged against the
jump, not against its own noise.
Usage: compare_csv.py reference.csv other.csv [rtol]
"""
import csv
import sys


def main():
    a = list(csv.reader(open(sys.argv[1])))
    b = list(csv.reader(open(sys.argv[2])))
    rtol = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-10
    if a[0] != b[0] or len(a) != len(b):
        print(f"different shape: {len(a)} vs {len(b)} lines, header {a[0]} vs {b[0]}")
        return 1
    own = []
    for c in range(len(a[0])):
        try:
            own.append(max(abs(float(r[c])) for r in a[1:]))
        except ValueError:
            own.append(None)
    def family(name):
        return name.split("_")[0] + "_" if "_" in name else name
    scale = []
    for c, name in enumerate(a[0]):
        if own[c] is None:
            scale.append(None)
            continue
        group = [own[k] for k, n in enumerate(a[0]) if own[k] is not None and family(n) == family(name)]
        scale.append(max(group) or 1.0)
    worst = 0.0
    for i, (ra, rb) in enumerate(zip(a[1:], b[1:]), start=2):
        for c, (x, y) in enumerate(zip(ra, rb)):
            if scale[c] is None:
                if x != y:
                    print(f"line {i} column {a[0][c]}: {x} vs {y}")
                    return 1
                continue
            d = abs(float(x) - float(y)) / scale[c]
            worst = max(worst, d)
            if d > rtol:
                print(f"line {i} column {a[0][c]}: {x} vs {y} (relative to column scale {d:.3e})")
                return 1
    print(f"{len(a) - 1} rows agree (worst difference {worst:.2e} of the column scale)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
