// The round-off floor of a residual row: y = |A| |x|, entry by entry (y_i = sum_j |a_ij| |x_j|),
// computed from A's own arrays. Row i of K u is a sum of the terms a_ij x_j, each computed with a
// relative error of about machine epsilon, so 100 eps (|A| |x|)_i is how far that row can be trusted
// (solver/stepper.cpp, docs/solver.md "When is a step converged"). A copy of |A| would cost a whole
// Jacobian's memory (3.6 GB at the full wing-fuselage junction: docs/performance.md); this costs a
// vector of A's off-process columns.
#pragma once
#include <petscmat.h>

namespace boltnet {

// What the product keeps between calls: the scatter of x's values at A's off-process columns
// (MATMPIAIJ), built for one matrix and nonzero pattern, and rebuilt when another is given. Destroy
// with AbsMultDestroy.
struct AbsMult {
  Mat              A       = nullptr; // the matrix the scatter was built for (referenced)
  PetscObjectState pattern = 0;       // its MatGetNonzeroState then
  VecScatter       scatter = nullptr;
  Vec              ghost   = nullptr;
};

// y = |A| |x| for a MATSEQAIJ or MATMPIAIJ A (x and y laid out as A's columns and rows); other
// types are converted to AIJ for the call. Collective on A. The sums run in MatMult's order (each
// row's local columns, then its off-process ones): test/test_abs_mult.cpp finds the result equal
// to a MatMult with an explicit |A| to the last bit.
PetscErrorCode AbsMultApply(AbsMult *c, Mat A, Vec x, Vec y);
PetscErrorCode AbsMultDestroy(AbsMult *c);

} // namespace boltnet
