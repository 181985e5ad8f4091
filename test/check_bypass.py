#!/usr/bin/python3
"""Check bypass.csv of a boltnet run (docs/output.md, "Bypass").

  check_bypass.py DIR [--uniform N] [--ref DIR1] [--h5]

- every row: the bearing load equals the in-plane force of the joint in joints.csv at that step;
  the bypass flux is sign(n_avg) (|n_avg| - bearing / (2 w)) and the bypass load flux * w; at least
  one element was averaged;
- --uniform N: the sheet is in uniform tension N (N/mm) and the fasteners carry nothing: the
  bypass flux is N to 1e-9 (the closed form: the whole running load passes the fastener);
- --ref DIR1: the same rows as DIR1 (another rank count) to 1e-9 of the largest bypass load;
- --h5: the rows are read from DIR/fields.h5 (each step's joints group: bypass_* per joint and
  side, written in parallel) instead of bypass.csv, the bearing check against the same group's
  in_plane_force; with --ref, compared with DIR1's bypass.csv (the path through rank 0).
"""
import argparse
import csv
import sys

import numpy as np


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def read_h5(path):
    """bypass.csv's rows from fields.h5: per step, joint (natural order: /joints/id) and side."""
    import h5py
    rows, inplane = [], {}
    with h5py.File(path, "r") as h:
        ids = np.asarray(h["joints/id"]).reshape(-1)
        for name in sorted(h["steps"]):
            g = h["steps"][name]["joints"]
            step = str(int(name))
            w = float(np.asarray(g.attrs["bypass_width"]).reshape(-1)[0])
            cols = {c: np.asarray(g["bypass_" + c]).reshape(-1, 2) for c in ("load", "flux", "n_avg", "bearing", "elements")}
            fip = np.asarray(g["in_plane_force"]).reshape(-1)
            for i, jid in enumerate(ids):
                inplane[(step, str(int(jid)))] = fip[i]
                for side in (0, 1):
                    if cols["elements"][i, side] < 1 and np.isnan(cols["bearing"][i, side]):
                        continue  # a side on a rigid part
                    rows.append({"step": step, "joint": str(int(jid)), "sheet": "ab"[side], "width": repr(w),
                                 "bearing": repr(cols["bearing"][i, side]), "n_avg": repr(cols["n_avg"][i, side]),
                                 "bypass_flux": repr(cols["flux"][i, side]), "bypass_load": repr(cols["load"][i, side]),
                                 "elements": str(int(cols["elements"][i, side]))})
    rows.sort(key=lambda r: (int(r["step"]), int(r["joint"]), r["sheet"]))
    return rows, inplane


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    ap.add_argument("--uniform", type=float)
    ap.add_argument("--ref")
    ap.add_argument("--h5", action="store_true")
    a = ap.parse_args()
    fails = []
    if a.h5:
        rows, inplane = read_h5(f"{a.dir}/fields.h5")
        joints = {k: {"f_t1": v, "f_t2": 0.0} for k, v in inplane.items()}
    else:
        rows = read(f"{a.dir}/bypass.csv")
        joints = {(r["step"], r["joint"]): r for r in read(f"{a.dir}/joints.csv")}
    scale = max([abs(float(r["bypass_load"])) for r in rows] + [1e-300])
    for r in rows:
        j = joints[(r["step"], r["joint"])]
        bearing, w, n = float(r["bearing"]), float(r["width"]), float(r["n_avg"])
        fip = np.hypot(float(j["f_t1"]), float(j["f_t2"]))
        where = f"step {r['step']} joint {r['joint']} sheet {r['sheet']}"
        if abs(bearing - fip) > 1e-12 * max(1.0, fip):
            fails.append(f"{where}: bearing {bearing}, joints.csv in-plane force {fip}")
        flux = np.copysign(abs(n) - bearing / (2 * w), n)
        if abs(flux - float(r["bypass_flux"])) > 1e-12 * max(1.0, abs(flux)) or abs(flux * w - float(r["bypass_load"])) > 1e-12 * scale:
            fails.append(f"{where}: bypass {r['bypass_flux']} / {r['bypass_load']}, expected {flux} / {flux * w}")
        if int(r["elements"]) < 1:
            fails.append(f"{where}: no element averaged")
        if a.uniform is not None and abs(float(r["bypass_flux"]) - a.uniform) > 1e-9 * abs(a.uniform):
            fails.append(f"{where}: bypass flux {r['bypass_flux']}, closed form {a.uniform}")
    if a.ref:
        ref = read(f"{a.ref}/bypass.csv")
        if len(ref) != len(rows):
            fails.append(f"{len(rows)} rows, {len(ref)} in {a.ref}")
        else:
            worst = max(abs(float(x["bypass_load"]) - float(y["bypass_load"])) for x, y in zip(rows, ref)) / scale
            if worst > 1e-9 or any((x["joint"], x["sheet"], x["step"]) != (y["joint"], y["sheet"], y["step"]) for x, y in zip(rows, ref)):
                fails.append(f"rows differ from {a.ref} (largest bypass load difference {worst:g} of the largest)")
    for f in fails:
        print("FAIL:", f)
    print(f"check_bypass: {len(rows)} rows" + (" from fields.h5" if a.h5 else "") + (f", uniform flux {a.uniform}" if a.uniform is not None else "") + (f", as {a.ref}" if a.ref else ""))
    print("check_bypass: PASS" if not fails and rows else "check_bypass: FAIL")
    return 1 if fails or not rows else 0


if __name__ == "__main__":
    sys.exit(main())
