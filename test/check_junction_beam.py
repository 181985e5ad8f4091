#!/usr/bin/python3
"""The junction's stiffness against beam theory, with every fastener a linear spring, under a pure
bending moment M (scripts/make-wing-fuselage --shear 0 --torque 0, run with NAME.linear.opts).

Requirement: the model's wing boxes bend like the box section they are made of, and the side-of-body
joint adds the compliance of its fasteners. The section rotation about the chord at a station y is
read from fields.h5 as theta(y) = (mean u_y of the lower skin - mean u_y of the upper skin) / h over
the box chord (h the distance between the skins' mid-surfaces).

1. Each box's bending stiffness EI = M / (d theta / dy), fitted over the stations away from the splice
   and the tip, must lie between the beam-theory values of its section (skins, spar webs, caps) with
   the plates free to contract across the span (modulus E, a laminate's 1/(t a_11): the lower bound)
   and held across (E/(1-nu^2), a laminate's A_11/t: the upper bound): where between depends on how
   much the ribs and spars hold the skins' Poisson contraction, which beam theory does not say.
   Tolerance: 5 % below the lower bound, for shear lag (the centre box takes its load through the
   splice plates, nine tenths of the chord, and the spanwise displacement varies by 15 to 20 %,
   standard deviation over mean, across the chord near them, which lowers the effective section by
   a few per cent); 3 % above the upper bound, for the stiffness a coarse mesh adds: on the small
   size (89 x 160 mm elements in the outer box's bays) refining to 44 x 80 mm lowers the outer box's
   EI by 4 % (carbon-epoxy skins: from 1.011 to 0.969 of the upper bound).
2. The joint's rotation dtheta_j = theta(y_o) - theta(y_c) - M (bending of the boxes between the two
   stations, with the fitted EI), y_c and y_o the inner edges of the two splice zones, against the
   estimate from the fastener springs: each skin splice carries F = M / h, through N fasteners in
   parallel on each side of the butt (stiffness kt, identified from the geometry: summary.json) and
   the two sides in series, dtheta = (delta_upper + delta_lower) / h with delta = 2 F / (N kt). The
   estimate leaves out the plates' own compliance in the splice, the secondary bending of the
   eccentric laps (docs/coupling.md: about twice the fastener's compliance on an unsupported single
   lap), shear lag (all softer), the spar splices in parallel and the rigid one-element footprints
   (up to 1.23 kf on coarse meshes, docs/coupling.md; both stiffer). Hence the band 0.7 to 3 for
   dtheta_j / estimate: a gross-error check (a wrong fastener type, missing rows, wrong offsets), not
   a validation of the joint's compliance.

usage: check_junction_beam.py RESULTS_DIR SCENE.yaml
"""
import csv
import json
import os
import sys

import h5py
import numpy as np


def section_EI(m, box, restrained):
    """Bending stiffness of a box section about its E-weighted neutral axis."""
    g, th, E = m["geometry"], m["thickness"], m["moduli"]
    k = 1 if restrained else 0
    Esub = E["sub"] / (1 - 0.33 ** 2) if restrained else E["sub"]
    chord = g["b"] + 2 * g["cap_width"]
    pieces = []   # (E, area, z, own inertia)
    for which, z in (("upper", g["z_up"]), ("lower", g["z_lo"])):
        Es = m["skin_modulus"][f"{which}_skin_{box}"][k]
        t = th[f"{which}_skin"]
        pieces.append((Es, t * chord, z, chord * t ** 3 / 12))
    ts, Hw = th["substructure"], g["z_upcap"] - g["z_locap"]
    for _ in range(2):
        pieces.append((Esub, ts * Hw, (g["z_upcap"] + g["z_locap"]) / 2, ts * Hw ** 3 / 12))
        for z in (g["z_upcap"], g["z_locap"]):
            pieces.append((Esub, ts * g["cap_width"], z, 0.0))
    EA = sum(e * a for e, a, _, _ in pieces)
    zna = sum(e * a * z for e, a, z, _ in pieces) / EA
    return sum(e * (a * (z - zna) ** 2 + i) for e, a, z, i in pieces)


def main():
    res, scene = sys.argv[1], sys.argv[2]
    base = scene[:-5]
    m = json.load(open(base + ".model.json"))
    summary = json.load(open(os.path.join(res, "summary.json")))
    if summary["status"] != "converged" or m["both_sides"]:
        sys.exit("needs a converged run of a half model")
    wing = m["wings"][0]
    M = wing["moment"][0]
    if abs(wing["force"][2]) > 1e-6 * abs(M) / 1000 or abs(wing["moment"][1]) > 1e-9 * abs(M):
        sys.exit("the scene must be loaded by a pure bending moment (--shear 0 --torque 0)")
    g = m["geometry"]
    b, h = g["b"], g["depth"]
    pid = {r["part"]: int(r["id"]) for r in csv.DictReader(l for l in open(base + ".patches.csv") if not l.startswith("#"))}
    f = h5py.File(os.path.join(res, "fields.h5"), "r")
    X, Q, qp = f["shells/coordinates"][:], f["shells/cells"][:], f["shells/part"][:, 0]
    step = sorted(f["steps"].keys())[-1]
    lam = float(f["steps"][step].attrs["load"])
    U = f[f"steps/{step}/shells/displacement"][:]
    Mlam = M * lam

    def theta(box):
        up, lo = (np.unique(Q[qp == pid[f"{box}_{w}"]]) for w in ("upper", "lower"))
        out = []
        for y in np.unique(np.round(X[up, 1], 6)):
            sel = [n[(np.abs(X[n, 1] - y) < 1e-5) & (X[n, 0] > -1e-6) & (X[n, 0] < b + 1e-6)] for n in (up, lo)]
            if all(len(s) for s in sel):
                out.append((y, (U[sel[1], 1].mean() - U[sel[0], 1].mean()) / h))
        return np.array(out)

    ok = True
    wf, yb = g["foot_width"], g["y_butt"]
    regions = {"centre": (0.15 * yb, g["y_centre_rib"] - wf), "outer": (g["y_ribs"][0] + wf, g["y_tip"] - 0.5 * (g["y_ribs"][-1] - g["y_ribs"][-2]))}
    prof, EI = {}, {}
    for box, (y0, y1) in regions.items():
        p = theta(box)
        prof[box] = p
        sel = p[(p[:, 0] >= y0 - 1e-6) & (p[:, 0] <= y1 + 1e-6)]
        if len(sel) < 2:
            sys.exit(f"{box} box: fewer than two stations between y = {y0:.0f} and {y1:.0f}")
        slope = np.polyfit(sel[:, 0], sel[:, 1], 1)[0]
        EI[box] = Mlam / slope
        lo, hi = section_EI(m, box, False), section_EI(m, box, True)
        good = 0.95 * lo <= EI[box] <= 1.03 * hi
        ok &= good
        print(f"{box} box: EI from the model {EI[box]:.4e} N mm2 over {len(sel)} stations (y {sel[0, 0]:.0f} to {sel[-1, 0]:.0f}); "
              f"beam theory {lo:.4e} (skins free across) to {hi:.4e} (held across): ratio {EI[box] / lo:.3f} to the lower bound "
              f"and {EI[box] / hi:.3f} to the upper [{'ok' if good else 'FAIL: outside [0.95 lower, 1.03 upper]'}]")
    yc, yo = g["y_centre_edge"] - g["splice_width"], g["y_outer_edge"] + g["splice_width"]
    tc = np.interp(yc, prof["centre"][:, 0], prof["centre"][:, 1])
    to = np.interp(yo, prof["outer"][:, 0], prof["outer"][:, 1])
    dj = to - tc - Mlam * ((g["y_centre_edge"] - yc) / EI["centre"] + (yo - g["y_outer_edge"]) / EI["outer"])
    meta = list(csv.DictReader(open(base + ".fasteners.csv")))
    kt = {t: p["kt"] for t, p in summary["identified_joint_types"].items()}
    est = 0.0
    for which in ("upper", "lower"):
        delta = 0.0
        for box in ("centre", "outer"):
            fs = [r for r in meta if r["splice"] == f"{which}_{box}" and r["side"] == "right"]
            ks = {kt[r["type"]] for r in fs}
            if max(ks) - min(ks) > 1e-9 * max(ks):
                sys.exit(f"{which}_{box}: joint types of one splice have different stiffnesses")
            delta += (Mlam / h) / (len(fs) * min(ks))
        est += delta / h
    ratio = dj / est
    good = 0.7 <= ratio <= 3.0
    ok &= good
    print(f"joint: rotation across the side-of-body joint {dj:.4e} rad at M = {Mlam:.4e} N mm (stiffness {Mlam / dj:.4e} N mm/rad); "
          f"fasteners in parallel: {est:.4e} rad; ratio {ratio:.3f} [{'ok' if good else 'FAIL: outside [0.7, 3]'}]")
    tip = prof["outer"][-1]
    beam = Mlam * (yb / section_EI(m, "centre", False) + (tip[0] - yb) / section_EI(m, "outer", False)) + est
    print(f"tip rotation {tip[1]:.4e} rad; beam theory (skins free across) plus the fasteners' estimate {beam:.4e} rad: ratio {tip[1] / beam:.3f}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
