// Nodal directors of a shell mesh (mesh.hpp). The element kernels bend and shear with the change of
// nodal directors; by default each element uses its own normals, which on a faceted curved surface
// disagree between neighbours, so that a rotation about one element's normal bends the next one
// (docs/shell.md, "Warped elements and kinks": triangles on the twisted beam converge to 1.098
// with their own normals, 0.9985 with the surface's). Averaging the elements' normals at each node
// gives every element around it the same director.
#include "mesh/mesh.hpp"

#include <cmath>

namespace boltnet {
namespace {

using Vec = std::array<double, 3>;

Vec Sub(const Vec &a, const Vec &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec Cross(const Vec &a, const Vec &b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double Dot(const Vec &a, const Vec &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double Norm(const Vec &a) { return std::sqrt(Dot(a, a)); }

Vec Unit(const Vec &a)
{
  const double n = Norm(a);
  return n > 0 ? Vec{a[0] / n, a[1] / n, a[2] / n} : Vec{0, 0, 0};
}

// Two unit vectors within 1e-8 rad of each other (by the sine: the cosine cannot resolve it).
bool Same(const Vec &a, const Vec &b) { return Dot(a, b) > 0 && Norm(Cross(a, b)) <= 1e-8; }

} // namespace

double CornerAngle(const ShellMesh &m, const MeshElement &e, int k)
{
  const int nn = ElementNodes(e);
  const Vec a  = Sub(m.x[e[(k + 1) % nn]], m.x[e[k]]), b = Sub(m.x[e[(k + nn - 1) % nn]], m.x[e[k]]);
  return std::atan2(Norm(Cross(a, b)), Dot(a, b));
}

std::array<double, 3> CornerNormal(const ShellMesh &m, const MeshElement &e, int k)
{
  const int nn = ElementNodes(e);
  const Vec &x = m.x[e[k]], &next = m.x[e[(k + 1) % nn]], &prev = m.x[e[(k + nn - 1) % nn]];
  return Cross(Sub(next, x), Sub(prev, x));
}

std::vector<std::array<double, 3>> NodalDirectors(const ShellMesh &m)
{
  const double     foldCos = std::cos(kFoldAngleDeg * 3.14159265358979323846 / 180);
  const size_t     nv      = m.x.size();
  std::vector<Vec> first(nv, Vec{0, 0, 0}), sum(nv, Vec{0, 0, 0});
  // The mean of the elements' unit normals at each node, each turned to the side of the node's first
  // element (elements numbered clockwise must not cancel) and weighted by the element's angle at the
  // node, so that the mean does not depend on how the cells around it were split into triangles
  // (Thuermer and Wuethrich, "Computing vertex normals from polygonal facets", J. Graphics Tools 3,
  // 1998).
  for (const MeshElement &e : m.elems)
    for (int k = 0; k < ElementNodes(e); ++k) {
      const int v = e[k];
      Vec       n = Unit(CornerNormal(m, e, k));
      if (Dot(first[v], first[v]) == 0) first[v] = n;
      const double w = (Dot(n, first[v]) < 0 ? -1 : 1) * CornerAngle(m, e, k);
      for (int c = 0; c < 3; ++c) sum[v][c] += w * n[c];
    }
  std::vector<Vec> V(nv);
  for (size_t v = 0; v < nv; ++v) V[v] = Unit(sum[v]);
  // Turned to the side of most of the elements around the node (by angle), whichever came first;
  // a node is a fold where some element's normal is more than kFoldAngleDeg from the mean (or there
  // is no mean).
  std::vector<double> side(nv, 0.0);
  std::vector<char>   fold(nv, 0);
  bool                curved = false;
  for (const MeshElement &e : m.elems)
    for (int k = 0; k < ElementNodes(e); ++k) {
      const int    v = e[k];
      const Vec    n = Unit(CornerNormal(m, e, k));
      const double c = Dot(n, V[v]);
      side[v] += c < 0 ? -CornerAngle(m, e, k) : CornerAngle(m, e, k);
      if (!(std::fabs(c) >= foldCos)) fold[v] = 1;
      if (!Same(n, V[v]) && !Same(n, Vec{-V[v][0], -V[v][1], -V[v][2]})) curved = true;
    }
  if (!curved) return {};
  for (size_t v = 0; v < nv; ++v) {
    if (fold[v]) V[v] = {0, 0, 0};
    if (side[v] < 0) V[v] = {-V[v][0], -V[v][1], -V[v][2]};
  }
  return V;
}

bool ElementDirectors(const ShellMesh &m, const MeshElement &e, std::array<std::array<double, 3>, 4> &V)
{
  if (m.directors.empty()) return false;
  std::array<Vec, 4> W{};
  bool               differs = false;
  for (int k = 0; k < ElementNodes(e); ++k) {
    const Vec own = Unit(CornerNormal(m, e, k));
    const Vec &d  = m.directors[e[k]];
    if (Dot(d, d) == 0) { // a fold: the element's own normal
      W[k] = own;
      continue;
    }
    W[k]    = Dot(d, own) < 0 ? Vec{-d[0], -d[1], -d[2]} : d;
    differs = differs || !Same(W[k], own);
  }
  if (!differs) return false;
  V = W;
  return true;
}

} // namespace boltnet
