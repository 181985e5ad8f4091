#!/usr/bin/python3
"""Picture of a boltnet field file (fields.h5, docs/output.md) without ParaView: the shells seen
from above (or along -axis), deformed by a scale factor and coloured by the displacement magnitude,
with each joint drawn as a marker coloured by its state at that step.

usage: scripts/plot_fields.py results/fig3b/fields.h5 -o fig3b-fields.png [--step N] [--scale S]
"""
import argparse
import sys

try:
    import h5py
    import matplotlib
    import numpy as np

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
except ImportError as e:  # Debian's modules live on /usr/bin/python3
    sys.exit(f"plot_fields.py: needs numpy, matplotlib and h5py ({e}); run it with /usr/bin/python3 "
             "after scripts/deps")

STATES = {0: ("linear", "tab:gray"), 1: ("open", "tab:orange"), 2: ("contact", "tab:green"),
          3: ("stick", "tab:blue"), 4: ("slide", "tab:red")}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("h5", help="fields.h5 written by boltnet")
    ap.add_argument("-o", "--output", required=True, help="output image")
    ap.add_argument("--step", type=int, help="converged step (default: the step of largest displacement)")
    ap.add_argument("--scale", type=float, help="displacement magnification (default: 10%% of the model size)")
    ap.add_argument("--view", choices=["xy", "xz", "yz"], default="xy", help="plane seen (default xy)")
    ap.add_argument("--title", help="chart title")
    a = ap.parse_args()

    try:
        f = h5py.File(a.h5, "r")
    except OSError as e:
        sys.exit(f"plot_fields.py: cannot read '{a.h5}': {e}")
    with f:
        steps = sorted(f["steps"].keys())
        if not steps:
            sys.exit(f"plot_fields.py: '{a.h5}' holds no converged step")
        if a.step is not None:
            name = f"{a.step:06d}"
            if name not in f["steps"]:
                sys.exit(f"plot_fields.py: no step {a.step} in '{a.h5}' (it has {int(steps[0])}..{int(steps[-1])})")
        else:
            name = max(steps, key=lambda s: np.abs(f["steps"][s]["shells"]["displacement"][...]).max())
        g = f["steps"][name]
        x = f["shells/coordinates"][...]
        # Cells padded with -1 past their node count (a triangle has three nodes).
        cells = [c[c >= 0] for c in f["shells/cells"][...].astype(int)]
        u = g["shells/displacement"][...]
        xj = f["joints/coordinates"][...]
        uj = g["joints/displacement"][...]
        state = g["joints/state"][...].reshape(-1).astype(int)
        load = float(np.ravel(g.attrs["load"])[0]) if "load" in g.attrs else float("nan")

    i, j = {"xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}[a.view]
    size = np.ptp(x, axis=0).max()
    umax = np.linalg.norm(u, axis=1).max()
    scale = a.scale if a.scale is not None else (0.1 * size / umax if umax > 0 else 1.0)
    xd = x + scale * u
    mag = np.linalg.norm(u, axis=1)
    fig, ax = plt.subplots(figsize=(9, 5.5))
    polys = [xd[c][:, [i, j]] for c in cells]
    pc = PolyCollection(polys, array=np.array([mag[c].mean() for c in cells]), cmap="viridis", edgecolors="k", linewidths=0.1)
    ax.add_collection(pc)
    fig.colorbar(pc, ax=ax, label="|displacement| (mm)")
    mid = 0.5 * ((xj + scale * uj)[0::2] + (xj + scale * uj)[1::2])
    for s, (label, colour) in STATES.items():
        k = state == s
        if k.any():
            ax.scatter(mid[k, i], mid[k, j], s=28, color=colour, edgecolors="k", linewidths=0.5, label=label, zorder=3)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_xlabel(f"{'xyz'[i]} (mm)")
    ax.set_ylabel(f"{'xyz'[j]} (mm)")
    ax.legend(title="joint state", loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=5, fontsize=8)
    ax.set_title(a.title or f"{a.h5}: step {int(name)}, load {load:g}, displacements x {scale:.3g}", fontsize=10)
    fig.tight_layout()
    fig.savefig(a.output, dpi=150)
    print(f"plot_fields.py: wrote {a.output}")


if __name__ == "__main__":
    main()
