// Load paths: the sequence of load factors a quasi-static analysis passes through.
#pragma once
#include <petscsys.h>
#include <vector>

namespace boltnet {

struct LoadPath {
  std::vector<PetscReal> breakpoints;       // factors to pass through, starting from 0
  PetscInt               steps_per_segment = 10;
};

// Reads -load_path ramp|table, -load_max, -load_table, -load_steps (with the given prefix).
PetscErrorCode LoadPathFromOptions(MPI_Comm comm, const char prefix[], LoadPath *path);

// The load factor of every step: segments split into steps_per_segment equal increments.
std::vector<PetscReal> LoadPathTargets(PetscReal start, const std::vector<PetscReal> &breakpoints, PetscInt steps_per_segment);

} // namespace boltnet
