// Trusting "converged": equilibrium against the problem's own force scale, and singular Jacobians
// (mechanisms) named by patch, dof and joint (docs/solver.md, "When is a step converged").
#include "core/guard.hpp"
#include "core/memory.hpp"
#include "network/internal.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>

namespace boltnet {

PetscErrorCode AssemblyEquilibrium(BoltnetAssembly a, Vec X, Equilibrium *eq)
{
  Vec                   F;
  std::vector<Response> resp;
  PetscReal             loc[4] = {0, 0, 0, 0}, glob[4];
  PetscInt              rstart;
  PetscFunctionBeginUser;
  // The residual without the constrained rows: at a free row the out-of-balance force, at a
  // constrained row the internal force there, i.e. the reaction. The rows are set aside for this one
  // evaluation (AssemblyFormFunction replaces them by u - lambda u_bar).
  std::vector<PetscInt> rows;
  std::swap(rows, a->bc.dirichlet_rows);
  PetscCall(VecDuplicate(X, &F));
  PetscErrorCode ierr = AssemblyFormFunction(a->snes, X, F, a);
  std::swap(rows, a->bc.dirichlet_rows);
  PetscCall(ierr);
  PetscCall(VecGetOwnershipRange(F, &rstart, nullptr));
  const PetscScalar *f;
  PetscCall(VecGetArrayRead(F, &f));
  PetscInt n;
  PetscCall(VecGetLocalSize(F, &n));
  std::vector<char> fixed(n, 0);
  for (PetscInt r : a->bc.dirichlet_rows) fixed[r - rstart] = 1;
  for (PetscInt i = 0; i < n; ++i) loc[fixed[i] ? 1 : 0] += PetscRealPart(f[i] * f[i]);
  PetscCall(VecRestoreArrayRead(F, &f));
  PetscCall(VecDestroy(&F));
  PetscCall(AssemblyEvaluateJoints(a, X, resp));
  for (const Response &r : resp)
    for (double v : r.force) loc[3] += v * v;
  PetscCall(MPIU_Allreduce(loc, glob, 4, MPIU_REAL, MPIU_SUM, a->comm));
  eq->imbalance = std::sqrt(glob[0]);
  eq->reactions = std::sqrt(glob[1]);
  eq->applied   = AssemblyAppliedForce(a, a->lambda_target); // also the forces inside condensed patches
  eq->joints    = std::sqrt(glob[3]);
  eq->scale     = std::max({eq->reactions, eq->applied, eq->joints, a->checks.force_scale_seen});
  eq->ratio     = eq->scale > 0 ? eq->imbalance / eq->scale : (eq->imbalance > 0 ? PETSC_INFINITY : 0.0);
  PetscFunctionReturn(0);
}

std::string DescribeEquilibrium(const Equilibrium &eq)
{
  std::ostringstream m;
  m.precision(3);
  m << "out-of-balance force " << eq.imbalance << " = " << eq.ratio << " of the force scale " << eq.scale << " (now: applied " << eq.applied << ", reactions " << eq.reactions << ", joint forces " << eq.joints << ")";
  return m.str();
}

namespace {

constexpr PetscInt kNodeDof                  = 6;
const char *const  kDofName[kNodeDof]        = {"ux", "uy", "uz", "rx", "ry", "rz"};
const char *const  kJumpName[kNodeDof]       = {"n", "t1", "t2", "rn", "rt1", "rt2"};
constexpr double   kNullShare                = 1e-2; // a dof is part of the mechanism above this share of the largest

// Every rank's text, in rank order, on every rank.
PetscErrorCode AllgatherText(MPI_Comm comm, const std::string &mine, std::string &all)
{
  PetscMPIInt size, len = (PetscMPIInt)mine.size();
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscMPIInt> lens(size), displs(size);
  PetscCallMPI(MPI_Allgather(&len, 1, MPI_INT, lens.data(), 1, MPI_INT, comm));
  PetscMPIInt total = 0;
  for (PetscMPIInt i = 0; i < size; ++i) {
    displs[i] = total;
    total += lens[i];
  }
  all.assign(total, ' ');
  PetscCallMPI(MPI_Allgatherv(mine.data(), len, MPI_CHAR, all.data(), lens.data(), displs.data(), MPI_CHAR, comm));
  PetscFunctionReturn(0);
}

// Name the patches (with their moving dof and node count) and the joints (with the jump components
// that open) of the null vector z: the mechanism the singular Jacobian admits.
PetscErrorCode DescribeMechanism(BoltnetAssembly a, Vec z, std::string &msg)
{
  PetscReal          zmax;
  PetscInt           rstart;
  const PetscScalar *zz;
  std::ostringstream patches, joints;
  PetscFunctionBeginUser;
  PetscCall(VecNorm(z, NORM_INFINITY, &zmax));
  if (!(zmax > 0)) {
    msg.clear();
    PetscFunctionReturn(0);
  }
  PetscCall(VecGetOwnershipRange(z, &rstart, nullptr));
  PetscCall(VecGetArrayRead(z, &zz));
  for (const OwnedPatch &op : a->patches.owned) {
    const PatchComp &p             = a->layout.patches[op.index];
    bool             dof[kNodeDof] = {false};
    PetscInt         nodes         = 0;
    for (PetscInt nd = 0; nd < p.nnodes; ++nd) {
      bool moves = false;
      for (PetscInt d = 0; d < kNodeDof; ++d)
        if (std::abs(PetscRealPart(zz[op.goff - rstart + kNodeDof * nd + d])) >= kNullShare * zmax) dof[d] = moves = true;
      nodes += moves;
    }
    if (!nodes) continue;
    PetscInt mask = 0;
    for (PetscInt d = 0; d < kNodeDof; ++d) mask |= dof[d] ? (1 << d) : 0;
    // A condensed shell patch carries its ports only: the null vector says which of its dof move,
    // not how many of its nodes (-1 below).
    const bool ports_only = op.shell && a->layout.shells.at(op.index).condensed;
    patches << p.id << " " << mask << " " << (ports_only ? -1 : nodes) << "\n"; // merged over ranks and cut patches below
  }
  PetscCall(VecRestoreArrayRead(z, &zz));
  // Joints: the jump of the mechanism across each local joint, in its frame.
  Vec                zl;
  const PetscScalar *x;
  PetscCall(GetLocalX(a, z, &zl, &x));
  const JointSet &jset = a->joints;
  for (size_t k = 0; k < jset.size(); ++k) {
    const JointComp &j  = jset.comp[k];
    const Vec6       ua = AttachmentDof(j.da, x + jset.oa[k]), ub = AttachmentDof(j.db, x + jset.ob[k]);
    std::string      open;
    for (int blk = 0; blk < 2; ++blk)
      for (int i = 0; i < 3; ++i) {
        double s = 0;
        for (int c = 0; c < 3; ++c) s += j.R[3 * i + c] * PetscRealPart(ub[3 * blk + c] - ua[3 * blk + c]);
        if (std::abs(s) >= kNullShare * zmax) open += (open.empty() ? "" : ",") + std::string(kJumpName[3 * blk + i]);
      }
    if (!open.empty()) joints << "joint " << j.id << " (" << open << "); ";
  }
  PetscCall(RestoreLocalX(a, &zl, &x));
  std::string all, ps, js;
  PetscCall(AllgatherText(a->comm, patches.str(), all));
  PetscCall(AllgatherText(a->comm, joints.str(), js));
  std::map<PetscInt, std::pair<PetscInt, PetscInt>> moved; // part id -> (dof mask, nodes)
  std::istringstream in(all);
  for (PetscInt id, mask, nodes; in >> id >> mask >> nodes;) {
    moved[id].first |= mask;
    moved[id].second = (nodes < 0 || moved[id].second < 0) ? -1 : moved[id].second + nodes;
  }
  for (const auto &[id, mn] : moved) {
    ps += "patch " + std::to_string(id) + " (";
    for (PetscInt d = 0, first = 1; d < kNodeDof; ++d)
      if (mn.first & (1 << d)) {
        ps += std::string(first ? "" : ",") + kDofName[d];
        first = 0;
      }
    ps += mn.second < 0 ? std::string("); ") : " of " + std::to_string(mn.second) + (mn.second == 1 ? " node" : " nodes") + "); ";
  }
  auto trim = [](std::string &s) {
    while (!s.empty() && (s.back() == ' ' || s.back() == ';')) s.pop_back();
  };
  trim(ps);
  trim(js);
  msg = "it moves " + (ps.empty() ? std::string("no patch") : ps) + "; across " + (js.empty() ? std::string("no joint") : js);
  PetscFunctionReturn(0);
}

// The Jacobian's null space, from MUMPS: the solve phase with ICNTL(25) = k returns its k-th basis
// vector (MUMPS users' guide, ICNTL(25)); z gets the largest normalised |entry| over (up to 12) of them. MUMPS refuses that with a distributed solution
// (INFOG(1) = -37), which PETSc uses on more than one rank, so the Jacobian is gathered to rank 0 and
// factorised there once more: only after a failure, and the same vector on any number of ranks.
PetscErrorCode NullVector(BoltnetAssembly a, Vec z, PetscBool *found)
{
  PetscInt    N, rstart, rend, nnull = 0;
  IS          all;
  Mat        *sub, F;
  Vec         zs, bs;
  VecScatter  toz;
  PetscFunctionBeginUser;
  PetscCall(MatGetSize(a->J, &N, nullptr));
  PetscCall(MatGetOwnershipRange(a->J, &rstart, &rend));
  PetscCall(ISCreateStride(PETSC_COMM_SELF, a->rank == 0 ? N : 0, 0, 1, &all));
  PetscCall(MatCreateSubMatrices(a->J, 1, &all, &all, MAT_INITIAL_MATRIX, &sub));
  PetscCall(ISDestroy(&all));
  PetscCall(VecScatterCreateToZero(z, &toz, &zs));
  if (a->rank == 0) {
    IS            rperm, cperm;
    MatFactorInfo info;
    PetscCall(MatGetFactor(sub[0], MATSOLVERMUMPS, MAT_FACTOR_LU, &F));
    PetscCall(MatMumpsSetIcntl(F, 24, 1));
    PetscCall(MatMumpsSetCntl(F, 3, a->checks.null_pivot_threshold));
    PetscCall(MatGetOrdering(sub[0], MATORDERINGNATURAL, &rperm, &cperm));
    PetscCall(MatFactorInfoInitialize(&info));
    PetscCall(MatLUFactorSymbolic(F, sub[0], rperm, cperm, &info));
    PetscCall(MatLUFactorNumeric(F, sub[0], &info));
    PetscCall(MatMumpsGetInfog(F, 28, &nnull));
    if (nnull > 0) { // |z| = the largest of the normalised |basis vectors|: every dof of every mode
      Vec zk;
      PetscCall(VecDuplicate(zs, &bs));
      PetscCall(VecDuplicate(zs, &zk));
      PetscCall(VecSet(bs, 0.0));
      PetscCall(VecSet(zs, 0.0));
      for (PetscInt k = 1; k <= PetscMin(nnull, 12); ++k) {
        PetscReal m;
        PetscCall(MatMumpsSetIcntl(F, 25, k));
        PetscCall(MatSolve(F, bs, zk));
        PetscCall(VecAbs(zk));
        PetscCall(VecNorm(zk, NORM_INFINITY, &m));
        if (m > 0) PetscCall(VecScale(zk, 1.0 / m));
        PetscCall(VecPointwiseMax(zs, zs, zk));
      }
      PetscCall(VecDestroy(&zk));
      PetscCall(VecDestroy(&bs));
    }
    PetscCall(ISDestroy(&rperm));
    PetscCall(ISDestroy(&cperm));
    PetscCall(MatDestroy(&F));
  }
  PetscCall(MatDestroySubMatrices(1, &sub));
  PetscCallMPI(MPI_Bcast(&nnull, 1, MPIU_INT, 0, a->comm));
  *found = nnull > 0 ? PETSC_TRUE : PETSC_FALSE;
  if (*found) {
    PetscCall(VecScatterBegin(toz, zs, z, INSERT_VALUES, SCATTER_REVERSE));
    PetscCall(VecScatterEnd(toz, zs, z, INSERT_VALUES, SCATTER_REVERSE));
  }
  PetscCall(VecScatterDestroy(&toz));
  PetscCall(VecDestroy(&zs));
  PetscFunctionReturn(0);
}

} // namespace

// The SNES's KSP and PC, and whether the PC is an LU factorisation by MUMPS (the only solver whose
// null pivots boltnet reads).
static PetscErrorCode MumpsLU(BoltnetAssembly a, KSP *ksp, PC *pc, PetscBool *mumps)
{
  PetscBool     lu;
  MatSolverType type;
  PetscFunctionBeginUser;
  *mumps = PETSC_FALSE;
  PetscCall(SNESGetKSP(a->snes, ksp));
  PetscCall(KSPGetPC(*ksp, pc));
  PetscCall(PetscObjectTypeCompare((PetscObject)*pc, PCLU, &lu));
  if (!lu) PetscFunctionReturn(0);
  PetscCall(PCFactorGetMatSolverType(*pc, &type));
  *mumps = type && !std::strcmp(type, MATSOLVERMUMPS) ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(0);
}

// Factors on disk from the start when they will not fit in memory (docs/solver.md, "Factors on
// disk"). MUMPS's analysis knows what its in-core factorisation will take on each rank (INFO(15),
// in MB, the workspace relaxation ICNTL(14) included), and ICNTL(22) is read only by the
// factorisation that follows (MUMPS users' guide, ICNTL(22)); so between the two, the ranks that
// share a node add up their estimates and compare them with what the node has. A factorisation in
// core that fails for want of memory can still be factored again on disk (stepper.cpp), but on the
// full wing-fuselage junction that retry held about 4 GB more than a run on disk from the start and
// was killed (docs/performance.md). Not called where the user's own -mat_mumps_icntl_22 decides.
static PetscErrorCode ChooseFactorStorage(BoltnetAssembly a, Mat F)
{
  PetscInt    info1, incore, ooc;
  MPI_Comm    node;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCall(MatMumpsGetInfog(F, 1, &info1));
  if (info1 < 0) PetscFunctionReturn(0); // the analysis failed: the factorisation reports it
  PetscCall(MatMumpsGetInfo(F, 15, &incore)); // this rank's estimate in core, MB
  PetscCall(MatMumpsGetInfo(F, 17, &ooc));    // and out of core
  double mine[2] = {(double)incore, (double)ooc}, need[2];
  PetscCallMPI(MPI_Comm_rank(a->comm, &rank));
  PetscCallMPI(MPI_Comm_split_type(a->comm, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node));
  PetscCallMPI(MPI_Allreduce(mine, need, 2, MPI_DOUBLE, MPI_SUM, node));
  double here = a->isolve.memory_mb > 0 ? a->isolve.memory_mb : AvailableMemory(), have;
  PetscCallMPI(MPI_Allreduce(&here, &have, 1, MPI_DOUBLE, MPI_MIN, node));
  PetscCallMPI(MPI_Comm_free(&node));
  // The node that is shortest of memory speaks for all: ICNTL(22) holds for every rank.
  struct {
    double      ratio;
    PetscMPIInt rank;
  } shortest{have > 0 ? need[0] / have : 0.0, rank}, worst;
  PetscCallMPI(MPI_Allreduce(&shortest, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, a->comm));
  double report[3] = {need[0], need[1], have};
  PetscCallMPI(MPI_Bcast(report, 3, MPI_DOUBLE, worst.rank, a->comm));
  PetscCall(PetscInfo(F, "MUMPS's analysis: %.0f MB in core, %.0f MB out of core, on the node that needs most against the %.0f MB it has%s\n", report[0], report[1], report[2], a->isolve.memory_mb > 0 ? " (-interface_memory_mb)" : " available"));
  if (report[2] <= 0 || worst.ratio <= 1) PetscFunctionReturn(0); // fits, or what the node has is unknown
  PetscCall(MatMumpsSetIcntl(F, 22, 1));
  a->isolve.factors_on_disk = PETSC_TRUE;
  PetscInt N;
  PetscCall(MatGetSize(F, &N, nullptr));
  PetscCall(PetscPrintf(a->comm, "boltnet: MUMPS's analysis estimates %.0f MB to factor the %" PetscInt_FMT "-dof Jacobian in memory, more than the %.0f MB %s: the factors go to disk, %.0f MB stay in memory (MUMPS ICNTL(22) = 1, in the directory MUMPS_OOC_TMPDIR names; -interface_out_of_core false keeps them in memory)\n", report[0], N, report[2],
                        a->isolve.memory_mb > 0 ? "given by -interface_memory_mb" : "the node has available", report[1]));
  PetscFunctionReturn(0);
}

// -interface_solve auto, once per run, from MUMPS's analysis of the first Jacobian (docs/solver.md,
// "The interface solve"). A lagged Newton iteration costs a few triangular solves with the factors
// (FGMRES at Eisenstat-Walker's tolerances: about three), a direct one a factorisation at most: the
// lagged solve pays where a factorisation costs many solves. MUMPS's estimates say so before
// anything is factored: the factorisation's flops (RINFOG(1)) per entry of the factors
// (INFOG(20)), an entry being read about once per solve; factors
// on disk are read back from disk at every solve and need a dearer factorisation (AutoTakesLagged in
// solver/interface.hpp). Another Krylov method or preconditioner than the default's is the user's
// own choice: it stays direct. The estimates are global, so every rank decides alike, and they
// depend on the matrix alone, so a run repeats its choice.
static PetscErrorCode ChooseInterfaceSolve(BoltnetAssembly a, Mat F)
{
  PetscInt  info1, entries, icntl22;
  PetscReal flops;
  KSP       ksp;
  PetscBool preonly;
  PetscFunctionBeginUser;
  a->isolve.solve_auto = PETSC_FALSE;
  PetscCall(MatMumpsGetInfog(F, 1, &info1));
  if (info1 < 0) PetscFunctionReturn(0); // the analysis failed: the factorisation reports it
  PetscCall(MatMumpsGetIcntl(F, 22, &icntl22));
  PetscCall(SNESGetKSP(a->snes, &ksp));
  PetscCall(PetscObjectTypeCompare((PetscObject)ksp, KSPPREONLY, &preonly));
  PetscCall(MatMumpsGetRinfog(F, 1, &flops));
  PetscCall(MatMumpsGetInfog(F, 20, &entries)); // in millions when negative (MUMPS users' guide)
  const double nentries = entries < 0 ? -1e6 * (double)entries : (double)entries;
  const double ratio    = nentries > 0 ? flops / nentries : 0;
  const bool   on_disk  = icntl22 != 0;
  const bool   lagged   = preonly && AutoTakesLagged(a->isolve, ratio, on_disk);
  a->isolve.flops_per_entry = ratio;
  PetscCall(PetscInfo(F, "-interface_solve auto: %s (MUMPS estimates %.6g flops for %.6g entries of the factors: %.0f per entry against -interface_lagged_flops_per_entry%s %g%s%s)\n", lagged ? "lagged" : "direct", (double)flops, nentries, ratio, on_disk ? "_on_disk" : "",
                      (double)(on_disk ? a->isolve.lagged_flops_per_entry_on_disk : a->isolve.lagged_flops_per_entry), on_disk ? (a->isolve.ew_default ? "; factors on disk" : "; factors on disk, without Eisenstat-Walker's tolerances") : "", preonly ? "" : "; the KSP is not the default's"));
  if (!lagged) {
    PetscCall(AssemblyDropDefaultEW(a)); // a direct solve has no Krylov tolerance to set
    PetscFunctionReturn(0);
  }
  // This analysis's factorisation is the lagged solve's first: the KSP becomes FGMRES at the next
  // Newton iteration (AssemblyFormJacobian), when no solve is under way.
  a->isolve.lagged        = PETSC_TRUE;
  a->isolve.lagged_auto   = PETSC_TRUE;
  a->isolve.factors_valid = PETSC_TRUE;
  a->isolve.factorisations = 1;
  PetscInt N;
  PetscCall(MatGetSize(F, &N, nullptr));
  PetscCall(PetscPrintf(a->comm, "boltnet: MUMPS's analysis estimates the %" PetscInt_FMT "-dof Jacobian's factorisation at %.0f flops per entry of its factors (-interface_lagged_flops_per_entry%s %g): the interface solve is lagged, FGMRES preconditioned by a factorisation kept while it converges, to Eisenstat-Walker's tolerances unless -snes_ksp_ew or -ksp_rtol is given (-interface_solve direct factors every Jacobian; docs/solver.md)\n", N, ratio,
                        on_disk ? "_on_disk" : "", (double)(on_disk ? a->isolve.lagged_flops_per_entry_on_disk : a->isolve.lagged_flops_per_entry)));
  PetscFunctionReturn(0);
}

// MUMPS's fill-reducing ordering for the interface Jacobian (ICNTL(7)). Left to itself (7), MUMPS
// takes METIS or SCOTCH where it was built with them, else PORD, Debian's case. Which ordering is
// best depends on the interface: on the 1M-dof plate grid QAMD's factorisation has a sixth fewer
// flops than PORD's (1.66e10 against 2.00e10) and took 14 % less time; on the medium wing-fuselage
// junction QAMD's has 1.6 times PORD's and AMF's 0.59 of it (6.56e11 against 1.11e12; 21 s against
// 30 s). So the first analysis is made with each candidate on a factor of its own, and F gets the
// ordering whose factorisation MUMPS estimates cheapest (RINFOG(1), global: every rank chooses
// alike) if that is at least a tenth below MUMPS's own choice: a factorisation's time follows the
// shape of its tree too (on plate-grid QAMD's 5 % fewer flops took no less time with two BLAS
// threads). An analysis costs a fraction of a factorisation (medium: 1.4 and 0.6 s against 41 s),
// and the choice is kept for the run's later analyses (a cut-back's new PC), so it is made once
// (docs/solver.md, "What a factorisation of the interface costs").
//
// The ordering goes in through the options database, -mat_mumps_icntl_7 under the assembly's prefix,
// for the one analysis that reads it: on one rank PETSc sets ICNTL(7) = 7 when it initialises the
// MUMPS instance, after what MatMumpsSetIcntl gave the factor before it, and before it reads the
// options.
using SymbolicFn = PetscErrorCode (*)(Mat, Mat, IS, IS, const MatFactorInfo *);

static PetscErrorCode SymbolicWithOrdering(BoltnetAssembly a, SymbolicFn symbolic, Mat F, Mat A, IS row, IS col, const MatFactorInfo *info, PetscInt ordering)
{
  const std::string name = "-" + a->prefix + "mat_mumps_icntl_7";
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsSetValue(nullptr, name.c_str(), std::to_string(ordering).c_str()));
  const PetscErrorCode ierr = symbolic(F, A, row, col, info);
  PetscCall(PetscOptionsClearValue(nullptr, name.c_str())); // also when the analysis failed
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

static PetscErrorCode ChooseOrdering(BoltnetAssembly a, Mat F, Mat A, IS row, IS col, const MatFactorInfo *info)
{
  PetscFunctionBeginUser;
  if (a->isolve.ordering >= 0) PetscFunctionReturn(0);
  const PetscInt  candidates[] = {7, 6, 2}; // MUMPS's own choice first, QAMD, AMF
  const PetscReal gain         = 0.9;       // another ordering only where it is estimated this much of MUMPS's own choice, or less
  PetscReal       best = PETSC_MAX_REAL, own = PETSC_MAX_REAL;
  PetscInt        pick = 7, picked_used = -1;
  for (PetscInt c : candidates) {
    Mat       T;
    PetscInt  info1, used;
    PetscReal flops;
    PetscCall(MatGetFactor(A, MATSOLVERMUMPS, MAT_FACTOR_LU, &T));
    PetscCall(SymbolicWithOrdering(a, MatLUFactorSymbolic, T, A, row, col, info, c));
    PetscCall(MatMumpsGetInfog(T, 1, &info1));
    PetscCall(MatMumpsGetInfog(T, 7, &used)); // the ordering MUMPS used (7: which one it took)
    PetscCall(MatMumpsGetRinfog(T, 1, &flops));
    PetscCall(MatDestroy(&T));
    if (info1 < 0) continue; // F's own analysis reports what fails
    PetscCall(PetscInfo(F, "ICNTL(7) = %" PetscInt_FMT " (MUMPS used %" PetscInt_FMT "): the factorisation estimated at %g flops\n", c, used, (double)flops));
    if (c == 7) own = flops;
    if (c == 7 ? flops < best : flops < best && flops <= gain * own) {
      best        = flops;
      pick        = c;
      picked_used = used;
    }
  }
  a->isolve.ordering = pick;
  PetscCall(PetscInfo(F, "the interface's ordering: ICNTL(7) = %" PetscInt_FMT " (MUMPS's ordering %" PetscInt_FMT ", %g flops)\n", pick, picked_used, (double)best));
  PetscFunctionReturn(0);
}

// MUMPS's symbolic factorisation, preceded by the choice of its ordering and followed by the two
// choices above (factors on disk, and the automatic interface solve): F's own symbolic operation,
// wrapped (MatSetOperation) so that every analysis PCSetUp makes, the first and any after a change
// of nonzero pattern, is followed by the choices before its numeric factorisation.
struct AnalysisChoice {
  SymbolicFn      symbolic;
  BoltnetAssembly a;
};

static PetscErrorCode SymbolicThenChoose(Mat F, Mat A, IS row, IS col, const MatFactorInfo *info)
{
  PetscContainer container;
  AnalysisChoice *choice;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectQuery((PetscObject)F, "boltnet_analysis_choice", (PetscObject *)&container));
  PetscCall(PetscContainerGetPointer(container, (void **)&choice));
  if (choice->a->isolve.choose_ordering) {
    PetscCall(ChooseOrdering(choice->a, F, A, row, col, info));
    PetscCall(SymbolicWithOrdering(choice->a, choice->symbolic, F, A, row, col, info, choice->a->isolve.ordering));
  } else PetscCall(choice->symbolic(F, A, row, col, info));
  if (choice->a->isolve.out_of_core && !choice->a->isolve.factors_on_disk) PetscCall(ChooseFactorStorage(choice->a, F));
  if (choice->a->isolve.solve_auto) PetscCall(ChooseInterfaceSolve(choice->a, F));
  PetscFunctionReturn(0);
}

static PetscErrorCode WrapSymbolic(BoltnetAssembly a, Mat F)
{
  PetscContainer container;
  AnalysisChoice *choice;
  void (*symbolic)(void);
  PetscFunctionBeginUser;
  PetscCall(PetscObjectQuery((PetscObject)F, "boltnet_analysis_choice", (PetscObject *)&container));
  if (container) PetscFunctionReturn(0); // this factor's analysis is wrapped already
  PetscCall(MatGetOperation(F, MATOP_LUFACTOR_SYMBOLIC, &symbolic));
  PetscCheck(symbolic, a->comm, PETSC_ERR_PLIB, "MUMPS's factor has no symbolic LU factorisation");
  PetscCall(PetscNew(&choice));
  choice->a        = a;
  choice->symbolic = (SymbolicFn)symbolic;
  PetscCall(PetscContainerCreate(a->comm, &container));
  PetscCall(PetscContainerSetPointer(container, choice));
  PetscCall(PetscContainerSetUserDestroy(container, PetscContainerUserDestroyDefault));
  PetscCall(PetscObjectCompose((PetscObject)F, "boltnet_analysis_choice", (PetscObject)container));
  PetscCall(PetscContainerDestroy(&container));
  PetscCall(MatSetOperation(F, MATOP_LUFACTOR_SYMBOLIC, (void (*)(void))SymbolicThenChoose));
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblySetUpNullPivots(BoltnetAssembly a)
{
  KSP       ksp;
  PC        pc;
  PetscBool mumps;
  Mat       F;
  PetscFunctionBeginUser;
  PetscCall(MumpsLU(a, &ksp, &pc, &mumps));
  if (!mumps) PetscFunctionReturn(0);
  PetscCall(KSPSetOperators(ksp, a->J, a->J));
  PetscCall(PCFactorSetUpMatSolverType(pc));
  PetscCall(PCFactorGetMatrix(pc, &F));
  // Set before the first factorisation; -mat_mumps_icntl_24 / -mat_mumps_cntl_3 still override them.
  // The scaling stays MUMPS's automatic choice (ICNTL(8) = 77): the diagonal one was a quarter
  // cheaper per factorisation on plate-grid, but its solutions of the medium junction stopped above
  // the round-off floor of the step's convergence test (docs/solver.md, "What a factorisation of the
  // interface costs").
  PetscCall(MatMumpsSetIcntl(F, 24, 1));                   // null pivot row detection
  PetscCall(MatMumpsSetCntl(F, 3, a->checks.null_pivot_threshold)); // null below this x ||A_pre|| (CNTL(3) > 0: relative)
  if (a->isolve.factors_on_disk) PetscCall(MatMumpsSetIcntl(F, 22, 1)); // out-of-core factors (MUMPS_OOC_TMPDIR)
  // After MUMPS's analysis: out of core if the factors will not fit, and the automatic choice of
  // the interface solve.
  if ((a->isolve.out_of_core && !a->isolve.factors_on_disk) || a->isolve.solve_auto || a->isolve.choose_ordering) PetscCall(WrapSymbolic(a, F));
  PetscFunctionReturn(0);
}

// Factors kept on disk by the user's own -mat_mumps_icntl_22 1 count as on disk too: summary.json
// says so, and a failure is not retried out of core nor told to go there.
static PetscErrorCode NoteFactorsOnDisk(BoltnetAssembly a, Mat F)
{
  PetscInt icntl22;
  PetscFunctionBeginUser;
  PetscCall(MatMumpsGetIcntl(F, 22, &icntl22));
  if (icntl22 == 1) a->isolve.factors_on_disk = PETSC_TRUE;
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyCheckNullPivots(BoltnetAssembly a, PetscInt *nnull)
{
  KSP       ksp;
  PC        pc;
  PetscBool mumps;
  Mat       F;
  PetscInt  icntl24;
  PetscFunctionBeginUser;
  *nnull = 0;
  PetscCall(MumpsLU(a, &ksp, &pc, &mumps));
  if (!mumps) PetscFunctionReturn(0);
  PetscCall(PCFactorGetMatrix(pc, &F));
  MatFactorType ftype;
  PetscCall(MatGetFactorType(F, &ftype));
  if (ftype == MAT_FACTOR_NONE) PetscFunctionReturn(0);
  PetscCall(NoteFactorsOnDisk(a, F));
  PetscCall(MatMumpsGetIcntl(F, 24, &icntl24));
  if (icntl24 != 1) PetscFunctionReturn(0);
  PetscCall(MatMumpsGetInfog(F, 28, nnull)); // INFOG(28): null pivots found by the last factorisation
  if (!*nnull) PetscFunctionReturn(0);
  Vec         z;
  PetscBool   found = PETSC_FALSE;
  std::string mech;
  PetscCall(MatCreateVecs(a->J, &z, nullptr));
  PetscCall(NullVector(a, z, &found));
  if (found) PetscCall(DescribeMechanism(a, z, mech));
  PetscCall(VecDestroy(&z));
  std::ostringstream m;
  m << "the Jacobian is singular: " << *nnull << " null pivot" << (*nnull > 1 ? "s" : "") << " (MUMPS INFOG(28), pivots below " << a->checks.null_pivot_threshold
    << " of the matrix norm, -load_null_pivot_threshold), a mechanism of the structure in its current joint states";
  if (!mech.empty()) m << ": " << mech;
  a->checks.singular = m.str();
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyFactorError(BoltnetAssembly a, std::string &why, std::string &advice, PetscBool *memory)
{
  KSP           ksp;
  PC            pc;
  PetscBool     mumps;
  Mat           F;
  MatFactorType ftype;
  PetscInt      info1, info2, N;
  PetscFunctionBeginUser;
  why.clear();
  advice.clear();
  *memory = PETSC_FALSE;
  PetscCall(MumpsLU(a, &ksp, &pc, &mumps));
  if (!mumps) PetscFunctionReturn(0);
  PetscCall(PCFactorGetMatrix(pc, &F));
  PetscCall(MatGetFactorType(F, &ftype));
  if (ftype == MAT_FACTOR_NONE) PetscFunctionReturn(0);
  PetscCall(NoteFactorsOnDisk(a, F));
  PetscCall(MatMumpsGetInfog(F, 1, &info1));
  PetscCall(MatMumpsGetInfog(F, 2, &info2));
  // -10 is a numerically singular matrix: a mechanism of the joints' states, which a smaller step
  // may avoid (AssemblyCheckNullPivots names it). Every other error is the matrix's size or
  // MUMPS's resources, the same at any load.
  if (info1 >= 0 || info1 == -10) PetscFunctionReturn(0);
  *memory = info1 == -13 || info1 == -19 ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(MatGetSize(a->J, &N, nullptr));
  std::ostringstream m, d;
  m.precision(3);
  m << "MUMPS could not factor the " << N << "-dof Jacobian" << (a->isolve.factors_on_disk ? " with its factors on disk" : "") << " (INFOG(1) = " << info1 << ", INFOG(2) = " << info2 << "): ";
  switch (info1) {
  case -13: {
    // INFOG(2): the allocation that failed, in reals, or in millions of reals when negative (MUMPS
    // users' guide, "Error diagnostics").
    const double bytes = (info2 < 0 ? -1e6 * (double)info2 : (double)info2) * sizeof(PetscScalar);
    m << "out of memory, an allocation of " << bytes / 1e9 << " GB failed";
    d << "A smaller load step does not change that; run on more ranks (MUMPS distributes its factors) or condense more patches onto their ports (-patch_condense_ratio)";
    if (!a->isolve.factors_on_disk) d << ", or keep the factors on disk (" << (a->isolve.storage_given ? "-mat_mumps_icntl_22 1" : "-interface_out_of_core") << ")";
    break;
  }
  case -19:
    m << "-mat_mumps_icntl_23 caps MUMPS's working memory per rank below what the factorisation needs";
    d << "Raise or remove the cap";
    if (!a->isolve.factors_on_disk) d << ", or keep the factors on disk (" << (a->isolve.storage_given ? "-mat_mumps_icntl_22 1" : "-interface_out_of_core") << ")";
    break;
  case -8: case -9: case -11: case -12: case -14: case -15: case -17: case -20:
    m << "MUMPS's estimate of its workspace was short";
    d << "Raise -mat_mumps_icntl_14 (the extra workspace, in percent)";
    break;
  default: m << "a MUMPS error"; d << "See the MUMPS users' guide, \"Error diagnostics\"";
  }
  why    = m.str();
  advice = d.str();
  PetscFunctionReturn(0);
}

} // namespace boltnet
