#!/usr/bin/python3
"""An independent reference for networks of rigid patches joined by macroelements.

Written from docs/joint-laws.md, docs/scenes.md and docs/solver.md (the load steps and what a
converged step commits), sharing no code with boltnet. Each rigid patch has one node with 6 dof
(ux uy uz rx ry rz). A joint joins two patches; its jump is
    du = R (u_B - u_A),  dtheta = R (theta_B - theta_A),  R = rows (n, t1, t2)
where u_A, u_B are the displacements of the joint's ends. How a joint attaches to a rigid patch:
  --attach node      (default; docs/scenes.md: a rigid patch is one node) the end moves with the
                     patch's node: u_A = u_a;
  --attach position  the end sits at the joint's position x (fastener table columns x, y, z) on the
                     rigid patch: u_A = u_a + theta_a x (x - X_a), so a joint away from the patch's
                     node has a lever arm (the eccentric bolt group of bolt_group.py needs this).
The joint's local force f (on B; A receives -f) and moment kr dtheta act at the joint's ends.

Each load step solves, from the last converged state and with the committed slips fixed, the
equilibrium  f_int(u) = lambda f_ext  on the free dof (prescribed dof at lambda times their value)
with Newton's method on this reference's own consistent tangent, a backtracking line search on
||r||, and, if that fails, a homotopy on the load within the step (intermediate load factors are
solved with the same committed slips and used only as starting points: nothing is committed
there, so the step's problem is unchanged). The step has converged when ||r||_inf <= 1e-13 of the
forces at play, or when every row is at round-off: |r_i| <= 100 eps sum_j |K_ij x_j|, the
precision to which a row that sums the terms K_ij x_j can be computed (a stiff loader or kr make
the first test unreachable). Only then are the trial slips committed.

Usage: network.py scene.yaml [-option value ...] [--loads joints.csv] [--attach node|position]
                  [-o out.csv] [--selftest]
  --loads  take the load factors from a boltnet joints.csv (its converged steps, cut-backs
           included) instead of the scene's load path.
"""
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import laws  # noqa: E402
from scene import Scene, SceneError  # noqa: E402

COLUMNS = ["step", "load", "joint", "state", "du_n", "du_t1", "du_t2", "f_n", "f_t1", "f_t2", "bearing", "slip_t1", "slip_t2"]


def skew(v):
    return np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


class Network:
    def __init__(self, scene, attach="node"):
        self.scene = scene
        self.ndof = 6 * len(scene.patch_ids)
        self.joints = scene.joints
        for jt in self.joints:
            # B maps the 12 dof (patch a, patch b) to the local jump (du, dtheta).
            T = []
            for side in ("a", "b"):
                t = np.eye(6)
                if attach == "position":
                    if jt["pos"] is None:
                        raise SceneError(f"joint {jt['id']}: --attach position needs the columns x, y, z")
                    t[0:3, 3:6] = -skew(jt["pos"] - scene.patch_pos[jt[side]])   # u + theta x (x - X)
                T.append(t)
            Rb = np.zeros((6, 6))
            Rb[0:3, 0:3] = jt["R"]
            Rb[3:6, 3:6] = jt["R"]
            jt["B"] = np.hstack([-Rb @ T[0], Rb @ T[1]])
            jt["dofs"] = np.r_[6 * jt["a"]:6 * jt["a"] + 6, 6 * jt["b"]:6 * jt["b"] + 6]
        self.fixed = np.array(sorted(scene.prescribed), dtype=int)
        self.fixed_value = np.array([scene.prescribed[g] for g in self.fixed])
        self.free = np.setdiff1d(np.arange(self.ndof), self.fixed)

    def evaluate(self, x, slips):
        """Internal forces, tangent, and each joint's law output at x with the committed slips."""
        f = np.zeros(self.ndof)
        K = np.zeros((self.ndof, self.ndof))
        out = []
        for jt, w in zip(self.joints, slips):
            q = jt["B"] @ x[jt["dofs"]]
            force, Kl, wt, state, bearing, margins = laws.evaluate(jt["p"], w, q[0:3])
            D = np.zeros((6, 6))
            D[0:3, 0:3] = Kl
            D[3:6, 3:6] = jt["p"]["kr"] * np.eye(3)
            g = np.r_[force, jt["p"]["kr"] * q[3:6]]
            f[jt["dofs"]] += jt["B"].T @ g
            K[np.ix_(jt["dofs"], jt["dofs"])] += jt["B"].T @ D @ jt["B"]
            out.append({"du": q[0:3], "f": force, "w": wt, "state": state, "bearing": bearing, "margins": margins})
        return f, K, out

    def residual(self, x, lam, slips):
        """Free rows of f_int - lambda f_ext, their Jacobian, the joints, the force scale and the
        round-off floor of each row: eps sum_j |K_ij x_j| (the row is a sum of such terms)."""
        f, K, out = self.evaluate(x, slips)
        r = f - lam * self.scene.force
        scale = max(np.max(np.abs(lam * self.scene.force)), max((np.max(np.abs(o["f"])) for o in out), default=0.0), 1e-300)
        floor = np.finfo(float).eps * (np.abs(K[self.free]) @ np.abs(x))
        return r[self.free], K[np.ix_(self.free, self.free)], out, scale, floor

    def newton(self, lam, x0, slips, maxit=60):
        """Solves one load step's equilibrium from x0; returns (x, ||r||_inf / scale) or (None, None).
        Converged: ||r||_inf <= 1e-13 of the forces, or every row within 100 times its round-off floor."""
        x = x0.copy()
        x[self.fixed] = lam * self.fixed_value
        r, J, out, scale, floor = self.residual(x, lam, slips)
        for _ in range(maxit):
            nr = np.max(np.abs(r)) if r.size else 0.0
            if nr <= 1e-13 * scale or np.all(np.abs(r) <= 100 * floor):
                return x, nr / scale
            try:
                dx = np.linalg.solve(J, -r)
            except np.linalg.LinAlgError:
                return None, None
            alpha, n2 = 1.0, np.linalg.norm(r)
            for _ in range(40):
                xt = x.copy()
                xt[self.free] += alpha * dx
                rt, Jt, outt, scalet, floort = self.residual(xt, lam, slips)
                if np.linalg.norm(rt) <= (1 - 1e-4 * alpha) * n2:
                    break
                alpha *= 0.5
            else:
                return None, None
            x, r, J, out, scale, floor = xt, rt, Jt, outt, scalet, floort
        return None, None

    def solve_step(self, lam_from, lam_to, x_from, slips, depth=0):
        """Newton; on failure, the homotopy on the load within the step (nothing committed)."""
        x, res = self.newton(lam_to, x_from, slips)
        if x is not None:
            return x, res
        if depth > 30:
            raise RuntimeError(f"the reference did not converge from load {lam_from} to {lam_to}")
        mid = 0.5 * (lam_from + lam_to)
        xm, _ = self.solve_step(lam_from, mid, x_from, slips, depth + 1)
        return self.solve_step(mid, lam_to, xm, slips, depth + 1)

    def run(self, loads):
        """All the load steps; one record per converged step: (load, x, joint outputs, residual)."""
        x = np.zeros(self.ndof)
        slips = [np.zeros(2) for _ in self.joints]
        lam, steps = 0.0, []
        for target in loads:
            x, res = self.solve_step(lam, target, x, slips)
            _, _, out = self.evaluate(x, slips)
            slips = [o["w"] for o in out]        # commit the converged step's trial slips
            lam = target
            steps.append({"load": lam, "x": x.copy(), "joints": out, "residual": res})
        return steps


def loads_from_csv(path):
    loads = []
    with open(path) as f:
        for row in csv.DictReader(f):
            s = int(row["step"])
            if len(loads) < s:
                loads.append(float(row["load"]))
    return loads


def write_csv(path, net, steps):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for s, st in enumerate(steps, start=1):
            for jt, o in zip(net.joints, st["joints"]):
                w.writerow([s, repr(st["load"]), jt["id"], o["state"], *map(repr, o["du"]), *map(repr, o["f"]),
                            o["bearing"], *map(repr, o["w"])])


def selftest(seed=7):
    """The reference's tangents against central differences of its forces (each law, both
    sides of every threshold, with clamp coupling and an offset), so that Newton's quadratic
    convergence is not left to chance. Returns the worst relative difference."""
    rng = np.random.default_rng(seed)
    worst = 0.0
    base = {"kn": 2e5, "kt": 1e5, "kr": 1e9, "kc": 4e4, "kg": 2e3, "gap": 0.03, "mu": 0.3, "nf": 2.0,
            "pretension": 5e3, "clamp_coupling": 0.4, "offset_t1": 0.01, "offset_t2": -0.005}
    for law in ("spring", "contact", "friction"):
        for _ in range(200):
            p = dict(base, law=law)
            w = rng.normal(scale=0.03, size=2)
            du = np.r_[rng.normal(scale=0.01), rng.normal(scale=0.05, size=2)]
            f0, K, *_ = laws.evaluate(p, w, du)
            h = 1e-7 * max(1e-3, np.max(np.abs(du)))
            Kfd = np.zeros((3, 3))
            for k in range(3):
                e = np.zeros(3)
                e[k] = h
                Kfd[:, k] = (laws.evaluate(p, w, du + e)[0] - laws.evaluate(p, w, du - e)[0]) / (2 * h)
            # A finite difference across a kink is not a derivative: skip points within 10 h of one.
            _, _, _, _, _, m = laws.evaluate(p, w, du)
            if any(abs(v) < 1e3 * h * (p["kt"] if k == "slip" else 1) for k, v in m.items()):
                continue
            worst = max(worst, np.max(np.abs(K - Kfd)) / np.max(np.abs(K)))
    return worst


def main(argv):
    if "--selftest" in argv:
        worst = selftest()
        print(f"network.py: tangents agree with central differences to {worst:.1e} of their size")
        return 0 if worst < 1e-6 else 1
    args, loads_csv, attach, out = [], None, "node", None
    it = iter(argv)
    for a in it:
        if a == "--loads":
            loads_csv = next(it)
        elif a == "--attach":
            attach = next(it)
        elif a == "-o":
            out = next(it)
        else:
            args.append(a)
    if not args:
        print(__doc__)
        return 2
    scene = Scene(args[0], args[1:])
    net = Network(scene, attach)
    loads = loads_from_csv(loads_csv) if loads_csv else scene.load_factors()
    steps = net.run(loads)
    if out:
        write_csv(out, net, steps)
    print(f"network.py: {len(steps)} steps, worst residual {max(s['residual'] for s in steps):.1e} of the forces")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except SceneError as e:
        print(f"network.py: {e}", file=sys.stderr)
        sys.exit(1)
