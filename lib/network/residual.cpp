// The residual of the network: joint forces, seam and patch internal forces, applied loads, and the
// prescribed dof.
#include "core/guard.hpp"
#include "core/log.hpp"
#include "network/internal.hpp"

namespace boltnet {

void SeamElementDofs(const Seam::Element &el, PetscInt oa, PetscInt ob, PetscInt dofs[24])
{
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 6; ++i) dofs[6 * k + i] = el.side[k] < 0 ? -1 : (el.side[k] ? ob : oa) + 6 * el.node[k] + i;
}

PetscErrorCode SeamOffsets(BoltnetAssembly a, PetscInt e, PetscBool global, PetscInt *oa, PetscInt *ob)
{
  const PetscInt *cone;
  PetscFunctionBeginUser;
  PetscCall(DMNetworkGetConnectedVertices(a->net.dm, e, &cone));
  if (global) {
    PetscCall(DMNetworkGetGlobalVecOffset(a->net.dm, cone[0], ALL_COMPONENTS, oa));
    PetscCall(DMNetworkGetGlobalVecOffset(a->net.dm, cone[1], ALL_COMPONENTS, ob));
  } else {
    PetscCall(DMNetworkGetLocalVecOffset(a->net.dm, cone[0], ALL_COMPONENTS, oa));
    PetscCall(DMNetworkGetLocalVecOffset(a->net.dm, cone[1], ALL_COMPONENTS, ob));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode SeamOf(BoltnetAssembly a, PetscInt e, const Seam **seam)
{
  SeamComp sc;
  PetscFunctionBeginUser;
  PetscCall(NetworkComponent(a->net.dm, e, nullptr, &sc, sizeof sc));
  *seam = &a->layout.seams.at(sc.index);
  PetscFunctionReturn(0);
}

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
  for (const auto &[e, Ks] : a->patches.seam_ops) { // the owned seams: the blocks between their two sides
    const Seam *seam;
    PetscInt    oa, ob, dofs[24];
    PetscCall(SeamOf(a, e, &seam));
    PetscCall(SeamOffsets(a, e, PETSC_FALSE, &oa, &ob));
    for (size_t k = 0; k < Ks.size(); ++k) {
      const Seam::Element &el = seam->elems[k];
      SeamElementDofs(el, oa, ob, dofs);
      for (int r = 0; r < 24; ++r) {
        const int sr = el.side[r / 6];
        if (sr < 0) continue;
        PetscScalar sum = 0;
        for (int c = 0; c < 24; ++c)
          if (el.side[c / 6] == 1 - sr) sum += Ks[k][24 * r + c] * xl[dofs[c]];
        f[dofs[r]] += sum;
      }
    }
  }
  for (const OwnedPatch &op : a->patches.owned) { // the owned shell patches' internal forces
    if (!op.shell) continue;
    if (a->layout.shells.at(op.index).condensed) { // S u_B + lambda c
      const PetscInt nb = op.cond.nb;
      for (PetscInt r = 0; r < nb; ++r) {
        const double *Sr  = op.cond.S.data() + (size_t)r * nb;
        PetscScalar   sum = a->lambda_target * op.cond.c[r];
        for (PetscInt c = 0; c < nb; ++c) sum += Sr[c] * xl[op.loff + c];
        f[op.loff + r] += sum;
      }
      continue;
    }
    for (PetscInt r = 0; r < op.op.n; ++r) { // K u
      PetscScalar sum = 0;
      for (PetscInt k = op.op.rowptr[r]; k < op.op.rowptr[r + 1]; ++k) sum += op.op.vals[k] * xl[op.loff + op.op.cols[k]];
      f[op.loff + r] += sum;
    }
  }
  PetscCall(RestoreLocalX(a, &Xl, &xl));
  PetscCall(VecRestoreArray(Fl, &f));
  PetscCall(VecSet(F, 0.0));
  PetscCall(DMLocalToGlobalBegin(a->net.dm, Fl, ADD_VALUES, F));
  PetscCall(DMLocalToGlobalEnd(a->net.dm, Fl, ADD_VALUES, F));
  PetscCall(DMRestoreLocalVector(a->net.dm, &Fl));

  // Applied forces, then the constrained rows: r = u - lambda * value.
  PetscInt rstart;
  PetscCall(VecGetOwnershipRange(F, &rstart, nullptr));
  PetscCall(VecGetArray(F, &f));
  PetscCall(VecGetArrayRead(X, &x));
  const Boundary &bc = a->bc;
  for (size_t i = 0; i < bc.force_rows.size(); ++i) f[bc.force_rows[i] - rstart] -= a->lambda_target * bc.force_values[i];
  for (size_t i = 0; i < bc.dirichlet_rows.size(); ++i) {
    const PetscInt r = bc.dirichlet_rows[i] - rstart;
    f[r]             = x[r] - a->lambda_target * bc.dirichlet_values[i];
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
