// The round-off test's |A| |x| (lib/solver/roundoff.hpp) against a MatMult with |A| built
// explicitly from the same entries: a random sparse matrix with entries of both signs, rows split
// unevenly over the ranks and columns reaching into every other rank's rows, so that the
// off-process part and its scatter are exercised; the scatter kept for a second vector and rebuilt
// for another matrix; and a MATBAIJ matrix through the AIJ conversion. Prints
// "test_abs_mult: PASS" on success.
#include "solver/roundoff.hpp"

#include <petscmat.h>

#include <cmath>
#include <vector>

namespace {

// A and |A| with the same pattern: row i has its diagonal and `per_row` entries in pseudo-random
// columns, values of both signs spread over twelve decades (as a joint's rotational stiffness
// beside a shell's membrane terms).
PetscErrorCode Build(MPI_Comm comm, PetscInt nlocal, PetscInt per_row, unsigned seed, Mat *A, Mat *Aabs)
{
  PetscInt N, rstart, rend;
  PetscFunctionBeginUser;
  for (Mat *M : {A, Aabs}) {
    PetscCall(MatCreate(comm, M));
    PetscCall(MatSetSizes(*M, nlocal, nlocal, PETSC_DETERMINE, PETSC_DETERMINE));
    PetscCall(MatSetType(*M, MATAIJ));
    PetscCall(MatSetUp(*M));
    PetscCall(MatSetOption(*M, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  }
  PetscCall(MatGetSize(*A, &N, nullptr));
  PetscCall(MatGetOwnershipRange(*A, &rstart, &rend));
  unsigned s = seed + 7919u * (unsigned)rstart;
  auto     next = [&s]() {
    s = 1664525u * s + 1013904223u;
    return s;
  };
  for (PetscInt i = rstart; i < rend; ++i)
    for (PetscInt k = 0; k <= per_row; ++k) {
      const PetscInt    j = k == 0 ? i : (PetscInt)(next() % (unsigned)N);
      const double      m = std::pow(10.0, (double)(next() % 13) - 6.0) * (1.0 + (next() % 1000) / 1000.0);
      const PetscScalar v = (next() % 2) ? m : -m;
      PetscCall(MatSetValue(*A, i, j, v, INSERT_VALUES));
      PetscCall(MatSetValue(*Aabs, i, j, std::fabs(v), INSERT_VALUES));
    }
  for (Mat *M : {A, Aabs}) {
    PetscCall(MatAssemblyBegin(*M, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(*M, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(0);
}

// The largest |y_i - r_i| / r_i over the rows (r = |A| |x| by MatMult), on every rank.
PetscErrorCode Compare(Vec y, Vec r, PetscReal *worst)
{
  Vec d;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(y, &d));
  PetscCall(VecWAXPY(d, -1.0, r, y));
  PetscCall(VecPointwiseDivide(d, d, r));
  PetscCall(VecNorm(d, NORM_INFINITY, worst));
  PetscCall(VecDestroy(&d));
  PetscFunctionReturn(0);
}

// x with entries of both signs (the displacements and rotations of a step).
PetscErrorCode FillSigned(Vec x, unsigned seed)
{
  PetscInt     n, rstart;
  PetscScalar *v;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetOwnershipRange(x, &rstart, nullptr));
  PetscCall(VecGetArray(x, &v));
  for (PetscInt i = 0; i < n; ++i) {
    const unsigned h = (unsigned)(rstart + i) * 2654435761u + seed;
    v[i]             = ((h >> 3) % 2 ? 1.0 : -1.0) * (1.0 + (h % 997) / 100.0);
  }
  PetscCall(VecRestoreArray(x, &v));
  PetscFunctionReturn(0);
}

// One check: y = |A| |x| by AbsMultApply against MatMult(|A|, |x|); worst relative difference.
PetscErrorCode Check(boltnet::AbsMult *c, Mat A, Mat Aabs, unsigned seed, PetscReal *worst)
{
  Vec x, ax, y, r;
  PetscFunctionBeginUser;
  PetscCall(MatCreateVecs(A, &x, &y));
  PetscCall(VecDuplicate(y, &r));
  PetscCall(VecDuplicate(x, &ax));
  PetscCall(FillSigned(x, seed));
  PetscCall(boltnet::AbsMultApply(c, A, x, y));
  PetscCall(VecCopy(x, ax));
  PetscCall(VecAbs(ax));
  PetscCall(MatMult(Aabs, ax, r));
  PetscCall(Compare(y, r, worst));
  for (Vec *v : {&x, &ax, &y, &r}) PetscCall(VecDestroy(v));
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv)
{
  PetscMPIInt      rank;
  Mat              A, Aabs, B, Babs, Abaij;
  boltnet::AbsMult c;
  PetscReal        w[5];
  PetscCall(PetscInitialize(&argc, &argv, nullptr, "Checks |A| |x| (solver/roundoff.hpp) against an explicit |A|"));
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCall(Build(PETSC_COMM_WORLD, 40 + 13 * rank, 9, 1u, &A, &Aabs));
  PetscCall(Check(&c, A, Aabs, 11u, &w[0]));
  PetscCall(Check(&c, A, Aabs, 12u, &w[1])); // the scatter kept from the first call
  PetscCall(Build(PETSC_COMM_WORLD, 25 + 7 * rank, 4, 2u, &B, &Babs));
  PetscCall(Check(&c, B, Babs, 13u, &w[2])); // another matrix: the scatter rebuilt
  PetscCall(Check(&c, A, Aabs, 14u, &w[3])); // and back
  PetscCall(MatConvert(A, MATBAIJ, MAT_INITIAL_MATRIX, &Abaij));
  PetscCall(Check(&c, Abaij, Aabs, 15u, &w[4])); // not AIJ: through a converted copy
  PetscReal worst = 0;
  for (PetscReal v : w) worst = PetscMax(worst, v);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "test_abs_mult: largest relative difference %g (%g %g %g %g %g)\n", (double)worst, (double)w[0], (double)w[1], (double)w[2], (double)w[3], (double)w[4]));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "test_abs_mult: %s\n", worst <= 1e-14 ? "PASS" : "FAIL"));
  PetscCall(boltnet::AbsMultDestroy(&c));
  for (Mat *M : {&A, &Aabs, &B, &Babs, &Abaij}) PetscCall(MatDestroy(M));
  PetscCall(PetscFinalize());
  return worst <= 1e-14 ? 0 : 1;
}
