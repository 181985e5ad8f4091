// The four-node flat-facet MITC4 shell element (see shell.hpp and docs/shell.md).
#include "shell/shell.hpp"

#include <algorithm>
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

namespace {

// The incompatible-mode membrane rows (QM6, Wilson-Taylor): modes 1 - xi^2 and 1 - eta^2 for u and v,
// amplitudes (a1u, a2u, a1v, a2v). Derivatives use the centre Jacobian J0 and are scaled by
// det J0 / det J (Taylor's correction), so that their integral over the element vanishes and the
// patch test passes on any quadrilateral.
void IncompatibleRows(const ElementFrame &f, double xi, double eta, double detJ, double G[3][4])
{
  const Shape s0 = ShapeAt(0, 0);
  double J0[2][2] = {};
  for (int i = 0; i < 4; ++i) {
    J0[0][0] += s0.dxi[i] * f.x[i];
    J0[0][1] += s0.dxi[i] * f.y[i];
    J0[1][0] += s0.deta[i] * f.x[i];
    J0[1][1] += s0.deta[i] * f.y[i];
  }
  const double d0 = J0[0][0] * J0[1][1] - J0[0][1] * J0[1][0], r = d0 / detJ;
  const double dP[2][2] = {{-2 * xi, 0}, {0, -2 * eta}}; // mode k: (d/dxi, d/deta)
  double dx[2], dy[2];
  for (int k = 0; k < 2; ++k) {
    dx[k] = r * (J0[1][1] * dP[k][0] - J0[0][1] * dP[k][1]) / d0;
    dy[k] = r * (-J0[1][0] * dP[k][0] + J0[0][0] * dP[k][1]) / d0;
  }
  const double rows[3][4] = {{dx[0], dx[1], 0, 0}, {0, 0, dy[0], dy[1]}, {dy[0], dy[1], dx[0], dx[1]}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) G[i][j] = rows[i][j];
}

// Solves the 4x4 system A x = b in place (A symmetric positive definite here), for nrhs columns of b.
void Solve4(double A[4][4], double *b, int nrhs)
{
  for (int c = 0; c < 4; ++c) {
    int piv = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::fabs(A[r][c]) > std::fabs(A[piv][c])) piv = r;
    if (!(std::fabs(A[piv][c]) > 0)) throw std::invalid_argument("Shell element: singular incompatible-mode stiffness (zero membrane stiffness?)");
    for (int k = 0; k < 4; ++k) std::swap(A[c][k], A[piv][k]);
    for (int k = 0; k < nrhs; ++k) std::swap(b[4 * k + c], b[4 * k + piv]);
    for (int r = c + 1; r < 4; ++r) {
      const double f = A[r][c] / A[c][c];
      for (int k = c; k < 4; ++k) A[r][k] -= f * A[c][k];
      for (int k = 0; k < nrhs; ++k) b[4 * k + r] -= f * b[4 * k + c];
    }
  }
  for (int k = 0; k < nrhs; ++k)
    for (int r = 3; r >= 0; --r) {
      double v = b[4 * k + r];
      for (int j = r + 1; j < 4; ++j) v -= A[r][j] * b[4 * k + j];
      b[4 * k + r] = v / A[r][r];
    }
}

// The local stiffness (element frame, flat nodes) KL, and for the incompatible membrane the blocks
// Kau (4 x 24) and Kaa (4 x 4) before condensation.
struct LocalStiffness {
  double KL[24][24] = {}, Kau[4][24] = {}, Kaa[4][4] = {};
};

void Local(const ElementFrame &f, const ShellMaterial &mat, const ElementOptions &o, LocalStiffness &S)
{
  if (!(o.drill >= 0) || !std::isfinite(o.drill))
    throw std::invalid_argument("Shell element: drilling factor = " + std::to_string(o.drill) + " must be >= 0");
  const ShellMaterial m = ElementSection(f, mat);
  const double gamma = o.drill * (m.A[0] + m.A[4] - 2 * m.A[1] + 4 * m.A[8]) / 8;
  const bool qm6 = o.membrane == Membrane::Incompatible;
  for (int g = 0; g < 4; ++g) {
    const double xi = kXi[g] * kGauss, eta = kEta[g] * kGauss;
    const BMatrix B = BAt(f, xi, eta);
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
        S.KL[a][b] += w * v;
      }
    if (qm6) {
      double G[3][4];
      IncompatibleRows(f, xi, eta, B.detJ, G);
      for (int a = 0; a < 4; ++a) {
        for (int b = 0; b < 24; ++b)
          for (int i = 0; i < 3; ++i) S.Kau[a][b] += w * G[i][a] * NM[i][b]; // G^T (A Bm + B Bb)
        for (int b = 0; b < 4; ++b)
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) S.Kaa[a][b] += w * G[i][a] * m.A[3 * i + j] * G[j][b];
      }
    }
  }
  if (qm6) { // static condensation: KL -= Kau^T Kaa^-1 Kau
    double X[24 * 4], A[4][4];
    for (int b = 0; b < 24; ++b)
      for (int a = 0; a < 4; ++a) X[4 * b + a] = S.Kau[a][b];
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) A[i][j] = S.Kaa[i][j];
    Solve4(A, X, 24);
    for (int a = 0; a < 24; ++a)
      for (int b = 0; b < 24; ++b) {
        double v = 0;
        for (int k = 0; k < 4; ++k) v += S.Kau[k][a] * X[4 * b + k];
        S.KL[a][b] -= v;
      }
  }
  // Symmetrise (the products above are symmetric up to round-off).
  for (int a = 0; a < 24; ++a)
    for (int b = a + 1; b < 24; ++b) S.KL[a][b] = S.KL[b][a] = 0.5 * (S.KL[a][b] + S.KL[b][a]);
}

} // namespace

void ElementStiffness(const Nodes &X, const ShellMaterial &mat, const ElementOptions &options, ElementMatrix &K)
{
  const ElementFrame f = MakeElementFrame(X);
  LocalStiffness S;
  Local(f, mat, options, S);
  // K = T^T KL T, node block by node block.
  const auto T = Transforms(f);
  for (int p = 0; p < 4; ++p)
    for (int q = 0; q < 4; ++q) {
      double tmp[6][6] = {};
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
          for (int k = 0; k < 6; ++k) tmp[i][j] += S.KL[6 * p + i][6 * q + k] * T[q][6 * k + j];
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
          double v = 0;
          for (int k = 0; k < 6; ++k) v += T[p][6 * k + i] * tmp[k][j];
          K[24 * (6 * p + i) + 6 * q + j] = v;
        }
    }
}

void ElementStiffness(const Nodes &X, const ShellMaterial &mat, double drill, ElementMatrix &K)
{
  ElementOptions o;
  o.drill = drill;
  ElementStiffness(X, mat, o, K);
}

namespace {
// Consistent nodal forces of a surface traction t(n dA) integrated over the bilinear surface with
// 2 x 2 Gauss points; n dA = X_xi x X_eta dxi deta is handed to `traction`, which returns t dA.
template <class Traction>
void SurfaceLoad(const Nodes &X, Traction traction, ElementVector &F)
{
  F.fill(0);
  for (int g = 0; g < 4; ++g) {
    const Shape s = ShapeAt(kXi[g] * kGauss, kEta[g] * kGauss);
    Vec3        gxi{}, geta{};
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) {
        gxi[k] += s.dxi[i] * X[i][k];
        geta[k] += s.deta[i] * X[i][k];
      }
    const Vec3 tdA = traction(Cross(gxi, geta));
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) F[6 * i + k] += s.N[i] * tdA[k];
  }
}
} // namespace

void ElementLoad(const Nodes &X, const Vec3 &q, ElementVector &F)
{
  SurfaceLoad(X, [&q](const Vec3 &ndA) { const double dA = Norm(ndA); return Vec3{q[0] * dA, q[1] * dA, q[2] * dA}; }, F);
}

void ElementPressure(const Nodes &X, double p, ElementVector &F)
{
  SurfaceLoad(X, [p](const Vec3 &ndA) { return Vec3{p * ndA[0], p * ndA[1], p * ndA[2]}; }, F);
}

GeneralisedStrains ElementStrains(const Nodes &X, const ShellMaterial &mat, const ElementOptions &options,
                                  const ElementVector &u, double xi, double eta)
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
  if (options.membrane == Membrane::Incompatible) { // recover the condensed amplitudes
    LocalStiffness S;
    Local(f, mat, options, S);
    double alpha[4] = {}, A[4][4];
    for (int a = 0; a < 4; ++a) {
      for (int k = 0; k < 24; ++k) alpha[a] -= S.Kau[a][k] * ul[k];
      for (int b = 0; b < 4; ++b) A[a][b] = S.Kaa[a][b];
    }
    Solve4(A, alpha, 1);
    double G[3][4];
    IncompatibleRows(f, xi, eta, B.detJ, G);
    for (int i = 0; i < 3; ++i)
      for (int a = 0; a < 4; ++a) e.membrane[i] += G[i][a] * alpha[a];
  }
  return e;
}

GeneralisedStrains ElementStrains(const Nodes &X, const ElementVector &u, double xi, double eta)
{
  ElementOptions o;
  o.membrane = Membrane::Bilinear; // no material: the nodal (compatible) part only
  return ElementStrains(X, ShellMaterial{}, o, u, xi, eta);
}

} // namespace boltnet::shell
