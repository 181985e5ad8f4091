// The residual of the network: joint forces, the linear part (patches and seams, through the
// Jacobian's linear part Jbase), condensed patches' load terms, applied loads, and the prescribed dof.
#include "core/guard.hpp"
#include "core/log.hpp"
#include "network/internal.hpp"

namespace boltnet {

PetscErrorCode GetLocalX(BoltnetAssembly a, Vec X, Vec *Xl, const PetscScalar **x)
{
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(a->net.dm, Xl));
  PetscCall(DMGlobalToLocalBegin(a->net.dm, X, INSERT_VALUES, *Xl));
  PetscCall(DMGlobalToLocalEnd(a->net.dm, X, INSERT_VALUES, *Xl));
  PetscCall(VecGetArrayRead(*Xl, x));
  PetscFunctionReturn(0);
}

PetscErrorCode RestoreLocalX(BoltnetAssembly a, Vec *Xl, const PetscScalar **x)
{
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArrayRead(*Xl, x));
  PetscCall(DMRestoreLocalVector(a->net.dm, Xl));
  PetscFunctionReturn(0);
}

static PetscErrorCode AssemblyFormFunctionImpl(SNES snes, Vec X, Vec F, void *ctx)
{
  BoltnetAssembly       a = static_cast<BoltnetAssembly>(ctx);
  Vec                   Xl, Fl;
  const PetscScalar    *x, *xl;
  PetscScalar          *f;
  std::vector<Response> resp;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Events().residual, 0, 0, 0, 0));
  // One ghost update of X, for the joints and the patches alike.
  PetscCall(GetLocalX(a, X, &Xl, &xl));
  EvaluateJoints(a->joints, xl, a->opt.tangent, false, resp, nullptr);
  PetscCall(DMGetLocalVector(a->net.dm, &Fl));
  PetscCall(VecSet(Fl, 0.0));
  PetscCall(VecGetArray(Fl, &f));
  const JointSet &js = a->joints;
  for (size_t k = 0; k < js.size(); ++k) {
    const Vec6 g = GlobalForce(js.comp[k].R, resp[k].force);
    const Vec6 gb = NodeLoad(js.comp[k].db, g), ga = NodeLoad(js.comp[k].da, g);
    for (int i = 0; i < 6; ++i) {
      f[js.ob[k] + i] += gb[i];
      f[js.oa[k] + i] -= ga[i];
    }
  }
  for (const OwnedPatch &op : a->patches.owned) { // the condensed patches' load terms, lambda c (+ c_held)
    if (!op.shell || !a->layout.shells.at(op.index).condensed) continue;
    for (PetscInt r = 0; r < op.cond.nb; ++r) f[op.loff + r] += a->lambda_target * op.cond.c[r];
    for (size_t r = 0; r < op.cond.c_held.size(); ++r) f[op.loff + r] += op.cond.c_held[r];
  }
  PetscCall(RestoreLocalX(a, &Xl, &xl));
  PetscCall(VecRestoreArray(Fl, &f));
  PetscCall(VecSet(F, 0.0));
  PetscCall(DMLocalToGlobalBegin(a->net.dm, Fl, ADD_VALUES, F));
  PetscCall(DMLocalToGlobalEnd(a->net.dm, Fl, ADD_VALUES, F));
  PetscCall(DMRestoreLocalVector(a->net.dm, &Fl));
  // The linear part, patches (K u, or S u_B where condensed) and seams: Jbase, which holds exactly
  // those blocks (jacobian.cpp), so that no second copy of them is kept for the residual.
  PetscCall(MatMultAdd(a->Jbase, X, F, F));

  // Applied forces, then the constrained rows: r = u - lambda * value (- the held value).
  PetscInt rstart;
  PetscCall(VecGetOwnershipRange(F, &rstart, nullptr));
  PetscCall(VecGetArray(F, &f));
  PetscCall(VecGetArrayRead(X, &x));
  const Boundary  &bc = a->bc;
  const HeldLoads &h  = a->held;
  for (size_t i = 0; i < bc.force_rows.size(); ++i) f[bc.force_rows[i] - rstart] -= a->lambda_target * bc.force_values[i];
  for (size_t i = 0; i < h.force_rows.size(); ++i) f[h.force_rows[i] - rstart] -= h.force_values[i];
  for (size_t i = 0; i < bc.dirichlet_rows.size(); ++i) {
    const PetscInt r = bc.dirichlet_rows[i] - rstart;
    f[r]             = x[r] - a->lambda_target * bc.dirichlet_values[i] - (h.dirichlet.empty() ? 0.0 : h.dirichlet[i]);
  }
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscCall(VecRestoreArray(F, &f));
  PetscCall(PetscLogEventEnd(Events().residual, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyFormFunction(SNES snes, Vec X, Vec F, void *ctx)
{
  return Guard("AssemblyFormFunction (SNES function)", [&] { return AssemblyFormFunctionImpl(snes, X, F, ctx); });
}

} // namespace boltnet
