// Shell element (issue 3, item 1) through a global solve: patch tests, laminate against CLT, square
// plates, and the MacNeal-Harder / Belytschko benchmarks (Scordelis-Lo roof, pinched cylinder, pinched
// hemisphere), with the symmetry models checked against full models.
//
// The harness (structured quad meshes, sequential PETSc AIJ assembly, BCs by row/column elimination,
// LU) is test code: the network assembly has its own. Run with --table to print the convergence
// tables instead of running the tests (scripts/shell-convergence writes them to docs/).
//   build/bin/test_shell_solve                          # the tests
//   build/bin/test_shell_solve --table > docs/shell-convergence.md
#include "shell/shell.hpp"

#include <gtest/gtest.h>
#include <petscksp.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

using namespace boltnet::shell;

#define CHK(call)                                                                                  \
  do {                                                                                             \
    PetscErrorCode ierr_ = (call);                                                                 \
    if (ierr_) throw std::runtime_error(std::string("PETSc error ") + std::to_string(ierr_) + " in " #call); \
  } while (0)

namespace {

constexpr double kPi = 3.14159265358979323846;
enum { UX = 0, UY, UZ, RX, RY, RZ };

ElementOptions Drill(double drill, Membrane membrane = ElementOptions{}.membrane)
{
  ElementOptions o;
  o.drill = drill;
  o.membrane = membrane;
  return o;
}

struct Mesh {
  std::vector<Vec3> X;
  std::vector<std::array<int, 4>> quads;
  int nx = 0, ny = 0;       // structured meshes: node (i, j) = j (nx + 1) + i
  bool periodic = false;    // in t: row ny is row 0 (a closed cylinder or sphere)
  int Node(int i, int j) const { return (periodic ? j % ny : j) * (nx + 1) + i; }
};

// A structured nx x ny mesh of the map (s, t) in [0,1]^2 -> R^3; elements counter-clockwise in (s, t).
// periodic: t = 1 is t = 0 (the map must agree), the mesh closes on itself.
Mesh Grid(int nx, int ny, const std::function<Vec3(double, double)> &map, bool periodic = false)
{
  Mesh m;
  m.nx = nx;
  m.ny = ny;
  m.periodic = periodic;
  for (int j = 0; j <= (periodic ? ny - 1 : ny); ++j)
    for (int i = 0; i <= nx; ++i) m.X.push_back(map(double(i) / nx, double(j) / ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) m.quads.push_back({m.Node(i, j), m.Node(i + 1, j), m.Node(i + 1, j + 1), m.Node(i, j + 1)});
  return m;
}

struct Problem {
  Mesh mesh;
  ShellMaterial mat;
  ElementOptions opt;                  // drilling factor, membrane interpolation
  std::vector<double> F;               // nodal forces, 6 per node
  std::map<PetscInt, double> fixed;    // prescribed dof -> value
  Problem(Mesh m, ShellMaterial s) : mesh(std::move(m)), mat(s), F(6 * mesh.X.size(), 0.0) {}
  void Fix(int node, int comp, double value = 0) { fixed[6 * node + comp] = value; }
  void FixAll(int node, std::initializer_list<int> comps)
  {
    for (int c : comps) Fix(node, c);
  }
  Nodes ElementNodes(const std::array<int, 4> &q) const
  {
    return {mesh.X[q[0]], mesh.X[q[1]], mesh.X[q[2]], mesh.X[q[3]]};
  }
  // Force per unit area q (global) on every element.
  void SurfaceLoad(const Vec3 &q)
  {
    for (const auto &quad : mesh.quads) {
      ElementVector Fe;
      ElementLoad(ElementNodes(quad), q, Fe);
      for (int n = 0; n < 4; ++n)
        for (int k = 0; k < 6; ++k) F[6 * quad[n] + k] += Fe[6 * n + k];
    }
  }
};

// Assemble K, eliminate prescribed dofs (rows and columns), solve by LU. Returns all nodal dofs.
std::vector<double> Solve(const Problem &p)
{
  const PetscInt n = 6 * PetscInt(p.mesh.X.size());
  Mat A;
  CHK(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 54, nullptr, &A));
  for (const auto &q : p.mesh.quads) {
    ElementMatrix K;
    ElementStiffness(p.ElementNodes(q), p.mat, p.opt, K);
    PetscInt idx[24];
    for (int a = 0; a < 4; ++a)
      for (int k = 0; k < 6; ++k) idx[6 * a + k] = 6 * q[a] + k;
    CHK(MatSetValues(A, 24, idx, 24, idx, K.data(), ADD_VALUES));
  }
  CHK(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  CHK(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  Vec b, x;
  CHK(VecCreateSeq(PETSC_COMM_SELF, n, &b));
  CHK(VecDuplicate(b, &x));
  double *bb, *xx;
  CHK(VecGetArray(b, &bb));
  CHK(VecGetArray(x, &xx));
  std::vector<PetscInt> rows;
  for (PetscInt i = 0; i < n; ++i) {
    bb[i] = p.F[i];
    xx[i] = 0;
  }
  for (const auto &[dof, value] : p.fixed) {
    rows.push_back(dof);
    xx[dof] = value;
  }
  CHK(VecRestoreArray(b, &bb));
  CHK(VecRestoreArray(x, &xx));
  CHK(MatZeroRowsColumns(A, PetscInt(rows.size()), rows.data(), 1.0, x, b));
  KSP ksp;
  PC pc;
  CHK(KSPCreate(PETSC_COMM_SELF, &ksp));
  CHK(KSPSetOperators(ksp, A, A));
  CHK(KSPSetType(ksp, KSPPREONLY));
  CHK(KSPGetPC(ksp, &pc));
  CHK(PCSetType(pc, PCLU));
  CHK(KSPSetErrorIfNotConverged(ksp, PETSC_TRUE));
  CHK(KSPSolve(ksp, b, x));
  std::vector<double> u(n);
  const double *xr;
  CHK(VecGetArrayRead(x, &xr));
  for (PetscInt i = 0; i < n; ++i) u[i] = xr[i];
  CHK(VecRestoreArrayRead(x, &xr));
  CHK(KSPDestroy(&ksp));
  CHK(VecDestroy(&b));
  CHK(VecDestroy(&x));
  CHK(MatDestroy(&A));
  return u;
}

ElementVector Gather(const std::vector<double> &u, const std::array<int, 4> &q)
{
  ElementVector ue;
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 6; ++k) ue[6 * a + k] = u[6 * q[a] + k];
  return ue;
}

// ---------------------------------------------------------------------------------------------------
// Benchmarks. Each returns the displacement the reference quotes (same sign convention as the
// reference: positive). n = elements per side of the symmetry model.

// Scordelis-Lo roof (MacNeal & Harder): R = 25, L = 50, +-40 deg, t = 0.25, E = 4.32e8, nu = 0, self
// weight 90 per unit area, rigid diaphragms at the ends. Axis along x, crown at y = 0, z = R.
// Quarter model (x in [0, 25], phi in [0, 40 deg]) or full model (2n x 2n, the same nodes mirrored).
struct RoofOptions {
  bool full = false;           // the whole roof instead of the quarter
  bool free_crown_normal = false; // quarter model without theta_z = 0 on the crown plane y = 0 (wrong)
  double distortion = 0;       // interior nodes moved along the surface by up to this fraction of an element
};
double ScordelisLo(int n, ElementOptions o, RoofOptions r = {})
{
  const double R = 25, L = 50, phi0 = 40 * kPi / 180;
  const bool full = r.full;
  const int m = full ? 2 * n : n;
  Mesh mesh = Grid(m, m, [&](double s, double t) {
    if (s > 0 && s < 1 && t > 0 && t < 1 && r.distortion > 0) { // smooth-free, node-to-node irregularity
      const int i = int(std::lround(s * m)), j = int(std::lround(t * m));
      s += r.distortion / m * (((i * 7 + j * 3) % 5) / 2.0 - 1);
      t += r.distortion / m * (((i * 3 + j * 11) % 5) / 2.0 - 1);
    }
    const double x = full ? L * s : L / 2 * s, phi = full ? phi0 * (2 * t - 1) : phi0 * t;
    return Vec3{x, R * std::sin(phi), R * std::cos(phi)};
  });
  Problem p(mesh, IsotropicMaterial(4.32e8, 0.0, 0.25));
  p.opt = o;
  p.SurfaceLoad({0, 0, -90});
  for (int j = 0; j <= m; ++j) {
    p.FixAll(mesh.Node(0, j), {UY, UZ}); // diaphragm at x = 0
    if (full) p.FixAll(mesh.Node(m, j), {UY, UZ});
    else p.FixAll(mesh.Node(m, j), {UX, RY, RZ}); // symmetry plane x = L/2 (normal x)
  }
  if (!full)
    for (int i = 0; i <= m; ++i) {
      p.FixAll(mesh.Node(i, 0), {UY, RX}); // symmetry plane y = 0 (normal y)
      if (!r.free_crown_normal) p.Fix(mesh.Node(i, 0), RZ);
    }
  else p.Fix(mesh.Node(n, n), UX); // the axial rigid translation
  const std::vector<double> u = Solve(p);
  return -u[6 * mesh.Node(full ? n : m, m) + UZ]; // free edge (phi = +40 deg), mid-span
}

// Pinched cylinder (MacNeal & Harder): R = 300, L = 600, t = 3, E = 3e6, nu = 0.3, diaphragms at both
// ends, two opposite radial loads P = 1 at mid-length. One eighth: x in [0, 300] (diaphragm at x = 0,
// symmetry at x = 300), theta in [0, 90 deg] from the load (top, z = R) to the plane z = 0.
// full: the whole cylinder (2n elements along the length, 4n around, closed), diaphragms at both ends,
// both loads, u_x fixed at one mid-length node (the axial rigid translation).
double PinchedCylinder(int n, ElementOptions o, bool full = false)
{
  const double R = 300, L = 600;
  Mesh mesh = full ? Grid(2 * n, 4 * n, [&](double s, double t) {
    const double th = 2 * kPi * t;
    return Vec3{L * s, R * std::sin(th), R * std::cos(th)};
  }, true)
                   : Grid(n, n, [&](double s, double t) {
    const double th = kPi / 2 * t;
    return Vec3{L / 2 * s, R * std::sin(th), R * std::cos(th)};
  });
  Problem p(mesh, IsotropicMaterial(3e6, 0.3, 3.0));
  p.opt = o;
  if (full) {
    for (int j = 0; j < 4 * n; ++j) {
      p.FixAll(mesh.Node(0, j), {UY, UZ});
      p.FixAll(mesh.Node(2 * n, j), {UY, UZ});
    }
    p.Fix(mesh.Node(n, n), UX);
    p.F[6 * mesh.Node(n, 0) + UZ] = -1;
    p.F[6 * mesh.Node(n, 2 * n) + UZ] = 1;
    const std::vector<double> u = Solve(p);
    return -u[6 * mesh.Node(n, 0) + UZ];
  }
  for (int j = 0; j <= n; ++j) {
    p.FixAll(mesh.Node(0, j), {UY, UZ});         // diaphragm
    p.FixAll(mesh.Node(n, j), {UX, RY, RZ});     // symmetry plane x = L/2
  }
  for (int i = 0; i <= n; ++i) {
    p.FixAll(mesh.Node(i, 0), {UY, RX, RZ}); // symmetry plane y = 0
    p.FixAll(mesh.Node(i, n), {UZ, RX, RY}); // symmetry plane z = 0
  }
  const int load = mesh.Node(n, 0);
  p.F[6 * load + UZ] = -0.25; // a quarter of P = 1 (the load point lies on two symmetry planes)
  const std::vector<double> u = Solve(p);
  return -u[6 * load + UZ];
}

// Pinched hemisphere (MacNeal & Harder): R = 10, t = 0.04, 18 deg hole, E = 6.825e7, nu = 0.3, radial
// loads of 2 on the equator alternately outward and inward. Quarter model: azimuth psi in [0, 90 deg]
// (s), polar angle from 90 deg (equator, t = 0) to 18 deg (hole, t = 1); symmetry planes y = 0 and
// x = 0; loads +1 along x at psi = 0, -1 along y at psi = 90 deg; u_z fixed at one equator node.
// full: the whole hemisphere (4n elements around, closed), loads of 2, rigid motions removed by
// u_y = 0 at psi = 0 and 180 deg, u_x = 0 at 90 deg, u_z = 0 at 45, 135 and 225 deg on the equator
// (all true of the symmetric solution, as in the quarter model).
double Hemisphere(int n, ElementOptions o, bool full = false)
{
  const double R = 10;
  const int ns = full ? 4 * n : n;
  auto map = [&](double t, double s) { // t: polar (0 equator .. 1 hole), s: azimuth fraction
    const double psi = (full ? 2 * kPi : kPi / 2) * s, th = kPi / 2 - (72 * kPi / 180) * t;
    return Vec3{R * std::sin(th) * std::cos(psi), R * std::sin(th) * std::sin(psi), R * std::cos(th)};
  };
  // Full: periodic in azimuth, which is the mesh's t direction; the quarter keeps azimuth along s.
  Mesh mesh = full ? Grid(n, ns, [&](double s, double t) { return map(s, t); }, true)
                   : Grid(n, n, [&](double s, double t) { return map(t, s); });
  // node at azimuth index a (0 .. ns), polar index b (0 = equator)
  auto node = [&](int a, int b) { return full ? mesh.Node(b, a) : mesh.Node(a, b); };
  Problem p(mesh, IsotropicMaterial(6.825e7, 0.3, 0.04));
  p.opt = o;
  if (full) {
    p.Fix(node(0, 0), UY);
    p.Fix(node(2 * n, 0), UY);
    p.Fix(node(n, 0), UX);
    for (int a : {n / 2, 3 * n / 2, 5 * n / 2}) p.Fix(node(a, 0), UZ);
    p.F[6 * node(0, 0) + UX] = 2;
    p.F[6 * node(n, 0) + UY] = -2;
    p.F[6 * node(2 * n, 0) + UX] = -2;
    p.F[6 * node(3 * n, 0) + UY] = 2;
  } else {
    for (int j = 0; j <= n; ++j) {
      p.FixAll(node(0, j), {UY, RX, RZ}); // plane y = 0
      p.FixAll(node(n, j), {UX, RY, RZ}); // plane x = 0
    }
    p.Fix(node(n / 2, 0), UZ);
    p.F[6 * node(0, 0) + UX] = 1;
    p.F[6 * node(n, 0) + UY] = -1;
  }
  const std::vector<double> u = Solve(p);
  return u[6 * node(0, 0) + UX];
}

// Straight cantilever (MacNeal & Harder): L = 6, width 0.2, t = 0.1, E = 1e7, nu = 0.3, 6 x 1 regular
// elements, clamped at x = 0; unit tip load shared by the two tip nodes. load: 0 extension (x), 1
// in-plane shear (y), 2 out-of-plane shear (z), 3 twist (unit moment about x as a couple of z forces;
// returns the tip rotation).
double Cantilever(int load, ElementOptions o)
{
  Mesh mesh = Grid(6, 1, [](double s, double t) { return Vec3{6 * s, 0.2 * t - 0.1, 0}; });
  Problem p(mesh, IsotropicMaterial(1e7, 0.3, 0.1));
  p.opt = o;
  p.FixAll(mesh.Node(0, 0), {UX, UY, UZ, RX, RY, RZ});
  p.FixAll(mesh.Node(0, 1), {UX, UY, UZ, RX, RY, RZ});
  const int a = mesh.Node(6, 0), b = mesh.Node(6, 1);
  if (load < 3) {
    p.F[6 * a + load] = p.F[6 * b + load] = 0.5;
  } else {
    p.F[6 * a + UZ] = -5; // a couple: -5 at y = -0.1, +5 at y = +0.1, moment 1 about x
    p.F[6 * b + UZ] = 5;
  }
  const std::vector<double> u = Solve(p);
  if (load < 3) return 0.5 * (u[6 * a + load] + u[6 * b + load]);
  return (u[6 * b + UZ] - u[6 * a + UZ]) / 0.2;
}

// Square plate, side a = 1, t = 0.01 (a/t = 100), E = 1e7, nu = 0.3, uniform q = 1;
// quarter model; hard simple support (w = 0 and the rotation about the edge normal = 0) or clamped.
// Returns w_centre D / (q a^4).
double SquarePlate(int n, bool clamped, ElementOptions o = {})
{
  const double a = 1, t = 0.01, E = 1e7, nu = 0.3, D = E * t * t * t / (12 * (1 - nu * nu));
  Mesh mesh = Grid(n, n, [&](double s, double r) { return Vec3{a / 2 * s, a / 2 * r, 0}; });
  Problem p(mesh, IsotropicMaterial(E, nu, t));
  p.opt = o;
  p.SurfaceLoad({0, 0, 1});
  for (int k = 0; k <= n; ++k) {
    // edges x = 0 and y = 0 are supported
    if (clamped) {
      p.FixAll(mesh.Node(0, k), {UZ, RX, RY});
      p.FixAll(mesh.Node(k, 0), {UZ, RX, RY});
    } else {
      p.FixAll(mesh.Node(0, k), {UZ, RX}); // edge along y: theta_x = dw/dy = 0
      p.FixAll(mesh.Node(k, 0), {UZ, RY}); // edge along x: theta_y = -dw/dx = 0
    }
    p.FixAll(mesh.Node(n, k), {UX, RY, RZ}); // symmetry x = a/2
    p.FixAll(mesh.Node(k, n), {UY, RX, RZ}); // symmetry y = a/2
  }
  const std::vector<double> u = Solve(p);
  return u[6 * mesh.Node(n, n) + UZ] * D / (a * a * a * a);
}

// Reference values (docs: benchmarks.md, "Shell element").
constexpr double kScordelisLo = 0.3024, kPinchedCylinder = 1.8248e-5, kHemisphere = 0.094;
constexpr double kPlateSS = 0.00406, kPlateClamped = 0.00126;

// ---------------------------------------------------------------------------------------------------
// Patch tests: the MacNeal-Harder patch (0.24 x 0.12, four interior nodes), placed on a tilted plane
// in 3D; all boundary dofs prescribed from the exact field, interior dofs solved.

struct Patch {
  Mesh mesh;
  Vec3 O{1, 2, 3}, a, b, c; // plane origin, in-plane axes a, b, normal c
  std::vector<int> boundary{0, 1, 2, 3};
  Patch()
  {
    const double pts[8][2] = {{0, 0}, {0.24, 0}, {0.24, 0.12}, {0, 0.12}, {0.04, 0.02}, {0.18, 0.03}, {0.16, 0.08}, {0.08, 0.08}};
    const double al = 0.3, be = 0.4; // the plane's orientation
    a = {std::cos(al), std::sin(al), 0};
    b = {-std::sin(al) * std::cos(be), std::cos(al) * std::cos(be), std::sin(be)};
    c = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    for (auto &q : pts) mesh.X.push_back(Global(q[0], q[1]));
    mesh.quads = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}};
  }
  Vec3 Global(double x, double y) const { return {O[0] + x * a[0] + y * b[0], O[1] + x * a[1] + y * b[1], O[2] + x * a[2] + y * b[2]}; }
  double X(int n) const { return (mesh.X[n][0] - O[0]) * a[0] + (mesh.X[n][1] - O[1]) * a[1] + (mesh.X[n][2] - O[2]) * a[2]; }
  double Y(int n) const { return (mesh.X[n][0] - O[0]) * b[0] + (mesh.X[n][1] - O[1]) * b[1] + (mesh.X[n][2] - O[2]) * b[2]; }
};

// The exact field of constant membrane strain eps, constant curvature kap (plane axes) and in-plane
// rotation omega at a point (x, y): local (u, v, w, theta_x, theta_y, theta_z).
std::array<double, 6> ExactField(const std::array<double, 3> &eps, const std::array<double, 3> &kap, double omega, double x, double y)
{
  const double u = eps[0] * x + 0.5 * eps[2] * y - omega * y, v = 0.5 * eps[2] * x + eps[1] * y + omega * x;
  const double w = -0.5 * (kap[0] * x * x + kap[1] * y * y + kap[2] * x * y);
  const double thx = -(kap[1] * y + 0.5 * kap[2] * x), thy = kap[0] * x + 0.5 * kap[2] * y; // zero transverse shear
  return {u, v, w, thx, thy, omega};
}

// Strain components (xx, yy, 2xy) of a plane tensor (plane axes a, b) seen in axes e1, e2.
std::array<double, 3> InAxes(const std::array<double, 3> &e, const Patch &P, const Vec3 &e1, const Vec3 &e2)
{
  auto dot = [](const Vec3 &p, const Vec3 &q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; };
  const double c1[2] = {dot(e1, P.a), dot(e1, P.b)}, c2[2] = {dot(e2, P.a), dot(e2, P.b)};
  const double T[2][2] = {{e[0], e[2] / 2}, {e[2] / 2, e[1]}};
  auto q = [&](const double *p, const double *r) {
    double s = 0;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) s += p[i] * T[i][j] * r[j];
    return s;
  };
  return {q(c1, c1), q(c2, c2), 2 * q(c1, c2)};
}

// Runs the patch test for a section; returns the largest error, relative to the field's scale, of
// (a) the interior nodal dofs (rotations times the patch length L, against the largest of |u| and
// |theta| L), and (b) the strains at the Gauss points of every element on both faces, eps +- t/2 kappa,
// with the transverse shear and the drilling defect (all exactly zero), against the largest face strain.
double PatchTestError(const ShellMaterial &mat, const std::array<double, 3> &eps, const std::array<double, 3> &kap, double omega)
{
  Patch P;
  const double L = 0.24, t = mat.thickness;
  Problem p(P.mesh, mat);
  auto global = [&](const std::array<double, 6> &l) {
    std::array<double, 6> g{};
    for (int k = 0; k < 3; ++k) {
      g[k] = l[0] * P.a[k] + l[1] * P.b[k] + l[2] * P.c[k];
      g[3 + k] = l[3] * P.a[k] + l[4] * P.b[k] + l[5] * P.c[k];
    }
    return g;
  };
  double uscale = 0;
  for (int n = 0; n < 8; ++n) {
    const auto g = global(ExactField(eps, kap, omega, P.X(n), P.Y(n)));
    for (int k = 0; k < 6; ++k) uscale = std::max(uscale, std::fabs(g[k]) * (k < 3 ? 1 : L));
  }
  for (int n : P.boundary) {
    const auto g = global(ExactField(eps, kap, omega, P.X(n), P.Y(n)));
    for (int k = 0; k < 6; ++k) p.Fix(n, k, g[k]);
  }
  const std::vector<double> u = Solve(p);
  double err = 0;
  for (int n = 4; n < 8; ++n) {
    const auto g = global(ExactField(eps, kap, omega, P.X(n), P.Y(n)));
    for (int k = 0; k < 6; ++k) err = std::max(err, std::fabs(u[6 * n + k] - g[k]) * (k < 3 ? 1 : L) / uscale);
  }
  double escale = 0;
  for (int k = 0; k < 3; ++k) escale = std::max({escale, std::fabs(eps[k] + t / 2 * kap[k]), std::fabs(eps[k] - t / 2 * kap[k])});
  for (const auto &q : P.mesh.quads) {
    const Nodes X = p.ElementNodes(q);
    const ElementFrame f = MakeElementFrame(X);
    const auto me = InAxes(eps, P, f.e1, f.e2), ke = InAxes(kap, P, f.e1, f.e2);
    for (double xi : {-0.577, 0.577})
      for (double eta : {-0.577, 0.577}) {
        const GeneralisedStrains s = ElementStrains(X, mat, p.opt, Gather(u, q), xi, eta);
        for (int k = 0; k < 3; ++k)
          for (double z : {-t / 2, t / 2})
            err = std::max(err, std::fabs(s.membrane[k] + z * s.curvature[k] - me[k] - z * ke[k]) / escale);
        err = std::max(err, std::max(std::fabs(s.shear[0]), std::fabs(s.shear[1])) / escale);
        err = std::max(err, std::fabs(s.drill) / escale);
      }
  }
  return err;
}

Ply Carbon(double angle, double t = 0.125) { return {angle, t, 140000, 10000, 0.3, 5000, 5000, 3500}; }

// Solves the 6x6 system [A B; B D] [eps; kap] = [N; M].
std::array<double, 6> CLT(const ShellMaterial &m, const std::array<double, 6> &NM)
{
  double S[6][7];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      S[i][j] = m.A[3 * i + j];
      S[i][j + 3] = m.B[3 * i + j];
      S[i + 3][j] = m.B[3 * i + j];
      S[i + 3][j + 3] = m.D[3 * i + j];
    }
  for (int i = 0; i < 6; ++i) S[i][6] = NM[i];
  for (int c = 0; c < 6; ++c) {
    int piv = c;
    for (int r = c + 1; r < 6; ++r)
      if (std::fabs(S[r][c]) > std::fabs(S[piv][c])) piv = r;
    for (int k = 0; k < 7; ++k) std::swap(S[c][k], S[piv][k]);
    for (int r = 0; r < 6; ++r)
      if (r != c) {
        const double f = S[r][c] / S[c][c];
        for (int k = c; k < 7; ++k) S[r][k] -= f * S[c][k];
      }
  }
  std::array<double, 6> x;
  for (int i = 0; i < 6; ++i) x[i] = S[i][6] / S[i][i];
  return x;
}

// A free laminated plate a x b (distorted interior nodes) loaded on its edges x = 0 and x = a by a
// uniform resultant Nx, Nxy (and Nxy on y = 0, b for equilibrium) or moment Mx; one corner node fixed.
// Returns the largest nodal error against the CLT field, relative to the field's scale.
double LaminatePlateError(const ShellMaterial &mat, double Nx, double Nxy, double Mx)
{
  const double a = 100, b = 50;
  const int nx = 8, ny = 4;
  Mesh mesh = Grid(nx, ny, [&](double s, double t) {
    // interior nodes moved off the grid (edges stay straight)
    const double ds = (s > 0 && s < 1 && t > 0 && t < 1) ? 0.3 / nx * std::sin(7 * s + 3 * t) : 0;
    const double dt = (s > 0 && s < 1 && t > 0 && t < 1) ? 0.3 / ny * std::cos(5 * s - 4 * t) : 0;
    return Vec3{a * (s + ds), b * (t + dt), 0};
  });
  Problem p(mesh, mat);
  // Edge loads by segment (consistent for a uniform resultant on a straight edge).
  auto edge = [&](int n0, int n1, int comp, double value) {
    const Vec3 &A = mesh.X[n0], &B = mesh.X[n1];
    const double len = std::hypot(B[0] - A[0], B[1] - A[1]);
    p.F[6 * n0 + comp] += value * len / 2;
    p.F[6 * n1 + comp] += value * len / 2;
  };
  for (int j = 0; j < ny; ++j) {
    const int r0 = mesh.Node(nx, j), r1 = mesh.Node(nx, j + 1), l0 = mesh.Node(0, j), l1 = mesh.Node(0, j + 1);
    edge(r0, r1, UX, Nx);
    edge(l0, l1, UX, -Nx);
    edge(r0, r1, UY, Nxy);
    edge(l0, l1, UY, -Nxy);
    edge(r0, r1, RY, Mx); // M_x does work on theta_y (u_x(z) = u + z theta_y)
    edge(l0, l1, RY, -Mx);
  }
  for (int i = 0; i < nx; ++i) {
    edge(mesh.Node(i, ny), mesh.Node(i + 1, ny), UX, Nxy);
    edge(mesh.Node(i, 0), mesh.Node(i + 1, 0), UX, -Nxy);
  }
  p.FixAll(0, {UX, UY, UZ, RX, RY, RZ});
  const std::vector<double> u = Solve(p);
  const auto ek = CLT(mat, {Nx, 0, Nxy, Mx, 0, 0});
  const std::array<double, 3> eps{ek[0], ek[1], ek[2]}, kap{ek[3], ek[4], ek[5]};
  double scale = 0, err = 0;
  for (int k = 0; k < 3; ++k) scale = std::max({scale, std::fabs(eps[k]) * a, std::fabs(kap[k]) * a * a});
  for (size_t n = 0; n < mesh.X.size(); ++n) {
    const auto f = ExactField(eps, kap, 0.0, mesh.X[n][0], mesh.X[n][1]);
    for (int k = 0; k < 6; ++k) err = std::max(err, std::fabs(u[6 * n + k] - f[k]) / (k < 3 ? scale : scale / a));
  }
  return err;
}

} // namespace

// ===================================================================================================
// Patch tests (issue 3: "constant membrane strain, constant curvature pass to round-off").

// Requirement: constant membrane strain (with an in-plane rotation) is reproduced to round-off on the
// distorted MacNeal-Harder patch placed on a tilted plane in 3D.
TEST(ShellPatch, ConstantMembraneStrain)
{
  EXPECT_LT(PatchTestError(IsotropicMaterial(1e6, 0.25, 0.001), {1e-3, -4e-4, 6e-4}, {0, 0, 0}, 2e-4), 1e-10);
}

// Requirement: constant curvature (zero transverse shear) is reproduced to round-off on the distorted
// patch: MITC4 passes the bending patch test.
TEST(ShellPatch, ConstantCurvature)
{
  EXPECT_LT(PatchTestError(IsotropicMaterial(1e6, 0.25, 0.001), {0, 0, 0}, {1e-3, 5e-4, -8e-4}, 0), 1e-10);
}

// Requirement: constant membrane strain and curvature together with membrane-bending coupling (an
// unsymmetric laminate, B != 0) on the distorted patch, to round-off.
TEST(ShellPatch, CoupledLaminate)
{
  const ShellMaterial m = LaminateMaterial({Carbon(0), Carbon(45), Carbon(90)});
  EXPECT_LT(PatchTestError(m, {1e-3, -4e-4, 6e-4}, {1e-2, 5e-3, -8e-3}, 1e-4), 1e-10);
}

// ===================================================================================================
// Laminates against classical lamination theory (benchmarks.md: "laminate ... CLT exactly").

// Requirement: an unsymmetric [0/90] plate under a membrane load Nx deforms (stretch and curvature from
// the ABD inverse) exactly as CLT says.
TEST(ShellLaminate, CrossPlyMembraneLoadMatchesCLT)
{
  EXPECT_LT(LaminatePlateError(LaminateMaterial({Carbon(0), Carbon(90)}), 10, 0, 0), 1e-9);
}

// Requirement: the unsymmetric [0/90] plate under an edge moment Mx matches CLT exactly.
TEST(ShellLaminate, CrossPlyMomentMatchesCLT)
{
  EXPECT_LT(LaminatePlateError(LaminateMaterial({Carbon(0), Carbon(90)}), 0, 0, 1.0), 1e-9);
}

// Requirement: an unsymmetric angle-ply [30/-45/0] (A16, B16, D16 non-zero) under Nx, Nxy and Mx
// together matches CLT exactly.
TEST(ShellLaminate, AnglePlyCombinedLoadMatchesCLT)
{
  EXPECT_LT(LaminatePlateError(LaminateMaterial({Carbon(30), Carbon(-45), Carbon(0)}), 10, 3, 1.0), 1e-9);
}

// ===================================================================================================
// Square plates (benchmarks.md: 0.00406 / 0.00126 q a^4 / D). Tolerances from docs/shell-convergence.md.

// Requirement: simply supported square plate, centre deflection 0.00406 q a^4/D; quarter model 8x8
// lands within 1% (the table: 8x8 is within 0.3%, and the converged value is 0.00406).
TEST(ShellPlate, SimplySupportedCentreDeflection)
{
  EXPECT_NEAR(SquarePlate(8, false) / kPlateSS, 1.0, 0.01);
}

// Requirement: clamped square plate, centre deflection 0.00126 q a^4/D; quarter model 8x8 within 1%.
TEST(ShellPlate, ClampedCentreDeflection)
{
  EXPECT_NEAR(SquarePlate(8, true) / kPlateClamped, 1.0, 0.01);
}

// ===================================================================================================
// MacNeal-Harder / Belytschko benchmarks (tolerances from docs/shell-convergence.md; see docs/shell.md).

// Requirement: Scordelis-Lo roof, 16x16 quarter model: vertical displacement at mid free edge 0.3024
// within 1% (table: from 8x8 on within 0.5%, 16x16 0.2% low; the mesh limit is 0.25% below 0.3024;
// the plain bilinear membrane is 1.1% low at 16x16).
TEST(ShellBenchmark, ScordelisLoRoof)
{
  EXPECT_NEAR(ScordelisLo(16, ElementOptions{}) / kScordelisLo, 1.0, 0.01);
}

// Requirement: the quarter model with its symmetry conditions (u_n = 0 and both in-plane rotations,
// the one about the shell normal included, = 0) gives the full model's answer to round-off.
TEST(ShellBenchmark, ScordelisLoSymmetryEqualsFullModel)
{
  const double quarter = ScordelisLo(6, ElementOptions{}), full = ScordelisLo(6, ElementOptions{}, {true});
  EXPECT_NEAR(quarter / full, 1.0, 1e-9);
}

// Requirement: the 1/8 cylinder with its three symmetry planes gives the whole (closed) cylinder's answer.
TEST(ShellBenchmark, PinchedCylinderSymmetryEqualsFullModel)
{
  EXPECT_NEAR(PinchedCylinder(4, ElementOptions{}) / PinchedCylinder(4, ElementOptions{}, true), 1.0, 1e-9);
}

// Requirement: the quarter hemisphere with its two symmetry planes gives the whole hemisphere's answer.
TEST(ShellBenchmark, PinchedHemisphereSymmetryEqualsFullModel)
{
  EXPECT_NEAR(Hemisphere(4, ElementOptions{}) / Hemisphere(4, ElementOptions{}, true), 1.0, 1e-9);
}

// Requirement: warped elements (arbitrary geometry): the roof on an irregular 16x16 mesh whose nodes
// lie on the cylinder off the regular grid (every element warped) is within 2% of 0.3024 (table:
// 16x16 irregular is 1.05% low, 32x32 0.6%, against 0.2% and 0.3% for the regular mesh).
TEST(ShellBenchmark, ScordelisLoWarpedMesh)
{
  EXPECT_NEAR(ScordelisLo(16, ElementOptions{}, {false, false, 0.3}) / kScordelisLo, 1.0, 0.02);
}

// Requirement: no membrane locking in in-plane bending (the incompatible modes): the straight
// cantilever (6 x 1, aspect ratio 5) under in-plane tip shear is within 5% of 0.1081 (table: 3% low;
// the plain bilinear membrane gives 9% of it).
TEST(ShellBenchmark, CantileverInPlaneShear)
{
  EXPECT_NEAR(Cantilever(1, ElementOptions{}) / 0.1081, 1.0, 0.05);
}

// Requirement: pinched cylinder, 1/8 model 32x32: radial displacement under the load 1.8248e-5
// within 2% (table: 16x16 is 7% low, 32x32 1.1% low; finer meshes overshoot by up to 1.6%, towards the
// shear-deformable value 1.8541e-5, as a point load on a Reissner-Mindlin shell should).
TEST(ShellBenchmark, PinchedCylinder)
{
  EXPECT_NEAR(PinchedCylinder(32, ElementOptions{}) / kPinchedCylinder, 1.0, 0.02);
}

// Requirement: pinched hemisphere with 18 deg hole, quarter model 16x16: radial displacement 0.094
// within 2% (table: every mesh from 8x8 is within 2%, 16x16 is 1.0% low, inside the quoted
// converged range 0.0924-0.093).
TEST(ShellBenchmark, PinchedHemisphere)
{
  const double w = Hemisphere(16, ElementOptions{});
  EXPECT_NEAR(w / kHemisphere, 1.0, 0.02);
  EXPECT_GE(w, 0.0924);
}

// Requirement: the default drilling factor lies on the plateau where the answers do not depend on it:
// a factor 10 either way changes the roof and the hemisphere (16x16) by less than 0.5%.
TEST(ShellBenchmark, DrillingFactorPlateau)
{
  for (auto run : {+[](double d) { return ScordelisLo(16, Drill(d)); }, +[](double d) { return Hemisphere(16, Drill(d)); }}) {
    const double mid = run(kDefaultDrill);
    EXPECT_NEAR(run(kDefaultDrill / 10) / mid, 1.0, 0.005);
    EXPECT_NEAR(run(kDefaultDrill * 10) / mid, 1.0, 0.005);
  }
}

// ===================================================================================================
// Convergence tables (--table).

namespace {

int PrintTables()
{
  const int meshes[] = {4, 8, 16, 32, 64};
  std::printf("# Shell element convergence (generated by scripts/shell-convergence)\n\n");
  std::printf("Flat-facet MITC4 with incompatible membrane modes (QM6), drilling factor %g (lib/shell/,\n"
              "docs/shell.md); the last column is the plain bilinear membrane (Membrane::Bilinear). n = elements\n"
              "per side of the symmetry model; value = the displacement the reference quotes; ratio = value /\n"
              "reference.\n\n",
              kDefaultDrill);
  struct Bench {
    const char *name, *model, *what;
    double ref;
    std::function<double(int, ElementOptions)> run;
  };
  const Bench benches[] = {
      {"Scordelis-Lo roof", "quarter", "vertical displacement, mid free edge", kScordelisLo, [](int n, ElementOptions o) { return ScordelisLo(n, o); }},
      {"Pinched cylinder", "one eighth", "radial displacement under the load", kPinchedCylinder, [](int n, ElementOptions o) { return PinchedCylinder(n, o); }},
      {"Pinched hemisphere", "quarter", "radial displacement under the load", kHemisphere, [](int n, ElementOptions o) { return Hemisphere(n, o); }},
      {"Square plate, simply supported", "quarter", "w_c D/(q a^4), a/t = 100", kPlateSS, [](int n, ElementOptions o) { return SquarePlate(n, false, o); }},
      {"Square plate, clamped", "quarter", "w_c D/(q a^4), a/t = 100", kPlateClamped, [](int n, ElementOptions o) { return SquarePlate(n, true, o); }},
  };
  const ElementOptions bilinear = Drill(kDefaultDrill, Membrane::Bilinear);
  for (const Bench &b : benches) {
    std::printf("## %s (%s model; %s; reference %g)\n\n| n | dofs | value | ratio | bilinear membrane: ratio |\n|---|---|---|---|---|\n", b.name, b.model, b.what, b.ref);
    for (int n : meshes) {
      const double v = b.run(n, ElementOptions{});
      std::printf("| %d | %d | %.6g | %.4f | %.4f |\n", n, 6 * (n + 1) * (n + 1), v, v / b.ref, b.run(n, bilinear) / b.ref);
    }
    std::printf("\n");
  }
  for (int n : {16, 64}) {
    std::printf("## Drilling factor (n = %d): ratio to the reference\n\n| drill | Scordelis-Lo | pinched cylinder | hemisphere |\n|---|---|---|---|\n", n);
    for (double d : {1e-6, 1e-4, 1e-3, 1e-2, 1e-1, 1.0})
      std::printf("| %g | %.4f | %.4f | %.4f |\n", d, ScordelisLo(n, Drill(d)) / kScordelisLo, PinchedCylinder(n, Drill(d)) / kPinchedCylinder,
                  Hemisphere(n, Drill(d)) / kHemisphere);
    std::printf("\n");
  }
  std::printf("## Symmetry models against full models\n\n| problem | n | symmetry model | full model | relative difference |\n|---|---|---|---|---|\n");
  for (int n : {4, 8, 16}) {
    const double q = ScordelisLo(n, ElementOptions{}), f = ScordelisLo(n, ElementOptions{}, {true});
    std::printf("| Scordelis-Lo, quarter / full (2n x 2n) | %d | %.8g | %.8g | %.1e |\n", n, q, f, std::fabs(q - f) / std::fabs(f));
  }
  for (int n : {4, 8, 16}) {
    const double q = ScordelisLo(n, ElementOptions{}, {false, true}), f = ScordelisLo(n, ElementOptions{}, {true});
    std::printf("| Scordelis-Lo, quarter with theta_z free on the crown plane (wrong) / full | %d | %.8g | %.8g | %.1e |\n", n, q, f, std::fabs(q - f) / std::fabs(f));
  }
  for (int n : {4, 8}) {
    const double q = PinchedCylinder(n, ElementOptions{}), f = PinchedCylinder(n, ElementOptions{}, true);
    std::printf("| pinched cylinder, 1/8 / closed (2n x 4n) | %d | %.8g | %.8g | %.1e |\n", n, q, f, std::fabs(q - f) / std::fabs(f));
  }
  for (int n : {4, 8}) {
    const double q = Hemisphere(n, ElementOptions{}), f = Hemisphere(n, ElementOptions{}, true);
    std::printf("| hemisphere, quarter / whole (n x 4n) | %d | %.8g | %.8g | %.1e |\n", n, q, f, std::fabs(q - f) / std::fabs(f));
  }
  std::printf("\n## Scordelis-Lo roof on irregular meshes (every element warped)\n\n"
              "Interior nodes moved along the surface by up to 0.3 of an element in each direction.\n\n"
              "| n | value | ratio | regular mesh ratio |\n|---|---|---|---|\n");
  for (int n : meshes) {
    const double v = ScordelisLo(n, ElementOptions{}, {false, false, 0.3});
    std::printf("| %d | %.6g | %.4f | %.4f |\n", n, v, v / kScordelisLo, ScordelisLo(n, ElementOptions{}) / kScordelisLo);
  }
  std::printf("\n## Straight cantilever (6 x 1 regular elements; a record, not a test)\n\n| load | reference | value | ratio | bilinear membrane: ratio |\n|---|---|---|---|---|\n");
  const char *cname[] = {"extension", "in-plane shear", "out-of-plane shear", "twist (rotation)"};
  const double cref[] = {3.0e-5, 0.1081, 0.4321, 0.03208};
  for (int k = 0; k < 4; ++k) {
    const double v = Cantilever(k, ElementOptions{});
    std::printf("| %s | %g | %.5g | %.4f | %.4f |\n", cname[k], cref[k], v, v / cref[k], Cantilever(k, bilinear) / cref[k]);
  }
  std::printf("\n## Exact solutions: largest relative error (round-off)\n\n| test | error |\n|---|---|\n");
  const ShellMaterial iso = IsotropicMaterial(1e6, 0.25, 0.001), lam = LaminateMaterial({Carbon(0), Carbon(45), Carbon(90)});
  std::printf("| membrane patch test (MacNeal-Harder patch, tilted in 3D) | %.1e |\n", PatchTestError(iso, {1e-3, -4e-4, 6e-4}, {0, 0, 0}, 2e-4));
  std::printf("| bending patch test (constant curvature) | %.1e |\n", PatchTestError(iso, {0, 0, 0}, {1e-3, 5e-4, -8e-4}, 0));
  std::printf("| coupled patch test, [0/45/90] laminate | %.1e |\n", PatchTestError(lam, {1e-3, -4e-4, 6e-4}, {1e-2, 5e-3, -8e-3}, 1e-4));
  const ShellMaterial cross = LaminateMaterial({Carbon(0), Carbon(90)}), angle = LaminateMaterial({Carbon(30), Carbon(-45), Carbon(0)});
  std::printf("| [0/90] free plate, Nx = 10, against CLT | %.1e |\n", LaminatePlateError(cross, 10, 0, 0));
  std::printf("| [0/90] free plate, Mx = 1, against CLT | %.1e |\n", LaminatePlateError(cross, 0, 0, 1));
  std::printf("| [30/-45/0] free plate, Nx, Nxy, Mx, against CLT | %.1e |\n", LaminatePlateError(angle, 10, 3, 1));
  return 0;
}

} // namespace

int main(int argc, char **argv)
{
  bool table = false;
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "--table")) table = true;
  ::testing::InitGoogleTest(&argc, argv);
  int pargc = 1; // PETSc sees no options: the tests set everything they need
  PetscErrorCode ierr = PetscInitialize(&pargc, &argv, nullptr, nullptr);
  if (ierr) return 1;
  int rc;
  try {
    rc = table ? PrintTables() : RUN_ALL_TESTS();
  } catch (const std::exception &e) {
    std::fprintf(stderr, "test_shell_solve: %s\n", e.what());
    rc = 1;
  }
  ierr = PetscFinalize();
  return rc ? rc : int(ierr);
}
