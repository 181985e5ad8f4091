// Test harness for the shell elements: meshes and a sequential PETSc solve (see shell_harness.hpp).
#include "shell_harness.hpp"

#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#define CHK(call)                                                                                               \
  do {                                                                                                          \
    PetscErrorCode ierr_ = (call);                                                                              \
    if (ierr_) throw std::runtime_error(std::string("PETSc error ") + std::to_string(ierr_) + " in " #call); \
  } while (0)

namespace shelltest {

const char *KindName(MeshKind k)
{
  switch (k) {
  case MeshKind::Quads: return "quadrilaterals";
  case MeshKind::Triangles: return "triangles";
  case MeshKind::Mixed: return "mixed";
  }
  return "?";
}

Mesh Split(const Mesh &quads, MeshKind kind, const std::vector<int> &parity, const std::vector<int> &diag)
{
  Mesh m  = quads;
  m.elems.clear();
  for (size_t e = 0; e < quads.elems.size(); ++e) {
    const std::vector<int> &q = quads.elems[e];
    const bool split = q.size() == 4 && (kind == MeshKind::Triangles || (kind == MeshKind::Mixed && parity[e]));
    if (!split) {
      m.elems.push_back(q);
      continue;
    }
    if ((e < diag.size() ? diag[e] : int(e)) % 2 == 0) { // diagonal 0-2
      m.elems.push_back({q[0], q[1], q[2]});
      m.elems.push_back({q[0], q[2], q[3]});
    } else { // diagonal 1-3
      m.elems.push_back({q[0], q[1], q[3]});
      m.elems.push_back({q[1], q[2], q[3]});
    }
  }
  return m;
}

Mesh Grid(int nx, int ny, const std::function<Vec3(double, double)> &map, MeshKind kind, bool periodic)
{
  Mesh m;
  m.nx       = nx;
  m.ny       = ny;
  m.periodic = periodic;
  for (int j = 0; j <= (periodic ? ny - 1 : ny); ++j)
    for (int i = 0; i <= nx; ++i) m.X.push_back(map(double(i) / nx, double(j) / ny));
  std::vector<int> parity, diag;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      m.elems.push_back({m.Node(i, j), m.Node(i + 1, j), m.Node(i + 1, j + 1), m.Node(i, j + 1)});
      parity.push_back((i + j) % 2);
      diag.push_back(kind == MeshKind::Mixed ? j : i + j);
    }
  return kind == MeshKind::Quads ? m : Split(m, kind, parity, diag);
}

Problem::Problem(Mesh m, ShellMaterial s, const Discretization &setup)
    : mesh(std::move(m)), mat(s), opt(setup.opt), F(6 * mesh.X.size(), 0.0), surface_directors(setup.surface_directors)
{
}

std::vector<Vec3> Problem::Directors() const
{
  if (!surface_directors) return {};
  if (!normal) throw std::logic_error("surface directors asked for a problem without a surface normal");
  std::vector<Vec3> V(mesh.X.size());
  for (size_t n = 0; n < V.size(); ++n) V[n] = normal(mesh.X[n]);
  // Orient along the elements' normals (the map's normal may point either way).
  for (const auto &e : mesh.elems) {
    const Vec3 &a = mesh.X[e[0]], &b = mesh.X[e[1]], &c = mesh.X[e[2]];
    const Vec3  u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const Vec3  n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    for (int i : e) {
      Vec3 &d = V[i];
      if (d[0] * n[0] + d[1] * n[1] + d[2] * n[2] < 0) d = Vec3{-d[0], -d[1], -d[2]};
    }
  }
  return V;
}

void Problem::SurfaceLoad(const Vec3 &q)
{
  for (const auto &e : mesh.elems) {
    std::vector<Vec3>   X;
    std::vector<double> Fe(6 * e.size());
    for (int i : e) X.push_back(mesh.X[i]);
    ElementLoad(int(e.size()), X.data(), q, Fe.data());
    for (size_t n = 0; n < e.size(); ++n)
      for (int k = 0; k < 6; ++k) F[6 * e[n] + k] += Fe[6 * n + k];
  }
}

std::vector<double> Solve(const Problem &p)
{
  const size_t   nn = p.mesh.X.size();
  const PetscInt n  = 6 * PetscInt(nn);
  // Exact preallocation from the node adjacency.
  std::vector<std::set<int>> adj(nn);
  for (const auto &e : p.mesh.elems)
    for (int a : e)
      for (int b : e) adj[a].insert(b);
  std::vector<PetscInt> nnz(n);
  for (size_t i = 0; i < nn; ++i)
    for (int k = 0; k < 6; ++k) nnz[6 * i + k] = 6 * PetscInt(adj[i].size());
  Mat A;
  CHK(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 0, nnz.data(), &A));
  const std::vector<Vec3> V = p.Directors();
  for (const auto &e : p.mesh.elems) {
    const int             ne = int(e.size());
    std::vector<Vec3>     X, Ve;
    std::vector<double>   K(36 * ne * ne);
    std::vector<PetscInt> idx;
    for (int i : e) {
      X.push_back(p.mesh.X[i]);
      if (!V.empty()) Ve.push_back(V[i]);
      for (int k = 0; k < 6; ++k) idx.push_back(6 * i + k);
    }
    ElementStiffness(ne, X.data(), V.empty() ? nullptr : Ve.data(), p.mat, p.opt, K.data());
    CHK(MatSetValues(A, 6 * ne, idx.data(), 6 * ne, idx.data(), K.data(), ADD_VALUES));
  }
  for (const auto &pen : p.penalties) {
    PetscInt    idx[6];
    PetscScalar K[36];
    for (int a = 0; a < 6; ++a) {
      idx[a] = 6 * pen.node + a;
      for (int b = 0; b < 6; ++b) K[6 * a + b] = pen.k * pen.c[a] * pen.c[b];
    }
    CHK(MatSetValues(A, 6, idx, 6, idx, K, ADD_VALUES));
  }
  CHK(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  CHK(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  Vec b, x;
  CHK(VecCreateSeq(PETSC_COMM_SELF, n, &b));
  CHK(VecDuplicate(b, &x));
  PetscScalar *bb, *xx;
  CHK(VecGetArray(b, &bb));
  CHK(VecGetArray(x, &xx));
  std::vector<PetscInt> rows;
  for (PetscInt i = 0; i < n; ++i) {
    bb[i] = p.F[i];
    xx[i] = 0;
  }
  for (const auto &[dof, value] : p.fixed) {
    rows.push_back(PetscInt(dof));
    xx[dof] = value;
  }
  CHK(VecRestoreArray(b, &bb));
  CHK(VecRestoreArray(x, &xx));
  CHK(MatZeroRowsColumns(A, PetscInt(rows.size()), rows.data(), 1.0, x, b));
  KSP ksp;
  PC  pc;
  CHK(KSPCreate(PETSC_COMM_SELF, &ksp));
  CHK(KSPSetOperators(ksp, A, A));
  CHK(KSPSetType(ksp, KSPPREONLY));
  CHK(KSPGetPC(ksp, &pc));
  CHK(PCSetType(pc, PCLU));
  CHK(KSPSetErrorIfNotConverged(ksp, PETSC_TRUE));
  CHK(KSPSolve(ksp, b, x));
  std::vector<double> u(n);
  const PetscScalar  *xr;
  CHK(VecGetArrayRead(x, &xr));
  for (PetscInt i = 0; i < n; ++i) u[i] = xr[i];
  CHK(VecRestoreArrayRead(x, &xr));
  CHK(KSPDestroy(&ksp));
  CHK(VecDestroy(&b));
  CHK(VecDestroy(&x));
  CHK(MatDestroy(&A));
  return u;
}

std::vector<double> Gather(const std::vector<double> &u, const std::vector<int> &elem)
{
  std::vector<double> ue;
  for (int a : elem)
    for (int k = 0; k < 6; ++k) ue.push_back(u[6 * a + k]);
  return ue;
}

GeneralisedStrains Strains(const Problem &p, const std::vector<double> &u, size_t e, double a, double b)
{
  const std::vector<int>   &el = p.mesh.elems[e];
  const std::vector<double> ue = Gather(u, el);
  const std::vector<Vec3>   V  = p.Directors();
  if (el.size() == 4) {
    const Nodes   X{p.mesh.X[el[0]], p.mesh.X[el[1]], p.mesh.X[el[2]], p.mesh.X[el[3]]};
    ElementVector uq;
    std::copy(ue.begin(), ue.end(), uq.begin());
    if (V.empty()) return ElementStrains(X, nullptr, p.mat, p.opt, uq, a, b);
    const boltnet::shell::Directors Vq{V[el[0]], V[el[1]], V[el[2]], V[el[3]]};
    return ElementStrains(X, &Vq, p.mat, p.opt, uq, a, b);
  }
  const TriNodes X{p.mesh.X[el[0]], p.mesh.X[el[1]], p.mesh.X[el[2]]};
  TriVector      ut;
  std::copy(ue.begin(), ue.end(), ut.begin());
  if (V.empty()) return ElementStrains(X, nullptr, p.mat, p.opt, ut, a, b);
  const TriDirectors Vt{V[el[0]], V[el[1]], V[el[2]]};
  return ElementStrains(X, &Vt, p.mat, p.opt, ut, a, b);
}

} // namespace shelltest
