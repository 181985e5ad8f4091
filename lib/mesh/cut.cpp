#include "mesh/cut.hpp"

#include <algorithm>
#include <numeric>

namespace boltnet {
namespace {

// Union-find root with path halving.
int Root(std::vector<int> &parent, int i)
{
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// A strip assignment is usable if every element spans at most two neighbouring strips and each
// strip but the last is joined to the next by at least one element (else a strip would be an island
// of the network, reached by no edge).
bool Usable(const QuadMesh &m, const std::vector<int> &patch, int npatches)
{
  std::vector<char> joined(npatches, 0);
  for (const auto &q : m.quads) {
    int lo = patch[q[0]], hi = lo;
    for (int k = 1; k < 4; ++k) {
      lo = std::min(lo, patch[q[k]]);
      hi = std::max(hi, patch[q[k]]);
    }
    if (hi - lo > 1) return false;
    if (hi > lo) joined[lo] = 1;
  }
  for (int s = 0; s + 1 < npatches; ++s)
    if (!joined[s]) return false;
  return true;
}

} // namespace

PartCut CutIntoStrips(const QuadMesh &m, const std::vector<std::vector<int>> &clusters, long max_nodes)
{
  const int n = (int)m.x.size();
  PartCut   cut;
  cut.patch.assign(n, 0);
  if (max_nodes <= 0 || n <= max_nodes) return cut;

  // The direction of the longest extent of the bounding box.
  int    axis = 0;
  double best = -1;
  for (int k = 0; k < 3; ++k) {
    double lo = m.x[0][k], hi = lo;
    for (const auto &x : m.x) {
      lo = std::min(lo, x[k]);
      hi = std::max(hi, x[k]);
    }
    if (hi - lo > best) best = hi - lo, axis = k;
  }
  // Units: single nodes, or clusters (footprints) merged where they share nodes.
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto &c : clusters)
    for (size_t i = 1; i < c.size(); ++i) parent[Root(parent, c[i])] = Root(parent, c[0]);
  std::vector<double> coord(n, 0.0);
  std::vector<int>    size(n, 0);
  for (int i = 0; i < n; ++i) {
    const int r = Root(parent, i);
    coord[r] += m.x[i][axis];
    size[r]++;
  }
  std::vector<int> units;
  for (int i = 0; i < n; ++i)
    if (Root(parent, i) == i) {
      coord[i] /= size[i];
      units.push_back(i);
    }
  std::stable_sort(units.begin(), units.end(), [&](int l, int r) { return coord[l] < coord[r]; });

  for (int k = (int)((n + max_nodes - 1) / max_nodes); k > 1; --k) {
    // Strip s takes units while the nodes before them are fewer than (s + 1) n / k.
    std::vector<int> strip(n, 0);
    long             before = 0;
    for (int u : units) {
      strip[u] = (int)std::min<long>(k - 1, before * k / n);
      before += size[u];
    }
    std::vector<int> patch(n);
    for (int i = 0; i < n; ++i) patch[i] = strip[Root(parent, i)];
    if (Usable(m, patch, k)) {
      cut.npatches = k;
      cut.patch    = std::move(patch);
      return cut;
    }
  }
  return cut; // no usable cut: the part stays whole
}

} // namespace boltnet
