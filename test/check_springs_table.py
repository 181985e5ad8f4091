#!/usr/bin/python3
"""springs.csv of scripts/plot-junction.py (docs/wing-fuselage.md, "What the linear springs answer").

  check_springs_table.py SPRINGS_CSV [--same]

- every splice has a row per level with its whole load, a share per row that sums to 1, its most
  loaded fastener at least the mean and the counts of sticking, sliding and bearing fasteners;
- --same: the run was compared with itself (a linear-spring run as both RESULTS and --compare), so
  each column of the frictional side must equal the linear side's: total ratio 1, the same shares,
  maxima and neighbour differences, and every fastener's load over its spring's 1, to 1e-9 (the
  table's two sides are computed from the run's rows and from the compared run's forces scaled by
  the level, by different code).
"""
import csv
import math
import sys


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    same = "--same" in sys.argv[2:]
    rows = list(csv.DictReader(open(sys.argv[1])))
    fails = []
    close = lambda x, y: abs(float(x) - float(y)) <= 1e-9 * max(1.0, abs(float(y)))
    for r in rows:
        where = f"{r['splice']} at {r['level']} g"
        if float(r["total_linear"]) > 0:
            shares = [float(v) for v in r["shares_frictional"].split("/")]
            if abs(sum(shares) - 1) > 2e-3 * len(shares):
                fails.append(f"{where}: shares {r['shares_frictional']} do not sum to 1")
            n = sum(int(r[k]) for k in ("stick_frictional", "slide_frictional", "bearing_frictional"))
            if n < 1 or float(r["max_frictional"]) * n < float(r["total_frictional"]) * (1 - 1e-9):
                fails.append(f"{where}: {n} fasteners, the most loaded {r['max_frictional']} below the mean of {r['total_frictional']}")
        if same and float(r["total_linear"]) > 0:
            for k in ("total_ratio", "ratio_min", "ratio_max"):
                if not close(r[k], 1):
                    fails.append(f"{where}: {k} {r[k]}, the run against itself")
            for f, l in (("total_frictional", "total_linear"), ("max_frictional", "max_linear"), ("neighbours_frictional", "neighbours_linear")):
                if not (math.isnan(float(r[f])) and math.isnan(float(r[l]))) and not close(r[f], r[l]):
                    fails.append(f"{where}: {f} {r[f]} against {l} {r[l]}")
            if r["shares_frictional"] != r["shares_linear"]:
                fails.append(f"{where}: shares {r['shares_frictional']} against {r['shares_linear']}")
    for f in fails:
        print("FAIL:", f)
    print(f"check_springs_table: {len(rows)} rows" + (", the run against itself" if same else ""))
    print("check_springs_table: PASS" if rows and not fails else "check_springs_table: FAIL")
    return 0 if rows and not fails else 1


if __name__ == "__main__":
    sys.exit(main())
