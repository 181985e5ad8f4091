#include "solver/loadpath.hpp"

#include <cmath>

namespace boltnet {

namespace {

// -<pre>path, -<pre>max, -<pre>table, -<pre>steps (pre: "load_" for the scene's path,
// "load_case_<name>_" for a case's), over the values already in *path.
PetscErrorCode ReadLoadPath(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, const std::string &pre, bool is_case, LoadPath *path)
{
  const char *kinds[] = {"ramp", "table"};
  PetscReal   table[256];
  PetscInt    ntable = 256;
  PetscBool   hastable = PETSC_FALSE, haskind = PETSC_FALSE;
  const std::string o_path = "-" + pre + "path", o_max = "-" + pre + "max", o_table = "-" + pre + "table", o_steps = "-" + pre + "steps";
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsEList(o_path.c_str(), is_case ? "This case's load path (default: the scene's -load_path)" : "Load path: a ramp from 0 to -load_max, or a piecewise-linear -load_table", "LoadPathFromOptions", kinds, 2, kinds[path->kind], &path->kind, &haskind));
  PetscCall(PetscOptionsReal(o_max.c_str(), is_case ? "This case's final load factor of the ramp (default: the scene's -load_max)" : "Final load factor of the ramp (the scene's boundary values are per unit factor)", "LoadPathFromOptions", path->lmax, &path->lmax, nullptr));
  PetscCall(PetscOptionsRealArray(o_table.c_str(), is_case ? "This case's load factors to pass through in turn, from 0 (default: the scene's -load_table); given alone, the case's path is this table" : "Load factors to pass through in turn, from 0 (comma separated, e.g. 1,-1,0)", "LoadPathFromOptions", table, &ntable, &hastable));
  PetscCall(PetscOptionsInt(o_steps.c_str(), is_case ? "This case's load steps per segment (default: the scene's -load_steps)" : "Equal load steps per segment of the path", "LoadPathFromOptions", path->steps_per_segment, &path->steps_per_segment, nullptr));
  PetscCheck(path->steps_per_segment >= 1, comm, PETSC_ERR_USER_INPUT, "%s %" PetscInt_FMT " must be >= 1", o_steps.c_str(), path->steps_per_segment);
  if (hastable) {
    PetscCheck(ntable > 0, comm, PETSC_ERR_USER_INPUT, "%s needs at least one load factor", o_table.c_str());
    path->table.assign(table, table + ntable);
    for (PetscInt i = 0; i < ntable; ++i) PetscCheck(std::isfinite(table[i]), comm, PETSC_ERR_USER_INPUT, "%s entry %" PetscInt_FMT " is not finite", o_table.c_str(), i);
    if (is_case && !haskind) path->kind = 1;
  }
  if (path->kind == 0) {
    PetscCheck(std::isfinite(path->lmax), comm, PETSC_ERR_USER_INPUT, "%s must be finite", o_max.c_str());
    path->breakpoints.assign(1, path->lmax);
  } else {
    PetscCheck(!path->table.empty(), comm, PETSC_ERR_USER_INPUT, "%s table needs %s with at least one load factor", o_path.c_str(), o_table.c_str());
    path->breakpoints = path->table;
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode LoadPathFromOptions(MPI_Comm comm, const char prefix[], LoadPath *path)
{
  PetscFunctionBeginUser;
  *path = LoadPath{};
  PetscOptionsBegin(comm, prefix, "boltnet load path options", "boltnet");
  PetscCall(ReadLoadPath(PetscOptionsObject, comm, "load_", false, path));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

PetscErrorCode LoadPathOfCase(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, const std::string &name, const LoadPath &base, LoadPath *path)
{
  PetscFunctionBeginUser;
  *path = base;
  PetscCall(ReadLoadPath(PetscOptionsObject, comm, "load_case_" + name + "_", true, path));
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
