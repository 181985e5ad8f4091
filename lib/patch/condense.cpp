#include "patch/condense.hpp"
#include "core/log.hpp"
#include "patch/operator.hpp"

#include <petscmat.h>

#include <algorithm>
#include <cmath>

namespace boltnet {

namespace {

// Eigenvalues and eigenvectors (columns of V) of a symmetric n x n matrix by cyclic Jacobi.
void SymmetricEigen(int n, std::vector<double> A, std::vector<double> &w, std::vector<double> &V)
{
  V.assign((size_t)n * n, 0.0);
  for (int i = 0; i < n; ++i) V[(size_t)i * n + i] = 1;
  for (int sweep = 0; sweep < 60; ++sweep) {
    double off = 0, diag = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) (i == j ? diag : off) += A[(size_t)i * n + j] * A[(size_t)i * n + j];
    if (off <= 1e-30 * diag) break;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) {
        const double apq = A[(size_t)p * n + q];
        if (apq == 0) continue;
        const double theta = (A[(size_t)q * n + q] - A[(size_t)p * n + p]) / (2 * apq);
        const double t     = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < n; ++k) { // A <- J^T A J
          const double akp = A[(size_t)k * n + p], akq = A[(size_t)k * n + q];
          A[(size_t)k * n + p] = c * akp - s * akq;
          A[(size_t)k * n + q] = s * akp + c * akq;
        }
        for (int k = 0; k < n; ++k) {
          const double apk = A[(size_t)p * n + k], aqk = A[(size_t)q * n + k];
          A[(size_t)p * n + k] = c * apk - s * aqk;
          A[(size_t)q * n + k] = s * apk + c * aqk;
        }
        for (int k = 0; k < n; ++k) {
          const double vkp = V[(size_t)k * n + p], vkq = V[(size_t)k * n + q];
          V[(size_t)k * n + p] = c * vkp - s * vkq;
          V[(size_t)k * n + q] = s * vkp + c * vkq;
        }
      }
  }
  w.resize(n);
  for (int i = 0; i < n; ++i) w[i] = A[(size_t)i * n + i];
}

} // namespace

// The rigid-body motions a patch is free to make are exact null vectors of its Schur complement,
// but the cancellation in K_BB - K_BI K_II^-1 K_IB leaves them a round-off stiffness. Where such a
// motion is carried by a single port dof, the interface matrix then has a row of round-off that
// MUMPS's scaling turns into an ordinary pivot, and a mechanism (that patch held by a joint with no
// stiffness in that direction) goes undetected. For a patch that is a whole part, the free motions
// are known from the geometry: the
// rigid motions (t, w) that leave every prescribed dof inside the patch at zero. S is projected off
// them (S <- P S P) and the entries left at round-off are set to zero, which restores the exact
// null space.
void ProjectFreeRigidMotions(const ShellPatch &p, CondensedPatch *cp)
{
  const PetscInt nb = cp->nb, nmesh = (PetscInt)p.mesh.x.size();
  // A patch cut from a larger part holds only its share of the elements it shares with other
  // patches (patch.hpp): those blocks alone resist a rigid motion of the patch, so its S has no
  // such null vector; the mechanism, if any, shows only with the seams, in the interface matrix.
  if (nb == 0 || !p.shared.empty()) return;
  auto pos = [&](PetscInt node) { return node < nmesh ? p.mesh.x[node] : p.joint_nodes[node - nmesh].x; };
  std::array<double, 3> c{0, 0, 0};
  for (int n : p.carried)
    for (int k = 0; k < 3; ++k) c[k] += pos(n)[k] / (double)p.carried.size();
  double L = 0;
  for (int n : p.carried)
    for (int k = 0; k < 3; ++k) L = std::max(L, std::fabs(pos(n)[k] - c[k]));
  if (L == 0) L = 1;
  // The value of dof `comp` at point y under the rigid motion with parameters a (a[0..2]: the
  // translation of c, a[3..5]: the rotation times L), as a row of 6 coefficients.
  auto row = [&](const std::array<double, 3> &y, int comp, double r[6]) {
    const double d[3] = {y[0] - c[0], y[1] - c[1], y[2] - c[2]};
    for (int k = 0; k < 6; ++k) r[k] = 0;
    if (comp >= 3) {
      r[comp] = 1 / L;
      return;
    }
    r[comp] = 1; // u = t + w x d
    const int i = (comp + 1) % 3, j = (comp + 2) % 3;
    r[3 + i] = d[j] / L; // (w x d)_comp = w_i d_j - w_j d_i
    r[3 + j] = -d[i] / L;
  };
  std::vector<double> CtC(36, 0.0), w, V;
  for (const auto &[dof, v] : cp->prescribed) {
    double r[6];
    row(pos(dof / 6), (int)(dof % 6), r);
    for (int k = 0; k < 6; ++k)
      for (int l = 0; l < 6; ++l) CtC[6 * k + l] += r[k] * r[l];
  }
  SymmetricEigen(6, CtC, w, V);
  double wmax = 0;
  for (double v : w) wmax = std::max(wmax, std::fabs(v));
  std::vector<std::vector<double>> N; // the free motions on the ports, orthonormal
  for (int k = 0; k < 6; ++k) {
    if (std::fabs(w[k]) > 1e-10 * wmax && wmax > 0) continue;
    std::vector<double> n(nb, 0.0);
    for (size_t q = 0; q < p.carried.size(); ++q)
      for (int comp = 0; comp < 6; ++comp) {
        double r[6];
        row(pos(p.carried[q]), comp, r);
        for (int l = 0; l < 6; ++l) n[6 * q + comp] += r[l] * V[(size_t)l * 6 + k];
      }
    for (const auto &m : N) {
      double dot = 0;
      for (PetscInt i = 0; i < nb; ++i) dot += n[i] * m[i];
      for (PetscInt i = 0; i < nb; ++i) n[i] -= dot * m[i];
    }
    double nrm = 0;
    for (double v : n) nrm += v * v;
    if (nrm < 1e-20) continue; // no trace on the ports (a rotation about a single port node's axis...)
    for (double &v : n) v /= std::sqrt(nrm);
    N.push_back(std::move(n));
  }
  if (N.empty()) return;
  double smax = 0;
  for (double v : cp->S) smax = std::max(smax, std::fabs(v));
  // S <- (I - n n^T) S (I - n n^T) for each free motion n (orthonormal, so one after the other).
  std::vector<double> Sn(nb);
  for (const auto &n : N) {
    for (PetscInt i = 0; i < nb; ++i) {
      double s = 0;
      for (PetscInt j = 0; j < nb; ++j) s += cp->S[(size_t)i * nb + j] * n[j];
      Sn[i] = s;
    }
    double nSn = 0;
    for (PetscInt i = 0; i < nb; ++i) nSn += n[i] * Sn[i];
    for (PetscInt i = 0; i < nb; ++i)
      for (PetscInt j = 0; j < nb; ++j) cp->S[(size_t)i * nb + j] += -Sn[i] * n[j] - n[i] * Sn[j] + nSn * n[i] * n[j];
  }
  for (double &v : cp->S)
    if (std::fabs(v) < 1e-13 * smax) v = 0;
  cp->free_motions = (PetscInt)N.size();
}

PetscErrorCode CondensePatch(const ShellPatch &p, CouplingType type, double penalty, double radius, const PatchLoads &loads, CondensedPatch *cp)
{
  PetscFunctionBeginUser;
  const PetscInt ndof = 6 * p.nnodes(), nmesh = (PetscInt)p.mesh.x.size();
  // Classes of the patch dof: row of K (>= 0: interior rows first, then the ports), or -1 for a
  // slave, -2 for a prescribed interior dof.
  std::vector<PetscInt> row(ndof, -1);
  PetscCall(PetscLogEventBegin(Events().patch_matrix, 0, 0, 0, 0));
  if (type == CouplingType::Exact) cp->slaves = ExactSlaves(p);
  std::vector<char> port(p.nnodes(), 0);
  for (int n : p.carried) port[n] = 1;
  cp->nb = 6 * (PetscInt)p.carried.size();
  cp->interior.clear();
  cp->prescribed.clear();
  for (PetscInt d = 0; d < ndof; ++d) {
    const PetscInt node = d / 6;
    if (port[node]) continue;
    if (node < nmesh && !cp->slaves.master.empty() && cp->slaves.master[node] >= 0) continue; // slave
    auto pr = loads.prescribed.find(d);
    if (pr != loads.prescribed.end()) {
      row[d]             = -2;
      cp->prescribed[d] = pr->second;
      continue;
    }
    row[d] = (PetscInt)cp->interior.size();
    cp->interior.push_back(d);
  }
  cp->ni = (PetscInt)cp->interior.size();
  for (size_t k = 0; k < p.carried.size(); ++k)
    for (int c = 0; c < 6; ++c) row[6 * p.carried[k] + c] = cp->ni + 6 * (PetscInt)k + c;
  const PetscInt n = cp->ni + cp->nb;

  // K over I and B; the entries of K in the columns of D are kept for the load terms
  // (CondensedPatchLoads), which change from one load case to the next.
  Triplets              t = PatchTriplets(p, type, penalty, radius, false);
  cp->kd.clear();
  for (const auto &[r, c, v] : t)
    if (row[r] >= 0 && row[c] == -2) cp->kd.push_back({row[r], c, v});
  {
    // K is kept for the run (the interiors' recovery multiplies by it), so it is allocated at its
    // size: the triplets repeat an entry once per element and per footprint node eliminated into
    // it, and SeqAIJ assembly keeps the room a preallocation by triplets would have reserved.
    const PatchOperator k = CompressRows(n, t, row);
    PetscCall(MatCreate(PETSC_COMM_SELF, cp->K.out()));
    PetscCall(MatSetSizes(cp->K.get(), n, n, n, n));
    PetscCall(MatSetType(cp->K.get(), MATSEQAIJ));
    PetscCall(MatSeqAIJSetPreallocationCSR(cp->K.get(), k.rowptr.data(), k.cols.data(), k.vals.data())); // assembles it
  }
  cp->row = std::move(row);
  Mat K   = cp->K.get();
  PetscCall(MatSetOption(K, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(PetscLogEventEnd(Events().patch_matrix, 0, 0, 0, 0));
  cp->S.assign((size_t)cp->nb * cp->nb, 0.0);

  if (cp->ni == 0) { // every dof is a port: S is K itself
    for (PetscInt r = 0; r < n; ++r) {
      PetscInt           nc;
      const PetscInt    *cols;
      const PetscScalar *vals;
      PetscCall(MatGetRow(K, r, &nc, &cols, &vals));
      for (PetscInt k = 0; k < nc; ++k) cp->S[(size_t)r * cp->nb + cols[k]] = vals[k];
      PetscCall(MatRestoreRow(K, r, &nc, &cols, &vals));
    }
    PetscCall(CondensedPatchLoads(p.id, loads, cp));
    PetscFunctionReturn(0);
  }

  ISHandle isB;
  PetscCall(ISCreateStride(PETSC_COMM_SELF, cp->nb, cp->ni, 1, isB.out()));
  // MUMPS sizes its integer workspace at the analysis from its estimate plus ICNTL(14) per cent; a
  // Schur complement larger than the interior (a small patch with many ports) makes that estimate
  // short (INFOG(1) = -8 or -9, seen on 36-node patches): analyse and factor again with more room.
  PetscInt infog1 = 0, nullpivots = 0;
  for (PetscInt relax = 50;; relax *= 4) {
    MatFactorInfo info;
    PetscCall(MatGetFactor(K, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, cp->F.out()));
    PetscCall(MatMumpsSetIcntl(cp->F.get(), 14, relax));
    PetscCall(MatMumpsSetIcntl(cp->F.get(), 24, 1)); // detect null pivots: a singular interior is reported, not factored
    PetscCall(MatFactorSetSchurIS(cp->F.get(), isB.get()));
    PetscCall(MatFactorInfoInitialize(&info));
    PetscCall(MatCholeskyFactorSymbolic(cp->F.get(), K, nullptr, &info));
    PetscCall(MatCholeskyFactorNumeric(cp->F.get(), K, &info));
    PetscCall(MatMumpsGetInfog(cp->F.get(), 1, &infog1));
    if (!(infog1 == -8 || infog1 == -9) || relax > 5000) break;
  }
  Mat            F = cp->F.get();
  MatFactorError ferr;
  PetscCall(MatFactorGetError(F, &ferr));
  PetscCall(MatMumpsGetInfog(F, 28, &nullpivots));
  PetscCheck(infog1 >= 0 || infog1 == -10, PETSC_COMM_SELF, PETSC_ERR_LIB, "Patch of part %" PetscInt_FMT " (%" PetscInt_FMT " nodes): MUMPS failed to factor its interior (INFOG(1) = %" PetscInt_FMT ")", p.id, p.nnodes(), infog1);
  PetscCheck(ferr == MAT_FACTOR_NOERROR && nullpivots == 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
             "Patch of part %" PetscInt_FMT " (%" PetscInt_FMT " nodes): its interior is singular (%" PetscInt_FMT " null pivots): some of it is held by no joint, seam or support (a mechanism, or a mesh island)", p.id, p.nnodes(), nullpivots);
  PetscCall(PetscLogEventBegin(Events().schur, 0, 0, 0, 0));
  {
    Mat                S;
    const PetscScalar *s;
    PetscCall(MatFactorCreateSchurComplement(F, &S, nullptr));
    PetscCall(MatDenseGetArrayRead(S, &s)); // column major; S is symmetric
    for (PetscInt j = 0; j < cp->nb; ++j)
      for (PetscInt i = 0; i < cp->nb; ++i) cp->S[(size_t)i * cp->nb + j] = s[(size_t)j * cp->nb + i];
    PetscCall(MatDenseRestoreArrayRead(S, &s));
    PetscCall(MatDestroy(&S));
  }
  ProjectFreeRigidMotions(p, cp);
  PetscCall(PetscLogEventEnd(Events().schur, 0, 0, 0, 0));
  PetscCall(PetscInfo(nullptr, "patch of part %" PetscInt_FMT ": %" PetscInt_FMT " interior and %" PetscInt_FMT " port dof, %" PetscInt_FMT " free rigid-body motions\n", p.id, cp->ni, cp->nb, cp->free_motions));
  PetscCall(MatMumpsSetIcntl(F, 26, 0)); // from now on MatSolve solves with K_II alone
  PetscCall(CondensedPatchLoads(p.id, loads, cp));
  PetscInt factor_mb = 0;
  PetscCall(MatMumpsGetInfog(F, 22, &factor_mb)); // MB of MUMPS working memory at the factorisation
  MatInfo kinfo;
  PetscCall(MatGetInfo(K, MAT_LOCAL, &kinfo));
  cp->bytes = 8.0 * (double)cp->S.size() + 1e6 * (double)factor_mb + kinfo.memory + (double)(sizeof(PetscInt) * cp->row.size() + sizeof(cp->kd[0]) * cp->kd.size());
  PetscFunctionReturn(0);
}

PetscErrorCode CondensedPatchLoads(PetscInt id, const PatchLoads &loads, CondensedPatch *cp)
{
  PetscFunctionBeginUser;
  const PetscInt n = cp->ni + cp->nb;
  // The split of the patch's dof was made for the supports it was condensed with: a load case may
  // change their values and the forces, not which dof are held.
  size_t held = 0, interior = 0; // prescribed dof: held inside the patch before, and interior unknowns then
  for (const auto &[d, v] : loads.prescribed) {
    const PetscInt r = d < (PetscInt)cp->row.size() ? cp->row[d] : -1;
    held += r == -2;
    interior += r >= 0 && r < cp->ni;
  }
  PetscCheck(interior == 0 && held == cp->prescribed.size(), PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP, "Patch of part %" PetscInt_FMT ": these loads hold other dof than those it was condensed with (%zu of its interior then, %zu now): a load case may change prescribed values and forces, not which dof are fixed or prescribed", id, cp->prescribed.size(), held + interior);
  for (auto &[d, v] : cp->prescribed) v = loads.prescribed.at(d);
  // -K_ID u_D (interior) and -K_BD u_D (ports), summed with the sign of a force.
  std::vector<double> rI(cp->ni, 0.0), cB(cp->nb, 0.0);
  for (const auto &[R, d, v] : cp->kd) (R < cp->ni ? rI[R] : cB[R - cp->ni]) -= v * cp->prescribed.at(d);
  for (const auto &[d, f] : loads.force)
    if (cp->row[d] >= 0 && cp->row[d] < cp->ni) rI[cp->row[d]] += f; // forces on the ports are the network's
  // The internal force on the ports is +K_BD u_D, then + K_BI w0.
  cp->c.assign(cp->nb, 0.0);
  cp->w0.assign(cp->ni, 0.0);
  for (PetscInt b = 0; b < cp->nb; ++b) cp->c[b] = -cB[b];
  bool loaded = false;
  for (double v : rI) loaded = loaded || v != 0;
  if (!loaded) PetscFunctionReturn(0);
  Mat       K = cp->K.get();
  VecHandle b, x, y;
  PetscCall(MatCreateVecs(K, x.out(), b.out()));
  PetscCall(VecDuplicate(b.get(), y.out()));
  PetscScalar *bb;
  PetscCall(VecGetArray(b.get(), &bb));
  for (PetscInt i = 0; i < n; ++i) bb[i] = i < cp->ni ? rI[i] : 0.0;
  PetscCall(VecRestoreArray(b.get(), &bb));
  PetscCall(MatSolve(cp->F.get(), b.get(), x.get())); // K_II alone (ICNTL(26) = 0)
  PetscScalar *xx;
  PetscCall(VecGetArray(x.get(), &xx));
  for (PetscInt i = 0; i < cp->ni; ++i) cp->w0[i] = xx[i];
  for (PetscInt i = cp->ni; i < n; ++i) xx[i] = 0.0;
  PetscCall(VecRestoreArray(x.get(), &xx));
  PetscCall(MatMult(K, x.get(), y.get())); // K_BI w0 in the port rows
  const PetscScalar *yy;
  PetscCall(VecGetArrayRead(y.get(), &yy));
  for (PetscInt b2 = 0; b2 < cp->nb; ++b2) cp->c[b2] += yy[cp->ni + b2];
  PetscCall(VecRestoreArrayRead(y.get(), &yy));
  PetscFunctionReturn(0);
}

PetscErrorCode RecoverPatch(const ShellPatch &p, const CondensedPatch &cp, PetscReal lambda, const PetscScalar *uB, std::vector<double> &u)
{
  PetscFunctionBeginUser;
  const PetscInt nmesh = (PetscInt)p.mesh.x.size();
  u.assign(6 * (size_t)p.nnodes(), 0.0);
  for (size_t k = 0; k < p.carried.size(); ++k)
    for (int c = 0; c < 6; ++c) u[6 * p.carried[k] + c] = uB[6 * k + c];
  for (const auto &[d, v] : cp.prescribed) u[d] = lambda * v;
  for (const auto &[d, v] : cp.prescribed_held) u[d] += v;
  if (cp.ni > 0) {
    // u_I = lambda w0 (+ w0_held) - K_II^-1 K_IB u_B
    Mat       K = cp.K.get();
    VecHandle x, y, z;
    PetscCall(MatCreateVecs(K, x.out(), y.out()));
    PetscCall(VecDuplicate(x.get(), z.out()));
    PetscScalar *xx;
    PetscCall(VecGetArray(x.get(), &xx));
    for (PetscInt i = 0; i < cp.ni; ++i) xx[i] = 0.0;
    for (PetscInt b = 0; b < cp.nb; ++b) xx[cp.ni + b] = uB[b];
    PetscCall(VecRestoreArray(x.get(), &xx));
    PetscCall(MatMult(K, x.get(), y.get()));
    PetscCall(MatSolve(cp.F.get(), y.get(), z.get()));
    const PetscScalar *zz;
    PetscCall(VecGetArrayRead(z.get(), &zz));
    for (PetscInt i = 0; i < cp.ni; ++i) u[cp.interior[i]] = lambda * cp.w0[i] + (cp.w0_held.empty() ? 0.0 : cp.w0_held[i]) - zz[i];
    PetscCall(VecRestoreArrayRead(z.get(), &zz));
  }
  for (PetscInt nd = 0; nd < nmesh && !cp.slaves.master.empty(); ++nd) {
    const PetscInt m = cp.slaves.master[nd];
    if (m < 0) continue;
    for (int i = 0; i < 6; ++i) {
      double s = 0;
      for (int j = 0; j < 6; ++j) s += cp.slaves.T[nd][6 * i + j] * u[6 * m + j];
      u[6 * nd + i] = s;
    }
  }
  PetscFunctionReturn(0);
}

} // namespace boltnet
