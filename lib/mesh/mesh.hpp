// Quadrilateral shell meshes: a built-in generator of rectangular plates, node sets for boundary
// conditions, fastener footprints (the cut of a part into patches: mesh/cut.hpp; the spatial index: mesh/search.hpp). Pure C++.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

namespace boltnet {

struct QuadMesh {
  std::vector<std::array<double, 3>>         x;     // node coordinates (mm)
  std::vector<std::array<int, 4>>            quads; // counter-clockwise node numbers
  std::map<std::string, std::vector<int>>    node_sets;
};

// A flat rectangular plate [x0, x0 + lx] x [y0, y0 + ly] at height z, nx by ny elements.
// Node sets: "xmin", "xmax", "ymin", "ymax" (the four edges).
QuadMesh RectanglePlate(double x0, double y0, double lx, double ly, int nx, int ny, double z);

// Nodes of the mesh within `radius` of the point p, measured in the plane normal to `axis`
// (the fastener's footprint); sorted by node number.
std::vector<int> Footprint(const QuadMesh &m, const std::array<double, 3> &p, const std::array<double, 3> &axis, double radius);

// The element whose projection on the plane normal to `axis` contains p (on its boundary counts),
// the nearest along the axis if several do; -1 if none (p is outside the part).
int ContainingElement(const QuadMesh &m, const std::array<double, 3> &p, const std::array<double, 3> &axis);

// The footprint the couplings use (docs/coupling.md): the nodes within `radius` of p and, when they
// are fewer than three (a coarse mesh: they cannot carry a moment about the fastener, or there are
// none), also the four nodes of the element containing p. Empty if neither finds a node.
std::vector<int> CouplingFootprint(const QuadMesh &m, const std::array<double, 3> &p, const std::array<double, 3> &axis, double radius);

// The mesh node nearest to p in the plane normal to `axis` (the lowest number among equals).
int NearestNode(const QuadMesh &m, const std::array<double, 3> &p, const std::array<double, 3> &axis);

} // namespace boltnet
