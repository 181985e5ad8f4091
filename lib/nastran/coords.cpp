// Coordinate systems: points and directions of rectangular, cylindrical and spherical systems in
// the basic system (Nastran Quick Reference Guide, CORD2R, CORD2C, CORD2S).
#include "nastran/deck.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace boltnet::nastran {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

Vec3 Combine(const Axes &a, const Vec3 &q) // q1 e1 + q2 e2 + q3 e3
{
  Vec3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[j] += q[i] * a[i][j];
  return r;
}

} // namespace

Vec3 ToBasic(const CoordSystem &cs, const Vec3 &x)
{
  Vec3 q = x; // Cartesian coordinates in the system's axes
  if (cs.kind == CoordKind::Cylindrical) {
    q = {x[0] * std::cos(x[1] * kDeg), x[0] * std::sin(x[1] * kDeg), x[2]};
  } else if (cs.kind == CoordKind::Spherical) {
    const double st = std::sin(x[1] * kDeg), ct = std::cos(x[1] * kDeg);
    q = {x[0] * st * std::cos(x[2] * kDeg), x[0] * st * std::sin(x[2] * kDeg), x[0] * ct};
  }
  Vec3 r = Combine(cs.axes, q);
  for (int j = 0; j < 3; ++j) r[j] += cs.origin[j];
  return r;
}

Axes DirectionsAt(const CoordSystem &cs, const Vec3 &p)
{
  if (cs.kind == CoordKind::Rectangular) return cs.axes;
  Vec3 d{}, q{};
  for (int j = 0; j < 3; ++j) d[j] = p[j] - cs.origin[j];
  for (int i = 0; i < 3; ++i) q[i] = cs.axes[i][0] * d[0] + cs.axes[i][1] * d[1] + cs.axes[i][2] * d[2];
  const double rho = std::hypot(q[0], q[1]), r = std::hypot(rho, q[2]);
  // On the axis the angular directions are undefined (relative to the point's distance, or to 1 at
  // the origin).
  if (rho <= 1e-12 * std::max(r, 1.0))
    throw std::domain_error("the point lies on the axis of " + std::string(cs.kind == CoordKind::Cylindrical ? "cylindrical" : "spherical") +
                            " system " + std::to_string(cs.id) + ", where its directions are undefined");
  const double c = q[0] / rho, s = q[1] / rho;
  Axes local;
  if (cs.kind == CoordKind::Cylindrical) {
    local = {{{c, s, 0}, {-s, c, 0}, {0, 0, 1}}};
  } else {
    const double st = rho / r, ct = q[2] / r;
    local = {{{st * c, st * s, ct}, {ct * c, ct * s, -st}, {-s, c, 0}}};
  }
  Axes out;
  for (int i = 0; i < 3; ++i) out[i] = Combine(cs.axes, local[i]);
  return out;
}

} // namespace boltnet::nastran
