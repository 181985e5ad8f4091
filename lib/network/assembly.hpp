// The assembly: a DMNetwork whose vertices are patches and whose edges are joints.
// Internal C++ view of the opaque BoltnetAssembly of boltnet.h.
#pragma once

#include "boltnet.h"
#include "core/compat.h"
#include "joint/law.hpp"
#include "network/patch.hpp"

#include <map>

#include <functional>
#include <string>
#include <vector>

namespace boltnet {

// Patch kinds. A rigid patch is one 6-dof node; shell patches (issue 3) add nodes and a stiffness.
enum class PatchKind : PetscInt { Rigid = 0, Shell = 1 };

// Vertex component: plain data, copied as raw bytes by DMNetworkDistribute.
struct PatchComp {
  PetscInt  id;     // user id
  PetscInt  index;  // position in the description
  PetscInt  kind;   // PatchKind
  PetscInt  nnodes; // nodes carried by the vertex (6 dof each)
  PetscReal x[3];   // reference position of node 0
};

// Edge component: plain data. R holds the local frame rows (n, t1, t2).
struct JointComp {
  PetscInt  id;     // user id
  PetscInt  index;  // position in the description (0..njoints-1)
  PetscInt  patch_a, patch_b; // user ids of the two patches
  PetscReal x[3];             // position of the fastener (where shell patches attach it)
  PetscInt  node_a; // attachment node inside patch a
  PetscInt  node_b; // attachment node inside patch b
  PetscReal R[9];
  Params    params;
};

// Edge component of a seam: plain data; the seam's elements are in the assembly's `seams`.
struct SeamComp {
  PetscInt index; // position in the assembly's seams
  PetscInt part;  // user id of the part
};

struct BCDesc {
  PetscInt      patch; // user id
  std::string   set;   // node set of a shell patch ("" : every node of the patch)
  PetscInt      dof;   // 0..5, or -1 for all six
  BoltnetBCKind kind;
  PetscReal     value; // per unit load factor (fixed: ignored); a force is the set's total
};

// One row of results for one joint at one converged step (gathered to rank 0 for output).
struct JointRecord {
  PetscInt  joint; // user id
  PetscInt  state; // State
  PetscInt  bearing;
  PetscReal jump[6];
  PetscReal force[6];
  PetscReal slip[2];
};

struct StepInfo {
  PetscInt  step;        // converged step number (1-based)
  PetscReal load;        // load factor
  PetscInt  newton_its;  // Newton iterations of the accepted solve
  PetscInt  cutbacks;    // cut-backs needed before this step converged
};

} // namespace boltnet

struct _p_BoltnetAssembly {
  MPI_Comm    comm   = MPI_COMM_NULL;
  PetscMPIInt rank   = 0;
  PetscMPIInt size   = 1;
  std::string prefix;

  // Description (replicated on every rank, used by rank 0 to build the network).
  std::vector<boltnet::PatchComp> patches;
  std::vector<boltnet::JointComp> joints;
  std::vector<boltnet::BCDesc>    bcs;
  std::map<PetscInt, boltnet::ShellPatch> shells; // shell patches by position in `patches`
  std::vector<boltnet::Seam>              seams;  // seams between patches cut from one part
  std::map<PetscInt, boltnet::QuadMesh>   cut_parts; // the meshes of the parts that were cut, by user id
  PetscInt nparts = 0; // parts described by the user (before large ones are cut into patches)

  // Cutting and balancing (docs/architecture.md): the largest patch in nodes (0: never cut,
  // -1: automatic), and whether boltnet partitions the network by dof (METIS) or PETSc does.
  PetscInt  patch_max_nodes = -1;
  PetscBool balance         = PETSC_TRUE;

  // Patch coupling (docs/coupling.md): type, footprint radius (mm) and penalty factor (link
  // stiffness = factor * A11).
  boltnet::CouplingType coupling_type = boltnet::CouplingType::Exact; // docs/coupling.md: why
  PetscReal coupling_radius  = 4.0;
  PetscReal coupling_penalty = 1e3;
  // Stiffness of the owned shell patches, by vertex point, built after distribution.
  std::map<PetscInt, boltnet::PatchOperator> ops;
  // Element stiffness of the owned seams, by edge point.
  std::map<PetscInt, std::vector<boltnet::shell::ElementMatrix>> seam_ops;

  // Options.
  boltnet::Tangent tangent        = boltnet::Tangent::Consistent; // docs/solver.md: why
  PetscInt         max_cuts       = 8;
  PetscBool        monitor_states = PETSC_FALSE;
  // Linear where it can be (docs/solver.md): joints that stay stuck are solved as linear springs,
  // and the Jacobian (and its factorisation) is kept while no joint's tangent changes.
  PetscBool stuck_linear = PETSC_TRUE;
  PetscReal stuck_margin = 0.3; // freeze a joint whose predicted utilization stays below this (docs/solver.md: why 0.3)
  PetscBool        setfromoptions_called = PETSC_FALSE;

  // Network and solver.
  DM       dm   = nullptr;
  SNES     snes = nullptr;
  Mat      J    = nullptr;
  Vec      X    = nullptr; // converged solution
  PetscInt vStart = 0, vEnd = 0, eStart = 0, eEnd = 0;
  PetscInt keyPatch = -1, keyJoint = -1, keySeam = -1; // component keys
  std::vector<PetscInt> jedges; // local edge points that are joints; joint arrays below follow it
  std::vector<PetscInt> sedges; // local edge points that are seams
  PetscInt ndof_global = 0;
  PetscReal dof_imbalance = 1; // max over ranks of the owned dof / their mean

  // History per local joint (jedges[i] has index i), owned by the edge's rank.
  std::vector<boltnet::History> committed;
  // The joints at the last converged step, evaluated against the history before it (so that the
  // state says what the joint did during the step: a joint that slid reads 'slide', not 'stick').
  std::vector<boltnet::Response> accepted;
  std::vector<boltnet::Vec6>     accepted_jump;
  // Joint states at each Newton iterate of the current solve (local joints), for the monitor and
  // for naming the joints that kept changing state when a step fails.
  std::vector<std::vector<PetscInt>> state_trace;
  // Joints solved as linear springs in the current attempt (1: frozen; empty: none), their
  // utilization (law.hpp) at the last two converged steps, and the last step's load increment.
  std::vector<char>      frozen;
  std::vector<PetscReal> util_now, util_before;
  PetscReal              last_increment = 0;
  PetscBool              util_ready     = PETSC_FALSE; // util_now holds the last converged step's
  // The joint tangents assembled into J (valid only while jac_valid) and the bookkeeping.
  std::vector<boltnet::Mat6> jac_tangent;
  PetscBool                  jac_valid = PETSC_FALSE;
  PetscInt jac_assembled = 0, jac_reused = 0;     // Jacobian evaluations assembled / kept
  PetscInt frozen_joint_steps = 0, joint_steps = 0; // summed over attempts: joints frozen / all
  PetscInt released = 0;                          // frozen joints the full law sent out of stick
  PetscBool                          user_atol = PETSC_FALSE; // -snes_atol given: keep it
  // Trusting "converged" (solver/equilibrium.cpp, docs/solver.md): a converged step must balance
  // to this fraction of its force scale; MUMPS pivots below null_pivot_threshold ||A|| are null.
  PetscReal   equilibrium_rtol     = 1e-6;
  PetscReal   null_pivot_threshold = 1e-12;
  std::string singular; // the mechanism found by the last factorisation with null pivots ("" if none)
  PetscReal   force_scale_seen = 0; // the largest force scale of the converged steps so far
  PetscReal                          jnorm     = 0;           // ||J||_inf of the last Jacobian

  // Boundary conditions on owned rows (global indices).
  std::vector<PetscInt>  dirichlet_rows;
  std::vector<PetscReal> dirichlet_values; // per unit load factor
  std::vector<PetscInt>  force_rows;
  std::vector<PetscReal> force_values;

  PetscReal lambda_target = 0; // load factor of the step being solved
  PetscReal lambda        = 0; // load factor of the last converged step

  // Record of the solve.
  std::vector<boltnet::StepInfo> steps;
  PetscInt total_cutbacks = 0;
  std::string failure; // non-empty after a step failed beyond the cut-back bound

  // Called on every rank after each converged step.
  std::function<PetscErrorCode(BoltnetAssembly, const boltnet::StepInfo &)> on_step;
};

namespace boltnet {

// A shell patch from a mesh (node sets included) and a section (network/api.cpp).
PetscErrorCode AssemblyAddShell(BoltnetAssembly a, PetscInt id, QuadMesh &&mesh, const shell::ShellMaterial &material);

// Network assembly (network/assembly.cpp).
PetscErrorCode AssemblyBuildNetwork(BoltnetAssembly a);
PetscErrorCode AssemblyFormFunction(SNES snes, Vec X, Vec F, void *ctx);
PetscErrorCode AssemblyFormJacobian(SNES snes, Vec X, Mat J, Mat P, void *ctx);
// Evaluate every local joint at X against the committed history (no side effects): as the solver
// sees it (frozen joints as linear springs), or with the full law everywhere.
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
// Gather the records of every joint at the last accepted point to rank 0 (sorted by joint id).
PetscErrorCode AssemblyGatherRecords(BoltnetAssembly a, std::vector<JointRecord> &records);
// Impose the prescribed values of the constrained dof at load factor lambda on X.
PetscErrorCode AssemblyApplyDirichlet(BoltnetAssembly a, Vec X, PetscReal lambda);

// Solver (solver/*.cpp).
PetscErrorCode AssemblySetUpSolver(BoltnetAssembly a);

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
// MUMPS null pivot detection (ICNTL(24), threshold CNTL(3)) on the SNES's factorisation; a no-op
// for other solvers. Call after the solver is set up and after every PCReset.
PetscErrorCode AssemblySetUpNullPivots(BoltnetAssembly a);
// After a factorisation: the number of null pivots (INFOG(28)); when there are some, a->singular
// names the mechanism (patches, dof, joints) from a null vector of the Jacobian.
PetscErrorCode AssemblyCheckNullPivots(BoltnetAssembly a, PetscInt *nnull);
PetscErrorCode MonitorJointStates(SNES snes, PetscInt its, PetscReal fnorm, void *ctx);
// After a failed solve: the joints that changed state most often during it, with their states.
PetscErrorCode AssemblyDescribeChatter(BoltnetAssembly a, std::string &msg);
// After a failed linear solve: the joints whose tangent at X has no stiffness in a translation
// (e.g. sliding with kg = 0), the likely reason for a singular Jacobian; "" if none.
PetscErrorCode AssemblyDescribeSingular(BoltnetAssembly a, Vec X, std::string &msg);

} // namespace boltnet
