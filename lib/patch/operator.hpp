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
// Compressed rows (columns increasing) of the n x n matrix that the triplets falling in it make:
// row[] maps a patch dof to its row and column (negative: not in the matrix). Each entry is summed
// in the triplets' order, the order in which MatSetValue(ADD_VALUES) would add them one by one, so
// the values are the same to the bit; a dense marker per column finds an entry already met in its
// row, so the cost is linear in the triplets.
PatchOperator CompressRows(PetscInt n, const Triplets &t, const std::vector<PetscInt> &row);

} // namespace boltnet
