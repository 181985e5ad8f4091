// The joints of the network: evaluation at a solution, commit after a converged step, the choice of
// joints solved as linear springs, and their records for output.
#include "core/guard.hpp"
#include "core/log.hpp"
#include "network/gather.hpp"
#include "network/internal.hpp"

#include <algorithm>
#include <cmath>

namespace boltnet {

PetscErrorCode AssemblyEvaluateJoints(BoltnetAssembly a, Vec X, std::vector<Response> &out, std::vector<Vec6> *jumps, bool full_law)
{
  Vec                Xl;
  const PetscScalar *x;
  PetscFunctionBeginUser;
  PetscCall(GetLocalX(a, X, &Xl, &x));
  PetscCall(PetscLogEventBegin(Events().joints, 0, 0, 0, 0));
  EvaluateJoints(a->joints, x, a->opt.tangent, full_law, out, jumps);
  PetscCall(PetscLogEventEnd(Events().joints, 0, 0, 0, 0));
  PetscCall(RestoreLocalX(a, &Xl, &x));
  PetscFunctionReturn(0);
}

static PetscErrorCode AssemblyCountStateChangesImpl(SNES snes, Vec ref, Vec X, PetscInt *nchanged, void *ctx)
{
  BoltnetAssembly       a = static_cast<BoltnetAssembly>(ctx);
  std::vector<Response> r0, r1;
  PetscFunctionBeginUser;
  PetscCall(AssemblyEvaluateJoints(a, ref, r0));
  PetscCall(AssemblyEvaluateJoints(a, X, r1));
  PetscInt n = 0;
  for (size_t i = 0; i < r0.size(); ++i) n += (r0[i].state != r1[i].state) ? 1 : 0;
  PetscCall(MPIU_Allreduce(&n, nchanged, 1, MPIU_INT, MPI_SUM, a->comm));
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyCountStateChanges(SNES snes, Vec ref, Vec X, PetscInt *nchanged, void *ctx)
{
  return Guard("AssemblyCountStateChanges (line search state function)", [&] { return AssemblyCountStateChangesImpl(snes, ref, X, nchanged, ctx); });
}

PetscErrorCode AssemblyStateCounts(BoltnetAssembly a, Vec X, PetscInt counts[5])
{
  std::vector<Response> r;
  PetscInt              loc[5] = {0, 0, 0, 0, 0};
  PetscFunctionBeginUser;
  PetscCall(AssemblyEvaluateJoints(a, X, r));
  for (const Response &x : r) loc[static_cast<int>(x.state)]++;
  PetscCall(MPIU_Allreduce(loc, counts, 5, MPIU_INT, MPI_SUM, a->comm));
  PetscFunctionReturn(0);
}

// The utilization (law.hpp) of every local joint at the given jumps, with its committed history.
static void UtilizationAt(const JointSet &js, const std::vector<Vec6> &jumps, std::vector<PetscReal> &util)
{
  util.resize(js.size());
  for (size_t i = 0; i < js.size(); ++i) util[i] = utilization(js.comp[i].params, js.committed[i], jumps[i]);
}

PetscErrorCode AssemblyCommit(BoltnetAssembly a, Vec X)
{
  JointSet &js = a->joints;
  PetscFunctionBeginUser;
  PetscCall(AssemblyEvaluateJoints(a, X, js.accepted, &js.accepted_jump, true));
  for (size_t i = 0; i < js.accepted.size(); ++i) js.committed[i] = js.accepted[i].trial;
  // Utilization with the new history, for the next step's choice of frozen joints.
  js.util_before = js.util_now;
  UtilizationAt(js, js.accepted_jump, js.util_now);
  if (!js.util_ready) js.util_before = js.util_now;
  js.util_ready = PETSC_TRUE;
  js.frozen.clear();
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyFreezeStuck(BoltnetAssembly a, PetscReal increment)
{
  JointSet &js = a->joints;
  PetscFunctionBeginUser;
  js.frozen.clear();
  if (!a->opt.stuck_linear) PetscFunctionReturn(0);
  if (!js.util_ready) { // before the first step: at the initial state (collective: every rank)
    std::vector<Response> r;
    std::vector<Vec6>     du;
    PetscCall(AssemblyEvaluateJoints(a, a->X, r, &du, true));
    UtilizationAt(js, du, js.util_now);
    js.util_before = js.util_now;
    js.util_ready  = PETSC_TRUE;
  }
  // Predicted utilization at the end of the step: the last step's change, scaled to this increment.
  // Before the first converged step nothing is known of how the joints load: none is frozen (an
  // elastic predictor there releases most of them again, at the cost of Newton iterations).
  if (js.last_increment == 0) PetscFunctionReturn(0);
  const PetscReal ratio  = std::abs(increment / js.last_increment);
  PetscInt        loc[2] = {0, (PetscInt)js.size()}, glob[2];
  js.frozen.assign(js.size(), 0);
  for (size_t i = 0; i < js.size(); ++i) {
    const PetscReal pred = js.util_now[i] + std::abs(js.util_now[i] - js.util_before[i]) * ratio;
    js.frozen[i]         = pred < a->opt.stuck_margin;
    loc[0] += js.frozen[i];
  }
  PetscCall(MPIU_Allreduce(loc, glob, 2, MPIU_INT, MPI_SUM, a->comm));
  js.frozen_joint_steps += glob[0];
  js.joint_steps += glob[1];
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyReleaseUnstuck(BoltnetAssembly a, Vec X, PetscInt *nreleased)
{
  JointSet             &js = a->joints;
  std::vector<Response> full;
  std::vector<Vec6>     du;
  PetscInt              n = 0;
  PetscFunctionBeginUser;
  PetscCall(AssemblyEvaluateJoints(a, X, full, &du, true)); // one ghost update; the frozen states below are local
  for (size_t i = 0; i < js.frozen.size(); ++i) {
    if (!js.frozen[i]) continue;
    if (full[i].state != evaluate(js.comp[i].params, js.committed[i], du[i], a->opt.tangent, true).state) {
      js.frozen[i] = 0;
      ++n;
    }
  }
  PetscCall(MPIU_Allreduce(&n, nreleased, 1, MPIU_INT, MPI_SUM, a->comm));
  js.released += *nreleased;
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyJointRecords(BoltnetAssembly a, std::vector<JointRecord> &mine)
{
  JointSet &js = a->joints;
  PetscFunctionBeginUser;
  // Before the first step no joint has an accepted state yet: evaluate them at X. GetLocalX() is
  // collective, so every rank takes part when any rank needs it (a rank may own no joint at all).
  PetscBool need = js.accepted.size() != js.size() ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &need, 1, MPIU_BOOL, MPI_LOR, a->comm));
  if (need) {
    std::vector<Response> fresh;
    std::vector<Vec6>     jumps;
    PetscCall(AssemblyEvaluateJoints(a, a->X, fresh, &jumps, true));
    if (js.accepted.size() != js.size()) {
      js.accepted      = std::move(fresh);
      js.accepted_jump = std::move(jumps);
    }
  }
  mine.clear();
  mine.reserve(js.size());
  for (size_t k = 0; k < js.size(); ++k) {
    const Response &re = js.accepted[k];
    const Vec6     &du = js.accepted_jump[k];
    JointRecord     rec{};
    rec.joint   = js.comp[k].id;
    rec.state   = static_cast<PetscInt>(re.state);
    rec.bearing = re.bearing ? 1 : 0;
    for (int i = 0; i < 6; ++i) {
      rec.jump[i]  = du[i];
      rec.force[i] = re.force[i];
    }
    rec.slip[0] = re.trial.slip[0];
    rec.slip[1] = re.trial.slip[1];
    mine.push_back(rec);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode GatherJointRecords(BoltnetAssembly a, const std::vector<JointRecord> &mine, std::vector<JointRecord> &records)
{
  PetscFunctionBeginUser;
  // -log_view counts this event: a run that writes joints.h5 only never enters it (test/output_tests.cmake).
  PetscCall(PetscLogEventBegin(Events().joint_gather, 0, 0, 0, 0));
  PetscCall(GatherToZero(a->comm, mine, records));
  std::sort(records.begin(), records.end(), [](const JointRecord &l, const JointRecord &r) { return l.joint < r.joint; });
  PetscCall(PetscLogEventEnd(Events().joint_gather, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyGatherRecords(BoltnetAssembly a, std::vector<JointRecord> &records)
{
  std::vector<JointRecord> mine;
  PetscFunctionBeginUser;
  PetscCall(AssemblyJointRecords(a, mine));
  PetscCall(GatherJointRecords(a, mine, records));
  PetscFunctionReturn(0);
}

} // namespace boltnet
