// boltnet's PetscLogEvents, registered once by BoltnetInitializePackage(), so that -log_view says
// where the time goes: set-up (layout, network), condensation of the patches, assembly of the
// interface (residual and Jacobian), recovery of the interiors, and output. The interface solve is
// PETSc's own KSPSolve / PCSetUp / MatLUFactorNum under SNESSolve.
#pragma once
#include <petsclog.h>

namespace boltnet {
struct LogEvents {
  PetscClassId  classid = 0;
  PetscLogEvent layout = 0, network = 0, condense = 0, residual = 0, jacobian = 0, joints = 0, recover = 0, output = 0, joint_output = 0, joint_gather = 0;
};
// The package's events (valid after BoltnetInitializePackage()).
const LogEvents &Events();
} // namespace boltnet
