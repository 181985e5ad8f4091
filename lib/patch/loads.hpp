// The boundary conditions of one patch in its own dof numbering (6 per node: mesh nodes, then joint
// nodes; a rigid patch has node 0 only), per unit load factor. A condensed patch keeps those on its
// interior inside its condensation (patch/condense.hpp); the rest become rows of the network's
// vectors (network/boundary.cpp).
#pragma once

#include "model/model.hpp"
#include "patch/patch.hpp"

#include <map>

namespace boltnet {

struct PatchLoads {
  std::map<PetscInt, double> prescribed; // dof -> displacement per unit load factor (fixed: 0)
  std::map<PetscInt, double> force;      // dof -> force per unit load factor
};

// The conditions of model.bcs on the patch of part `part_id` (sp: its shell patch, or null for a
// rigid patch). A later condition on a dof overrides an earlier prescribed value; forces on a dof
// add up. A force on a dof that is also fixed or prescribed is an error naming both conditions
// (the force would be absorbed by the support and the run would look converged). A pressure
// (BOLTNET_BC_PRESSURE) adds the consistent nodal forces of the elements it loads; with exact
// coupling, those on footprint nodes go to their joint node (the footprint moves rigidly with it).
PetscErrorCode PatchLoadsFromModel(MPI_Comm comm, const Model &model, PetscInt part_id, const ShellPatch *sp, CouplingType coupling, PatchLoads *loads);

} // namespace boltnet
