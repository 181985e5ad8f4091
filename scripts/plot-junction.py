#!/usr/bin/python3
"""Charts of a wing-fuselage junction run (scenes of scripts/make-wing-fuselage; docs/wing-fuselage.md).

  scripts/plot-junction.py RESULTS_DIR SCENE.yaml -o OUT_DIR [--compare LINEAR_RESULTS_DIR] [--levels 1,2.5,-1]

reads RESULTS_DIR/{joints.csv (or the joint table joints.h5),summary.json,fields.h5} and the scene's metadata (NAME.fasteners.csv,
NAME.model.json), and writes into OUT_DIR:

- load-transfer.png: the load of each fastener (signed: spanwise on the skin splices, vertical
  on the spar splices and the spar frames, around the fuselage on the lap) along each row of the
  side-of-body splices (upper and lower skins, spars, fuselage lap, spar frames) at each load
  level: the classic chart where the end fasteners of a row carry most; with --compare, the same
  model with every fastener a linear spring (a run with NAME.linear.opts at load factor 1, scaled
  to each level) as dashed lines;
- row-share.png: the share of a splice side's load carried by each row (the multi-row joint's
  load transfer), at each load level, with the linear model;
- states.png: maps of the joint states (stick, slide, bearing) over the junction at each level;
- most-loaded.csv and most-loaded.png: per row, the most loaded fastener over the load path, its
  margin to slip (1 - |F|/G: negative once it has slid) and to bearing (clearance j minus the slip
  |w|, mm: zero or less when the bolt bears);
- junction.png: one picture of the run (the upper outer splice and the lap along their rows, the
  skin splices' states at the highest level, the hysteresis);
- bypass.png: along each row of the skin splices at the highest level, the load each fastener
  takes out of the skin and the bypass load that passes its hole in the skin's strip (bypass.csv,
  else fields.h5; the strip is the scene's -output_bypass_width, the splices' pitch along a row);
- hysteresis.png: the joint's overall deflection over the load cycle: the rotation across the
  side-of-body joint (from the skins' spanwise displacements on either side of the splices,
  fields.h5) against the load factor, with the linear model;
- springs.csv (with --compare): what the linear springs get right and wrong, per splice and level:
  the splice's whole load (the sum of its fasteners' in-plane forces), each row's share of it, the
  most loaded fastener, the range of each fastener's load over its spring's, the largest difference
  between neighbours along a row in the middle half of the row (over the row's mean load:
  clearances make neighbours differ, springs do not), and the counts of sticking, sliding and
  bearing fasteners; and, at the last step of the load path, the largest force left in each splice
  (springs leave none when unloaded).
Only the right wing is charted for a model with both wings.
"""
import argparse
import csv
import json
import math
import os
import sys

try:
    import h5py
    import numpy as np
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError as e:
    sys.exit(f"plot-junction.py: cannot import {e.name or e}: install python3-matplotlib, python3-numpy and python3-h5py (scripts/deps)")

STATE = {"stick": ("tab:blue", "stick"), "slide": ("tab:red", "slide"), "contact": ("tab:green", "bearing"),
         "linear": ("tab:gray", "linear"), "open": ("tab:orange", "open")}
SPLICES = ["upper_outer", "upper_centre", "lower_outer", "lower_centre", "front_spar_outer", "front_spar_centre",
           "rear_spar_outer", "rear_spar_centre", "fuselage_lap", "front_frame", "rear_frame"]


def table_rows(path):
    """joints.h5 (-output_joints hdf5, docs/output.md "The joint table") as joints.csv's rows."""
    with h5py.File(path, "r") as f:
        names = [n.decode() if isinstance(n, bytes) else str(n) for n in f["state_names"][()]]
        step, load, ids = f["step"][()], f["load"][()], f["joint"][()]
        state, bearing, jump, force, slip = (f[k][()] for k in ("state", "bearing", "jump", "force", "slip"))
    cols = ["du_n", "du_t1", "du_t2", "f_n", "f_t1", "f_t2", "slip_t1", "slip_t2"]
    for s in range(len(step)):
        for j, jid in enumerate(ids):
            vals = [*jump[s, j, :3], *force[s, j, :3], *slip[s, j]]
            yield {"step": str(step[s]), "load": repr(float(load[s])), "joint": str(jid), "state": names[state[s, j]],
                   "bearing": str(bearing[s, j]), **{c: repr(float(v)) for c, v in zip(cols, vals)}}


def read_run(res):
    table = os.path.join(res, "joints.h5")
    use_table = not os.path.exists(os.path.join(res, "joints.csv")) and os.path.exists(table)
    for f in ("summary.json",) if use_table else ("joints.csv", "summary.json"):
        if not os.path.exists(os.path.join(res, f)):
            sys.exit(f"plot-junction.py: cannot read '{os.path.join(res, f)}'")
    rows = list(table_rows(table)) if use_table else list(csv.DictReader(open(os.path.join(res, "joints.csv"))))
    steps = {}
    for r in rows:
        steps.setdefault(int(r["step"]), {})[int(r["joint"])] = r
    return steps, json.load(open(os.path.join(res, "summary.json")))


def bypass_rows(res):
    """{step: {joint: {sheet: (bearing, bypass load)}}} from bypass.csv, else from fields.h5 (a model
    large enough for joints.h5 has them there alone: docs/output.md, "Bypass"); None if neither."""
    path = os.path.join(res, "bypass.csv")
    out = {}
    if os.path.exists(path):
        for r in csv.DictReader(open(path)):
            out.setdefault(int(r["step"]), {}).setdefault(int(r["joint"]), {})[r["sheet"]] = (float(r["bearing"]), float(r["bypass_load"]))
        return out
    path = os.path.join(res, "fields.h5")
    if not os.path.exists(path):
        return None
    with h5py.File(path, "r") as f:
        ids = f["joints/id"][()].ravel()
        for g in f["steps"].values():
            if "joints" not in g or "bypass_load" not in g["joints"]:
                continue
            load, bearing = g["joints/bypass_load"][()], g["joints/bypass_bearing"][()]
            out[int(g.attrs["step"])] = {int(j): {"a": (bearing[k, 0], load[k, 0]), "b": (bearing[k, 1], load[k, 1])} for k, j in enumerate(ids)}
    return out or None


def bypass_width(res, step):
    """The strip width of the bypass loads (bypass.csv's column, fields.h5's attribute)."""
    path = os.path.join(res, "bypass.csv")
    if os.path.exists(path):
        return float(next(csv.DictReader(open(path)))["width"])
    with h5py.File(os.path.join(res, "fields.h5"), "r") as f:
        return float(f[f"steps/{step:06d}/joints"].attrs["bypass_width"])


def force(r):
    return math.hypot(float(r["f_t1"]), float(r["f_t2"]))


def main_load(splice, r):
    """The load a splice transfers, signed: along the span (t1) for the skin splices, vertical (t2 =
    n x t1 = z) for the spar splices and the spar frames, around the fuselage (t2) for the lap."""
    return float(r["f_t1"] if splice.startswith(("upper", "lower")) else r["f_t2"])


LABEL = {"skin": "spanwise load f_t1 (kN)", "spar": "vertical load f_t2 (kN)", "lap": "circumferential load f_t2 (kN)"}


def label(splice):
    return LABEL["spar" if "spar" in splice or "frame" in splice else "lap" if splice == "fuselage_lap" else "skin"]


def level_steps(steps, levels):
    """The first step reaching each load level (the peaks of the load path)."""
    out = {}
    for lv in levels:
        for s in sorted(steps):
            if abs(float(next(iter(steps[s].values()))["load"]) - lv) < 1e-9 * max(1, abs(lv)):
                out[lv] = s
                break
    return out


def joint_rotation(res, base, model):
    """Rotation across the side-of-body joint at every step (right wing), and the load factors."""
    g = model["geometry"]
    pid = {r["part"]: int(r["id"]) for r in csv.DictReader(l for l in open(base + ".patches.csv") if not l.startswith("#"))}
    f = h5py.File(os.path.join(res, "fields.h5"), "r")
    X, Q, qp = f["shells/coordinates"][:], f["shells/cells"][:], f["shells/part"][:, 0]
    t = "_r" if model["both_sides"] else ""
    sel = {}
    for box, y in (("centre", g["y_centre_edge"] - g["splice_width"]), ("outer", g["y_outer_edge"] + g["splice_width"])):
        for w in ("upper", "lower"):
            part = f"{box}_{w}" if box == "centre" else f"outer_{w}{t}"
            n = np.unique(Q[qp == pid[part]])
            y0 = n[np.argmin(np.abs(X[n, 1] - y))]
            sel[box, w] = n[(np.abs(X[n, 1] - X[y0, 1]) < 1e-6) & (X[n, 0] > -1e-6) & (X[n, 0] < g["b"] + 1e-6)]
    loads, dth = [0.0], [0.0]
    for step in sorted(f["steps"].keys()):
        U = f[f"steps/{step}/shells/displacement"][:, 1]
        th = {box: (U[sel[box, "lower"]].mean() - U[sel[box, "upper"]].mean()) / g["depth"] for box in ("centre", "outer")}
        loads.append(float(f["steps"][step].attrs["load"]))
        dth.append(th["outer"] - th["centre"])
    return np.array(loads), np.array(dth)


def summary_figure(a, base, model, steps, summary, right, at, lin, lcol, table):
    """junction.png: the load along the upper outer splice's rows, the states over both skin splices at
    the highest level, the fuselage lap, the joint's hysteresis: one picture of a run."""
    fig, axes = plt.subplots(2, 2, figsize=(12, 8))
    for ax, sp in ((axes[0][0], "upper_outer"), (axes[0][1], "fuselage_lap")):
        js = [j for j, m in right.items() if m["splice"] == sp]
        for lv, s in at.items():
            for k, row in enumerate(sorted({int(right[j]["row"]) for j in js})):
                jr = sorted((j for j in js if int(right[j]["row"]) == row), key=lambda j: float(right[j]["position"]))
                pos = [float(right[j]["position"]) for j in jr]
                ax.plot(pos, [main_load(sp, steps[s][j]) / 1000 for j in jr], color=lcol[lv], marker="os^vD<>"[k % 7], ms=3, lw=1,
                        label=f"{lv:g} g, row {row}")
                if lin:
                    ax.plot(pos, [lv * lin[j][0] / 1000 for j in jr], color=lcol[lv], ls="--", lw=0.8)
        ax.set_title(f"{sp.replace('_', ' ')}: load of each fastener along its row" + (" (dashed: linear springs)" if lin else ""), fontsize=9)
        ax.set_xlabel("x along the chord (mm)")
        ax.set_ylabel(label(sp))
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=6, ncol=2)
    top = max(at, key=abs)
    ax = axes[1][0]
    js = [j for j, m in right.items() if m["splice"].startswith(("upper", "lower"))]
    for j in js:
        x, y = float(table[j]["x"]), float(table[j]["y"])
        y += 0 if right[j]["splice"].startswith("upper") else -(model["geometry"]["splice_width"] * 2 + 60)
        ax.scatter([x], [y], c=STATE.get(steps[at[top]][j]["state"], ("k", ""))[0], s=8)
    ax.set_title(f"states at {top:g} g: upper skin splice (top), lower (bottom)", fontsize=9)
    ax.set_xlabel("x along the chord (mm)")
    ax.set_yticks([])
    handles = [plt.Line2D([], [], marker="o", ls="", color=c, label=l) for c, l in list(STATE.values())[:3]]
    ax.legend(handles=handles, fontsize=7, loc="upper right")
    ax = axes[1][1]
    if os.path.exists(os.path.join(a.results, "fields.h5")):
        lam, dth = joint_rotation(a.results, base, model)
        ax.plot(lam, 1000 * dth, "o-", ms=3, label="frictional fasteners")
        if a.compare:
            l2, d2 = joint_rotation(a.compare, base, model)
            xs = np.array([min(lam), max(lam)])
            ax.plot(xs, 1000 * d2[-1] / l2[-1] * xs, "k--", label="linear springs")
        ax.legend(fontsize=8)
    ax.set_title("rotation across the side-of-body joint over the load path", fontsize=9)
    ax.set_xlabel("load factor (g)")
    ax.set_ylabel("rotation (mrad)")
    ax.grid(alpha=0.3)
    fig.suptitle(f"{summary['scene']}: {model['junction_fasteners']} side-of-body fasteners, {model['dof']:,} dof", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "junction.png"), dpi=100)
    plt.close(fig)


def springs_table(path, steps, at, lin, right, splices):
    """springs.csv: the frictional run against the linear springs (lin: force at load factor 1)."""
    def neighbours(loads):
        """Largest jump between neighbours in the middle half of a row, over the row's mean."""
        mid = loads[len(loads) // 4: 3 * len(loads) // 4]
        if len(mid) < 2 or np.mean(mid) <= 0:
            return float("nan")
        return float(np.max(np.abs(np.diff(mid))) / np.mean(mid))
    last = max(steps)
    levels = list(at.items()) + ([(float(next(iter(steps[last].values()))["load"]), last)] if last not in at.values() else [])
    with open(path, "w") as fh:
        fh.write("splice,level,total_frictional,total_linear,total_ratio,shares_frictional,shares_linear,max_frictional,max_linear,"
                 "ratio_min,ratio_max,neighbours_frictional,neighbours_linear,stick_frictional,slide_frictional,bearing_frictional\n")
        for sp in splices:
            js = [j for j, m in right.items() if m["splice"] == sp]
            rows = sorted({int(right[j]["row"]) for j in js})
            by_row = {r: sorted((j for j in js if int(right[j]["row"]) == r), key=lambda j: float(right[j]["position"])) for r in rows}
            for lv, st in levels:
                fr = {j: force(steps[st][j]) for j in js}
                li = {j: abs(lv) * lin[j] for j in js}
                tf, tl = sum(fr.values()), sum(li.values())
                share = lambda f, t: "/".join(f"{sum(f[j] for j in by_row[r]) / t:.3f}" if t > 0 else "nan" for r in rows)
                jump = lambda f: max((neighbours([f[j] for j in by_row[r]]) for r in rows), default=float("nan"))
                states = [steps[st][j]["state"] for j in js]
                # Each fastener's load over its spring's (the fasteners that carry at least 1 % of the splice's most).
                ratios = [fr[j] / li[j] for j in js if li[j] > 0.01 * max(li.values())] if tl > 0 else []
                rmin, rmax = (min(ratios), max(ratios)) if ratios else (float("nan"), float("nan"))
                fh.write(f"{sp},{lv:g},{tf:.1f},{tl:.1f},{tf / tl if tl > 0 else float('nan'):.4f},{share(fr, tf)},{share(li, tl)},"
                         f"{max(fr.values()):.1f},{max(li.values()):.1f},{rmin:.3f},{rmax:.3f},{jump(fr):.3f},{jump(li):.3f},"
                         f"{states.count('stick')},{states.count('slide')},{states.count('contact')}\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("results")
    ap.add_argument("scene")
    ap.add_argument("-o", "--out", required=True)
    ap.add_argument("--compare", help="results of the same scene with every fastener a linear spring, at load factor 1")
    ap.add_argument("--levels", help="load levels to chart, comma separated (default: the non-zero values of the scene's load table)")
    a = ap.parse_args()
    base = a.scene[:-5] if a.scene.endswith(".yaml") else a.scene
    for f in (base + ".fasteners.csv", base + ".model.json"):
        if not os.path.exists(f):
            sys.exit(f"plot-junction.py: cannot read '{f}' (scenes of scripts/make-wing-fuselage have it)")
    meta = {int(r["joint"]): r for r in csv.DictReader(open(base + ".fasteners.csv"))}
    model = json.load(open(base + ".model.json"))
    steps, summary = read_run(a.results)
    if a.levels:
        levels = [float(v) for v in a.levels.split(",")]
    else:
        levels = [v for v in model.get("load_table", []) if v != 0]
    at = level_steps(steps, levels)
    if not at:
        sys.exit(f"plot-junction.py: no step of {a.results} reaches the levels {levels}")
    lin = None
    if a.compare:
        ls, _ = read_run(a.compare)
        last = max(ls)
        lam = float(next(iter(ls[last].values()))["load"])
        if lam == 0:
            sys.exit(f"plot-junction.py: the last step of {a.compare} is unloaded: --compare takes a linear run that ends at a load "
                     "factor (e.g. -load_table 1 -load_steps 1)")
        lin = {j: (main_load(meta[j]["splice"], r) / lam, r) for j, r in ls[last].items() if j in meta}
        lin_force = {j: force(r) / abs(lam) for j, r in ls[last].items() if j in meta}
    os.makedirs(a.out, exist_ok=True)
    right = {j: m for j, m in meta.items() if m["side"] == "right" and m["splice"] in SPLICES}
    splices = [s for s in SPLICES if any(m["splice"] == s for m in right.values())]
    lcol = {lv: c for lv, c in zip(at, plt.rcParams["axes.prop_cycle"].by_key()["color"])}

    # Load along each row.
    nc = 2
    nr = math.ceil(len(splices) / nc)
    fig, axes = plt.subplots(nr, nc, figsize=(12, 3.0 * nr), squeeze=False)
    for ax, sp in zip(axes.flat, splices):
        js = [j for j, m in right.items() if m["splice"] == sp]
        rows = sorted({int(right[j]["row"]) for j in js})
        for lv, s in at.items():
            for k, row in enumerate(rows):
                jr = sorted((j for j in js if int(right[j]["row"]) == row), key=lambda j: float(right[j]["position"]))
                pos = [float(right[j]["position"]) for j in jr]
                ax.plot(pos, [main_load(sp, steps[s][j]) / 1000 for j in jr], color=lcol[lv], marker="os^vD<>"[k % 7], ms=3, lw=1,
                        label=f"{lv:g} g, row {row}" if sp == splices[0] else None)
                if lin:
                    ax.plot(pos, [lv * lin[j][0] / 1000 for j in jr], color=lcol[lv], ls="--", lw=0.8)
        ax.set_title(sp.replace("_", " "), fontsize=9)
        ax.set_xlabel("z (mm)" if "spar" in sp or "frame" in sp else "x along the chord (mm)", fontsize=8)
        ax.set_ylabel(label(sp), fontsize=8)
        ax.tick_params(labelsize=7)
    for ax in list(axes.flat)[len(splices):]:
        ax.axis("off")
    fig.legend(loc="lower center", ncol=min(8, 2 * len(at)), fontsize=7, frameon=False)
    fig.suptitle(f"{summary['scene']}: in-plane load of each fastener along its row" + (" (dashed: every fastener a linear spring)" if lin else ""), fontsize=10)
    fig.tight_layout(rect=(0, 0.05, 1, 0.97))
    fig.savefig(os.path.join(a.out, "load-transfer.png"), dpi=110)
    plt.close(fig)

    # Share of each row (skin splices).
    skin = [s for s in splices if s.startswith(("upper", "lower"))]
    fig, axes = plt.subplots(1, len(skin), figsize=(3.2 * len(skin), 3.2), squeeze=False)
    for ax, sp in zip(axes[0], skin):
        js = [j for j, m in right.items() if m["splice"] == sp]
        rows = sorted({int(right[j]["row"]) for j in js})
        for lv, s in at.items():
            tot = [sum(float(steps[s][j]["f_t1"]) for j in js if int(right[j]["row"]) == r) for r in rows]
            ax.plot(rows, np.array(tot) / sum(tot), "o-", color=lcol[lv], label=f"{lv:g} g")
        if lin:
            tot = [sum(float(lin[j][1]["f_t1"]) for j in js if int(right[j]["row"]) == r) for r in rows]
            ax.plot(rows, np.array(tot) / sum(tot), "k--", label="linear springs")
        ax.set_title(sp.replace("_", " "), fontsize=9)
        ax.set_xlabel("row (1: at the butt)", fontsize=8)
        ax.set_ylabel("share of the splice side's load", fontsize=8)
        ax.set_xticks(rows)
    axes[0][0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "row-share.png"), dpi=110)
    plt.close(fig)

    # State maps: skin splices in the (x, y) plane, spar splices in (y, z), the lap in (x, arc).
    views = [("upper skin splice", lambda m: m["splice"].startswith("upper"), 0, 1),
             ("lower skin splice", lambda m: m["splice"].startswith("lower"), 0, 1),
             ("spar splices and frames", lambda m: "spar" in m["splice"] or "frame" in m["splice"], 1, 2),
             ("fuselage lap", lambda m: m["splice"] == "fuselage_lap", 0, 2)]
    table = {int(r["id"]): r for r in csv.DictReader(open(base + ".joints.csv"))}
    fig, axes = plt.subplots(len(views), len(at), figsize=(3.6 * len(at), 2.4 * len(views)), squeeze=False)
    for c, (lv, s) in enumerate(at.items()):
        for r, (title, pick, i, k) in enumerate(views):
            ax = axes[r][c]
            js = [j for j, m in right.items() if pick(m)]
            coords = "xyz"
            xs = [float(table[j][coords[i]]) for j in js]
            ys = [float(table[j][coords[k]]) for j in js]
            if "spar" in title:   # front spar left, rear spar right of the same axis
                xs = [x + (0 if "front" in right[j]["splice"] else 400) for x, j in zip(xs, js)]
            cols = [STATE.get(steps[s][j]["state"], ("k", ""))[0] for j in js]
            ax.scatter(xs, ys, c=cols, s=6)
            ax.set_title(f"{title}, {lv:g} g", fontsize=8)
            ax.tick_params(labelsize=6)
    handles = [plt.Line2D([], [], marker="o", ls="", color=c, label=l) for c, l in STATE.values()]
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.04, 1, 1))
    fig.savefig(os.path.join(a.out, "states.png"), dpi=110)
    plt.close(fig)

    # Most loaded fastener per row, margins to slip and to bearing.
    types = summary.get("identified_joint_types", {})
    # A fastener's own gap (the fastener table's column gap: a clearance per fastener) over its type's.
    own_gap = {int(r["id"]): float(r["gap"]) for r in csv.DictReader(open(base + ".joints.csv")) if (r.get("gap") or "").strip()}
    out = []
    for sp in splices:
        js = [j for j, m in right.items() if m["splice"] == sp]
        for row in sorted({int(right[j]["row"]) for j in js}):
            best = max(((force(steps[s][j]), s, j) for s in steps for j in js if int(right[j]["row"]) == row))
            F, s, j = best
            r = steps[s][j]
            p = types.get(right[j]["type"], {})
            G, gap = p.get("G", float("nan")), own_gap.get(j, p.get("gap", float("nan")))
            w = math.hypot(float(r["slip_t1"]), float(r["slip_t2"]))
            out.append(dict(splice=sp, row=row, joint=j, index=int(right[j]["index"]), position=float(right[j]["position"]),
                            load=float(r["load"]), force=F, G=G, slip_margin=1 - F / G if G > 0 else float("nan"),
                            gap=gap, bearing_margin=gap - w, state=r["state"]))
    with open(os.path.join(a.out, "most-loaded.csv"), "w") as fh:
        fh.write("splice,row,joint,index,position,load,force,G,slip_margin,gap,bearing_margin,state\n")
        for o in out:
            fh.write(f"{o['splice']},{o['row']},{o['joint']},{o['index']},{o['position']:.1f},{o['load']:g},{o['force']:.1f},"
                     f"{o['G']:.1f},{o['slip_margin']:.3f},{o['gap']:.4f},{o['bearing_margin']:.4f},{o['state']}\n")
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(12, 3.6))
    lab = [f"{o['splice'].replace('_', ' ')} {o['row']}" for o in out]
    a1.bar(range(len(out)), [o["slip_margin"] for o in out], color="tab:red")
    a1.axhline(0, color="k", lw=0.8)
    a1.set_ylabel("margin to slip 1 - |F|/G")
    a2.bar(range(len(out)), [1000 * o["bearing_margin"] for o in out], color="tab:green")
    a2.axhline(0, color="k", lw=0.8)
    a2.set_ylabel("margin to bearing j - |w| (um)")
    for ax in (a1, a2):
        ax.set_xticks(range(len(out)))
        ax.set_xticklabels(lab, rotation=90, fontsize=6)
    fig.suptitle("most loaded fastener of each row over the load path (splice, row)", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "most-loaded.png"), dpi=110)
    plt.close(fig)

    # Hysteresis of the joint's rotation.
    fig, ax = plt.subplots(figsize=(5.5, 4))
    if os.path.exists(os.path.join(a.results, "fields.h5")):
        lam, dth = joint_rotation(a.results, base, model)
        ax.plot(lam, 1000 * dth, "o-", ms=3, label="frictional fasteners")
        if a.compare:
            l2, d2 = joint_rotation(a.compare, base, model)
            k = d2[-1] / l2[-1]
            xs = np.array([min(lam), max(lam)])
            ax.plot(xs, 1000 * k * xs, "k--", label="linear springs")
        ax.set_xlabel("load factor (g)")
        ax.set_ylabel("rotation across the side-of-body joint (mrad)")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "hysteresis.png"), dpi=110)
    plt.close(fig)
    # Bypass beside each fastener: the skin's load that passes the hole against the load the
    # fastener takes out of it, along each row of the skin splices, at the highest level.
    byp = bypass_rows(a.results)
    lv_top = max(at, key=abs)
    s_top = at[lv_top]
    if byp is None or s_top not in byp:
        print(f"plot-junction.py: no bypass loads in {a.results} (bypass.csv or fields.h5): bypass.png not written")
    else:
        fig, axes = plt.subplots(1, len(skin), figsize=(3.4 * len(skin), 3.4), squeeze=False)
        drawn = 0
        for ax, sp in zip(axes[0], skin):
            js = [j for j, m in right.items() if m["splice"] == sp]
            for k, row in enumerate(sorted({int(right[j]["row"]) for j in js})):
                jr = sorted((j for j in js if int(right[j]["row"]) == row), key=lambda j: float(right[j]["position"]))
                side = lambda j: "a" if right[j]["part_a"].startswith(("outer_", "centre_")) else "b"
                vals = [byp[s_top].get(j, {}).get(side(j), (float("nan"), float("nan"))) for j in jr]
                pos = [float(right[j]["position"]) for j in jr]
                c = plt.rcParams["axes.prop_cycle"].by_key()["color"][k % 10]
                ax.plot(pos, [abs(v[0]) / 1000 for v in vals], "-", marker="o", ms=3, lw=1, color=c, label=f"row {row}: fastener")
                ax.plot(pos, [abs(v[1]) / 1000 for v in vals], "--", marker="s", ms=3, lw=1, color=c, label=f"row {row}: bypass")
                drawn += sum(1 for v in vals if math.isfinite(v[1]))
            ax.set_title(sp.replace("_", " "), fontsize=9)
            ax.set_xlabel("x along the chord (mm)", fontsize=8)
            ax.set_ylabel("load in the skin's strip (kN)", fontsize=8)
            ax.tick_params(labelsize=7)
            ax.legend(fontsize=6)
        fig.suptitle(f"{summary['scene']} at {lv_top:g} g: each fastener's load on the skin (solid) and the bypass load beside it "
                     f"(dashed; strip {bypass_width(a.results, s_top):g} mm)", fontsize=9)
        fig.tight_layout(rect=(0, 0, 1, 0.93))
        fig.savefig(os.path.join(a.out, "bypass.png"), dpi=110)
        plt.close(fig)
        if not drawn:
            print("plot-junction.py: every bypass load is NaN (the strip, -output_bypass_width, holds no element outside the footprints)")
    if lin:
        springs_table(os.path.join(a.out, "springs.csv"), steps, at, lin_force, right, splices)
    summary_figure(a, base, model, steps, summary, right, at, lin, lcol, table)
    print(f"plot-junction.py: charts of {summary['scene']} at {', '.join(f'{lv:g} g' for lv in at)} in {a.out}/")
    return 0


if __name__ == "__main__":
    sys.exit(main())
