// Quasi-static load stepping: SNES per step, history committed only after convergence,
// automatic cut-back with a bounded number of halvings.
#include "core/check.hpp"
#include "core/log.hpp"
#include "core/guard.hpp"
#include "core/handle.hpp"
#include "io/limits.hpp"
#include "network/assembly.hpp"
#include "solver/loadpath.hpp"
#include "solver/progress.hpp"

#include <petsc/private/snesimpl.h> // KSPPreSolve_SNESEW, KSPPostSolve_SNESEW: SNES's own KSP hooks
#include <petsctime.h>

#include <cmath>
#include <sstream>

namespace boltnet {
namespace {
PetscErrorCode ConvergedInBalance(SNES, PetscInt, PetscReal, PetscReal, PetscReal, SNESConvergedReason *, void *);
PetscErrorCode AtFloorInBalance(BoltnetAssembly, Vec, Vec, PetscReal, PetscBool *);
PetscErrorCode RoundOffBound(BoltnetAssembly, Vec, Vec, Vec);
}

// Eisenstat-Walker's tolerances (SNESKSPSetUseEW) for the lagged solve's FGMRES, unless the command
// line gives -snes_ksp_ew or -ksp_rtol. Each FGMRES iteration is a triangular solve with the factors,
// and far from the solution a Newton step needs no solve to 1e-10: the forcing term follows the
// residual's own decrease (docs/solver.md, "Inexact Newton"). Set from the first Newton iteration
// on whenever the solve may be lagged, so that the forcing term of the first FGMRES solve already
// has the residual it follows; AssemblyDropDefaultEW takes it back where the solve is direct.
PetscErrorCode AssemblyDefaultEW(BoltnetAssembly a)
{
  const char *prefix;
  PetscBool   ew_given, rtol_given, ksp_given;
  KSP         ksp;
  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(a->snes, &ksp));
  if (a->isolve.ew_default) { // already on: the lagged KSP has just been given its own tolerance
    PetscCall(KSPGetTolerances(ksp, &a->isolve.rtol_before_ew, nullptr, nullptr, nullptr));
    PetscFunctionReturn(0);
  }
  PetscCall(SNESGetOptionsPrefix(a->snes, &prefix));
  PetscCall(PetscOptionsHasName(nullptr, prefix, "-snes_ksp_ew", &ew_given));
  PetscCall(PetscOptionsHasName(nullptr, prefix, "-ksp_rtol", &rtol_given));
  PetscCall(PetscOptionsHasName(nullptr, prefix, "-ksp_type", &ksp_given));
  // With the user's own Krylov method auto stays direct (solver/equilibrium.cpp): that KSP keeps
  // its tolerance.
  if (ew_given || rtol_given || (ksp_given && !a->isolve.lagged)) PetscFunctionReturn(0);
  PetscCall(KSPGetTolerances(ksp, &a->isolve.rtol_before_ew, nullptr, nullptr, nullptr));
  PetscCall(SNESKSPSetUseEW(a->snes, PETSC_TRUE));
  // PETSc's parameters but the largest forcing term, 0.5 instead of 0.9: a direction that leaves
  // 90 % of the residual to GMRES is no descent direction for the line search once joints change
  // state (fig3a lagged: a step cut back at 0.9, none at 0.5); -snes_ksp_ew_rtolmax still decides.
  PetscCall(SNESKSPSetParametersEW(a->snes, PETSC_DEFAULT, PETSC_DEFAULT, a->isolve.ew_rtol_max, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
  a->isolve.ew_default = PETSC_TRUE;
  PetscFunctionReturn(0);
}

// Eisenstat-Walker set a tolerance at each solve's start: the KSP gets its own back.
PetscErrorCode AssemblyDropDefaultEW(BoltnetAssembly a)
{
  KSP ksp;
  PetscFunctionBeginUser;
  if (!a->isolve.ew_default) PetscFunctionReturn(0);
  PetscCall(SNESKSPSetUseEW(a->snes, PETSC_FALSE));
  PetscCall(SNESGetKSP(a->snes, &ksp));
  PetscCall(KSPSetTolerances(ksp, a->isolve.rtol_before_ew, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
  a->isolve.ew_default = PETSC_FALSE;
  PetscFunctionReturn(0);
}

// The lagged solve's Krylov method: flexible GMRES (KSPFGMRES), right preconditioned as it must be,
// so that it watches the true residual of J, to Eisenstat-Walker's tolerances by default (above),
// else to 1e-10 of it unless -ksp_rtol says otherwise. Flexible, although the preconditioner (the
// kept factors) does not change within a solve, because it keeps the preconditioned directions and
// builds the solution from them: right-preconditioned GMRES keeps only the Krylov basis and
// applies the preconditioner once more at the end of each solve (KSPGMRESBuildSoln), a triangular
// solve that reads all the factors for no new direction. With about three iterations per solve
// that extra solve is a quarter of them (the medium junction: 347 triangular solves with GMRES,
// 264 with FGMRES, the same 83 solves and 264 iterations; docs/solver.md), for one more vector per
// iteration. Called at set-up, or by the automatic choice before the Newton iteration after MUMPS's
// first analysis (a KSP's type cannot change inside its own solve).
PetscErrorCode AssemblyUseLaggedKSP(BoltnetAssembly a)
{
  KSP ksp;
  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(a->snes, &ksp));
  PetscCall(KSPSetType(ksp, KSPFGMRES));
  PetscCall(KSPSetPCSide(ksp, PC_RIGHT));
  PetscCall(KSPGMRESSetRestart(ksp, 100));
  PetscCall(KSPSetTolerances(ksp, 1e-10, 0.0, PETSC_DEFAULT, 100));
  PetscCall(AssemblyDefaultEW(a));
  a->isolve.lagged_ksp = PETSC_TRUE;
  PetscFunctionReturn(0);
}

// The direct solve's KSP again, for a lagged solve that the automatic choice made in core and whose
// factors then had to go to disk (a factorisation that ran out of memory), where auto's rule for
// factors on disk chooses direct (AutoTakesLagged; docs/solver.md, "Which one the default takes").
// SNES's lag of the preconditioner goes back to 1: refactor whenever J changes.
PetscErrorCode AssemblyUseDirectKSP(BoltnetAssembly a)
{
  KSP ksp;
  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(a->snes, &ksp));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(SNESSetLagPreconditioner(a->snes, 1));
  PetscCall(AssemblyDropDefaultEW(a));
  a->isolve.lagged = a->isolve.lagged_ksp = a->isolve.lagged_auto = PETSC_FALSE;
  a->isolve.factorisations = 0;
  PetscFunctionReturn(0);
}

// BDDC's fields (-interface_matis): the six dof of a node as six fields, in the subdomain's local
// numbering, which is what BDDC takes from the local matrix's block size when it has nothing else.
// Given, because otherwise it asks the SNES's DM for a field decomposition, which DMNetwork does not
// have. No-op for any other PC.
static PetscErrorCode SetBDDCFields(BoltnetAssembly a, PC pc)
{
  IS fields[6];
  PetscFunctionBeginUser;
  if (!a->isolve.P) PetscFunctionReturn(0);
  const PetscInt nodes = (PetscInt)a->isolve.subdomain_nodes.size();
  // On the PC's communicator, with local sizes, as PCBDDCSetDofsSplittingLocal checks.
  for (PetscInt f = 0; f < 6; ++f) PetscCall(ISCreateStride(PetscObjectComm((PetscObject)pc), nodes, f, 6, &fields[f]));
  PetscCall(PCBDDCSetDofsSplittingLocal(pc, 6, fields));
  for (PetscInt f = 0; f < 6; ++f) PetscCall(ISDestroy(&fields[f]));
  PetscFunctionReturn(0);
}

// A fresh preconditioner for the next solve. PCReset for a factorisation: a failed one leaves
// MUMPS in an error state that the next solve would raise. BDDC is made anew instead (its type
// set again, its options read again, its fields given again): in PETSc 3.18.5 a PCSetUp after
// PCReset on PCBDDC crashes in PCBDDCGraphInit.
PetscErrorCode AssemblyResetPC(BoltnetAssembly a)
{
  KSP       ksp;
  PC        pc;
  PetscBool bddc;
  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(a->snes, &ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCBDDC, &bddc));
  if (!bddc) {
    PetscCall(PCReset(pc));
    PetscFunctionReturn(0);
  }
  PetscCall(PCSetType(pc, PCNONE));
  PetscCall(PCSetType(pc, PCBDDC));
  PetscCall(PCSetFromOptions(pc));
  PetscCall(SetBDDCFields(a, pc));
  PetscFunctionReturn(0);
}

// The interface solve of a Newton iteration as one event (BoltnetInterfaceSolve): KSPSolve calls
// the pre-solve hook before KSPSetUp, so the factorisation (PCSetUp) is inside it, and the
// post-solve hook once the Krylov method (or the triangular solves alone) has returned. KSP holds
// one pair of hooks, and SNESGetKSP has already given it SNES's own: KSPPreSolve_SNESEW and
// KSPPostSolve_SNESEW, where -snes_ksp_ew (Eisenstat-Walker) sets each solve's tolerance and
// measures it. These hooks take their place, so they call them (with the assembly's SNES); without
// it -snes_ksp_ew would silently do nothing. The assembly records that the event is open, for
// SolveInStage below.
static PetscErrorCode BeginInterfaceSolve(KSP ksp, Vec b, Vec x, void *ctx)
{
  BoltnetAssembly a = static_cast<BoltnetAssembly>(ctx);
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Events().interface_solve, 0, 0, 0, 0));
  a->isolve.in_event = PETSC_TRUE;
  PetscCall(KSPPreSolve_SNESEW(ksp, b, x, a->snes));
  PetscFunctionReturn(0);
}

static PetscErrorCode EndInterfaceSolve(KSP ksp, Vec b, Vec x, void *ctx)
{
  BoltnetAssembly a = static_cast<BoltnetAssembly>(ctx);
  PetscFunctionBeginUser;
  PetscCall(KSPPostSolve_SNESEW(ksp, b, x, a->snes));
  a->isolve.in_event = PETSC_FALSE;
  PetscCall(PetscLogEventEnd(Events().interface_solve, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

// SNESSolve in the Boltnet Solve stage. A hard error inside it (a factorisation PETSc cannot start,
// such as an unknown -pc_factor_mat_solver_type) returns from PCSetUp before KSP's post-solve hook
// and leaves BoltnetInterfaceSolve begun; PetscLogView lists no event still begun, so -log_view of
// the failed run would not show the interface solve at all. The event is ended here (whether or not
// a log is kept: PetscLogEventEnd does nothing without one) and the stage popped before the error
// goes on. PETSc's own events (SNESSolve, KSPSolve, PCSetUp) stay begun, as PETSc leaves them.
static PetscErrorCode SolveInStage(BoltnetAssembly a, Vec X)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogStagePush(Events().solve_stage));
  a->isolve.in_event         = PETSC_FALSE;
  const PetscErrorCode ierr = SNESSolve(a->snes, nullptr, X);
  if (ierr && a->isolve.in_event) {
    a->isolve.in_event = PETSC_FALSE;
    PetscCall(PetscLogEventEnd(Events().interface_solve, 0, 0, 0, 0));
  }
  PetscCall(PetscLogStagePop());
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblySetUpSolver(BoltnetAssembly a)
{
  SNESLineSearch ls;
  KSP            ksp;
  PC             pc;
  PetscFunctionBeginUser;
  const char *isolves[] = {"auto", "direct", "lagged"};
  PetscInt    isolve    = a->isolve.solve_auto ? 0 : a->isolve.lagged ? 2 : 1;
  PetscOptionsBegin(a->comm, a->prefix.c_str(), "boltnet interface solve", "boltnet");
  PetscCall(PetscOptionsEList("-interface_solve", "The linear solve of each Newton iteration: direct (the Jacobian factored whenever it changes), lagged (flexible GMRES preconditioned by the factorisation of an earlier Jacobian, refactored when it needs more than -interface_refactor_its iterations; to Eisenstat-Walker's tolerances unless -snes_ksp_ew or -ksp_rtol is given) or auto (lagged where MUMPS's analysis of the first Jacobian estimates a factorisation dear against a triangular solve: -interface_lagged_flops_per_entry, with the factors on disk -interface_lagged_flops_per_entry_on_disk; else direct): docs/solver.md", "AssemblySetUpSolver", isolves, 3, isolves[isolve], &isolve, nullptr));
  PetscCall(PetscOptionsReal("-interface_lagged_flops_per_entry", "-interface_solve auto: the lagged solve when MUMPS's analysis estimates at least this many flops for the factorisation (RINFOG(1)) per entry of the factors (INFOG(20)), a triangular solve's cost, with the factors in memory", "AssemblySetUpSolver", a->isolve.lagged_flops_per_entry, &a->isolve.lagged_flops_per_entry, nullptr));
  PetscCall(PetscOptionsReal("-interface_lagged_flops_per_entry_on_disk", "-interface_solve auto with the factors on disk (each triangular solve reads them back): the lagged solve when MUMPS estimates at least this many flops per entry of the factors and the Krylov solve stops at Eisenstat-Walker's tolerances", "AssemblySetUpSolver", a->isolve.lagged_flops_per_entry_on_disk, &a->isolve.lagged_flops_per_entry_on_disk, nullptr));
  PetscCall(PetscOptionsBool("-interface_out_of_core", "Keep the factors on disk (MUMPS ICNTL(22) = 1, in the directory MUMPS_OOC_TMPDIR names) when MUMPS's analysis estimates more memory for them in core than a node has (-interface_memory_mb), or when a factorisation runs out of memory (INFOG(1) = -13, or -19 under -mat_mumps_icntl_23; it is factored again on disk); false keeps them in memory and stops on such a failure: docs/solver.md", "AssemblySetUpSolver", a->isolve.out_of_core, &a->isolve.out_of_core, nullptr));
  PetscCall(PetscOptionsReal("-interface_memory_mb", "Memory in MB that the factorisation may take on each node, against MUMPS's in-core estimate summed over the node's ranks (0: what the node has available, /proc/meminfo's MemAvailable within the process's cgroup limit)", "AssemblySetUpSolver", a->isolve.memory_mb, &a->isolve.memory_mb, nullptr));
  PetscCall(PetscOptionsInt("-interface_refactor_its", "Lagged interface solve: refactor the preconditioner when the last Krylov solve took more than this many iterations or failed", "AssemblySetUpSolver", a->isolve.refactor_its, &a->isolve.refactor_its, nullptr));
  PetscCall(PetscOptionsBool("-interface_choose_ordering", "At MUMPS's first analysis of the Jacobian, analyse it also with the QAMD and AMF orderings and factor with the ordering whose factorisation MUMPS estimates cheapest (RINFOG(1)); false: MUMPS's own choice (ICNTL(7) = 7); -mat_mumps_icntl_7 decides alone: docs/solver.md", "AssemblySetUpSolver", a->isolve.choose_ordering, &a->isolve.choose_ordering, nullptr));
  PetscCall(PetscOptionsReal("-interface_keep_ratio", "Direct interface solve: keep the Jacobian and its factorisation from an earlier Newton iterate while the residual falls by at least this factor per iteration and no joint changes state (modified Newton; 0: refactor at every iteration): docs/solver.md", "AssemblySetUpSolver", a->isolve.keep_ratio, &a->isolve.keep_ratio, nullptr));
  PetscOptionsEnd();
  PetscCheck(a->isolve.keep_ratio >= 0 && a->isolve.keep_ratio < 1, a->comm, PETSC_ERR_USER_INPUT, "-interface_keep_ratio %g must be in [0, 1): the factor by which the residual must fall per iteration for the factorisation to be kept (0: never kept)", (double)a->isolve.keep_ratio);
  PetscCheck(a->isolve.refactor_its >= 1, a->comm, PETSC_ERR_USER_INPUT, "-interface_refactor_its %" PetscInt_FMT " must be >= 1", a->isolve.refactor_its);
  PetscCheck(a->isolve.lagged_flops_per_entry > 0, a->comm, PETSC_ERR_USER_INPUT, "-interface_lagged_flops_per_entry %g must be > 0", (double)a->isolve.lagged_flops_per_entry);
  PetscCheck(a->isolve.lagged_flops_per_entry_on_disk > 0, a->comm, PETSC_ERR_USER_INPUT, "-interface_lagged_flops_per_entry_on_disk %g must be > 0", (double)a->isolve.lagged_flops_per_entry_on_disk);
  PetscCall(PetscOptionsHasName(nullptr, a->prefix.empty() ? nullptr : a->prefix.c_str(), "-mat_mumps_icntl_22", &a->isolve.storage_given));
  if (a->isolve.storage_given) a->isolve.out_of_core = PETSC_FALSE;
  PetscBool ordering_given;
  PetscCall(PetscOptionsHasName(nullptr, a->prefix.empty() ? nullptr : a->prefix.c_str(), "-mat_mumps_icntl_7", &ordering_given));
  if (ordering_given) a->isolve.choose_ordering = PETSC_FALSE;
  PetscCheck(a->isolve.memory_mb >= 0, a->comm, PETSC_ERR_USER_INPUT, "-interface_memory_mb %g must be >= 0 (0: what the node has available)", (double)a->isolve.memory_mb);
  // -interface_matis: GMRES with BDDC at every Jacobian; neither MUMPS's analysis (auto) nor a
  // kept factorisation (lagged) applies.
  PetscCheck(!a->opt.matis || isolve != 2, a->comm, PETSC_ERR_USER_INPUT, "-interface_solve lagged keeps a factorisation of J; with -interface_matis the preconditioner is BDDC: give -interface_solve direct or auto");
  a->isolve.solve_auto = isolve == 0 && !a->opt.matis ? PETSC_TRUE : PETSC_FALSE;
  a->isolve.lagged     = isolve == 2 ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(SNESCreate(a->comm, &a->snes));
  if (!a->prefix.empty()) PetscCall(SNESSetOptionsPrefix(a->snes, a->prefix.c_str()));
  PetscCall(SNESSetDM(a->snes, a->net.dm));
  PetscCall(SNESSetFunction(a->snes, nullptr, AssemblyFormFunction, a));
  // Both solves precondition with a factorisation of J itself: the lagged one keeps an earlier
  // one in the PC (AssemblyLaggedFactorisation) instead of factoring a copy of J.
  PetscCall(SNESSetJacobian(a->snes, a->J, a->isolve.P ? a->isolve.P : a->J, AssemblyFormJacobian, a));
  PetscCall(SNESMonitorSet(a->snes, MonitorJointStates, a, nullptr));
  // Defaults that the command line overrides: Newton with boltnet's line search, direct solve.
  PetscCall(SNESSetType(a->snes, SNESNEWTONLS));
  PetscCall(SNESGetLineSearch(a->snes, &ls));
  PetscCall(SNESLineSearchSetType(ls, SNESLINESEARCHBOLTNET));
  PetscCall(SNESSetTolerances(a->snes, PETSC_DEFAULT, 1e-10, 0.0, 50, PETSC_DEFAULT));
  PetscCall(SNESGetKSP(a->snes, &ksp));
  if (a->isolve.lagged) PetscCall(AssemblyUseLaggedKSP(a));
  else PetscCall(KSPSetType(ksp, KSPPREONLY));
  if (a->isolve.solve_auto) PetscCall(AssemblyDefaultEW(a)); // until MUMPS's first analysis chooses
  PetscCall(KSPSetPreSolve(ksp, BeginInterfaceSolve, a));
  PetscCall(KSPSetPostSolve(ksp, EndInterfaceSolve, a));
  PetscCall(KSPGetPC(ksp, &pc));
  if (a->isolve.P) {
    // BDDC on J's MATIS (docs/solver.md, "BDDC"): GMRES, right preconditioned so that it watches
    // the true residual, to the lagged solve's 1e-10 (J is not symmetric: exact footprint coupling).
    PetscCall(KSPSetType(ksp, KSPGMRES));
    PetscCall(KSPSetPCSide(ksp, PC_RIGHT));
    PetscCall(KSPGMRESSetRestart(ksp, 200));
    PetscCall(KSPSetTolerances(ksp, 1e-10, 0.0, PETSC_DEFAULT, 400));
    PetscCall(PCSetType(pc, PCBDDC));
    PetscCall(SetBDDCFields(a, pc));
    // J is not symmetric, and BDDC computes its primal basis functions as for a symmetric matrix
    // unless -pc_bddc_symmetric false says otherwise (PETSc 3.18 has no function for it, and does
    // not read MAT_SYMMETRIC): with MUMPS as the Neumann solver, GMRES then stalls near its initial
    // residual where patches are cut across ranks. So false, unless the command line gives it.
    PetscBool   given;
    std::string name = "-" + a->prefix + "pc_bddc_symmetric";
    PetscCall(PetscOptionsHasName(nullptr, a->prefix.empty() ? nullptr : a->prefix.c_str(), "-pc_bddc_symmetric", &given));
    if (!given) {
      PetscCall(PetscOptionsSetValue(nullptr, name.c_str(), "false"));
      a->isolve.bddc_option = name; // cleared again with the assembly
    }
  } else {
    PetscCall(PCSetType(pc, PCLU));
    PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  }
  PetscCall(SNESSetConvergenceTest(a->snes, ConvergedInBalance, a, nullptr));
  PetscCall(SNESSetFromOptions(a->snes));
  PetscOptionsBegin(a->comm, a->prefix.c_str(), "boltnet convergence checks", "boltnet");
  PetscCall(PetscOptionsReal("-load_equilibrium_rtol", "A converged step must balance: out-of-balance force (2-norm over the free dof) at most this fraction of the force scale (the largest of the applied loads, the reactions and the joint forces); else the step is cut back", "BoltnetAssemblySolveLoadPath", a->checks.equilibrium_rtol, &a->checks.equilibrium_rtol, nullptr));
  PetscCall(PetscOptionsReal("-load_null_pivot_threshold", "With MUMPS: pivots below this fraction of the matrix norm are null (CNTL(3)); a Jacobian with null pivots (a mechanism) fails the solve, and the message names its patches, dof and joints", "BoltnetAssemblySolveLoadPath", a->checks.null_pivot_threshold, &a->checks.null_pivot_threshold, nullptr));
  PetscOptionsEnd();
  PetscCheck(a->checks.equilibrium_rtol > 0 && a->checks.equilibrium_rtol < 1, a->comm, PETSC_ERR_USER_INPUT, "-load_equilibrium_rtol %g must lie in (0, 1)", (double)a->checks.equilibrium_rtol);
  PetscCheck(a->checks.null_pivot_threshold > 0 && a->checks.null_pivot_threshold < 1, a->comm, PETSC_ERR_USER_INPUT, "-load_null_pivot_threshold %g must lie in (0, 1)", (double)a->checks.null_pivot_threshold);
  { // -pc_type fieldsplit: boltnet's splits, before PCSetUp (docs/solver.md, "Algebraic multigrid")
    PetscBool fs;
    PetscCall(SNESGetKSP(a->snes, &ksp));
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCFIELDSPLIT, &fs));
    if (fs && a->opt.slave_split) PetscCall(AssemblySetSlaveSplit(a, pc));
  }
  PetscCall(AssemblySetUpNullPivots(a));
  // SNESSetFromOptions may have changed the SNES type (-snes_type ksponly, say), which destroys the
  // line search fetched above and gives the SNES a new one: fetch it again.
  PetscCall(SNESGetLineSearch(a->snes, &ls));
  PetscCall(SNESLineSearchBoltnetSetStateChangeFunction(ls, AssemblyCountStateChanges, a));
  PetscCall(PetscOptionsHasName(nullptr, a->prefix.empty() ? nullptr : a->prefix.c_str(), "-snes_atol", &a->checks.user_atol));
  PetscCall(SNESGetForceIteration(a->snes, &a->checks.user_force)); // -snes_force_iteration; a predicted step forces its own
  PetscCall(SNESGetMaxNonlinearStepFailures(a->snes, &a->checks.user_max_fail)); // -snes_max_fail; a predicted step may fail once more
  PetscFunctionReturn(0);
}

namespace {

// SNES's default test, with two changes.
// - A factorisation with null pivots (a mechanism: AssemblyCheckNullPivots) fails the solve as a
//   linear solve failure, whatever ||F|| does: its Newton step is meaningless.
// - Converged at the round-off of evaluating F, but only in balance: row i of K u is a sum of terms
//   |J_ij x_j| computed with relative error about machine epsilon, so below 100 eps (|J| |x|)_i its
//   residual cannot decrease any more (stiff patch couplings reach that floor before -snes_rtol).
//   That floor grows with the stiffness in the row, whatever the forces: with kn = 1e18 a global
//   100 eps ||J|| ||x|| accepted a 4.6 % error. So it stops a solve only where every row is at its
//   floor and the out-of-balance force is also below -load_equilibrium_rtol of the problem's own
//   force scale (AssemblyEquilibrium); elsewhere the solve goes on, and fails (and is cut back) if it
//   cannot get there.
PetscErrorCode ConvergedInBalanceImpl(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm, PetscReal fnorm, SNESConvergedReason *reason, void *ctx)
{
  BoltnetAssembly a = static_cast<BoltnetAssembly>(ctx);
  PetscFunctionBeginUser;
  PetscCall(SNESConvergedDefault(snes, it, xnorm, snorm, fnorm, reason, nullptr));
  if (it > 0) {
    PetscInt nnull;
    PetscCall(AssemblyCheckNullPivots(a, &nnull));
    if (nnull) {
      PetscCall(PetscInfo(snes, "Null pivots in the factorisation: %s\n", a->checks.singular.c_str()));
      *reason = SNES_DIVERGED_LINEAR_SOLVE;
      PetscFunctionReturn(0);
    }
  }
  if (*reason != SNES_CONVERGED_ITERATING || it == 0) PetscFunctionReturn(0);
  Vec       X, F;
  PetscBool floor;
  PetscCall(SNESGetSolution(snes, &X));
  PetscCall(SNESGetFunction(snes, &F, nullptr, nullptr));
  PetscCall(AtFloorInBalance(a, X, F, fnorm, &floor));
  if (floor) *reason = SNES_CONVERGED_FNORM_ABS;
  PetscFunctionReturn(0);
}

// The scale of each row's round-off (the comment in AtFloorInBalance): b_i = (|J| |x|)_i, or
// (|J| |x| + |J| z)_i where (|J| |x|)_i is itself at the round-off of the solution's size. w is
// work space of X's layout.
PetscErrorCode RoundOffBound(BoltnetAssembly a, Vec X, Vec w, Vec b)
{
  PetscInt           n, N, rstart;
  PetscReal          loc[2] = {0, 0}, big[2];
  const PetscScalar *x;
  PetscScalar       *z;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(X, &n));
  PetscCall(VecGetSize(X, &N));
  PetscCall(VecGetOwnershipRange(X, &rstart, nullptr));
  // The largest translation and rotation: dof 0-2 and 3-5 of a node (J has block size 6, so every
  // rank's rows start at a node: network/jacobian.cpp).
  const auto kind = [rstart](PetscInt i) { return (rstart + i) % 6 < 3 ? 0 : 1; };
  PetscCall(VecGetArrayRead(X, &x));
  for (PetscInt i = 0; i < n; ++i) loc[kind(i)] = std::max(loc[kind(i)], PetscAbsScalar(x[i]));
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscCall(MPIU_Allreduce(loc, big, 2, MPIU_REAL, MPIU_MAX, a->comm));
  PetscCall(VecGetArray(w, &z));
  for (PetscInt i = 0; i < n; ++i) z[i] = big[kind(i)];
  PetscCall(VecRestoreArray(w, &z));
  Vec sized;
  PetscCall(VecDuplicate(X, &sized));
  PetscCall(AbsMultApply(&a->checks.roundoff, a->checks.Jlast, w, sized)); // |J| z
  PetscCall(AbsMultApply(&a->checks.roundoff, a->checks.Jlast, X, b));     // |J| |x|
  const PetscScalar *s;
  PetscScalar       *y;
  PetscCall(VecGetArrayRead(sized, &s));
  PetscCall(VecGetArray(b, &y));
  const PetscReal tiny = 1000.0 * (PetscReal)N * PETSC_MACHINE_EPSILON;
  for (PetscInt i = 0; i < n; ++i)
    if (PetscRealPart(y[i]) <= tiny * PetscRealPart(s[i])) y[i] += s[i];
  PetscCall(VecRestoreArray(b, &y));
  PetscCall(VecRestoreArrayRead(sized, &s));
  PetscCall(VecDestroy(&sized));
  PetscFunctionReturn(0);
}

// The "round-off" half of the test above: every row of F(X) at its floor and the step in balance.
PetscErrorCode AtFloorInBalance(BoltnetAssembly a, Vec X, Vec F, PetscReal fnorm, PetscBool *floor)
{
  Vec       share, bound;
  PetscReal worst;
  SNES      snes = a->snes;
  PetscFunctionBeginUser;
  *floor = PETSC_FALSE;
  if (!a->checks.Jlast) PetscFunctionReturn(0);
  // Row by row: |F_i| <= 100 eps (|J| |x|)_i, the round-off of the terms summed in that row. A row
  // of a soft part is not judged by the stiffest row (a loader spring, a joint's rotational
  // stiffness), nor a translation row by the size of the rotations.
  // A row whose terms all nearly vanish (a dof the load leaves at zero, u_i = 0 up to round-off)
  // cannot be solved to that relative accuracy: a factorisation's solution is accurate relative to
  // the whole solution, not to each of its entries. As in the sparse backward error of Arioli,
  // Demmel and Duff (SIAM J. Matrix Anal. Appl. 10, 1989), such a row is judged by what its terms
  // would be at the size of the solution: (|J| z)_i, z_j the largest |x| of j's kind (translation
  // or rotation, so that neither is measured in the other's units). A row is one of these where
  // (|J| |x|)_i <= 1000 n eps (|J| z)_i, n the number of rows.
  PetscCall(VecDuplicate(X, &share));
  PetscCall(VecDuplicate(X, &bound));
  PetscCall(RoundOffBound(a, X, share, bound));
  PetscCall(VecScale(bound, 100.0 * PETSC_MACHINE_EPSILON));
  PetscCall(VecShift(bound, PETSC_SMALL * PETSC_MACHINE_EPSILON)); // rows with nothing in them
  PetscCall(VecPointwiseDivide(share, F, bound));
  PetscCall(VecAbs(share));
  PetscInt row;
  PetscCall(VecMax(share, &row, &worst)); // the largest |F_i| / bound_i
  if (worst > 1) PetscCall(PetscInfo(snes, "Not at the round-off floor: row %" PetscInt_FMT " has |F_i| %g times its round-off bound\n", row, (double)worst));
  PetscCall(VecDestroy(&share));
  PetscCall(VecDestroy(&bound));
  if (worst <= 1) {
    Equilibrium eq;
    PetscCall(AssemblyEquilibrium(a, X, &eq));
    if (eq.ratio <= a->checks.equilibrium_rtol) {
      PetscCall(PetscInfo(snes, "Converged to round-off: every |F_i| within its round-off bound (||F|| %g), %s\n", (double)fnorm, DescribeEquilibrium(eq).c_str()));
      *floor = PETSC_TRUE;
    } else PetscCall(PetscInfo(snes, "At the round-off floor of every row but not in balance: %s\n", DescribeEquilibrium(eq).c_str()));
  }
  PetscFunctionReturn(0);
}

// The convergence test handed to SNESSetConvergenceTest(): its messages are std::strings.
PetscErrorCode ConvergedInBalance(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm, PetscReal fnorm, SNESConvergedReason *reason, void *ctx)
{
  return Guard("ConvergedInBalance (SNES convergence test)", [&] { return ConvergedInBalanceImpl(snes, it, xnorm, snorm, fnorm, reason, ctx); });
}

// The Newton iterations' linear solves and their Krylov iterations, for summary.json.
PetscErrorCode RecordLinearSolves(BoltnetAssembly a)
{
  PetscInt its, lits;
  PetscFunctionBeginUser;
  PetscCall(SNESGetIterationNumber(a->snes, &its));
  PetscCall(SNESGetLinearSolveIterations(a->snes, &lits));
  a->isolve.linear_solves += its;
  a->isolve.krylov_its += lits;
  PetscFunctionReturn(0);
}

// Absolute tolerance for one step: round-off relative to the forces at play, so that a step whose
// initial residual is already tiny (nothing changes) still converges.
PetscErrorCode SetStepTolerance(BoltnetAssembly a, Vec Xtry)
{
  Vec       F;
  PetscReal r0, fj = 0, fext = 0, loc = 0;
  PetscFunctionBeginUser;
  if (a->checks.user_atol) PetscFunctionReturn(0);
  std::vector<Response> resp;
  PetscCall(AssemblyEvaluateJoints(a, a->X, resp));
  for (const Response &r : resp)
    for (double f : r.force) loc += f * f;
  PetscCall(MPIU_Allreduce(&loc, &fj, 1, MPIU_REAL, MPIU_SUM, a->comm));
  fext = AssemblyAppliedForce(a, a->lambda_target); // every applied force, also those inside condensed patches, and the held ones
  PetscCall(VecDuplicate(Xtry, &F));
  PetscCall(AssemblyFormFunction(a->snes, Xtry, F, a));
  PetscCall(VecNorm(F, NORM_2, &r0));
  PetscCall(VecDestroy(&F));
  // The forces of the problem: the joints', the applied loads, those of the converged steps before;
  // the step's initial residual only when there is none yet (it holds the increment of a prescribed
  // displacement times the stiffness it acts on, which is no force of the solution).
  PetscReal scale = PetscMax(PetscMax(std::sqrt(fj), fext), a->checks.force_scale_seen);
  if (scale == 0) scale = r0;
  PetscCall(SNESSetTolerances(a->snes, scale > 0 ? 1e-12 * scale : 1e-50, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscFunctionReturn(0);
}

// A restart's path must be the one the checkpoint was written on: the same number of targets, and
// the load factor reached where the saved position says it is (the driver also refuses a checkpoint
// whose options differ; this guards the library's callers).
PetscErrorCode CheckResumedPath(BoltnetAssembly a, const std::vector<PetscReal> &targets)
{
  const PathPosition &p = a->path;
  PetscFunctionBeginUser;
  PetscCheck(p.ntargets == (PetscInt)targets.size(), a->comm, PETSC_ERR_USER_INPUT, "The load path has %zu steps, the checkpoint's had %" PetscInt_FMT ": a restart must follow the path of the run that wrote the checkpoint (-load_path, -load_max, -load_table, -load_steps)", targets.size(), p.ntargets);
  PetscCheck(p.target >= 0 && p.target <= p.ntargets, a->comm, PETSC_ERR_FILE_UNEXPECTED, "The checkpoint's position on the load path (step %" PetscInt_FMT " of %" PetscInt_FMT ") is not on it", p.target, p.ntargets);
  const PetscReal reached = p.target == 0 ? p.start : targets[p.target - 1];
  PetscCheck(p.sub != 0 || a->lambda == reached, a->comm, PETSC_ERR_USER_INPUT, "The checkpoint's load factor %.17g is not the load path's %.17g at its step %" PetscInt_FMT ": a restart must follow the path of the run that wrote the checkpoint", (double)a->lambda, (double)reached, p.target);
  PetscFunctionReturn(0);
}

// The joints at the last converged step as joints.csv records them (the accepted responses), summed
// over the ranks' own joints: in state stick, in state slide, and bearing (the bolt on its hole,
// whatever the state: a frictional joint stuck or sliding in bearing, a contact joint closed).
PetscErrorCode CountProgressStates(BoltnetAssembly a, Progress *p)
{
  PetscInt loc[3] = {0, 0, 0}, glob[3];
  PetscFunctionBeginUser;
  for (const Response &r : a->joints.accepted) {
    loc[0] += r.state == State::Stick;
    loc[1] += r.state == State::Slide;
    loc[2] += r.bearing;
  }
  PetscCall(MPIU_Allreduce(loc, glob, 3, MPIU_INT, MPI_SUM, a->comm));
  p->stick = glob[0];
  p->slide = glob[1];
  p->bear  = glob[2];
  PetscFunctionReturn(0);
}

// The progress line of the converged step `info` (docs/scenes.md, "Progress"): the nominal step i + 1
// of the path, reached or (after cut-backs) part of the way to it.
PetscErrorCode PrintProgress(BoltnetAssembly a, const StepInfo &info, const std::vector<PetscReal> &targets, size_t i, PetscInt halved, PetscReal done0, PetscLogDouble t0)
{
  Progress       p;
  PetscLogDouble now;
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&now));
  const PetscReal done = PathFraction(a->path.start, targets, (size_t)a->path.target, a->lambda);
  p.step    = (PetscInt)i + 1;
  p.nsteps  = (PetscInt)targets.size();
  p.part    = a->lambda == targets[i] ? 1.0 : done - (PetscReal)i;
  p.cuts    = halved;
  p.load    = info.load;
  p.newton  = info.newton_its;
  p.elapsed = (PetscReal)(now - t0);
  p.left    = EstimateTimeLeft(p.elapsed, done0, done, (PetscReal)targets.size());
  PetscCall(CountProgressStates(a, &p));
  PetscCall(PetscPrintf(a->comm, "%s\n", FormatProgress(p).c_str()));
  PetscFunctionReturn(0);
}

// The first iterate of a step from lambda to lambda_target (docs/solver.md, "The first iterate of a
// step"): X + r (X - Xprev), r = (lambda_target - lambda) / (lambda - lambda_prev), the last
// converged step's increment scaled to this one. Only where the load goes on the same way (r > 0),
// and by at most that increment (r <= 1): past a reversal, or far beyond what the last step saw, the
// last converged solution is the better guess. The converged solution does not depend on the first
// iterate (each iterate's joint forces come from the committed history, not the path of the
// iterates), only the Newton iterations do: on plate-grid 40 instead of 49 (docs/performance.md).
// A predicted step takes at least one Newton iteration (SNESSetForceIteration): where the response
// is linear the prediction is the solution to round-off, and whether its residual passes the
// round-off test before any iteration would then depend on the rank count. From such a point a line
// search that asks for a decrease (PETSc's bt) cannot find one, so a predicted step may fail one
// line search more (SNESSetMaxNonlinearStepFailures) and the convergence test then judges the point.
PetscErrorCode PredictStep(BoltnetAssembly a, Vec Xtry, PetscBool *moved)
{
  PetscFunctionBeginUser;
  *moved = PETSC_FALSE;
  if (!a->has_prev || a->lambda == a->lambda_prev) PetscFunctionReturn(0);
  const PetscReal r = (a->lambda_target - a->lambda) / (a->lambda - a->lambda_prev);
  if (!(r > 0)) PetscFunctionReturn(0);
  const PetscReal s = PetscMin(r, 1.0);
  PetscCall(VecAXPBY(Xtry, -s, 1.0 + s, a->Xprev)); // Xtry = X: (1 + s) X - s Xprev
  *moved = PETSC_TRUE;
  PetscFunctionReturn(0);
}

} // namespace
} // namespace boltnet

using namespace boltnet;

namespace {
// The load path after the checks of BoltnetAssemblySolveLoadPath(), inside its Guard(): the work
// vector is a VecHandle, so that it is destroyed whichever way the solve ends.
PetscErrorCode SolveLoadPath(BoltnetAssembly a, PetscInt n, const PetscReal factors[], PetscInt steps_per_segment)
{
  VecHandle xtry;
  PetscFunctionBeginUser;
  // A new path starts from the current state; a restart (io/checkpoint.hpp) goes on along the path
  // of the run that wrote the checkpoint, from where that run stood.
  if (!a->resume) a->path = PathPosition{a->lambda, 0, 0, 0, 0};
  const std::vector<PetscReal> targets = LoadPathTargets(a->path.start, std::vector<PetscReal>(factors, factors + n), steps_per_segment);
  if (a->resume) PetscCall(CheckResumedPath(a, targets));
  a->resume        = PETSC_FALSE;
  a->path.ntargets = (PetscInt)targets.size();
  // For -load_progress: the clock and the nominal steps done when this run took the path up.
  PetscLogDouble t0;
  PetscCall(PetscTime(&t0));
  const PetscReal done0 = PathFraction(a->path.start, targets, (size_t)a->path.target, a->lambda);
  PetscCall(VecDuplicate(a->X, xtry.out()));
  Vec Xtry = xtry.get();
  for (size_t i = (size_t)a->path.target; i < targets.size(); ++i) {
    const PetscReal target = targets[i];
    PetscReal sub    = a->path.sub != 0 ? a->path.sub : target - a->lambda; // current increment, halved on failure
    PetscInt  cuts   = 0;              // cut-backs since the last converged step (recorded with it)
    PetscInt  halved = a->path.halved; // halvings on the way to this target: bounded by -load_max_cuts,
                                       // and not reset by a converged sub-step, else a load the structure
                                       // cannot carry (a mechanism at 450 N) is approached by ever
                                       // smaller sub-steps forever
    while (a->lambda != target) {
      const PetscBool last = std::abs(target - a->lambda) <= std::abs(sub) * (1 + 1e-12) ? PETSC_TRUE : PETSC_FALSE;
      a->lambda_target     = last ? target : a->lambda + sub;
      PetscCall(VecCopy(a->X, Xtry));
      PetscBool predicted = PETSC_FALSE;
      if (a->opt.predictor && cuts == 0) PetscCall(PredictStep(a, Xtry, &predicted));
      PetscCall(SNESSetForceIteration(a->snes, predicted || a->checks.user_force ? PETSC_TRUE : PETSC_FALSE));
      PetscCall(SNESSetMaxNonlinearStepFailures(a->snes, a->checks.user_max_fail + (predicted ? 1 : 0)));
      PetscCall(AssemblyApplyDirichlet(a, Xtry, a->lambda_target));
      PetscCall(AssemblyFreezeStuck(a, a->lambda_target - a->lambda));
      PetscCall(SetStepTolerance(a, Xtry));
      a->checks.singular.clear();
      PetscCall(SolveInStage(a, Xtry));
      SNESConvergedReason reason;
      PetscInt            its;
      PetscCall(SNESGetConvergedReason(a->snes, &reason));
      PetscCall(SNESGetIterationNumber(a->snes, &its));
      PetscCall(RecordLinearSolves(a));
      // A predicted step must take a Newton iteration (SNESSetForceIteration), and where the
      // prediction is already at the round-off floor that iteration cannot lower ||F||: its line
      // search fails. The prediction is then the solution, by the same test an iteration would meet.
      if (reason == SNES_DIVERGED_LINE_SEARCH && its == 0 && predicted) {
        VecHandle F0;
        PetscReal fnorm;
        PetscBool floor;
        PetscCall(VecDuplicate(Xtry, F0.out()));
        PetscCall(SNESComputeFunction(a->snes, Xtry, F0.get()));
        PetscCall(VecNorm(F0.get(), NORM_2, &fnorm));
        PetscCall(AtFloorInBalance(a, Xtry, F0.get(), fnorm, &floor));
        if (floor) {
          PetscCall(PetscInfo(a->snes, "step %zu: the predicted iterate is at the round-off floor and in balance; its line search could not go below it\n", a->steps.size() + 1));
          reason = SNES_CONVERGED_FNORM_ABS;
        }
      }
      // Joints solved as linear springs must still be stuck under the full law at the solution;
      // those that are not are released and the solve goes on from there. What is accepted is
      // then a solution of the full model.
      // The step keeps one budget of -snes_max_it Newton iterations.
      PetscInt maxit;
      PetscCall(SNESGetTolerances(a->snes, nullptr, nullptr, nullptr, &maxit, nullptr));
      while (reason > 0) {
        PetscInt nreleased, more;
        PetscCall(AssemblyReleaseUnstuck(a, Xtry, &nreleased));
        if (!nreleased) break;
        PetscCall(SNESSetTolerances(a->snes, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, PetscMax(1, maxit - its), PETSC_DEFAULT));
        PetscCall(PetscInfo(a->snes, "step %zu: %" PetscInt_FMT " joints solved as linear springs left their linear state; solving on with the full law for them\n", a->steps.size() + 1, nreleased));
        if (a->opt.monitor_states) PetscCall(PetscPrintf(a->comm, "  step %zu: %" PetscInt_FMT " joints solved as linear springs would leave their linear state: solving on with the full law for them\n", a->steps.size() + 1, nreleased));
        PetscCall(SolveInStage(a, Xtry));
        PetscCall(SNESGetConvergedReason(a->snes, &reason));
        PetscCall(SNESGetIterationNumber(a->snes, &more));
        PetscCall(RecordLinearSolves(a));
        its += more;
      }
      PetscCall(SNESSetTolerances(a->snes, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, maxit, PETSC_DEFAULT));
      // Whatever SNES's test said, a converged step balances its loads (docs/solver.md): the
      // out-of-balance force against the problem's force scale, not against ||F0|| or ||J||.
      std::string why      = SNESConvergedReasons[reason];
      bool        accepted = reason > 0;
      if (accepted) {
        Equilibrium eq;
        PetscCall(AssemblyEquilibrium(a, Xtry, &eq));
        PetscCall(PetscInfo(a->snes, "step %zu: %s\n", a->steps.size() + 1, DescribeEquilibrium(eq).c_str()));
        if (!(eq.ratio <= a->checks.equilibrium_rtol)) {
          std::ostringstream m;
          m << why << " but not in balance: " << DescribeEquilibrium(eq) << " > -load_equilibrium_rtol " << a->checks.equilibrium_rtol;
          why      = m.str();
          accepted = false;
        } else a->checks.force_scale_seen = eq.scale;
      }
      if (accepted) {
        a->joints.last_increment = a->lambda_target - a->lambda;
        PetscCall(AssemblyCommit(a, Xtry));
        if (!a->Xprev) PetscCall(VecDuplicate(a->X, &a->Xprev));
        PetscCall(VecCopy(a->X, a->Xprev)); // the secant predictor's other point
        a->lambda_prev = a->lambda;
        a->has_prev    = PETSC_TRUE;
        PetscCall(VecCopy(Xtry, a->X));
        a->lambda = a->lambda_target;
        StepInfo info{(PetscInt)a->steps.size() + 1, a->lambda, its, cuts};
        a->steps.push_back(info);
        cuts = 0;
        // Where the path goes on from here: the next target, or this one by the increment left.
        if (a->lambda == target) a->path = PathPosition{a->path.start, a->path.ntargets, (PetscInt)i + 1, 0, 0};
        else a->path = PathPosition{a->path.start, a->path.ntargets, (PetscInt)i, sub, halved};
        if (a->on_step) PetscCall(a->on_step(a, info));
        if (a->opt.progress) PetscCall(PrintProgress(a, info, targets, (size_t)i, halved, done0, t0)); // once the step's results are out
        continue;
      }
      std::string chatter;
      PetscCall(AssemblyDescribeChatter(a, chatter));
      if (reason == SNES_DIVERGED_LINEAR_SOLVE) {
        // A failed factorisation leaves MUMPS in an error state that the next solve would raise as
        // an error: start the next attempt from a fresh factorisation. And name the joints that
        // may have made the tangent singular.
        std::string singular;
        // A factorisation that failed for want of memory fails the same way at any load: rather
        // than cut the step back and factor again, factor the same step again once with the
        // factors on disk (MUMPS then holds in memory only the fronts it works on: its users'
        // guide, "Out-of-core facility"), or stop here and say why.
        std::string fatal, advice;
        PetscBool   memory;
        PetscCall(AssemblyFactorError(a, fatal, advice, &memory));
        if (!fatal.empty() && memory && a->isolve.out_of_core && !a->isolve.factors_on_disk) {
          a->isolve.factors_on_disk = PETSC_TRUE;
          // auto's lagged choice was made for factors in memory: made again for factors on disk.
          const bool direct_again = a->isolve.lagged_auto && !AutoTakesLagged(a->isolve, a->isolve.flops_per_entry, true);
          PetscCall(PetscPrintf(a->comm, "boltnet: load step %zu: %s; factoring again with the factors on disk (MUMPS ICNTL(22) = 1, in the directory MUMPS_OOC_TMPDIR names; -interface_out_of_core false stops instead)%s\n", a->steps.size() + 1, fatal.c_str(),
                                direct_again ? "; the interface solve is direct again, as -interface_solve auto chooses with factors on disk (-interface_lagged_flops_per_entry_on_disk)" : ""));
          if (direct_again) PetscCall(AssemblyUseDirectKSP(a));
          PetscCall(AssemblyResetPC(a));
          a->isolve.factors_valid = PETSC_FALSE;
          PetscCall(AssemblySetUpNullPivots(a));
          continue;
        }
        if (!fatal.empty()) {
          std::ostringstream m;
          m << "Load step " << a->steps.size() + 1 << " from load factor " << a->lambda << " to " << a->lambda_target << ": " << fatal << ". " << advice;
          a->failure = m.str();
          SETERRQ(a->comm, PETSC_ERR_LIB, "%s", a->failure.c_str());
        }
        // A Krylov solve preconditioned by a singular factorisation breaks down before the
        // convergence test sees the null pivots: look at them here, before the reset.
        if (a->checks.singular.empty()) {
          PetscInt nnull;
          PetscCall(AssemblyCheckNullPivots(a, &nnull));
        }
        PetscCall(AssemblyResetPC(a));
        a->isolve.factors_valid = PETSC_FALSE; // the lagged solve refactors from the next Jacobian
        PetscCall(AssemblySetUpNullPivots(a));
        if (!a->checks.singular.empty()) singular = a->checks.singular;
        else PetscCall(AssemblyDescribeSingular(a, Xtry, singular));
        if (!singular.empty()) chatter += "; " + singular;
      }
      if (halved >= a->opt.max_cuts) {
        std::ostringstream m;
        m << "Load step " << a->steps.size() + 1 << " from load factor " << a->lambda << " to " << a->lambda_target << " did not converge (" << why << " after " << its
          << " Newton iterations) after " << halved << " cut-backs (-load_max_cuts " << a->opt.max_cuts << "); " << chatter;
        a->failure = m.str();
        SETERRQ(a->comm, PETSC_ERR_NOT_CONVERGED, "%s", a->failure.c_str());
      }
      ++cuts;
      ++halved;
      ++a->total_cutbacks;
      sub *= 0.5;
      PetscCall(PetscInfo(a->snes, "step %zu: %s at load %g, cutting the increment to %g; %s\n", a->steps.size() + 1, why.c_str(), (double)a->lambda_target, (double)sub, chatter.c_str()));
      PetscCall(PetscPrintf(a->comm, "boltnet: load step %zu did not converge at load factor %g (%s); cutting the increment to %g. %s\n", a->steps.size() + 1, (double)a->lambda_target, why.c_str(), (double)sub, chatter.c_str()));
    }
  }
  PetscFunctionReturn(0);
}
} // namespace

// Checks the request before anything is allocated from it: n load factors (finite; NULL only when
// n is 0), steps_per_segment steps per segment, at most limits::kMaxLoadSteps steps in all, as the
// driver's -load_steps (docs/scenes.md, "Limits"). The halvings per step are -load_max_cuts,
// bounded when the options are read.
PetscErrorCode BoltnetAssemblySolveLoadPath(BoltnetAssembly a, PetscInt n, const PetscReal factors[], PetscInt steps_per_segment)
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  PetscCheck(a->net.dm, a->comm, PETSC_ERR_ORDER, "Call BoltnetAssemblySetUp() before BoltnetAssemblySolveLoadPath()");
  PetscCheck(n >= 0 && n <= limits::kMaxLoadSteps, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: argument 2 (n, the number of load factors) = %" PetscInt_FMT " is not in 0..%lld", __func__, n, (long long)limits::kMaxLoadSteps);
  if (n > 0) BoltnetCheckPointer(factors, 3, "factors");
  PetscCheck(steps_per_segment >= 1 && steps_per_segment <= limits::kMaxLoadSteps, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: argument 4 (steps_per_segment) = %" PetscInt_FMT " is not in 1..%lld", __func__, steps_per_segment, (long long)limits::kMaxLoadSteps);
  // The segments that LoadPathTargets() splits into steps: those that move the load factor.
  std::int64_t segments = 0;
  PetscReal    from     = a->resume ? a->path.start : a->lambda;
  for (PetscInt i = 0; i < n; ++i) {
    PetscCheck(std::isfinite(factors[i]), a->comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: argument 3 (factors): factors[%" PetscInt_FMT "] is not finite", __func__, i);
    if (factors[i] != from) ++segments;
    from = factors[i];
  }
  PetscCheck(segments * steps_per_segment <= limits::kMaxLoadSteps, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: %" PetscInt_FMT " steps per segment (argument 4) over %lld segments is more than the limit of %lld load steps", __func__, steps_per_segment, (long long)segments, (long long)limits::kMaxLoadSteps);
  PetscCall(Guard(__func__, [&] { return SolveLoadPath(a, n, factors, steps_per_segment); }));
  PetscFunctionReturn(0);
}
