// The four-node flat-facet MITC4 shell element (see shell.hpp and docs/shell.md).
#include "shell/shell.hpp"

#include <cmath>
#include <stdexcept>

namespace boltnet::shell {

namespace {

constexpr double kXi[4] = {-1, 1, 1, -1}, kEta[4] = {-1, -1, 1, 1};
constexpr double kGauss = 0.57735026918962576451; // 1/sqrt(3)

Vec3 Sub(const Vec3 &a, const Vec3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double Dot(const Vec3 &a, const Vec3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 Cross(const Vec3 &a, const Vec3 &b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double Norm(const Vec3 &a) { return std::sqrt(Dot(a, a)); }

struct Shape {
  double N[4], dxi[4], deta[4];
};

Shape ShapeAt(double xi, double eta)
{
  Shape s;
  for (int i = 0; i < 4; ++i) {
    s.N[i] = 0.25 * (1 + kXi[i] * xi) * (1 + kEta[i] * eta);
    s.dxi[i] = 0.25 * kXi[i] * (1 + kEta[i] * eta);
    s.deta[i] = 0.25 * kEta[i] * (1 + kXi[i] * xi);
  }
  return s;
}

// Local dof order per node: u, v, w, theta_x, theta_y, theta_z (element frame).
enum { U = 0, V = 1, W = 2, TX = 3, TY = 4, TZ = 5 };

// Strain-displacement rows at one point of the flat element, local dofs.
struct BMatrix {
  double m[3][24] = {}, b[3][24] = {}, s[2][24] = {}, d[24] = {};
  double detJ = 0;
};

// Covariant transverse shear rows (gamma_xi, gamma_eta) at (xi, eta):
// gamma_xi = dw/dxi + theta_y x_xi - theta_x y_xi (likewise for eta).
void CovariantShear(const ElementFrame &f, double xi, double eta, double row_xi[24], double row_eta[24])
{
  const Shape s = ShapeAt(xi, eta);
  double x_xi = 0, y_xi = 0, x_eta = 0, y_eta = 0;
  for (int i = 0; i < 4; ++i) {
    x_xi += s.dxi[i] * f.x[i];
    y_xi += s.dxi[i] * f.y[i];
    x_eta += s.deta[i] * f.x[i];
    y_eta += s.deta[i] * f.y[i];
  }
  for (int i = 0; i < 4; ++i) {
    if (row_xi) {
      row_xi[6 * i + W] = s.dxi[i];
      row_xi[6 * i + TY] = s.N[i] * x_xi;
      row_xi[6 * i + TX] = -s.N[i] * y_xi;
    }
    if (row_eta) {
      row_eta[6 * i + W] = s.deta[i];
      row_eta[6 * i + TY] = s.N[i] * x_eta;
      row_eta[6 * i + TX] = -s.N[i] * y_eta;
    }
  }
}

BMatrix BAt(const ElementFrame &f, double xi, double eta)
{
  BMatrix B;
  const Shape s = ShapeAt(xi, eta);
  double J[2][2] = {};
  for (int i = 0; i < 4; ++i) {
    J[0][0] += s.dxi[i] * f.x[i];
    J[0][1] += s.dxi[i] * f.y[i];
    J[1][0] += s.deta[i] * f.x[i];
    J[1][1] += s.deta[i] * f.y[i];
  }
  B.detJ = J[0][0] * J[1][1] - J[0][1] * J[1][0];
  if (!(B.detJ > 0))
    throw std::invalid_argument("Shell element: degenerate or inverted quadrilateral (Jacobian determinant " +
                                std::to_string(B.detJ) + " at a Gauss point); number the nodes counter-clockwise");
  const double Ji[2][2] = {{J[1][1] / B.detJ, -J[0][1] / B.detJ}, {-J[1][0] / B.detJ, J[0][0] / B.detJ}};
  for (int i = 0; i < 4; ++i) {
    const double dx = Ji[0][0] * s.dxi[i] + Ji[0][1] * s.deta[i];
    const double dy = Ji[1][0] * s.dxi[i] + Ji[1][1] * s.deta[i];
    B.m[0][6 * i + U] = dx;
    B.m[1][6 * i + V] = dy;
    B.m[2][6 * i + U] = dy;
    B.m[2][6 * i + V] = dx;
    B.b[0][6 * i + TY] = dx;
    B.b[1][6 * i + TX] = -dy;
    B.b[2][6 * i + TY] = dy;
    B.b[2][6 * i + TX] = -dx;
    B.d[6 * i + TZ] = s.N[i];
    B.d[6 * i + V] = -0.5 * dx;
    B.d[6 * i + U] = 0.5 * dy;
  }
  // MITC4: gamma_xi tied at (0, +-1), gamma_eta at (+-1, 0), interpolated linearly across.
  double A[24] = {}, Bt[24] = {}, C[24] = {}, Dt[24] = {};
  CovariantShear(f, 0, 1, A, nullptr);
  CovariantShear(f, 0, -1, Bt, nullptr);
  CovariantShear(f, 1, 0, nullptr, C);
  CovariantShear(f, -1, 0, nullptr, Dt);
  for (int k = 0; k < 24; ++k) {
    const double gxi = 0.5 * (1 + eta) * A[k] + 0.5 * (1 - eta) * Bt[k];
    const double geta = 0.5 * (1 + xi) * C[k] + 0.5 * (1 - xi) * Dt[k];
    // gamma_xi = x_xi gamma_x + y_xi gamma_y (likewise eta): Cartesian = J^-1 covariant.
    B.s[0][k] = Ji[0][0] * gxi + Ji[0][1] * geta;
    B.s[1][k] = Ji[1][0] * gxi + Ji[1][1] * geta;
  }
  return B;
}

// Per node: local dofs = M global dofs, M = W diag(R, R) with R the rows e1, e2, e3 and W the rigid
// offset from the node to its projection on the mean plane (u_f = u - h theta_y, v_f = v + h theta_x).
using NodeTransform = std::array<double, 36>;

std::array<NodeTransform, 4> Transforms(const ElementFrame &f)
{
  std::array<NodeTransform, 4> T{};
  const Vec3 *R[3] = {&f.e1, &f.e2, &f.e3};
  for (int n = 0; n < 4; ++n) {
    NodeTransform &M = T[n];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        M[6 * a + b] = (*R[a])[b];
        M[6 * (a + 3) + b + 3] = (*R[a])[b];
      }
    for (int b = 0; b < 3; ++b) {
      M[6 * U + 3 + b] -= f.h[n] * f.e2[b];       // - h theta_y
      M[6 * V + 3 + b] += f.h[n] * f.e1[b];       // + h theta_x
    }
  }
  return T;
}

// Section in the element frame: the material reference direction projected on the element plane.
ShellMaterial ElementSection(const ElementFrame &f, const ShellMaterial &mat)
{
  const Vec3 &r = mat.direction;
  const double c = Dot(r, f.e1), s = Dot(r, f.e2);
  if (std::hypot(c, s) <= 1e-8 * Norm(r)) return mat; // direction along the normal: use e1
  return RotateMaterial(mat, std::atan2(s, c));
}

} // namespace

ElementFrame MakeElementFrame(const Nodes &X)
{
  ElementFrame f;
  Vec3 gxi{}, geta{};
  f.centre = {0, 0, 0};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) {
      f.centre[k] += 0.25 * X[i][k];
      gxi[k] += 0.25 * kXi[i] * X[i][k];
      geta[k] += 0.25 * kEta[i] * X[i][k];
    }
  const Vec3 n = Cross(gxi, geta);
  const double nn = Norm(n), lx = Norm(gxi), ly = Norm(geta);
  if (!(nn > 1e-12 * lx * ly) || !(lx > 0) || !std::isfinite(nn))
    throw std::invalid_argument("Shell element: degenerate quadrilateral (zero area or coincident nodes)");
  for (int k = 0; k < 3; ++k) {
    f.e3[k] = n[k] / nn;
    f.e1[k] = gxi[k] / lx;
  }
  f.e2 = Cross(f.e3, f.e1);
  for (int i = 0; i < 4; ++i) {
    const Vec3 d = Sub(X[i], f.centre);
    f.x[i] = Dot(d, f.e1);
    f.y[i] = Dot(d, f.e2);
    f.h[i] = Dot(d, f.e3);
  }
  return f;
}

void ElementStiffness(const Nodes &X, const ShellMaterial &mat, double drill, ElementMatrix &K)
{
  if (!(drill >= 0) || !std::isfinite(drill))
    throw std::invalid_argument("Shell element: drilling factor = " + std::to_string(drill) + " must be >= 0");
  const ElementFrame f = MakeElementFrame(X);
  const ShellMaterial m = ElementSection(f, mat);
  const double gamma = drill * (m.A[0] + m.A[4] - 2 * m.A[1] + 4 * m.A[8]) / 8;
  double KL[24][24] = {};
  for (int g = 0; g < 4; ++g) {
    const BMatrix B = BAt(f, kXi[g] * kGauss, kEta[g] * kGauss);
    const double w = B.detJ; // Gauss weights are 1
    // Generalised stresses per unit dof: S = C E, with E = [m; b] (6 rows) and s (2 rows).
    double NM[6][24] = {}, Q[2][24] = {};
    for (int k = 0; k < 24; ++k) {
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          NM[i][k] += m.A[3 * i + j] * B.m[j][k] + m.B[3 * i + j] * B.b[j][k];
          NM[i + 3][k] += m.B[3 * i + j] * B.m[j][k] + m.D[3 * i + j] * B.b[j][k];
        }
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) Q[i][k] += m.H[2 * i + j] * B.s[j][k];
    }
    for (int a = 0; a < 24; ++a)
      for (int b = 0; b < 24; ++b) {
        double v = gamma * B.d[a] * B.d[b];
        for (int i = 0; i < 3; ++i) v += B.m[i][a] * NM[i][b] + B.b[i][a] * NM[i + 3][b];
        for (int i = 0; i < 2; ++i) v += B.s[i][a] * Q[i][b];
        KL[a][b] += w * v;
      }
  }
  // Symmetrise (the products above are symmetric up to round-off).
  for (int a = 0; a < 24; ++a)
    for (int b = a + 1; b < 24; ++b) KL[a][b] = KL[b][a] = 0.5 * (KL[a][b] + KL[b][a]);
  // K = T^T KL T, node block by node block.
  const auto T = Transforms(f);
  for (int p = 0; p < 4; ++p)
    for (int q = 0; q < 4; ++q) {
      double tmp[6][6] = {};
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
          for (int k = 0; k < 6; ++k) tmp[i][j] += KL[6 * p + i][6 * q + k] * T[q][6 * k + j];
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
          double v = 0;
          for (int k = 0; k < 6; ++k) v += T[p][6 * k + i] * tmp[k][j];
          K[24 * (6 * p + i) + 6 * q + j] = v;
        }
    }
}

void ElementLoad(const Nodes &X, const Vec3 &q, ElementVector &F)
{
  F.fill(0);
  for (int g = 0; g < 4; ++g) {
    const Shape s = ShapeAt(kXi[g] * kGauss, kEta[g] * kGauss);
    Vec3 gxi{}, geta{};
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) {
        gxi[k] += s.dxi[i] * X[i][k];
        geta[k] += s.deta[i] * X[i][k];
      }
    const double dA = Norm(Cross(gxi, geta));
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) F[6 * i + k] += s.N[i] * q[k] * dA;
  }
}

void ElementPressure(const Nodes &X, double p, ElementVector &F)
{
  F.fill(0);
  for (int g = 0; g < 4; ++g) {
    const Shape s = ShapeAt(kXi[g] * kGauss, kEta[g] * kGauss);
    Vec3 gxi{}, geta{};
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) {
        gxi[k] += s.dxi[i] * X[i][k];
        geta[k] += s.deta[i] * X[i][k];
      }
    const Vec3 ndA = Cross(gxi, geta);
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) F[6 * i + k] += s.N[i] * p * ndA[k];
  }
}

GeneralisedStrains ElementStrains(const Nodes &X, const ElementVector &u, double xi, double eta)
{
  const ElementFrame f = MakeElementFrame(X);
  const auto T = Transforms(f);
  double ul[24] = {};
  for (int n = 0; n < 4; ++n)
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) ul[6 * n + i] += T[n][6 * i + j] * u[6 * n + j];
  const BMatrix B = BAt(f, xi, eta);
  GeneralisedStrains e{};
  for (int k = 0; k < 24; ++k) {
    for (int i = 0; i < 3; ++i) {
      e.membrane[i] += B.m[i][k] * ul[k];
      e.curvature[i] += B.b[i][k] * ul[k];
    }
    for (int i = 0; i < 2; ++i) e.shear[i] += B.s[i][k] * ul[k];
    e.drill += B.d[k] * ul[k];
  }
  return e;
}

} // namespace boltnet::shell
