// Cutting a large shell part into patches (network vertices) with a graph partitioner. Pure C++.
//
// Every mesh node goes to exactly one patch. An element whose nodes all lie in one patch belongs to
// that patch; an element with nodes in several patches is split: the stiffness between two nodes of
// one patch is added to that patch, the stiffness between nodes of two patches to the seam edge
// joining them (docs/architecture.md, "Patches and seams"). The discrete model is therefore the same
// however the part is cut; only where each stiffness entry is added changes. With condensed patches
// (docs/solver.md) every node that a seam touches is a port of its patch, so the cut decides the size
// of the interface problem: METIS keeps it small.
#pragma once

#include "mesh/mesh.hpp"

#include <vector>

namespace boltnet {

struct PartCut {
  int              npatches = 1;
  std::vector<int> patch; // patch of every mesh node, 0..npatches-1
};

// Cut mesh m into ceil(nodes / max_nodes) patches of about the same number of nodes, minimising the
// number of element connections cut: METIS k-way on the graph of nodes (two nodes are adjacent when
// they share an element), contiguous parts. The nodes of each cluster (a fastener's footprint and
// the elements touching it) are contracted to one graph vertex first, so each cluster stays in one
// patch. max_nodes <= 0, or a part within it, means no cut. Deterministic (fixed METIS seed).
// Throws std::runtime_error if METIS fails.
PartCut CutPart(const ShellMesh &m, const std::vector<std::vector<int>> &clusters, long max_nodes);

} // namespace boltnet
