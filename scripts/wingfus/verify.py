"""Checks every fastener against the meshes the way boltnet attaches it, before anything is written.

boltnet's footprint of a fastener on a shell part (lib/mesh/search.cpp, FootprintFinder) is the
part's nodes within -coupling_radius of the fastener in the plane normal to the bolt axis, on the
sheet nearest the fastener along the axis within -coupling_reach, plus, when they are fewer than
three, the element that contains the fastener in that plane (the nearest along the axis). The driver
only stops when a footprint is empty. This check replays the rule and requires, for each fastener and
each part:

- no node within the radius, at any distance along the axis (so the footprint is exactly one
  element: fasteners at element centres; and no other sheet of the part comes near the bolt);
- the containing element found by the rule is a sheet of this part at the fastener: its corners lie
  within the reach along the axis;
- the footprints of two fasteners on one part share no node (boltnet would give the node to the
  nearer one, silently changing both);
- no footprint node carries a boundary condition (boltnet stops on it with exact coupling).

Each part is checked on its own (check_part), by the process that meshed it.
"""
import numpy as np
from scipy.spatial import cKDTree


def _frame(n):
    n = np.asarray(n, float) / np.linalg.norm(n)
    t = np.array([1.0, 0, 0]) if abs(n[0]) < 0.9 else np.array([0, 1.0, 0])
    e1 = t - n * (t @ n)
    e1 /= np.linalg.norm(e1)
    return n, e1, np.cross(n, e1)


def footprints(mesh, fasteners, side, radius, reach):
    """Element of `mesh` (xyz, quads) holding each fastener (side 'a' or 'b'); raises ValueError
    naming the first fastener that breaks a rule."""
    xyz, quads = mesh
    # Group fasteners by axis (rows share one): project the part once per axis.
    groups = {}
    for f in fasteners:
        groups.setdefault(tuple(np.round(f.n, 9)), []).append(f)
    cent = xyz[quads].mean(axis=1)
    size = np.linalg.norm(xyz[quads[:, 2]] - xyz[quads[:, 0]], axis=1).max()
    out = {}
    for axis, fs in groups.items():
        n, e1, e2 = _frame(axis)
        P = np.c_[xyz @ e1, xyz @ e2]
        nodes_tree = cKDTree(P)
        C = np.c_[cent @ e1, cent @ e2]
        elem_tree = cKDTree(C)
        for f in fs:
            p = np.asarray(f.x, float)
            q = np.array([p @ e1, p @ e2])
            close = nodes_tree.query_ball_point(q, radius * (1 + 1e-9))
            if close:
                raise ValueError(f"fastener {f.id} ({f.splice}) at {np.round(p, 3)}: node(s) of part '{getattr(f, side)}' lie within "
                                 f"the footprint radius {radius} mm (at {np.round(xyz[close[0]], 3)})")
            cand = np.array(elem_tree.query_ball_point(q, size), dtype=int)
            c = P[quads[cand]] - q                                            # (k, 4, 2)
            cr = c[:, :, 0] * np.roll(c[:, :, 1], -1, axis=1) - c[:, :, 1] * np.roll(c[:, :, 0], -1, axis=1)
            tol = 1e-10 * (np.abs(c).max(axis=(1, 2)) ** 2)[:, None]
            inside = ~(((cr > tol).any(axis=1)) & ((cr < -tol).any(axis=1)))
            best = -1
            if inside.any():
                cand = cand[inside]
                d = np.abs(((xyz[quads[cand]] - p) @ n).mean(axis=1))
                best = int(cand[np.argmin(d)])
            if best < 0:
                raise ValueError(f"fastener {f.id} ({f.splice}) at {np.round(p, 3)} is outside part '{getattr(f, side)}'")
            dn = np.abs((xyz[quads[best]] - p) @ n)
            if dn.max() > reach:
                raise ValueError(f"fastener {f.id} ({f.splice}) at {np.round(p, 3)}: the element of part '{getattr(f, side)}' "
                                 f"that holds it lies {dn.max():.1f} mm away along the bolt axis, beyond the reach {reach} mm "
                                 f"(--coupling-reach)")
            out[f.id] = best
    return out


def check_part(part, mesh, sets, lst, radius, reach):
    """The rules on one part: mesh (xyz, quads); sets: {set: node indices}; lst: the (fastener, side)
    pairs that attach to it ('a' or 'b'); radius and reach: -coupling_radius and -coupling_reach.
    The generator checks each part as it meshes it, in its own process, so that no process holds
    more than one part's mesh."""
    quads = mesh[1]
    elem = {}
    for side in ("a", "b"):
        fs = [f for f, s in lst if s == side]
        if fs:
            el = footprints(mesh, fs, side, radius, reach)
            elem.update({(f.id, side): el[f.id] for f in fs})
    owner = {}
    for f, side in lst:
        for nd in quads[elem[(f.id, side)]]:
            if nd in owner:
                raise ValueError(f"fasteners {owner[nd]} and {f.id} share node {nd} of part '{part}' in their footprints: too close for the mesh")
            owner[nd] = f.id
    for name, nodes in sets.items():
        hit = set(nodes.tolist()) & owner.keys()
        if hit:
            nd = hit.pop()
            raise ValueError(f"fastener {owner[nd]}'s footprint holds node {nd} of part '{part}', which is in node set '{name}' (a boundary condition)")


def by_part(fasteners, built):
    """{part: [(fastener, side)]}; a fastener naming a part not in `built` is an error."""
    by = {}
    for f in fasteners:
        for side in ("a", "b"):
            part = getattr(f, side)
            if part not in built:
                raise ValueError(f"fastener {f.id} names part '{part}', which is not built")
            by.setdefault(part, []).append((f, side))
    return by
