#!/usr/bin/python3
"""Writes a random network of rigid patches and macroelements (a boltnet scene) for the comparison
with the independent reference (network.py, check_network.py).

Usage: make_scene.py SEED OUTDIR [--planar] [--kr KR]

The scene, fixed by the seed (numpy's PCG64 stream):
- 4 to 6 rigid patches; patch 0 clamped;
- a spanning tree of the patches, each tree edge carried by 1 to 3 parallel joints of different
  types (several joints sharing the load between two plates), plus 2 to 4 joints across the tree
  (statically indeterminate loops);
- joint types: three frictional (different ke, kg, kc, clearance, mu, nf, pretension; one with clamp
  coupling and one with the bolt offset in its hole), one contact, one spring; every joint's
  in-plane frame t1 at a random angle; without --planar a third of the bolt axes are tilted out of
  the z axis (so in-plane loads open or close joints and, with clamp coupling, change G);
- loads: a force on a patch L and a prescribed in-plane displacement, at 60 to 120 degrees to it,
  on a patch D joined to L by one more frictional joint; a second force on a third patch if there
  is one (forces with a small out-of-plane part without --planar);
- the load path: the load factor goes to 1, then through 2 to 4 reversals of random size (each
  0.5 to 1 times the square root of the previous extreme: loading, unloading, reversal,
  reloading), back to 0, in 6 to 10 steps per segment.
  The driver scales every boundary condition by one load factor, so a load's direction can only
  reverse; the slip directions turn because the joint L-D saturates (slides, bears) while the force
  on L keeps growing, and because joints slide and bear one after the other around the loops
  (check_network.py measures how much they turn and can require a turn).
--kr sets every joint's rotational stiffness (default: 1e9 N mm/rad for the bolts, 1e8 for the
spring, as in the shipped scenes); on rigid patches the rotations do not touch the compared
quantities, but a smaller kr lowers boltnet's round-off stop (docs/verification-2d.md).
Sizes: the forces are 1.2 to 2 times the friction capacity of the joints at the clamped patch and
the prescribed displacement 1.5 to 2.5 clearances, so that joints stick, slide and bear.
"""
import os
import sys

import numpy as np


def friction_type(rng, ke, clamp=False, offset=False):
    gap = rng.uniform(0.01, 0.08)
    t = {"law": "friction", "kn": 2.0e5, "kt": ke, "kr": 1.0e9, "kg": ke * rng.uniform(3e-3, 2e-2),
         "kc": ke * rng.uniform(0.2, 0.5), "gap": gap, "mu": rng.uniform(0.15, 0.35),
         "nf": int(rng.integers(1, 3)), "pretension": rng.uniform(3e3, 1e4)}
    if clamp:
        t["clamp_coupling"] = rng.uniform(0.2, 0.6)
    if offset:
        a = rng.uniform(0, 2 * np.pi)
        t["offset_t1"], t["offset_t2"] = 0.4 * gap * np.cos(a), 0.4 * gap * np.sin(a)
    return t


def make(seed, planar, kr=None):
    rng = np.random.default_rng(seed)
    npatch = int(rng.integers(4, 7))
    pos = np.c_[rng.uniform(0, 100, size=(npatch, 2)), np.zeros(npatch)]
    types = {"f0": friction_type(rng, rng.uniform(8e4, 1.5e5)),
             "f1": friction_type(rng, rng.uniform(8e4, 1.5e5), clamp=not planar),
             "f2": friction_type(rng, rng.uniform(8e4, 1.5e5), offset=True),
             "c0": {"law": "contact", "kn": 2.0e5, "kt": rng.uniform(2e3, 1e4), "kc": rng.uniform(3e4, 6e4),
                    "kr": 1.0e9, "gap": rng.uniform(0.03, 0.08)},
             "s0": {"law": "spring", "kn": 1.0e5, "kt": rng.uniform(1e4, 2e4), "kr": 1.0e8}}
    edges = []
    for p in range(1, npatch):
        q = int(rng.integers(0, p))
        k = int(rng.integers(1, 4))
        for name in rng.choice(["f0", "f1", "f2", "c0"], size=k, replace=False):
            edges.append((q, p, str(name)))
    if kr is not None:
        for t in types.values():
            t["kr"] = kr
    for _ in range(int(rng.integers(2, 5))):
        a, b = rng.choice(npatch, size=2, replace=False)
        edges.append((int(a), int(b), str(rng.choice(["f0", "f1", "f2", "s0"]))))
    if not any(e[2] == "s0" for e in edges):
        edges.append((0, npatch - 1, "s0"))
    joints = []
    for i, (a, b, name) in enumerate(edges):
        n = np.array([0.0, 0.0, 1.0])
        if not planar and rng.uniform() < 1 / 3:
            n = np.array([*rng.uniform(-0.25, 0.25, size=2), 1.0])
        phi = rng.uniform(0, 2 * np.pi)
        joints.append((i, a, b, name, n, np.array([np.cos(phi), np.sin(phi), 0.0])))
    # Loads: a force on patch L, a prescribed displacement at 60 to 120 degrees to it on patch D
    # joined to L by a frictional joint (as that joint saturates, L's other joints see their load
    # turn), a second force on another patch when there is one.
    capacity = sum(types[name]["mu"] * types[name]["nf"] * types[name]["pretension"]
                   for _, a, b, name, _, _ in joints if 0 in (a, b) and types[name]["law"] == "friction")
    capacity = max(capacity, 2000.0)
    L, D, *other = (int(p) for p in rng.permutation(np.arange(1, npatch)))
    phi = rng.uniform(0, 2 * np.pi)
    joints.append((len(joints), L, D, str(rng.choice(["f0", "f1"])), np.array([0.0, 0.0, 1.0]), np.array([np.cos(phi), np.sin(phi), 0.0])))
    bcs = [(0, "all", "fixed", 0.0)]
    a = rng.uniform(0, 2 * np.pi)
    for p, angle in [(L, a)] + [(q, rng.uniform(0, 2 * np.pi)) for q in other[:1]]:
        F = capacity * rng.uniform(1.2, 2.0) / 2
        bcs += [(p, "ux", "force", F * np.cos(angle)), (p, "uy", "force", F * np.sin(angle))]
        if not planar:
            bcs.append((p, "uz", "force", 0.1 * F * rng.uniform(-1, 1)))
    d = rng.uniform(1.5, 2.5) * max(t.get("gap", 0) for t in types.values())
    b = a + rng.choice([-1, 1]) * rng.uniform(np.pi / 3, 2 * np.pi / 3)
    bcs += [(D, "ux", "displacement", d * np.cos(b)), (D, "uy", "displacement", d * np.sin(b))]
    # The load path, drawn last (the network above does not depend on it): up to 1, then 2 to 4
    # reversals, each 0.5 to 1 times the square root of the previous extreme, back to 0; 6 to 10
    # steps per segment.
    table = [1.0]
    for k in range(int(rng.integers(2, 5))):
        table.append((-1) ** (k + 1) * rng.uniform(0.5, 1.0) * abs(table[-1]) ** 0.5)
    table.append(0.0)
    steps = int(rng.integers(6, 11))
    return pos, types, joints, bcs, table, steps


def write(seed, outdir, planar, kr=None):
    pos, types, joints, bcs, table, steps = make(seed, planar, kr)
    name = f"net{seed}" + ("-planar" if planar else "") + (f"-kr{kr:g}" if kr is not None else "")
    os.makedirs(outdir, exist_ok=True)
    g = lambda v: repr(float(v))  # noqa: E731  every digit, so that both solvers read the same numbers
    with open(os.path.join(outdir, name + ".patches.csv"), "w") as f:
        f.write("id,kind,x,y,z\n")
        for i, p in enumerate(pos):
            f.write(f"{i},rigid,{g(p[0])},{g(p[1])},{g(p[2])}\n")
    with open(os.path.join(outdir, name + ".joints.csv"), "w") as f:
        f.write("id,patch_a,patch_b,type,nx,ny,nz,t1x,t1y,t1z\n")
        for i, a, b, t, n, t1 in joints:
            f.write(f"{i},{a},{b},{t},{','.join(map(g, n))},{','.join(map(g, t1))}\n")
    with open(os.path.join(outdir, name + ".bcs.csv"), "w") as f:
        f.write("patch,dof,kind,value\n")
        for p, dof, kind, v in bcs:
            f.write(f"{p},{dof},{kind},{g(v)}\n")
    with open(os.path.join(outdir, name + ".yaml"), "w") as f:
        f.write(f"# {name}: a random network of rigid patches written by test/ref2d/make_scene.py {seed}"
                f"{' --planar' if planar else ''}{f' --kr {kr:g}' if kr is not None else ''}\n")
        f.write(f"scene:\n  name: {name}\n  patches: {name}.patches.csv\n  joints: {name}.joints.csv\n  bcs: {name}.bcs.csv\n")
        f.write("joint:\n")
        used = {t for _, _, _, t, _, _ in joints}      # boltnet refuses options of an unused type
        for t, params in types.items():
            if t not in used:
                continue
            f.write(f"  {t}:\n")
            for k, v in params.items():
                f.write(f"    {k}: {v if isinstance(v, str) else g(v)}\n")
        f.write(f"load:\n  path: table\n  table: {','.join(f'{v:.6g}' for v in table)}\n  steps: {steps}\n")
    return os.path.join(outdir, name + ".yaml")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        print(__doc__)
        sys.exit(2)
    rest = sys.argv[3:]
    kr = float(rest[rest.index("--kr") + 1]) if "--kr" in rest else None
    print(write(int(sys.argv[1]), sys.argv[2], "--planar" in rest, kr))
