// Section results at an element's centroid (resultants.hpp): ElementStrains there, the section law
// in the element frame, and the stresses of a homogeneous section.
#include "shell/resultants.hpp"
#include "shell/kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace boltnet::shell {

using namespace detail;

namespace {

std::array<double, 3> Mul3(const Mat3 &A, const std::array<double, 3> &x)
{
  return {A[0] * x[0] + A[1] * x[1] + A[2] * x[2], A[3] * x[0] + A[4] * x[1] + A[5] * x[2], A[6] * x[0] + A[7] * x[1] + A[8] * x[2]};
}

double MaxAbs(const Mat3 &A)
{
  double m = 0;
  for (double v : A) m = std::max(m, std::fabs(v));
  return m;
}

// Resultants, surface strains and stresses from the generalised strains in the frame (e1, e2, e3).
SectionResults FromStrains(const GeneralisedStrains &g, const Vec3 &e1, const Vec3 &e2, const Vec3 &e3, const ShellMaterial &mat)
{
  const ShellMaterial m = SectionInFrame(mat, e1, e2); // the section law in the element frame
  SectionResults      r{};
  r.e1 = e1, r.e2 = e2, r.e3 = e3;
  const auto An = Mul3(m.A, g.membrane), Bk = Mul3(m.B, g.curvature), Be = Mul3(m.B, g.membrane), Dk = Mul3(m.D, g.curvature);
  for (int i = 0; i < 3; ++i) {
    r.N[i]             = An[i] + Bk[i];
    r.M[i]             = Be[i] + Dk[i];
    r.strain_top[i]    = g.membrane[i] + 0.5 * m.thickness * g.curvature[i];
    r.strain_bottom[i] = g.membrane[i] - 0.5 * m.thickness * g.curvature[i];
  }
  r.Q           = {m.H[0] * g.shear[0] + m.H[1] * g.shear[1], m.H[2] * g.shear[0] + m.H[3] * g.shear[1]};
  r.homogeneous = HomogeneousSection(mat);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  r.stress_top = r.stress_bottom = {nan, nan, nan};
  if (r.homogeneous) {
    const auto st = Mul3(m.A, r.strain_top), sb = Mul3(m.A, r.strain_bottom);
    for (int i = 0; i < 3; ++i) {
      r.stress_top[i]    = st[i] / m.thickness;
      r.stress_bottom[i] = sb[i] / m.thickness;
    }
  }
  return r;
}

// Tensor components (xx, yy, xy) in axes turned by phi; engineering shear when `engineering`.
std::array<double, 3> Turn(const std::array<double, 3> &v, double c, double s, bool engineering)
{
  const double xy = engineering ? 0.5 * v[2] : v[2];
  const double xx = c * c * v[0] + s * s * v[1] + 2 * c * s * xy;
  const double yy = s * s * v[0] + c * c * v[1] - 2 * c * s * xy;
  const double nxy = -c * s * v[0] + c * s * v[1] + (c * c - s * s) * xy;
  return {xx, yy, engineering ? 2 * nxy : nxy};
}

} // namespace

bool HomogeneousSection(const ShellMaterial &mat)
{
  const double t = mat.thickness, a = MaxAbs(mat.A);
  if (!(t > 0) || !(a > 0)) return false;
  Mat3 d;
  for (int i = 0; i < 9; ++i) d[i] = mat.D[i] - mat.A[i] * t * t / 12;
  return MaxAbs(mat.B) <= 1e-9 * a * t && MaxAbs(d) <= 1e-9 * a * t * t;
}

SectionResults ElementResults(const Nodes &X, const Directors *V, const ShellMaterial &mat, const ElementOptions &options, const ElementVector &u,
                              const CondensedModes *kept)
{
  const ElementFrame f = MakeElementFrame(X);
  return FromStrains(ElementStrains(X, V, mat, options, u, 0.0, 0.0, kept), f.e1, f.e2, f.e3, mat);
}

SectionResults ElementResults(const TriNodes &X, const TriDirectors *V, const ShellMaterial &mat, const ElementOptions &options, const TriVector &u,
                              const CondensedModes *kept)
{
  const TriFrame f = MakeElementFrame(X);
  return FromStrains(ElementStrains(X, V, mat, options, u, 1.0 / 3, 1.0 / 3, kept), f.e1, f.e2, f.e3, mat);
}

SectionResults Rotated(const SectionResults &r, double phi)
{
  const double   c = std::cos(phi), s = std::sin(phi);
  SectionResults o = r;
  o.e1             = Add(Scale(c, r.e1), Scale(s, r.e2));
  o.e2             = Add(Scale(-s, r.e1), Scale(c, r.e2));
  o.N              = Turn(r.N, c, s, false);
  o.M              = Turn(r.M, c, s, false);
  o.Q              = {c * r.Q[0] + s * r.Q[1], -s * r.Q[0] + c * r.Q[1]};
  o.strain_top     = Turn(r.strain_top, c, s, true);
  o.strain_bottom  = Turn(r.strain_bottom, c, s, true);
  if (r.homogeneous) {
    o.stress_top    = Turn(r.stress_top, c, s, false);
    o.stress_bottom = Turn(r.stress_bottom, c, s, false);
  }
  return o;
}

double MaterialAngle(const SectionResults &r, const ShellMaterial &mat)
{
  const double c = Dot(mat.direction, r.e1), s = Dot(mat.direction, r.e2);
  return std::hypot(c, s) <= 1e-8 * Norm(mat.direction) ? 0.0 : std::atan2(s, c);
}

double VonMises(const std::array<double, 3> &s)
{
  return std::sqrt(std::max(0.0, s[0] * s[0] - s[0] * s[1] + s[1] * s[1] + 3 * s[2] * s[2]));
}

std::array<double, 2> Principal(const std::array<double, 3> &s)
{
  const double c = 0.5 * (s[0] + s[1]), r = std::hypot(0.5 * (s[0] - s[1]), s[2]);
  return {c + r, c - r};
}

} // namespace boltnet::shell
