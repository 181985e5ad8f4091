#!/usr/bin/python3
"""Open a run's fields.xdmf and joints.xdmf with meshio (docs/output.md, "Files the usual tools open").

  check_meshio.py DIR

An independent reader of XDMF 3 + HDF5 (Debian's python3-meshio): through its time-series reader,
- fields.xdmf: as many points as fields.h5 holds nodes, and as many quadrilaterals and triangles
  as it holds cells of each type (/shells/cell_type, counted with h5py; meshio reads the Mixed
  topology of a mesh with triangles), the displacement of every step readable with one row per
  point and the cell data with one row per cell;
- joints.xdmf: one line per joint, one step per converged step of joints.csv, and at every step the
  joints' state and in-plane force equal joints.csv's (the table rank 0 writes from its own gather).
"""
import csv
import sys
import warnings

import h5py
import numpy as np

warnings.filterwarnings("ignore")  # meshio warns about the unused HDF5 handles it keeps open
import meshio  # noqa: E402

STATES = {"linear": 0, "open": 1, "contact": 2, "stick": 3, "slide": 4}


def main():
    d = sys.argv[1]
    fails = []
    h5 = h5py.File(f"{d}/fields.h5", "r")
    nnodes, ncells = h5["/shells/coordinates"].shape[0], h5["/shells/cells"].shape[0]
    types = h5["/shells/cell_type"][:, 0]
    want = {"quad": int((types == 5).sum()), "triangle": int((types == 4).sum())}
    with meshio.xdmf.TimeSeriesReader(f"{d}/fields.xdmf") as r:
        points, cells = r.read_points_cells()
        got = {k: sum(len(c.data) for c in cells if c.type == k) for k in want}
        if points.shape != (nnodes, 3) or got != want:
            fails.append(f"fields.xdmf: meshio reads {points.shape[0]} points, cells {got}; fields.h5 has {nnodes} nodes, cells {want}")
        for k in range(r.num_steps):
            t, pd, cd = r.read_data(k)
            if pd["displacement"].shape != (nnodes, 3) or sum(len(b) for b in cd["von_mises_top"]) != ncells:
                fails.append(f"fields.xdmf step {t}: displacement {pd['displacement'].shape}")
        nsteps = r.num_steps
    print(f"check_meshio: fields.xdmf: {points.shape[0]} points, {got['quad']} quads, {got['triangle']} triangles, {nsteps} steps")

    with open(f"{d}/joints.csv") as f:
        rows = list(csv.DictReader(f))
    bystep = {}
    for row in rows:
        bystep.setdefault(int(row["step"]), {})[int(row["joint"])] = row
    worst = 0.0
    with meshio.xdmf.TimeSeriesReader(f"{d}/joints.xdmf") as r:
        points, cells = r.read_points_cells()
        lines = np.concatenate([c.data for c in cells if c.type == "line"])
        if r.num_steps != len(bystep):
            fails.append(f"joints.xdmf: {r.num_steps} steps, joints.csv {len(bystep)}")
        for k in range(r.num_steps):
            t, pd, cd = r.read_data(k)
            ids, state, fip = cd["joint"][0].ravel(), cd["state"][0].ravel(), cd["in_plane_force"][0].ravel()
            ref = bystep.get(int(t), {})
            if len(ids) != len(ref) or len(lines) != len(ref):
                fails.append(f"step {t}: {len(ids)} joints in joints.xdmf, {len(ref)} in joints.csv")
                continue
            for i, jid in enumerate(ids):
                row = ref[int(jid)]
                if state[i] != STATES[row["state"]]:
                    fails.append(f"step {t} joint {jid}: state {state[i]}, joints.csv {row['state']}")
                f = np.hypot(float(row["f_t1"]), float(row["f_t2"]))
                worst = max(worst, abs(fip[i] - f) / max(1.0, f))
    if worst > 1e-12:
        fails.append(f"in-plane forces differ from joints.csv by {worst:g} (relative)")
    print(f"check_meshio: joints.xdmf: {len(lines)} lines, {len(bystep)} steps; state and in-plane force as joints.csv (largest difference {worst:.2g})")
    for f in fails:
        print("FAIL:", f)
    print("check_meshio: PASS" if not fails else f"check_meshio: {len(fails)} failure(s)")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
