// The patch operator of a shell patch with a joint node (docs/coupling.md): exact
// elimination of the footprint against closed forms, and penalty converging to it; curved meshes of
// triangles with the mesh's nodal directors.
#include "patch/patch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace boltnet;

namespace {

// A 40 x 20 mm aluminium plate of nx by ny elements with one joint node at p, axis z.
ShellPatch Plate(int nx, int ny, const std::array<double, 3> &p, double radius)
{
  ShellPatch sp;
  sp.mesh     = RectanglePlate(0, 0, 40, 20, nx, ny, 0);
  sp.material = shell::IsotropicMaterial(72000, 0.33, 1.27);
  ShellPatch::JointNode jn;
  jn.x         = p;
  jn.axis      = {0, 0, 1};
  jn.footprint = CouplingFootprint(sp.mesh, p, jn.axis, radius);
  sp.joint_nodes.push_back(jn);
  return sp;
}

// Solve A u = f with the dof in `fixed` prescribed to `value` (dense LU with partial pivoting).
std::vector<double> Solve(const PatchOperator &op, std::vector<double> f, const std::vector<int> &fixed, const std::vector<double> &value)
{
  const int           n = (int)op.n;
  std::vector<double> A((size_t)n * n, 0.0);
  for (int r = 0; r < n; ++r)
    for (PetscInt k = op.rowptr[r]; k < op.rowptr[r + 1]; ++k) A[(size_t)r * n + op.cols[k]] += op.vals[k];
  for (size_t i = 0; i < fixed.size(); ++i) {
    for (int c = 0; c < n; ++c) A[(size_t)fixed[i] * n + c] = 0;
    A[(size_t)fixed[i] * n + fixed[i]] = 1;
    f[fixed[i]]                        = value[i];
  }
  for (int c = 0; c < n; ++c) {
    int piv = c;
    for (int r = c + 1; r < n; ++r)
      if (std::fabs(A[(size_t)r * n + c]) > std::fabs(A[(size_t)piv * n + c])) piv = r;
    if (piv != c) {
      for (int k = 0; k < n; ++k) std::swap(A[(size_t)c * n + k], A[(size_t)piv * n + k]);
      std::swap(f[c], f[piv]);
    }
    for (int r = c + 1; r < n; ++r) {
      const double m = A[(size_t)r * n + c] / A[(size_t)c * n + c];
      if (m == 0) continue;
      for (int k = c; k < n; ++k) A[(size_t)r * n + k] -= m * A[(size_t)c * n + k];
      f[r] -= m * f[c];
    }
  }
  std::vector<double> u(n);
  for (int r = n - 1; r >= 0; --r) {
    double s = f[r];
    for (int k = r + 1; k < n; ++k) s -= A[(size_t)r * n + k] * u[k];
    u[r] = s / A[(size_t)r * n + r];
  }
  return u;
}

} // namespace

// Requirement: with exact coupling, a rigid-body motion (translation and rotation) given to the joint
// node moves every footprint node exactly by u_m + theta_m x d, theta_m (d = x_s - x_m, the joint
// node off the mid-surface as in a lap joint), and an unloaded free plate follows the same rigid
// motion; the operator does no work on it (A u = 0 on the kept rows).
TEST(PatchOperator, ExactFootprintFollowsRigidMotion)
{
  const std::array<double, 3> p  = {21, 9, 0.635};
  const ShellPatch            sp = Plate(8, 4, p, 6.0);
  ASSERT_GE(sp.joint_nodes[0].footprint.size(), 4u);
  const PatchOperator op = BuildShellOperator(sp, CouplingType::Exact, 0, 6.0);
  const int           m  = (int)sp.mesh.x.size(); // the joint node
  const double        um[6] = {0.1, -0.05, 0.02, 0.003, -0.002, 0.004};
  std::vector<int>    fixed;
  std::vector<double> value;
  for (int i = 0; i < 6; ++i) fixed.push_back(6 * m + i), value.push_back(um[i]);
  const std::vector<double> u = Solve(op, std::vector<double>(op.n, 0.0), fixed, value);
  double                    scale = 0;
  for (int s = 0; s < m; ++s) {
    const double d[3]    = {sp.mesh.x[s][0] - p[0], sp.mesh.x[s][1] - p[1], sp.mesh.x[s][2] - p[2]};
    const double want[6] = {um[0] + um[4] * d[2] - um[5] * d[1], um[1] + um[5] * d[0] - um[3] * d[2], um[2] + um[3] * d[1] - um[4] * d[0], um[3], um[4], um[5]};
    const bool   slave   = std::count(sp.joint_nodes[0].footprint.begin(), sp.joint_nodes[0].footprint.end(), s) > 0;
    for (int i = 0; i < 6; ++i) {
      scale = std::max(scale, std::fabs(want[i]));
      // slaves: exactly (the constraint rows); the free plate: to the solve's round-off
      EXPECT_NEAR(u[6 * s + i], want[i], slave ? 1e-14 : 1e-9) << "node " << s << " dof " << i << (slave ? " (footprint)" : "");
    }
  }
  // No force anywhere for a rigid motion.
  for (int r = 0; r < (int)op.n; ++r) {
    double s = 0;
    for (PetscInt k = op.rowptr[r]; k < op.rowptr[r + 1]; ++k) s += op.vals[k] * u[op.cols[k]];
    EXPECT_NEAR(s, 0.0, 1e-6 * scale) << "row " << r;
  }
}

// Requirement: penalty coupling converges to the exact elimination as the penalty grows. A plate
// clamped at x = 0, a force and a moment on the joint node: the joint node's displacement with
// penalty factors 1e1, 1e3, 1e5 (times A11) approaches the exact one, each step closer, the last
// within 1e-4.
TEST(PatchOperator, PenaltyConvergesToExact)
{
  const std::array<double, 3> p  = {30, 10, 0.635};
  const ShellPatch            sp = Plate(8, 4, p, 4.0);
  const int                   m  = (int)sp.mesh.x.size();
  std::vector<int>            fixed;
  for (int n : sp.mesh.node_sets.at("xmin"))
    for (int i = 0; i < 6; ++i) fixed.push_back(6 * n + i);
  const std::vector<double> zero(fixed.size(), 0.0);
  auto                      joint = [&](CouplingType t, double factor) {
    const PatchOperator op = BuildShellOperator(sp, t, factor * sp.material.A[0], 4.0);
    std::vector<double> f(op.n, 0.0);
    f[6 * m + 0] = 1000, f[6 * m + 2] = 10, f[6 * m + 5] = 2000;
    const std::vector<double> u = Solve(op, f, fixed, zero);
    return std::vector<double>(u.begin() + 6 * m, u.begin() + 6 * m + 6);
  };
  const std::vector<double> ue   = joint(CouplingType::Exact, 0);
  const double              norm = std::hypot(ue[0], std::hypot(ue[1], ue[2]));
  double                    last = INFINITY;
  for (double factor : {1e1, 1e3, 1e5}) {
    const std::vector<double> up = joint(CouplingType::Penalty, factor);
    ASSERT_TRUE(std::isfinite(up[0]));
    const double err = std::hypot(up[0] - ue[0], std::hypot(up[1] - ue[1], up[2] - ue[2])) / norm;
    EXPECT_LT(err, last) << "penalty " << factor;
    last = err;
  }
  EXPECT_LT(last, 1e-4);
}

// Requirement (docs/coupling.md): on a mesh coarser than the footprint, the footprint is the nodes
// of the element containing the fastener; the node coupling picks the nearest node.
TEST(PatchOperator, CoarseFootprintAndNearestNode)
{
  const ShellMesh m = RectanglePlate(0, 0, 40, 20, 2, 1, 0); // 20 x 20 elements
  EXPECT_TRUE(Footprint(m, {27, 9, 0}, {0, 0, 1}, 4.0).empty());
  EXPECT_EQ(ContainingElement(m, {27, 9, 0}, {0, 0, 1}), 1);
  const std::vector<int> f = CouplingFootprint(m, {27, 9, 0}, {0, 0, 1}, 4.0);
  EXPECT_EQ(f, (std::vector<int>{1, 2, 4, 5}));
  EXPECT_EQ(NearestNode(m, {27, 9, 5}, {0, 0, 1}), 1); // (20, 0), in-plane distance
  EXPECT_EQ(ContainingElement(m, {45, 9, 0}, {0, 0, 1}), -1);
  EXPECT_TRUE(CouplingFootprint(m, {60, 9, 0}, {0, 0, 1}, 4.0).empty());
}

namespace {
// The MacNeal-Harder twisted beam (docs/shell.md): L = 12, width 1.1, t = 0.32, E = 29e6, nu = 0.22,
// twisted by 90 deg, clamped at x = 0, a unit load along the tip's width (z), spread by consistent
// edge weights; 12 r x 2 r cells of the given kind. The tip's deflection along the load (the
// weighted mean of the tip nodes'), with the mesh's nodal directors or each element's own normals.
double TwistedBeam(int r, PlateElements kind, bool directors)
{
  const double kPi = std::acos(-1.0), L = 12, b = 1.1;
  ShellPatch   sp;
  sp.mesh = RectanglePlate(0, 0, 1, 1, 12 * r, 2 * r, 0, kind);
  for (auto &x : sp.mesh.x) {
    const double phi = kPi / 2 * x[0], y = b * (x[1] - 0.5);
    x                = {L * x[0], y * std::cos(phi), y * std::sin(phi)};
  }
  if (directors) sp.mesh.directors = NodalDirectors(sp.mesh);
  sp.material            = shell::IsotropicMaterial(29e6, 0.22, 0.32);
  const PatchOperator op = BuildShellOperator(sp, CouplingType::Node, 0, 1);
  std::vector<int>    fixed;
  for (int n : sp.mesh.node_sets.at("xmin"))
    for (int i = 0; i < 6; ++i) fixed.push_back(6 * n + i);
  std::vector<double>     f(op.n, 0.0);
  const std::vector<int> &tip = sp.mesh.node_sets.at("xmax");
  const int               m   = (int)tip.size() - 1;
  for (int j = 0; j <= m; ++j) f[6 * tip[j] + 2] = (j == 0 || j == m ? 0.5 : 1.0) / m;
  const std::vector<double> u = Solve(op, f, fixed, std::vector<double>(fixed.size(), 0.0));
  double                    w = 0;
  for (int j = 0; j <= m; ++j) w += f[6 * tip[j] + 2] * u[6 * tip[j] + 2];
  return w;
}
} // namespace

// Requirement (docs/shell.md, "Warped elements and kinks"): the patch operator hands the elements
// of a curved mesh its nodal directors. On the twisted beam (in-plane load, MacNeal-Harder 0.005424)
// split into triangles, or mixed, the answer with them converges to the reference (within 1% on the
// 24 x 4 mesh, closer than on 12 x 2), while with each element's own normals it moves away as the
// mesh is refined (docs/shell.md: 1.098 at 192 x 32). The quadrilaterals' corner normals agree
// between neighbours on this mesh: it gets no directors and the same answer to the last bit.
TEST(PatchOperator, CurvedMeshTakesNodalDirectors)
{
  const double ref = 0.005424;
  EXPECT_EQ(TwistedBeam(2, PlateElements::Quads, true), TwistedBeam(2, PlateElements::Quads, false));
  for (PlateElements kind : {PlateElements::Triangles, PlateElements::Mixed}) {
    double with[2], without[2];
    for (int r : {1, 2}) {
      const double a = TwistedBeam(r, kind, true) / ref, b = TwistedBeam(r, kind, false) / ref;
      with[r - 1]    = std::fabs(a - 1);
      without[r - 1] = std::fabs(b - 1);
      std::printf("twisted beam, %s, %d x %d: %.4f of the reference with the mesh's directors, %.4f with the elements' own normals\n", kind == PlateElements::Mixed ? "mixed" : "triangles", 12 * r, 2 * r, a, b);
    }
    EXPECT_LT(with[1], 0.01);
    EXPECT_LT(with[1], with[0]);
    EXPECT_GT(without[1], without[0]);
    EXPECT_GT(without[1], 0.02);
  }
}
