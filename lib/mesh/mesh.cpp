#include "mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace boltnet {

QuadMesh RectanglePlate(double x0, double y0, double lx, double ly, int nx, int ny, double z)
{
  if (nx < 1 || ny < 1) throw std::invalid_argument("a plate needs at least one element in each direction");
  if (!(lx > 0) || !(ly > 0)) throw std::invalid_argument("a plate needs positive lengths");
  QuadMesh m;
  auto     id = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.x.push_back({x0 + lx * i / nx, y0 + ly * j / ny, z});
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) m.quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  for (int j = 0; j <= ny; ++j) {
    m.node_sets["xmin"].push_back(id(0, j));
    m.node_sets["xmax"].push_back(id(nx, j));
  }
  for (int i = 0; i <= nx; ++i) {
    m.node_sets["ymin"].push_back(id(i, 0));
    m.node_sets["ymax"].push_back(id(i, ny));
  }
  return m;
}

std::vector<int> Footprint(const QuadMesh &m, const std::array<double, 3> &p, const std::array<double, 3> &axis, double radius)
{
  const double an = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  if (!(an > 0)) throw std::invalid_argument("the fastener axis is the zero vector");
  std::vector<int> nodes;
  for (size_t i = 0; i < m.x.size(); ++i) {
    double d[3], dn = 0;
    for (int k = 0; k < 3; ++k) {
      d[k] = m.x[i][k] - p[k];
      dn += d[k] * axis[k] / an;
    }
    double r2 = 0;
    for (int k = 0; k < 3; ++k) {
      const double t = d[k] - dn * axis[k] / an;
      r2 += t * t;
    }
    if (r2 <= radius * radius * (1 + 1e-12)) nodes.push_back(static_cast<int>(i));
  }
  return nodes;
}

} // namespace boltnet
