#!/usr/bin/python3
"""Replace every RBE3 of a deck by the nodal forces it stands for, computed independently of boltnet.

    rbe3_equivalent.py IN.bdf OUT.bdf

Requirement (docs/nastran.md, "RBE3"): a load on an RBE3's REFGRID acts on the independent grids as
Nastran's weighted least-squares average implies. This script is the textbook form for independent
components 123 (Quick Reference Guide, RBE3): with weights w_i, W = sum w_i, the weighted centroid
c = sum w_i x_i / W, r_i = x_i - c,
    f_i = w_i F / W + w_i (J^+ M_c) x r_i,   M_c = M + (x_ref - c) x F,   J = sum w_i (|r_i|^2 I - r_i r_i^T)
(J^+ the pseudo-inverse: on grids along one line J has no inverse, and M_c has no component along
the line when the RBE3 can carry the load). It reads the free-field decks of test/make_rbe3_decks.py
(GRID in the basic system, RBE3 with Ci = 123, FORCE/MOMENT with CID 0), checks that the forces sum
to F and their moment about REFGRID is M, and writes the deck without its RBE3 cards and with FORCE
cards at the independent grids instead of the loads on the REFGRIDs. Running both decks must give
the same displacements.
"""
import sys

import numpy as np


def cards(text):
    out = []
    for line in text.splitlines():
        if line.startswith(","):
            out[-1] += line.split(",")[1:]
        elif line and line[0].isalpha():
            out.append(line.split(","))
    return out


def main():
    src, dst = sys.argv[1], sys.argv[2]
    text = open(src).read()
    head, bulk = text.split("BEGIN BULK\n")
    grids, rbe3, loads = {}, {}, {}
    for c in cards(bulk):
        if c[0] == "GRID":
            grids[int(c[1])] = np.array([float(v) for v in c[3:6]])
        elif c[0] == "RBE3":
            ref, weights, k = int(c[3]), {}, 5
            while k < len(c) and c[k]:
                w = float(c[k])
                if c[k + 1] != "123":
                    sys.exit(f"rbe3_equivalent: RBE3 {c[1]}: C = {c[k + 1]}, only 123 is handled here")
                k += 2
                while k < len(c) and c[k] and "." not in c[k]:
                    weights[int(c[k])] = weights.get(int(c[k]), 0.0) + w
                    k += 1
            rbe3[ref] = weights
        elif c[0] in ("FORCE", "MOMENT"):
            sid, g = int(c[1]), int(c[2])
            assert c[3] in ("", "0")
            v = float(c[4]) * np.array([float(x) for x in c[5:8]])
            l = loads.setdefault((sid, g), [np.zeros(3), np.zeros(3)])
            l[c[0] == "MOMENT"] += v
    extra = []
    for (sid, ref), (F, M) in sorted(loads.items()):
        if ref not in rbe3:
            continue
        ids = sorted(rbe3[ref])
        w = np.array([rbe3[ref][i] for i in ids])
        x = np.array([grids[i] for i in ids])
        W = w.sum()
        c = (w[:, None] * x).sum(axis=0) / W
        r = x - c
        J = sum(wi * (ri @ ri * np.eye(3) - np.outer(ri, ri)) for wi, ri in zip(w, r))
        Mc = M + np.cross(grids[ref] - c, F)
        omega = np.linalg.pinv(J, rcond=1e-10) @ Mc
        f = w[:, None] * F / W + w[:, None] * np.cross(omega, r)
        scale = np.linalg.norm(F) + np.linalg.norm(M) / np.sqrt((w * (r * r).sum(axis=1)).sum() / W)
        df = np.abs(f.sum(axis=0) - F).max()
        dm = np.abs(np.cross(x - grids[ref], f).sum(axis=0) - M).max()
        print(f"rbe3_equivalent: set {sid}, REFGRID {ref}: {len(ids)} grids, |sum f - F| = {df:.1e}, |sum r x f - M| = {dm:.1e}")
        if df > 1e-12 * scale or dm > 1e-12 * scale * np.abs(x - grids[ref]).max():
            sys.exit(f"rbe3_equivalent: set {sid}, REFGRID {ref}: the forces do not reproduce F and M (the RBE3 cannot carry this load)")
        for i, fi in zip(ids, f):
            extra.append("FORCE,%d,%d,0,1.0,%r,%r,%r\n" % (sid, i, fi[0], fi[1], fi[2]))
    keep = []
    for line in bulk.splitlines(True):
        name = line.split(",")[0]
        if name == "RBE3" or (name in ("FORCE", "MOMENT") and int(line.split(",")[2]) in rbe3):
            keep.append(None)  # this card and its continuations go
            continue
        if line.startswith(",") and keep and keep[-1] is None:
            continue
        keep.append(line)
    body = "".join(l for l in keep if l is not None).replace("ENDDATA\n", "".join(extra) + "ENDDATA\n")
    with open(dst, "w") as f:
        f.write(head + "BEGIN BULK\n" + body)


if __name__ == "__main__":
    main()
