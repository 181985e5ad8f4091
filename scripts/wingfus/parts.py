"""The parts of the junction, each a list of mapped blocks on the grids of geometry.py.

A part is one section (material and thickness): boltnet gives one material to a part, so components
of different thickness that are riveted together in the aircraft are separate parts joined by
fasteners, and components of one part (a spar web and its caps) share their nodes. Parts, for one
side (s = +1 right, -1 left, its mirror image):

- fuselage: skin (cylinder of radius R), frames (radial webs) and stringers (radial blades), one
  section; the lower lobe is cut out where the wing box passes (x in the cut-out, below the upper
  skin), and the skin laps on the upper tee's stem along the side of body. The frames at the spars
  (x = 0 and b) go on inside the cut-out, in the spar webs' planes, down to the lower skin: the spar
  frames, fastened to the webs (fasteners.spar_frames).
- centre box and outer box: upper skin, lower skin, substructure (front and rear spar webs with caps
  pointing out of the box, ribs with feet on both skins), the substructure fastened to the skins.
- the side-of-body joint: the upper tee (a flange under both upper skins, folded up into a stem that
  runs along the fuselage contour through the butt gap), the lower strap (over both lower skins) and
  the spar splice fittings (on the inner face of the spar webs).
"""
import math

from .grids import Grid


def mirror(f, s):
    if s > 0:
        return f
    return lambda u, v: (lambda p: (p[0], -p[1], p[2]))(f(u, v))


def cyl(r, s):
    return mirror(lambda x, th: (x, r * math.cos(th), r * math.sin(th)), s)


def fuselage(P, g, s):
    a, R = g.a, g.R
    cut0, cut1 = g.x_cut
    incut = lambda us: us[0] >= cut0 - 1e-9 and us[1] <= cut1 + 1e-9
    keep = lambda us, vs: not (incut(us) and vs[1] <= g.th_e + 1e-12)
    # With a cabin pressure the skin is the surface group "skin", its elements facing away from the
    # axis: the pressure's node set (loads.cabin_pressure). Without, the mesh files stay as they were.
    skin = dict(group="skin", outward=lambda p: (0.0, p[1], p[2])) if a.cabin_pressure > 0 else {}
    P.blocks(cyl(R, s), g.x_fus, g.th_fus, keep, v_centre=lambda x: (x, 0.0, 0.0), planar=False, **skin)
    r_in, r_st = R - a.frame_depth, R - a.stringer_depth
    rg = Grid([(r_in, r_st, 1), (r_st, R, 1)]) if a.frame_depth > a.stringer_depth + 1e-9 else Grid([(r_in, R, 1)])
    for xk in g.frames:
        if cut0 < xk < cut1 and g.x_s0 - 1e-9 <= xk <= g.x_s1 + 1e-9:   # in the box's chord: above the stem
            ring = Grid([seg for seg in g.th_fus.segs if seg[0] >= g.th_ftop - 1e-12])
        elif cut0 < xk < cut1:   # at a spar: above the cut-out's edge, and a spar frame's own grid below it
            ring = Grid([seg for seg in g.th_fus.segs if seg[0] >= g.th_e - 1e-12])
            if g.th_spar_grid is not None:
                ring = g.th_spar_grid + ring
        else:
            ring = g.th_fus
        f = mirror(lambda th, r, xk=xk: (xk, r * math.cos(th), r * math.sin(th)), s)
        P.blocks(f, ring, rg, u_centre=lambda r, xk=xk: (xk, 0.0, 0.0))
    for th in g.stringers_lo + g.stringers_up:
        xs = [seg for seg in g.x_fus.segs if th > g.th_e or not incut(seg)]
        f = mirror(lambda x, r, th=th: (x, r * math.cos(th), r * math.sin(th)), s)
        # A blade ends at a cut-out edge or at the fuselage ends; it runs through the frames.
        for run in _runs(xs):
            P.blocks(f, run, Grid([(r_st, R, 1)]))


def _runs(segs):
    """Split a list of segments into runs of contiguous segments (each a Grid)."""
    runs, cur = [], []
    for seg in segs:
        if cur and abs(cur[-1][1] - seg[0]) > 1e-9:
            runs.append(Grid(cur))
            cur = []
        cur.append(seg)
    if cur:
        runs.append(Grid(cur))
    return runs


def skin(P, g, ygrid, z, s):
    P.blocks(mirror(lambda x, y: (x, y, z), s), g.x_skin, ygrid)


def substructure(P, g, ygrid, ribs, s):
    """Spar webs (x = 0, b) with caps pointing out of the box, ribs at y in `ribs` with feet on both
    skins (a rib at the grid's last node has feet on its inboard side only)."""
    for x0, caps in ((0.0, g.x_cap_front), (g.b, g.x_cap_rear)):
        P.blocks(mirror(lambda y, z, x0=x0: (x0, y, z), s), ygrid, g.z_web)
        for zc in (g.z_upcap, g.z_locap):
            P.blocks(mirror(lambda y, x, zc=zc: (x, y, zc), s), ygrid, caps)
    wf = g.a.foot_width
    for yr in ribs:
        P.blocks(mirror(lambda x, z, yr=yr: (x, yr, z), s), g.x_sub, g.z_web)
        feet = Grid([seg for seg in ygrid.segs if yr - wf - 1e-9 <= seg[0] and seg[1] <= yr + wf + 1e-9])
        for zc in (g.z_upcap, g.z_locap):
            P.blocks(mirror(lambda x, y, zc=zc: (x, y, zc), s), g.x_sub, feet)


def upper_tee(P, g, s):
    P.blocks(mirror(lambda x, y: (x, y, g.z_us), s), g.x_strap, g.y_tee)
    P.blocks(cyl(g.Rs, s), g.x_strap, g.th_stem, v_centre=lambda x: (x, 0.0, 0.0), planar=False)


def lower_strap(P, g, s):
    P.blocks(mirror(lambda x, y: (x, y, g.z_ls), s), g.x_strap, g.y_strap)


def fitting(P, g, x0, s):
    P.blocks(mirror(lambda y, z: (x0, y, z), s), g.y_strap, g.z_fit)


def near(v, w):
    return abs(v - w) < 1e-6


def node_sets(name, g, half):
    """Node sets (physical curves) of a part: symmetry plane, fuselage ends, loaded tip sections
    (each piece for the beam-theory loads, and the whole section, `tip`, for a rigid loading patch)."""
    sets = {}
    if half and (name == "fuselage" or name.startswith("centre")):
        sets["sym"] = lambda p: near(p[1], 0.0)
    if name == "fuselage":
        sets["fwd_end"] = lambda p: near(p[0], g.x_min)
        sets["aft_end"] = lambda p: near(p[0], g.x_max)
    tip = lambda p: near(abs(p[1]), g.y_tip)
    if name.startswith("outer"):
        sets["tip"] = tip
    if name.startswith("outer") and ("upper" in name or "lower" in name):
        sets["tip_front_overhang"] = lambda p: tip(p) and p[0] <= 1e-6
        sets["tip_box"] = lambda p: tip(p) and -1e-6 <= p[0] <= g.b + 1e-6
        sets["tip_rear_overhang"] = lambda p: tip(p) and p[0] >= g.b - 1e-6
    if name.startswith("outer") and "sub" in name:
        for spar, x0 in (("front", 0.0), ("rear", g.b)):
            for k, (z0, z1, _) in enumerate(g.z_web.segs):
                sets[f"tip_{spar}_web{k}"] = lambda p, x0=x0, z0=z0, z1=z1: tip(p) and near(p[0], x0) and z0 - 1e-6 <= p[2] <= z1 + 1e-6
            for which, zc in (("upper", g.z_upcap), ("lower", g.z_locap)):
                inside = (lambda p: p[0] <= 1e-6) if spar == "front" else (lambda p: p[0] >= g.b - 1e-6)
                sets[f"tip_{spar}_cap_{which}"] = lambda p, zc=zc, inside=inside: tip(p) and near(p[2], zc) and inside(p)
    return sets


def build_list(g, both):
    """(part name, material, builder) for every part; builder(P) adds the part's blocks."""
    sides = (1, -1) if both else (1,)
    yc = g.y_centre.mirrored() + g.y_centre if both else g.y_centre
    cribs = [g.y_crib, -g.y_crib] if both else [g.y_crib]

    out = [("fuselage", "fuselage", lambda P: [fuselage(P, g, s) for s in sides]),
           ("centre_upper", "upper_skin_centre", lambda P: skin(P, g, yc, g.z_up, 1)),
           ("centre_lower", "lower_skin_centre", lambda P: skin(P, g, yc, g.z_lo, 1)),
           ("centre_sub", "substructure", lambda P: substructure(P, g, yc, cribs, 1))]
    for s in sides:
        t = "" if not both else ("_r" if s > 0 else "_l")
        out += [(f"outer_upper{t}", "upper_skin_outer", lambda P, s=s: skin(P, g, g.y_outer, g.z_up, s)),
                (f"outer_lower{t}", "lower_skin_outer", lambda P, s=s: skin(P, g, g.y_outer, g.z_lo, s)),
                (f"outer_sub{t}", "substructure", lambda P, s=s: substructure(P, g, g.y_outer, g.y_ribs, s)),
                (f"upper_tee{t}", "upper_tee", lambda P, s=s: upper_tee(P, g, s)),
                (f"lower_strap{t}", "lower_strap", lambda P, s=s: lower_strap(P, g, s)),
                (f"front_fitting{t}", "fitting", lambda P, s=s: fitting(P, g, g.x_fit_front, s)),
                (f"rear_fitting{t}", "fitting", lambda P, s=s: fitting(P, g, g.x_fit_rear, s))]
    return out

