// Load cases on one set-up (docs/scenes.md, "Load cases"): the mesh, the partition, the DMNetwork
// and the condensed patches (their factorisations and Schur complements) are built once; each case
// then starts from the unloaded state and only the loads change: the right-hand sides and the
// prescribed values, never which dof are held.
#include "core/guard.hpp"
#include "network/internal.hpp"

namespace boltnet {

PetscErrorCode AssemblyReset(BoltnetAssembly a)
{
  PetscFunctionBeginUser;
  PetscCheck(a->net.dm && a->snes, a->comm, PETSC_ERR_ORDER, "AssemblyReset() comes after BoltnetAssemblySetUp()");
  PetscCall(VecSet(a->X, 0.0));
  a->lambda = a->lambda_target = 0;
  a->path                      = PathPosition{};
  a->resume                    = PETSC_FALSE;
  a->steps.clear();
  a->total_cutbacks   = 0;
  a->failure.clear();
  a->checks.singular.clear();
  a->checks.force_scale_seen = 0;
  a->has_prev         = PETSC_FALSE; // no secant predictor from the last case's path
  a->isolve.factorisations = a->isolve.krylov_its = a->isolve.linear_solves = a->isolve.kept = 0;
  a->isolve.keep_it = -1;
  a->isolve.factors_valid = PETSC_FALSE;
  JointSet &js  = a->joints;
  js.committed.assign(js.size(), History{}); // every joint back to its initial history
  js.accepted.clear();
  js.accepted_jump.clear();
  js.state_trace.clear();
  js.frozen.clear();
  js.util_now.clear();
  js.util_before.clear();
  js.last_increment = 0;
  js.util_ready     = PETSC_FALSE;
  js.jac_valid      = PETSC_FALSE; // its joint tangents are the last case's
  js.jac_assembled = js.jac_reused = js.frozen_joint_steps = js.joint_steps = js.released = 0;
  // A fresh factorisation for the first Jacobian, as in a run of its own (a case that failed may
  // leave MUMPS in an error state).
  PetscCall(AssemblyResetPC(a));
  PetscCall(AssemblySetUpNullPivots(a));
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblySetLoads(BoltnetAssembly a, const std::vector<BCDesc> &bcs)
{
  PetscFunctionBeginUser;
  PetscCheck(a->net.dm, a->comm, PETSC_ERR_ORDER, "AssemblySetLoads() comes after BoltnetAssemblySetUp()");
  for (const BCDesc &b : bcs) PetscCheck(a->model.Find(b.patch) >= 0, a->comm, PETSC_ERR_ARG_WRONG, "A load names patch %" PetscInt_FMT ", which the model does not have", b.patch);
  const std::vector<PetscInt> held = a->bc.dirichlet_rows;
  a->model.bcs                     = bcs;
  // The condensed patches: new load terms from their kept factorisations.
  PetscCall(Collective(a->comm, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    for (OwnedPatch &op : a->patches.owned) {
      if (!op.shell) continue;
      const ShellPatch &sp = a->layout.shells.at(op.index);
      if (!sp.condensed) continue;
      PatchLoads        loads;
      PetscCall(PatchLoadsFromModel(PETSC_COMM_SELF, a->model, sp.id, &sp, a->opt.coupling_type, &loads));
      PetscCall(CondensedPatchLoads(sp.id, loads, &op.cond));
    }
    PetscFunctionReturn(0);
  }));
  // The network's rows: the same held rows, new values and forces.
  PetscCall(AssemblySetUpBoundary(a));
  PetscInt differ = a->bc.dirichlet_rows != held, any;
  PetscCall(MPIU_Allreduce(&differ, &any, 1, MPIU_INT, MPI_MAX, a->comm));
  PetscCheck(!any, a->comm, PETSC_ERR_ARG_INCOMP, "These loads fix or prescribe other dof of the network than those it was set up with: a load case may change prescribed values and forces, not which dof are held (docs/scenes.md, \"Load cases\")");
  PetscFunctionReturn(0);
}

} // namespace boltnet
