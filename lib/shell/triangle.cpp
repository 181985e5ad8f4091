// The three-node shell element: MITC3+ (or MITC3) bending and transverse shear with director
// kinematics; the CST membrane with the Hughes-Brezzi drilling term, or Felippa's ANDES OPT membrane
// with drilling freedoms (all-triangle meshes). See shell.hpp, kinematics.hpp and docs/shell.md.
//
// References: P.S. Lee, K.J. Bathe, "Development of MITC isotropic triangular shell finite elements",
// Computers & Structures 82 (2004) 945-962 (MITC3); Y. Lee, P.S. Lee, K.J. Bathe, "The MITC3+ shell
// element and its performance", Computers & Structures 138 (2014) 12-23; C.A. Felippa, "A study of
// optimal membrane triangles with drilling freedoms", Comput. Methods Appl. Mech. Engrg. 192 (2003)
// 2125-2168 (the ANDES template and the OPT signature).
#include "shell/kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace boltnet::shell {

using namespace detail;

namespace {

constexpr int kCols = 20; // 18 nodal dofs + the two bubble rotations of MITC3+

// 7-point rule of degree 5 on the triangle (Radon): r, s and weights summing to 1 (times the area).
struct RulePoint {
  double r, s, w;
};
std::array<RulePoint, 7> Rule7()
{
  const double q = std::sqrt(15.0), a = (6 - q) / 21, b = (6 + q) / 21, wa = (155 - q) / 1200, wb = (155 + q) / 1200;
  return {{{1.0 / 3, 1.0 / 3, 9.0 / 40}, {a, a, wa}, {1 - 2 * a, a, wa}, {a, 1 - 2 * a, wa}, {b, b, wb}, {1 - 2 * b, b, wb}, {b, 1 - 2 * b, wb}}};
}

constexpr double kdN[2][3] = {{-1, 1, 0}, {-1, 0, 1}}; // d N_i / d r, d N_i / d s

struct Tri {
  TriNodes     X;
  TriDirectors V;  // unit nodal directors
  TriFrame     f;
  SurfacePoint p;  // the flat mid-surface: one tangent frame
  Vec3         V4, t1, t2; // bubble director (mean of the nodal ones) and the axes of its rotation
  double       dN[3][2];   // Cartesian derivatives of the linear shape functions
  Vec3         dV[2];      // director gradient V_,k
};

Tri MakeTri(const TriNodes &X, const TriDirectors *V)
{
  Tri t;
  t.X = X;
  t.f = MakeElementFrame(X);
  t.p = MakeSurfacePoint(Sub(X[1], X[0]), Sub(X[2], X[0]), t.f.e1, t.f.e3, "triangle");
  t.V4 = {0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    t.V[i] = V ? CheckedDirector((*V)[i], t.f.e3, i, "triangle") : t.f.e3;
    t.V4   = Add(t.V4, Scale(1.0 / 3, t.V[i]));
  }
  const Vec3 v = Scale(1 / Norm(t.V4), t.V4);
  const Vec3 a = Sub(t.f.e1, Scale(Dot(t.f.e1, v), v));
  t.t1         = Scale(1 / Norm(a), a);
  t.t2         = Cross(v, t.t1);
  t.dV[0] = t.dV[1] = Vec3{0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    Cartesian(t.p, kdN[0][i], kdN[1][i], t.dN[i]);
    for (int l = 0; l < 2; ++l) t.dV[l] = Add(t.dV[l], Scale(t.dN[i][l], t.V[i]));
  }
  return t;
}

// Rotation interpolation of MITC3+: f_i = N_i - f4 / 3, f4 = 27 r s (1 - r - s) (the bubble is zero
// for MITC3). Values and natural derivatives of f1..f4.
struct Rotations {
  double f[4], dr[4], ds[4];
};
Rotations RotationsAt(bool bubble, double r, double s)
{
  Rotations R;
  const double N[3] = {1 - r - s, r, s};
  const double b = bubble ? 27 * r * s * (1 - r - s) : 0, br = bubble ? 27 * s * (1 - 2 * r - s) : 0,
               bs = bubble ? 27 * r * (1 - r - 2 * s) : 0;
  for (int i = 0; i < 3; ++i) {
    R.f[i]  = N[i] - b / 3;
    R.dr[i] = kdN[0][i] - br / 3;
    R.ds[i] = kdN[1][i] - bs / 3;
  }
  R.f[3]  = b;
  R.dr[3] = br;
  R.ds[3] = bs;
  return R;
}

// Covariant transverse shear (gamma_r, gamma_s) at (r, s): a_a . D + V . u_,a.
void CovariantShear(const Tri &t, bool bubble, double r, double s, double gr[kCols], double gs[kCols])
{
  const Rotations R = RotationsAt(bubble, r, s);
  const double    N[3] = {1 - r - s, r, s};
  Vec3            V{0, 0, 0};
  for (int i = 0; i < 3; ++i) V = Add(V, Scale(N[i], t.V[i]));
  double *row[2] = {gr, gs};
  for (int a = 0; a < 2; ++a) {
    std::fill(row[a], row[a] + kCols, 0.0);
    for (int i = 0; i < 3; ++i) {
      AddShearRotation(t.p.a[a], R.f[i], t.V[i], row[a], 6 * i + 3);
      AddShearTranslation(V, kdN[a][i], row[a], 6 * i);
    }
    const Vec3 c = Cross(t.V4, t.p.a[a]); // a . (theta4 x V4) = theta4 . (V4 x a)
    row[a][18] += R.f[3] * Dot(t.t1, c);
    row[a][19] += R.f[3] * Dot(t.t2, c);
  }
}

// The tied covariant shear at (r, s): MITC3+ (Lee, Lee & Bathe 2014, tying points A-F inside the
// element) or MITC3 (Lee & Bathe 2004, edge midpoints: constant tangential shear along each edge).
void TiedShear(const Tri &t, TriangleShear kind, double r, double s, double er[kCols], double es[kCols])
{
  if (kind == TriangleShear::MITC3) {
    double r1[kCols], s1[kCols], r2[kCols], s2[kCols], r3[kCols], s3[kCols];
    CovariantShear(t, false, 0.5, 0, r1, s1);
    CovariantShear(t, false, 0, 0.5, r2, s2);
    CovariantShear(t, false, 0.5, 0.5, r3, s3);
    for (int k = 0; k < kCols; ++k) {
      const double c = s2[k] - r1[k] - s3[k] + r3[k];
      er[k]          = r1[k] + c * s;
      es[k]          = s2[k] - c * r;
    }
    return;
  }
  const double d = 1e-4;
  double       rA[kCols], sA[kCols], rB[kCols], sB[kCols], rC[kCols], sC[kCols], rD[kCols], sD[kCols], rE[kCols], sE[kCols], rF[kCols], sF[kCols];
  CovariantShear(t, true, 1.0 / 6, 2.0 / 3, rA, sA);
  CovariantShear(t, true, 2.0 / 3, 1.0 / 6, rB, sB);
  CovariantShear(t, true, 1.0 / 6, 1.0 / 6, rC, sC);
  CovariantShear(t, true, 1.0 / 3 + d, 1.0 / 3 - 2 * d, rD, sD);
  CovariantShear(t, true, 1.0 / 3 - 2 * d, 1.0 / 3 + d, rE, sE);
  CovariantShear(t, true, 1.0 / 3 + d, 1.0 / 3 + d, rF, sF);
  for (int k = 0; k < kCols; ++k) {
    const double c = rF[k] - rD[k] - sF[k] + sE[k];
    er[k]          = 2.0 / 3 * (rB[k] - 0.5 * sB[k]) + 1.0 / 3 * (rC[k] + sC[k]) + c / 3 * (3 * s - 1);
    es[k]          = 2.0 / 3 * (sA[k] - 0.5 * rA[k]) + 1.0 / 3 * (rC[k] + sC[k]) + c / 3 * (1 - 3 * r);
  }
}

// The OPT membrane (Felippa 2003): eps = (L^T / A + sqrt(beta0) B_h(zeta)) q with q = (u_i, v_i,
// theta_i) in the element frame; L the basic lumping matrix (alpha_b = 3/2), B_h = 3/2 Te Q(zeta) Ttu
// the higher-order natural strain, of zero mean, so that K = K_basic + beta0 K_higher exactly.
struct Opt {
  double L[9][3], Te[3][3], Q[3][3][3], T[3][9], A, sqb0;
};

// beta0 of the OPT signature for an anisotropic membrane (Felippa 2003): 2 / avg(E11 C11) - 3/2,
// at least 1/100; (1 - 4 nu^2) / 2 when isotropic.
double Beta0(const Mat3 &E)
{
  const double E11 = E[0], E12 = E[1], E13 = E[2], E22 = E[4], E23 = E[5], E33 = E[8];
  const double det = E11 * E22 * E33 + 2 * E12 * E13 * E23 - E11 * E23 * E23 - E22 * E13 * E13 - E33 * E12 * E12;
  const double W = -6 * E12 * E12 * E12 + 5 * E11 * E11 * E22 - 5 * E12 * E12 * E22 -
                   E22 * (75 * E13 * E13 + 14 * E13 * E23 + 3 * E23 * E23) + 2 * E12 * (7 * E13 * E13 + 46 * E13 * E23 + 7 * E23 * E23) -
                   E11 * (5 * E12 * E12 + 3 * E13 * E13 - 6 * E12 * E22 - 5 * E22 * E22 + 14 * E13 * E23 + 75 * E23 * E23) +
                   (3 * E11 * E11 + 82 * E11 * E22 + 3 * E22 * E22 - 4 * (6 * E12 * E12 + 5 * E13 * E13 - 6 * E13 * E23 + 5 * E23 * E23)) * E33 +
                   4 * (5 * E11 - 6 * E12 + 5 * E22) * E33 * E33;
  if (!(det > 0)) throw std::invalid_argument("Shell triangle: membrane stiffness A is not positive definite (OPT membrane)");
  return std::max(2 / (W / (128 * det)) - 1.5, 0.01);
}

Opt MakeOpt(const Tri &t, const Mat3 &A)
{
  Opt          o{};
  const auto  &x = t.f.x, &y = t.f.y;
  const double x12 = x[0] - x[1], x21 = -x12, x13 = x[0] - x[2], x31 = -x13, x23 = x[1] - x[2], x32 = -x23;
  const double y12 = y[0] - y[1], y21 = -y12, y13 = y[0] - y[2], y31 = -y13, y23 = y[1] - y[2], y32 = -y23;
  const double L21 = x21 * x21 + y21 * y21, L32 = x32 * x32 + y32 * y32, L13 = x13 * x13 + y13 * y13;
  o.A = 0.5 * (y21 * x13 - x21 * y13);
  const double ab = 1.5, b[10] = {0, 1, 2, 1, 0, 1, -1, -1, -1, -2}; // b[1..9]: the OPT signature
  const double L[9][3] = {{y23, 0, x32},
                          {0, x32, y23},
                          {ab * y23 * (y13 - y21) / 6, ab * x32 * (x31 - x12) / 6, ab * (x31 * y13 - x12 * y21) / 3},
                          {y31, 0, x13},
                          {0, x13, y31},
                          {ab * y31 * (y21 - y32) / 6, ab * x13 * (x12 - x23) / 6, ab * (x12 * y21 - x23 * y32) / 3},
                          {y12, 0, x21},
                          {0, x21, y12},
                          {ab * y12 * (y32 - y13) / 6, ab * x21 * (x23 - x31) / 6, ab * (x23 * y32 - x31 * y13) / 3}};
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 3; ++j) o.L[i][j] = 0.5 * L[i][j];
  const double s = 1 / (4 * o.A * o.A);
  const double Te[3][3] = {{y23 * y13 * L21, y31 * y21 * L32, y12 * y32 * L13},
                           {x23 * x13 * L21, x31 * x21 * L32, x12 * x32 * L13},
                           {(y23 * x31 + x32 * y13) * L21, (y31 * x12 + x13 * y21) * L32, (y12 * x23 + x21 * y32) * L13}};
  const int    perm[3][3][3] = {{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}}, {{9, 7, 8}, {3, 1, 2}, {6, 4, 5}}, {{5, 6, 4}, {8, 9, 7}, {2, 3, 1}}};
  const double LL[3] = {L21, L32, L13};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      o.Te[i][j] = s * Te[i][j];
      for (int k = 0; k < 3; ++k) o.Q[k][i][j] = 2 * o.A / 3 * b[perm[k][i][j]] / LL[i];
    }
  const double x_[3] = {x32, x13, x21}, y_[3] = {y32, y13, y21};
  for (int r = 0; r < 3; ++r)
    for (int n = 0; n < 3; ++n) {
      o.T[r][3 * n]     = x_[n] / (4 * o.A);
      o.T[r][3 * n + 1] = y_[n] / (4 * o.A);
      o.T[r][3 * n + 2] = r == n;
    }
  o.sqb0 = std::sqrt(Beta0(A));
  return o;
}

// Membrane rows (3 x kCols, global dofs) at (r, s): OPT, or the CST (constant) when opt is null.
void MembraneRows(const Tri &t, const Opt *opt, double r, double s, double m[3][kCols])
{
  double B[3][9] = {};
  if (opt) {
    const double z[3] = {1 - r - s, r, s};
    double       TQ[3][3] = {}, TQT[3][9] = {};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          for (int n = 0; n < 3; ++n) TQ[i][j] += opt->Te[i][k] * z[n] * opt->Q[n][k][j];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 9; ++j)
        for (int k = 0; k < 3; ++k) TQT[i][j] += TQ[i][k] * opt->T[k][j];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 9; ++j) B[i][j] = opt->L[j][i] / opt->A + opt->sqb0 * 1.5 * TQT[i][j];
  } else {
    for (int n = 0; n < 3; ++n) {
      B[0][3 * n]     = t.dN[n][0];
      B[1][3 * n + 1] = t.dN[n][1];
      B[2][3 * n]     = t.dN[n][1];
      B[2][3 * n + 1] = t.dN[n][0];
    }
  }
  for (int i = 0; i < 3; ++i) {
    std::fill(m[i], m[i] + kCols, 0.0);
    for (int n = 0; n < 3; ++n)
      for (int k = 0; k < 3; ++k) {
        m[i][6 * n + k] = B[i][3 * n] * t.f.e1[k] + B[i][3 * n + 1] * t.f.e2[k];
        m[i][6 * n + 3 + k] = B[i][3 * n + 2] * t.f.e3[k];
      }
  }
}

// Strain rows at (r, s): membrane m, curvature b (with the bubble columns), tied shear s, drilling d.
struct Rows {
  double m[3][kCols], b[3][kCols] = {}, s[2][kCols], d[kCols] = {};
};

Rows RowsAt(const Tri &t, const Opt *opt, TriangleShear shear, double r, double s)
{
  Rows  B;
  const bool      bubble = shear == TriangleShear::MITC3Plus;
  const Rotations R      = RotationsAt(bubble, r, s);
  MembraneRows(t, opt, r, s, B.m);
  const double N[3] = {1 - r - s, r, s};
  for (int i = 0; i < 3; ++i) {
    double df[2];
    Cartesian(t.p, R.dr[i], R.ds[i], df);
    AddDirectorBending(t.p, df, t.V[i], &B.b[0][0], kCols, 6 * i + 3);
    AddDirectorCurvature(t.dN[i], t.dV, &B.b[0][0], kCols, 6 * i);
    AddDrill(t.p, N[i], t.dN[i], B.d, 6 * i, 6 * i + 3);
  }
  if (bubble) { // e_k . (theta4 x V4)_,l = f4_,l theta4 . (V4 x e_k)
    double df[2];
    Cartesian(t.p, R.dr[3], R.ds[3], df);
    const Vec3 c1 = Cross(t.V4, t.p.e[0]), c2 = Cross(t.V4, t.p.e[1]);
    const Vec3 *axis[2] = {&t.t1, &t.t2};
    for (int q = 0; q < 2; ++q) {
      B.b[0][18 + q] += df[0] * Dot(*axis[q], c1);
      B.b[1][18 + q] += df[1] * Dot(*axis[q], c2);
      B.b[2][18 + q] += df[1] * Dot(*axis[q], c1) + df[0] * Dot(*axis[q], c2);
    }
  }
  double er[kCols], es[kCols];
  TiedShear(t, shear, r, s, er, es);
  for (int k = 0; k < kCols; ++k) {
    double g[2];
    Cartesian(t.p, er[k], es[k], g);
    B.s[0][k] = g[0];
    B.s[1][k] = g[1];
  }
  return B;
}

// Stiffness with the bubble columns (20 x 20) before condensation.
struct Stiffness {
  double K[kCols][kCols] = {};
  bool   bubble;
};

void Integrate(const Tri &t, const ShellMaterial &mat, const ElementOptions &o, Stiffness &S, Opt *opt_out = nullptr)
{
  if (!(o.drill >= 0) || !std::isfinite(o.drill))
    throw std::invalid_argument("Shell element: drilling factor = " + std::to_string(o.drill) + " must be >= 0");
  const ShellMaterial m   = SectionInFrame(mat, t.f.e1, t.f.e2);
  const bool          opt = o.triangle_membrane == TriangleMembrane::Optimal;
  Opt                 O{};
  if (opt) O = MakeOpt(t, m.A);
  if (opt_out) *opt_out = O;
  const double gamma = opt ? 0 : o.drill * MembraneShear(m);
  S.bubble           = o.triangle_shear == TriangleShear::MITC3Plus;
  const double area  = 0.5 * t.p.detJ;
  for (const RulePoint &g : Rule7()) {
    const Rows   B = RowsAt(t, opt ? &O : nullptr, o.triangle_shear, g.r, g.s);
    const double w = g.w * area;
    double       NM[6][kCols] = {}, Q[2][kCols] = {};
    for (int k = 0; k < kCols; ++k) {
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          NM[i][k] += m.A[3 * i + j] * B.m[j][k] + m.B[3 * i + j] * B.b[j][k];
          NM[i + 3][k] += m.B[3 * i + j] * B.m[j][k] + m.D[3 * i + j] * B.b[j][k];
        }
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) Q[i][k] += m.H[2 * i + j] * B.s[j][k];
    }
    for (int a = 0; a < kCols; ++a)
      for (int b = 0; b < kCols; ++b) {
        double v = gamma * B.d[a] * B.d[b];
        for (int i = 0; i < 3; ++i) v += B.m[i][a] * NM[i][b] + B.b[i][a] * NM[i + 3][b];
        for (int i = 0; i < 2; ++i) v += B.s[i][a] * Q[i][b];
        S.K[a][b] += w * v;
      }
  }
}

// Kbb^-1 (2 x 2) of the bubble rotations.
void BubbleInverse(const Stiffness &S, double inv[2][2])
{
  const double a = S.K[18][18], b = S.K[18][19], c = S.K[19][18], d = S.K[19][19], det = a * d - b * c;
  if (!(det > 0)) throw std::invalid_argument("Shell triangle: singular bubble stiffness (zero bending stiffness?)");
  inv[0][0] = d / det;
  inv[0][1] = -b / det;
  inv[1][0] = -c / det;
  inv[1][1] = a / det;
}

} // namespace

TriFrame MakeElementFrame(const TriNodes &X)
{
  TriFrame     f;
  const Vec3   a = Sub(X[1], X[0]), b = Sub(X[2], X[0]), n = Cross(a, b);
  const double la = Norm(a), nn = Norm(n), lmax = std::max({la, Norm(b), Norm(Sub(X[2], X[1]))});
  if (!(nn > 1e-12 * lmax * lmax) || !std::isfinite(nn))
    throw std::invalid_argument("Shell element: degenerate triangle (zero area, collinear or coincident nodes)");
  f.e1 = Scale(1 / la, a);
  f.e3 = Scale(1 / nn, n);
  f.e2 = Cross(f.e3, f.e1);
  f.centre = Scale(1.0 / 3, Add(Add(X[0], X[1]), X[2]));
  for (int i = 0; i < 3; ++i) {
    const Vec3 d = Sub(X[i], f.centre);
    f.x[i]       = Dot(d, f.e1);
    f.y[i]       = Dot(d, f.e2);
  }
  return f;
}

void ElementStiffness(const TriNodes &X, const TriDirectors *V, const ShellMaterial &mat, const ElementOptions &options, TriMatrix &K)
{
  const Tri t = MakeTri(X, V);
  Stiffness S;
  Integrate(t, mat, options, S);
  double inv[2][2] = {};
  if (S.bubble) BubbleInverse(S, inv);
  for (int a = 0; a < 18; ++a)
    for (int b = 0; b < 18; ++b) {
      double v = S.K[a][b];
      if (S.bubble) // static condensation of the bubble rotations
        for (int i = 0; i < 2; ++i)
          for (int j = 0; j < 2; ++j) v -= S.K[a][18 + i] * inv[i][j] * S.K[18 + j][b];
      K[18 * a + b] = v;
    }
  for (int a = 0; a < 18; ++a) // symmetrise (symmetric up to round-off)
    for (int b = a + 1; b < 18; ++b) K[18 * a + b] = K[18 * b + a] = 0.5 * (K[18 * a + b] + K[18 * b + a]);
}

void ElementStiffness(const TriNodes &X, const ShellMaterial &mat, const ElementOptions &options, TriMatrix &K)
{
  ElementStiffness(X, nullptr, mat, options, K);
}

void ElementLoad(const TriNodes &X, const Vec3 &q, TriVector &F)
{
  const double A = 0.5 * Norm(Cross(Sub(X[1], X[0]), Sub(X[2], X[0])));
  F.fill(0);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) F[6 * i + k] = q[k] * A / 3;
}

void ElementPressure(const TriNodes &X, double p, TriVector &F)
{
  const Vec3 ndA = Scale(0.5, Cross(Sub(X[1], X[0]), Sub(X[2], X[0])));
  F.fill(0);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) F[6 * i + k] = p * ndA[k] / 3;
}

namespace {

// P = -Kbb^-1 Kbu of the triangle t (ElementCondensedModes).
CondensedModes BubbleModes(const Tri &t, const ShellMaterial &mat, const ElementOptions &options)
{
  Stiffness S;
  Opt       O{};
  Integrate(t, mat, options, S, &O);
  CondensedModes c;
  if (!S.bubble) return c;
  double inv[2][2]; // the condensed bubble rotations: Kbb q4 = -Kbu u
  BubbleInverse(S, inv);
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 18; ++k) c.Y[18 * i + k] = -(inv[i][0] * S.K[18][k] + inv[i][1] * S.K[19][k]);
  c.any = true;
  return c;
}

} // namespace

CondensedModes ElementCondensedModes(const TriNodes &X, const TriDirectors *V, const ShellMaterial &mat, const ElementOptions &options)
{
  return BubbleModes(MakeTri(X, V), mat, options);
}

GeneralisedStrains ElementStrains(const TriNodes &X, const TriDirectors *V, const ShellMaterial &mat, const ElementOptions &options,
                                  const TriVector &u, double r, double s, const CondensedModes *kept)
{
  const Tri t = MakeTri(X, V);
  Opt       O{};
  if (options.triangle_membrane == TriangleMembrane::Optimal) O = MakeOpt(t, SectionInFrame(mat, t.f.e1, t.f.e2).A); // as Integrate
  std::optional<CondensedModes> fresh; // integrated here only when the caller keeps none
  if (!kept) fresh = BubbleModes(t, mat, options);
  const CondensedModes &c = kept ? *kept : *fresh;
  double ue[kCols] = {};
  for (int k = 0; k < 18; ++k) ue[k] = u[k];
  if (c.any)
    for (int i = 0; i < 2; ++i)
      for (int k = 0; k < 18; ++k) ue[18 + i] += c.Y[18 * i + k] * u[k];
  const bool         opt = options.triangle_membrane == TriangleMembrane::Optimal;
  const Rows         B   = RowsAt(t, opt ? &O : nullptr, options.triangle_shear, r, s);
  GeneralisedStrains e{};
  for (int k = 0; k < kCols; ++k) {
    for (int i = 0; i < 3; ++i) {
      e.membrane[i] += B.m[i][k] * ue[k];
      e.curvature[i] += B.b[i][k] * ue[k];
    }
    for (int i = 0; i < 2; ++i) e.shear[i] += B.s[i][k] * ue[k];
    e.drill += B.d[k] * ue[k];
  }
  return e;
}

// Mixed meshes: one entry point for both element kinds.
void ElementStiffness(int n, const Vec3 *X, const Vec3 *V, const ShellMaterial &mat, const ElementOptions &options, double *K)
{
  if (n == 4) {
    const Nodes     Xq{X[0], X[1], X[2], X[3]};
    const Directors Vq = V ? Directors{V[0], V[1], V[2], V[3]} : Directors{};
    ElementMatrix   Kq;
    ElementStiffness(Xq, V ? &Vq : nullptr, mat, options, Kq);
    std::copy(Kq.begin(), Kq.end(), K);
  } else if (n == 3) {
    const TriNodes     Xt{X[0], X[1], X[2]};
    const TriDirectors Vt = V ? TriDirectors{V[0], V[1], V[2]} : TriDirectors{};
    TriMatrix          Kt;
    ElementStiffness(Xt, V ? &Vt : nullptr, mat, options, Kt);
    std::copy(Kt.begin(), Kt.end(), K);
  } else throw std::invalid_argument("Shell element: " + std::to_string(n) + " nodes (a shell element has 3 or 4)");
}

void ElementLoad(int n, const Vec3 *X, const Vec3 &q, double *F)
{
  if (n == 4) {
    ElementVector Fq;
    ElementLoad(Nodes{X[0], X[1], X[2], X[3]}, q, Fq);
    std::copy(Fq.begin(), Fq.end(), F);
  } else if (n == 3) {
    TriVector Ft;
    ElementLoad(TriNodes{X[0], X[1], X[2]}, q, Ft);
    std::copy(Ft.begin(), Ft.end(), F);
  } else throw std::invalid_argument("Shell element: " + std::to_string(n) + " nodes (a shell element has 3 or 4)");
}

void ElementPressure(int n, const Vec3 *X, double p, double *F)
{
  if (n == 4) {
    ElementVector Fq;
    ElementPressure(Nodes{X[0], X[1], X[2], X[3]}, p, Fq);
    std::copy(Fq.begin(), Fq.end(), F);
  } else if (n == 3) {
    TriVector Ft;
    ElementPressure(TriNodes{X[0], X[1], X[2]}, p, Ft);
    std::copy(Ft.begin(), Ft.end(), F);
  } else throw std::invalid_argument("Shell element: " + std::to_string(n) + " nodes (a shell element has 3 or 4)");
}

} // namespace boltnet::shell
