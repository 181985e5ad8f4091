"""Writes the scene: NAME.yaml, its three CSV tables, the per-fastener metadata, the linear-spring
override and a JSON description of the model (loads, parts, counts) for the checks and the charts."""
import json
import os

from .fasteners import TORQUE, axial_k, huth_k, laminate_modulus


def _num(v):
    return f"{v:.10g}"


def materials(a):
    """name -> (YAML mapping text, membrane modulus along the span free to contract across (Huth's
    E, beam theory's lower bound), and held across (the upper bound))."""
    iso = lambda E, t: (f"{{E: {_num(E)}, nu: 0.33, t: {_num(t)}}}", E, E / (1 - 0.33 ** 2))
    th = a.thickness
    m = {"fuselage": iso(a.E_fuselage, th["fuselage"]), "substructure": iso(a.E_sub, th["substructure"]),
         "upper_tee": iso(a.E_fitting, th["upper_tee"]), "lower_strap": iso(a.E_fitting, th["lower_strap"]),
         "fitting": iso(a.E_fitting, th["fitting"]),
         "upper_skin_centre": iso(a.E_upper, th["upper_skin"]), "lower_skin_centre": iso(a.E_lower, th["lower_skin"])}
    for which, E in (("upper", a.E_upper), ("lower", a.E_lower)):
        t = th[f"{which}_skin"]
        if a.outer_skin == "aluminium":
            m[f"{which}_skin_outer"] = iso(E, t)
            continue
        plies = laminate_layup(a, t)
        ply = dict(a.ply, t=t / len(plies))
        # boltnet's laminate reference direction is global x (the chord here): a spanwise ply is 90.
        ref = [((p + 90 + 90) % 180) - 90 for p in plies]
        txt = (f"{{type: laminate, layup: \"{','.join(_num(p) for p in ref)}\", ply_t: {_num(ply['t'])}, E1: {_num(ply['E1'])}, "
               f"E2: {_num(ply['E2'])}, nu12: {_num(ply['nu12'])}, G12: {_num(ply['G12'])}, G13: {_num(ply['G13'])}, G23: {_num(ply['G23'])}}}")
        m[f"{which}_skin_outer"] = (txt,) + laminate_modulus(ref, ply, 90.0)
    return m


def laminate_layup(a, t):
    """A balanced symmetric layup of about t / ply thickness plies from the repeating sub-laminate
    (angles from the span)."""
    n = max(2, int(round(t / a.ply["t"] / 2)) * 2)
    half = [a.sublaminate[k % len(a.sublaminate)] for k in range(n // 2)]
    return half + half[::-1]


def joint_types(a, fasteners, bin_centres, part_material, mats):
    """YAML of every joint type used, and the parameters of each (for the metadata)."""
    th = a.thickness
    part_t = lambda p: th[thickness_key(part_material[p])]
    types = {}
    for f in fasteners:
        if f.type in types:
            continue
        t1, t2 = part_t(f.a), part_t(f.b)
        E1, E2 = mats[part_material[f.a]][1], mats[part_material[f.b]][1]
        laminate = any(mats[part_material[p]][0].startswith("{type: laminate") for p in (f.a, f.b))
        kind = "bolted-composite" if laminate else "bolted-metal"
        if f.family.startswith("a"):
            k = huth_k(f.d, t1, t2, E1, E2, a.E_fastener, kind)
            kn = axial_k(f.d, t1, t2, a.E_fastener)
            types[f.type] = dict(law="spring", kn=kn, kt=k, kr=1e3 * kn * f.d ** 2, d=f.d, t1=t1, t2=t2, E1=E1, E2=E2, huth=kind)
        else:
            suffix = f.type[len(f.family):]   # the bin's number, or "" for a type with per-joint gaps
            hole = f.d + (0.0 if a.fit == "interference" else bin_centres[int(suffix) - 1 if suffix else 0])
            types[f.type] = dict(law="friction", d=f.d, hole=hole, t1=t1, t2=t2, E1=E1, E2=E2, Ef=a.E_fastener, torque=TORQUE[f.d] * a.torque_factor,
                                 mu=a.mu, huth=kind)
    lines = []
    for name, p in sorted(types.items()):
        if p["law"] == "spring":
            lines.append(f"  {name}: {{law: spring, kn: {_num(p['kn'])}, kt: {_num(p['kt'])}, kr: {_num(p['kr'])}}}"
                         f"   # Huth {p['huth']}, d {p['d']}, t {_num(p['t1'])} + {_num(p['t2'])}")
        else:
            lines.append(f"  {name}:\n    from: geometry\n    fastener: {{d: {p['d']}, hole: {_num(p['hole'])}, t1: {_num(p['t1'])}, t2: {_num(p['t2'])}, "
                         f"E1: {_num(p['E1'])}, E2: {_num(p['E2'])}, Ef: {_num(p['Ef'])}, torque: {_num(p['torque'])}, mu: {_num(p['mu'])}, "
                         f"formula: huth, type: {p['huth']}}}")
    return types, "\n".join(lines)


def thickness_key(material):
    for k in ("upper_skin", "lower_skin"):
        if material.startswith(k):
            return k
    return material


def bypass_width(fasteners):
    """The pitch along a row of the upper outer skin splice: the width of the strip that each of its
    fasteners takes the bypass load of (the default, 6 coupling radii, is narrower than the
    footprint's one element here, and its strip would hold no element outside the footprint)."""
    pos = sorted(j.pos for j in fasteners if j.splice == "upper_outer" and j.row == 1 and j.side == fasteners[0].side)
    gaps = [b - a for a, b in zip(pos, pos[1:])]
    return min(gaps) if gaps else 0.0  # one fastener a row: no pitch, the driver's default (0)


def write(out, name, a, part_info, fasteners, bcs, types_yaml, mats, model, rigid=(), ties=()):
    """rigid: (name, position) of rigid patches (after the shell parts); ties: (rigid patch, part,
    axis, t1) of joints of type `tie` from a rigid patch to the part's node set `tip`, at the rigid
    patch's position."""
    os.makedirs(out, exist_ok=True)
    base = os.path.join(out, name)
    pid = {p["name"]: k + 1 for k, p in enumerate(part_info)}
    pid.update({r: len(part_info) + 1 + k for k, (r, _) in enumerate(rigid)})
    model["rigid_patches"] = {r: pid[r] for r, _ in rigid}
    with open(base + ".patches.csv", "w") as f:
        f.write(f"# {name}: one Gmsh part per file (scripts/make-wing-fuselage)\nid,kind,x,y,z,mesh,part,material\n")
        for p in part_info:
            f.write(f"{pid[p['name']]},gmsh,0,0,0,{p['file']},{p['name']},{p['material']}\n")
        for r, P in rigid:
            f.write(f"{pid[r]},rigid," + ",".join(_num(c) for c in P) + ",,,\n")
    where = dict(rigid)
    gaps = any(j.gap is not None for j in fasteners)   # each fastener's own clearance (assign_types)
    with open(base + ".joints.csv", "w") as f:
        f.write("id,patch_a,patch_b,type,nx,ny,nz,t1x,t1y,t1z,x,y,z" + (",footprint" if ties else "") + (",gap" if gaps else "") + "\n")
        for j in fasteners:
            v = list(j.n) + list(j.t1) + list(j.x)
            f.write(f"{j.id},{pid[j.a]},{pid[j.b]},{j.type}," + ",".join(_num(c) for c in v) + ("," if ties else "")
                    + (f",{'' if j.gap is None else f'{j.gap:.6g}'}" if gaps else "") + "\n")
        for k, (r, part, n, t1) in enumerate(ties):
            v = list(n) + list(t1) + list(where[r])
            f.write(f"{len(fasteners) + 1 + k},{pid[r]},{pid[part]},tie," + ",".join(_num(c) for c in v) + ",tip" + ("," if gaps else "") + "\n")
    with open(base + ".fasteners.csv", "w") as f:
        f.write("joint,splice,side,row,index,position,family,type,d,clearance,patch_a,patch_b,part_a,part_b\n")
        for j in fasteners:
            f.write(f"{j.id},{j.splice},{j.side},{j.row},{j.index},{_num(j.pos)},{j.family},{j.type},{j.d},{j.clearance:.5f},"
                    f"{pid[j.a]},{pid[j.b]},{j.a},{j.b}\n")
    loads = any(len(r) > 5 for r in bcs)   # rows of a named load (the cabin pressure's cases)
    with open(base + ".bcs.csv", "w") as f:
        f.write("patch,dof,kind,value,set" + (",load" if loads else "") + "\n")
        for part, dof, kind, value, st, *load in bcs:
            f.write(f"{pid[part]},{dof},{kind},{_num(value)},{st}" + (f",{load[0] if load else ''}" if loads else "") + "\n")
    with open(base + ".linear.opts", "w") as f:
        f.write("# Every junction fastener a linear spring: a preload so large that no fastener ever slides, so each\n"
                "# one keeps its identified stick stiffness (kt = kc, kn, kr). Use: boltnet -scene NAME.yaml -options_file this\n")
        for t, p in sorted(model["joint_types"].items()):
            if p["law"] == "friction":
                f.write(f"-joint_{t}_fastener_preload 1e12\n")
    mat_yaml = "\n".join(f"  {k}: {v[0]}" for k, v in sorted(mats.items()) if any(p["material"] == k for p in part_info))
    with open(base + ".yaml", "w") as f:
        f.write(model["yaml_header"])
        f.write(f"scene:\n  name: {name}\n  patches: {name}.patches.csv\n  joints: {name}.joints.csv\n  bcs: {name}.bcs.csv\n")
        f.write(f"material:\n{mat_yaml}\njoint:\n{types_yaml}\n")
        f.write(f"coupling:\n  type: exact\n  radius: {_num(a.coupling_radius)}   # below half of every element: each footprint is the element holding the fastener\n"
                f"  reach: {_num(a.coupling_reach)}    # along the bolt: beyond the distance from a fastener to its sheets' mid-surfaces\n")
        f.write(f"load:\n  path: table\n  table: {','.join(_num(v) for v in a.load_table)}   # load factors (g); forces in the bcs table are the 1 g loads\n"
                f"  steps: {a.load_steps}\n")
        if a.cabin_pressure > 0:
            # The wing's path alone, the pressure alone, both together up to 1 g, and the wing's
            # path with the cabin pressurised first and the pressure held (docs/scenes.md, "Load
            # cases", "Held loads").
            f.write("  cases: [flight, cabin, cruise, pressurise, pressurised-flight]\n  case:\n"
                    "    flight:   # the wing's load path, unpressurised\n      loads: wing\n"
                    "    cabin:    # the cabin pressurised and let down, no wing load\n      loads: cabin\n      table: 1,0\n"
                    "    cruise:   # 1 g with the cabin pressurised, both applied together\n      loads: wing,cabin\n      table: 1\n"
                    "    pressurise:   # the cabin pressurised, no wing load ...\n      loads: cabin\n      table: 1\n"
                    "    pressurised-flight:   # ... then held while the wing goes through its load path\n"
                    "      loads: wing\n      continues: pressurise\n")
        f.write(f"output:\n  bypass_width: {_num(bypass_width(fasteners))}   # the skin splices' pitch along a row: each fastener's "
                f"bypass load is its strip's (docs/output.md, \"Bypass\")\n"
                f"  bypass_length: {_num(a.row_spacing_skin / 2)}   # half the row spacing: each band ends short of the next row\n")
    with open(base + ".model.json", "w") as f:
        json.dump({k: v for k, v in model.items() if k != "yaml_header"}, f, indent=1)
