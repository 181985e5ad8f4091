// CompressRows (patch/operator.hpp), which builds a condensed patch's K from its triplets, against
// PETSc's own assembly of the same triplets one MatSetValue(ADD_VALUES) at a time: the same
// nonzeros and the same values to the bit, and no room allocated beyond them. Triplets are drawn with
// many repeats (as element blocks and the footprint elimination make them), values of mixed signs
// and magnitudes (so that the order of the sums shows), and dof that fall outside the matrix.
#include "patch/operator.hpp"

#include <petscmat.h>

#include <cstring>
#include <map>
#include <random>

namespace {

struct Case {
  PetscInt                  ndof, n;
  std::vector<PetscInt>     row;
  boltnet::Triplets         t;
};

Case Draw(unsigned seed, PetscInt ndof, size_t ntriplets)
{
  std::mt19937                            g(seed);
  std::uniform_int_distribution<PetscInt> dof(0, ndof - 1), band(-12, 12), kind(0, 9);
  std::uniform_real_distribution<double>  mant(-1, 1), expo(-8, 8);
  Case                                    c;
  c.ndof = ndof;
  c.row.assign(ndof, -1);
  c.n = 0;
  for (PetscInt d = 0; d < ndof; ++d) { // about one dof in five outside the matrix (-1 or -2)
    const PetscInt k = kind(g);
    c.row[d]         = k == 0 ? -1 : k == 1 ? -2 : c.n++;
  }
  for (size_t i = 0; i < ntriplets; ++i) {
    const PetscInt r = dof(g), cc = std::min<PetscInt>(ndof - 1, std::max<PetscInt>(0, r + band(g)));
    c.t.emplace_back(r, cc, mant(g) * std::pow(10.0, expo(g)));
  }
  return c;
}

// The former assembly: preallocated by triplet counts, one MatSetValue per triplet.
PetscErrorCode AssembleOneByOne(const Case &c, Mat *A)
{
  PetscFunctionBeginUser;
  std::vector<PetscInt> nnz(c.n, 0);
  for (const auto &[r, col, v] : c.t)
    if (c.row[r] >= 0 && c.row[col] >= 0) nnz[c.row[r]]++;
  for (PetscInt &k : nnz) k = std::min(k, c.n);
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, c.n, c.n, 0, nnz.data(), A));
  for (const auto &[r, col, v] : c.t)
    if (c.row[r] >= 0 && c.row[col] >= 0) PetscCall(MatSetValue(*A, c.row[r], c.row[col], v, ADD_VALUES));
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

PetscErrorCode Check(unsigned seed, PetscInt ndof, size_t ntriplets, PetscInt *bad)
{
  PetscFunctionBeginUser;
  const Case              c = Draw(seed, ndof, ntriplets);
  const boltnet::PatchOperator k = boltnet::CompressRows(c.n, c.t, c.row);
  Mat                     A, B;
  PetscCall(AssembleOneByOne(c, &A));
  PetscCall(MatCreate(PETSC_COMM_SELF, &B));
  PetscCall(MatSetSizes(B, c.n, c.n, c.n, c.n));
  PetscCall(MatSetType(B, MATSEQAIJ));
  PetscCall(MatSeqAIJSetPreallocationCSR(B, k.rowptr.data(), k.cols.data(), k.vals.data()));
  // The same entries, bit for bit, row by row; columns increasing in the compressed rows.
  PetscInt differ = 0;
  for (PetscInt i = 0; i < c.n; ++i) {
    PetscInt           na;
    const PetscInt    *ca;
    const PetscScalar *va;
    PetscCall(MatGetRow(A, i, &na, &ca, &va));
    const PetscInt nb = k.rowptr[i + 1] - k.rowptr[i];
    if (na != nb) ++differ;
    else
      for (PetscInt e = 0; e < na; ++e) {
        const PetscInt    kc = k.cols[k.rowptr[i] + e];
        const PetscScalar kv = k.vals[k.rowptr[i] + e];
        if (ca[e] != kc || std::memcmp(&va[e], &kv, sizeof kv) != 0) ++differ;
        if (e > 0 && k.cols[k.rowptr[i] + e - 1] >= kc) ++differ;
      }
    PetscCall(MatRestoreRow(A, i, &na, &ca, &va));
  }
  // Every triplet in the matrix is counted once in a distinct entry (a map of the sums).
  std::map<std::pair<PetscInt, PetscInt>, int> distinct;
  for (const auto &[r, col, v] : c.t)
    if (c.row[r] >= 0 && c.row[col] >= 0) distinct[{c.row[r], c.row[col]}]++;
  if ((size_t)k.rowptr[c.n] != distinct.size()) ++differ;
  MatInfo ia, ib;
  PetscCall(MatGetInfo(A, MAT_LOCAL, &ia));
  PetscCall(MatGetInfo(B, MAT_LOCAL, &ib));
  if (ib.nz_allocated != ib.nz_used || ib.nz_used != ia.nz_used) ++differ;
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "seed %u: %" PetscInt_FMT " rows, %zu triplets, %.0f nonzeros; one by one allocates %.0f, compressed %.0f; %" PetscInt_FMT " differences\n", seed, c.n, c.t.size(), ib.nz_used, ia.nz_allocated, ib.nz_allocated, differ));
  *bad += differ;
  PetscCall(MatDestroy(&A));
  PetscCall(MatDestroy(&B));
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv)
{
  PetscInt bad = 0;
  PetscCall(PetscInitialize(&argc, &argv, nullptr, "Checks CompressRows (patch/operator.hpp) against MatSetValue assembly"));
  PetscCall(Check(1u, 60, 4000, &bad));     // dense rows: every entry met many times
  PetscCall(Check(2u, 1500, 200000, &bad)); // a patch's size: about 130 triplets a row
  PetscCall(Check(3u, 7, 3, &bad));         // rows with no entry
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "test_compress_rows: %s\n", bad ? "FAIL" : "PASS"));
  PetscCall(PetscFinalize());
  return bad ? 1 : 0;
}
