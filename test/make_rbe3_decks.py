#!/usr/bin/python3
"""Write the Nastran decks of the RBE3 tests (docs/nastran.md, "RBE3"; test/nastran_model_tests.cmake).

    make_rbe3_decks.py OUTDIR

rbe3-strip.bdf: an aluminium strip (150 x 20 mm, t = 1.27 mm, E = 72000 MPa, nu = 0), 12 x 4 CQUAD4,
  clamped at x = 0 (SPC1 123456), with a bush from the root to a clamped tab (boltnet needs a joint;
  it carries nothing), and three RBE3 whose REFGRIDs are off the centroid of what they average:
  - RBE3 901 over the free edge (x = 150), REFGRID (160, 14, 0), REFC 1246 (grids on one line with
    translations carry no moment about it: components 3 and 5 left out), weights 1 at the corners and
    2 inside (the consistent loads of a uniform edge traction). Subcase 1: FORCE (1, 0, 0) and
    MOMENT (0, 0, 4) on it: the moment cancels the force's offset (M + (x_ref - c) x F = 0 with
    c = (150, 10, 0)), so the strip is in pure tension F = 1.
  - RBE3 902 over the free edge, REFGRID (155, -6, 0), weights 5 at the corners and 12 inside (the
    consistent loads of a linear edge traction on elements of width 5). Subcase 2: MOMENT (0, 0, 1):
    in-plane pure bending M = 1.
  - RBE3 903 over the last two grid lines (x = 137.5, weight 1, and x = 150, weight 3), REFGRID
    (170, 5, 8), REFC 123456. Subcase 3: FORCE (0.3, -0.2, 0.004) and MOMENT (0.5, 0.02, -0.7), a
    general 3-D load for the comparison with FORCE cards computed independently (rbe3_equivalent.py).
  With nu = 0 the exact solutions of subcases 1 and 2 are constant strain and constant in-plane
  curvature states that the elements reproduce (test/check_strip.py tension and inplane).
Bad decks, each refused with the card and its place:
  rbe3-refgrid-undefined.bdf (REFGRID is no grid), rbe3-no-grids.bdf (a weight with no grid),
  rbe3-zero-weight.bdf (WT1 = 0.), rbe3-collinear.bdf (REFC 123456 over the edge: the moment about
  the edge cannot be carried), rbe3-spc.bdf (an SPC on REFGRID's REFC components).
"""
import os
import sys


def real(v):
    s = repr(float(v))
    return s if ("." in s or "e" in s) else s + "."


def card(name, *fields):
    """A free-field card; continuation lines of eight fields start with an empty field."""
    f = ["" if x is None else (real(x) if isinstance(x, float) else str(x)) for x in fields]
    lines = [",".join([name] + f[:8])]
    for i in range(8, len(f), 8):
        lines.append(",".join([""] + f[i:i + 8]))
    return "\n".join(lines) + "\n"


NX, NY, L, W = 12, 4, 150.0, 20.0
CASES = "SPC = 1\nSUBCASE 1\n  LOAD = 1\nSUBCASE 2\n  LOAD = 2\nSUBCASE 3\n  LOAD = 3\n"


def strip(rbe3s, loads, extra=(), cases=CASES):
    """The strip's cards; g[i][j] is the grid at x = L i / NX, y = W j / NY."""
    grids, cards = [], []
    g = [[(NY + 1) * i + j + 1 for j in range(NY + 1)] for i in range(NX + 1)]
    for i in range(NX + 1):
        for j in range(NY + 1):
            grids.append(card("GRID", g[i][j], None, L * i / NX, W * j / NY, 0.0))
    for i in range(NX):
        for j in range(NY):
            cards.append(card("CQUAD4", NY * i + j + 1, 1, g[i][j], g[i + 1][j], g[i + 1][j + 1], g[i][j + 1]))
    cards += [card("PSHELL", 1, 1, 1.27, 1, None, 1), card("MAT1", 1, 72000.0, None, 0.0)]
    cards += [card("SPC1", 1, 123456, g[0][j]) for j in range(NY + 1)]
    # A bush from the clamped root to a clamped tab in the plane x = 0: boltnet's assembly has at
    # least one joint; this one carries nothing.
    tab = [201, 202, 203, 204]
    for t, (y, z) in zip(tab, ((0.0, -10.0), (5.0, -10.0), (5.0, -5.0), (0.0, -5.0))):
        grids.append(card("GRID", t, None, 0.0, y, z))
    cards += [card("CQUAD4", 1000, 2, *tab), card("PSHELL", 2, 1, 1.27, 1, None, 1)]
    cards += [card("PBUSH", 8, "K", 1000.0, 1000.0, 1000.0, 1e5, 1e5, 1e5), card("CBUSH", 1001, 8, g[0][0], tab[3], 1.0, 0.0, 0.0)]
    cards += [card("SPC1", 1, 123456, t) for t in tab]
    for eid, ref, x, refc, groups in rbe3s(g):
        if x is not None:
            grids.append(card("GRID", ref, None, *x))
        fields = [eid, None, ref, refc]
        for w, gs in groups:
            fields += [w, 123] + gs
        cards.append(card("RBE3", *fields))
    cards += loads + list(extra)
    return "SOL 101\nCEND\n" + cases + "BEGIN BULK\n" + "".join(grids) + "".join(cards) + "ENDDATA\n"


def edge(g, corner, inside):
    ends = [g[NX][0], g[NX][NY]]
    return [(corner, ends), (inside, [g[NX][j] for j in range(1, NY)])]


def good(g):
    return [
        (901, 901, (160.0, 14.0, 0.0), 1246, edge(g, 1.0, 2.0)),
        (902, 902, (155.0, -6.0, 0.0), 1246, edge(g, 5.0, 12.0)),
        (903, 903, (170.0, 5.0, 8.0), 123456, [(1.0, [g[NX - 1][j] for j in range(NY + 1)]), (3.0, [g[NX][j] for j in range(NY + 1)])]),
    ]


LOADS = [
    card("FORCE", 1, 901, 0, 1.0, 1.0, 0.0, 0.0),
    card("MOMENT", 1, 901, 0, 4.0, 0.0, 0.0, 1.0),
    card("MOMENT", 2, 902, 0, 1.0, 0.0, 0.0, 1.0),
    card("FORCE", 3, 903, 0, 1.0, 0.3, -0.2, 0.004),
    card("MOMENT", 3, 903, 0, 1.0, 0.5, 0.02, -0.7),
]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)

    def write(name, text):
        with open(os.path.join(out, name), "w") as f:
            f.write(text)

    write("rbe3-strip.bdf", strip(good, LOADS))
    one = [LOADS[0], LOADS[1]]
    at = (160.0, 14.0, 0.0)
    bad = {
        "rbe3-collinear.bdf": (lambda g: [(901, 901, at, 123456, edge(g, 1.0, 2.0))], ()),
        "rbe3-spc.bdf": (lambda g: [(901, 901, at, 1246, edge(g, 1.0, 2.0))], [card("SPC1", 1, 12, 901)]),
        "rbe3-refgrid-undefined.bdf": (lambda g: [(901, 999, None, 1246, edge(g, 1.0, 2.0))], [card("GRID", 901, None, *at)]),
        "rbe3-zero-weight.bdf": (lambda g: [(901, 901, at, 1246, edge(g, 0.0, 0.0))], ()),
        "rbe3-no-grids.bdf": (lambda g: [(901, 901, at, 1246, [(1.0, [])])], ()),
    }
    for name, (rbe3s, extra) in bad.items():
        write(name, strip(rbe3s, one, extra, "SPC = 1\nLOAD = 1\n"))
    print("make_rbe3_decks: rbe3-strip.bdf and the bad RBE3 decks in %s" % out)


if __name__ == "__main__":
    main()
