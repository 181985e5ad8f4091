// Shell meshes of three- and four-node elements: a built-in generator of rectangular plates, node
// sets for boundary conditions, fastener footprints, nodal directors for curved surfaces (the cut of
// a part into patches: mesh/cut.hpp; the spatial index: mesh/search.hpp). Pure C++.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

namespace boltnet {

// The nodes of one element, counter-clockwise about its normal: four for a quadrilateral; three
// and -1 in the last place for a triangle (the layout of the C API and of the Nastran reader).
using MeshElement = std::array<int, 4>;

// The number of nodes of an element: 3 or 4.
inline int ElementNodes(const MeshElement &e) { return e[3] < 0 ? 3 : 4; }

struct ShellMesh {
  std::vector<std::array<double, 3>>      x;     // node coordinates (mm)
  std::vector<MeshElement>                elems; // quadrilaterals and triangles, in any order
  std::map<std::string, std::vector<int>> node_sets;
  // Nodal directors (NodalDirectors): empty, or one per node; a zero vector at a fold, where every
  // element keeps its own normal.
  std::vector<std::array<double, 3>> directors;
};

// Whether some element of m has all its nodes in its node set `set` (what a pressure on the set
// loads: patch/loads.hpp); false for a set m does not have.
bool HasElementIn(const ShellMesh &m, const std::string &set);

// How a generated plate is meshed: quadrilaterals; each quadrilateral split into two triangles
// along a diagonal that alternates like a checkerboard, so that the mesh is symmetric about the
// plate's centre lines when nx and ny are even; or mixed, quadrilaterals and triangle pairs in a
// checkerboard.
enum class PlateElements { Quads, Triangles, Mixed };

// A flat rectangular plate [x0, x0 + lx] x [y0, y0 + ly] at height z, nx by ny cells.
// Node sets: "xmin", "xmax", "ymin", "ymax" (the four edges).
ShellMesh RectanglePlate(double x0, double y0, double lx, double ly, int nx, int ny, double z, PlateElements kind = PlateElements::Quads);

// Nodes of the mesh within `radius` of the point p, measured in the plane normal to `axis`
// (the fastener's footprint); sorted by node number.
std::vector<int> Footprint(const ShellMesh &m, const std::array<double, 3> &p, const std::array<double, 3> &axis, double radius);

// The element whose projection on the plane normal to `axis` contains p (on its boundary counts),
// the nearest along the axis if several do; -1 if none (p is outside the part).
int ContainingElement(const ShellMesh &m, const std::array<double, 3> &p, const std::array<double, 3> &axis);

// The footprint the couplings use (docs/coupling.md): the nodes within `radius` of p and, when they
// are fewer than three (a coarse mesh: they cannot carry a moment about the fastener, or there are
// none), also the nodes of the element containing p. Empty if neither finds a node.
std::vector<int> CouplingFootprint(const ShellMesh &m, const std::array<double, 3> &p, const std::array<double, 3> &axis, double radius);

// The mesh node nearest to p in the plane normal to `axis` (the lowest number among equals).
int NearestNode(const ShellMesh &m, const std::array<double, 3> &p, const std::array<double, 3> &axis);

// The element's own normal at its node k (not normalised): the triangle's plane, or the normal of
// the quadrilateral's bilinear surface at that corner, (X_k+1 - X_k) x (X_k-1 - X_k).
std::array<double, 3> CornerNormal(const ShellMesh &m, const MeshElement &e, int k);

// The element's angle at its node k (radians).
double CornerAngle(const ShellMesh &m, const MeshElement &e, int k);

// Directors of a curved mesh (docs/shell.md, "Warped elements and kinks"): at each node the unit
// mean of the adjacent elements' own normals at that node, weighted by the element's angle there,
// on the side of most of them (elements numbered clockwise neither cancel nor turn it). A node
// where some element's normal is more than kFoldAngleDeg from that mean is a fold (a stiffener, a
// T-joint, a flange) and gets the zero vector: there every element keeps its own normal. Empty when
// every element's own normal lies within 1e-8 rad of the mean at every node: a flat mesh, or
// quadrilaterals whose corner normals already agree (a regular mesh of the twisted beam). At a free
// edge the mean is one-sided (first order in the element size; second order inside).
constexpr double kFoldAngleDeg = 20;
std::vector<std::array<double, 3>> NodalDirectors(const ShellMesh &m);

// The directors handed to element e: for each node the mesh director turned to the element's side
// (the element's own normal at a fold). False, and V untouched, where the mesh has no directors or
// they all agree with the element's own normals to 1e-8 rad (the element's default is then the
// same, to round-off, and flat elements stay bit for bit what they were).
bool ElementDirectors(const ShellMesh &m, const MeshElement &e, std::array<std::array<double, 3>, 4> &V);

} // namespace boltnet
