// boltnet's PetscLogEvents and PetscLogStages, registered once by BoltnetInitializePackage(), so that
// -log_view says where the time goes. Events: set-up (layout, network), condensation of the patches
// (within it: each patch's matrix, its Schur complement taken out of MUMPS),
// assembly of the interface (residual and Jacobian), its linear solve in each Newton iteration
// (the factorisation included: KSPSetPreSolve / KSPSetPostSolve), recovery of the interiors, and output
// (within it, the element results of the fields: strains, stresses, section forces). Stages
// (-log_view's "Summary of Stages", and every event table split by stage): "Boltnet Set-up" (layout
// and network), "Boltnet Condense" (the patch operators and their Schur complements), "Boltnet Solve"
// (SNESSolve on the interface: assembly, PETSc's KSPSolve / PCSetUp / MatLUFactorNum, the line
// search) and "Boltnet Output" (recovery of the interiors where output needs them, the files).
// What runs outside them (reading the scene, the driver) stays in PETSc's "Main Stage".
#pragma once
#include <petsclog.h>

namespace boltnet {
struct LogEvents {
  PetscClassId  classid = 0;
  PetscLogEvent layout = 0, network = 0, condense = 0, patch_matrix = 0, schur = 0, residual = 0, jacobian = 0, joints = 0, interface_solve = 0, recover = 0, output = 0, element_results = 0, joint_output = 0, joint_gather = 0;
  PetscLogStage setup_stage = 0, condense_stage = 0, solve_stage = 0, output_stage = 0;
};
// The package's events (valid after BoltnetInitializePackage()).
const LogEvents &Events();
} // namespace boltnet
