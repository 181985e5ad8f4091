#include "mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace boltnet {

bool HasElementIn(const ShellMesh &m, const std::string &set)
{
  auto it = m.node_sets.find(set);
  if (it == m.node_sets.end()) return false;
  std::vector<char> in(m.x.size(), 0);
  for (int v : it->second) in[v] = 1;
  return std::any_of(m.elems.begin(), m.elems.end(), [&](const MeshElement &e) { return std::all_of(e.begin(), e.begin() + ElementNodes(e), [&](int v) { return in[v]; }); });
}

ShellMesh RectanglePlate(double x0, double y0, double lx, double ly, int nx, int ny, double z, PlateElements kind)
{
  if (nx < 1 || ny < 1) throw std::invalid_argument("a plate needs at least one element in each direction");
  if (!(lx > 0) || !(ly > 0)) throw std::invalid_argument("a plate needs positive lengths");
  ShellMesh m;
  auto      id = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.x.push_back({x0 + lx * i / nx, y0 + ly * j / ny, z});
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      const bool even = (i + j) % 2 == 0;
      if (kind == PlateElements::Quads || (kind == PlateElements::Mixed && even)) {
        m.elems.push_back({a, b, c, d});
        continue;
      }
      // Two triangles, counter-clockwise; the diagonal a-c on even cells, b-d on odd ones.
      if (even || kind == PlateElements::Mixed) { // a mixed mesh splits only odd cells: along a-c
        m.elems.push_back({a, b, c, -1});
        m.elems.push_back({a, c, d, -1});
      } else {
        m.elems.push_back({a, b, d, -1});
        m.elems.push_back({b, c, d, -1});
      }
    }
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

namespace {
// In-plane offset of q from p (the component normal to the unit axis n removed) and the axial one.
void Split(const std::array<double, 3> &q, const std::array<double, 3> &p, const double n[3], double t[3], double *dn)
{
  double d[3];
  *dn = 0;
  for (int k = 0; k < 3; ++k) {
    d[k] = q[k] - p[k];
    *dn += d[k] * n[k];
  }
  for (int k = 0; k < 3; ++k) t[k] = d[k] - *dn * n[k];
}

void UnitAxis(const std::array<double, 3> &axis, double n[3])
{
  const double an = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  if (!(an > 0)) throw std::invalid_argument("the fastener axis is the zero vector");
  for (int k = 0; k < 3; ++k) n[k] = axis[k] / an;
}
} // namespace

int ContainingElement(const ShellMesh &m, const std::array<double, 3> &p, const std::array<double, 3> &axis)
{
  double n[3];
  UnitAxis(axis, n);
  int    best = -1;
  double bestd = 0;
  for (size_t e = 0; e < m.elems.size(); ++e) {
    // Corners relative to p, in the plane normal to the axis: p is inside a convex (or mildly
    // warped) quadrangle or a triangle when every edge sees it on the same side, up to a relative
    // tolerance.
    const int nn = ElementNodes(m.elems[e]);
    double    t[4][3], dn[4], size = 0, sum = 0;
    for (int k = 0; k < nn; ++k) {
      Split(m.x[m.elems[e][k]], p, n, t[k], &dn[k]);
      size = std::max(size, std::sqrt(t[k][0] * t[k][0] + t[k][1] * t[k][1] + t[k][2] * t[k][2]));
      sum += dn[k];
    }
    int pos = 0, neg = 0;
    for (int k = 0; k < nn; ++k) {
      const double *a = t[k], *b = t[(k + 1) % nn];
      // (a - p) x (b - p) . n, with p at the origin
      const double c = (a[1] * b[2] - a[2] * b[1]) * n[0] + (a[2] * b[0] - a[0] * b[2]) * n[1] + (a[0] * b[1] - a[1] * b[0]) * n[2];
      const double tol = 1e-10 * size * size;
      if (c > tol) pos++;
      else if (c < -tol) neg++;
    }
    if (pos && neg) continue;
    const double d = std::fabs(sum / nn); // the mean axial distance
    if (best < 0 || d < bestd) best = (int)e, bestd = d;
  }
  return best;
}

std::vector<int> CouplingFootprint(const ShellMesh &m, const std::array<double, 3> &p, const std::array<double, 3> &axis, double radius)
{
  std::vector<int> nodes = Footprint(m, p, axis, radius);
  if (nodes.size() >= 3) return nodes;
  const int e = ContainingElement(m, p, axis);
  if (e < 0) return nodes;
  for (int k = 0; k < ElementNodes(m.elems[e]); ++k) nodes.push_back(m.elems[e][k]);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

int NearestNode(const ShellMesh &m, const std::array<double, 3> &p, const std::array<double, 3> &axis)
{
  double n[3];
  UnitAxis(axis, n);
  int    best = -1;
  double bestr = 0;
  for (size_t i = 0; i < m.x.size(); ++i) {
    double t[3], dn;
    Split(m.x[i], p, n, t, &dn);
    const double r2 = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
    if (best < 0 || r2 < bestr * (1 - 1e-12)) best = (int)i, bestr = r2;
  }
  return best;
}

std::vector<int> Footprint(const ShellMesh &m, const std::array<double, 3> &p, const std::array<double, 3> &axis, double radius)
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
