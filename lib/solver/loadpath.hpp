// Load paths: the sequence of load factors a quasi-static analysis passes through.
#pragma once
#include <petscsys.h>
#include <string>
#include <vector>

namespace boltnet {

struct LoadPath {
  std::vector<PetscReal> breakpoints;       // factors to pass through, starting from 0
  PetscInt               steps_per_segment = 10;
  PetscInt               kind = 0;          // -load_path: 0 a ramp to lmax, 1 the table
  PetscReal              lmax = 1.0;        // -load_max
  std::vector<PetscReal> table;             // -load_table (also when the path is a ramp)
};

// Reads -load_path ramp|table, -load_max, -load_table, -load_steps (with the given prefix).
PetscErrorCode LoadPathFromOptions(MPI_Comm comm, const char prefix[], LoadPath *path);

// The load path of load case `name` (docs/scenes.md, "Load cases"): -load_case_<name>_path,
// _max, _table, _steps, each defaulting to the scene's (base); a table given alone makes the path a
// table. Inside the caller's PetscOptionsBegin/End (the section "Load case '<name>'" of -help: PETSc
// prints a section's title once, so a case's options are read in one section).
PetscErrorCode LoadPathOfCase(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, const std::string &name, const LoadPath &base, LoadPath *path);

// The load factor of every step: segments split into steps_per_segment equal increments.
std::vector<PetscReal> LoadPathTargets(PetscReal start, const std::vector<PetscReal> &breakpoints, PetscInt steps_per_segment);

} // namespace boltnet
