#!/usr/bin/python3
"""Chart the joints.csv, or the joint table joints.h5, written by the boltnet driver.

Default (paper fig. 3c): x = load factor, y = jump du_t1 (mm), one line per joint,
markers coloured (and shaped) by the joint state at that step.
--force: the joint's own response curve, x = du_t1 (mm), y = f_t1 (N).

joints.h5 (-output_joints hdf5, docs/output.md "The joint table") gives the same chart as joints.csv
of the same run; --data FILE also writes the chart's data (per joint: x, y, states) as JSON.

Usage: plot_joints.py joints.csv|joints.h5 -o out.png [--joint ID ...] [--x load|du_t1] [--title T] [--force] [--data FILE]
"""
# Debian's /usr/bin/python3 is used on purpose: python3-matplotlib/python3-numpy install there.
import argparse
import csv
import json
import sys

try:
    import numpy as np
    import matplotlib
    matplotlib.use("Agg")  # no display needed (CI, containers)
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
except ImportError as e:
    print(f"plot_joints.py: cannot import {e.name or e}: install python3-matplotlib and python3-numpy "
          "(apt-get install python3-matplotlib python3-numpy, or run scripts/deps)", file=sys.stderr)
    sys.exit(2)

COLUMNS = ["step", "load", "joint", "state", "du_n", "du_t1", "du_t2",
           "f_n", "f_t1", "f_t2", "bearing", "slip_t1", "slip_t2"]
NUMERIC = ["load", "du_t1", "f_t1", "f_t2"]  # the only columns this script draws
# One fixed colour (and marker shape) per state word (law.hpp: stateName()), so charts are
# comparable across runs.
STATE_COLORS = {
    "stick": "tab:blue",
    "slide": "tab:red",
    "contact": "tab:green",
    "open": "tab:orange",
    "linear": "tab:gray",
}
STATE_MARKERS = {"stick": "o", "slide": "^", "contact": "s", "open": "v", "linear": "D"}
UNKNOWN_STATE_COLOR, UNKNOWN_STATE_MARKER = "black", "x"
# Joint lines avoid the state colours so a line is never mistaken for a state; more joints than
# colours cycle through line styles.
JOINT_COLORS = ["black", "tab:purple", "tab:brown", "tab:pink", "tab:olive", "tab:cyan"]
JOINT_STYLES = ["-", "--", ":", "-."]


def fail(msg):
    print(f"plot_joints.py: {msg}", file=sys.stderr)
    sys.exit(2)


def read_rows(path):
    """Return {joint id: {"step": [...], "load": array, ..., "state": [...]}} in file order."""
    try:
        f = open(path, newline="")
    except OSError as e:
        fail(f"cannot read {path}: {e.strerror}")
    with f:
        reader = csv.DictReader(f)
        header = [h.strip() for h in (reader.fieldnames or [])]
        if not header:
            fail(f"{path} is empty (expected header {','.join(COLUMNS)})")
        reader.fieldnames = header
        needed = ["step", "joint", "state"] + NUMERIC
        missing = [c for c in needed if c not in header]
        if missing:
            fail(f"{path}: missing column(s) {', '.join(missing)} (header is: {','.join(header)})")
        joints = {}
        for lineno, row in enumerate(reader, start=2):
            if not any(isinstance(v, str) and v.strip() for v in row.values()):
                continue  # tolerate blank lines
            short = [c for c in needed if row.get(c) is None or not row[c].strip()]
            if short:
                fail(f"{path}:{lineno}: empty or missing value for column(s) {', '.join(short)}")
            jid = row["joint"].strip()
            d = joints.setdefault(jid, {"step": [], "state": [], **{c: [] for c in NUMERIC}})
            col = "step"
            try:
                d["step"].append(int(float(row["step"])))
                for col in NUMERIC:
                    d[col].append(float(row[col]))
            except ValueError:
                fail(f"{path}:{lineno}: column {col}: not a number: {row[col]!r}")
            d["state"].append(row["state"].strip().lower())
    if not joints:
        fail(f"{path} has a header but no data rows")
    for d in joints.values():
        for c in NUMERIC:
            d[c] = np.asarray(d[c], dtype=float)
    return joints


def read_table(path):
    """The same as read_rows, from joints.h5: datasets of shape (steps, joints[, columns])."""
    try:
        import h5py
    except ImportError:
        fail("reading joints.h5 needs h5py: install python3-h5py (apt-get install python3-h5py, or run scripts/deps)")
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        fail(f"cannot read {path}: {e}")
    with f:
        missing = [k for k in ("step", "load", "joint", "state", "state_names", "jump", "force") if k not in f]
        if missing:
            fail(f"{path}: not a boltnet joint table: no dataset(s) {', '.join(missing)}")
        names = [n.decode() if isinstance(n, bytes) else str(n) for n in f["state_names"][()]]
        step, load, ids = f["step"][()], f["load"][()], f["joint"][()]
        state, jump, force = f["state"][()], f["jump"][()], f["force"][()]
    if len(step) == 0:
        fail(f"{path} holds no step")
    cols = {"load": lambda j: load, "du_t1": lambda j: jump[:, j, 1], "f_t1": lambda j: force[:, j, 1], "f_t2": lambda j: force[:, j, 2]}
    return {str(int(jid)): {"step": [int(s) for s in step], "state": [names[c] for c in state[:, j]],
                            **{c: np.asarray(cols[c](j), dtype=float) for c in NUMERIC}} for j, jid in enumerate(ids)}


def joint_sort_key(jid):
    return (0, int(jid), "") if jid.lstrip("-").isdigit() else (1, 0, jid)


def main():
    ap = argparse.ArgumentParser(description="Plot the joint jumps/forces of a boltnet joints.csv.")
    ap.add_argument("csv", help="joints.csv or joints.h5 written by the boltnet driver")
    ap.add_argument("-o", "--output", required=True, help="output image (e.g. out.png)")
    ap.add_argument("--joint", nargs="+", metavar="ID", help="only these joint ids (default: all)")
    ap.add_argument("--x", choices=["load", "du_t1"], default="load",
                    help="x axis of the default chart: load (default) or du_t1")
    ap.add_argument("--force", action="store_true",
                    help="plot f_t1 (N) against du_t1 (mm) instead (the joint's response curve)")
    ap.add_argument("--share", action="store_true",
                    help="plot each joint's share of the in-plane force carried by the plotted joints, "
                         "|f_t| / sum |f_t| at each step, against the load (the load share of each fastener)")
    ap.add_argument("--title", help="chart title (default: the CSV path)")
    ap.add_argument("--data", help="also write the chart's data (per joint: x, y and states) to this JSON file")
    args = ap.parse_args()

    joints = read_table(args.csv) if args.csv.endswith((".h5", ".hdf5")) else read_rows(args.csv)
    ids = sorted(joints, key=joint_sort_key)
    if args.joint:
        wanted = [j.strip() for j in args.joint]
        unknown = [j for j in wanted if j not in joints]
        if unknown:
            fail(f"{args.csv}: no joint(s) {', '.join(unknown)} (joints present: {', '.join(ids)})")
        ids = [j for j in ids if j in wanted]

    if args.share:
        # |f_t| of every plotted joint, divided by their sum at the same step.
        total = {}
        for jid in ids:
            d = joints[jid]
            d["share"] = np.hypot(d["f_t1"], d["f_t2"])
            for st, v in zip(d["step"], d["share"]):
                total[st] = total.get(st, 0.0) + v
        for jid in ids:
            d = joints[jid]
            t = np.array([total[st] for st in d["step"]])
            d["share"] = np.divide(d["share"], t, out=np.zeros_like(t), where=t > 0)
        xcol, ycol = "load", "share"
        xlabel, ylabel = "load factor (N for the shipped scenes)", "share of the in-plane fastener load"
    elif args.force:
        xcol, ycol = "du_t1", "f_t1"
        xlabel, ylabel = "jump du_t1 (mm)", "force f_t1 (N)"
    elif args.x == "du_t1":
        # Axes swapped: the classic load-slip curve (jump on x, load on y).
        xcol, ycol = "du_t1", "load"
        xlabel, ylabel = "jump du_t1 (mm)", "load factor (N for the shipped scenes)"
    else:
        xcol, ycol = "load", "du_t1"
        xlabel, ylabel = "load factor (N for the shipped scenes)", "jump du_t1 (mm)"

    fig, ax = plt.subplots(figsize=(8, 5.5))
    line_handles = []
    states_seen = []
    data = {"x": xcol, "y": ycol, "joints": {}}
    for i, jid in enumerate(ids):
        d = joints[jid]
        order = np.argsort(d["step"], kind="stable")  # steps in order, even if ranks wrote out of order
        x, y = d[xcol][order], d[ycol][order]
        states = [d["state"][k] for k in order]
        data["joints"][jid] = {"x": x.tolist(), "y": y.tolist(), "state": states}
        style = JOINT_STYLES[(i // len(JOINT_COLORS)) % len(JOINT_STYLES)]
        (line,) = ax.plot(x, y, style, color=JOINT_COLORS[i % len(JOINT_COLORS)], lw=1.3,
                          label=f"joint {jid}", zorder=2)
        line_handles.append(line)
        for s in dict.fromkeys(states):  # one scatter per state: colour and marker shape
            mask = np.array([st == s for st in states])
            ax.scatter(x[mask], y[mask], s=22, color=STATE_COLORS.get(s, UNKNOWN_STATE_COLOR),
                       marker=STATE_MARKERS.get(s, UNKNOWN_STATE_MARKER), edgecolors="none", zorder=3)
            if s not in states_seen:
                states_seen.append(s)

    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(args.title if args.title is not None else args.csv)
    ax.grid(True, alpha=0.4)

    # Two legends outside the axes (never hide data): joints (lines) and states (marker colour/shape),
    # states in a fixed order.
    leg1 = ax.legend(handles=line_handles, loc="upper left", bbox_to_anchor=(1.01, 1.0),
                     fontsize="small", title="joints")
    ax.add_artist(leg1)
    order = [s for s in STATE_COLORS if s in states_seen] + [s for s in states_seen if s not in STATE_COLORS]
    state_handles = [Line2D([], [], ls="", marker=STATE_MARKERS.get(s, UNKNOWN_STATE_MARKER), markersize=6,
                            color=STATE_COLORS.get(s, UNKNOWN_STATE_COLOR), label=s) for s in order]
    ax.legend(handles=state_handles, loc="lower left", bbox_to_anchor=(1.01, 0.0),
              fontsize="small", title="state")

    fig.tight_layout()
    try:
        fig.savefig(args.output, dpi=150, bbox_inches="tight")  # keeps the outside legends
    except OSError as e:
        fail(f"cannot write {args.output}: {e.strerror}")
    print(f"plot_joints.py: wrote {args.output}")
    if args.data:
        try:
            with open(args.data, "w") as f:
                json.dump(data, f)
        except OSError as e:
            fail(f"cannot write {args.data}: {e.strerror}")


if __name__ == "__main__":
    main()
