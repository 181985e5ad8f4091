"""Supports and loads (the bcs table), and the resultant they apply.

- The fuselage is clamped at both ends of the barrel (all dof of the end sections).
- Half model: the symmetry plane y = 0 holds u_y = r_x = r_z = 0 on the fuselage and the centre box
  (docs/shell.md, "Symmetry conditions").
- Each wing's loads enter at the outboard end of its outer box as node-set forces (boltnet's force on
  a set is its total, shared equally by the set's nodes): a spanwise couple on the two skins' tip
  edges and vertical forces on the two spar webs' tip edges, chosen so that the resultant at the
  side-of-body section (the butt line, box mid-chord and mid-depth) is the shear V, the bending moment
  M and the torque T. Per unit load factor (the scene's load table is in g), the 1 g loads.
"""
import numpy as np


def supports(half, side_tags):
    out = [("fuselage", "all", "fixed", 0.0, "fwd_end"), ("fuselage", "all", "fixed", 0.0, "aft_end")]
    if half:
        for part in ("fuselage", "centre_upper", "centre_lower", "centre_sub"):
            for dof in ("uy", "rx", "rz"):
                out.append((part, dof, "fixed", 0.0, "sym"))
    return out


def wing_loads(g, a, s, t):
    """Node-set forces of one wing (s = +1 right, -1 left; t the part suffix)."""
    h = g.z_up - g.z_lo
    C = a.moment - a.shear * (g.y_tip - g.yb)     # bending couple at the tip section
    Fu = -s * C / h                               # upper skin pushed inboard for positive M (tip up)
    Ff = a.shear / 2 + a.torque / g.b             # torque about +y: nose-up positive
    Fr = a.shear / 2 - a.torque / g.b
    return [(f"outer_upper{t}", "uy", "force", Fu, "tip"), (f"outer_lower{t}", "uy", "force", -Fu, "tip"),
            (f"outer_sub{t}", "uz", "force", Ff, "tip_front"), (f"outer_sub{t}", "uz", "force", Fr, "tip_rear")]


def resultant(rows, xyz_of, sets_of, origin):
    """Force and moment about `origin` of node-set forces shared equally by each set's nodes."""
    F, M = np.zeros(3), np.zeros(3)
    k = {"ux": 0, "uy": 1, "uz": 2}
    for part, dof, kind, value, st in rows:
        if kind != "force":
            continue
        nodes = sets_of[part][st]
        f = np.zeros(3)
        f[k[dof]] = value / len(nodes)
        for x in xyz_of[part][nodes]:
            F += f
            M += np.cross(x - origin, f)
    return F, M
