#!/usr/bin/python3
"""Writes a scene of an open thin cylinder under internal pressure (for check_tube_pressure.py).

An open tube (radius R, length L, thickness t) meshed by Gmsh with quadrangles, its elements facing
outward (checked here), loaded by the pressure p along their normals (bcs kind `pressure`). It is held
against rigid motion only: u_x = 0 on the end x = 0 (no radial restraint), u_z = 0 at the points at
angles 0 and 180 degrees of that end, u_y = 0 at 90 degrees; so its state is the membrane one, a hoop
stress pR/t and no axial stress. A spring of 1e-9 N/mm joins the node at (L/2, R, 0) to a fixed rigid
patch along y (node coupling): its jump is minus the radial displacement there.
Usage: make_tube_scene.py OUTDIR [--R 500 --L 1000 --t 2 --p 0.1 --around 48 --along 20]
"""
import argparse
import os

import numpy as np

import gmsh


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    for k, v in (("R", 500.0), ("L", 1000.0), ("t", 2.0), ("p", 0.1)):
        ap.add_argument("--" + k, type=float, default=v)
    ap.add_argument("--around", type=int, default=48, help="elements around (a multiple of 4)")
    ap.add_argument("--along", type=int, default=20, help="elements along (even: a node at L/2)")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    gmsh.initialize(readConfigFiles=False)
    gmsh.option.setNumber("General.Verbosity", 2)
    gmsh.model.add("tube")
    geo = gmsh.model.geo
    c = geo.addPoint(0, 0, 0)
    pts = [geo.addPoint(0, a.R * np.cos(th), a.R * np.sin(th)) for th in np.arange(4) * np.pi / 2]
    arcs = [geo.addCircleArc(pts[k], c, pts[(k + 1) % 4]) for k in range(4)]
    for arc in arcs:
        geo.mesh.setTransfiniteCurve(arc, a.around // 4 + 1)
    out = geo.extrude([(1, arc) for arc in arcs], a.L, 0, 0, numElements=[a.along], recombine=True)
    surfaces = [t for d, t in out if d == 2]
    geo.synchronize()
    gmsh.model.mesh.generate(2)
    ntags, xyz, _ = gmsh.model.mesh.getNodes()
    pos = dict(zip(ntags.tolist(), xyz.reshape(-1, 3)))
    facing = []
    for s in surfaces:
        _, _, enodes = gmsh.model.mesh.getElements(2, s)
        for q in np.asarray(enodes[0]).reshape(-1, 4):
            X = np.array([pos[int(n)] for n in q])
            n = np.cross(X[1] - X[0], X[3] - X[0])
            m = X.mean(axis=0)
            facing.append(np.sign(n @ np.array([0.0, m[1], m[2]])))
    facing = set(facing)
    if len(facing) != 1:
        raise SystemExit("make_tube_scene: the tube's elements do not all face one way")
    sign = facing.pop()   # +1: outward; the pressure is written along the normals so that it pushes out
    gmsh.model.addPhysicalGroup(2, surfaces, 1)
    gmsh.model.setPhysicalName(2, 1, "tube")
    gmsh.model.addPhysicalGroup(1, arcs, 2)
    gmsh.model.setPhysicalName(1, 2, "end0")
    for k, name in ((0, "at0"), (1, "at90"), (2, "at180")):
        gmsh.model.addPhysicalGroup(0, [pts[k]], 3 + k)
        gmsh.model.setPhysicalName(0, 3 + k, name)
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.option.setNumber("Mesh.SaveAll", 0)
    gmsh.write(os.path.join(a.out, "tube.msh"))
    gmsh.finalize()
    with open(os.path.join(a.out, "tube.patches.csv"), "w") as f:
        f.write(f"id,kind,x,y,z,mesh,part,material\n0,gmsh,0,0,0,tube.msh,tube,tube\n1,rigid,{a.L / 2},{a.R},0,,,\n")
    with open(os.path.join(a.out, "tube.joints.csv"), "w") as f:
        f.write(f"id,patch_a,patch_b,type,nx,ny,nz,t1x,t1y,t1z,x,y,z\n0,0,1,sensor,0,1,0,1,0,0,{a.L / 2},{a.R},0\n")
    with open(os.path.join(a.out, "tube.bcs.csv"), "w") as f:
        f.write("patch,dof,kind,value,set\n0,ux,fixed,0,end0\n0,uz,fixed,0,at0\n0,uz,fixed,0,at180\n0,uy,fixed,0,at90\n"
                f"1,all,fixed,0,\n0,all,pressure,{sign * a.p},\n")
    with open(os.path.join(a.out, "tube.yaml"), "w") as f:
        f.write(f"# An open tube under internal pressure {a.p} MPa (test/make_tube_scene.py).\n"
                "scene:\n  name: tube\n  patches: tube.patches.csv\n  joints: tube.joints.csv\n  bcs: tube.bcs.csv\n"
                f"material:\n  tube:\n    E: 70000\n    nu: 0.3\n    t: {a.t}\n"
                "joint:\n  sensor:\n    law: spring\n    kn: 1.0e-9\n    kt: 1.0e-9\n"
                "coupling:\n  type: node\nload:\n  path: table\n  table: 1\n  steps: 1\n")


if __name__ == "__main__":
    main()
