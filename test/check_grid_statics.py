#!/usr/bin/env python3
"""Statics of a plate grid (scripts/make-plate-grid): cut the grid between two columns of plates;
the plates to the right of the cut are held in x only by the fasteners that join the two columns,
and loaded by the right column's pull, FORCE x load on each of its NY plates. So at every step of
joints.csv and at every cut, the x-forces of the fasteners crossing it (f_t1: the generator puts t1
along x) sum to NY x FORCE x load. Asserts that to RTOL of the largest such total over the steps.

usage: check_grid_statics.py joints.csv grid.joints.csv NX NY FORCE RTOL
"""
import csv
import sys


def main():
    path, table, nx, ny, force, rtol = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), float(sys.argv[5]), float(sys.argv[6])
    crossing = {}  # fastener id -> the column to the left of the cut it crosses
    for r in csv.DictReader(open(table)):
        a, b = int(r["patch_a"]), int(r["patch_b"])
        if (float(r["t1x"]), float(r["t1y"]), float(r["t1z"])) != (1.0, 0.0, 0.0):
            sys.exit(f"{table}: fastener {r['id']} has t1 = ({r['t1x']}, {r['t1y']}, {r['t1z']}), not x")
        if b == a + 1 and a // nx == b // nx:  # neighbours in a row: the fastener crosses the cut right of column a % nx
            crossing[r["id"]] = a % nx
    if len({c for c in crossing.values()}) != nx - 1:
        sys.exit(f"{table}: fasteners cross {len(set(crossing.values()))} cuts between columns, not NX - 1 = {nx - 1}")
    sums, loads = {}, {}
    for r in csv.DictReader(open(path)):
        if r["joint"] not in crossing:
            continue
        key = (int(r["step"]), crossing[r["joint"]])
        sums[key] = sums.get(key, 0.0) + float(r["f_t1"])
        loads[int(r["step"])] = float(r["load"])
    if not loads:
        sys.exit(f"{path}: no step")
    scale = max(abs(ny * force * load) for load in loads.values())
    if scale == 0:
        sys.exit(f"{path}: every step is at load 0")
    worst = max(abs(total - ny * force * loads[step]) for (step, cut), total in sums.items()) / scale
    print(f"{path}: x-forces across the {nx - 1} cuts at {len(loads)} steps against NY x FORCE x load: worst difference {worst:.2e} of the largest total (rtol {rtol:g})")
    sys.exit(0 if worst <= rtol else 1)


if __name__ == "__main__":
    main()
