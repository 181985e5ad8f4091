// Quadrilateral shell meshes: a built-in generator of rectangular plates, node sets for boundary
// conditions, fastener footprints (the cut of a part into patches: mesh/cut.hpp). Pure C++.
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

} // namespace boltnet
