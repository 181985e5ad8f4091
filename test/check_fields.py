#!/usr/bin/python3
"""Check fields.h5, fields.xdmf and joints.xdmf of a boltnet run (docs/output.md).

  check_fields.py DIR SCENE_JOINTS_CSV [--ref DIR1 [--rtol R]] [--fixed PART,AXIS,VALUE,DOFS]...
                  [--elements quad|tri|mixed]

- the xdmf files parse as XML (XDMF 3); every DataItem names a dataset of fields.h5 with exactly the
  declared dimensions, data type and precision; topology sizes agree with NumberOfElements;
- the numbering: every node of a part once (/shells/node_part, /shells/node: 0..n-1 per part), every
  element of a part once (/shells/part, /shells/element), the cells' nodes in the cell's part;
- the element results agree with one another: von Mises and principal stresses from the surface
  stresses, the material-frame resultants the element-frame ones turned from /shells/element_axis to
  /shells/material_axis;
- one temporal step per converged step of joints.csv (rows = steps x joints), times increasing,
  each step's load factor (Information "load" and the HDF5 attribute) equal to joints.csv's;
- independent of the writer: at every step, each joint line's endpoint displacements, differenced
  (b - a) and projected on the joint frame built from the scene's fastener table, equal the jump
  du_n, du_t1, du_t2 of joints.csv (1e-9 of the largest jump); state and in-plane force likewise;
- --fixed: the nodes of shell part PART whose coordinate AXIS (x, y or z) equals VALUE have zero
  DOFS (colon-separated from ux uy uz rx ry rz, or all) at every step, and some node moves;
- independent of the writer: each joint line's end on a shell part lies on the fastener's axis
  (the scene table's position and normal) to 1e-9 of the model's size, and where that part's nodes
  nearest the axis are at one axial position (a flat sheet across the fastener), at that position:
  the reference point of a footprint-coupled joint is the bolt axis at its footprint's mid-surface;
- --ref DIR1: every dataset equals the one in DIR1 (another rank count) to R (default 1e-9) of its
  quantity's scale (largest magnitude over all steps, or for a quantity the load leaves zero the
  load's scale in its units); integer datasets exactly;
- --elements quad|tri|mixed: the shells are quadrilaterals, triangles or both (/shells/cell_type),
  the xdmf topology is Quadrilateral or, with triangles, Mixed (/shells/topology: per cell its type
  code and nodes), and every shell node is a node of some element.
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


def check_numbering(h5):
    """Every node and element of a part once, in the part's own numbering; cells within their part."""
    npart, node = h5["/shells/node_part"][:, 0], h5["/shells/node"][:, 0]
    cpart, elem = h5["/shells/part"][:, 0], h5["/shells/element"][:, 0]
    cells = h5["/shells/cells"][:]
    for p in np.unique(npart):
        n = np.sort(node[npart == p])
        if not np.array_equal(n, np.arange(len(n))):
            fail(f"part {p}: its node numbers are not 0..{len(n) - 1} once each")
        e = np.sort(elem[cpart == p])
        if not np.array_equal(e, np.arange(len(e))):
            fail(f"part {p}: its element numbers are not 0..{len(e) - 1} once each")
    used = cells[cells >= 0]
    if used.max() >= len(node) or (npart[cells] != cpart[:, None])[cells >= 0].any():
        fail("a cell names a node outside its part")
    print(f"check_fields: {len(node)} nodes and {len(elem)} elements of {len(np.unique(npart))} parts, each once")


def check_results(h5, times):
    """Element results consistent with one another at every step."""
    ea, ma, nrm = h5["/shells/element_axis"][:], h5["/shells/material_axis"][:], h5["/shells/normal"][:]
    c = np.einsum("ij,ij->i", ma, ea)
    s = np.einsum("ij,ij->i", ma, np.cross(nrm, ea))
    worst, nsteps = 0.0, 0
    for t in times:
        g = h5[f"/steps/{int(t):06d}/shells"]
        if "N" not in g:
            continue
        nsteps += 1
        for name in ("N", "M"):
            a, b = g[name][:], g[name + "_element"][:]
            xx = c * c * b[:, 0] + s * s * b[:, 1] + 2 * c * s * b[:, 2]
            yy = s * s * b[:, 0] + c * c * b[:, 1] - 2 * c * s * b[:, 2]
            xy = -c * s * b[:, 0] + c * s * b[:, 1] + (c * c - s * s) * b[:, 2]
            scale = max(np.abs(b).max(), 1e-300)
            worst = max(worst, np.abs(np.stack([xx, yy, xy], 1) - a).max() / scale)
        for face in ("top", "bottom"):
            st = g["stress_" + face][:]
            vm = np.sqrt(st[:, 0] ** 2 - st[:, 0] * st[:, 1] + st[:, 1] ** 2 + 3 * st[:, 2] ** 2)
            centre, radius = 0.5 * (st[:, 0] + st[:, 1]), np.hypot(0.5 * (st[:, 0] - st[:, 1]), st[:, 2])
            scale = max(np.nanmax(np.abs(st)) if st.size else 0, 1e-300)
            worst = max(worst, np.nanmax(np.abs(vm - g["von_mises_" + face][:])) / scale)
            worst = max(worst, np.nanmax(np.abs(np.stack([centre + radius, centre - radius], 1) - g["principal_" + face][:])) / scale)
    if worst > 1e-12:
        fail(f"element results disagree with one another by {worst:g} of their scale")
    if nsteps:
        print(f"check_fields: element results of {nsteps} steps consistent (frames, von Mises, principal): {worst:.2g}")


def check_joint_points(h5, table, ids, lines):
    """Each joint line's ends on shell parts: on the fastener's axis, at a flat sheet's mid-surface."""
    if "/shells/coordinates" not in h5:
        print("check_fields: no shell part, no joint line end to check on a sheet")
        return
    pts, x = h5["/joints/coordinates"][:], h5["/shells/coordinates"][:]
    npart = h5["/shells/node_part"][:, 0]
    size = max(np.abs(x).max(), 1.0)
    rows = {int(r["id"]): r for r in table}
    off_axis = off_sheet = 0.0
    checked = flat = 0
    for i, jid in enumerate(ids):
        r = rows[int(jid)]
        c = np.array([float(r[k]) for k in ("x", "y", "z")])
        n = np.array([float(r[k]) for k in ("nx", "ny", "nz")])
        n /= np.linalg.norm(n)
        for side, part in enumerate((int(r["patch_a"]), int(r["patch_b"]))):
            mine = x[npart == part]
            if not len(mine):
                continue  # a rigid part
            p = pts[lines[i, side]]
            v = p - c
            off_axis = max(off_axis, np.linalg.norm(v - v.dot(n) * n) / size)
            w = mine - c
            radial = np.linalg.norm(w - np.outer(w @ n, n), axis=1)
            near = np.argsort(radial)[:4]
            axial = w[near] @ n
            if np.ptp(axial) <= 1e-12 * size:
                off_sheet = max(off_sheet, abs(v.dot(n) - axial.mean()) / size)
                flat += 1
            checked += 1
    if off_axis > 1e-9 or off_sheet > 1e-9:
        fail(f"joint line ends off the fastener axis by {off_axis:g}, off the sheet's mid-surface by {off_sheet:g} of the model's size")
    if checked and not flat:
        fail(f"none of the {checked} joint line ends on shell parts lies on a sheet flat across its fastener: the mid-surface was not checked")
    print(f"check_fields: {checked} joint line ends on shell parts on their axes ({off_axis:.2g}), {flat} of them on flat sheets at the mid-surface ({off_sheet:.2g})")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    ap.add_argument("scene_joints")
    ap.add_argument("--ref")
    ap.add_argument("--rtol", type=float, default=1e-9)
    ap.add_argument("--fixed", action="append", default=[])
    ap.add_argument("--elements", choices=["quad", "tri", "mixed"])
    args = ap.parse_args()

    h5 = h5py.File(args.dir + "/fields.h5", "r")
    roots = {}
    for name in ("fields.xdmf", "joints.xdmf"):
        try:
            roots[name] = ET.parse(f"{args.dir}/{name}").getroot()
        except FileNotFoundError:
            if name == "joints.xdmf" or "shells" in h5:
                fail(f"{name} is missing")
    for name, root in roots.items():
        if root.get("Version") != "3.0":
            fail(f"{name}: Xdmf Version {root.get('Version')}, not 3.0")
    # Every DataItem against the file.
    nitems = 0
    for root in roots.values():
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
            kind = "i" if item.get("DataType") == "Int" else "f"
            if ds.dtype.kind != kind or ds.dtype.itemsize != int(item.get("Precision")):
                fail(f"{path}: dtype {ds.dtype}, xdmf says {item.get('DataType')} {item.get('Precision')}")
        for topo in root.iter("Topology"):
            item = topo.find("DataItem")
            if topo.get("TopologyType") == "Mixed":  # a flat list: per cell its type code and nodes
                types = h5["/shells/cell_type"][:, 0]
                if len(types) != int(topo.get("NumberOfElements")) or int(item.get("Dimensions")) != int(np.sum(np.where(types == 4, 4, 5))):
                    fail(f"Mixed topology: NumberOfElements {topo.get('NumberOfElements')}, Dimensions {item.get('Dimensions')}, for {len(types)} cells")
            elif int(item.get("Dimensions").split()[0]) != int(topo.get("NumberOfElements")):
                fail(f"Topology {item.text.strip()}: NumberOfElements {topo.get('NumberOfElements')} vs {item.get('Dimensions')}")
    print(f"check_fields: {nitems} DataItems match fields.h5")

    grids = {}
    for name, root in roots.items():
        temporal = root.find("Domain/Grid")
        if temporal.get("GridType") != "Collection" or temporal.get("CollectionType") != "Temporal":
            fail(f"{name}: the top grid is not a temporal collection")
        grids[name] = temporal.findall("Grid")
        if any(g.get("GridType") != "Uniform" for g in grids[name]):
            fail(f"{name}: a step is not a uniform grid")
    steps = grids["joints.xdmf"]
    times = [float(g.find("Time").get("Value")) for g in steps]
    loads = [float(g.find("Information[@Name='load']").get("Value")) for g in steps]
    if "fields.xdmf" in grids and [float(g.find("Time").get("Value")) for g in grids["fields.xdmf"]] != times:
        fail("fields.xdmf and joints.xdmf do not hold the same steps")
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

    check_joint_points(h5, read_table(args.scene_joints), ids, lines)

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

    if "shells" in h5:
        check_numbering(h5)
        check_results(h5, times)

    # --elements: the kinds of cell (/shells/cell_type, XDMF codes: 5 quadrilateral, 4 triangle)
    # agree with the cells' node counts and with the xdmf topology (Quadrilateral, or Mixed as soon as
    # there is a triangle, whose flat list /shells/topology is the cells' type and nodes in order),
    # and every shell node is a node of some cell.
    if args.elements:
        types, cells = h5["/shells/cell_type"][:, 0], h5["/shells/cells"][:]
        has = {"quad": bool((types == 5).any()), "tri": bool((types == 4).any())}
        want = {"quad": args.elements in ("quad", "mixed"), "tri": args.elements in ("tri", "mixed")}
        if has != want:
            fail(f"--elements {args.elements}: the file holds quadrilaterals {has['quad']}, triangles {has['tri']}")
        if not np.isin(types, (4, 5)).all() or ((types == 4) != (cells[:, 3] < 0)).any() or (cells[:, :3] < 0).any():
            fail("/shells/cell_type disagrees with the node counts of /shells/cells")
        kinds = {t.get("TopologyType") for t in roots["fields.xdmf"].iter("Topology")}
        if kinds != {"Mixed" if has["tri"] else "Quadrilateral"}:
            fail(f"--elements {args.elements}: xdmf topologies {kinds}")
        if has["tri"]:
            flat = np.concatenate([[t] + list(c[: 3 if t == 4 else 4]) for t, c in zip(types, cells)])
            if "/shells/topology" not in h5 or not np.array_equal(h5["/shells/topology"][:], flat):
                fail("/shells/topology is not the cells' type codes and nodes in order")
        used = np.zeros(len(h5["/shells/coordinates"]), bool)
        used[cells[cells >= 0]] = True
        if not used.all():
            fail(f"{(~used).sum()} shell nodes belong to no element")
        print(f"check_fields: {len(types)} elements ({int((types == 4).sum())} triangles) over {len(used)} nodes, every node used, topology {kinds}")

    # Fixed dof.
    dofnames = ["ux", "uy", "uz", "rx", "ry", "rz"]
    for spec in args.fixed:
        part, axis, value, dofs = spec.split(",")
        dofs = list(range(6)) if dofs == "all" else [dofnames.index(d) for d in dofs.split(":")]
        x = h5["/shells/coordinates"][:]
        nodes = np.flatnonzero(h5["/shells/node_part"][:, 0] == int(part))
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
        # A quantity the load leaves zero (the shear of a strip in pure bending, the force of a joint
        # that carries none) holds round-off only: its scale is then the load's in its units, from
        # the quantities of other units and h, the mean element size (membrane and shear forces
        # N/mm, moments N mm/mm, joint forces N, translations mm, rotations rad).
        if "shells/cells" in ref:
            xyz, cells = ref["shells/coordinates"][:], ref["shells/cells"][:]
            first = xyz[cells[:, 0]]
            h = np.mean([np.linalg.norm(xyz[cells[:, 2]] - first, axis=1).mean(), 1e-300])
            get = lambda *names: max([qscale.get(k, 0.0) for k in names] + [0.0])
            per_length = max(get("shells/N", "shells/Q", "shells/N_element", "shells/Q_element"), get("shells/M", "shells/M_element") / h)
            translation = max(get("shells/displacement", "joints/displacement", "joints/jump"), get("shells/rotation") * h)
            floor = {"N": per_length, "Q": per_length, "N_element": per_length, "Q_element": per_length,
                     "M": per_length * h, "M_element": per_length * h, "force": per_length * h, "in_plane_force": per_length * h,
                     "displacement": translation, "jump": translation, "rotation": translation / h}
            for q in qscale:
                if q.split("/")[-1] in floor:
                    qscale[q] = max(qscale[q], floor[q.split("/")[-1]])
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
