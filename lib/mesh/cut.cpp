#include "mesh/cut.hpp"

#include <metis.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>

namespace boltnet {
namespace {

int Root(std::vector<int> &parent, int i)
{
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

} // namespace

PartCut CutPart(const ShellMesh &m, const std::vector<std::vector<int>> &clusters, long max_nodes)
{
  PartCut    cut;
  const long n = (long)m.x.size();
  cut.patch.assign(n, 0);
  if (max_nodes <= 0 || n <= max_nodes) return cut;
  // Contract the clusters: graph vertex of each node.
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto &c : clusters)
    for (size_t k = 1; k < c.size(); ++k) parent[Root(parent, c[k])] = Root(parent, c[0]);
  std::vector<int> vertex(n, -1);
  idx_t            nv = 0;
  for (long i = 0; i < n; ++i)
    if (Root(parent, (int)i) == i) vertex[i] = nv++;
  for (long i = 0; i < n; ++i) vertex[i] = vertex[Root(parent, (int)i)];
  const long want = (n + max_nodes - 1) / max_nodes;
  if (nv < 2 || want < 2) return cut;
  // Adjacency of graph vertices through elements, weighted by the number of node pairs.
  std::vector<std::map<idx_t, idx_t>> adj(nv);
  for (const auto &q : m.elems)
    for (int a = 0; a < ElementNodes(q); ++a)
      for (int b = 0; b < ElementNodes(q); ++b) {
        const idx_t u = vertex[q[a]], v = vertex[q[b]];
        if (u != v) adj[u][v]++;
      }
  std::vector<idx_t> xadj(1, 0), adjncy, adjwgt, vwgt(nv, 0), part(nv, 0);
  for (long i = 0; i < n; ++i) vwgt[vertex[i]]++;
  for (idx_t u = 0; u < nv; ++u) {
    for (const auto &kv : adj[u]) {
      adjncy.push_back(kv.first);
      adjwgt.push_back(kv.second);
    }
    xadj.push_back((idx_t)adjncy.size());
  }
  idx_t ncon = 1, nparts = (idx_t)std::min<long>(want, nv), objval = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED]      = 1; // the same cut on every run and every rank
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_CONTIG]    = 1; // patches without islands where the part has none
  int status = METIS_PartGraphKway(&nv, &ncon, xadj.data(), adjncy.data(), vwgt.data(), nullptr, adjwgt.data(), &nparts, nullptr, nullptr, options, &objval, part.data());
  if (status != METIS_OK) { // a part made of several pieces cannot be cut into contiguous patches
    options[METIS_OPTION_CONTIG] = 0;
    status = METIS_PartGraphKway(&nv, &ncon, xadj.data(), adjncy.data(), vwgt.data(), nullptr, adjwgt.data(), &nparts, nullptr, nullptr, options, &objval, part.data());
  }
  if (status != METIS_OK) throw std::runtime_error("METIS could not cut a part of " + std::to_string(n) + " nodes into " + std::to_string(nparts) + " patches (status " + std::to_string(status) + ")");
  // Number the patches that received nodes 0..npatches-1, in order of their lowest node.
  std::vector<int> renum(nparts, -1);
  int              np = 0;
  for (long i = 0; i < n; ++i) {
    int &r = renum[part[vertex[i]]];
    if (r < 0) r = np++;
    cut.patch[i] = r;
  }
  cut.npatches = np;
  return cut;
}

} // namespace boltnet
