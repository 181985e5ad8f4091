#!/usr/bin/python3
"""Compares the results of one load case in two folders: joints.csv and, where written, fields.h5.

Requirement (docs/scenes.md, "Load cases"): a case of a multi-case run, on a set-up shared with other
cases, gives what a run of that case alone gives. The run alone is the reference: it sets its model
up with that case's loads only. Numbers must agree to rtol of their quantity's scale: in joints.csv
the largest magnitude of the column's family (du_*, f_*, slip_*), in fields.h5 the largest magnitude
of the datasets of the same unit over every step (N and Q, M, displacement and jump, stresses, ...);
integers and words exactly. With --scale-from, the scales
are also taken over those folders (the other cases of the run): a quantity a case leaves at zero
(the joint's jump under a pure moment) is judged against the size it has in the run, not against
its own round-off.
Usage: compare_case.py REF_DIR DIR [--rtol 1e-10] [--scale-from DIR]...
"""
import argparse
import csv
import os
import sys

import h5py
import numpy as np


def family(name):
    return name.split("_")[0]


def number(s):
    try:
        return float(s)
    except ValueError:
        return None


def joints_scales(path, scales):
    rows = list(csv.reader(open(path)))
    for c, name in enumerate(rows[0]):
        vals = [number(r[c]) for r in rows[1:]]
        if vals and all(v is not None for v in vals):
            scales[family(name)] = max(scales.get(family(name), 0.0), max(abs(v) for v in vals))


def fields(path):
    out = {}
    if os.path.exists(path):
        h5py.File(path, "r").visititems(lambda name, obj: out.__setitem__(name, np.asarray(obj[()])) if isinstance(obj, h5py.Dataset) else None)
    return out


# The datasets of fields.h5 in families of one unit: a dataset is judged against the largest value
# of its family (the shear Q of a strip in pure bending, round-off, against the membrane forces N).
UNITS = {"N": "force/length", "Q": "force/length", "N_element": "force/length", "Q_element": "force/length",
         "M": "moment/length", "M_element": "moment/length", "displacement": "length", "jump": "length",
         "force": "force", "in_plane_force": "force"}
for face in ("top", "bottom"):
    UNITS.update({f"stress_{face}": "stress", f"principal_{face}": "stress", f"von_mises_{face}": "stress", f"strain_{face}": "strain"})


def unit(name):
    key = name.split("/")[-1]
    return UNITS.get(key, key)


def fields_scales(data, scales):
    for name, v in data.items():
        if np.issubdtype(v.dtype, np.floating) and v.size:
            scales[unit(name)] = max(scales.get(unit(name), 0.0), float(np.abs(v).max()))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("ref")
    ap.add_argument("dir")
    ap.add_argument("--rtol", type=float, default=1e-10)
    ap.add_argument("--scale-from", action="append", default=[])
    a = ap.parse_args()
    js, fs = {}, {}
    for d in [a.ref] + a.scale_from:
        joints_scales(os.path.join(d, "joints.csv"), js)
        fields_scales(fields(os.path.join(d, "fields.h5")), fs)

    ra, rb = list(csv.reader(open(os.path.join(a.ref, "joints.csv")))), list(csv.reader(open(os.path.join(a.dir, "joints.csv"))))
    if ra[0] != rb[0] or len(ra) != len(rb):
        print(f"compare_case: joints.csv: {len(ra)} against {len(rb)} lines, or another header")
        return 1
    worst = 0.0
    for i, (x, y) in enumerate(zip(ra[1:], rb[1:]), start=2):
        for c, name in enumerate(ra[0]):
            u, v = number(x[c]), number(y[c])
            if u is None or v is None:
                if x[c] != y[c]:
                    print(f"compare_case: joints.csv line {i} column {name}: {x[c]} against {y[c]}")
                    return 1
                continue
            d = abs(u - v) / (js.get(family(name)) or 1.0)
            worst = max(worst, d)
            if d > a.rtol:
                print(f"compare_case: joints.csv line {i} column {name}: {x[c]} against {y[c]} ({d:.2e} of the scale {js.get(family(name)):.3e})")
                return 1
    print(f"compare_case: {len(ra) - 1} rows of joints.csv agree (largest difference {worst:.2e} of the scale; rtol {a.rtol:g})")

    fa, fb = fields(os.path.join(a.ref, "fields.h5")), fields(os.path.join(a.dir, "fields.h5"))
    if bool(fa) != bool(fb):
        print("compare_case: fields.h5 is in one folder only")
        return 1
    if not fa:
        print("compare_case: no fields (a scene without shell patches)")
        return 0
    worst, where = 0.0, ""
    for name, v in fa.items():
        w = fb.get(name)
        if w is None or w.shape != v.shape:
            print(f"compare_case: dataset {name} is missing from {a.dir}/fields.h5 or has another shape")
            return 1
        if np.issubdtype(v.dtype, np.floating):
            d = float(np.abs(v - w).max()) / (fs.get(unit(name)) or 1.0) if v.size else 0.0
            if d > worst:
                worst, where = d, name
        elif not np.array_equal(v, w):
            print(f"compare_case: dataset {name} differs")
            return 1
    print(f"compare_case: {len(fa)} datasets of fields.h5 agree (largest difference {worst:.2e} of the dataset's scale{', in ' + where if where else ''}; rtol {a.rtol:g})")
    return 0 if worst <= a.rtol else 1


if __name__ == "__main__":
    sys.exit(main())
