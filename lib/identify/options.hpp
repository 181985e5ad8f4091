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

// The shell correction (identify/coupon.hpp): options -<prefix>shell_*.
struct ShellCorrectionOptions {
  PetscBool on     = PETSC_FALSE;
  double    h      = 0;    // element size around the fastener (mm); 0: measured on the joint's patches (scenes)
  double    width  = 0;    // coupon width; 0: 5 d
  double    spring = 1e3;  // the coupon's fastener spring, as a multiple of kc
  // boltnet-identify only (a scene uses its patches' sections and its -coupling_* options):
  double    nu       = 0.33; // Poisson ratio of the two (isotropic) sheets
  PetscInt  coupling = 1;    // CouplingType: exact
  double    radius   = 4.0;  // footprint radius (mm)
};
// Reads -<prefix>shell_correction, _shell_h, _shell_width, _shell_spring and, when standalone
// (boltnet-identify), _shell_nu, _shell_coupling, _shell_radius.
PetscErrorCode ShellCorrectionFromOptions(MPI_Comm comm, const char prefix[], const char title[], PetscBool standalone, ShellCorrectionOptions *o);

// Reads the geometry options -<prefix>d, -<prefix>hole, ... (listed by -help with units).
PetscErrorCode FastenerFromOptions(MPI_Comm comm, const char prefix[], const char title[], FastenerOptions *o);
// Checks the geometry and returns the frictional macroelement; errors name the options -<prefix>*.
PetscErrorCode FastenerMacroelement(MPI_Comm comm, const char prefix[], const FastenerOptions &o, Params *p);

} // namespace identify
} // namespace boltnet
