"""Derived geometry of the junction: positions of every surface and the grids they are meshed on.

Axes: x aft along the fuselage (x = 0 at the front spar), y to the right (outboard of the right wing),
z up; the fuselage axis is the x axis. Angles th on the fuselage are measured from +y towards +z
(y = r cos th, z = r sin th). The right half (y >= 0) is built; the left half of a both-sides model is
its mirror image y -> -y (th -> pi - th).

Surfaces are mid-surfaces. Parts that lie on each other (a splice plate on a skin) are offset along
their normal by the sum of their half thicknesses, as share/scenes/fig3a does with two plates.
"""
import math

from .grids import Grid


class Geometry:
    def __init__(self, a):
        self.a = a
        t = a.thickness
        self.R = a.radius
        self.b = a.frame_pitch * a.box_bays                       # front spar x = 0, rear spar x = b
        # The upper tee's stem runs along the fuselage contour just inside the fuselage skin; the butt
        # line y_b is where it crosses the upper skin's mid-surface.
        self.Rs = self.R - (t["fuselage"] + t["upper_tee"]) / 2
        self.yb = a.butt_line
        if not self.yb < self.Rs:
            raise ValueError(f"--butt-line {self.yb} must be less than the fuselage radius")
        self.z_up = -math.sqrt(self.Rs ** 2 - self.yb ** 2)
        self.z_lo = self.z_up - a.box_depth
        self.z_upcap = self.z_up - (t["upper_skin"] + t["substructure"]) / 2   # caps and rib feet
        self.z_locap = self.z_lo + (t["lower_skin"] + t["substructure"]) / 2
        self.z_us = self.z_up - (t["upper_skin"] + t["upper_tee"]) / 2         # upper tee flange
        self.z_ls = self.z_lo + (t["lower_skin"] + t["lower_strap"]) / 2       # lower strap
        self.th_strap = math.asin(self.z_us / self.Rs)
        self.y_stem = self.Rs * math.cos(self.th_strap)                         # fold of the tee
        g = a.butt_gap
        self.y_ci, self.y_oi = self.yb - g / 2, self.yb + g / 2                 # skin edges at the butt
        # The stem crosses the skin between th(z_up - t/2) and th(z_up + t/2); it must pass the gap.
        ts = t["upper_skin"]
        ys = [self.Rs * math.cos(math.asin((self.z_up + s * ts / 2) / self.Rs)) for s in (-1, 1)]
        half = t["upper_tee"] / 2 / math.cos(math.asin(self.z_up / self.Rs))
        if not (self.y_ci < min(ys + [self.y_stem]) - half and max(ys + [self.y_stem]) + half < self.y_oi):
            raise ValueError(f"--butt-gap {g} is too small for the tee's stem to pass between the skins "
                             f"(the stem crosses the skins at y = {min(ys):.1f} to {max(ys):.1f}, {2 * half:.1f} mm thick)")
        # Fuselage skin edge above the wing (clear of the upper skin's top face by a.fuselage_clearance).
        self.th_e = math.asin((self.z_up + ts / 2 + a.fuselage_clearance) / self.R)
        self.grids()

    # -- grids ------------------------------------------------------------------------------------
    def grids(self):
        a, b = self.a, self.b
        self.hx = b / a.nx
        wc = a.cap_width
        self.x_cap_front = Grid([(-wc, 0, 2)])
        self.x_cap_rear = Grid([(b, b + wc, 2)])
        self.x_box = Grid([(0, b, a.nx)])
        self.x_skin = self.x_cap_front + self.x_box + self.x_cap_rear
        self.x_sub = Grid([(0, b, a.nx // a.rib_coarsening)])                  # rib webs and feet
        i0 = max(1, math.ceil((self.a.thickness["substructure"] / 2 + self.a.thickness["fitting"] + 5) / self.hx))
        self.x_s0, self.x_s1 = i0 * self.hx, b - i0 * self.hx                   # straps and stem
        self.x_strap = Grid([(self.x_s0, self.x_s1, a.nx - 2 * i0)])
        self.hy = a.row_spacing_skin / 2
        self.W = (2 * a.rows + 1) * self.hy                                     # splice zone, one side
        wf, hc = a.foot_width, a.coarse
        # Centre box (right half): coarse, the centre box's side rib, transition, splice zone.
        ys0 = self.y_ci - self.W
        self.y_crib = ys0 - self.hy - wf
        c = Grid().add_size(0, self.y_crib - wf, hc).add(self.y_crib - wf, self.y_crib, 2).add(self.y_crib, self.y_crib + wf, 2)
        c.add_size(self.y_crib + wf, ys0, self.hy).add(ys0, self.y_ci, 2 * a.rows + 1)
        self.y_centre = c
        # Outer box: splice zone, transition, root rib, bays, tip rib.
        ye = self.y_oi + self.W
        self.y_ribs = [ye + self.hy + wf + k * a.rib_pitch for k in range(a.rib_bays + 1)]
        self.y_tip = self.y_ribs[-1]
        o = Grid().add(self.y_oi, ye, 2 * a.rows + 1).add_size(ye, self.y_ribs[0] - wf, self.hy)
        for k, yr in enumerate(self.y_ribs):
            o.add(yr - wf, yr, 2)
            if k < len(self.y_ribs) - 1:
                o.add(yr, yr + wf, 2).add_size(yr + wf, self.y_ribs[k + 1] - wf, hc)
        self.y_outer = o
        # Splice plates span both splice zones and the butt gap; the tee's flange is folded at y_stem.
        self.y_splice_c = Grid([(ys0, self.y_ci, 2 * a.rows + 1)])
        self.y_splice_o = Grid([(self.y_oi, ye, 2 * a.rows + 1)])
        self.y_tee = self.y_splice_c + Grid([(self.y_ci, self.y_stem, 1), (self.y_stem, self.y_oi, 1)]) + self.y_splice_o
        self.y_strap = self.y_splice_c + Grid([(self.y_ci, self.y_oi, 1)]) + self.y_splice_o
        # Webs (spars, ribs, spar fittings).
        self.hz = (self.z_upcap - self.z_locap) / a.nz
        # One segment per element, so that each element edge of a web's tip is a curve (a node set that
        # takes its share of the tip load: loads.py).
        zk = [self.z_locap + (self.z_upcap - self.z_locap) * k / a.nz for k in range(a.nz + 1)]
        self.z_web = Grid([(zk[k], zk[k + 1], 1) for k in range(a.nz)])
        self.z_fit = Grid([(self.z_locap + self.hz, self.z_upcap - self.hz, a.nz - 2)])
        self.x_fit_front = (self.a.thickness["substructure"] + self.a.thickness["fitting"]) / 2
        self.x_fit_rear = b - self.x_fit_front
        self.fuselage_grids()

    def fuselage_grids(self):
        a, b, R = self.a, self.b, self.R
        p, wc = a.frame_pitch, a.cap_width
        # x: frame bays; the box chord on the box's own grid (coarsened by an odd factor, so that the
        # fuselage's element centres over the stem are the stem's).
        self.frames = [k * p for k in range(-a.fuselage_bays, a.box_bays + a.fuselage_bays + 1)]
        x = Grid()
        nb = max(1, round(p / a.fuselage_h))
        for k in range(-a.fuselage_bays, -1):
            x.add(k * p, (k + 1) * p, nb)
        x.add_size(-p, -wc, a.fuselage_h).add(-wc, 0, 1)
        per_bay = a.nx // a.box_bays // a.fuselage_coarsening
        for k in range(a.box_bays):
            x.add(k * p, (k + 1) * p, per_bay)
        x.add(b, b + wc, 1).add_size(b + wc, b + p, a.fuselage_h)
        for k in range(a.box_bays + 1, a.box_bays + a.fuselage_bays):
            x.add(k * p, (k + 1) * p, nb)
        self.x_fus = x
        self.x_cut = (-wc, b + wc)                                             # lower-lobe cut-out
        # th: stringer bays in the lower lobe, the cut-out edge, the lap on the tee's stem, the upper lobe.
        ds = a.stringer_pitch / R
        hth = a.row_spacing_fuselage / 2 / R
        self.th_top = self.th_e + (2 * a.fuselage_rows + 1) * hth               # stem top
        self.th_ftop = self.th_top + a.fuselage_h / R                           # frames end above the stem
        lo = [-math.pi / 2 + j * ds for j in range(0, 200) if -math.pi / 2 + j * ds < self.th_e - 0.5 * ds]
        up = [math.pi / 2 - j * ds for j in range(0, 200) if math.pi / 2 - j * ds > self.th_ftop + 0.5 * ds][::-1]
        th = Grid()
        for t0, t1 in zip(lo[:-1], lo[1:]):
            th.add(t0, t1, a.fuselage_sub)
        th.add_size(lo[-1], self.th_e, a.fuselage_h / R)
        th.add(self.th_e, self.th_top, 2 * a.fuselage_rows + 1)
        th.add(self.th_top, self.th_ftop, 1).add_size(self.th_ftop, up[0], a.fuselage_h / R)
        for t0, t1 in zip(up[:-1], up[1:]):
            th.add(t0, t1, a.fuselage_sub)
        self.th_fus = th
        self.stringers_lo = lo[1:]          # not at the keel (y = 0): a blade there lies in the symmetry plane
        self.stringers_up = up[:-1]
        # The frames at the spars, fastened to the spar webs (--spar-frames fastened), go on below the
        # cut-out's edge inside the box, from the first frame node whose outer edge is above the lower
        # skin's mid-surface, on a grid of their own there (no skin shares it): elements of about half
        # the fastener pitch along the frame, no finer than a quarter of the fuselage's element.
        starts = [seg[0] for seg in th.segs if seg[0] < self.th_e - 1e-12 and R * math.sin(seg[0]) >= self.z_lo]
        self.th_spar_frame = min(starts) if starts and a.spar_frames == "fastened" else self.th_e
        rf = R - a.frame_depth / 2
        h = max(a.pitch * a.d_spar / 2, a.fuselage_h / 4) / rf
        self.th_spar_grid = Grid().add_size(self.th_spar_frame, self.th_e, h) if self.th_spar_frame < self.th_e else None
        self.th_stem = Grid().add_size(self.th_strap, self.th_e, a.fuselage_h / R).add(self.th_e, self.th_top, 2 * a.fuselage_rows + 1)
        self.x_min, self.x_max = self.frames[0], self.frames[-1]
