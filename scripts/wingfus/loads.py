"""Supports and loads (the bcs table), and the resultant they apply.

- The fuselage is clamped at both ends of the barrel (all dof of the end sections).
- Half model: the symmetry plane y = 0 holds u_y = r_x = r_z = 0 on the fuselage and the centre box
  (docs/shell.md, "Symmetry conditions").
- Each wing's loads enter at the outboard end of its outer box as node-set forces (boltnet shares a
  set's force equally among its nodes; a set here is one curve of the tip section: an element edge of
  a web, a cap, a stretch of skin). They are the stresses of thin-walled beam theory on the tip
  section, so that the box is loaded as it would be by the rest of the wing:
  * bending: axial stresses proportional to the distance from the neutral axis, E kappa (z - z_na),
    over skins, caps and webs (plane sections), with kappa set to give the couple C at the tip;
  * shear V: a uniform shear flow in the two spar webs;
  * torque T: Bredt's shear flow q = T / (2 b h) around the cell (webs vertical, skins chordwise).
  With C = M - V (y_tip - y_b), the resultant at the side-of-body section (butt line, mid-chord,
  mid-depth) is the shear V, the bending moment M and the torque T (nose-up positive). Forces are per
  unit load factor: the scene's load table is in g.
- With --tip-load rigid, the same resultant enters through a rigid patch instead (rigid_tip): a
  6-dof node at the tip section's centre, tied to the whole section of each of the box's three
  parts (its node set `tip`) by a stiff spring joint whose footprint is that set (docs/scenes.md,
  "Ties"): Nastran's RBE2 on the tip. The section then stays plane and undistorted, which stiffens
  the last rib bay; the beam-theory stresses leave it free. The rib bays between the tip and the
  joint make the two agree at the joint (St-Venant): docs/wing-fuselage.md.
- Cabin pressure (optional): a pressure on the fuselage skin (the surface group "skin", its
  elements facing outward), the pressurised cabin's differential pressure. Its own load: the wing's
  rows are the load `wing`, the pressure's `cabin`, and the scene runs them as load cases
  (scene.write): the wing's load path alone, the pressure alone (up and down), both at 1 g, and
  the wing's load path with the pressure brought on first and held (a case that continues
  another, docs/scenes.md "Held loads").
"""
import numpy as np


def supports(half):
    out = [("fuselage", "all", "fixed", 0.0, "fwd_end"), ("fuselage", "all", "fixed", 0.0, "aft_end")]
    if half:
        for part in ("fuselage", "centre_upper", "centre_lower", "centre_sub"):
            for dof in ("uy", "rx", "rz"):
                out.append((part, dof, "fixed", 0.0, "sym"))
    return out


def tip_section(g, t):
    """(part, set, E x area, z, x-extent) of each piece of the tip section."""
    a, th = g.a, g.a.thickness
    wc, b = a.cap_width, g.b
    out = []
    for which, z, E, ts in (("upper", g.z_up, a.E_upper_eff, th["upper_skin"]), ("lower", g.z_lo, a.E_lower_eff, th["lower_skin"])):
        for st, w in (("tip_front_overhang", wc), ("tip_box", b), ("tip_rear_overhang", wc)):
            out.append((f"outer_{which}{t}", st, E * ts * w, z))
    for spar in ("front", "rear"):
        for k, (z0, z1, _) in enumerate(g.z_web.segs):
            out.append((f"outer_sub{t}", f"tip_{spar}_web{k}", a.E_sub * th["substructure"] * (z1 - z0), (z0 + z1) / 2))
        for which, zc in (("upper", g.z_upcap), ("lower", g.z_locap)):
            out.append((f"outer_sub{t}", f"tip_{spar}_cap_{which}", a.E_sub * th["substructure"] * wc, zc))
    return out


def wing_loads(g, a, s, t):
    """Node-set forces of one wing (s = +1 right, -1 left; t the part suffix)."""
    sec = tip_section(g, t)
    EA = np.array([p[2] for p in sec])
    z = np.array([p[3] for p in sec])
    zna = (EA * z).sum() / EA.sum()
    EI = (EA * (z - zna) ** 2).sum()
    C = a.moment - a.shear * (g.y_tip - g.yb)
    kappa = C / EI
    rows = []
    # Bending about x: tip up (C > 0) compresses the upper side, pushed inboard (-s y).
    for (part, st, ea, zz) in sec:
        rows.append((part, "uy", "force", -s * kappa * ea * (zz - zna), st))
    nz = len(g.z_web.segs)
    h = g.z_up - g.z_lo
    q = a.torque / (2 * g.b * h)
    for spar, sign in (("front", 1), ("rear", -1)):
        for k in range(nz):
            rows.append((f"outer_sub{t}", "uz", "force", (a.shear / 2 + sign * q * h) / nz, f"tip_{spar}_web{k}"))
    rows.append((f"outer_upper{t}", "ux", "force", q * g.b, "tip_box"))
    rows.append((f"outer_lower{t}", "ux", "force", -q * g.b, "tip_box"))
    return [r for r in rows if r[3] != 0.0]


def resultant(rows, set_xyz, origin):
    """Force and moment about `origin` of node-set forces shared equally by each set's nodes;
    set_xyz: {part: {set: coordinates of its nodes}}."""
    F, M = np.zeros(3), np.zeros(3)
    k = {"ux": 0, "uy": 1, "uz": 2}
    for part, dof, kind, value, st in rows:
        if kind != "force":
            continue
        x = set_xyz[part][st]
        f = np.zeros(3)
        f[k[dof]] = value / len(x)
        F += f * len(x)
        M += np.cross(x - origin, f).sum(axis=0)
    return F, M


def cabin_pressure(a):
    """The cabin pressure's row (load `cabin`), or none."""
    if a.cabin_pressure <= 0:
        return []
    return [("fuselage", "all", "pressure", a.cabin_pressure, "skin", "cabin")]


def rigid_tip(g, s, t, rows, set_xyz, origin):
    """The tip load of one wing through a rigid patch: its position P (the tip section's centre),
    the tie joints (part, joint axis n, t1) from it to each part of the box, and its bcs rows: the
    force and moment at P with the same resultant about `origin` as the beam-theory rows."""
    F, M = resultant(rows, set_xyz, origin)
    P = np.array([g.b / 2, s * g.y_tip, (g.z_up + g.z_lo) / 2])
    MP = M - np.cross(P - origin, F)
    ties = [(f"outer_{p}{t}", (0.0, float(s), 0.0), (1.0, 0.0, 0.0)) for p in ("upper", "lower", "sub")]
    names = ("ux", "uy", "uz", "rx", "ry", "rz")
    # Components at round-off of the resultant (the beam rows' sums) are zero.
    v = [c if abs(c) > 1e-9 * np.abs(F).max() else 0.0 for c in F] + [c if abs(c) > 1e-9 * np.abs(MP).max() else 0.0 for c in MP]
    bcs = [(f"tip_load{t}", names[k], "force", float(c), "") for k, c in enumerate(v) if c != 0.0]
    return P, ties, bcs
