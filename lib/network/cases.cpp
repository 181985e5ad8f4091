// Load cases on one set-up (docs/scenes.md, "Load cases"): the mesh, the partition, the DMNetwork
// and the condensed patches (their factorisations and Schur complements) are built once; each case
// then starts from the unloaded state and only the loads change: the right-hand sides and the
// prescribed values, never which dof are held.
#include "core/guard.hpp"
#include "network/internal.hpp"

#include <cmath>
#include <map>

namespace boltnet {

namespace {

// The record of a load path back to its start at load factor 0: the steps, cut-backs and solves
// counted again, no secant predictor and no stuck-joint prediction (both come from the last path's
// increments). The state (solution, joint histories, factorisation) is the caller's to keep or reset.
void RestartPath(BoltnetAssembly a)
{
  a->lambda = a->lambda_target = a->lambda_prev = 0;
  a->path                      = PathPosition{};
  a->resume                    = PETSC_FALSE;
  a->steps.clear();
  a->total_cutbacks = 0;
  a->failure.clear();
  a->checks.singular.clear();
  a->has_prev              = PETSC_FALSE;
  a->isolve.factorisations = a->isolve.krylov_its = a->isolve.linear_solves = a->isolve.kept = 0;
  JointSet &js             = a->joints;
  js.state_trace.clear();
  js.frozen.clear();
  js.util_now.clear();
  js.util_before.clear();
  js.last_increment = 0;
  js.util_ready     = PETSC_FALSE;
  js.jac_assembled = js.jac_reused = js.frozen_joint_steps = js.joint_steps = js.released = 0;
}

} // namespace

PetscErrorCode AssemblyReset(BoltnetAssembly a)
{
  PetscFunctionBeginUser;
  PetscCheck(a->net.dm && a->snes, a->comm, PETSC_ERR_ORDER, "AssemblyReset() comes after BoltnetAssemblySetUp()");
  PetscCall(VecSet(a->X, 0.0));
  a->held = HeldLoads{}; // nothing held
  for (OwnedPatch &op : a->patches.owned) {
    op.cond.c_held.clear();
    op.cond.w0_held.clear();
    op.cond.prescribed_held.clear();
  }
  RestartPath(a);
  a->checks.force_scale_seen = 0;
  a->isolve.keep_it          = -1;
  a->isolve.factors_valid    = PETSC_FALSE;
  JointSet &js               = a->joints;
  js.committed.assign(js.size(), History{}); // every joint back to its initial history
  js.accepted.clear();
  js.accepted_jump.clear();
  js.jac_valid = PETSC_FALSE; // its joint tangents are the last case's
  // A fresh factorisation for the first Jacobian, as in a run of its own (a case that failed may
  // leave MUMPS in an error state).
  PetscCall(AssemblyResetPC(a));
  PetscCall(AssemblySetUpNullPivots(a));
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyHoldLoads(BoltnetAssembly a)
{
  PetscFunctionBeginUser;
  PetscCheck(a->net.dm && a->snes, a->comm, PETSC_ERR_ORDER, "AssemblyHoldLoads() comes after BoltnetAssemblySetUp()");
  const PetscReal l  = a->lambda;
  const Boundary &bc = a->bc;
  HeldLoads      &h  = a->held;
  // The loads at load factor l, added to those held before: the network's rows...
  if (h.dirichlet.empty()) h.dirichlet.assign(bc.dirichlet_rows.size(), 0.0);
  for (size_t i = 0; i < bc.dirichlet_rows.size(); ++i) h.dirichlet[i] += l * bc.dirichlet_values[i];
  std::map<PetscInt, PetscReal> force;
  for (size_t i = 0; i < h.force_rows.size(); ++i) force[h.force_rows[i]] += h.force_values[i];
  for (size_t i = 0; i < bc.force_rows.size(); ++i) force[bc.force_rows[i]] += l * bc.force_values[i];
  h.force_rows.clear();
  h.force_values.clear();
  for (const auto &[r, v] : force) {
    h.force_rows.push_back(r);
    h.force_values.push_back(v);
  }
  h.norm += std::abs(l) * bc.fext_norm;
  // ... and the condensed patches' load terms (their loads inside the patch).
  for (OwnedPatch &op : a->patches.owned) {
    if (!op.shell || !a->layout.shells.at(op.index).condensed) continue;
    CondensedPatch &cp = op.cond;
    cp.c_held.resize(cp.c.size(), 0.0);
    cp.w0_held.resize(cp.w0.size(), 0.0);
    for (size_t r = 0; r < cp.c.size(); ++r) cp.c_held[r] += l * cp.c[r];
    for (size_t i = 0; i < cp.w0.size(); ++i) cp.w0_held[i] += l * cp.w0[i];
    for (const auto &[d, v] : cp.prescribed) cp.prescribed_held[d] += l * v;
  }
  // The path starts again from load factor 0 at the state reached: the solution and every joint's
  // history stay, and so does the factorisation (the tangent has not changed).
  RestartPath(a);
  PetscFunctionReturn(0);
}

PetscReal AssemblyAppliedForce(BoltnetAssembly a, PetscReal lambda)
{
  return std::abs(lambda) * a->bc.fext_norm + a->held.norm;
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
