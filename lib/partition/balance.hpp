// Distributing the patches over the ranks by dof (docs/architecture.md, "Patches and seams").
#pragma once

#include <petscdmnetwork.h>

#include <vector>

namespace boltnet {

// On rank 0 (the graph given there; other ranks pass empty vectors): METIS k-way on the patch
// graph, vertex weight = the patch's dof, edge weight = the joints and seams between two patches,
// then each edge goes to the lower of its two vertices' ranks. PETSc gives a vertex shared by
// several ranks to the highest of them, so a patch joined to a patch of its own rank stays there;
// the achieved balance is measured after distribution. The network's plex partitioner becomes a
// shell partitioner holding that edge partition (-petscpartitioner_type on the command line still
// overrides it). Collective.
PetscErrorCode SetPatchPartition(DM dm, const std::vector<PetscInt> &weights, const std::vector<PetscInt> &edgelist);

} // namespace boltnet
