// The assembly: the opaque BoltnetAssembly of boltnet.h, in the order the data flows.
//
//   model    what the user described: parts, fasteners, boundary conditions (model/model.hpp);
//            a scene's meshes not yet read
//   layout   the parts, each read and laid out by one rank: cut into patches, joints attached,
//            the nodes each vertex carries (patch/layout.hpp)
//   net      the DMNetwork of patches (vertices), joints and seams (edges), distributed
//   patches  the operators of the patches and seams this rank owns: kept whole, or condensed onto
//            their ports (patch/condense.hpp)
//   joints   the joints this rank owns and their history (joint/jointset.hpp)
//   bc       the boundary rows of the network's vectors (network/boundary.cpp)
// and the solver state: SNES, Jacobian, solution and load factor; isolve, the interface solve's
// choice and factorisation, and checks, what a converged step must satisfy (solver/interface.hpp);
// the record of the steps.
#pragma once

#include "boltnet.h"
#include "core/compat.h"
#include "core/memory.hpp"
#include "joint/jointset.hpp"
#include "model/model.hpp"
#include "patch/condense.hpp"
#include "patch/layout.hpp"
#include "shell/shell.hpp"
#include "solver/interface.hpp"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace boltnet {

// Options of the assembly (BoltnetAssemblySetFromOptions lists each with its help).
struct AssemblyOptions {
  Tangent      tangent        = Tangent::Consistent; // docs/solver.md: why
  PetscInt     max_cuts       = 8;
  PetscBool    monitor_states = PETSC_FALSE;
  PetscBool    progress       = PETSC_FALSE; // one line per converged step (the driver turns it on)
  // Linear where it can be (docs/solver.md): joints that stay stuck are solved as linear springs,
  // and the Jacobian (and its factorisation) is kept while no joint's tangent changes.
  PetscBool    stuck_linear = PETSC_TRUE;
  PetscReal    stuck_margin = 0.3; // freeze a joint whose predicted utilization stays below this
  // The first iterate of a load step: the last converged solution moved on by the last converged
  // step's increment, scaled to this one (docs/solver.md, "The first iterate of a step").
  PetscBool    predictor = PETSC_TRUE;
  // Patches: condensed onto their ports, or kept whole (docs/solver.md, "Condensed patches"):
  // every one, none, or each where its dense port block is cheaper (patch/layout.hpp).
  Condense     condense       = Condense::Auto;
  PetscReal    condense_ratio = 4;
  // The six rigid-body modes of the nodes as the Jacobian's near-null space (MatSetNearNullSpace),
  // for algebraic multigrid (docs/solver.md, "Iterative solvers"); LU ignores it.
  PetscBool    near_null_space = PETSC_TRUE;
  // With PCFIELDSPLIT: the splits m (masters) and s (exact coupling's slaves) of a Jacobian kept
  // whole (AssemblySetSlaveSplit).
  PetscBool    slave_split = PETSC_TRUE;
  // The Jacobian also as a MATIS, one subdomain per rank, for PCBDDC (docs/solver.md, "BDDC").
  PetscBool    matis = PETSC_FALSE;
  // Cutting and balancing (docs/architecture.md): the largest patch in nodes (0: never cut,
  // -1: automatic), and whether boltnet partitions the network by dof (METIS) or PETSc does.
  PetscInt     patch_max_nodes = -1;
  PetscBool    balance         = PETSC_TRUE;
  // Patch coupling (docs/coupling.md): type, footprint radius and reach (mm), penalty factor (link
  // stiffness = factor * A11).
  CouplingType coupling_type    = CouplingType::Exact; // docs/coupling.md: why
  PetscReal    coupling_radius  = 4.0;
  PetscReal    coupling_reach   = 0;
  PetscReal    coupling_penalty = 1e3;
  // Curved shell parts: the elements around a node share the mesh's nodal director (docs/shell.md).
  PetscBool    shell_directors = PETSC_TRUE;
  // Every rank receives and keeps the whole layout (the gathering fields writer needs it on rank
  // 0); otherwise each keeps only the patches and seams its operators and joints use.
  PetscBool    keep_layout = PETSC_FALSE;
  PetscBool    setfromoptions_called = PETSC_FALSE;
};

// The DMNetwork and the local views of it.
struct Network {
  DM                    dm     = nullptr;
  PetscInt              vStart = 0, vEnd = 0, eStart = 0, eEnd = 0;
  PetscInt              keyPatch = -1, keyJoint = -1, keySeam = -1; // component keys
  std::vector<PetscInt> sedges;          // local edge points that are seams
  PetscInt              ndof_global = 0; // the network's dof (the interface's when condensed)
  PetscInt              ncondensed  = 0; // shell patches condensed onto their ports (every rank knows)
  PetscInt              ndof_model  = 0; // every dof of the model (patches kept whole)
  PetscReal             dof_imbalance = 1; // max over ranks of the owned model dof / their mean
};

// A patch this rank owns, with its operator.
struct OwnedPatch {
  PetscInt       v     = -1; // vertex point
  PetscInt       index = -1; // position in the layout's patches
  PetscInt       goff = 0, loff = 0; // offsets of its dof in the global and the local vector
  bool           shell = false;
  PatchOperator  op;   // kept whole: the operator over every node (until it is in Jbase)
  CondensedPatch cond; // condensed: the operator on the ports (S until it is in Jbase)
};

struct PatchSet {
  std::vector<OwnedPatch>                                        owned;
  std::map<PetscInt, std::vector<shell::ElementMatrix>>          seam_ops; // owned seams by edge point (until they are in Jbase)
  PetscLogDouble                                                 condensed_bytes = 0; // on this rank
};

// Boundary conditions on owned rows (global indices), per unit load factor.
struct Boundary {
  std::vector<PetscInt>  dirichlet_rows;
  std::vector<PetscReal> dirichlet_values;
  std::vector<PetscInt>  force_rows;
  std::vector<PetscReal> force_values;
  PetscReal              fext_norm = 0; // || every applied force || per unit load factor (the model's)
};

// Loads held at fixed values while the load factor follows a path: those of the load cases that a
// case continues (AssemblyHoldLoads, docs/scenes.md "Held loads"), on owned rows, as they are (not
// per unit load factor). The loads the path scales stay in Boundary; the prescribed rows are the
// same in both (a case may change values, never which dof are held).
struct HeldLoads {
  std::vector<PetscReal> dirichlet; // per Boundary::dirichlet_rows entry (empty: none held)
  std::vector<PetscInt>  force_rows;
  std::vector<PetscReal> force_values;
  PetscReal              norm = 0; // an upper bound of || every held force || (a force scale)
};

struct StepInfo {
  PetscInt  step;       // converged step number (1-based)
  PetscReal load;       // load factor
  PetscInt  newton_its; // Newton iterations of the accepted solve
  PetscInt  cutbacks;   // cut-backs needed before this step converged
};

// Where the load path stands after the last converged step (solver/stepper.cpp): the path's
// targets are LoadPathTargets(start, ...) (solver/loadpath.hpp); the step being approached is
// targets[target], from the last converged load factor by increments of sub (0: the whole way to the
// target, the first attempt; else the increment cut-backs left), after `halved` halvings on the way
// to it. A checkpoint keeps it, so that a restart goes on exactly where the run stopped
// (io/checkpoint.hpp).
struct PathPosition {
  PetscReal start    = 0;
  PetscInt  ntargets = 0;
  PetscInt  target   = 0;
  PetscReal sub      = 0;
  PetscInt  halved   = 0;
};

// One row of results for one joint at one converged step (joints.csv, joints.h5).
struct JointRecord {
  PetscInt  joint; // user id
  PetscInt  state; // State
  PetscInt  bearing;
  PetscReal jump[6];
  PetscReal force[6];
  PetscReal slip[2];
};

} // namespace boltnet

struct _p_BoltnetAssembly {
  MPI_Comm    comm = MPI_COMM_NULL;
  PetscMPIInt rank = 0;
  PetscMPIInt size = 1;
  std::string prefix;

  boltnet::AssemblyOptions opt;
  boltnet::Model           model;
  boltnet::Layout          layout;
  boltnet::Network         net;
  boltnet::PatchSet        patches;
  boltnet::JointSet        joints;
  boltnet::Boundary        bc;
  boltnet::HeldLoads       held;

  // Solver state.
  SNES      snes      = nullptr;
  Mat       J         = nullptr;
  Vec       X         = nullptr; // converged solution
  // The converged solution before X, at load factor lambda_prev (has_prev: there is one): the
  // secant predictor's other point (solver/stepper.cpp), kept in checkpoints.
  Vec       Xprev       = nullptr;
  PetscReal lambda_prev = 0;
  PetscBool has_prev    = PETSC_FALSE;
  Mat       Jbase     = nullptr;     // the linear part of J (patches, seams), copied in before the joints
  boltnet::InterfaceSolve    isolve; // the interface solve's choice and factorisation (solver/interface.hpp)
  boltnet::ConvergenceChecks checks; // what a converged step must satisfy, and the last Jacobian's round-off
  PetscReal lambda_target = 0; // load factor of the step being solved
  PetscReal lambda        = 0; // load factor of the last converged step

  // Record of the solve.
  boltnet::PathPosition          path;
  PetscBool                      resume = PETSC_FALSE; // the next solve goes on from `path` (a restart)
  std::vector<boltnet::StepInfo> steps;
  PetscInt                       total_cutbacks = 0;
  std::string                    failure; // non-empty after a step failed beyond the cut-back bound
  // Resident memory per rank at the end of each phase of the set-up (network/build.cpp), for
  // summary.json.
  std::vector<boltnet::MemoryMark> memory;

  // Called on every rank after each converged step.
  std::function<PetscErrorCode(BoltnetAssembly, const boltnet::StepInfo &)> on_step;
};

namespace boltnet {

// A shell part from a mesh (node sets included) and a section (model/describe.cpp).
PetscErrorCode AssemblyAddShell(BoltnetAssembly a, PetscInt id, ShellMesh &&mesh, const shell::ShellMaterial &material);
// A shell part whose mesh only the rank that lays it out reads, by read() (ShellPart::read): the
// scene's plates and Gmsh parts. `size` weighs it in the assignment of parts to ranks.
PetscErrorCode AssemblyAddShellRead(BoltnetAssembly a, PetscInt id, std::int64_t size, std::function<PetscErrorCode(ShellMesh *)> read, const shell::ShellMaterial &material);
// A shell part whose mesh rank 0 alone holds (ShellPart::on_rank0): a Nastran deck's, read on rank
// 0 (io/nastran.cpp). Called on every rank with the same id, first node x0, node count and section;
// `mesh` (node sets included) is the mesh on rank 0 and ignored elsewhere. Rank 0 sends it to the
// rank that lays the part out.
PetscErrorCode AssemblyAddShellOnRank0(BoltnetAssembly a, PetscInt id, const std::array<double, 3> &x0, std::int64_t size, ShellMesh &&mesh, const shell::ShellMaterial &material);
// The footprint of joint `id` (already added) on the shell parts it joins: the nodes of their node
// set `set` (JointDesc::footprint); needs -coupling_type exact or penalty, checked at set-up.
PetscErrorCode AssemblySetJointFootprint(BoltnetAssembly a, PetscInt id, const char set[]);
// A linear spring joint with a full stiffness K (6 x 6, row major, in the joint frame n, t1,
// t2 = n x t1: Params::full) acting at x (model/describe.cpp). With at_a and at_b (both or
// neither), side a attaches at the point at_a (node coupling: the part's node nearest it; a rigid
// part: its node) and carries the spring at x by a rigid lever, and side b likewise: a Nastran
// CBUSH between grids that do not coincide (docs/nastran.md).
PetscErrorCode AssemblyAddFullSpring(BoltnetAssembly a, PetscInt id, PetscInt patch_a, PetscInt patch_b, const std::array<double, 36> &K, const PetscReal normal[3], const PetscReal t1[3], const PetscReal x[3], const PetscReal *at_a = nullptr, const PetscReal *at_b = nullptr);

// The network (network/build.cpp): lays the model out, builds and distributes the DMNetwork,
// builds (and condenses) the operators of the owned patches and seams, the Jacobian and the
// boundary rows.
PetscErrorCode AssemblyBuildNetwork(BoltnetAssembly a);
// Residual and Jacobian (network/residual.cpp, network/jacobian.cpp).
PetscErrorCode AssemblyFormFunction(SNES snes, Vec X, Vec F, void *ctx);
PetscErrorCode AssemblyFormJacobian(SNES snes, Vec X, Mat J, Mat P, void *ctx);
// Evaluate every local joint at X against the committed history (no side effects): as the solver
// sees it (frozen joints as linear springs), or with the full law everywhere (network/joints.cpp).
PetscErrorCode AssemblyEvaluateJoints(BoltnetAssembly a, Vec X, std::vector<Response> &out, std::vector<Vec6> *jumps = nullptr, bool full_law = false);
// Before an attempt at a step of the given load increment: choose the joints to solve as linear
// springs (those whose predicted utilization stays below -joint_stuck_margin).
PetscErrorCode AssemblyFreezeStuck(BoltnetAssembly a, PetscReal increment);
// After a converged attempt: check every frozen joint with the full law at X; those that would not
// stay in their linear state are released (no longer frozen). *nreleased is the global count.
PetscErrorCode AssemblyReleaseUnstuck(BoltnetAssembly a, Vec X, PetscInt *nreleased);
// Joints whose state at X differs from their state at ref (global count).
PetscErrorCode AssemblyCountStateChanges(SNES snes, Vec ref, Vec X, PetscInt *nchanged, void *ctx);
// Global counts of joints per State at X.
PetscErrorCode AssemblyStateCounts(BoltnetAssembly a, Vec X, PetscInt counts[5]);
// Accept the converged point X: keep the joints' responses there, commit their trial history.
PetscErrorCode AssemblyCommit(BoltnetAssembly a, Vec X);
// Collective: the records of the joints this rank owns at the last accepted point (JointSet order).
PetscErrorCode AssemblyJointRecords(BoltnetAssembly a, std::vector<JointRecord> &mine);
// Collective: every rank's records gathered to rank 0 and sorted by joint id (empty elsewhere). For
// joints.csv only (PETSc event BoltnetJointGather): joints.h5 is written without it (io/joint_table.hpp).
PetscErrorCode GatherJointRecords(BoltnetAssembly a, const std::vector<JointRecord> &mine, std::vector<JointRecord> &records);
// Both: the records of every joint at the last accepted point on rank 0, sorted by joint id.
PetscErrorCode AssemblyGatherRecords(BoltnetAssembly a, std::vector<JointRecord> &records);
// Impose the prescribed values of the constrained dof at load factor lambda on X.
PetscErrorCode AssemblyApplyDirichlet(BoltnetAssembly a, Vec X, PetscReal lambda);
// Every dof of an owned shell patch (6 per node: mesh nodes, then joint nodes) at the solution X
// and load factor lambda, recovering the interior of a condensed patch (network/boundary.cpp).
PetscErrorCode AssemblyPatchDisplacement(BoltnetAssembly a, const OwnedPatch &op, const PetscScalar *xlocal, PetscReal lambda, std::vector<double> &u);

// Solver (solver/*.cpp).
PetscErrorCode AssemblySetUpSolver(BoltnetAssembly a);

// Load cases on one set-up (network/cases.cpp, docs/scenes.md "Load cases"). AssemblyReset: back to
// the unloaded state (solution zero, every joint's history its initial value, load factor 0, the
// record of steps and solves empty, a fresh factorisation next). AssemblySetLoads: the boundary
// conditions of another case in place of model.bcs: the condensed patches' load terms come from
// their kept factorisations and the network's rows are rebuilt; an error when the case fixes or
// prescribes other dof than the set-up (which would need a set-up of its own). AssemblyHoldLoads:
// the loads at the last converged load factor become held loads (HeldLoads, added to those held
// before), and the path starts again from load factor 0 at the state reached: a case that continues
// another (docs/scenes.md, "Held loads"); AssemblySetLoads then gives the loads the new path scales.
PetscErrorCode AssemblyReset(BoltnetAssembly a);
PetscErrorCode AssemblyHoldLoads(BoltnetAssembly a);
// The applied forces' scale at load factor lambda: |lambda| || f || plus the held loads' bound.
PetscReal AssemblyAppliedForce(BoltnetAssembly a, PetscReal lambda);
PetscErrorCode AssemblySetLoads(BoltnetAssembly a, const std::vector<BCDesc> &bcs);

// Equilibrium at X for the load factor being solved (solver/equilibrium.cpp): the out-of-balance
// force (2-norm over the free rows) against the force scale, the largest of the applied loads,
// the reactions (the internal forces at the constrained rows) and the joint forces, here or at any
// converged step before (unloaded to zero, the forces the structure carried set the round-off).
struct Equilibrium {
  PetscReal imbalance = 0, applied = 0, reactions = 0, joints = 0;
  PetscReal scale = 0, ratio = 0; // ratio = imbalance / scale
};
PetscErrorCode AssemblyEquilibrium(BoltnetAssembly a, Vec X, Equilibrium *eq);
std::string    DescribeEquilibrium(const Equilibrium &eq);
// With -pc_type fieldsplit on a Jacobian kept whole: the splits "m" (masters) and "s" (exact
// coupling's slaves), the masters with their rigid-body modes (network/jacobian.cpp).
PetscErrorCode AssemblySetSlaveSplit(BoltnetAssembly a, PC pc);
// MUMPS null pivot detection (ICNTL(24), threshold CNTL(3)) on the SNES's factorisation, and its
// factors on disk (ICNTL(22)) once they did not fit in memory; a no-op for other solvers. Call
// after the solver is set up and after every PCReset.
PetscErrorCode AssemblySetUpNullPivots(BoltnetAssembly a);
// A fresh preconditioner for the next solve, after a failed one or before another load case:
// PCReset, or for BDDC a new one (solver/stepper.cpp). Call AssemblySetUpNullPivots after it.
PetscErrorCode AssemblyResetPC(BoltnetAssembly a);
// The lagged interface solve's Krylov method (flexible GMRES, right preconditioned) on the SNES's KSP.
PetscErrorCode AssemblyUseLaggedKSP(BoltnetAssembly a);
// Eisenstat-Walker's tolerances for the lagged solve unless -snes_ksp_ew or -ksp_rtol is given, and
// their removal where the solve turns out direct (solver/stepper.cpp).
PetscErrorCode AssemblyDefaultEW(BoltnetAssembly a);
PetscErrorCode AssemblyDropDefaultEW(BoltnetAssembly a);
// Back to the direct solve (a KSP that applies the factorisation, refactored whenever J changes),
// where the automatic choice had taken the lagged one and the factors then had to go to disk.
PetscErrorCode AssemblyUseDirectKSP(BoltnetAssembly a);
// After a factorisation: the number of null pivots (INFOG(28)); when there are some, a->checks.singular
// names the mechanism (patches, dof, joints) from a null vector of the Jacobian.
PetscErrorCode AssemblyCheckNullPivots(BoltnetAssembly a, PetscInt *nnull);
// After a failed linear solve: why MUMPS could not factor the Jacobian when a smaller load step
// cannot change it (out of memory, a workspace estimate too small: every MUMPS error but a singular
// matrix), and what to do about it; "" otherwise, or for other solvers. *memory: the error is
// MUMPS's memory (INFOG(1) = -13, an allocation refused, or -19, the cap of -mat_mumps_icntl_23),
// which factors kept on disk may avoid.
PetscErrorCode AssemblyFactorError(BoltnetAssembly a, std::string &why, std::string &advice, PetscBool *memory);
PetscErrorCode MonitorJointStates(SNES snes, PetscInt its, PetscReal fnorm, void *ctx);
// After a failed solve: the joints that changed state most often during it, with their states.
PetscErrorCode AssemblyDescribeChatter(BoltnetAssembly a, std::string &msg);
// After a failed linear solve: the joints whose tangent at X has no stiffness in a translation
// (e.g. sliding with kg = 0), the likely reason for a singular Jacobian; "" if none.
PetscErrorCode AssemblyDescribeSingular(BoltnetAssembly a, Vec X, std::string &msg);

} // namespace boltnet
