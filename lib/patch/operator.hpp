// Building blocks of the patch operators (patch.hpp), shared by the whole and the condensed forms.
#pragma once

#include "patch/patch.hpp"

#include <tuple>
#include <vector>

namespace boltnet {

using Triplets = std::vector<std::tuple<PetscInt, PetscInt, double>>;

// The shell stiffness of the patch's whole elements and its share of the shared ones, in the
// patch's dof numbering (6 per node, joint nodes after the mesh nodes).
Triplets ShellTriplets(const ShellPatch &p);
// T^T K T for exact coupling (no slave column); constraint_rows adds c (u_s - T u_m) = 0 on each
// slave row (the patch kept whole), otherwise the slave rows are left empty (condensed patches
// recover the slaves from their joint node).
Triplets EliminateSlaves(const ShellPatch &p, const SlaveMap &s, const Triplets &t, bool constraint_rows);
// The penalty links of every footprint.
void AddPenaltyLinks(const ShellPatch &p, double penalty, double radius, Triplets &t);
// K with its coupling: the operator of BuildShellOperator as triplets.
Triplets PatchTriplets(const ShellPatch &p, CouplingType type, double penalty, double radius, bool constraint_rows);
// Compressed rows of n x n from triplets (summing duplicates; t is sorted in place).
PatchOperator Compress(PetscInt n, Triplets &t);

} // namespace boltnet
