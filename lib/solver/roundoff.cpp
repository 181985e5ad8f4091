// y = |A| |x| from A's own arrays (roundoff.hpp).
#include "solver/roundoff.hpp"

namespace boltnet {
namespace {

// y_i (+)= sum_k |v_k| |x_{ja_k}| over the rows of the sequential AIJ matrix S, starting each sum
// from y_i when add is set (MatMultAdd_SeqAIJ's order).
PetscErrorCode AbsRowSums(Mat S, const PetscScalar *x, PetscScalar *y, bool add)
{
  PetscInt           n;
  const PetscInt    *ia, *ja;
  const PetscScalar *v;
  PetscBool          done;
  PetscFunctionBeginUser;
  PetscCall(MatGetRowIJ(S, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  PetscCheck(done, PetscObjectComm((PetscObject)S), PETSC_ERR_SUP, "Cannot read the rows of the matrix for |A| |x|");
  PetscCall(MatSeqAIJGetArrayRead(S, &v));
  for (PetscInt i = 0; i < n; ++i) {
    PetscReal s = add ? PetscRealPart(y[i]) : 0.0;
    for (PetscInt k = ia[i]; k < ia[i + 1]; ++k) s += PetscAbsScalar(v[k]) * PetscAbsScalar(x[ja[k]]);
    y[i] = s;
  }
  PetscCall(MatSeqAIJRestoreArrayRead(S, &v));
  PetscCall(MatRestoreRowIJ(S, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  PetscFunctionReturn(0);
}

// The scatter of x to A's off-process columns, in the order of Ao's compressed columns.
PetscErrorCode BuildGhostScatter(AbsMult *c, Mat A, Mat Ao, const PetscInt *colmap, Vec x)
{
  PetscInt nghost;
  IS       is;
  PetscFunctionBeginUser;
  PetscCall(AbsMultDestroy(c));
  PetscCall(MatGetSize(Ao, nullptr, &nghost));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, nghost, colmap, PETSC_COPY_VALUES, &is));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, nghost, &c->ghost));
  PetscCall(VecScatterCreate(x, is, c->ghost, nullptr, &c->scatter));
  PetscCall(ISDestroy(&is));
  PetscCall(PetscObjectReference((PetscObject)A));
  c->A = A;
  PetscCall(MatGetNonzeroState(A, &c->pattern));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode AbsMultApply(AbsMult *c, Mat A, Vec x, Vec y)
{
  PetscBool seq, mpi;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)A, MATSEQAIJ, &seq));
  PetscCall(PetscObjectTypeCompare((PetscObject)A, MATMPIAIJ, &mpi));
  if (!seq && !mpi) { // another type (a user's -mat_type): through a temporary AIJ copy
    Mat     B;
    AbsMult tmp;
    PetscCall(MatConvert(A, MATAIJ, MAT_INITIAL_MATRIX, &B));
    PetscCall(AbsMultApply(&tmp, B, x, y));
    PetscCall(AbsMultDestroy(&tmp));
    PetscCall(MatDestroy(&B));
    PetscFunctionReturn(0);
  }
  Mat                Ad = A, Ao = nullptr;
  const PetscInt    *colmap = nullptr;
  const PetscScalar *xa;
  PetscScalar       *ya;
  if (mpi) PetscCall(MatMPIAIJGetSeqAIJ(A, &Ad, &Ao, &colmap));
  if (Ao) { // the scatter started first, so that the local rows' sums overlap the messages
    PetscObjectState pattern;
    PetscCall(MatGetNonzeroState(A, &pattern));
    if (c->A != A || c->pattern != pattern) PetscCall(BuildGhostScatter(c, A, Ao, colmap, x));
    PetscCall(VecScatterBegin(c->scatter, x, c->ghost, INSERT_VALUES, SCATTER_FORWARD));
  }
  PetscCall(VecGetArrayRead(x, &xa));
  PetscCall(VecGetArray(y, &ya));
  PetscCall(AbsRowSums(Ad, xa, ya, false));
  PetscCall(VecRestoreArrayRead(x, &xa));
  if (Ao) {
    const PetscScalar *ga;
    PetscCall(VecScatterEnd(c->scatter, x, c->ghost, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecGetArrayRead(c->ghost, &ga));
    PetscCall(AbsRowSums(Ao, ga, ya, true));
    PetscCall(VecRestoreArrayRead(c->ghost, &ga));
  }
  PetscCall(VecRestoreArray(y, &ya));
  PetscFunctionReturn(0);
}

PetscErrorCode AbsMultDestroy(AbsMult *c)
{
  PetscFunctionBeginUser;
  PetscCall(VecScatterDestroy(&c->scatter));
  PetscCall(VecDestroy(&c->ghost));
  PetscCall(MatDestroy(&c->A));
  PetscFunctionReturn(0);
}

} // namespace boltnet
