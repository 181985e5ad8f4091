"""Fasteners of the junction: where they are, which joint type each one is, and the types' parameters.

Every fastener sits at the centre of an element of both parts it joins (the grids of geometry.py are
built so that those centres coincide), on the bolt axis half-way between the two mid-surfaces. With a
footprint radius (-coupling_radius) smaller than half the smallest element, boltnet's footprint of a
fastener is then exactly that element on each part (docs/coupling.md, "Footprints on coarse meshes"),
and fasteners two or more elements apart have disjoint footprints.

Junction fasteners (the side-of-body joint) are frictional joint types identified from the geometry at
start-up (`from: geometry`, docs/identify.md), one per family; the clearance of each fastener, drawn
from a tolerance band with a seed, is its own, in the fastener table's column `gap` (or, with
--clearance-bins N, binned into N joint types per family); the drawn value is also kept in the
metadata table. The fasteners that attach each box's substructure to its skins are linear springs
(law spring) with Huth's stiffness: they are not the subject of the study and stay stuck far from
the joint ("model no more than a scene needs").
"""
import math

import numpy as np

# Installation torque (N mm) by diameter (mm): representative collar break-off torques of titanium
# Hi-Lok fasteners (about 35, 70 and 125 lbf in); the data sheet of the actual collar replaces them.
TORQUE = {4.8: 4000.0, 6.35: 8000.0, 7.94: 14000.0}
# Huth's constants (ASTM STP 927, 1986): a, b for bolted metal and bolted graphite/epoxy.
HUTH = {"bolted-metal": (2.0 / 3.0, 3.0), "bolted-composite": (2.0 / 3.0, 4.2)}


def huth_k(d, t1, t2, E1, E2, Ef, kind):
    """Huth's single-shear stiffness (N/mm), as docs/identify.md writes it."""
    a, b = HUTH[kind]
    C = ((t1 + t2) / (2 * d)) ** a * b * (1 / (t1 * E1) + 1 / (t2 * E2) + 1 / (2 * t1 * Ef) + 1 / (2 * t2 * Ef))
    return 1 / C


def axial_k(d, t1, t2, Ef):
    return Ef * math.pi * d * d / 4 / (t1 + t2)


def laminate_modulus(layup, ply, angle_of_load):
    """Membrane moduli of a laminate along `angle_of_load` (degrees from the ply reference), by
    classical lamination theory (docs/shell.md): free to contract across, 1 / (t (A^-1)_11), and
    held across (no transverse strain), A_11 / t, in axes turned to the load direction."""
    E1, E2, nu12, G12 = ply["E1"], ply["E2"], ply["nu12"], ply["G12"]
    nu21 = nu12 * E2 / E1
    den = 1 - nu12 * nu21
    Q = np.array([[E1 / den, nu12 * E2 / den, 0], [nu12 * E2 / den, E2 / den, 0], [0, 0, G12]])
    A = np.zeros((3, 3))
    for ang in layup:
        c, s = math.cos(math.radians(ang - angle_of_load)), math.sin(math.radians(ang - angle_of_load))
        T = np.array([[c * c, s * s, 2 * c * s], [s * s, c * c, -2 * c * s], [-c * s, c * s, c * c - s * s]])
        R = np.diag([1, 1, 2])
        Qb = np.linalg.inv(T) @ Q @ R @ T @ np.linalg.inv(R)
        A += Qb * ply["t"]
    t = ply["t"] * len(layup)
    return 1 / (t * np.linalg.inv(A)[0, 0]), A[0, 0] / t


class Fastener:
    __slots__ = ("id", "a", "b", "n", "t1", "x", "family", "splice", "side", "row", "index", "pos", "d", "clearance", "gap", "type", "elem_a", "elem_b")

    def __init__(self, **kw):
        for k in self.__slots__:
            setattr(self, k, kw.get(k))


def pick(centres, every, margin=1):
    """Every `every`-th of the centres, keeping `margin` centres free at both ends, centred."""
    n = len(centres) - 2 * margin
    if n <= 0:
        return []
    first = margin + ((n - 1) % every) // 2
    return list(centres[first:len(centres) - margin:every])


def spaced(centres, pitch, lo, hi):
    """Centres in (lo, hi) at least `pitch` apart and never in neighbouring elements."""
    out, last, lastk = [], -1e30, -10
    for k, c in enumerate(centres):
        if lo < c < hi and c - last >= pitch - 1e-9 and k - lastk >= 2:
            out.append(c)
            last, lastk = c, k
    return out


def place(g, both):
    """All fasteners, in a deterministic order; ids are given by the caller."""
    a = g.a
    out = []
    sides = (1, -1) if both else (1,)
    for s in sides:
        t = "" if not both else ("_r" if s > 0 else "_l")
        side = "right" if s > 0 else "left"
        tee, strap = f"upper_tee{t}", f"lower_strap{t}"
        xs_all = g.x_box.centres(g.x_s0, g.x_s1)
        kp = max(2, round(a.pitch_skin / g.hx))
        xs = pick(xs_all, kp)
        for box, yedge, sgn in (("centre", g.y_ci, -1), ("outer", g.y_oi, 1)):
            skin_u = "centre_upper" if box == "centre" else f"outer_upper{t}"
            skin_l = "centre_lower" if box == "centre" else f"outer_lower{t}"
            sub = "centre_sub" if box == "centre" else f"outer_sub{t}"
            for r in range(a.rows):
                y = yedge + sgn * (2 * r + 1.5) * g.hy
                for skin, plate, zs, zp, fam in ((skin_u, tee, g.z_up, g.z_us, "u"), (skin_l, strap, g.z_lo, g.z_ls, "l")):
                    for k, x in enumerate(xs):
                        out.append(Fastener(a=skin, b=plate, n=(0, 0, 1), t1=(0, s, 0), x=(x, s * y, (zs + zp) / 2),
                                            family=fam + box[0], splice=f"{'upper' if fam == 'u' else 'lower'}_{box}", side=side,
                                            row=r + 1, index=k + 1, pos=x, d=a.d_skin))
                # Spar splice: a column of fasteners under each skin row, through web and fitting.
                zs_all = g.z_web.centres()
                kz = max(2, round(a.pitch_spar / g.hz))
                zc = pick(zs_all, kz, margin=2)
                for x0, xf, spar in ((0.0, g.x_fit_front, "front"), (g.b, g.x_fit_rear, "rear")):
                    for k, z in enumerate(zc):
                        out.append(Fastener(a=sub, b=f"{spar}_fitting{t}", n=(1, 0, 0), t1=(0, s, 0), x=((x0 + xf) / 2, s * y, z),
                                            family="s" + box[0], splice=f"{spar}_spar_{box}", side=side, row=r + 1, index=k + 1,
                                            pos=z, d=a.d_spar))
        # Fuselage skin on the tee's stem: rows along x at the lap's odd elements.
        hth = (g.th_top - g.th_e) / (2 * a.fuselage_rows + 1)
        xf_all = [c for c in g.x_fus.centres() if g.x_s0 < c < g.x_s1]
        kf = max(2, round(a.pitch_fuselage / (g.hx * a.fuselage_coarsening)))
        for r in range(a.fuselage_rows):
            th = g.th_e + (2 * r + 1.5) * hth
            n = (0.0, s * math.cos(th), math.sin(th))
            rm = (g.R + g.Rs) / 2
            for k, x in enumerate(pick(xf_all, kf)):
                out.append(Fastener(a="fuselage", b=tee, n=n, t1=(1, 0, 0), x=(x, s * rm * math.cos(th), rm * math.sin(th)),
                                    family="fu", splice="fuselage_lap", side=side, row=r + 1, index=k + 1, pos=x, d=a.d_fuselage))
        out += spar_frames(g, s, side)
        out += attachments(g, s, t, side)
    return out


def spar_frames(g, s, side):
    """The fuselage frames at the spars on the centre box's spar webs (--spar-frames fastened): one
    row along the frame at the middle of its inner element, every other frame element, where the web
    is clear of its caps (two web elements) and of the spar splice's zone. The frame lies in the web's
    plane (their 5 mm offset is left out: the row carries shear in that plane), so a fastener joins
    two sheets at the same x; its footprint is the element holding it on each."""
    a = g.a
    if a.spar_frames != "fastened" or g.th_spar_grid is None:
        return []
    r_in, r_st = g.R - a.frame_depth, g.R - a.stringer_depth
    rf = (r_in + r_st) / 2 if a.frame_depth > a.stringer_depth + 1e-9 else (r_in + g.R) / 2
    ys0 = g.y_ci - g.W                                        # the spar splice's zone starts here
    yn, zn = g.y_centre.nodes(), g.z_web.nodes()
    clear = lambda y, z: min(abs(yn - y)) > 2 * a.coupling_radius or min(abs(zn - z)) > 2 * a.coupling_radius
    ok = lambda y, z: g.z_locap + 2 * g.hz < z < g.z_upcap - 2 * g.hz and y < ys0 - 2 * g.hy and clear(y, z)
    web = lambda y, z: (int(np.searchsorted(yn, y)), int(np.searchsorted(zn, z)))   # the web element holding it
    # From the top down: at least the pitch apart, two or more frame elements apart, and never in
    # neighbouring web elements (footprints share no node on either part).
    ths, last, lastk, used = [], 1e30, -10, []
    for k, th in enumerate(sorted(g.th_spar_grid.centres(), reverse=True)):
        y, z = rf * math.cos(th), rf * math.sin(th)
        w = web(y, z)
        if (ok(y, z) and k - lastk >= 2 and rf * (last - th) >= a.pitch_spar - 1e-9
                and all(abs(w[0] - u[0]) > 1 or abs(w[1] - u[1]) > 1 for u in used)):
            ths.append(th)
            last, lastk = th, k
            used.append(w)
    out = []
    for x0, spar in ((0.0, "front"), (g.b, "rear")):
        for k, th in enumerate(ths):
            z = rf * math.sin(th)
            out.append(Fastener(a="centre_sub", b="fuselage", n=(1, 0, 0), t1=(0, s, 0), x=(x0, s * rf * math.cos(th), z),
                                family="ff", splice=f"{spar}_frame", side=side, row=1, index=k + 1, pos=z, d=a.d_spar))
    return out


def attachments(g, s, t, side):
    """Substructure to skins: spar caps (one row per cap) and rib feet (one row each side of a rib)."""
    a, out = g.a, []
    wc, wf = a.cap_width, a.foot_width
    for box, ygrid, ribs in (("centre", g.y_centre, [g.y_crib]), ("outer", g.y_outer, g.y_ribs)):
        sub = "centre_sub" if box == "centre" else f"outer_sub{t}"
        yn = ygrid.nodes()
        yc = ygrid.centres()
        # Keep clear of the first and last element (the symmetry plane, the tip, the butt edge).
        ys = spaced(yc, a.attach_pitch, yn[0] + 1.01 * (yn[1] - yn[0]), yn[-1] - 1.01 * (yn[-1] - yn[-2]))
        for which, zs, zc in (("upper", g.z_up, g.z_upcap), ("lower", g.z_lo, g.z_locap)):
            skin = f"{box}_{which}" if box == "centre" else f"outer_{which}{t}"
            fam = "a" + which[0] + box[0]
            for xcap, cap in ((-0.75 * wc, "front_cap"), (g.b + 0.75 * wc, "rear_cap")):
                for k, y in enumerate(ys):
                    out.append(Fastener(a=skin, b=sub, n=(0, 0, 1), t1=(0, s, 0), x=(xcap, s * y, (zs + zc) / 2), family=fam,
                                        splice=f"{box}_{which}_{cap}", side=side, row=1, index=k + 1, pos=y, d=a.d_attach))
            xr = pick(g.x_sub.centres(), max(2, round(a.attach_pitch / (g.hx * a.rib_coarsening))))
            for ri, yr in enumerate(ribs):
                feet = (-1,) if yr == ribs[-1] and box == "outer" else (-1, 1)
                for f in feet:
                    y = yr + f * 0.75 * wf
                    for k, x in enumerate(xr):
                        out.append(Fastener(a=skin, b=sub, n=(0, 0, 1), t1=(1, 0, 0), x=(x, s * y, (zs + zc) / 2), family=fam,
                                            splice=f"{box}_{which}_rib{ri + 1}", side=side, row=1 if f < 0 else 2, index=k + 1,
                                            pos=x, d=a.d_attach))
    return out


def assign_types(fasteners, a):
    """Junction fasteners: a clearance drawn from [clearance_min, clearance_max] (diametral, mm) with
    the seed. With a.clearance_bins 0 (the default) each fastener keeps its own: one joint type per
    family (its hole the band's middle) and the fastener's gap, half its clearance, in the fastener
    table's column `gap` (docs/scenes.md, "Per-joint parameters"). With N > 0 the clearances are
    binned into N joint types per family instead, each with its bin's middle. Interference fit: one
    type, no clearance. Attachment fasteners: one linear type per family. Returns the clearance of
    each type's hole: the band's middle, or the bins' middles."""
    rng = np.random.default_rng(a.seed)
    per_joint = a.clearance_bins == 0
    edges = np.linspace(a.clearance_min, a.clearance_max, max(1, a.clearance_bins) + 1)
    for f in fasteners:
        f.gap = None
        if f.family.startswith("a"):
            f.type, f.clearance = f.family, 0.0
        elif a.fit == "interference":
            f.type, f.clearance = f.family + "i", 0.0
        else:
            c = rng.uniform(a.clearance_min, a.clearance_max)
            if per_joint:
                f.type, f.clearance, f.gap = f.family, c, c / 2
            else:
                k = min(int(np.searchsorted(edges, c, side="right")) - 1, a.clearance_bins - 1)
                f.type, f.clearance = f"{f.family}{k + 1}", c
    return [0.5 * (edges[k] + edges[k + 1]) for k in range(len(edges) - 1)]
