// Static condensation of a linear shell patch onto its ports (docs/solver.md, "Condensed patches").
//
// The patch's dof split into its ports B (the nodes its vertex carries: joint nodes and the nodes a
// seam touches), its prescribed interior dof D (supports, known per unit load factor), the slaves of
// exact coupling (known from their joint node) and the rest, its interior I. With K the patch
// operator over I and B (slaves eliminated exactly, patch/operator.hpp), the interior equations
//   K_II u_I + K_IB u_B + K_ID lambda u_D = lambda f_I
// give u_I = lambda w0 - K_II^-1 K_IB u_B with w0 = K_II^-1 (f_I - K_ID u_D), and the patch's
// internal force on its ports is
//   S u_B + lambda c,   S = K_BB - K_BI K_II^-1 K_IB,   c = K_BD u_D + K_BI w0.
// S is computed by MUMPS as the Schur complement of a single sparse factorisation of K
// (MatFactorSetSchurIS, MatFactorCreateSchurComplement); the same factorisation solves with K_II
// (MUMPS ICNTL(26) = 0: the interior problem alone) for w0 and for the interior recovered after a
// converged step (RecoverPatch). Each rank condenses the patches it owns, sequentially.
#pragma once

#include "core/handle.hpp"
#include "patch/loads.hpp"
#include "patch/patch.hpp"

#include <petscmat.h>

#include <tuple>
#include <vector>

namespace boltnet {

struct CondensedPatch {
  PetscInt            nb = 0;  // port dof (6 per carried node)
  PetscInt            ni = 0;  // interior dof
  std::vector<double> S;       // nb x nb, row major (the network frees it once it is in its Jacobian)
  std::vector<double> c;       // nb: the load term per unit load factor
  // For the recovery of the interior.
  std::vector<PetscInt> interior; // patch dof of each interior unknown (K's rows 0..ni-1)
  std::vector<double>   w0;       // interior displacement per unit load factor when u_B = 0
  std::map<PetscInt, double> prescribed; // interior prescribed dof -> value per unit load factor
  // Loads held at fixed values while the load factor follows a path (a load case that continues
  // another: AssemblyHoldLoads): c, w0 and the prescribed values as they are, not per unit load
  // factor; empty when nothing is held.
  std::vector<double>        c_held, w0_held;
  std::map<PetscInt, double> prescribed_held;
  // What the load terms need when the loads change (a load case: CondensedPatchLoads): the row of
  // K of every patch dof (-1: a slave; -2: a prescribed interior dof), and K's entries in the
  // columns of the prescribed dof, as (row of K, patch dof, value).
  std::vector<PetscInt>                              row;
  std::vector<std::tuple<PetscInt, PetscInt, double>> kd;
  SlaveMap              slaves;   // exact coupling (empty master list otherwise)
  MatHandle             K;        // (ni + nb) x (ni + nb): interior rows first, then the ports
  MatHandle             F;        // its MUMPS factorisation, Schur complement on the ports
  PetscLogDouble        bytes = 0; // memory held: S, the factorisation (MUMPS INFOG(22)), K
  PetscInt              free_motions = 0; // rigid-body motions no support in the patch holds
};

// Condense the patch (its operator with the given coupling, its loads). Errors name the patch: a
// singular interior (a part of the patch that neither a joint, a seam nor a support holds).
PetscErrorCode CondensePatch(const ShellPatch &p, CouplingType type, double penalty, double radius, const PatchLoads &loads, CondensedPatch *cp);

// The load terms c and w0 (and the prescribed values) of a condensed patch for other loads, with its
// kept factorisation: one interior solve, no new factorisation. The loads must hold the same dof
// inside the patch as those it was condensed with (else an error naming the patch, id); forces and
// prescribed values may differ. CondensePatch ends with it.
PetscErrorCode CondensedPatchLoads(PetscInt id, const PatchLoads &loads, CondensedPatch *cp);

// Every dof of the patch (6 per node: mesh nodes, then joint nodes) from its port dof uB at load
// factor lambda (and the held loads, if any): the ports, the interior (one solve with the kept
// factorisation), the prescribed dof and the slaves.
PetscErrorCode RecoverPatch(const ShellPatch &p, const CondensedPatch &cp, PetscReal lambda, const PetscScalar *uB, std::vector<double> &u);

} // namespace boltnet
