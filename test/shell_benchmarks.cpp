// Shell benchmark problems (see shell_benchmarks.hpp; definitions and references in docs/shell.md).
#include "shell_benchmarks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shelltest {

namespace {

Vec3 Unit(const Vec3 &v)
{
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

// Work-conjugate displacement of the nodes `nodes` with load weights w along d: sum w_j d . u_j / sum w_j.
double Conjugate(const std::vector<double> &u, const std::vector<int> &nodes, const std::vector<double> &w, const Vec3 &d)
{
  double s = 0, ws = 0;
  for (size_t j = 0; j < nodes.size(); ++j) {
    for (int k = 0; k < 3; ++k) s += w[j] * d[k] * u[6 * nodes[j] + k];
    ws += w[j];
  }
  return s / ws;
}

// Trapezoid weights of an edge of m equal segments (a uniform edge load's consistent nodal shares).
std::vector<double> EdgeWeights(int m)
{
  std::vector<double> w(m + 1, 1.0 / m);
  w[0] = w[m] = 0.5 / m;
  return w;
}

} // namespace

// Scordelis-Lo roof (MacNeal & Harder): R = 25, L = 50, +-40 deg, t = 0.25, E = 4.32e8, nu = 0, self
// weight 90 per unit area, rigid diaphragms at the ends. Axis along x, crown at y = 0, z = R.
// Quarter model (x in [0, 25], phi in [0, 40 deg]) or full model (2n x 2n, the same nodes mirrored).
double ScordelisLo(int n, const Discretization &s, RoofOptions r)
{
  const double R = 25, L = 50, phi0 = 40 * kPi / 180;
  const bool   full = r.full;
  const int    m    = full ? 2 * n : n;
  Mesh         mesh = Grid(m, m, [&](double a, double b) {
    if (a > 0 && a < 1 && b > 0 && b < 1 && r.distortion > 0) { // node-to-node irregularity, nodes stay on the surface
      const int i = int(std::lround(a * m)), j = int(std::lround(b * m));
      a += r.distortion / m * (((i * 7 + j * 3) % 5) / 2.0 - 1);
      b += r.distortion / m * (((i * 3 + j * 11) % 5) / 2.0 - 1);
    }
    const double x = full ? L * a : L / 2 * a, phi = full ? phi0 * (2 * b - 1) : phi0 * b;
    return Vec3{x, R * std::sin(phi), R * std::cos(phi)};
  }, s.kind);
  Problem p(mesh, IsotropicMaterial(4.32e8, 0.0, 0.25), s);
  p.normal = [](const Vec3 &X) { return Unit(Vec3{0, X[1], X[2]}); };
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
double PinchedCylinder(int n, const Discretization &s, bool full)
{
  const double R = 300, L = 600;
  Mesh mesh = full ? Grid(2 * n, 4 * n, [&](double a, double b) {
    const double th = 2 * kPi * b;
    return Vec3{L * a, R * std::sin(th), R * std::cos(th)};
  }, s.kind, true)
                   : Grid(n, n, [&](double a, double b) {
    const double th = kPi / 2 * b;
    return Vec3{L / 2 * a, R * std::sin(th), R * std::cos(th)};
  }, s.kind);
  Problem p(mesh, IsotropicMaterial(3e6, 0.3, 3.0), s);
  p.normal = [](const Vec3 &X) { return Unit(Vec3{0, X[1], X[2]}); };
  if (full) {
    for (int j = 0; j < 4 * n; ++j) {
      p.FixAll(mesh.Node(0, j), {UY, UZ});
      p.FixAll(mesh.Node(2 * n, j), {UY, UZ});
    }
    p.Fix(mesh.Node(n, n), UX);
    p.F[6 * mesh.Node(n, 0) + UZ]     = -1;
    p.F[6 * mesh.Node(n, 2 * n) + UZ] = 1;
    const std::vector<double> u = Solve(p);
    return -u[6 * mesh.Node(n, 0) + UZ];
  }
  for (int j = 0; j <= n; ++j) {
    p.FixAll(mesh.Node(0, j), {UY, UZ});     // diaphragm
    p.FixAll(mesh.Node(n, j), {UX, RY, RZ}); // symmetry plane x = L/2
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
double Hemisphere(int n, const Discretization &s, bool full)
{
  const double R  = 10;
  const int    ns = full ? 4 * n : n;
  auto         map = [&](double t, double a) { // t: polar (0 equator .. 1 hole), a: azimuth fraction
    const double psi = (full ? 2 * kPi : kPi / 2) * a, th = kPi / 2 - (72 * kPi / 180) * t;
    return Vec3{R * std::sin(th) * std::cos(psi), R * std::sin(th) * std::sin(psi), R * std::cos(th)};
  };
  // Full: periodic in azimuth, which is the mesh's t direction; the quarter keeps azimuth along s.
  Mesh mesh = full ? Grid(n, ns, [&](double a, double b) { return map(a, b); }, s.kind, true)
                   : Grid(n, n, [&](double a, double b) { return map(b, a); }, s.kind);
  auto node = [&](int a, int b) { return full ? mesh.Node(b, a) : mesh.Node(a, b); }; // azimuth a, polar b
  Problem p(mesh, IsotropicMaterial(6.825e7, 0.3, 0.04), s);
  p.normal = [](const Vec3 &X) { return Unit(X); };
  if (full) {
    p.Fix(node(0, 0), UY);
    p.Fix(node(2 * n, 0), UY);
    p.Fix(node(n, 0), UX);
    for (int a : {n / 2, 3 * n / 2, 5 * n / 2}) p.Fix(node(a, 0), UZ);
    p.F[6 * node(0, 0) + UX]     = 2;
    p.F[6 * node(n, 0) + UY]     = -2;
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

// Square plate, side a = 1, t = 0.01 (a/t = 100), E = 1e7, nu = 0.3, uniform q = 1; quarter model;
// hard simple support (w = 0 and the rotation about the edge normal = 0) or clamped.
double SquarePlate(int n, bool clamped, const Discretization &s)
{
  const double a = 1, t = 0.01, E = 1e7, nu = 0.3, D = E * t * t * t / (12 * (1 - nu * nu));
  Mesh    mesh = Grid(n, n, [&](double x, double y) { return Vec3{a / 2 * x, a / 2 * y, 0}; }, s.kind);
  Problem p(mesh, IsotropicMaterial(E, nu, t), s);
  p.normal = [](const Vec3 &) { return Vec3{0, 0, 1}; };
  p.SurfaceLoad({0, 0, 1});
  for (int k = 0; k <= n; ++k) {
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

double RectPlate(int n, double aspect, bool clamped, bool point, const Discretization &s)
{
  const double a = 2, b = aspect * a, t = 1e-4, E = 1.7472e7, nu = 0.3, D = E * t * t * t / (12 * (1 - nu * nu));
  const double q = 1e-4, P = 4e-4;
  Mesh    mesh = Grid(n, n, [&](double x, double y) { return Vec3{a / 2 * x, b / 2 * y, 0}; }, s.kind);
  Problem p(mesh, IsotropicMaterial(E, nu, t), s);
  p.normal = [](const Vec3 &) { return Vec3{0, 0, 1}; };
  if (point) p.F[6 * mesh.Node(n, n) + UZ] = P / 4; // a quarter of P at the centre
  else p.SurfaceLoad({0, 0, q});
  for (int k = 0; k <= n; ++k) {
    if (clamped) {
      p.FixAll(mesh.Node(0, k), {UZ, RX, RY});
      p.FixAll(mesh.Node(k, 0), {UZ, RX, RY});
    } else {
      p.FixAll(mesh.Node(0, k), {UZ, RX});
      p.FixAll(mesh.Node(k, 0), {UZ, RY});
    }
    p.FixAll(mesh.Node(n, k), {UX, RY, RZ});
    p.FixAll(mesh.Node(k, n), {UY, RX, RZ});
  }
  const std::vector<double> u = Solve(p);
  const double              w = u[6 * mesh.Node(n, n) + UZ];
  return point ? w * D / (P * a * a) : w * D / (q * a * a * a * a);
}

const char *ShapeName(CantileverShape c)
{
  switch (c) {
  case CantileverShape::Regular: return "regular";
  case CantileverShape::Trapezoidal: return "trapezoidal";
  case CantileverShape::Parallelogram: return "parallelogram";
  }
  return "?";
}

// Straight cantilever (MacNeal & Harder): L = 6, width 0.2, t = 0.1, E = 1e7, nu = 0.3, 6 x 1
// elements, clamped at x = 0, unit tip load. Trapezoidal: the five interior element edges inclined at
// +-45 deg alternately; parallelogram: all inclined at 45 deg the same way; the clamped and loaded
// ends stay square (the beam is a 6 x 0.2 rectangle in every mesh). Refinement subdivides each
// element (its bilinear map) into refine x refine. The tip load is shared by the tip nodes like a
// uniform edge load (the twist: forces along z proportional to y, unit moment about x); returned is
// the work-conjugate tip displacement (for the twist, the tip rotation).
double Cantilever(int load, CantileverShape shape, int refine, const Discretization &s)
{
  double off[7] = {0, 0, 0, 0, 0, 0, 0}; // station i: bottom at i - 0.1 off, top at i + 0.1 off
  for (int i = 1; i < 6; ++i) off[i] = shape == CantileverShape::Regular ? 0 : shape == CantileverShape::Parallelogram ? 1 : (i % 2 ? 1 : -1);
  auto map = [&](double a, double b) {
    const double sg = 6 * a;
    const int    k  = std::min(int(sg), 5);
    const double xi = sg - k, o = (1 - xi) * off[k] + xi * off[k + 1];
    return Vec3{sg + 0.1 * o * (2 * b - 1), 0.2 * b - 0.1, 0};
  };
  const int m = refine;
  Mesh      mesh = Grid(6 * m, m, map, s.kind);
  Problem   p(mesh, IsotropicMaterial(1e7, 0.3, 0.1), s);
  p.normal = [](const Vec3 &) { return Vec3{0, 0, 1}; };
  std::vector<int> tip;
  for (int j = 0; j <= m; ++j) {
    p.FixAll(mesh.Node(0, j), {UX, UY, UZ, RX, RY, RZ});
    tip.push_back(mesh.Node(6 * m, j));
  }
  std::vector<double> w = EdgeWeights(m);
  if (load < 3) {
    for (int j = 0; j <= m; ++j) p.F[6 * tip[j] + load] = w[j];
    const std::vector<double> u = Solve(p);
    Vec3                      d{0, 0, 0};
    d[load] = 1;
    return Conjugate(u, tip, w, d);
  }
  double I = 0; // sum w_j y_j^2: forces f_j = w_j y_j / I give a unit moment
  for (int j = 0; j <= m; ++j) I += w[j] * mesh.X[tip[j]][1] * mesh.X[tip[j]][1];
  for (int j = 0; j <= m; ++j) p.F[6 * tip[j] + UZ] = w[j] * mesh.X[tip[j]][1] / I;
  const std::vector<double> u = Solve(p);
  double                    work = 0;
  for (int j = 0; j <= m; ++j) work += p.F[6 * tip[j] + UZ] * u[6 * tip[j] + UZ];
  return work; // = the conjugate rotation of a unit moment
}

// Curved beam (MacNeal & Harder): quarter ring, inner radius 4.12, outer 4.32, t = 0.1, E = 1e7,
// nu = 0.25, 6 x 1 elements, clamped at theta = 0, unit tip load at theta = 90 deg: in-plane along the
// radius there (y), out-of-plane along z.
double CurvedBeam(int load, int refine, const Discretization &s)
{
  const int m    = refine;
  Mesh      mesh = Grid(6 * m, m, [](double a, double b) {
    const double th = kPi / 2 * a, r = 4.12 + 0.2 * b;
    return Vec3{r * std::cos(th), r * std::sin(th), 0};
  }, s.kind);
  Problem p(mesh, IsotropicMaterial(1e7, 0.25, 0.1), s);
  p.normal = [](const Vec3 &) { return Vec3{0, 0, 1}; };
  std::vector<int> tip;
  for (int j = 0; j <= m; ++j) {
    p.FixAll(mesh.Node(0, j), {UX, UY, UZ, RX, RY, RZ});
    tip.push_back(mesh.Node(6 * m, j));
  }
  const std::vector<double> w = EdgeWeights(m);
  const Vec3                d = load == 0 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  for (int j = 0; j <= m; ++j)
    for (int k = 0; k < 3; ++k) p.F[6 * tip[j] + k] = w[j] * d[k];
  return Conjugate(Solve(p), tip, w, d);
}

// Twisted beam (MacNeal & Harder): L = 12, width 1.1, t = 0.32, E = 29e6, nu = 0.22, twisted by 90 deg
// along its length (width along y at the root, along z at the tip), 12 x 2 elements, clamped root;
// unit tip load in-plane (along the tip's width, z) or out-of-plane (along the tip's normal, -y).
double TwistedBeam(int load, int refine, const Discretization &s)
{
  const double L = 12, b = 1.1;
  Mesh         mesh = Grid(12 * refine, 2 * refine, [&](double a, double c) {
    const double phi = kPi / 2 * a, y = b * (c - 0.5);
    return Vec3{L * a, y * std::cos(phi), y * std::sin(phi)};
  }, s.kind);
  Problem p(mesh, IsotropicMaterial(29e6, 0.22, 0.32), s);
  p.normal = [&](const Vec3 &X) { // the helicoid's normal: X_x x X_w = (-w phi', -sin phi, cos phi)
    const double phi = kPi / 2 * X[0] / L, w = X[1] * std::cos(phi) + X[2] * std::sin(phi);
    return Unit(Vec3{-w * kPi / (2 * L), -std::sin(phi), std::cos(phi)});
  };
  std::vector<int> tip;
  const int        m = 2 * refine;
  for (int j = 0; j <= m; ++j) {
    p.FixAll(mesh.Node(0, j), {UX, UY, UZ, RX, RY, RZ});
    tip.push_back(mesh.Node(12 * refine, j));
  }
  const std::vector<double> w = EdgeWeights(m);
  const Vec3                d = load == 0 ? Vec3{0, 0, 1} : Vec3{0, -1, 0};
  for (int j = 0; j <= m; ++j)
    for (int k = 0; k < 3; ++k) p.F[6 * tip[j] + k] = w[j] * d[k];
  return Conjugate(Solve(p), tip, w, d);
}

// Morley's skew plate (NAFEMS LE6): rhombus of side L = 1 with a 30 deg acute angle, t = 0.01,
// E = 210e9, nu = 0.3, pressure q = 700 along +z, hard simple support on all edges (w = 0, no
// rotation about the edge's in-plane normal: the edge stays straight), bending only (the in-plane
// dofs and the drilling rotation are fixed). The principal moments at the centre node are the
// average of the adjacent elements' M = D kappa there.
double SkewPlateMoment(int n, const Discretization &s, double angle_deg, double grading)
{
  if (n % 2) throw std::invalid_argument("SkewPlateMoment: n must be even (the centre is a node)");
  const double L = 1, t = 0.01, E = 210e9, nu = 0.3, q = 700, c = std::cos(angle_deg * kPi / 180), sn = std::sin(angle_deg * kPi / 180);
  // The moments are singular at the obtuse corners (r^-0.8, Williams 1952); a uniform mesh leaves a
  // pollution error of order h^0.45 at the centre. Nodes are graded towards the edges, h ~ s^3.
  auto grade = [&](double a) { return a < 0.5 ? 0.5 * std::pow(2 * a, grading) : 1 - 0.5 * std::pow(2 * (1 - a), grading); };
  Mesh    mesh = Grid(n, n, [&](double a, double b) { a = grade(a), b = grade(b); return Vec3{L * (a + b * c), L * b * sn, 0}; }, s.kind);
  Problem p(mesh, IsotropicMaterial(E, nu, t), s);
  p.normal = [](const Vec3 &) { return Vec3{0, 0, 1}; };
  p.SurfaceLoad({0, 0, q});
  const double k = 1e6 * E * t * t * t; // skew constraint penalty, far above the rotational stiffness
  for (size_t i = 0; i < mesh.X.size(); ++i) p.FixAll(int(i), {UX, UY, RZ});
  for (int j = 0; j <= n; ++j) {
    for (int e : {mesh.Node(j, 0), mesh.Node(j, n)}) p.FixAll(e, {UZ, RY}); // edges along x
    for (int e : {mesh.Node(0, j), mesh.Node(n, j)}) {                    // edges along (cos 30, sin 30)
      p.Fix(e, UZ);
      p.penalties.push_back({e, {0, 0, 0, -sn, c, 0}, k});
    }
  }
  const std::vector<double> u = Solve(p);
  const int                 centre = mesh.Node(n / 2, n / 2);
  const ShellMaterial       m = IsotropicMaterial(E, nu, t);
  double                    M[3] = {}, count = 0;
  for (size_t e = 0; e < mesh.elems.size(); ++e) {
    const auto &el = mesh.elems[e];
    for (size_t a = 0; a < el.size(); ++a) {
      if (el[a] != centre) continue;
      const double quad[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, tri[3][2] = {{0, 0}, {1, 0}, {0, 1}};
      const double *nat = el.size() == 4 ? quad[a] : tri[a];
      const GeneralisedStrains g = Strains(p, u, e, nat[0], nat[1]);
      // Curvature in the element's frame at the point; e1 is along a mesh direction, so rotate to x, y.
      Vec3 e1;
      if (el.size() == 4) e1 = MakeElementFrame(Nodes{mesh.X[el[0]], mesh.X[el[1]], mesh.X[el[2]], mesh.X[el[3]]}).e1;
      else e1 = MakeElementFrame(TriNodes{mesh.X[el[0]], mesh.X[el[1]], mesh.X[el[2]]}).e1;
      const double ca = e1[0], sa = e1[1]; // e1 = (cos a, sin a): kappa_xy-frame = R^T kappa R
      const double k11 = g.curvature[0], k22 = g.curvature[1], k12 = g.curvature[2] / 2;
      const double kx = ca * ca * k11 + sa * sa * k22 - 2 * ca * sa * k12, ky = sa * sa * k11 + ca * ca * k22 + 2 * ca * sa * k12;
      const double kxy = 2 * (ca * sa * (k11 - k22) + (ca * ca - sa * sa) * k12);
      const double kap[3] = {kx, ky, kxy};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) M[i] += m.D[3 * i + j] * kap[j];
      count += 1;
    }
  }
  for (double &v : M) v /= count;
  const double mean = (M[0] + M[1]) / 2, rad = std::hypot((M[0] - M[1]) / 2, M[2]);
  return (mean + rad) / (q * L * L);
}

} // namespace shelltest
