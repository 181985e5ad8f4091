// Cutting a large shell part into patches (network vertices) joined by seams. Pure C++.
//
// Every mesh node goes to exactly one patch. An element whose four nodes are in one patch belongs
// to that patch; an element with nodes in two patches belongs to the seam between them (a network
// edge). The discrete model is therefore the same, element for element, however the part is cut:
// only where each element's stiffness is added changes (docs/architecture.md, "Patches and seams").
#pragma once

#include "mesh/mesh.hpp"

#include <vector>

namespace boltnet {

struct PartCut {
  int              npatches = 1;
  std::vector<int> patch; // patch of every mesh node, 0..npatches-1
};

// Cut mesh m into at most ceil(nodes / max_nodes) strips across its longest extent, with about the
// same number of nodes each. The nodes of each cluster (a fastener's footprint) stay in one strip, so
// that a joint and its footprint live in one patch. A cut is kept only if every element has its nodes
// in at most two neighbouring strips and every strip is joined to the next one by a seam element;
// otherwise fewer strips are tried, down to one (no cut). max_nodes <= 0 means no cut.
PartCut CutIntoStrips(const QuadMesh &m, const std::vector<std::vector<int>> &clusters, long max_nodes);

} // namespace boltnet
