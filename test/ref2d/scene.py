"""Reads a boltnet scene (docs/scenes.md) for the independent network reference (network.py).

A scene is a PETSc YAML options file: nested maps become option names (`joint: bolt: kt: 1.5e5` is
`-joint_bolt_kt 1.5e5`); options on the command line win over the file; relative paths in the file
are relative to its directory, on the command line to the current directory. The patches, joints
and boundary conditions are CSV tables (a header; blank lines and lines starting with '#' skipped;
columns found by name). Only what a network of rigid patches needs is read; anything else the
reference cannot model (shell patches) is refused with a message naming it.

Written from docs/scenes.md and docs/joint-laws.md only, so that it shares no code with boltnet.
"""
import csv
import os

import numpy as np

DOFS = ["ux", "uy", "uz", "rx", "ry", "rz"]

# Parameters of a joint type and their defaults (docs/scenes.md, "Options").
JOINT_DEFAULTS = {"law": "spring", "kn": 0.0, "kt": 0.0, "kr": 0.0, "kc": 0.0, "kg": 0.0, "gap": 0.0,
                  "mu": 0.0, "nf": 1.0, "pretension": 0.0, "clamp_coupling": 0.0,
                  "offset_t1": 0.0, "offset_t2": 0.0}


class SceneError(Exception):
    pass


def read_yaml_options(path):
    """The options of a PETSc YAML file made of nested maps of scalars (block maps, and flow maps
    `{kn: 1, kt: 2}` of scalars): {'-joint_bolt_kt': '1.5e5'}."""
    options = {}
    stack = []  # (indent, key)
    with open(path) as f:
        for lineno, raw in enumerate(f, start=1):
            line = raw.split("#", 1)[0].rstrip()
            if not line.strip():
                continue
            indent = len(line) - len(line.lstrip(" "))
            if ":" not in line:
                raise SceneError(f"{path} line {lineno}: expected 'key: value'")
            key, value = line.strip().split(":", 1)
            while stack and stack[-1][0] >= indent:
                stack.pop()
            value = value.strip()
            name = "-" + "_".join([k for _, k in stack] + [key.strip()])
            if value.startswith("{") and value.endswith("}"):   # a flow map of scalars: {kn: 1, kt: 2}
                for item in value[1:-1].split(","):
                    if ":" not in item:
                        raise SceneError(f"{path} line {lineno}: expected 'key: value' in '{value}'")
                    k, v = item.split(":", 1)
                    options[name + "_" + k.strip()] = v.strip()
            elif value:
                options[name] = value
            else:
                stack.append((indent, key.strip()))
    return options


def read_table(path, required):
    """Rows of a CSV table as dicts; a missing column is named with the file."""
    with open(path) as f:
        lines = [(n, l) for n, l in enumerate(f, start=1) if l.strip() and not l.lstrip().startswith("#")]
    if not lines:
        raise SceneError(f"{path}: empty table")
    header = [c.strip() for c in next(csv.reader([lines[0][1]]))]
    for c in required:
        if c not in header:
            raise SceneError(f"{path}: no column '{c}'")
    rows = []
    for n, l in lines[1:]:
        cells = [c.strip() for c in next(csv.reader([l]))]
        row = dict(zip(header, cells))
        row["_where"] = f"{path} line {n}"
        rows.append(row)
    return rows


class Scene:
    """Patches, joints (with their types' parameters), boundary conditions and the load path."""

    def __init__(self, path, overrides=()):
        self.path = path
        opts = read_yaml_options(path)
        base = os.path.dirname(os.path.abspath(path))
        for k, v in list(opts.items()):
            if k in ("-scene_patches", "-scene_joints", "-scene_bcs") and not os.path.isabs(v):
                opts[k] = os.path.join(base, v)
        over = list(overrides)
        if len(over) % 2:
            raise SceneError(f"options must come in pairs: {over}")
        for k, v in zip(over[0::2], over[1::2]):
            if not k.startswith("-"):
                raise SceneError(f"option name '{k}' must start with '-'")
            opts[k] = v
        self.options = opts
        self._read_patches()
        self._read_joints()
        self._read_bcs()
        self._read_load()

    def option(self, name, default=None):
        return self.options.get(name, default)

    def _read_patches(self):
        rows = read_table(self.options["-scene_patches"], ["id", "kind", "x", "y", "z"])
        self.patch_ids = []
        self.patch_pos = []
        for r in rows:
            if r["kind"] != "rigid":
                raise SceneError(f"{r['_where']}: patch kind '{r['kind']}': the reference models rigid patches only")
            self.patch_ids.append(int(r["id"]))
            self.patch_pos.append([float(r[c]) for c in "xyz"])
        self.patch_index = {p: i for i, p in enumerate(self.patch_ids)}
        self.patch_pos = np.array(self.patch_pos)

    def joint_type(self, name):
        params = dict(JOINT_DEFAULTS)
        for k in params:
            v = self.options.get(f"-joint_{name}_{k}")
            if v is not None:
                params[k] = v if k == "law" else float(v)
        if params["law"] not in ("spring", "contact", "friction"):
            raise SceneError(f"-joint_{name}_law {params['law']}: not spring, contact or friction")
        return params

    def _read_joints(self):
        rows = read_table(self.options["-scene_joints"], ["id", "patch_a", "patch_b", "type", "nx", "ny", "nz", "t1x", "t1y", "t1z"])
        self.joints = []
        types = {}
        for r in rows:
            for side in ("patch_a", "patch_b"):
                if int(r[side]) not in self.patch_index:
                    raise SceneError(f"{r['_where']}: {side} {r[side]} is not a patch")
            n = np.array([float(r[c]) for c in ("nx", "ny", "nz")])
            t1 = np.array([float(r[c]) for c in ("t1x", "t1y", "t1z")])
            n = n / np.linalg.norm(n)
            t1 = t1 - (t1 @ n) * n                # t1 made orthogonal to n (docs/scenes.md)
            t1 = t1 / np.linalg.norm(t1)
            t2 = np.cross(n, t1)                  # the frame (n, t1, t2) is right-handed
            pos = None
            if all(r.get(c, "") != "" for c in "xyz"):
                pos = np.array([float(r[c]) for c in "xyz"])
            name = r["type"]
            if name not in types:
                types[name] = self.joint_type(name)
            self.joints.append({"id": int(r["id"]), "a": self.patch_index[int(r["patch_a"])],
                                "b": self.patch_index[int(r["patch_b"])], "R": np.array([n, t1, t2]),
                                "pos": pos, "type": name, "p": types[name]})
        self.joints.sort(key=lambda j: j["id"])

    def _read_bcs(self):
        rows = read_table(self.options["-scene_bcs"], ["patch", "dof", "kind", "value"])
        npd = 6 * len(self.patch_ids)
        self.prescribed = {}          # global dof -> value per unit load factor (fixed: 0)
        self.force = np.zeros(npd)    # applied force per unit load factor
        for r in rows:
            p = int(r["patch"])
            if p not in self.patch_index:
                raise SceneError(f"{r['_where']}: patch {p} does not exist")
            dofs = range(6) if r["dof"] == "all" else [DOFS.index(r["dof"])]
            for d in dofs:
                g = 6 * self.patch_index[p] + d
                if r["kind"] == "fixed":
                    self.prescribed[g] = 0.0
                elif r["kind"] == "displacement":
                    self.prescribed[g] = float(r["value"])
                elif r["kind"] == "force":
                    self.force[g] += float(r["value"])
                else:
                    raise SceneError(f"{r['_where']}: kind '{r['kind']}'")

    def _read_load(self):
        kind = self.options.get("-load_path", "ramp")
        if kind == "ramp":
            self.breakpoints = [float(self.options.get("-load_max", 1.0))]
        else:
            self.breakpoints = [float(v) for v in str(self.options["-load_table"]).split(",")]
        self.steps = int(self.options.get("-load_steps", 10))

    def load_factors(self):
        """Each segment from the previous breakpoint (0 first) split into equal steps (docs/solver.md)."""
        out, start = [], 0.0
        for to in self.breakpoints:
            if to == start:
                continue
            for k in range(1, self.steps + 1):
                out.append(to if k == self.steps else start + (to - start) * k / self.steps)
            start = to
        return out
