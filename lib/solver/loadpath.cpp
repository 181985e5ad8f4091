#include "solver/loadpath.hpp"

#include <cmath>

namespace boltnet {

PetscErrorCode LoadPathFromOptions(MPI_Comm comm, const char prefix[], LoadPath *path)
{
  const char *kinds[] = {"ramp", "table"};
  PetscInt    kind    = 0;
  PetscReal   lmax    = 1.0;
  PetscReal   table[256];
  PetscInt    ntable = 256;
  PetscBool   hastable = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, prefix, "boltnet load path options", "boltnet");
  PetscCall(PetscOptionsEList("-load_path", "Load path: a ramp from 0 to -load_max, or a piecewise-linear -load_table", "LoadPathFromOptions", kinds, 2, kinds[kind], &kind, nullptr));
  PetscCall(PetscOptionsReal("-load_max", "Final load factor of the ramp (the scene's boundary values are per unit factor)", "LoadPathFromOptions", lmax, &lmax, nullptr));
  PetscCall(PetscOptionsRealArray("-load_table", "Load factors to pass through in turn, from 0 (comma separated, e.g. 1,-1,0)", "LoadPathFromOptions", table, &ntable, &hastable));
  PetscCall(PetscOptionsInt("-load_steps", "Equal load steps per segment of the path", "LoadPathFromOptions", path->steps_per_segment, &path->steps_per_segment, nullptr));
  PetscOptionsEnd();
  PetscCheck(path->steps_per_segment >= 1, comm, PETSC_ERR_USER_INPUT, "-load_steps %" PetscInt_FMT " must be >= 1", path->steps_per_segment);
  path->breakpoints.clear();
  if (kind == 0) {
    PetscCheck(std::isfinite(lmax), comm, PETSC_ERR_USER_INPUT, "-load_max must be finite");
    path->breakpoints.push_back(lmax);
  } else {
    PetscCheck(hastable && ntable > 0, comm, PETSC_ERR_USER_INPUT, "-load_path table needs -load_table with at least one load factor");
    for (PetscInt i = 0; i < ntable; ++i) {
      PetscCheck(std::isfinite(table[i]), comm, PETSC_ERR_USER_INPUT, "-load_table entry %" PetscInt_FMT " is not finite", i);
      path->breakpoints.push_back(table[i]);
    }
  }
  PetscFunctionReturn(0);
}

std::vector<PetscReal> LoadPathTargets(PetscReal start, const std::vector<PetscReal> &breakpoints, PetscInt steps_per_segment)
{
  std::vector<PetscReal> t;
  PetscReal              from = start;
  for (PetscReal to : breakpoints) {
    if (to == from) continue;
    for (PetscInt k = 1; k <= steps_per_segment; ++k) t.push_back(k == steps_per_segment ? to : from + (to - from) * (PetscReal)k / (PetscReal)steps_per_segment);
    from = to;
  }
  return t;
}

} // namespace boltnet
