// Boundary conditions on the network's rows, and the whole displacement of a patch.
#include "core/guard.hpp"
#include "core/log.hpp"
#include "network/internal.hpp"

#include <cmath>

namespace boltnet {

PetscErrorCode AssemblySetUpBoundary(BoltnetAssembly a)
{
  Boundary &bc = a->bc;
  PetscFunctionBeginUser;
  bc = Boundary{};
  std::map<PetscInt, PetscReal> dir, frc; // global row -> value
  PetscReal                     f2 = 0;
  PetscCall(Collective(a->comm, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    for (const OwnedPatch &op : a->patches.owned) {
      const ShellPatch *sp = op.shell ? &a->layout.shells.at(op.index) : nullptr;
      PatchLoads        loads;
      PetscCall(PatchLoadsFromModel(PETSC_COMM_SELF, a->model, a->layout.patches[op.index].id, sp, a->opt.coupling_type, &loads));
      for (const auto &kv : loads.force) f2 += kv.second * kv.second;
      // The row of a patch dof, or -1 when a condensed patch keeps it inside (an interior dof).
      auto row = [&](PetscInt dof) -> PetscInt {
        if (!sp || !sp->condensed) return op.goff + dof;
        auto it = sp->carried_index.find((int)(dof / 6));
        return it == sp->carried_index.end() ? -1 : op.goff + 6 * it->second + dof % 6;
      };
      for (const auto &[dof, v] : loads.prescribed)
        if (row(dof) >= 0) dir[row(dof)] = v;
      for (const auto &[dof, v] : loads.force)
        if (row(dof) >= 0) frc[row(dof)] += v;
    }
    PetscFunctionReturn(0);
  }));
  PetscCallMPI(MPI_Allreduce(&f2, &bc.fext_norm, 1, MPIU_REAL, MPIU_SUM, a->comm));
  bc.fext_norm = std::sqrt(bc.fext_norm);
  for (auto &kv : dir) {
    bc.dirichlet_rows.push_back(kv.first);
    bc.dirichlet_values.push_back(kv.second);
  }
  for (auto &kv : frc) {
    bc.force_rows.push_back(kv.first);
    bc.force_values.push_back(kv.second);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyApplyDirichlet(BoltnetAssembly a, Vec X, PetscReal lambda)
{
  PetscScalar *x;
  PetscInt     rstart;
  PetscFunctionBeginUser;
  PetscCall(VecGetOwnershipRange(X, &rstart, nullptr));
  PetscCall(VecGetArray(X, &x));
  const std::vector<PetscReal> &held = a->held.dirichlet;
  for (size_t i = 0; i < a->bc.dirichlet_rows.size(); ++i) x[a->bc.dirichlet_rows[i] - rstart] = lambda * a->bc.dirichlet_values[i] + (held.empty() ? 0.0 : held[i]);
  PetscCall(VecRestoreArray(X, &x));
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyPatchDisplacement(BoltnetAssembly a, const OwnedPatch &op, const PetscScalar *xlocal, PetscReal lambda, std::vector<double> &u)
{
  PetscFunctionBeginUser;
  if (!op.shell) {
    u.assign(xlocal + op.loff, xlocal + op.loff + 6);
    PetscFunctionReturn(0);
  }
  const ShellPatch &sp = a->layout.shells.at(op.index);
  if (!sp.condensed) {
    u.assign(xlocal + op.loff, xlocal + op.loff + 6 * sp.nnodes());
    PetscFunctionReturn(0);
  }
  PetscCall(PetscLogEventBegin(Events().recover, 0, 0, 0, 0));
  PetscCall(RecoverPatch(sp, op.cond, lambda, xlocal + op.loff, u));
  PetscCall(PetscLogEventEnd(Events().recover, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

} // namespace boltnet
