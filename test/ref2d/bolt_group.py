#!/usr/bin/python3
"""A bolt group under eccentric in-plane shear: closed forms, scenes, and checks of boltnet's results.

The group: six fasteners in two lines (gauge 60 mm) of three (pitch 50 mm), centroid at the origin,
joining a plate (patch 1) to a fixed support (patch 0, rigid). The load P acts along -y at
x_L = (300, 0) mm (eccentricity e = 300 mm; at e = 150 mm the rigid-plastic IC falls on the
fastener at (-30, 0), which then sticks: a degenerate case of (b)). It reaches the plate through a
loader: a rigid patch 2 joined to the plate at x_L by a stiff in-plane spring (kt = 1e7 N/mm, axis z,
kn = kr = 0: no moment); patch 2 is fixed but for uy, which is loaded (force control) or prescribed
(displacement control: the plateau can be followed past the ultimate load). The spring also holds
x at the load point, but the group and the plate are symmetric about y = 0, so that reaction is
zero (the checks print it). (A loader with its axis along x, kn = 0, would hold y alone, but a
footprint is measured in the plane normal to the axis: on the plate that is a strip across the whole
part, which the exact coupling makes rigid, with lever arms of 360 mm.)

Closed forms (the fastener forces are the forces the fasteners carry, on the plate's side, in the
plane; for a rigid plate both are exact statics and kinematics):
(a) elastic, identical springs kt (and a rotational stiffness kr per joint): the plate translates and
    rotates about the group's centroid, F_i = P/n + T kt (e_z x r_i) / (kt sum r^2 + n kr),
    T the load's moment about the centroid (the elastic centroid method: direct shear plus torsion,
    the "elastic method" of the AISC Steel Construction Manual, Part 7; with kr = 0 its usual form);
(b) ultimate, every fastener sliding at the same threshold G (pure Coulomb: kg = kc = 0): the plate
    rotates about an instantaneous centre (IC) and each fastener carries G perpendicular to its ray
    from the IC; the IC and P_u follow from the three equilibrium equations (Crawford & Kulak,
    "Eccentrically loaded bolted connections", J. Struct. Div. ASCE 97(ST3), 1971; the AISC Steel
    Construction Manual, Part 7, instantaneous centre of rotation method, here with the rigid-plastic
    fastener law instead of their R = R_ult (1 - exp(-10 D))^0.55 curve; Brandt, "Rapid determination
    of ultimate strength of eccentrically loaded bolt groups", AISC Eng. J. 19(2), 1982, solves the
    same equations).

Subcommands:
  bolt_group.py scene OUTDIR --plate rigid|shell --control force|displacement [--E MPa]
  bolt_group.py elastic joints.csv [--kr KR] [--rtol R]     (a), rigid plate, at every step
  bolt_group.py elastic-limit E.csv E2.csv --ratio E2/E [--rtol R]
                                                    (a), shell plates: convergence to the closed form
  bolt_group.py plateau joints.csv [--rtol R]       (b) at the last step
  bolt_group.py selftest                            the closed forms' limits, and the reference
                                                    network (network.py --attach position) against them
"""
import csv
import os
import sys

import numpy as np

BOLTS = np.array([[x, y] for x in (-30.0, 30.0) for y in (-50.0, 0.0, 50.0)])
LOAD_AT = np.array([300.0, 0.0])
LOAD_DIR = np.array([0.0, -1.0])
LOADER_ID = 100
KT, KN = 1.0e5, 2.0e5           # fastener stiffnesses (N/mm)
KR_RIGID = 1.0e-3               # N mm/rad: a rigid plate whose joints lose their lever arms (today) needs some
G = 0.3 * 1.0 * 1.0e4           # mu nf Pc (N)


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def perp(v):
    """e_z x v."""
    return np.array([-v[1], v[0]])


def elastic(P, kt=KT, kr=0.0, bolts=BOLTS, at=LOAD_AT, d=LOAD_DIR):
    """Fastener forces (n x 2) for the load P d at `at`: the elastic centroid method."""
    c = bolts.mean(axis=0)
    r = bolts - c
    T = cross(at - c, P * d)
    return np.array([P * d / len(bolts) + T * kt * perp(ri) / (kt * np.sum(r * r) + len(bolts) * kr) for ri in r])


def instantaneous_centre(G=G, bolts=BOLTS, at=LOAD_AT, d=LOAD_DIR):
    """(IC, P_u, forces) of the rigid-plastic group: sum F_i = P d, sum (x_i - at) x F_i = 0 with
    F_i = G s e_z x (x_i - IC)/|x_i - IC|. Newton on the IC from the elastic centre of rotation."""
    c = bolts.mean(axis=0)
    r2 = np.sum((bolts - c) ** 2) / len(bolts)
    arm = cross(at - c, d)                       # moment of a unit load about the centroid
    s = np.sign(arm)                             # the plate turns the way the load's moment does
    # Start from the elastic centre of rotation: on the line through the centroid normal to the
    # load, at r2/e from it, on the side away from the load.
    ic = c + s * (r2 / abs(arm)) * perp(d)

    def forces(ic):
        v = bolts - ic
        return np.array([G * s * perp(vi) / np.linalg.norm(vi) for vi in v])

    def resid(ic):
        # P = sum F . d; what must vanish: the force across the load, the moment about the load point
        F = forces(ic)
        return np.array([F.sum(axis=0) @ perp(d), sum(cross(xi - at, Fi) for xi, Fi in zip(bolts, F))])

    # Newton with backtracking on |resid| (the forces have kinks where the IC crosses a fastener).
    r = resid(ic)
    for _ in range(200):
        if np.max(np.abs(r)) < 1e-12 * G * len(bolts) * max(1.0, np.max(np.abs(bolts - at))):
            break
        J = np.zeros((2, 2))
        for k in range(2):
            h = 1e-7 * max(1.0, np.linalg.norm(ic - c))
            e = np.zeros(2)
            e[k] = h
            J[:, k] = (resid(ic + e) - resid(ic - e)) / (2 * h)
        step = np.linalg.lstsq(J, -r, rcond=None)[0]
        t = 1.0
        while t > 1e-12:
            trial = ic + t * step
            rt = resid(trial)
            if np.linalg.norm(rt) < (1 - 1e-4 * t) * np.linalg.norm(r):
                break
            t *= 0.5
        ic, r = trial, rt
    else:
        raise RuntimeError("the instantaneous centre did not converge")
    F = forces(ic)
    return ic, F.sum(axis=0) @ d, F


# ------------------------------------------------------------------------------------------------
def write_scene(outdir, plate, control, E=7.2e4):
    """A boltnet scene of the group: rigid or shell plate, force or displacement control."""
    os.makedirs(outdir, exist_ok=True)
    name = f"group-{plate}-{control}"
    with open(os.path.join(outdir, name + ".patches.csv"), "w") as f:
        f.write("id,kind,x,y,z,lx,ly,nx,ny,mesh,part,material\n0,rigid,0,0,0,,,,,,,\n")
        if plate == "rigid":
            f.write("1,rigid,0,0,0,,,,,,,\n")
        else:  # 370 x 160 mm, 10 mm elements: every fastener and the load point on a node
            f.write("1,plate,-60,-80,0,370,160,37,16,,,plate\n")
        f.write(f"2,rigid,{LOAD_AT[0]},{LOAD_AT[1]},0,,,,,,,\n")
    with open(os.path.join(outdir, name + ".joints.csv"), "w") as f:
        f.write("id,patch_a,patch_b,type,nx,ny,nz,t1x,t1y,t1z,x,y,z\n")
        for i, (x, y) in enumerate(BOLTS):
            f.write(f"{i},0,1,bolt,0,0,1,1,0,0,{x},{y},0\n")
        f.write(f"{LOADER_ID},1,2,loader,0,0,1,1,0,0,{LOAD_AT[0]},{LOAD_AT[1]},0\n")
    with open(os.path.join(outdir, name + ".bcs.csv"), "w") as f:
        f.write("patch,dof,kind,value\n0,all,fixed,0\n")
        for dof in ("ux", "uz", "rx", "ry", "rz"):
            f.write(f"2,{dof},fixed,0\n")
        # per unit load factor: 1 N, or 1 mm, along -y
        f.write(f"2,uy,{'force' if control == 'force' else 'displacement'},-1\n")
    kr = KR_RIGID if plate == "rigid" else 0.0
    if control == "force":   # (a) identical linear springs, 10 kN in 2 steps
        bolt = f"{{law: spring, kn: {KN}, kt: {KT}, kr: {kr}}}"
        load = "  path: ramp\n  max: 10000\n  steps: 2\n"
    else:                    # (b) pure Coulomb (kg = kc = 0, clearance never closed), the load point pushed 15 mm
        bolt = f"{{law: friction, kn: {KN}, kt: {KT}, kr: {kr}, kg: 0, kc: 0, gap: 1000, mu: 0.3, nf: 1, pretension: 1.0e4}}"
        load = "  path: ramp\n  max: 15\n  steps: 12\n"
    with open(os.path.join(outdir, name + ".yaml"), "w") as f:
        f.write(f"# {name}: the eccentric bolt group of test/ref2d/bolt_group.py\n")
        f.write(f"scene:\n  name: {name}\n  patches: {name}.patches.csv\n  joints: {name}.joints.csv\n  bcs: {name}.bcs.csv\n")
        if plate == "shell":
            f.write(f"material:\n  plate:\n    E: {E}\n    nu: 0.33\n    t: 5\ncoupling:\n  radius: 11\n")
        f.write(f"joint:\n  bolt: {bolt}\n  loader: {{law: spring, kn: 0, kt: 1.0e7, kr: 0}}\n")
        f.write("load:\n" + load)
    return os.path.join(outdir, name + ".yaml")


# ------------------------------------------------------------------------------------------------
def read_steps(path):
    """Per step: load factor, the fasteners' in-plane forces (global x, y), their states, and the
    loader's force on the plate (global x, y)."""
    steps = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            st = steps.setdefault(int(r["step"]), {"load": float(r["load"]), "bolts": {}, "states": {}})
            j = int(r["joint"])
            f_t = np.array([float(r["f_t1"]), float(r["f_t2"])])
            if j == LOADER_ID:   # every joint: axis n = z, t1 = x, t2 = y
                st["loader"] = f_t
            else:
                st["bolts"][j] = f_t
                st["states"][j] = r["state"]
    return [steps[s] for s in sorted(steps)]


def bolt_forces(st):
    return np.array([st["bolts"][i] for i in range(len(BOLTS))])


def check_elastic(path, rtol, kr):
    """(a) on a rigid plate: exact at every step."""
    worst = 0.0
    steps = read_steps(path)
    for s, st in enumerate(steps, start=1):
        want = elastic(st["load"], kr=kr)
        got = bolt_forces(st)
        err = np.max(np.abs(got - want)) / np.max(np.abs(want))
        worst = max(worst, err)
        print(f"step {s}: P = {st['load']:g} N, fastener forces {np.round(got, 3).tolist()}, "
              f"elastic centroid method {np.round(want, 3).tolist()}, difference {err:.2e} of the largest")
    ok = worst <= rtol
    print(f"bolt_group.py elastic: largest difference {worst:.2e} of the largest fastener force (tolerance {rtol:g}): {'PASS' if ok else 'FAIL'}")
    return 0 if ok else 1


def check_elastic_limit(path1, path2, ratio, rtol):
    """(a) on shell plates of moduli E and ratio E: the plate's compliance adds an error in 1/E, so
    the error must shrink by the ratio (to 2%: the next term is second order) and the Richardson
    extrapolation to a rigid plate, (ratio F(ratio E) - F(E)) / (ratio - 1), must give the closed form."""
    s1, s2 = read_steps(path1)[-1], read_steps(path2)[-1]
    if s1["load"] != s2["load"]:
        print(f"FAIL: the runs end at different loads {s1['load']} and {s2['load']}")
        return 1
    want = elastic(s1["load"])
    f1, f2 = bolt_forces(s1), bolt_forces(s2)
    scale = np.max(np.abs(want))
    e1, e2 = np.max(np.abs(f1 - want)) / scale, np.max(np.abs(f2 - want)) / scale
    rich = (ratio * f2 - f1) / (ratio - 1)
    er = np.max(np.abs(rich - want)) / scale
    print(f"P = {s1['load']:g} N: elastic centroid method {np.round(want, 3).tolist()}")
    print(f"plate E:         {np.round(f1, 3).tolist()}, {e1:.3e} of the largest force")
    print(f"plate {ratio:g} E:  {np.round(f2, 3).tolist()}, {e2:.3e}; error ratio {e1 / e2:.4f}")
    print(f"Richardson extrapolation to a rigid plate: {er:.2e} of the largest force (tolerance {rtol:g})")
    ok = abs(e1 / e2 / ratio - 1) <= 0.02 and er <= rtol
    print(f"bolt_group.py elastic-limit: {'PASS' if ok else 'FAIL'}")
    return 0 if ok else 1


def check_plateau(path, rtol):
    ic, Pu, want = instantaneous_centre()
    st = read_steps(path)[-1]
    got = bolt_forces(st)
    P = st["loader"]
    ang = [abs(np.degrees(np.arctan2(cross(w, g), w @ g))) for w, g in zip(want, got)]
    e_P = abs(P @ LOAD_DIR - Pu) / Pu
    e_F = np.max(np.abs(got - want)) / G
    sliding = all(s == "slide" for s in st["states"].values())
    print(f"IC method: IC at ({ic[0]:.6f}, {ic[1]:.6f}) mm, P_u = {Pu:.6f} N")
    print(f"boltnet at load factor {st['load']:g}: P = {P @ LOAD_DIR:.6f} N (across: {P @ perp(LOAD_DIR):.2e}), "
          f"states {sorted(set(st['states'].values()))}")
    print(f"plateau load: {e_P:.2e} of P_u; fastener forces: {e_F:.2e} of G; directions within {max(ang):.2e} degrees")
    ok = sliding and e_P <= rtol and e_F <= rtol
    print(f"bolt_group.py plateau: {'PASS' if ok else 'FAIL'} (tolerance {rtol:g}{'' if sliding else '; not every fastener slides'})")
    return 0 if ok else 1


def selftest():
    """The closed forms' limits, then the reference network with lever arms against both."""
    fails = []
    # (b) e -> 0: every fastener carries G along the load (the IC goes to infinity);
    # e -> infinity: rotation about the centroid.
    _, Pu0, F0 = instantaneous_centre(at=np.array([0.01, 0.0]))
    if abs(Pu0 - len(BOLTS) * G) > 1e-6 * G:
        fails.append(f"IC method at e = 0: P_u = {Pu0}, not n G = {len(BOLTS) * G}")
    far = 1e7
    icf, Puf, _ = instantaneous_centre(at=np.array([far, 0.0]))
    Mu = G * np.sum(np.linalg.norm(BOLTS, axis=1))
    if abs(Puf * far - Mu) > 1e-5 * Mu or np.linalg.norm(icf) > 1e-3:
        fails.append(f"IC method at e = {far}: P_u e = {Puf * far}, not G sum r = {Mu}; IC {icf}")
    ic, Pu, F = instantaneous_centre()
    print(f"IC method: e = 300 mm: IC ({ic[0]:.4f}, {ic[1]:.4f}) mm, P_u = {Pu:.4f} N = {Pu / G:.5f} G "
          f"(e = 0: {Pu0 / G:.5f} G; pure moment: M_u = {Mu / G:.4f} G mm)")
    # The reference network (rigid plate, joints at their positions) against (a) and (b).
    here = os.path.dirname(os.path.abspath(__file__))
    sys.path.insert(0, here)
    from network import Network
    from scene import Scene
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        for control in ("force", "displacement"):
            net = Network(Scene(write_scene(tmp, "rigid", control)), attach="position")
            steps = net.run(net.scene.load_factors())
            last = steps[-1]
            got = np.array([net.joints[i]["R"][1:, :2].T @ last["joints"][i]["f"][1:] for i in range(len(BOLTS))])
            if control == "force":
                want = elastic(last["load"], kr=KR_RIGID)
                err = np.max(np.abs(got - want)) / np.max(np.abs(want))
                print(f"reference network, rigid plate, springs: {err:.1e} from the elastic centroid method")
                if err > 1e-10:
                    fails.append(f"reference network against the elastic centroid method: {err:.1e}")
            else:
                err = np.max(np.abs(got - F)) / G
                P = last["joints"][-1]["f"][1:] @ LOAD_DIR
                print(f"reference network, rigid plate, pure Coulomb, load point pushed 15 mm: fastener forces "
                      f"{err:.1e} of G from the IC method, load {abs(P) / Pu - 1:+.1e} of P_u")
                if err > 1e-6:
                    fails.append(f"reference network against the IC method: {err:.1e}")
    for f in fails:
        print("FAIL:", f)
    return 1 if fails else 0


def main(argv):
    if not argv:
        print(__doc__)
        return 2
    cmd, rest = argv[0], argv[1:]
    files = [a for a in rest if not a.startswith("--")][:2]
    opt = {rest[i]: rest[i + 1] for i in range(len(rest) - 1) if rest[i].startswith("--")}
    if cmd == "scene":
        print(write_scene(rest[0], opt.get("--plate", "shell"), opt.get("--control", "force"), float(opt.get("--E", 7.2e4))))
        return 0
    if cmd == "elastic":
        return check_elastic(rest[0], float(opt.get("--rtol", 1e-8)), float(opt.get("--kr", 0.0)))
    if cmd == "elastic-limit":
        return check_elastic_limit(files[0], files[1], float(opt["--ratio"]), float(opt.get("--rtol", 1e-7)))
    if cmd == "plateau":
        return check_plateau(rest[0], float(opt.get("--rtol", 1e-8)))
    if cmd == "selftest":
        return selftest()
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
