#include "mesh/search.hpp"

#include <algorithm>
#include <map>
#include <cmath>
#include <stdexcept>

namespace boltnet {

NodeGrid::NodeGrid(const std::vector<std::array<double, 3>> &x, double cell) : x_(x), h_(cell)
{
  if (!(h_ > 0) || !std::isfinite(h_)) throw std::invalid_argument("NodeGrid: the cell size must be > 0");
  cells_.reserve(x.size() / 4 + 1);
  for (size_t i = 0; i < x.size(); ++i) cells_[CellOf(x[i])].push_back((int)i);
}

NodeGrid::Key NodeGrid::CellOf(const std::array<double, 3> &p) const
{
  return {(long long)std::floor(p[0] / h_), (long long)std::floor(p[1] / h_), (long long)std::floor(p[2] / h_)};
}

std::vector<int> NodeGrid::Ball(const std::array<double, 3> &p, double r) const
{
  std::vector<int> out;
  const Key        lo = CellOf({p[0] - r, p[1] - r, p[2] - r}), hi = CellOf({p[0] + r, p[1] + r, p[2] + r});
  const double     r2 = r * r * (1 + 1e-12);
  // A huge query against a fine grid visits the occupied cells instead of the empty ones.
  const double span = (double)(hi[0] - lo[0] + 1) * (double)(hi[1] - lo[1] + 1) * (double)(hi[2] - lo[2] + 1);
  auto         take = [&](const std::vector<int> &nodes) {
    for (int i : nodes) {
      double d2 = 0;
      for (int k = 0; k < 3; ++k) d2 += (x_[i][k] - p[k]) * (x_[i][k] - p[k]);
      if (d2 <= r2) out.push_back(i);
    }
  };
  if (span > (double)cells_.size()) {
    for (const auto &kv : cells_) {
      bool in = true;
      for (int k = 0; k < 3; ++k) in = in && kv.first[k] >= lo[k] && kv.first[k] <= hi[k];
      if (in) take(kv.second);
    }
  } else {
    for (long long i = lo[0]; i <= hi[0]; ++i)
      for (long long j = lo[1]; j <= hi[1]; ++j)
        for (long long k = lo[2]; k <= hi[2]; ++k) {
          auto it = cells_.find({i, j, k});
          if (it != cells_.end()) take(it->second);
        }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::vector<int>> NodeElements(const ShellMesh &m)
{
  std::vector<std::vector<int>> t(m.x.size());
  for (size_t e = 0; e < m.elems.size(); ++e)
    for (int k = 0; k < ElementNodes(m.elems[e]); ++k) t[m.elems[e][k]].push_back((int)e);
  return t;
}

} // namespace boltnet

namespace boltnet {
namespace {
double ElementDiameter(const ShellMesh &m, const MeshElement &q)
{
  double    d  = 0;
  const int nn = ElementNodes(q);
  for (int a = 0; a < nn; ++a)
    for (int b = a + 1; b < nn; ++b) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += (m.x[q[a]][k] - m.x[q[b]][k]) * (m.x[q[a]][k] - m.x[q[b]][k]);
      d = std::max(d, std::sqrt(s));
    }
  return d;
}

double MeanEdge(const ShellMesh &m)
{
  double s = 0;
  for (const auto &q : m.elems) s += ElementDiameter(m, q);
  return m.elems.empty() ? 1.0 : std::max(s / (double)m.elems.size() / std::sqrt(2.0), 1e-9);
}

void Unit(const std::array<double, 3> &axis, double n[3])
{
  const double an = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  if (!(an > 0)) throw std::invalid_argument("the fastener axis is the zero vector");
  for (int k = 0; k < 3; ++k) n[k] = axis[k] / an;
}
} // namespace

FootprintFinder::FootprintFinder(const ShellMesh &m, double reach) : m_(m), reach_(reach), grid_(m.x, MeanEdge(m)), touching_(NodeElements(m))
{
  for (const auto &q : m.elems) hmax_ = std::max(hmax_, ElementDiameter(m, q));
}

std::vector<int> FootprintFinder::Near(const std::array<double, 3> &p, const double n[3], double r, double sheet) const
{
  std::vector<int>    cand;
  std::vector<double> axial;
  double              amin = -1;
  for (int i : grid_.Ball(p, std::sqrt(r * r + reach_ * reach_))) {
    double d[3], dn = 0, r2 = 0;
    for (int k = 0; k < 3; ++k) {
      d[k] = m_.x[i][k] - p[k];
      dn += d[k] * n[k];
    }
    for (int k = 0; k < 3; ++k) r2 += (d[k] - dn * n[k]) * (d[k] - dn * n[k]);
    if (r2 > r * r * (1 + 1e-12) || std::fabs(dn) > reach_) continue;
    cand.push_back(i);
    axial.push_back(std::fabs(dn));
    amin = amin < 0 ? std::fabs(dn) : std::min(amin, std::fabs(dn));
  }
  std::vector<int> out;
  for (size_t k = 0; k < cand.size(); ++k)
    if (axial[k] <= amin + sheet) out.push_back(cand[k]);
  return out;
}

std::vector<int> FootprintFinder::Footprint(const std::array<double, 3> &p, const std::array<double, 3> &axis, double radius) const
{
  double n[3];
  Unit(axis, n);
  return Near(p, n, radius, radius);
}

int FootprintFinder::ContainingElement(const std::array<double, 3> &p, const std::array<double, 3> &axis) const
{
  double n[3];
  Unit(axis, n);
  // Candidates: the elements touching a node near the point; then the test of mesh.cpp on them.
  std::vector<int> elems;
  for (int i : Near(p, n, hmax_, hmax_))
    for (int e : touching_[i]) elems.push_back(e);
  std::sort(elems.begin(), elems.end());
  elems.erase(std::unique(elems.begin(), elems.end()), elems.end());
  ShellMesh sub;
  std::map<int, int> local;
  for (int e : elems) {
    MeshElement q = {-1, -1, -1, -1};
    for (int k = 0; k < ElementNodes(m_.elems[e]); ++k) {
      auto it = local.find(m_.elems[e][k]);
      if (it == local.end()) {
        it = local.emplace(m_.elems[e][k], (int)sub.x.size()).first;
        sub.x.push_back(m_.x[m_.elems[e][k]]);
      }
      q[k] = it->second;
    }
    sub.elems.push_back(q);
  }
  const int s = boltnet::ContainingElement(sub, p, axis);
  return s < 0 ? -1 : elems[s];
}

std::vector<int> FootprintFinder::CouplingFootprint(const std::array<double, 3> &p, const std::array<double, 3> &axis, double radius) const
{
  std::vector<int> nodes = Footprint(p, axis, radius);
  if (nodes.size() >= 3) return nodes;
  const int e = ContainingElement(p, axis);
  if (e < 0) return nodes;
  for (int k = 0; k < ElementNodes(m_.elems[e]); ++k) nodes.push_back(m_.elems[e][k]);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

int FootprintFinder::NearestNode(const std::array<double, 3> &p, const std::array<double, 3> &axis) const
{
  double n[3];
  Unit(axis, n);
  // Widen the in-plane search until a node is found (the nearest sheet within the reach).
  for (double r = std::max(hmax_, 1e-9);; r *= 2) {
    const std::vector<int> near = Near(p, n, r, r);
    int                    best = -1;
    double                 bestr = 0;
    for (int i : near) {
      double d[3], dn = 0, r2 = 0;
      for (int k = 0; k < 3; ++k) {
        d[k] = m_.x[i][k] - p[k];
        dn += d[k] * n[k];
      }
      for (int k = 0; k < 3; ++k) r2 += (d[k] - dn * n[k]) * (d[k] - dn * n[k]);
      if (best < 0 || r2 < bestr * (1 - 1e-12)) best = i, bestr = r2;
    }
    if (best >= 0) return best;
    if (r > 1e3 * (reach_ + hmax_) + 1e12 || m_.x.empty()) return -1;
  }
}

} // namespace boltnet
