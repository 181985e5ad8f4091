// Exact solutions for the shell tests: closed forms and series for the benchmark references, patch tests
// and laminated plates against classical lamination theory (see shell_benchmarks.hpp).
#include "shell_benchmarks.hpp"

#include <algorithm>
#include <cmath>

namespace shelltest {

double CantileverTwistSaintVenant()
{
  // J = k1 b t^3, k1 = (1 - 192 t / (pi^5 b) sum_{n odd} tanh(n pi b / (2 t)) / n^5) / 3.
  const double b = 0.2, t = 0.1, G = 1e7 / 2.6;
  double       sum = 0;
  for (int n = 1; n < 200; n += 2) sum += std::tanh(n * kPi * b / (2 * t)) / std::pow(n, 5);
  const double k1 = (1 - 192 * t / (std::pow(kPi, 5) * b) * sum) / 3;
  return 6.0 / (G * k1 * b * t * t * t);
}

double CantileverTwistMindlin()
{
  const double b = 0.2, t = 0.1, G = 1e7 / 2.6, lambda = std::sqrt(12 * 5.0 / 6.0) / t;
  const double GJ = G * b * t * t * t / 3 * (1 - 2 * std::tanh(lambda * b / 2) / (lambda * b));
  return 6.0 / GJ;
}

double CurvedBeamInPlaneElasticity()
{
  // Airy function (A r^3 + B / r + C r + D r ln r) sin(theta) with traction-free faces: D = -P (a^2 +
  // b^2) / N, N = a^2 - b^2 + (a^2 + b^2) ln(b / a); the loaded end moves by -pi D / E (plane stress,
  // unit thickness: P is the load per unit thickness, 1 / 0.1).
  const long double a = 4.12L, b = 4.32L, P = 10, E = 1e7L;
  const long double N = a * a - b * b + (a * a + b * b) * std::log(b / a);
  return double(kPi * P * (a * a + b * b) / (E * N));
}

double NavierCentre(double aspect, bool point)
{
  // a = 1, b = aspect: w = sum_mn q_mn sin(m pi/2) sin(n pi/2) / (D pi^4 (m^2 + (n/b)^2)^2), m, n odd;
  // q_mn = 16 q / (pi^2 m n) (uniform) or 4 P / b (central point load).
  const double b = aspect;
  const int    M = point ? 6001 : 401;
  double       w = 0;
  for (int m = 1; m <= M; m += 2)
    for (int n = 1; n <= M; n += 2) {
      const double sgn = ((m + n) / 2 - 1) % 2 ? -1 : 1; // sin(m pi/2) sin(n pi/2)
      const double den = std::pow(kPi, 4) * std::pow(m * m + (n / b) * (n / b), 2);
      w += (point ? 4 / b : 16 / (kPi * kPi * m * n)) * (point ? 1 : sgn) / den;
    }
  return w;
}

double StripPoint(bool clamped)
{
  // Strip 0 <= y <= 1, D = 1, P = 1 at (0, 1/2). W(k, y) = int w e^{-ikx} dx solves
  // W'''' - 2 k^2 W'' + k^4 W = delta(y - 1/2); on eta = y - 1/2 in [0, 1/2],
  // W = A cosh(k eta) + B eta sinh(k eta) + C sinh(k eta) + E eta cosh(k eta), with W'(0) = 0 and
  // W'''(0+) = 1/2 (symmetry and the load), and at eta = 1/2 W = 0 with W' = 0 (clamped) or W'' = 0
  // (simply supported). w(0, 1/2) = int_0^inf A dk / pi.
  auto A = [clamped](long double k) {
    const long double h = 0.5L, C = -1 / (4 * k * k * k), E = 1 / (4 * k * k), t = std::tanh(k * h);
    // Row 1: W(h) = 0; row 2: W'(h) = 0 or W''(h) = 0; both divided by cosh(k h).
    const long double a11 = 1, a12 = h * t, r1 = -(C * t + E * h);
    long double       a21, a22, r2;
    if (clamped) {
      a21 = k * t, a22 = t + k * h, r2 = -(C * k + E * (1 + k * h * t));
    } else {
      a21 = k * k, a22 = 2 * k + k * k * h * t, r2 = -(C * k * k * t + E * (2 * k * t + k * k * h));
    }
    return (r1 * a22 - a12 * r2) / (a11 * a22 - a12 * a21);
  };
  // A(k) is smooth, finite at 0 and decays like k^-3: Simpson on [0.001, 60], the tails by their limits.
  const int         n  = 60000;
  const long double k0 = 1e-3L, k1 = 60, h = (k1 - k0) / n;
  long double       s  = A(k0) + A(k1);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4 : 2) * A(k0 + i * h);
  const long double integral = s * h / 3 + A(k0) * k0 + A(k1) * k1 / 2; // A ~ c k^-3 beyond k1
  return double(integral / kPi);
}

Ply Carbon(double angle, double t) { return {angle, t, 140000, 10000, 0.3, 5000, 5000, 3500}; }

namespace {

// The MacNeal-Harder patch (0.24 x 0.12, four interior nodes), placed on a tilted plane in 3D.
struct Patch {
  Mesh             mesh;
  Vec3             O{1, 2, 3}, a, b, c; // plane origin, in-plane axes a, b, normal c
  std::vector<int> boundary{0, 1, 2, 3};
  explicit Patch(MeshKind kind)
  {
    const double pts[8][2] = {{0, 0}, {0.24, 0}, {0.24, 0.12}, {0, 0.12}, {0.04, 0.02}, {0.18, 0.03}, {0.16, 0.08}, {0.08, 0.08}};
    const double al = 0.3, be = 0.4; // the plane's orientation
    a = {std::cos(al), std::sin(al), 0};
    b = {-std::sin(al) * std::cos(be), std::cos(al) * std::cos(be), std::sin(be)};
    c = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    for (auto &q : pts) mesh.X.push_back(Global(q[0], q[1]));
    mesh.elems = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}};
    mesh       = Split(mesh, kind, {0, 1, 0, 1, 1}, {0, 1, 2, 3, 4});
  }
  Vec3   Global(double x, double y) const { return {O[0] + x * a[0] + y * b[0], O[1] + x * a[1] + y * b[1], O[2] + x * a[2] + y * b[2]}; }
  double X(int n) const { return (mesh.X[n][0] - O[0]) * a[0] + (mesh.X[n][1] - O[1]) * a[1] + (mesh.X[n][2] - O[2]) * a[2]; }
  double Y(int n) const { return (mesh.X[n][0] - O[0]) * b[0] + (mesh.X[n][1] - O[1]) * b[1] + (mesh.X[n][2] - O[2]) * b[2]; }
};

// The exact field of constant membrane strain eps, constant curvature kap (plane axes) and in-plane
// rotation omega at a point (x, y): local (u, v, w, theta_x, theta_y, theta_z).
std::array<double, 6> ExactField(const std::array<double, 3> &eps, const std::array<double, 3> &kap, double omega, double x, double y)
{
  const double u = eps[0] * x + 0.5 * eps[2] * y - omega * y, v = 0.5 * eps[2] * x + eps[1] * y + omega * x;
  const double w   = -0.5 * (kap[0] * x * x + kap[1] * y * y + kap[2] * x * y);
  const double thx = -(kap[1] * y + 0.5 * kap[2] * x), thy = kap[0] * x + 0.5 * kap[2] * y; // zero transverse shear
  return {u, v, w, thx, thy, omega};
}

// Strain components (xx, yy, 2xy) of a plane tensor (plane axes a, b) seen in axes e1, e2.
std::array<double, 3> InAxes(const std::array<double, 3> &e, const Patch &P, const Vec3 &e1, const Vec3 &e2)
{
  auto         dot = [](const Vec3 &p, const Vec3 &q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; };
  const double c1[2] = {dot(e1, P.a), dot(e1, P.b)}, c2[2] = {dot(e2, P.a), dot(e2, P.b)};
  const double T[2][2] = {{e[0], e[2] / 2}, {e[2] / 2, e[1]}};
  auto         q       = [&](const double *p, const double *r) {
    double s = 0;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) s += p[i] * T[i][j] * r[j];
    return s;
  };
  return {q(c1, c1), q(c2, c2), 2 * q(c1, c2)};
}

// Solves the 6x6 system [A B; B D] [eps; kap] = [N; M].
std::array<double, 6> CLT(const ShellMaterial &m, const std::array<double, 6> &NM)
{
  double S[6][7];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      S[i][j]         = m.A[3 * i + j];
      S[i][j + 3]     = m.B[3 * i + j];
      S[i + 3][j]     = m.B[3 * i + j];
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

} // namespace

// Returns the largest error, relative to the field's scale, of (a) the interior nodal dofs (rotations
// times the patch length L, against the largest of |u| and |theta| L), and (b) the strains at interior
// points of every element on both faces, eps +- t/2 kappa, with the transverse shear and the drilling
// defect (all exactly zero), against the largest face strain.
double PatchTestError(const ShellMaterial &mat, const std::array<double, 3> &eps, const std::array<double, 3> &kap, double omega,
                      const Discretization &s)
{
  const Patch  P(s.kind);
  const double L = 0.24, t = mat.thickness;
  Problem      p(P.mesh, mat, s);
  p.normal    = [&](const Vec3 &) { return P.c; };
  auto global = [&](const std::array<double, 6> &l) {
    std::array<double, 6> g{};
    for (int k = 0; k < 3; ++k) {
      g[k]     = l[0] * P.a[k] + l[1] * P.b[k] + l[2] * P.c[k];
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
  const std::vector<double> u   = Solve(p);
  double                    err = 0;
  for (int n = 4; n < 8; ++n) {
    const auto g = global(ExactField(eps, kap, omega, P.X(n), P.Y(n)));
    for (int k = 0; k < 6; ++k) err = std::max(err, std::fabs(u[6 * n + k] - g[k]) * (k < 3 ? 1 : L) / uscale);
  }
  double escale = 0;
  for (int k = 0; k < 3; ++k) escale = std::max({escale, std::fabs(eps[k] + t / 2 * kap[k]), std::fabs(eps[k] - t / 2 * kap[k])});
  const double quad[4][2] = {{-0.577, -0.577}, {0.577, -0.577}, {0.577, 0.577}, {-0.577, 0.577}};
  const double tri[3][2]  = {{1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6}, {1.0 / 6, 2.0 / 3}};
  for (size_t e = 0; e < P.mesh.elems.size(); ++e) {
    const auto &el = P.mesh.elems[e];
    Vec3        e1, e2;
    if (el.size() == 4) {
      const ElementFrame f = MakeElementFrame(Nodes{P.mesh.X[el[0]], P.mesh.X[el[1]], P.mesh.X[el[2]], P.mesh.X[el[3]]});
      e1 = f.e1, e2 = f.e2;
    } else {
      const TriFrame f = MakeElementFrame(TriNodes{P.mesh.X[el[0]], P.mesh.X[el[1]], P.mesh.X[el[2]]});
      e1 = f.e1, e2 = f.e2;
    }
    const auto me = InAxes(eps, P, e1, e2), ke = InAxes(kap, P, e1, e2);
    for (size_t g = 0; g < el.size(); ++g) {
      const double           *nat = el.size() == 4 ? quad[g] : tri[g];
      const GeneralisedStrains st = Strains(p, u, e, nat[0], nat[1]);
      for (int k = 0; k < 3; ++k)
        for (double z : {-t / 2, t / 2}) err = std::max(err, std::fabs(st.membrane[k] + z * st.curvature[k] - me[k] - z * ke[k]) / escale);
      err = std::max(err, std::max(std::fabs(st.shear[0]), std::fabs(st.shear[1])) / escale);
      err = std::max(err, std::fabs(st.drill) / escale);
    }
  }
  return err;
}

// A free laminated plate a x b (distorted interior nodes) loaded on its edges x = 0 and x = a by a
// uniform resultant Nx, Nxy (and Nxy on y = 0, b for equilibrium) or moment Mx; one corner node fixed.
double LaminatePlateError(const ShellMaterial &mat, double Nx, double Nxy, double Mx, const Discretization &s)
{
  const double a = 100, b = 50;
  const int    nx = 8, ny = 4;
  Mesh         mesh = Grid(nx, ny, [&](double x, double y) {
    // interior nodes moved off the grid (edges stay straight)
    const double dx = (x > 0 && x < 1 && y > 0 && y < 1) ? 0.3 / nx * std::sin(7 * x + 3 * y) : 0;
    const double dy = (x > 0 && x < 1 && y > 0 && y < 1) ? 0.3 / ny * std::cos(5 * x - 4 * y) : 0;
    return Vec3{a * (x + dx), b * (y + dy), 0};
  }, s.kind);
  Problem p(mesh, mat, s);
  p.normal = [](const Vec3 &) { return Vec3{0, 0, 1}; };
  // Edge loads by segment (consistent for a uniform resultant on a straight edge).
  auto edge = [&](int n0, int n1, int comp, double value) {
    const Vec3  &A = mesh.X[n0], &B = mesh.X[n1];
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
  const std::vector<double>   u  = Solve(p);
  const auto                  ek = CLT(mat, {Nx, 0, Nxy, Mx, 0, 0});
  const std::array<double, 3> eps{ek[0], ek[1], ek[2]}, kap{ek[3], ek[4], ek[5]};
  double                      scale = 0, err = 0;
  for (int k = 0; k < 3; ++k) scale = std::max({scale, std::fabs(eps[k]) * a, std::fabs(kap[k]) * a * a});
  for (size_t n = 0; n < mesh.X.size(); ++n) {
    const auto f = ExactField(eps, kap, 0.0, mesh.X[n][0], mesh.X[n][1]);
    for (int k = 0; k < 6; ++k) err = std::max(err, std::fabs(u[6 * n + k] - f[k]) / (k < 3 ? scale : scale / a));
  }
  return err;
}

} // namespace shelltest
