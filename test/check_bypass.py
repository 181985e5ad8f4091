#!/usr/bin/python3
"""Check bypass.csv of a boltnet run (docs/output.md, "Bypass").

  check_bypass.py DIR [--uniform N] [--strip JOINTS_CSV [--rtol R]] [--ref DIR1] [--h5]

- every row: the bearing load equals the in-plane force of the joint in joints.csv at that step;
  the bypass load is the bypass flux times w; the bypass flux is the band of the smaller running
  load (|flux| <= |n_incoming|), and the two bands differ by the bearing load over w, up to the
  balance column: | |n_incoming - flux| w - bearing | = |balance| (exactly when the balance is NaN,
  one band being taken from the balance); at least one element was averaged;
- --uniform N: the sheet is in uniform tension N (N/mm) and the fasteners carry nothing: the
  bypass flux is N to 1e-9 (the closed form: the whole running load passes the fastener);
- --strip JOINTS_CSV: every sheet is a strip of width w loaded at one end only, its fasteners (the
  scene's fastener table, JOINTS_CSV) in a line along the load: a free body of the strip from a cut
  beside a fastener to the sheet's free end says that the bypass load is the sum of the bearing
  loads of the fasteners behind it along d (towards the free end). Checked to R (default 0.01) of
  the sheet's whole load, as is the balance column (lap-rows, docs/output.md: the element
  resultants at the centroids give the section force to the discretisation error);
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
            L = float(np.asarray(g.attrs["bypass_length"]).reshape(-1)[0])
            cols = {c: np.asarray(g["bypass_" + c]).reshape(-1, 2) for c in ("load", "flux", "n_incoming", "balance", "bearing", "elements")}
            fip = np.asarray(g["in_plane_force"]).reshape(-1)
            for i, jid in enumerate(ids):
                inplane[(step, str(int(jid)))] = fip[i]
                for side in (0, 1):
                    if cols["elements"][i, side] < 1 and np.isnan(cols["bearing"][i, side]):
                        continue  # a side on a rigid part
                    rows.append({"step": step, "joint": str(int(jid)), "sheet": "ab"[side], "width": repr(w), "length": repr(L),
                                 "bearing": repr(cols["bearing"][i, side]), "n_incoming": repr(cols["n_incoming"][i, side]),
                                 "balance": repr(cols["balance"][i, side]),
                                 "bypass_flux": repr(cols["flux"][i, side]), "bypass_load": repr(cols["load"][i, side]),
                                 "elements": str(int(cols["elements"][i, side]))})
    rows.sort(key=lambda r: (int(r["step"]), int(r["joint"]), r["sheet"]))
    return rows, inplane


def strip_balance(rows, table, rtol):
    """--strip: each bypass load against the bearing loads behind its fastener on the same sheet."""
    with open(table) as f:
        x = {r["id"]: np.array([float(r["x"]), float(r["y"]), float(r["z"])]) for r in csv.DictReader(l for l in f if not l.lstrip().startswith("#"))}
    fails, worst = [], 0.0
    sheets = {}
    for r in rows:
        sheets.setdefault((r["step"], r["part"]), []).append(r)
    for (step, part), rs in sheets.items():
        total = sum(float(r["bearing"]) for r in rs)
        for r in rs:
            d = np.array([float(r["dx"]), float(r["dy"]), float(r["dz"])])
            behind = sum(float(q["bearing"]) for q in rs if np.dot(x[q["joint"]] - x[r["joint"]], d) < 0)
            err = abs(abs(float(r["bypass_load"])) - behind) / total
            bal = abs(float(r["balance"])) / total if r["balance"] != "nan" else 0.0
            worst = max(worst, err, bal)
            if err > rtol or bal > rtol:
                fails.append(f"step {step} joint {r['joint']} on part {part}: bypass {r['bypass_load']}, the strip's balance {behind} "
                             f"(off by {err:.3g} of the sheet's load {total:.6g}), balance {r['balance']}")
    print(f"check_bypass: strip balance of {len(sheets)} sheets: largest difference {worst:.3g} of a sheet's load (tolerance {rtol})")
    return fails


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    ap.add_argument("--uniform", type=float)
    ap.add_argument("--ref")
    ap.add_argument("--strip")
    ap.add_argument("--rtol", type=float, default=0.01)
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
        bearing, w, n, flux, bal = float(r["bearing"]), float(r["width"]), float(r["n_incoming"]), float(r["bypass_flux"]), float(r["balance"])
        fip = np.hypot(float(j["f_t1"]), float(j["f_t2"]))
        where = f"step {r['step']} joint {r['joint']} sheet {r['sheet']}"
        if abs(bearing - fip) > 1e-12 * max(1.0, fip):
            fails.append(f"{where}: bearing {bearing}, joints.csv in-plane force {fip}")
        if abs(flux * w - float(r["bypass_load"])) > 1e-12 * scale:
            fails.append(f"{where}: bypass load {r['bypass_load']}, flux x w {flux * w}")
        if abs(flux) > abs(n) * (1 + 1e-12):
            fails.append(f"{where}: bypass flux {flux} above the incoming {n}")
        gap = abs(abs(n - flux) * w - bearing) - (0 if np.isnan(bal) else abs(bal))
        if abs(gap) > 1e-9 * max(1.0, bearing, abs(n) * w):
            fails.append(f"{where}: bands {n} and {flux} differ by {abs(n - flux) * w} x w, bearing {bearing}, balance {bal}")
        if int(r["elements"]) < 1:
            fails.append(f"{where}: no element averaged")
        if a.uniform is not None and abs(float(r["bypass_flux"]) - a.uniform) > 1e-9 * abs(a.uniform):
            fails.append(f"{where}: bypass flux {r['bypass_flux']}, closed form {a.uniform}")
    if a.strip:
        fails += strip_balance(rows, a.strip, a.rtol)
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
