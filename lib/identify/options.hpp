// A fastener's geometry as PETSc options (prefix chosen by the caller), shared by boltnet-identify
// (-fastener_*) and the scenes (-joint_<type>_fastener_*, with -joint_<type>_from geometry).
#pragma once
#include "identify/fastener.hpp"

#include <petscsys.h>

namespace boltnet {
namespace identify {

struct FastenerOptions {
  FastenerGeometry g;
  Formula          formula = Formula::Huth;
  HuthType         type    = HuthType::BoltedMetal;
  double           kt = 0, kg = 0, kr = 0;
  PetscBool        has_mu = PETSC_FALSE;
};

// Reads the geometry options -<prefix>d, -<prefix>hole, ... (listed by -help with units).
PetscErrorCode FastenerFromOptions(MPI_Comm comm, const char prefix[], const char title[], FastenerOptions *o);
// Checks the geometry and returns the frictional macroelement; errors name the options -<prefix>*.
PetscErrorCode FastenerMacroelement(MPI_Comm comm, const char prefix[], const FastenerOptions &o, Params *p);

} // namespace identify
} // namespace boltnet
