// What the solver keeps between Newton iterations and load steps, beside the solution itself: the
// interface solve's choice and its factorisation (InterfaceSolve), and what it needs to trust a
// "converged" (ConvergenceChecks). Both live in the assembly (network/assembly.hpp); the code that
// reads and writes them is in lib/solver and network/jacobian.cpp.
#pragma once

#include "solver/roundoff.hpp"

#include <petscmat.h>
#include <string>
#include <vector>

namespace boltnet {

// The interface solve (docs/solver.md, "The interface solve"): direct (J factored whenever it
// changes) or lagged (Krylov on J preconditioned by the factorisation of an earlier Jacobian, kept
// in the PC and refactored when the Krylov solve takes more than refactor_its iterations or fails).
// solve_auto: not chosen yet; MUMPS's first analysis of J decides (lagged where it estimates at
// least lagged_flops_per_entry flops per entry of the factors in core, lagged_flops_per_entry_on_disk
// with the factors on disk and Eisenstat-Walker's tolerances).
struct InterfaceSolve {
  PetscBool lagged                 = PETSC_FALSE;
  PetscBool solve_auto             = PETSC_TRUE;
  PetscBool lagged_ksp             = PETSC_FALSE; // the KSP is set up for the lagged solve
  PetscBool lagged_auto            = PETSC_FALSE; // lagged by auto's choice: direct again if the factors go to disk
  PetscBool ew_default             = PETSC_FALSE; // Eisenstat-Walker's tolerances set by the lagged solve, not by the user
  PetscReal rtol_before_ew         = 1e-10;       // the KSP's own relative tolerance, given back when they are dropped
  PetscReal ew_rtol_max            = 0.5;         // their largest forcing term (PETSc's default 0.9: solver/stepper.cpp)
  PetscReal lagged_flops_per_entry = 1000;
  PetscReal lagged_flops_per_entry_on_disk = 2500;
  PetscReal flops_per_entry        = 0; // MUMPS's estimate at auto's choice (0: not made)
  PetscInt  refactor_its           = 25;
  PetscBool factors_valid          = PETSC_FALSE; // the PC's factors are of a Jacobian of this analysis
  // The direct solve's modified Newton (docs/solver.md, "Keeping the factorisation"): the Jacobian
  // of an earlier iterate of the same solve, and its factors, are kept while the residual falls by
  // at least this factor per iteration and no joint changes state (0: refactor at every iteration).
  PetscReal keep_ratio = 0.1;
  PetscInt  keep_it    = -1; // iteration of the last Jacobian call in this solve
  PetscReal keep_fnorm = 0;  // the residual norm there
  PetscInt  kept       = 0;  // Jacobians kept by this rule, for summary.json
  PetscBool in_event   = PETSC_FALSE; // BoltnetInterfaceSolve begun and not yet ended (solver/stepper.cpp)
  // Factors on disk (MUMPS ICNTL(22) = 1) when MUMPS's analysis estimates more memory than a node
  // has (memory_mb, 0: what the operating system says is available), or when a factorisation runs
  // out of memory: -interface_out_of_core; factors_on_disk once that happened, or once a
  // factorisation ran with the user's own -mat_mumps_icntl_22 1 (solver/equilibrium.cpp). That
  // option, given either way, decides alone (storage_given): boltnet neither chooses nor retries.
  PetscBool out_of_core     = PETSC_TRUE;
  PetscBool storage_given   = PETSC_FALSE;
  PetscReal memory_mb       = 0;
  PetscBool factors_on_disk = PETSC_FALSE;
  PetscInt  factorisations = 0, krylov_its = 0, linear_solves = 0; // the record, for summary.json
  // The fill-reducing ordering of MUMPS's analysis (ICNTL(7)): with choose_ordering, the first
  // analysis tries MUMPS's own choice, QAMD and AMF and keeps the one it estimates cheapest, if a
  // tenth below its own choice (solver/equilibrium.cpp, ChooseOrdering); ordering is then that value
  // for every later analysis of the run (-1: not chosen yet). The user's -mat_mumps_icntl_7 decides
  // alone.
  PetscBool choose_ordering = PETSC_TRUE;
  PetscInt  ordering        = -1;
  // -interface_matis: J's MATIS, the preconditioning matrix of PCBDDC, and its linear part; the
  // global nodes of this rank's subdomain, sorted (network/jacobian.cpp, CreateSubdomainMatrix).
  Mat                   P = nullptr, Pbase = nullptr;
  std::vector<PetscInt> subdomain_nodes;
  std::string           bddc_option; // the option boltnet put into the options database, if any (solver/stepper.cpp)
};

// -interface_solve auto's rule (docs/solver.md, "Which one the default takes"): lagged where MUMPS
// estimates a factorisation dear against the triangular solves a lagged Newton iteration makes in
// its place, its flops per entry of the factors (an entry is read once per solve). In core, from
// lagged_flops_per_entry. On disk each solve reads the factors back from disk, which costs 4 to 9
// times as many flops' worth per entry (the full junction at 4,480 flops per entry: a factorisation
// 8 to 20 solves of 37 to 53 s; medium in core at 1,734: 27, 15.4 s against 0.57 s). With
// Eisenstat-Walker's tolerances a lagged Newton iteration makes about 3 solves with FGMRES (4 with
// the right-preconditioned GMRES the threshold was set with), a direct one about 0.75
// factorisations and a solve, so on disk the two break even near 1,600 flops per entry (2,300 with
// GMRES) at the full junction's 8 solves a factorisation, lower where a factorisation costs more
// solves (20: about 630). The threshold lagged_flops_per_entry_on_disk, 2,500, stays above both: on
// disk auto goes lagged only where it wins by a margin. Without them a solve to 1e-10 makes 11 to
// 18 solves per Newton iteration (medium: 310 in 24 with GMRES), as dear on disk as refactoring:
// direct.
inline bool AutoTakesLagged(const InterfaceSolve &s, double flops_per_entry, bool on_disk)
{
  if (!on_disk) return flops_per_entry >= s.lagged_flops_per_entry;
  return s.ew_default && flops_per_entry >= s.lagged_flops_per_entry_on_disk;
}

// Trusting "converged" (solver/equilibrium.cpp, docs/solver.md, "When is a step converged").
struct ConvergenceChecks {
  PetscBool user_atol     = PETSC_FALSE; // -snes_atol given: keep it
  PetscBool user_force    = PETSC_FALSE; // -snes_force_iteration given
  PetscInt  user_max_fail = 1;           // -snes_max_fail
  PetscReal jnorm         = 0;           // ||J||_inf of the last Jacobian
  // The last Jacobian assembled (referenced), whose |J| |x| is the round-off of each row of K u,
  // and what that product keeps between calls (solver/roundoff.hpp).
  Mat     Jlast = nullptr;
  AbsMult roundoff;
  // A converged step must balance to this fraction of its force scale; MUMPS pivots below
  // null_pivot_threshold ||A|| are null.
  PetscReal   equilibrium_rtol     = 1e-6;
  PetscReal   null_pivot_threshold = 1e-12;
  std::string singular;             // the mechanism found by the last factorisation with null pivots ("" if none)
  PetscReal   force_scale_seen = 0; // the largest force scale of the converged steps so far
};

} // namespace boltnet
