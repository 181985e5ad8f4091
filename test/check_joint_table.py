#!/usr/bin/python3
"""Checks the joint table joints.h5 of a boltnet run (docs/output.md, "The joint table").

  check_joint_table.py RUN_DIR                      joints.h5 against joints.csv of the same run
  check_joint_table.py RUN_DIR --ref REF_DIR [--rtol R]   joints.h5 against REF_DIR's joints.h5

Requirements checked:
- the table holds joints.csv's quantities (written by the rank-0 path, the verified reference) for
  every step and joint, equal to the printed precision (%.17g: the same doubles), the state names
  stored once (state_names) and every dataset's columns and units as attributes;
- rows are the joints in increasing id, as joints.csv's, whatever the number of ranks: with --ref,
  another rank count's table has the same steps, ids, states and bearing flags, and numbers equal
  to R (default 1e-10) of each quantity's scale (the largest magnitude of jump, force or slip, as
  compare_csv.py judges joints.csv).
Exits 1 with the first difference.
"""
import argparse
import csv
import sys

import h5py
import numpy as np

COLUMNS = ["step", "load", "joint", "state", "du_n", "du_t1", "du_t2", "f_n", "f_t1", "f_t2", "bearing", "slip_t1", "slip_t2"]
STEP_DATASETS = {"step": 0, "load": 0, "state": 1, "bearing": 1, "jump": 6, "force": 6, "slip": 2}


def fail(msg):
    print(f"check_joint_table: FAIL: {msg}")
    sys.exit(1)


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def read_table(path):
    """The table as numpy arrays, its structure checked."""
    with h5py.File(path, "r") as f:
        t = {k: f[k][()] for k in ["joint", "state_names"] + list(STEP_DATASETS)}
        for k, width in STEP_DATASETS.items():
            d = f[k]
            for a in ("columns", "units", "meaning"):
                if a not in d.attrs:
                    fail(f"{path}: dataset {k} has no attribute {a}")
            ncols = len(text(d.attrs["columns"]).split())
            if ncols != max(width, 1) or len(text(d.attrs["units"]).split()) != ncols:
                fail(f"{path}: dataset {k}: {ncols} columns named for width {width}")
            want = (len(t["step"]),) + ((len(t["joint"]),) if width else ()) + ((width,) if width > 1 else ())
            if d.shape != want:
                fail(f"{path}: dataset {k} has shape {d.shape}, expected {want}")
        t["names"] = [text(n) for n in t["state_names"]]
    if list(t["joint"]) != sorted(t["joint"]):
        fail(f"{path}: the joint ids are not in increasing order")
    if list(t["step"]) != list(range(1, len(t["step"]) + 1)):
        fail(f"{path}: steps {list(t['step'])} are not 1..{len(t['step'])}")
    return t


def against_csv(t, path):
    rows = list(csv.reader(open(path)))
    if rows[0] != COLUMNS:
        fail(f"{path}: header {rows[0]}")
    T, J = len(t["step"]), len(t["joint"])
    if len(rows) - 1 != T * J:
        fail(f"{path} has {len(rows) - 1} rows, the table {T} steps x {J} joints")
    for n, r in enumerate(rows[1:]):
        s, j = divmod(n, J)  # joints.csv: by step, then by joint id
        got = [t["step"][s], t["load"][s], t["joint"][j], t["names"][t["state"][s, j]], *t["jump"][s, j, :3], *t["force"][s, j, :3], t["bearing"][s, j], *t["slip"][s, j]]
        for c, (x, y) in enumerate(zip(r, got)):
            ok = x == y if COLUMNS[c] == "state" else float(x) == float(y)
            if not ok:
                fail(f"{path} line {n + 2} column {COLUMNS[c]}: {x} vs the table's {y!r}")
    print(f"check_joint_table: joints.h5 equals joints.csv: {T} steps x {J} joints, every value to the printed precision")


def against_ref(t, r, rtol):
    for k in ("step", "joint", "state", "bearing"):
        if not np.array_equal(t[k], r[k]):
            fail(f"dataset {k} differs from the reference's")
    if t["names"] != r["names"]:
        fail(f"state names {t['names']} vs {r['names']}")
    worst = 0.0
    # Translations and rotations (forces and moments) are judged apart: their units differ.
    parts = [("load", np.s_[...]), ("jump", np.s_[..., :3]), ("jump", np.s_[..., 3:]), ("force", np.s_[..., :3]), ("force", np.s_[..., 3:]), ("slip", np.s_[...])]
    for k, sl in parts:
        a, b = t[k][sl], r[k][sl]
        if not b.size:
            continue
        scale = max(float(np.abs(b).max()), 1e-300)
        d = float(np.abs(a - b).max() / scale)
        worst = max(worst, d)
        if d > rtol:
            fail(f"dataset {k}{'' if sl is Ellipsis else ' ' + str(sl)} differs from the reference's by {d:.3e} of its scale {scale:g} (rtol {rtol:g})")
    print(f"check_joint_table: joints.h5 equals the reference's: {len(t['step'])} steps x {len(t['joint'])} joints, worst {worst:.2e} of the scale")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    ap.add_argument("--ref")
    ap.add_argument("--rtol", type=float, default=1e-10)
    a = ap.parse_args()
    t = read_table(a.dir + "/joints.h5")
    if a.ref:
        against_ref(t, read_table(a.ref + "/joints.h5"), a.rtol)
    else:
        against_csv(t, a.dir + "/joints.csv")


if __name__ == "__main__":
    main()
