#!/usr/bin/python3
"""Check fields.xdmf + fields.h5 of a boltnet run (docs/output.md).

  check_fields.py DIR SCENE_JOINTS_CSV [--ref DIR1 [--rtol R]] [--fixed PART,AXIS,VALUE,DOFS]...
                  [--elements quad|tri|mixed]

- fields.xdmf parses as XML; every DataItem names a dataset of fields.h5 with exactly the declared
  dimensions, number type and precision; topology sizes agree with NumberOfElements;
- one temporal step per converged step of joints.csv (rows = steps x joints), times increasing,
  each step's load factor (Information "load" and the HDF5 attribute) equal to joints.csv's;
- independent of the writer: at every step, each joint line's endpoint displacements, differenced
  (b - a) and projected on the joint frame built from the scene's fastener table, equal the jump
  du_n, du_t1, du_t2 of joints.csv (1e-9 of the largest jump); state and in-plane force likewise;
- --fixed: the nodes of shell part PART whose coordinate AXIS (x, y or z) equals VALUE have zero
  DOFS (colon-separated from ux uy uz rx ry rz, or all) at every step, and some node moves;
- --ref DIR1: every dataset equals the one in DIR1 (another rank count) to R (default 1e-9) of its
  quantity's scale (largest magnitude over all steps); integer datasets exactly;
- --elements quad|tri|mixed: the shells are quadrilaterals (/shells/quads), triangles
  (/shells/triangles, a grid of Triangle topology in the xdmf) or both, every shell node is a node of
  some element, and each element's nodes belong to one part.
"""
import argparse
import csv
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

STATES = {"linear": 0, "open": 1, "contact": 2, "stick": 3, "slide": 4}
fails = []


def fail(msg):
    fails.append(msg)
    print("FAIL:", msg)


def read_table(path):
    with open(path) as f:
        lines = [l for l in f if l.strip() and not l.lstrip().startswith("#")]
    return list(csv.DictReader(lines))


def frame(row):
    n = np.array([float(row[k]) for k in ("nx", "ny", "nz")])
    t = np.array([float(row[k]) for k in ("t1x", "t1y", "t1z")])
    n /= np.linalg.norm(n)
    t = t - t.dot(n) * n
    t /= np.linalg.norm(t)
    return np.array([n, t, np.cross(n, t)])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    ap.add_argument("scene_joints")
    ap.add_argument("--ref")
    ap.add_argument("--rtol", type=float, default=1e-9)
    ap.add_argument("--fixed", action="append", default=[])
    ap.add_argument("--elements", choices=["quad", "tri", "mixed"])
    args = ap.parse_args()

    root = ET.parse(args.dir + "/fields.xdmf").getroot()
    h5 = h5py.File(args.dir + "/fields.h5", "r")

    # Every DataItem against the file.
    nitems = 0
    for item in root.iter("DataItem"):
        nitems += 1
        fname, path = item.text.strip().split(":", 1)
        if fname != "fields.h5":
            fail(f"DataItem names file {fname}")
            continue
        if path not in h5:
            fail(f"{path} is not in fields.h5")
            continue
        ds = h5[path]
        dims = tuple(int(d) for d in item.get("Dimensions").split())
        if ds.shape != dims:
            fail(f"{path}: shape {ds.shape} in the file, {dims} in the xdmf")
        kind = "i" if item.get("NumberType") == "Int" else "f"
        if ds.dtype.kind != kind or ds.dtype.itemsize != int(item.get("Precision")):
            fail(f"{path}: dtype {ds.dtype}, xdmf says {item.get('NumberType')} {item.get('Precision')}")
    for topo in root.iter("Topology"):
        item = topo.find("DataItem")
        if int(item.get("Dimensions").split()[0]) != int(topo.get("NumberOfElements")):
            fail(f"Topology {item.text.strip()}: NumberOfElements {topo.get('NumberOfElements')} vs {item.get('Dimensions')}")
    print(f"check_fields: {nitems} DataItems match fields.h5")

    temporal = root.find("Domain/Grid")
    if temporal.get("GridType") != "Collection" or temporal.get("CollectionType") != "Temporal":
        fail("the top grid is not a temporal collection")
    steps = temporal.findall("Grid")
    times = [float(g.find("Time").get("Value")) for g in steps]
    loads = [float(g.find("Information[@Name='load']").get("Value")) for g in steps]
    if any(b <= a for a, b in zip(times, times[1:])):
        fail("times are not increasing")

    # joints.csv, by step.
    rows = read_table(args.dir + "/joints.csv")
    bystep = {}
    for r in rows:
        bystep.setdefault(int(r["step"]), []).append(r)
    njoints = h5["/joints/id"].shape[0]
    if len(steps) != len(bystep) or len(rows) != len(steps) * njoints:
        fail(f"{len(steps)} steps in the xdmf, {len(bystep)} in joints.csv ({len(rows)} rows, {njoints} joints)")
    frames = {int(r["id"]): frame(r) for r in read_table(args.scene_joints)}
    ids = h5["/joints/id"][:, 0]
    lines = h5["/joints/lines"][:]

    maxerr, scale = 0.0, 0.0
    for k, (t, load) in enumerate(zip(times, loads)):
        step = int(t)
        g = h5[f"/steps/{step:06d}"]
        if abs(g.attrs["load"] - load) > 0 or int(g.attrs["step"]) != step:
            fail(f"step {step}: attributes {dict(g.attrs)} vs load {load}")
        csvrows = {int(r["joint"]): r for r in bystep.get(step, [])}
        if csvrows and abs(float(next(iter(csvrows.values()))["load"]) - load) > 1e-12 * max(1, abs(load)):
            fail(f"step {step}: load {load} in the xdmf, {next(iter(csvrows.values()))['load']} in joints.csv")
        u = g["joints/displacement"][:]
        state = g["joints/state"][:, 0]
        fip = g["joints/in_plane_force"][:]
        for i, jid in enumerate(ids):
            r = csvrows[int(jid)]
            du = frames[int(jid)] @ (u[lines[i, 1]] - u[lines[i, 0]])
            ref = np.array([float(r["du_n"]), float(r["du_t1"]), float(r["du_t2"])])
            maxerr = max(maxerr, np.abs(du - ref).max())
            scale = max(scale, np.abs(ref).max())
            if state[i] != STATES[r["state"]]:
                fail(f"step {step} joint {jid}: state {state[i]} vs {r['state']}")
            fr = np.hypot(float(r["f_t1"]), float(r["f_t2"]))
            if abs(fip[i] - fr) > 1e-12 * max(1.0, fr):
                fail(f"step {step} joint {jid}: in-plane force {fip[i]} vs {fr}")
    if maxerr > 1e-9 * scale:
        fail(f"joint line displacements differ from the jumps of joints.csv by {maxerr:g} (largest jump {scale:g})")
    print(f"check_fields: {len(steps)} steps, {njoints} joints; line endpoints vs jumps: max difference {maxerr:.3g} (largest jump {scale:.3g})")

    # Shell elements: quadrilaterals and triangles, each block with its part ids.
    blocks = []
    for conn, part in (("/shells/quads", "/shells/part"), ("/shells/triangles", "/shells/triangle_part")):
        if conn in h5:
            blocks.append((h5[conn][:], h5[part][:, 0]))
    if args.elements:
        has = {"quad": "/shells/quads" in h5, "tri": "/shells/triangles" in h5}
        want = {"quad": args.elements in ("quad", "mixed"), "tri": args.elements in ("tri", "mixed")}
        if has != want:
            fail(f"--elements {args.elements}: the file holds quadrilaterals {has['quad']}, triangles {has['tri']}")
        grids = [g for g in root.iter("Grid") if g.find("Topology") is not None and g.find("Topology").get("TopologyType") == "Triangle"]
        ntri = h5["/shells/triangles"].shape[0] if has["tri"] else 0
        if len(grids) != (len(steps) if ntri else 0) or any(int(g.find("Topology").get("NumberOfElements")) != ntri for g in grids):
            fail(f"--elements {args.elements}: {len(grids)} Triangle grids in the xdmf for {len(steps)} steps and {ntri} triangles")
        x = h5["/shells/coordinates"][:]
        used = np.zeros(len(x), bool)
        owner = np.full(len(x), -1)
        for conn, part in blocks:
            used[conn.ravel()] = True
            for e, p in zip(conn, part):
                if (owner[e] >= 0).any() and (owner[e][owner[e] >= 0] != p).any():
                    fail(f"an element of part {p} has nodes of another part")
                    break
                owner[e] = p
        if not used.all():
            fail(f"{(~used).sum()} shell nodes belong to no element")
        print(f"check_fields: {sum(len(c) for c, _ in blocks)} elements ({ntri} triangles) over {len(x)} nodes, every node used")

    # Fixed dof.
    dofnames = ["ux", "uy", "uz", "rx", "ry", "rz"]
    for spec in args.fixed:
        part, axis, value, dofs = spec.split(",")
        dofs = list(range(6)) if dofs == "all" else [dofnames.index(d) for d in dofs.split(":")]
        x = h5["/shells/coordinates"][:]
        nodes = np.unique(np.concatenate([conn[cellpart == int(part)].ravel() for conn, cellpart in blocks]))
        nodes = nodes[np.abs(x[nodes, "xyz".index(axis)] - float(value)) < 1e-9]
        if len(nodes) == 0:
            fail(f"--fixed {spec}: no node")
            continue
        worst, moving = 0.0, 0.0
        for t in times:
            g = h5[f"/steps/{int(t):06d}/shells"]
            v = np.hstack([g["displacement"][:], g["rotation"][:]])
            worst = max(worst, np.abs(v[np.ix_(nodes, dofs)]).max())
            moving = max(moving, np.abs(g["displacement"][:]).max())
        if worst != 0.0 or moving == 0.0:
            fail(f"--fixed {spec}: {len(nodes)} nodes, largest fixed dof {worst:g}, largest displacement {moving:g}")
        print(f"check_fields: part {part}, {axis} = {value}: {len(nodes)} nodes, dof {dofs} exactly zero at every step (largest displacement {moving:.3g} mm)")

    # Another rank count.
    if args.ref:
        ref = h5py.File(args.ref + "/fields.h5", "r")
        names = []
        h5.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
        ref_names = []
        ref.visititems(lambda n, o: ref_names.append(n) if isinstance(o, h5py.Dataset) else None)
        if sorted(names) != sorted(ref_names):
            fail("the two files do not hold the same datasets")
        # The scale of a quantity is its largest magnitude over every step (at a zero load every
        # value is round-off).
        qscale = {}
        for n in names:
            if n in ref and ref[n].dtype.kind == "f" and ref[n].size:
                q = n.split("/", 2)[-1] if n.startswith("steps/") else n
                qscale[q] = max(qscale.get(q, 0.0), np.abs(ref[n][:]).max())
        worst = 0.0
        for n in names:
            if n not in ref:
                continue
            a, b = h5[n][:], ref[n][:]
            if a.shape != b.shape or a.dtype != b.dtype:
                fail(f"{n}: {a.shape} {a.dtype} vs {b.shape} {b.dtype}")
                continue
            if a.dtype.kind == "i":
                if (a != b).any():
                    fail(f"{n}: integers differ")
                continue
            s = qscale[n.split("/", 2)[-1] if n.startswith("steps/") else n]
            d = np.abs(a - b).max() if a.size else 0.0
            worst = max(worst, d / s if s > 0 else d)
            if d > args.rtol * s:
                fail(f"{n}: differs by {d:g} (scale {s:g})")
        print(f"check_fields: {len(names)} datasets agree with {args.ref} (largest relative difference {worst:.3g})")

    if fails:
        print(f"check_fields: {len(fails)} failure(s)")
        return 1
    print("check_fields: PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
