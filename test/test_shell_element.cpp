// Unit tests of the shell kernels that need no global solve: sections (isotropic,
// laminate by CLT, rotation, bad input), element stiffness (symmetry, rigid-body modes on a warped
// element, rank), consistent loads.
#include "shell/shell.hpp"
#include "shell_element_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

using namespace boltnet::shell;

namespace {

double MaxAbs(const Mat3 &a)
{
  double m = 0;
  for (double v : a) m = std::max(m, std::fabs(v));
  return m;
}

// A warped, skewed, arbitrarily oriented element (warp about 5% of its size).
Nodes WarpedElement()
{
  return {Vec3{0.1, -0.2, 0.3}, Vec3{1.3, 0.1, 0.2}, Vec3{1.5, 1.2, 0.55}, Vec3{-0.1, 0.9, 0.4}};
}

double MaxAbs(const ElementMatrix &K)
{
  double m = 0;
  for (double v : K) m = std::max(m, std::fabs(v));
  return m;
}

// A ply of a carbon/epoxy (T300/914 like) in MPa, mm.
Ply Carbon(double angle, double t = 0.125) { return {angle, t, 140000, 10000, 0.3, 5000, 5000, 3500}; }

// Rigid-body motion `mode` of the element's nodes (shell_element_util.hpp) as an element vector.
ElementVector RigidMode(const Nodes &X, const Vec3 &origin, int mode)
{
  const std::vector<double> v = shelltest::RigidMotion({X.begin(), X.end()}, mode, origin);
  ElementVector             u;
  std::copy(v.begin(), v.end(), u.begin());
  return u;
}

} // namespace

// Requirement: isotropic section A = E t/(1-nu^2), D = E t^3/(12(1-nu^2)), B = 0, H = 5/6 G t.
TEST(ShellMaterial, IsotropicClosedForm)
{
  const double E = 70000, nu = 0.33, t = 2;
  const ShellMaterial m = IsotropicMaterial(E, nu, t);
  EXPECT_DOUBLE_EQ(m.A[0], E * t / (1 - nu * nu));
  EXPECT_DOUBLE_EQ(m.A[1], nu * E * t / (1 - nu * nu));
  EXPECT_DOUBLE_EQ(m.A[8], E * t / (2 * (1 + nu)));
  EXPECT_DOUBLE_EQ(m.D[0], E * t * t * t / (12 * (1 - nu * nu)));
  EXPECT_EQ(MaxAbs(m.B), 0.0);
  EXPECT_DOUBLE_EQ(m.H[0], 5.0 / 6.0 * E / (2 * (1 + nu)) * t);
  EXPECT_EQ(m.H[1], 0.0);
}

// Requirement: a laminate of identical isotropic plies at any angles is the isotropic section (CLT).
TEST(ShellMaterial, LaminateOfIsotropicPliesIsIsotropic)
{
  const double E = 70000, nu = 0.3, G = E / (2 * (1 + nu));
  std::vector<Ply> plies;
  for (double a : {0.0, 30.0, -45.0, 90.0}) plies.push_back({a, 0.5, E, E, nu, G, G, G});
  const ShellMaterial lam = LaminateMaterial(plies), iso = IsotropicMaterial(E, nu, 2.0);
  for (int k = 0; k < 9; ++k) {
    EXPECT_NEAR(lam.A[k], iso.A[k], 1e-12 * iso.A[0]);
    EXPECT_NEAR(lam.B[k], 0, 1e-12 * iso.A[0]);
    EXPECT_NEAR(lam.D[k], iso.D[k], 1e-12 * iso.D[0]);
  }
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(lam.H[k], iso.H[k], 1e-12 * iso.H[0]);
  EXPECT_DOUBLE_EQ(lam.thickness, 2.0);
}

// Requirement: the unsymmetric [0/90] laminate against its CLT closed form (A, B, D, H).
TEST(ShellMaterial, CrossPlyClosedForm)
{
  const double t = 0.125;
  const Ply p = Carbon(0, t);
  const ShellMaterial m = LaminateMaterial({Carbon(0, t), Carbon(90, t)});
  const double d = 1 - p.nu12 * p.nu12 * p.E2 / p.E1, Q11 = p.E1 / d, Q22 = p.E2 / d, Q12 = p.nu12 * p.E2 / d;
  const double tol = 1e-12 * Q11;
  EXPECT_NEAR(m.A[0], (Q11 + Q22) * t, tol);
  EXPECT_NEAR(m.A[4], (Q11 + Q22) * t, tol);
  EXPECT_NEAR(m.A[1], 2 * Q12 * t, tol);
  EXPECT_NEAR(m.A[8], 2 * p.G12 * t, tol);
  EXPECT_NEAR(m.A[2], 0, tol);
  // Bottom ply (0 deg) on z in [-t, 0], top ply (90 deg) on [0, t].
  EXPECT_NEAR(m.B[0], (Q22 - Q11) * t * t / 2, tol * t);
  EXPECT_NEAR(m.B[4], (Q11 - Q22) * t * t / 2, tol * t);
  EXPECT_NEAR(m.B[1], 0, tol * t);
  EXPECT_NEAR(m.B[8], 0, tol * t);
  EXPECT_NEAR(m.D[0], (Q11 + Q22) * t * t * t / 3, tol * t * t);
  EXPECT_NEAR(m.D[8], 2 * p.G12 * t * t * t / 3, tol * t * t);
  EXPECT_NEAR(m.H[0], 5.0 / 6.0 * (p.G13 + p.G23) * t, tol);
  EXPECT_NEAR(m.H[3], 5.0 / 6.0 * (p.G13 + p.G23) * t, tol);
  EXPECT_NEAR(m.H[1], 0, tol);
}

// Requirement: rotating a section by phi equals rotating every ply by phi (CLT), and back again.
TEST(ShellMaterial, RotationMatchesRotatedPlies)
{
  const double phi = 25 * M_PI / 180;
  const std::vector<Ply> plies{Carbon(0), Carbon(45), Carbon(90), Carbon(-30)};
  std::vector<Ply> turned = plies;
  for (Ply &p : turned) p.angle_deg += 25;
  // Seen from axes at -25 deg to the reference (RotateMaterial: the material axis lies at +25 deg from
  // the new axes), every ply angle grows by 25 deg.
  const ShellMaterial c = RotateMaterial(LaminateMaterial(plies), phi), base = LaminateMaterial(turned);
  for (int k = 0; k < 9; ++k) {
    EXPECT_NEAR(c.A[k], base.A[k], 1e-10 * base.A[0]);
    EXPECT_NEAR(c.B[k], base.B[k], 1e-10 * base.A[0] * 0.5);
    EXPECT_NEAR(c.D[k], base.D[k], 1e-10 * base.D[0]);
  }
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(c.H[k], base.H[k], 1e-10 * base.H[0]);
}

// Requirement: a laminate with no plies or a non-positive thickness is rejected with a message naming it.
TEST(ShellMaterial, BadLaminateRejected)
{
  auto message = [](auto &&f) {
    try {
      f();
    } catch (const std::invalid_argument &e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_NE(message([] { LaminateMaterial({}); }).find("no plies"), std::string::npos);
  EXPECT_NE(message([] { LaminateMaterial({Carbon(0), Carbon(90, -0.1)}); }).find("ply 1: thickness = -0.1"), std::string::npos);
  EXPECT_NE(message([] { LaminateMaterial({Carbon(0, 0.0)}); }).find("ply 0: thickness = 0"), std::string::npos);
  Ply bad = Carbon(0);
  bad.G23 = 0;
  EXPECT_NE(message([&] { LaminateMaterial({bad}); }).find("ply 0: G23 = 0"), std::string::npos);
  EXPECT_NE(message([] { IsotropicMaterial(70000, 0.3, -1); }).find("thickness t = -1"), std::string::npos);
  EXPECT_NE(message([] { IsotropicMaterial(-1, 0.3, 1); }).find("E = -1"), std::string::npos);
}

// Requirement: the element stiffness is symmetric (warped element, laminate with B coupling, both
// membranes, the director kinematics and the rigid-link formulation it replaced).
TEST(ShellElement, StiffnessSymmetric)
{
  const ShellMaterial m = LaminateMaterial({Carbon(0, 0.1), Carbon(45, 0.1), Carbon(90, 0.1)});
  for (Warping warping : {Warping::Directors, Warping::RigidLinks})
  for (Membrane membrane : {Membrane::Incompatible, Membrane::Bilinear}) {
    ElementOptions o;
    o.membrane = membrane;
    o.warping = warping;
    ElementMatrix K;
    ElementStiffness(WarpedElement(), m, o, K);
    const double s = MaxAbs(K);
    for (int i = 0; i < 24; ++i)
      for (int j = 0; j < i; ++j) EXPECT_NEAR(K[24 * i + j], K[24 * j + i], 1e-14 * s) << i << "," << j;
  }
}

// Requirement: the six rigid-body motions (3 translations, 3 rotations about an arbitrary point) give
// zero nodal forces and zero strains to round-off on a warped element (both membranes, isotropic and
// laminate, director kinematics and rigid links, whose node transforms the strains must apply).
TEST(ShellElement, RigidBodyModes)
{
  const Nodes X = WarpedElement();
  for (const ShellMaterial &m : {IsotropicMaterial(70000, 0.3, 0.05), LaminateMaterial({Carbon(0), Carbon(90)})})
  for (Warping warping : {Warping::Directors, Warping::RigidLinks})
  for (Membrane membrane : {Membrane::Incompatible, Membrane::Bilinear}) {
    ElementOptions o;
    o.membrane = membrane;
    o.warping = warping;
    ElementMatrix K;
    ElementStiffness(X, m, o, K);
    const double s = MaxAbs(K);
    const Vec3 origin{0.7, -0.3, 2.0};
    for (int mode = 0; mode < 6; ++mode) {
      const ElementVector u = RigidMode(X, origin, mode);
      double fmax = 0, umax = 0;
      for (int i = 0; i < 24; ++i) {
        double f = 0;
        for (int j = 0; j < 24; ++j) f += K[24 * i + j] * u[j];
        fmax = std::max(fmax, std::fabs(f));
        umax = std::max(umax, std::fabs(u[i]));
      }
      EXPECT_LT(fmax, 1e-12 * s * umax) << "rigid mode " << mode << " membrane " << int(membrane);
      // No strain either (ElementStrains, its condensed modes computed afresh or kept). A non-rigid
      // field of this size has strains of order 1 here (unit rotations, nodes about 1 apart).
      const CondensedModes kept = ElementCondensedModes(X, nullptr, m, o);
      for (const auto &pt : {std::array<double, 2>{0, 0}, std::array<double, 2>{0.5, -0.3}})
        for (const CondensedModes *k : {static_cast<const CondensedModes *>(nullptr), &kept}) {
          const GeneralisedStrains e    = ElementStrains(X, nullptr, m, o, u, pt[0], pt[1], k);
          double                   emax = std::fabs(e.drill);
          for (double v : e.membrane) emax = std::max(emax, std::fabs(v));
          for (double v : e.curvature) emax = std::max(emax, std::fabs(v));
          for (double v : e.shear) emax = std::max(emax, std::fabs(v));
          EXPECT_LT(emax, 1e-12) << "rigid mode " << mode << " warping " << int(warping) << " membrane " << int(membrane) << " at " << pt[0] << "," << pt[1] << (k ? " (kept modes)" : "");
        }
    }
  }
}

// Requirement: the condensed incompatible modes recover in-plane pure bending exactly. On a rectangle
// 2a x 2b the field u = k x y, v = -k (x^2 + nu y^2) / 2 has eps_xx = k y, eps_yy = -nu k y and no
// shear, and lies in the incompatible element's space (Wilson's x^2, y^2 modes), so the strains at
// any point are these to round-off; the bilinear membrane alone shows the parasitic shear gamma = k x
// instead (the reason for the modes), which the test also checks.
TEST(ShellElement, IncompatibleModesRecoverInPlaneBending)
{
  const double a = 1.5, b = 0.5, k = 1e-3, nu = 0.3;
  const Nodes  X{Vec3{-a, -b, 0}, Vec3{a, -b, 0}, Vec3{a, b, 0}, Vec3{-a, b, 0}};
  ElementVector u{};
  for (int n = 0; n < 4; ++n) {
    const double x = X[n][0], y = X[n][1];
    u[6 * n + 0] = k * x * y;
    u[6 * n + 1] = -k * (x * x + nu * y * y) / 2;
    u[6 * n + 5] = -k * x; // the drilling rotation of the field: (v,x - u,y) / 2
  }
  const ShellMaterial m = IsotropicMaterial(70000, nu, 2);
  for (const auto &pt : {std::array<double, 2>{0, 0}, std::array<double, 2>{0.5, -0.3}, std::array<double, 2>{-0.8, 0.9}}) {
    const double   x = a * pt[0], y = b * pt[1];
    ElementOptions o;
    o.membrane                 = Membrane::Incompatible;
    const CondensedModes kept = ElementCondensedModes(X, nullptr, m, o);
    for (const CondensedModes *km : {static_cast<const CondensedModes *>(nullptr), &kept}) {
      const GeneralisedStrains e = ElementStrains(X, nullptr, m, o, u, pt[0], pt[1], km);
      EXPECT_NEAR(e.membrane[0], k * y, 1e-12 * k) << "at " << pt[0] << "," << pt[1] << (km ? " (kept modes)" : "");
      EXPECT_NEAR(e.membrane[1], -nu * k * y, 1e-12 * k);
      EXPECT_NEAR(e.membrane[2], 0, 1e-12 * k);
    }
    o.membrane                 = Membrane::Bilinear;
    const GeneralisedStrains c = ElementStrains(X, m, o, u, pt[0], pt[1]);
    EXPECT_NEAR(c.membrane[2], k * x, 1e-12 * k);
  }
}

// Requirement: strains from kept condensed modes (what the field writer does from its second step
// on) are the strains of the element integrated afresh, to the bit: warped quadrilateral with either
// warping treatment, laminate, and a triangle with its MITC3+ bubble, at the centroid and off it.
TEST(ShellElement, KeptCondensedModesGiveTheSameStrains)
{
  const Nodes         X = WarpedElement();
  const ShellMaterial m = LaminateMaterial({Carbon(0), Carbon(45), Carbon(90)});
  ElementVector       u{};
  for (int i = 0; i < 24; ++i) u[i] = std::sin(1.0 + 0.7 * i) * (i % 6 < 3 ? 1e-2 : 1e-3);
  auto same = [](const GeneralisedStrains &a, const GeneralisedStrains &b) {
    return a.membrane == b.membrane && a.curvature == b.curvature && a.shear == b.shear && a.drill == b.drill;
  };
  for (Warping warping : {Warping::Directors, Warping::RigidLinks}) {
    ElementOptions o;
    o.warping                 = warping;
    const CondensedModes kept = ElementCondensedModes(X, nullptr, m, o);
    EXPECT_TRUE(kept.any);
    for (const auto &pt : {std::array<double, 2>{0, 0}, std::array<double, 2>{0.5, -0.3}})
      EXPECT_TRUE(same(ElementStrains(X, nullptr, m, o, u, pt[0], pt[1]), ElementStrains(X, nullptr, m, o, u, pt[0], pt[1], &kept))) << int(warping);
  }
  const TriNodes  T{X[0], X[1], X[2]};
  TriVector       ut;
  ElementOptions  o;
  std::copy(u.begin(), u.begin() + 18, ut.begin());
  o.triangle_shear          = TriangleShear::MITC3Plus;
  const CondensedModes kept = ElementCondensedModes(T, nullptr, m, o);
  EXPECT_TRUE(kept.any);
  for (const auto &pt : {std::array<double, 2>{1.0 / 3, 1.0 / 3}, std::array<double, 2>{0.2, 0.5}})
    EXPECT_TRUE(same(ElementStrains(T, nullptr, m, o, ut, pt[0], pt[1]), ElementStrains(T, nullptr, m, o, ut, pt[0], pt[1], &kept)));
}

// Requirement: no spurious zero-energy mode: exactly 6 zero eigenvalues (Jacobi eigenvalues of K), with
// either membrane, either warping treatment and a small or a large drilling factor.
TEST(ShellElement, ExactlySixZeroEigenvalues)
{
  for (double drill : {kDefaultDrill, 1.0})
  for (Warping warping : {Warping::Directors, Warping::RigidLinks})
  for (Membrane membrane : {Membrane::Incompatible, Membrane::Bilinear}) {
    ElementOptions o;
    o.drill = drill;
    o.membrane = membrane;
    o.warping = warping;
    ElementMatrix K;
    ElementStiffness(WarpedElement(), IsotropicMaterial(70000, 0.3, 0.05), o, K);
    // Cyclic Jacobi on the 24x24 symmetric matrix.
    std::array<double, 576> a = K;
    for (int sweep = 0; sweep < 100; ++sweep) {
      double off = 0;
      for (int p = 0; p < 24; ++p)
        for (int q = p + 1; q < 24; ++q) off += a[24 * p + q] * a[24 * p + q];
      if (off < 1e-30 * MaxAbs(K) * MaxAbs(K)) break;
      for (int p = 0; p < 24; ++p)
        for (int q = p + 1; q < 24; ++q) {
          const double apq = a[24 * p + q];
          if (apq == 0) continue;
          const double theta = (a[24 * q + q] - a[24 * p + p]) / (2 * apq);
          const double t = (theta >= 0 ? 1 : -1) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
          const double c = 1 / std::sqrt(t * t + 1), s = t * c;
          for (int k = 0; k < 24; ++k) {
            const double akp = a[24 * k + p], akq = a[24 * k + q];
            a[24 * k + p] = c * akp - s * akq;
            a[24 * k + q] = s * akp + c * akq;
          }
          for (int k = 0; k < 24; ++k) {
            const double apk = a[24 * p + k], aqk = a[24 * q + k];
            a[24 * p + k] = c * apk - s * aqk;
            a[24 * q + k] = s * apk + c * aqk;
          }
        }
    }
    std::vector<double> ev;
    for (int i = 0; i < 24; ++i) ev.push_back(std::fabs(a[25 * i]));
    std::sort(ev.begin(), ev.end());
    const double big = ev.back();
    for (int i = 0; i < 6; ++i) EXPECT_LT(ev[i], 1e-10 * big) << "drill " << drill << " membrane " << int(membrane) << " eigenvalue " << i;
    // The seventh (smallest non-zero) is a genuine deformation mode, well clear of round-off.
    EXPECT_GT(ev[6], 1e-9 * big) << "drill " << drill;
  }
}

// Requirement: the consistent load of a uniform force per area sums to q times the area, and a
// uniform pressure on a flat element to p A n; rotations carry no load.
TEST(ShellElement, ConsistentLoads)
{
  const Nodes X{Vec3{0, 0, 1}, Vec3{2, 0, 1}, Vec3{2.5, 1.5, 1}, Vec3{0, 1, 1}};
  double shoelace = 0;
  for (int i = 0; i < 4; ++i) shoelace += X[i][0] * X[(i + 1) % 4][1] - X[(i + 1) % 4][0] * X[i][1];
  shoelace *= 0.5;
  ElementVector F;
  ElementLoad(X, Vec3{1, -2, 3}, F);
  for (int k = 0; k < 3; ++k) {
    double s = 0;
    for (int n = 0; n < 4; ++n) s += F[6 * n + k];
    EXPECT_NEAR(s, (k == 0 ? 1 : k == 1 ? -2 : 3) * shoelace, 1e-13);
  }
  for (int n = 0; n < 4; ++n)
    for (int k = 3; k < 6; ++k) EXPECT_EQ(F[6 * n + k], 0.0);
  ElementPressure(X, 2.0, F);
  double fz = 0;
  for (int n = 0; n < 4; ++n) fz += F[6 * n + 2];
  EXPECT_NEAR(fz, 2.0 * shoelace, 1e-13);
  EXPECT_NEAR(F[0], 0, 1e-15);
}

// Requirement: a degenerate element, a negative drilling factor and nodal directors handed to the
// rigid-link formulation (which has none) are rejected with a message, not a silent NaN.
TEST(ShellElement, DegenerateRejected)
{
  const Nodes X{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 0, 0}};
  ElementMatrix K;
  EXPECT_THROW(ElementStiffness(X, IsotropicMaterial(1, 0.3, 0.1), kDefaultDrill, K), std::invalid_argument);
  const Nodes bowtie{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{1, 1, 0}};
  EXPECT_THROW(ElementStiffness(bowtie, IsotropicMaterial(1, 0.3, 0.1), kDefaultDrill, K), std::invalid_argument);
  const Nodes square{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1, 0}};
  EXPECT_THROW(ElementStiffness(square, IsotropicMaterial(1, 0.3, 0.1), -1.0, K), std::invalid_argument);
  ElementOptions rigid;
  rigid.warping = Warping::RigidLinks;
  const Directors V{Vec3{0, 0, 1}, Vec3{0, 0, 1}, Vec3{0, 0, 1}, Vec3{0, 0, 1}};
  EXPECT_THROW(ElementStiffness(square, &V, IsotropicMaterial(1, 0.3, 0.1), rigid, K), std::invalid_argument);
}

namespace {

ShellMaterial AnglePly()
{
  ShellMaterial m = LaminateMaterial({Carbon(30), Carbon(-45), Carbon(0)});
  m.direction = {1, 0.3, 0.2};
  return m;
}

} // namespace

// Requirement: the element is objective: rotating the nodes and the material direction by R gives
// R K R^T (warped element, anisotropic laminate with B coupling).
TEST(ShellElement, ObjectiveUnderRotation)
{
  const double a = 0.7, b = -0.4, c = 1.1; // R = Rz(a) Ry(b) Rx(c)
  const double Rz[3][3] = {{std::cos(a), -std::sin(a), 0}, {std::sin(a), std::cos(a), 0}, {0, 0, 1}};
  const double Ry[3][3] = {{std::cos(b), 0, std::sin(b)}, {0, 1, 0}, {-std::sin(b), 0, std::cos(b)}};
  const double Rx[3][3] = {{1, 0, 0}, {0, std::cos(c), -std::sin(c)}, {0, std::sin(c), std::cos(c)}};
  double R[3][3] = {}, T[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) T[i][j] += Ry[i][k] * Rx[k][j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) R[i][j] += Rz[i][k] * T[k][j];
  auto rot = [&](const Vec3 &v) {
    Vec3 r{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r[i] += R[i][j] * v[j];
    return r;
  };
  const Nodes X = WarpedElement();
  Nodes Xr;
  for (int n = 0; n < 4; ++n) Xr[n] = rot(X[n]);
  ShellMaterial m = AnglePly(), mr = m;
  mr.direction = rot(m.direction);
  ElementMatrix K, Kr;
  ElementStiffness(X, m, ElementOptions{}, K);
  ElementStiffness(Xr, mr, ElementOptions{}, Kr);
  // Q = blockdiag(R, ..., R) (8 blocks): expect Kr = Q K Q^T.
  auto Q = [&](int i, int j) { return (i / 3 == j / 3) ? R[i % 3][j % 3] : 0.0; };
  const double s = MaxAbs(K);
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j) {
      double v = 0;
      for (int k = 3 * (i / 3); k < 3 * (i / 3) + 3; ++k)
        for (int l = 3 * (j / 3); l < 3 * (j / 3) + 3; ++l) v += Q(i, k) * K[24 * k + l] * Q(j, l);
      EXPECT_NEAR(Kr[24 * i + j], v, 1e-12 * s) << i << "," << j;
    }
}

// Requirement: the stiffness does not depend on which node is numbered first (the element frame e1
// changes; the material direction is projected on each point's tangent plane): cyclic renumbering
// permutes K, nothing else.
TEST(ShellElement, NodeNumberingInvariant)
{
  const Nodes X = WarpedElement();
  for (Warping warping : {Warping::Directors, Warping::RigidLinks})
  for (Membrane membrane : {Membrane::Incompatible, Membrane::Bilinear}) {
    ElementOptions o;
    o.membrane = membrane;
    o.warping = warping;
    ElementMatrix K;
    ElementStiffness(X, AnglePly(), o, K);
    const double s = MaxAbs(K);
    for (int shift = 1; shift < 4; ++shift) {
      Nodes Xs;
      for (int n = 0; n < 4; ++n) Xs[n] = X[(n + shift) % 4];
      ElementMatrix Ks;
      ElementStiffness(Xs, AnglePly(), o, Ks);
      for (int p = 0; p < 4; ++p)
        for (int q = 0; q < 4; ++q)
          for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j)
              EXPECT_NEAR(Ks[24 * (6 * p + i) + 6 * q + j], K[24 * (6 * ((p + shift) % 4) + i) + 6 * ((q + shift) % 4) + j], 1e-12 * s)
                  << "shift " << shift << " membrane " << int(membrane);
    }
  }
}
