"""The macroelement laws, written from docs/joint-laws.md for the independent network reference.

Each law maps (parameters, committed slip w_n, local jump du = (du_n, du_t1, du_t2)) to the local
force on node B, its derivative with respect to du at fixed history, the trial slip, the state and
the distances to the thresholds that decide the state (used by the comparison to recognise a joint
that sits on a threshold). Nothing here is committed: network.py commits the trial slips of a load
step only once the step has converged.

The in-plane force of the frictional law (docs/joint-laws.md, "Frictional contact"):
    G    = mu nf max(0, Pc - phi F_n),  F_n = kn du_n
    F_tr = ke (du_t - w_n); stick (w = w_n) if |F_tr| <= G, else slide by radial return:
           n = F_tr/|F_tr|, F_f = G n, w = du_t - G n / ke
    h(w) = kg w + (kc - kg) <|w - c| - j>+ (w - c)/|w - c|     (regularisation, then bearing)
    F_t  = F_f + h(w)
The derivatives below are this reference's own (by the chain rule on the formulas above); network.py
checks them against finite differences of the forces (--selftest).
"""
import numpy as np

I2 = np.eye(2)


def bearing_term(w, c, j, k_out, k_in):
    """(k_out - k_in) <|w - c| - j>+ m and its derivative in w; r = |w - c| (the clearance circle)."""
    d = w - c
    r = float(np.hypot(d[0], d[1]))
    if r <= j or k_out == k_in:
        return np.zeros(2), np.zeros((2, 2)), r
    m = d / r
    value = (k_out - k_in) * (r - j) * m
    # d/dw [(r - j) m] = m m^T + (r - j)/r (I - m m^T) = I - (j/r)(I - m m^T)
    deriv = (k_out - k_in) * (I2 - (j / r) * (I2 - np.outer(m, m)))
    return value, deriv, r


def evaluate(p, w_n, du):
    """Returns (force (3), tangent (3x3) dF/ddu, trial slip (2), state, bearing, margins).

    margins: {'slip': |F_tr| - G (friction), 'gap': r - j (friction: slip circle; contact: jump
    circle)} in force and length units, for the comparison's threshold detection."""
    law = p["law"]
    kn, kt = p["kn"], p["kt"]
    c = np.array([p["offset_t1"], p["offset_t2"]])
    dun, dut = du[0], np.asarray(du[1:3], dtype=float)
    K = np.zeros((3, 3))
    K[0, 0] = kn
    fn = kn * dun
    if law == "spring":
        K[1:, 1:] = kt * I2
        return np.array([fn, *(kt * dut)]), K, np.zeros(2), "linear", 0, {}
    if law == "contact":
        j = p["gap"]
        extra, dextra, r = bearing_term(dut, c, j, p["kc"], kt)
        K[1:, 1:] = kt * I2 + dextra
        state = "contact" if r > j else "open"
        return np.array([fn, *(kt * dut + extra)]), K, np.zeros(2), state, int(r > j), {"gap": r - j}
    # Frictional contact.
    ke, kg, kc, j = kt, p["kg"], p["kc"], p["gap"]
    clamp = p["mu"] * p["nf"] * (p["pretension"] - p["clamp_coupling"] * fn)
    G = max(0.0, clamp)
    dG_ddun = -p["mu"] * p["nf"] * p["clamp_coupling"] * kn if clamp > 0 else 0.0
    w_n = np.asarray(w_n, dtype=float)
    ftr = ke * (dut - w_n)
    a = float(np.hypot(ftr[0], ftr[1]))
    if a <= G:
        w, ff = w_n.copy(), ftr
        dff_dut, dff_dun = ke * I2, np.zeros(2)
        dw_dut, dw_dun = np.zeros((2, 2)), np.zeros(2)
        slipped = False
    else:
        n = ftr / a
        P = I2 - np.outer(n, n)
        ff = G * n
        w = dut - G * n / ke
        dff_dut, dff_dun = (G * ke / a) * P, n * dG_ddun
        dw_dut, dw_dun = I2 - (G / a) * P, -n * dG_ddun / ke
        slipped = True
    bear, dbear, r = bearing_term(w, c, j, kc, kg)
    h = kg * w + bear
    Hw = kg * I2 + dbear
    K[1:, 1:] = dff_dut + Hw @ dw_dut
    K[1:, 0] = dff_dun + Hw @ dw_dun
    state = ("contact" if r > j else "slide") if slipped else "stick"
    return np.array([fn, *(ff + h)]), K, w, state, int(r > j), {"slip": a - G, "gap": r - j}
