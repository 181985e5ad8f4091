"""One part of the junction as a Gmsh model: mapped (transfinite) blocks meshed with quadrangles.

Each part is built in its own Gmsh model from four-sided blocks: a map (u, v) -> (x, y, z) over a
rectangle of parameters with n_u by n_v elements. Edges are straight lines, or circular arcs about
the fuselage axis (the x axis). Blocks that share an edge share its Gmsh curve (points and curves are
looked up by position), so a part made of several surfaces (a skin and its frames, a spar web and its
caps) is one conformal mesh. Every block is a transfinite surface with recombination: structured
quadrangles only, with the node positions of the grids (grids.py), so that the fasteners computed from
the same grids fall at element centres.

The part is written as a Gmsh MSH 4.1 ASCII file holding one physical surface (the part, named like
the file), physical curves (node sets for boundary conditions) and, where a part has them, physical
surfaces of some of its blocks (the fuselage's skin: a node set for the cabin pressure); boltnet
reads one part per file.
"""
import numpy as np

import gmsh

_KEY = 1e-5  # mm: points closer than this are one point


def _key(p):
    return tuple(int(round(c / _KEY)) for c in p)


class Part:
    def __init__(self, name):
        self.name = name
        gmsh.model.add(name)
        self.points = {}   # key -> tag
        self.curves = {}   # (pa, pb, centre key) -> (tag, n)
        self.curve_pts = {}  # tag -> (start, mid, end) coordinates
        self.surfaces = []
        self.groups = {}   # name -> (surface tags, outward(p) -> the direction its elements must face, or None)
        self.nblocks = 0

    def point(self, p):
        k = _key(p)
        t = self.points.get(k)
        if t is None:
            t = gmsh.model.geo.addPoint(float(p[0]), float(p[1]), float(p[2]))
            self.points[k] = t
        return t

    def curve(self, p, q, n, centre=None):
        """A line from p to q, or an arc about `centre`, with n elements; signed tag (reused curves
        run backwards)."""
        a, b = self.point(p), self.point(q)
        ck = _key(centre) if centre is not None else None
        for key, sign in (((a, b, ck), 1), ((b, a, ck), -1)):
            if key in self.curves:
                tag, m = self.curves[key]
                if m != n:
                    raise ValueError(f"part {self.name}: a curve shared by two blocks has {m} and {n} elements")
                return sign * tag
        if centre is None:
            tag = gmsh.model.geo.addLine(a, b)
            mid = 0.5 * (np.asarray(p) + np.asarray(q))
        else:
            c = np.asarray(centre, float)
            tag = gmsh.model.geo.addCircleArc(a, self.point(centre), b)
            m = 0.5 * (np.asarray(p) + np.asarray(q)) - c
            r = np.linalg.norm(np.asarray(p) - c)
            mid = c + m * r / np.linalg.norm(m)
        gmsh.model.geo.mesh.setTransfiniteCurve(tag, n + 1)
        self.curves[(a, b, ck)] = (tag, n)
        self.curve_pts[tag] = (np.asarray(p, float), mid, np.asarray(q, float))
        return tag

    def block(self, f, useg, vseg, u_centre=None, v_centre=None, planar=True, group=None, outward=None):
        """Block (u0, u1, nu) x (v0, v1, nv) of the map f(u, v) -> xyz. u_centre(v): centre of the
        arcs along u (None: lines); v_centre(u) likewise along v. group: a physical surface (besides
        the part) that the block belongs to; outward(p): the direction its elements must face (their
        normal, right-handed about their node order: what a pressure pushes along), at point p."""
        (u0, u1, nu), (v0, v1, nv) = useg, vseg
        P = [f(u0, v0), f(u1, v0), f(u1, v1), f(u0, v1)]
        c = [self.curve(P[0], P[1], nu, u_centre(v0) if u_centre else None),
             self.curve(P[1], P[2], nv, v_centre(u1) if v_centre else None),
             self.curve(P[2], P[3], nu, u_centre(v1) if u_centre else None),
             self.curve(P[3], P[0], nv, v_centre(u0) if v_centre else None)]
        loop = gmsh.model.geo.addCurveLoop(c)
        s = gmsh.model.geo.addPlaneSurface([loop]) if planar else gmsh.model.geo.addSurfaceFilling([loop])
        gmsh.model.geo.mesh.setTransfiniteSurface(s)
        gmsh.model.geo.mesh.setRecombine(2, s)
        if outward is not None:
            # The mesh follows the orientation of the curve loop P0 P1 P2 P3; reversed where that
            # faces the other way (checked element by element once meshed).
            n = np.cross(np.subtract(P[1], P[0]), np.subtract(P[3], P[0]))
            if np.dot(n, outward(np.mean(P, axis=0))) < 0:
                gmsh.model.geo.mesh.setReverse(2, s)
        if group is not None:
            self.groups.setdefault(group, ([], outward))[0].append(s)
        self.surfaces.append(s)
        self.nblocks += 1
        return s

    def blocks(self, f, ugrid, vgrid, keep=None, **kw):
        """Every (u segment, v segment) block of two grids, or those for which keep(useg, vseg)."""
        for us in ugrid.segs:
            for vs in vgrid.segs:
                if keep is None or keep(us, vs):
                    self.block(f, us, vs, **kw)

    def mesh(self, node_sets):
        """Mesh the part; node_sets: name -> predicate(xyz array (3,)) true on every point of the
        set's curves (checked at both ends and the middle of each curve)."""
        gmsh.model.geo.synchronize()
        gmsh.model.mesh.generate(2)
        gmsh.model.addPhysicalGroup(2, self.surfaces, 1)
        gmsh.model.setPhysicalName(2, 1, self.name)
        # Groups of surfaces: physical surfaces that boltnet reads as node sets of the part (a pressure
        # on such a set loads the group's elements: docs/scenes.md, "Pressure").
        for k, (name, (tags, outward)) in enumerate(sorted(self.groups.items())):
            gmsh.model.addPhysicalGroup(2, tags, 2 + k)
            gmsh.model.setPhysicalName(2, 2 + k, name)
            if outward is not None:
                self._check_facing(name, tags, outward)
        self.sets = {}
        for k, (name, pred) in enumerate(node_sets.items()):
            tags = [t for t, pts in self.curve_pts.items() if all(pred(p) for p in pts)]
            if not tags:
                raise ValueError(f"part {self.name}: node set '{name}' holds no curve")
            gmsh.model.addPhysicalGroup(1, tags, 100 + k)
            gmsh.model.setPhysicalName(1, 100 + k, name)
            self.sets[name] = 100 + k

    def _check_facing(self, name, tags, outward):
        """Every element of the surfaces `tags` faces outward(its centre)."""
        ntags, xyz, _ = gmsh.model.mesh.getNodes()
        pos = dict(zip(ntags.tolist(), xyz.reshape(-1, 3)))
        for s in tags:
            etypes, _, enodes = gmsh.model.mesh.getElements(2, s)
            for et, en in zip(etypes, enodes):
                nn = 4 if et == 3 else 3
                for q in np.asarray(en).reshape(-1, nn):
                    X = np.array([pos[int(t)] for t in q])
                    n = np.cross(X[1] - X[0], X[nn - 1] - X[0])
                    if np.dot(n, outward(X.mean(axis=0))) <= 0:
                        raise RuntimeError(f"part {self.name}: an element of surface group '{name}' faces inward at {X.mean(axis=0)}")

    def arrays(self):
        """Node coordinates (N, 3), quadrangles (Q, 4) as row indices, node sets as index arrays."""
        tags, xyz, _ = gmsh.model.mesh.getNodes()
        order = np.argsort(tags)
        tags, xyz = tags[order], xyz.reshape(-1, 3)[order]
        etypes, _, enodes = gmsh.model.mesh.getElements(2)
        if list(etypes) != [3]:
            raise RuntimeError(f"part {self.name}: the mesh has element types {list(etypes)}, not only 4-node quadrangles")
        quads = np.searchsorted(tags, enodes[0]).reshape(-1, 4)
        used = np.unique(quads)
        sets = {}
        for name, ptag in self.sets.items():
            st, _ = gmsh.model.mesh.getNodesForPhysicalGroup(1, ptag)
            sets[name] = np.searchsorted(tags, st)
        return xyz, quads, used, sets

    def write(self, path):
        gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
        gmsh.option.setNumber("Mesh.Binary", 0)
        gmsh.option.setNumber("Mesh.SaveAll", 0)
        gmsh.write(path)

    def close(self):
        gmsh.model.remove()
