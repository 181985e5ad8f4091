#!/usr/bin/python3
"""Compares the results of one load case in two folders: joints.csv and, where written, fields.h5.

Requirement (docs/scenes.md, "Load cases"): a case of a multi-case run, on a set-up shared with other
cases, gives what a run of that case alone gives. joints.csv goes through compare_csv.py (numbers to
rtol of each quantity's scale); in fields.h5 every dataset of REF must be in DIR with the same shape,
integer datasets equal, real ones equal to rtol of the largest magnitude that dataset's name takes
over every step (a displacement judged against the displacements). The run alone is the reference:
it sets its model up with that case's loads only.
Usage: compare_case.py REF_DIR DIR [rtol (default 1e-10)]
"""
import os
import subprocess
import sys

import h5py
import numpy as np


def datasets(h5):
    out = {}
    h5.visititems(lambda name, obj: out.__setitem__(name, obj[()]) if isinstance(obj, h5py.Dataset) else None)
    return out


def main():
    ref, other = sys.argv[1], sys.argv[2]
    rtol = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-10
    here = os.path.dirname(os.path.abspath(__file__))
    r = subprocess.run([sys.executable, os.path.join(here, "compare_csv.py"), os.path.join(ref, "joints.csv"), os.path.join(other, "joints.csv"), str(rtol)])
    if r.returncode != 0:
        return 1
    fr, fo = os.path.join(ref, "fields.h5"), os.path.join(other, "fields.h5")
    if not os.path.exists(fr):
        if os.path.exists(fo):
            print(f"compare_case: {fo} exists but {fr} does not")
            return 1
        print("compare_case: no fields (a scene without shell patches)")
        return 0
    a, b = datasets(h5py.File(fr, "r")), datasets(h5py.File(fo, "r"))
    scale = {}
    for name, v in a.items():
        if np.issubdtype(np.asarray(v).dtype, np.floating) and np.size(v):
            key = name.split("/")[-1]
            scale[key] = max(scale.get(key, 0.0), float(np.abs(v).max()))
    worst, where = 0.0, ""
    for name, v in a.items():
        if name not in b or np.shape(b[name]) != np.shape(v):
            print(f"compare_case: dataset {name} of {fr} is missing from {fo} or has another shape")
            return 1
        v, w = np.asarray(v), np.asarray(b[name])
        if np.issubdtype(v.dtype, np.floating):
            d = float(np.abs(v - w).max()) / (scale[name.split("/")[-1]] or 1.0) if v.size else 0.0
            if d > worst:
                worst, where = d, name
        elif not np.array_equal(v, w):
            print(f"compare_case: dataset {name} differs")
            return 1
    print(f"compare_case: {len(a)} datasets of fields.h5 agree (largest difference {worst:.2e} of the dataset's scale{', in ' + where if where else ''}; rtol {rtol:g})")
    return 0 if worst <= rtol else 1


if __name__ == "__main__":
    sys.exit(main())
