// Joint-state monitoring: per Newton iteration, the joints in each state and how many changed.
#include "network/assembly.hpp"
#include "core/guard.hpp"

#include <algorithm>
#include <sstream>

namespace boltnet {

namespace {
// Records the state of every local joint at each iterate; prints counts with -joint_monitor.
PetscErrorCode MonitorJointStatesImpl(SNES snes, PetscInt its, PetscReal fnorm, void *ctx)
{
  BoltnetAssembly       a = static_cast<BoltnetAssembly>(ctx);
  Vec                   X;
  std::vector<Response> r;
  PetscFunctionBeginUser;
  PetscCall(SNESGetSolution(snes, &X));
  PetscCall(AssemblyEvaluateJoints(a, X, r));
  if (its == 0) a->joints.state_trace.assign(r.size(), {});
  PetscInt loc[7] = {0, 0, 0, 0, 0, 0, 0}, glob[7];
  for (char f : a->joints.frozen) loc[6] += f;
  for (size_t i = 0; i < r.size(); ++i) {
    const PetscInt s = static_cast<PetscInt>(r[i].state);
    if (!a->joints.state_trace[i].empty() && a->joints.state_trace[i].back() != s) loc[5]++;
    a->joints.state_trace[i].push_back(s);
    loc[s]++;
  }
  if (!a->opt.monitor_states) PetscFunctionReturn(0);
  PetscCall(MPIU_Allreduce(loc, glob, 7, MPIU_INT, MPI_SUM, a->comm));
  PetscCall(PetscPrintf(a->comm, "  %3" PetscInt_FMT " joints: stick %" PetscInt_FMT " slide %" PetscInt_FMT " contact %" PetscInt_FMT " open %" PetscInt_FMT " linear %" PetscInt_FMT " | changed %" PetscInt_FMT " | as springs %" PetscInt_FMT " | ||F|| %g\n", its,
                        glob[static_cast<int>(State::Stick)], glob[static_cast<int>(State::Slide)], glob[static_cast<int>(State::Contact)], glob[static_cast<int>(State::Open)], glob[static_cast<int>(State::Linear)], glob[5], glob[6], (double)fnorm));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode MonitorJointStates(SNES snes, PetscInt its, PetscReal fnorm, void *ctx)
{
  return Guard("MonitorJointStates (SNES monitor)", [&] { return MonitorJointStatesImpl(snes, its, fnorm, ctx); });
}

namespace {
// Concatenate a string from every rank, in rank order, on every rank.
PetscErrorCode AllgatherText(BoltnetAssembly a, const std::string &mine, std::string &all)
{
  PetscFunctionBeginUser;
  PetscMPIInt              len = (PetscMPIInt)mine.size();
  std::vector<PetscMPIInt> lens(a->size), displs(a->size);
  PetscCallMPI(MPI_Allgather(&len, 1, MPI_INT, lens.data(), 1, MPI_INT, a->comm));
  PetscMPIInt total = 0;
  for (PetscMPIInt i = 0; i < a->size; ++i) {
    displs[i] = total;
    total += lens[i];
  }
  all.assign(total, ' ');
  PetscCallMPI(MPI_Allgatherv(mine.data(), len, MPI_CHAR, all.data(), lens.data(), displs.data(), MPI_CHAR, a->comm));
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode AssemblyDescribeSingular(BoltnetAssembly a, Vec X, std::string &msg)
{
  std::vector<Response> resp;
  std::ostringstream    loc;
  PetscInt              n = 0;
  PetscFunctionBeginUser;
  PetscCall(AssemblyEvaluateJoints(a, X, resp));
  static const char *const dir[3] = {"n", "t1", "t2"};
  for (size_t i = 0; i < resp.size() && n < 10; ++i) {
    double scale = 0;
    for (int k = 0; k < 36; ++k) scale = std::max(scale, std::abs(resp[i].tangent[k]));
    std::string none;
    for (int d = 0; d < 3; ++d)
      if (std::abs(resp[i].tangent[7 * d]) <= 1e-12 * scale || scale == 0) none += (none.empty() ? "" : ",") + std::string(dir[d]);
    if (none.empty()) continue;
    loc << "joint " << a->joints.comp[i].id << " (" << stateName(resp[i].state) << ", no stiffness along " << none << "); ";
    ++n;
  }
  std::string all;
  PetscCall(AllgatherText(a, loc.str(), all));
  while (!all.empty() && (all.back() == ' ' || all.back() == ';')) all.pop_back();
  msg = all.empty() ? std::string() : "joints with no tangent stiffness in a direction (a singular Jacobian if nothing else holds it): " + all;
  PetscFunctionReturn(0);
}

// After a failed solve: the joints that changed state most often during it, with their states.
PetscErrorCode AssemblyDescribeChatter(BoltnetAssembly a, std::string &msg)
{
  PetscFunctionBeginUser;
  // Local summary: (changes, joint id, sequence) for joints that changed state at least twice.
  std::ostringstream loc;
  PetscInt           n = 0;
  for (size_t i = 0; i < a->joints.size(); ++i) {
    const auto &tr = a->joints.state_trace.size() > i ? a->joints.state_trace[i] : std::vector<PetscInt>{};
    PetscInt    changes = 0;
    for (size_t k = 1; k < tr.size(); ++k) changes += tr[k] != tr[k - 1];
    if (changes < 2 || n >= 10) continue;
    loc << "joint " << a->joints.comp[i].id << " (" << changes << " changes: ";
    const size_t first = tr.size() > 8 ? tr.size() - 8 : 0;
    if (first) loc << "... ";
    for (size_t k = first; k < tr.size(); ++k) loc << (k > first ? ">" : "") << stateName(static_cast<State>(tr[k]));
    loc << "); ";
    ++n;
  }
  // Every rank gets the whole text (error messages are raised collectively).
  std::string all;
  PetscCall(AllgatherText(a, loc.str(), all));
  msg = all.empty() ? std::string("no joint changed state more than once") : "joints that kept changing state: " + all;
  PetscFunctionReturn(0);
}

} // namespace boltnet
