// Unit tests of the three-node shell element and of the director kinematics both elements share (no
// global solve, no PETSc): stiffness symmetry, rigid-body modes, rank, objectivity, node numbering,
// consistent loads, bad input, the OPT membrane's exact in-plane pure bending, and rotations about the
// directors costing no bending energy (the warping fix; docs/shell.md, "Warped elements").
#include "shell_element_util.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using namespace shelltest;

namespace {

// A triangle in general position (arbitrary orientation in space).
TriNodes GeneralTriangle() { return {Vec3{0.1, -0.2, 0.3}, Vec3{1.3, 0.1, 0.2}, Vec3{0.5, 1.2, 0.55}}; }

// Directors tilted away from the facet normal by up to ~15 deg (the normals of a curved surface).
TriDirectors TiltedDirectors(const TriNodes &X)
{
  const TriFrame f = MakeElementFrame(X);
  TriDirectors   V;
  const double   tilt[3][2] = {{0.2, -0.1}, {-0.15, 0.05}, {0.1, 0.25}};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) V[i][k] = f.e3[k] + tilt[i][0] * f.e1[k] + tilt[i][1] * f.e2[k];
  return V;
}

ShellMaterial AnglePly()
{
  ShellMaterial m = LaminateMaterial({CarbonPly(30), CarbonPly(-45), CarbonPly(0)});
  m.direction     = {1, 0.3, 0.2};
  return m;
}

std::vector<ElementOptions> TriangleVariants()
{
  std::vector<ElementOptions> v;
  for (TriangleMembrane mem : {TriangleMembrane::Linear, TriangleMembrane::Optimal})
    for (TriangleShear sh : {TriangleShear::MITC3Plus, TriangleShear::MITC3}) {
      ElementOptions o;
      o.triangle_membrane = mem;
      o.triangle_shear    = sh;
      v.push_back(o);
    }
  return v;
}

std::string Name(const ElementOptions &o)
{
  return std::string(o.triangle_membrane == TriangleMembrane::Linear ? "CST+HB" : "OPT") + (o.triangle_shear == TriangleShear::MITC3Plus ? " MITC3+" : " MITC3");
}

} // namespace

// Requirement: the triangle's stiffness is symmetric (laminate with B coupling, every variant, with
// and without directors).
TEST(ShellTriangle, StiffnessSymmetric)
{
  const TriNodes     X = GeneralTriangle();
  const TriDirectors V = TiltedDirectors(X);
  for (const ElementOptions &o : TriangleVariants())
    for (const TriDirectors *v : {static_cast<const TriDirectors *>(nullptr), &V}) {
      TriMatrix K;
      ElementStiffness(X, v, AnglePly(), o, K);
      const double s = MaxAbs(K.data(), K.size());
      for (int i = 0; i < 18; ++i)
        for (int j = 0; j < i; ++j) EXPECT_NEAR(K[18 * i + j], K[18 * j + i], 1e-14 * s) << Name(o);
    }
}

// Requirement: the six rigid-body motions give zero nodal forces to round-off (every variant,
// isotropic and laminate, own and tilted directors).
TEST(ShellTriangle, RigidBodyModes)
{
  const TriNodes          X = GeneralTriangle();
  const TriDirectors      V = TiltedDirectors(X);
  const std::vector<Vec3> Xv(X.begin(), X.end());
  for (const ShellMaterial &m : {IsotropicMaterial(70000, 0.3, 0.05), AnglePly()})
    for (const ElementOptions &o : TriangleVariants())
      for (const TriDirectors *v : {static_cast<const TriDirectors *>(nullptr), &V}) {
        TriMatrix K;
        ElementStiffness(X, v, m, o, K);
        const double s = MaxAbs(K.data(), K.size());
        for (int mode = 0; mode < 6; ++mode) {
          const std::vector<double> u = RigidMotion(Xv, mode, Vec3{0.7, -0.3, 2.0});
          EXPECT_LT(MaxForce(K.data(), u), 1e-12 * s * MaxAbs(u.data(), u.size())) << Name(o) << " mode " << mode;
        }
      }
}

// Requirement: no spurious zero-energy mode: exactly six zero eigenvalues (the seventh well clear of
// round-off). MITC3+ ties the linear part of its shear field at points a distance d = 1e-4 apart
// (Lee, Lee & Bathe 2014), so its softest single-element deformation (a rotational transverse-shear
// field) has an energy of order d^2: 1e-8 of the largest eigenvalue here, eight orders above round-off.
TEST(ShellTriangle, ExactlySixZeroEigenvalues)
{
  for (double drill : {kDefaultDrill, 1.0})
    for (ElementOptions o : TriangleVariants()) {
      o.drill = drill;
      TriMatrix K;
      ElementStiffness(GeneralTriangle(), IsotropicMaterial(70000, 0.3, 0.05), o, K);
      const std::vector<double> ev = Eigenvalues(K.data(), 18);
      for (int i = 0; i < 6; ++i) EXPECT_LT(ev[i], 1e-13 * ev.back()) << Name(o) << " drill " << drill << " eigenvalue " << i;
      EXPECT_GT(ev[6], 1e-10 * ev.back()) << Name(o) << " drill " << drill;
    }
}

// Requirement: objectivity: rotating the nodes, the directors and the material direction by R gives
// R K R^T (anisotropic laminate with B coupling, tilted directors, every variant).
TEST(ShellTriangle, ObjectiveUnderRotation)
{
  const double a = 0.7, b = -0.4, c = 1.1;
  const double Rz[3][3] = {{std::cos(a), -std::sin(a), 0}, {std::sin(a), std::cos(a), 0}, {0, 0, 1}};
  const double Ry[3][3] = {{std::cos(b), 0, std::sin(b)}, {0, 1, 0}, {-std::sin(b), 0, std::cos(b)}};
  const double Rx[3][3] = {{1, 0, 0}, {0, std::cos(c), -std::sin(c)}, {0, std::sin(c), std::cos(c)}};
  double       R[3][3] = {}, T[3][3] = {};
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
  const TriNodes     X = GeneralTriangle();
  const TriDirectors V = TiltedDirectors(X);
  TriNodes           Xr;
  TriDirectors       Vr;
  for (int n = 0; n < 3; ++n) {
    Xr[n] = rot(X[n]);
    Vr[n] = rot(V[n]);
  }
  ShellMaterial m = AnglePly(), mr = m;
  mr.direction    = rot(m.direction);
  for (const ElementOptions &o : TriangleVariants()) {
    TriMatrix K, Kr;
    ElementStiffness(X, &V, m, o, K);
    ElementStiffness(Xr, &Vr, mr, o, Kr);
    const double s = MaxAbs(K.data(), K.size());
    for (int i = 0; i < 18; ++i)
      for (int j = 0; j < 18; ++j) {
        double v = 0;
        for (int k = 3 * (i / 3); k < 3 * (i / 3) + 3; ++k)
          for (int l = 3 * (j / 3); l < 3 * (j / 3) + 3; ++l) v += R[i % 3][k % 3] * K[18 * k + l] * R[j % 3][l % 3];
        EXPECT_NEAR(Kr[18 * i + j], v, 1e-12 * s) << Name(o) << " " << i << "," << j;
      }
  }
}

// Requirement: the stiffness does not depend on which node is numbered first (element frame e1 and
// the MITC3/MITC3+ natural coordinates change): a cyclic renumbering permutes K, nothing else.
TEST(ShellTriangle, NodeNumberingInvariant)
{
  const TriNodes     X = GeneralTriangle();
  const TriDirectors V = TiltedDirectors(X);
  for (const ElementOptions &o : TriangleVariants()) {
    TriMatrix K;
    ElementStiffness(X, &V, AnglePly(), o, K);
    const double s = MaxAbs(K.data(), K.size());
    for (int shift = 1; shift < 3; ++shift) {
      TriNodes     Xs;
      TriDirectors Vs;
      for (int n = 0; n < 3; ++n) {
        Xs[n] = X[(n + shift) % 3];
        Vs[n] = V[(n + shift) % 3];
      }
      TriMatrix Ks;
      ElementStiffness(Xs, &Vs, AnglePly(), o, Ks);
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q)
          for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j)
              EXPECT_NEAR(Ks[18 * (6 * p + i) + 6 * q + j], K[18 * (6 * ((p + shift) % 3) + i) + 6 * ((q + shift) % 3) + j], 1e-11 * s)
                  << Name(o) << " shift " << shift;
    }
  }
}

// Requirement: the OPT membrane is exact in in-plane pure bending of a rectangle split into two
// triangles, for any aspect ratio, either diagonal and any Poisson ratio (Felippa 2003's optimality:
// the strain energy of the exact nodal field equals the exact energy); the CST is not.
TEST(ShellTriangle, OptimalMembraneExactInPureBending)
{
  for (double nu : {0.0, 0.3, 0.45})
    for (double aspect : {0.25, 1.0, 4.0})
      for (int diagonal : {0, 1}) {
        const double  a = 1, b = aspect, kap = 1;
        ShellMaterial m = IsotropicMaterial(1.0, nu, 1.0);
        // u = -k x y, v = k (x^2 + nu y^2) / 2, rotation (v,x - u,y) / 2 = k x; exact energy k^2 E I a / 2.
        const Vec3 P[4] = {{0, -b / 2, 0}, {a, -b / 2, 0}, {a, b / 2, 0}, {0, b / 2, 0}};
        const int  tris[2][2][3] = {{{0, 1, 2}, {0, 2, 3}}, {{0, 1, 3}, {1, 2, 3}}};
        double     U[2]          = {};
        for (TriangleMembrane mem : {TriangleMembrane::Optimal, TriangleMembrane::Linear}) {
          ElementOptions o;
          o.triangle_membrane = mem;
          o.drill             = 0;
          for (const auto &t : tris[diagonal]) {
            const TriNodes X{P[t[0]], P[t[1]], P[t[2]]};
            TriMatrix      K;
            ElementStiffness(X, m, o, K);
            TriVector u{};
            for (int n = 0; n < 3; ++n) {
              const double x = X[n][0], y = X[n][1];
              u[6 * n]     = -kap * x * y;
              u[6 * n + 1] = kap * (x * x + nu * y * y) / 2;
              u[6 * n + 5] = kap * x;
            }
            for (int i = 0; i < 18; ++i)
              for (int j = 0; j < 18; ++j) U[int(mem)] += 0.5 * u[i] * K[18 * i + j] * u[j];
          }
        }
        const double exact = 0.5 * kap * kap * a * b * b * b / 12;
        EXPECT_NEAR(U[int(TriangleMembrane::Optimal)] / exact, 1.0, 1e-12) << "nu " << nu << " aspect " << aspect << " diagonal " << diagonal;
        EXPECT_GT(U[int(TriangleMembrane::Linear)] / exact, 1.5) << "the CST locks";
      }
}

// Requirement: the consistent load of a uniform force per area sums to q A, a pressure to p A n; the
// rotations carry no load.
TEST(ShellTriangle, ConsistentLoads)
{
  const TriNodes X{Vec3{0, 0, 1}, Vec3{2, 0, 1}, Vec3{0.5, 1.5, 1}};
  const double   A = 1.5;
  TriVector      F;
  ElementLoad(X, Vec3{1, -2, 3}, F);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(F[k] + F[6 + k] + F[12 + k], (k == 0 ? 1 : k == 1 ? -2 : 3) * A, 1e-14);
  for (int n = 0; n < 3; ++n)
    for (int k = 3; k < 6; ++k) EXPECT_EQ(F[6 * n + k], 0.0);
  ElementPressure(X, 2.0, F);
  EXPECT_NEAR(F[2] + F[8] + F[14], 2.0 * A, 1e-14);
  EXPECT_NEAR(F[0] + F[6] + F[12], 0, 1e-15);
}

// Requirement: a degenerate triangle, a director on the wrong side, a negative drilling factor and an
// element with 5 nodes are rejected with a message naming the problem.
TEST(ShellTriangle, BadInputRejected)
{
  auto message = [](auto &&f) {
    try {
      f();
    } catch (const std::invalid_argument &e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  const ShellMaterial m = IsotropicMaterial(1, 0.3, 0.1);
  TriMatrix           K;
  EXPECT_NE(message([&] { ElementStiffness(TriNodes{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{2, 0, 0}}, m, ElementOptions{}, K); }).find("degenerate triangle"),
            std::string::npos);
  const TriNodes     X{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}};
  const TriDirectors V{Vec3{0, 0, 1}, Vec3{0, 0, -1}, Vec3{0, 0, 1}};
  EXPECT_NE(message([&] { ElementStiffness(X, &V, m, ElementOptions{}, K); }).find("director of triangle node 1"), std::string::npos);
  ElementOptions o;
  o.drill = -1;
  EXPECT_NE(message([&] { ElementStiffness(X, m, o, K); }).find("drilling factor"), std::string::npos);
  double     Kn[900];
  const Vec3 P[5] = {};
  EXPECT_NE(message([&] { ElementStiffness(5, P, nullptr, m, ElementOptions{}, Kn); }).find("5 nodes"), std::string::npos);
}

// Requirement: the mixed-mesh entry point (n nodes) gives the same matrices and loads as the typed
// quadrilateral and triangle functions, with and without directors.
TEST(ShellTriangle, MixedEntryPointMatchesTyped)
{
  const TriNodes     Xt = GeneralTriangle();
  const TriDirectors Vt = TiltedDirectors(Xt);
  TriMatrix          Kt;
  double             K[576], F[24];
  ElementStiffness(Xt, &Vt, AnglePly(), ElementOptions{}, Kt);
  ElementStiffness(3, Xt.data(), Vt.data(), AnglePly(), ElementOptions{}, K);
  for (int i = 0; i < 324; ++i) EXPECT_EQ(K[i], Kt[i]);
  const Nodes   Xq{Vec3{0.1, -0.2, 0.3}, Vec3{1.3, 0.1, 0.2}, Vec3{1.5, 1.2, 0.55}, Vec3{-0.1, 0.9, 0.4}};
  ElementMatrix Kq;
  ElementStiffness(Xq, AnglePly(), ElementOptions{}, Kq);
  ElementStiffness(4, Xq.data(), nullptr, AnglePly(), ElementOptions{}, K);
  for (int i = 0; i < 576; ++i) EXPECT_EQ(K[i], Kq[i]);
  ElementVector Fq;
  ElementPressure(Xq, 3.0, Fq);
  ElementPressure(4, Xq.data(), 3.0, F);
  for (int i = 0; i < 24; ++i) EXPECT_EQ(F[i], Fq[i]);
  TriVector Ft;
  ElementLoad(Xt, Vec3{1, 2, 3}, Ft);
  ElementLoad(3, Xt.data(), Vec3{1, 2, 3}, F);
  for (int i = 0; i < 18; ++i) EXPECT_EQ(F[i], Ft[i]);
}

// ===================================================================================================
// Director kinematics (both elements).

// Requirement (the warping fix): a rotation about each node's director changes no director, so it
// costs no bending or shear energy: with the drilling term off, theta_i = c_i V_i and u = 0 give zero
// nodal forces, on a warped quadrilateral (its own corner normals) and on a triangle with tilted
// directors. The flat projection with rigid links (Warping::RigidLinks) charges this motion with
// bending energy: the drilling rotation leaks into bending, which made the twisted beam depend on the
// drilling factor (docs/shell.md).
TEST(ShellDirectors, RotationAboutDirectorsCostsNoEnergy)
{
  const Nodes        Xq{Vec3{0.1, -0.2, 0.3}, Vec3{1.3, 0.1, 0.2}, Vec3{1.5, 1.2, 0.55}, Vec3{-0.1, 0.9, 0.4}};
  const double       c[4] = {1.0, -0.7, 0.4, 1.3};
  const ShellMaterial m   = IsotropicMaterial(70000, 0.3, 0.05);
  // The quadrilateral's own directors: its bilinear surface's normals at the nodes.
  const double nat[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  Directors    V;
  for (int i = 0; i < 4; ++i) {
    Vec3 axi{}, aeta{};
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 3; ++k) {
        const double xj = nat[j][0], yj = nat[j][1];
        axi[k] += 0.25 * xj * (1 + yj * nat[i][1]) * Xq[j][k];
        aeta[k] += 0.25 * yj * (1 + xj * nat[i][0]) * Xq[j][k];
      }
    V[i] = {axi[1] * aeta[2] - axi[2] * aeta[1], axi[2] * aeta[0] - axi[0] * aeta[2], axi[0] * aeta[1] - axi[1] * aeta[0]};
    const double n = std::sqrt(V[i][0] * V[i][0] + V[i][1] * V[i][1] + V[i][2] * V[i][2]);
    for (double &v : V[i]) v /= n;
  }
  std::vector<double> u(24, 0.0);
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) u[6 * i + 3 + k] = c[i] * V[i][k];
  for (Membrane membrane : {Membrane::Incompatible, Membrane::Bilinear}) {
    ElementOptions o;
    o.drill    = 0;
    o.membrane = membrane;
    ElementMatrix K, Kown;
    ElementStiffness(Xq, &V, m, o, K);
    ElementStiffness(Xq, m, o, Kown);
    const double s = MaxAbs(K.data(), K.size());
    EXPECT_LT(MaxForce(K.data(), u), 1e-12 * s);
    for (int i = 0; i < 576; ++i) EXPECT_NEAR(K[i], Kown[i], 1e-12 * s) << "the element's own directors are its corner normals";
    o.warping = Warping::RigidLinks;
    ElementStiffness(Xq, m, o, K);
    EXPECT_GT(MaxForce(K.data(), u), 1e-3 * s) << "rigid links: the drilling rotation bends the element";
  }
  const TriNodes     Xt = GeneralTriangle();
  const TriDirectors Vt = TiltedDirectors(Xt);
  for (ElementOptions o : TriangleVariants()) {
    if (o.triangle_membrane == TriangleMembrane::Optimal) continue; // OPT has its own drilling stiffness
    o.drill = 0;
    TriMatrix K;
    ElementStiffness(Xt, &Vt, m, o, K);
    std::vector<double> ut(18, 0.0);
    for (int i = 0; i < 3; ++i) {
      const double n = std::sqrt(Vt[i][0] * Vt[i][0] + Vt[i][1] * Vt[i][1] + Vt[i][2] * Vt[i][2]);
      for (int k = 0; k < 3; ++k) ut[6 * i + 3 + k] = c[i] * Vt[i][k] / n;
    }
    EXPECT_LT(MaxForce(K.data(), ut), 1e-12 * MaxAbs(K.data(), K.size())) << Name(o);
  }
}

// Requirement: on a flat quadrilateral the director kinematics is the flat MITC4 element it replaced
// (Warping::RigidLinks has no offsets there): identical stiffness, so every flat-plate result is
// unchanged.
TEST(ShellDirectors, FlatQuadrilateralUnchanged)
{
  const Nodes X{Vec3{0, 0, 1}, Vec3{2, 0.2, 1}, Vec3{2.5, 1.5, 1}, Vec3{-0.2, 1, 1}};
  for (const ShellMaterial &m : {IsotropicMaterial(70000, 0.3, 0.05), AnglePly()})
    for (Membrane membrane : {Membrane::Incompatible, Membrane::Bilinear}) {
      ElementOptions o;
      o.membrane = membrane;
      ElementMatrix K, Kflat;
      ElementStiffness(X, m, o, K);
      o.warping = Warping::RigidLinks;
      ElementStiffness(X, m, o, Kflat);
      const double s = MaxAbs(K.data(), K.size());
      for (int i = 0; i < 576; ++i) EXPECT_NEAR(K[i], Kflat[i], 1e-13 * s);
    }
}
