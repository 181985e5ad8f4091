// The four-node shell element: MITC4 with director kinematics (see shell.hpp, kinematics.hpp and
// docs/shell.md).
#include "shell/kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace boltnet::shell {

using namespace detail;

namespace {

constexpr double kXi[4] = {-1, 1, 1, -1}, kEta[4] = {-1, -1, 1, 1};
constexpr double kGauss = 0.57735026918962576451; // 1/sqrt(3)

struct Shape {
  double N[4], dxi[4], deta[4];
};

Shape ShapeAt(double xi, double eta)
{
  Shape s;
  for (int i = 0; i < 4; ++i) {
    s.N[i]    = 0.25 * (1 + kXi[i] * xi) * (1 + kEta[i] * eta);
    s.dxi[i]  = 0.25 * kXi[i] * (1 + kEta[i] * eta);
    s.deta[i] = 0.25 * kEta[i] * (1 + kXi[i] * xi);
  }
  return s;
}

// The element: nodes, unit nodal directors, the element frame.
struct Quad {
  Nodes        X;
  Directors    V;
  ElementFrame f;
};

void Tangents(const Nodes &X, const Shape &s, Vec3 &axi, Vec3 &aeta)
{
  axi = aeta = Vec3{0, 0, 0};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) {
      axi[k] += s.dxi[i] * X[i][k];
      aeta[k] += s.deta[i] * X[i][k];
    }
}

// Directors: the caller's (a smooth surface's normals shared by neighbours), or the element's own
// normals at its corners (X_xi x X_eta there; all equal to e3 on a flat element).
Quad MakeQuad(const Nodes &X, const Directors *V)
{
  Quad q{X, {}, MakeElementFrame(X)};
  for (int i = 0; i < 4; ++i) {
    if (V) {
      q.V[i] = CheckedDirector((*V)[i], q.f.e3, i, "quadrilateral");
      continue;
    }
    Vec3 axi, aeta;
    Tangents(X, ShapeAt(kXi[i], kEta[i]), axi, aeta);
    const Vec3   c = Cross(axi, aeta);
    const double n = Norm(c);
    if (!(n > 0) || !(Dot(c, q.f.e3) > 0))
      throw std::invalid_argument("Shell element: degenerate or inverted quadrilateral (no normal at node " + std::to_string(i) +
                                  "); number the nodes counter-clockwise");
    q.V[i] = Scale(1 / n, c);
  }
  return q;
}

SurfacePoint PointAt(const Quad &q, const Shape &s)
{
  Vec3 axi, aeta;
  Tangents(q.X, s, axi, aeta);
  return MakeSurfacePoint(axi, aeta, q.f.e1, q.f.e3, "quadrilateral");
}

// Covariant transverse shear rows (gamma_xi, gamma_eta) at (xi, eta), global dofs.
void CovariantShear(const Quad &q, double xi, double eta, double row_xi[24], double row_eta[24])
{
  const Shape s = ShapeAt(xi, eta);
  Vec3        axi, aeta, V{0, 0, 0};
  Tangents(q.X, s, axi, aeta);
  for (int i = 0; i < 4; ++i) V = Add(V, Scale(s.N[i], q.V[i]));
  for (int i = 0; i < 4; ++i) {
    if (row_xi) {
      AddShearRotation(axi, s.N[i], q.V[i], row_xi, 6 * i + 3);
      AddShearTranslation(V, s.dxi[i], row_xi, 6 * i);
    }
    if (row_eta) {
      AddShearRotation(aeta, s.N[i], q.V[i], row_eta, 6 * i + 3);
      AddShearTranslation(V, s.deta[i], row_eta, 6 * i);
    }
  }
}

// Strain rows at one point (local frame of the point), global dofs.
struct Rows {
  double       m[3][24] = {}, b[3][24] = {}, s[2][24] = {}, d[24] = {};
  SurfacePoint p;
};

// Without `shear` the transverse shear rows B.s stay zero: the incompatible blocks need only the
// membrane and bending rows, and the four tying points are half the cost of a point.
Rows RowsAt(const Quad &q, double xi, double eta, bool shear = true)
{
  Rows        B;
  const Shape s = ShapeAt(xi, eta);
  B.p           = PointAt(q, s);
  double dN[4][2];
  Vec3   dV[2] = {{0, 0, 0}, {0, 0, 0}};
  for (int i = 0; i < 4; ++i) {
    Cartesian(B.p, s.dxi[i], s.deta[i], dN[i]);
    for (int l = 0; l < 2; ++l) dV[l] = Add(dV[l], Scale(dN[i][l], q.V[i]));
  }
  for (int i = 0; i < 4; ++i) {
    AddMembrane(B.p, dN[i], &B.m[0][0], 24, 6 * i);
    AddDirectorBending(B.p, dN[i], q.V[i], &B.b[0][0], 24, 6 * i + 3);
    AddDirectorCurvature(dN[i], dV, &B.b[0][0], 24, 6 * i);
    AddDrill(B.p, s.N[i], dN[i], B.d, 6 * i, 6 * i + 3);
  }
  if (!shear) return B;
  // MITC4: gamma_xi tied at (0, +-1), gamma_eta at (+-1, 0), interpolated linearly across.
  double A[24] = {}, Bt[24] = {}, C[24] = {}, Dt[24] = {};
  CovariantShear(q, 0, 1, A, nullptr);
  CovariantShear(q, 0, -1, Bt, nullptr);
  CovariantShear(q, 1, 0, nullptr, C);
  CovariantShear(q, -1, 0, nullptr, Dt);
  for (int k = 0; k < 24; ++k) {
    const double gxi  = 0.5 * (1 + eta) * A[k] + 0.5 * (1 - eta) * Bt[k];
    const double geta = 0.5 * (1 + xi) * C[k] + 0.5 * (1 - xi) * Dt[k];
    double       g[2];
    Cartesian(B.p, gxi, geta, g);
    B.s[0][k] = g[0];
    B.s[1][k] = g[1];
  }
  return B;
}

// The incompatible-mode membrane rows (QM6, Wilson-Taylor): modes 1 - xi^2 and 1 - eta^2 for u and v,
// amplitudes (a1u, a2u, a1v, a2v) along the centre frame's axes. Derivatives use the centre Jacobian
// J0 and are scaled by det J0 / det J (Taylor's correction), so that their integral over the element
// vanishes and the patch test passes on any quadrilateral; on a warped element the displacement
// gradient is then seen in the local frame of the point p (R_nk = e_n(centre) . e_k(p)).
void IncompatibleRows(const Quad &q, const SurfacePoint &p, double xi, double eta, double G[3][4])
{
  const SurfacePoint p0 = PointAt(q, ShapeAt(0, 0));
  const double       r  = p0.detJ / p.detJ;
  const double       dP[2][2] = {{-2 * xi, 0}, {0, -2 * eta}}; // mode k: (d/dxi, d/deta)
  double             R[2][2];
  for (int n = 0; n < 2; ++n)
    for (int k = 0; k < 2; ++k) R[n][k] = Dot(p0.e[n], p.e[k]);
  for (int k = 0; k < 2; ++k) { // mode k, amplitude along centre axis c: gradient g_cm = d_m (centre)
    double d[2];
    Cartesian(p0, dP[k][0], dP[k][1], d);
    for (int c = 0; c < 2; ++c) {
      double e[2][2] = {}; // e_kl = sum_nm R_nk (delta_nc d_m r) R_ml: the gradient seen in p's frame
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
          for (int m = 0; m < 2; ++m) e[a][b] += R[c][a] * r * d[m] * R[m][b];
      const int col = 2 * c + k; // (a1u, a2u, a1v, a2v)
      G[0][col]     = e[0][0];
      G[1][col]     = e[1][1];
      G[2][col]     = e[0][1] + e[1][0];
    }
  }
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

// The stiffness K (global dofs), and for the incompatible membrane the blocks Kau (4 x 24) and Kaa
// (4 x 4) before condensation.
struct Stiffness {
  double K[24][24] = {}, Kau[4][24] = {}, Kaa[4][4] = {};
};

// With `stiffness` false only the incompatible blocks Kau and Kaa are integrated: ElementStrains
// needs nothing else, and the 24 x 24 products and the condensation are most of the work (the
// stresses of every element at every step written: docs/output.md).
void Integrate(const Quad &q, const ShellMaterial &mat, const ElementOptions &o, Stiffness &S, bool stiffness = true)
{
  if (!(o.drill >= 0) || !std::isfinite(o.drill))
    throw std::invalid_argument("Shell element: drilling factor = " + std::to_string(o.drill) + " must be >= 0");
  const bool qm6 = o.membrane == Membrane::Incompatible;
  for (int g = 0; g < 4; ++g) {
    const double xi = kXi[g] * kGauss, eta = kEta[g] * kGauss;
    const Rows   B  = RowsAt(q, xi, eta, stiffness);
    const double w  = B.p.detJ; // Gauss weights are 1
    // The section in the point's frame (the material direction projected on its tangent plane).
    const ShellMaterial m     = SectionInFrame(mat, B.p.e[0], B.p.e[1]);
    const double        gamma = o.drill * MembraneShear(m);
    // Generalised stresses per unit dof: S = C E, with E = [m; b] (6 rows) and s (2 rows).
    double NM[6][24] = {}, Q[2][24] = {};
    for (int k = 0; k < 24; ++k) {
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) NM[i][k] += m.A[3 * i + j] * B.m[j][k] + m.B[3 * i + j] * B.b[j][k];
      if (!stiffness) continue; // Kau needs the membrane forces N only
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) NM[i + 3][k] += m.B[3 * i + j] * B.m[j][k] + m.D[3 * i + j] * B.b[j][k];
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) Q[i][k] += m.H[2 * i + j] * B.s[j][k];
    }
    for (int a = 0; a < 24 && stiffness; ++a)
      for (int b = 0; b < 24; ++b) {
        double v = gamma * B.d[a] * B.d[b];
        for (int i = 0; i < 3; ++i) v += B.m[i][a] * NM[i][b] + B.b[i][a] * NM[i + 3][b];
        for (int i = 0; i < 2; ++i) v += B.s[i][a] * Q[i][b];
        S.K[a][b] += w * v;
      }
    if (qm6) {
      double G[3][4];
      IncompatibleRows(q, B.p, xi, eta, G);
      for (int a = 0; a < 4; ++a) {
        for (int b = 0; b < 24; ++b)
          for (int i = 0; i < 3; ++i) S.Kau[a][b] += w * G[i][a] * NM[i][b]; // G^T (A Bm + B Bb)
        for (int b = 0; b < 4; ++b)
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) S.Kaa[a][b] += w * G[i][a] * m.A[3 * i + j] * G[j][b];
      }
    }
  }
  if (!stiffness) return;
  if (qm6) { // static condensation: K -= Kau^T Kaa^-1 Kau
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
        S.K[a][b] -= v;
      }
  }
  // Symmetrise (the products above are symmetric up to round-off).
  for (int a = 0; a < 24; ++a)
    for (int b = a + 1; b < 24; ++b) S.K[a][b] = S.K[b][a] = 0.5 * (S.K[a][b] + S.K[b][a]);
}

// Warping::RigidLinks: the flat element in the mean plane (nodes projected along e3, director e3),
// joined to the nodes by rigid links u_flat = u + h (e3 x theta). Per node: flat dofs = T global dofs.
struct RigidLinks {
  Quad   flat;
  double T[4][6][6];
};

RigidLinks MakeRigidLinks(const Nodes &X)
{
  RigidLinks r;
  const ElementFrame f = MakeElementFrame(X);
  Nodes              P;
  for (int i = 0; i < 4; ++i) P[i] = Sub(X[i], Scale(f.h[i], f.e3));
  r.flat = Quad{P, {f.e3, f.e3, f.e3, f.e3}, MakeElementFrame(P)};
  for (int i = 0; i < 4; ++i) {
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b) r.T[i][a][b] = a == b;
    const Vec3 &e = f.e3; // (e x theta)_a = sum_b [e]x_ab theta_b
    const double ex[3][3] = {{0, -e[2], e[1]}, {e[2], 0, -e[0]}, {-e[1], e[0], 0}};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) r.T[i][a][3 + b] = f.h[i] * ex[a][b];
  }
  return r;
}

void CheckNoDirectors(const ElementOptions &o, const Directors *V)
{
  if (V && o.warping == Warping::RigidLinks)
    throw std::invalid_argument("Shell element: Warping::RigidLinks is the flat projected element; it takes no nodal directors");
}

} // namespace

ElementFrame MakeElementFrame(const Nodes &X)
{
  ElementFrame f;
  Vec3         gxi{}, geta{};
  f.centre = {0, 0, 0};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) {
      f.centre[k] += 0.25 * X[i][k];
      gxi[k] += 0.25 * kXi[i] * X[i][k];
      geta[k] += 0.25 * kEta[i] * X[i][k];
    }
  const Vec3   n  = Cross(gxi, geta);
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
    f.x[i]       = Dot(d, f.e1);
    f.y[i]       = Dot(d, f.e2);
    f.h[i]       = Dot(d, f.e3);
  }
  return f;
}

void ElementStiffness(const Nodes &X, const Directors *V, const ShellMaterial &mat, const ElementOptions &options, ElementMatrix &K)
{
  CheckNoDirectors(options, V);
  Stiffness S;
  if (options.warping == Warping::Directors) {
    Integrate(MakeQuad(X, V), mat, options, S);
    for (int a = 0; a < 24; ++a)
      for (int b = 0; b < 24; ++b) K[24 * a + b] = S.K[a][b];
    return;
  }
  const RigidLinks r = MakeRigidLinks(X);
  Integrate(r.flat, mat, options, S);
  for (int p = 0; p < 4; ++p) // K = T^T K_flat T, node block by node block
    for (int q = 0; q < 4; ++q)
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
          double v = 0;
          for (int k = 0; k < 6; ++k)
            for (int l = 0; l < 6; ++l) v += r.T[p][k][i] * S.K[6 * p + k][6 * q + l] * r.T[q][l][j];
          K[24 * (6 * p + i) + 6 * q + j] = v;
        }
}

void ElementStiffness(const Nodes &X, const ShellMaterial &mat, const ElementOptions &options, ElementMatrix &K)
{
  ElementStiffness(X, nullptr, mat, options, K);
}

void ElementStiffness(const Nodes &X, const ShellMaterial &mat, double drill, ElementMatrix &K)
{
  ElementOptions o;
  o.drill = drill;
  ElementStiffness(X, nullptr, mat, o, K);
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
    Vec3        gxi, geta;
    Tangents(X, s, gxi, geta);
    const Vec3 tdA = traction(Cross(gxi, geta));
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) F[6 * i + k] += s.N[i] * tdA[k];
  }
}
} // namespace

void ElementLoad(const Nodes &X, const Vec3 &q, ElementVector &F)
{
  SurfaceLoad(X, [&q](const Vec3 &ndA) { return Scale(Norm(ndA), q); }, F);
}

void ElementPressure(const Nodes &X, double p, ElementVector &F)
{
  SurfaceLoad(X, [p](const Vec3 &ndA) { return Scale(p, ndA); }, F);
}

namespace {

// Y = Kaa^-1 Kau of the element as integrated (ElementCondensedModes).
CondensedModes IncompatibleModes(const Quad &q, const ShellMaterial &mat, const ElementOptions &options)
{
  CondensedModes c;
  if (options.membrane != Membrane::Incompatible) return c;
  Stiffness S;
  Integrate(q, mat, options, S, false);
  double A[4][4];
  for (int k = 0; k < 24; ++k)
    for (int a = 0; a < 4; ++a) c.Y[4 * k + a] = S.Kau[a][k];
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) A[a][b] = S.Kaa[a][b];
  Solve4(A, c.Y.data(), 24);
  c.any = true;
  return c;
}

} // namespace

CondensedModes ElementCondensedModes(const Nodes &X, const Directors *V, const ShellMaterial &mat, const ElementOptions &options)
{
  CheckNoDirectors(options, V);
  return IncompatibleModes(options.warping == Warping::Directors ? MakeQuad(X, V) : MakeRigidLinks(X).flat, mat, options);
}

GeneralisedStrains ElementStrains(const Nodes &X, const Directors *V, const ShellMaterial &mat, const ElementOptions &options,
                                  const ElementVector &u, double xi, double eta, const CondensedModes *kept)
{
  CheckNoDirectors(options, V);
  Quad          q;
  ElementVector ul = u; // dofs of the element q
  if (options.warping == Warping::Directors) q = MakeQuad(X, V);
  else {
    const RigidLinks r = MakeRigidLinks(X);
    q                  = r.flat;
    for (int n = 0; n < 4; ++n)
      for (int i = 0; i < 6; ++i) {
        ul[6 * n + i] = 0;
        for (int j = 0; j < 6; ++j) ul[6 * n + i] += r.T[n][i][j] * u[6 * n + j];
      }
  }
  const Rows         B = RowsAt(q, xi, eta);
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
    std::optional<CondensedModes> fresh; // integrated here only when the caller keeps none
    if (!kept) fresh = IncompatibleModes(q, mat, options);
    const CondensedModes &c = kept ? *kept : *fresh;
    if (!c.any) throw std::invalid_argument("Shell element: the kept condensed modes are not those of an element with incompatible modes");
    double alpha[4] = {};
    for (int a = 0; a < 4; ++a)
      for (int k = 0; k < 24; ++k) alpha[a] -= c.Y[4 * k + a] * ul[k];
    double G[3][4];
    IncompatibleRows(q, B.p, xi, eta, G);
    for (int i = 0; i < 3; ++i)
      for (int a = 0; a < 4; ++a) e.membrane[i] += G[i][a] * alpha[a];
  }
  return e;
}

GeneralisedStrains ElementStrains(const Nodes &X, const ShellMaterial &mat, const ElementOptions &options, const ElementVector &u,
                                  double xi, double eta)
{
  return ElementStrains(X, nullptr, mat, options, u, xi, eta);
}

GeneralisedStrains ElementStrains(const Nodes &X, const ElementVector &u, double xi, double eta)
{
  ElementOptions o;
  o.membrane = Membrane::Bilinear; // no material: the nodal (compatible) part only
  return ElementStrains(X, nullptr, ShellMaterial{}, o, u, xi, eta);
}

} // namespace boltnet::shell
