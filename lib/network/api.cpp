// The public assembly API of boltnet.h: create and destroy, options, set-up, results. The
// description calls are in model/describe.cpp. Each entry point checks its arguments
// (core/check.hpp) and runs what can throw (new, std::vector, std::string) inside Guard()
// (core/guard.hpp): a C++ exception becomes a PETSc error naming the function.
#include "core/check.hpp"
#include "core/guard.hpp"
#include "network/internal.hpp"

#include <cmath>
#include <algorithm>
#include <cstring>

using namespace boltnet;

namespace {
PetscErrorCode SetFromOptions(BoltnetAssembly a);
}

PetscErrorCode BoltnetAssemblyCreate(MPI_Comm comm, BoltnetAssembly *a)
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 2, "BoltnetAssembly *");
  *a = nullptr;
  PetscCheck(comm != MPI_COMM_NULL, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s: argument 1 (comm) is MPI_COMM_NULL", __func__);
  PetscCall(BoltnetInitializePackage());
  PetscCall(Guard(__func__, [&] {
    *a = new _p_BoltnetAssembly();
    return PetscErrorCode(0);
  }));
  PetscCallMPI(MPI_Comm_dup(comm, &(*a)->comm));
  PetscCallMPI(MPI_Comm_rank((*a)->comm, &(*a)->rank));
  PetscCallMPI(MPI_Comm_size((*a)->comm, &(*a)->size));
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyDestroy(BoltnetAssembly *a)
{
  PetscFunctionBeginUser;
  if (!a || !*a) PetscFunctionReturn(0);
  PetscCall(SNESDestroy(&(*a)->snes));
  PetscCall(MatDestroy(&(*a)->J));
  PetscCall(MatDestroy(&(*a)->checks.Jlast));
  PetscCall(AbsMultDestroy(&(*a)->checks.roundoff));
  PetscCall(MatDestroy(&(*a)->Jbase));
  PetscCall(MatDestroy(&(*a)->isolve.P));
  PetscCall(MatDestroy(&(*a)->isolve.Pbase));
  if (!(*a)->isolve.bddc_option.empty()) PetscCall(PetscOptionsClearValue(nullptr, (*a)->isolve.bddc_option.c_str()));
  PetscCall(VecDestroy(&(*a)->X));
  PetscCall(VecDestroy(&(*a)->Xprev));
  PetscCall(DMDestroy(&(*a)->net.dm));
  PetscCallMPI(MPI_Comm_free(&(*a)->comm));
  delete *a; // the condensed patches' PETSc objects go with it (core/handle.hpp)
  *a = nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblySetOptionsPrefix(BoltnetAssembly a, const char prefix[])
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  PetscCall(Guard(__func__, [&] {
    a->prefix = prefix ? prefix : "";
    return PetscErrorCode(0);
  }));
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblySetFromOptions(BoltnetAssembly a)
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  PetscCall(SetFromOptions(a));
  PetscFunctionReturn(0);
}

namespace {
PetscErrorCode SetFromOptions(BoltnetAssembly a)
{
  AssemblyOptions &o        = a->opt;
  const char      *tangents[] = {"paper", "consistent"};
  PetscInt         t          = static_cast<PetscInt>(o.tangent);
  PetscInt         ct         = static_cast<PetscInt>(o.coupling_type);
  PetscFunctionBeginUser;
  // -patch_condense: auto, or one of PETSc's boolean words for every patch or none.
  const char *condense_names[] = {"false", "true", "auto"};
  char        condense[16];
  PetscBool   condense_set = PETSC_FALSE;
  PetscCall(PetscStrncpy(condense, condense_names[static_cast<int>(o.condense)], sizeof condense));
  // No C++ allocation here: PETSc's options only.
  PetscOptionsBegin(a->comm, a->prefix.c_str(), "boltnet solver options", "boltnet");
  PetscCall(PetscOptionsEList("-joint_tangent", "Joint tangent in the Jacobian: the paper's state-switched one or the consistent one", "BoltnetAssemblySetFromOptions", tangents, 2, tangents[t], &t, nullptr));
  PetscCall(PetscOptionsInt("-load_max_cuts", "Step cut-backs (halvings) allowed per load step before the solve stops", "BoltnetAssemblySolveLoadPath", o.max_cuts, &o.max_cuts, nullptr));
  PetscCall(PetscOptionsEList("-coupling_type", "How a joint attaches to a shell patch: its footprint tied rigidly to the joint node by penalty links, or eliminated exactly (rigid-body slaves), or the joint on the nearest mesh node (no footprint)", "BoltnetAssemblySetFromOptions", kCouplingTypeNames, 3, kCouplingTypeNames[ct], &ct, nullptr));
  PetscCall(PetscOptionsReal("-coupling_radius", "Footprint radius of a fastener on a shell patch (mm): nodes within it follow the joint node rigidly", "BoltnetAssemblySetFromOptions", o.coupling_radius, &o.coupling_radius, nullptr));
  PetscCall(PetscOptionsReal("-coupling_reach", "How far along its axis a fastener reaches for the sheet it attaches to (mm); the footprint is taken on the nearest sheet within it (0: 4 x -coupling_radius)", "BoltnetAssemblySetFromOptions", o.coupling_reach, &o.coupling_reach, nullptr));
  PetscCall(PetscOptionsString("-patch_condense", "Condense shell patches onto their ports (joint nodes and seam nodes) once per analysis, so that Newton iterates on the interface only: auto (each patch whose port dof are at most -patch_condense_ratio times the square root of its dof), true (every patch) or false (none: every node in the global system); docs/solver.md", "BoltnetAssemblySetFromOptions", condense, condense, sizeof condense, &condense_set));
  PetscCall(PetscOptionsReal("-patch_condense_ratio", "With -patch_condense auto: condense a shell patch when its port dof are at most this many times the square root of its dof, where its dense port block costs less than its sparse factorisation (docs/solver.md, \"Which patches are condensed\")", "BoltnetAssemblySetFromOptions", o.condense_ratio, &o.condense_ratio, nullptr));
  PetscCall(PetscOptionsBool("-interface_near_null_space", "Give the Jacobian the six rigid-body modes of its nodes (three translations, three rotations) as near-null space (MatSetNearNullSpace), which GAMG and BoomerAMG use to build their coarse spaces; LU ignores it (docs/solver.md)", "BoltnetAssemblySetFromOptions", o.near_null_space, &o.near_null_space, nullptr));
  PetscCall(PetscOptionsBool("-interface_slave_split", "With -pc_type fieldsplit on patches kept whole: split the Jacobian into m (every row but the slaves of exact coupling, with the rigid-body modes of its nodes as near-null space) and s (the slaves' constraint rows); J is block lower triangular in them, so -pc_fieldsplit_type multiplicative with an algebraic multigrid on m solves it (docs/solver.md, \"Algebraic multigrid\"); false: PCFIELDSPLIT's own splits", "BoltnetAssemblySetFromOptions", o.slave_split, &o.slave_split, nullptr));
  PetscCall(PetscOptionsBool("-interface_matis", "Also assemble the Jacobian unassembled, as a MATIS with one subdomain per rank (its patches, seams and joints), and precondition GMRES with PETSc's BDDC on it (PCBDDC; -ksp_ and -pc_bddc_ options apply) instead of factoring J: docs/solver.md, \"BDDC\"", "BoltnetAssemblySetFromOptions", o.matis, &o.matis, nullptr));
  PetscCall(PetscOptionsInt("-patch_max_nodes", "Largest shell patch in nodes: a larger part is cut by METIS into patches joined by seam edges (0: never cut; -1: automatic: no cut on one rank; on several, about four patches per rank (none below 64 nodes), or with -patch_condense false eight (none below 32); docs/solver.md)", "BoltnetAssemblySetFromOptions", o.patch_max_nodes, &o.patch_max_nodes, nullptr));
  PetscCall(PetscOptionsBool("-patch_balance", "Distribute the patches over the ranks by dof with METIS (false: PETSc's partitioner, by edge count)", "BoltnetAssemblySetFromOptions", o.balance, &o.balance, nullptr));
  PetscCall(PetscOptionsReal("-coupling_penalty", "Penalty of the rigid footprint links, as a multiple of the shell's membrane stiffness A11 (N/mm)", "BoltnetAssemblySetFromOptions", o.coupling_penalty, &o.coupling_penalty, nullptr));
  PetscCall(PetscOptionsBool("-shell_directors", "On curved shell parts, give the elements around each node the mean of their normals there as the common director (folds keep each element's own normal); false: every element its own normals (docs/shell.md)", "BoltnetAssemblySetFromOptions", o.shell_directors, &o.shell_directors, nullptr));
  PetscCall(PetscOptionsBool("-joint_stuck_linear", "Solve joints that stay stuck as linear springs (no state logic) and keep the Jacobian and its factorisation while no joint's tangent changes; every such joint is checked with the full law before a step is accepted", "BoltnetAssemblySetFromOptions", o.stuck_linear, &o.stuck_linear, nullptr));
  PetscCall(PetscOptionsBool("-load_predictor", "Start each load step from the last converged solution moved on by the last converged step's increment, scaled to this step's (a secant predictor), where the load goes on the same way and the step was not cut back; false: from the last converged solution (docs/solver.md)", "BoltnetAssemblySolveLoadPath", o.predictor, &o.predictor, nullptr));
  PetscCall(PetscOptionsReal("-joint_stuck_margin", "Solve a joint as a linear spring in a step when its predicted utilization (trial force / friction threshold, or jump / clearance) stays below this", "BoltnetAssemblySetFromOptions", o.stuck_margin, &o.stuck_margin, nullptr));
  PetscCall(PetscOptionsBool("-load_progress", "Print one line per converged load step: the nominal step of the path reached (and the part of it, after cut-backs), load factor, Newton iterations, joints sticking, sliding and bearing (summed over ranks), elapsed time and an estimate of the time left (docs/scenes.md)", "BoltnetAssemblySolveLoadPath", o.progress, &o.progress, nullptr));
  PetscCall(PetscOptionsBool("-joint_monitor", "Print, per Newton iteration, the joints in each state and how many changed (summed over ranks)", "BoltnetAssemblySetFromOptions", o.monitor_states, &o.monitor_states, nullptr));
  PetscOptionsEnd();
  if (condense_set) {
    // PetscOptionsStringToBool's words, compared here so that a wrong one gets one line.
    const char *words[] = {"auto", "true", "yes", "on", "1", "false", "no", "off", "0"};
    int         w       = -1;
    for (int k = 0; k < 9 && w < 0; ++k) {
      PetscBool eq;
      PetscCall(PetscStrcasecmp(condense, words[k], &eq));
      if (eq) w = k;
    }
    PetscCheck(w >= 0, a->comm, PETSC_ERR_USER_INPUT, "-patch_condense %s: expected auto, true or false", condense);
    o.condense = w == 0 ? Condense::Auto : w <= 4 ? Condense::All : Condense::None;
  }
  PetscCheck(o.condense_ratio >= 0, a->comm, PETSC_ERR_USER_INPUT, "-patch_condense_ratio %g must be >= 0", (double)o.condense_ratio);
  PetscCheck(o.coupling_radius > 0, a->comm, PETSC_ERR_USER_INPUT, "-coupling_radius %g must be > 0", (double)o.coupling_radius);
  PetscCheck(o.coupling_reach >= 0, a->comm, PETSC_ERR_USER_INPUT, "-coupling_reach %g must be >= 0 (0: automatic)", (double)o.coupling_reach);
  PetscCheck(o.patch_max_nodes >= -1, a->comm, PETSC_ERR_USER_INPUT, "-patch_max_nodes %" PetscInt_FMT " must be -1 (automatic), 0 (never cut) or a positive node count", o.patch_max_nodes);
  PetscCheck(o.coupling_penalty > 0, a->comm, PETSC_ERR_USER_INPUT, "-coupling_penalty %g must be > 0", (double)o.coupling_penalty);
  PetscCheck(o.stuck_margin >= 0 && o.stuck_margin <= 1, a->comm, PETSC_ERR_USER_INPUT, "-joint_stuck_margin %g must lie in [0, 1] (0: no joint is frozen)", (double)o.stuck_margin);
  PetscCheck(o.max_cuts >= 0 && o.max_cuts <= 60, a->comm, PETSC_ERR_USER_INPUT, "-load_max_cuts %" PetscInt_FMT " must lie in [0, 60]", o.max_cuts);
  o.tangent               = static_cast<Tangent>(t);
  o.coupling_type         = static_cast<CouplingType>(ct);
  o.setfromoptions_called = PETSC_TRUE;
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode BoltnetAssemblySetUp(BoltnetAssembly a)
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  if (a->net.dm) PetscFunctionReturn(0);
  if (!a->opt.setfromoptions_called) PetscCall(SetFromOptions(a));
  PetscCall(Guard(__func__, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(AssemblyBuildNetwork(a));
    PetscCall(AssemblySetUpSolver(a));
    PetscFunctionReturn(0);
  }));
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyGetDM(BoltnetAssembly a, DM *dm)
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  BoltnetCheckPointer(dm, 2, "DM *");
  *dm = a->net.dm;
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyGetSNES(BoltnetAssembly a, SNES *snes)
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  BoltnetCheckPointer(snes, 2, "SNES *");
  *snes = a->snes;
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyGetLoadFactor(BoltnetAssembly a, PetscReal *lambda)
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  BoltnetCheckPointer(lambda, 2, "PetscReal *");
  *lambda = a->lambda;
  PetscFunctionReturn(0);
}

// force, jump and state may be NULL (that result is not wanted).
PetscErrorCode BoltnetAssemblyGetJointResult(BoltnetAssembly a, PetscInt id, PetscReal force[6], PetscReal jump[6], BoltnetJointState *state)
{
  JointRecord found{};
  PetscMPIInt owner, first;
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  PetscCheck(a->net.dm, a->comm, PETSC_ERR_ORDER, "%s: call BoltnetAssemblySetUp() first", __func__);
  PetscCheck(id >= 0, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: argument 2 (id) = %" PetscInt_FMT " is not a joint id (ids are >= 0)", __func__, id);
  // The rank that owns the joint finds it among its own records and sends it to all: no rank
  // gathers the others' joints.
  owner = a->size;
  PetscCall(Guard(__func__, [&]() -> PetscErrorCode {
    std::vector<JointRecord> mine;
    PetscFunctionBeginUser;
    PetscCall(AssemblyJointRecords(a, mine));
    for (const JointRecord &r : mine)
      if (r.joint == id) {
        found = r;
        owner = a->rank;
      }
    PetscFunctionReturn(0);
  }));
  PetscCallMPI(MPI_Allreduce(&owner, &first, 1, MPI_INT, MPI_MIN, a->comm));
  PetscCheck(first < a->size, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "No joint with id %" PetscInt_FMT, id);
  PetscCallMPI(MPI_Bcast(&found, sizeof(JointRecord), MPI_BYTE, first, a->comm));
  for (int i = 0; i < 6; ++i) {
    if (force) force[i] = found.force[i];
    if (jump) jump[i] = found.jump[i];
  }
  if (state) *state = static_cast<BoltnetJointState>(found.state);
  PetscFunctionReturn(0);
}

// The displacement of a patch's node 0 (a rigid patch's node, a shell patch's first mesh node; of a
// cut part, the patch that holds its node 0), recovered from the interface when condensed.
PetscErrorCode BoltnetAssemblyGetPatchDisplacement(BoltnetAssembly a, PetscInt patch, PetscReal u[6])
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  BoltnetCheckPointer(u, 3, "u");
  PetscCheck(a->net.dm, a->comm, PETSC_ERR_ORDER, "%s: call BoltnetAssemblySetUp() first", __func__);
  PetscCheck(patch >= 0, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: argument 2 (patch) = %" PetscInt_FMT " is not a patch id (ids are >= 0)", __func__, patch);
  PetscReal          loc[7] = {0, 0, 0, 0, 0, 0, 0}, glob[7];
  Vec                Xl;
  const PetscScalar *x;
  PetscCall(GetLocalX(a, a->X, &Xl, &x));
  PetscCall(Collective(a->comm, __func__, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    for (const OwnedPatch &op : a->patches.owned) {
      if (a->layout.patches[op.index].id != patch) continue;
      if (op.shell) {
        const ShellPatch &sp = a->layout.shells.at(op.index);
        if (!(sp.part_node.empty() || sp.part_node[0] == 0)) {
          const auto it = std::find(sp.part_node.begin(), sp.part_node.end(), 0);
          if (it == sp.part_node.end()) continue;
        }
      }
      std::vector<double> full;
      PetscCall(AssemblyPatchDisplacement(a, op, x, a->lambda, full));
      size_t n0 = 0;
      if (op.shell) {
        const ShellPatch &sp = a->layout.shells.at(op.index);
        if (!sp.part_node.empty()) n0 = (size_t)(std::find(sp.part_node.begin(), sp.part_node.end(), 0) - sp.part_node.begin());
      }
      for (int i = 0; i < 6; ++i) loc[i] = full[6 * n0 + i];
      loc[6] = 1;
    }
    PetscFunctionReturn(0);
  }));
  PetscCall(RestoreLocalX(a, &Xl, &x));
  PetscCall(MPIU_Allreduce(loc, glob, 7, MPIU_REAL, MPIU_SUM, a->comm));
  PetscCheck(glob[6] == 1, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "No patch with id %" PetscInt_FMT, patch);
  for (int i = 0; i < 6; ++i) u[i] = glob[i];
  PetscFunctionReturn(0);
}
