// Small helpers shared by the element-level shell tests (no PETSc): eigenvalues of a symmetric
// element matrix, rigid-body motions of an element's nodes.
#pragma once

#include "shell/shell.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace shelltest {

using namespace boltnet::shell;

inline double MaxAbs(const double *K, size_t n)
{
  double m = 0;
  for (size_t i = 0; i < n; ++i) m = std::max(m, std::fabs(K[i]));
  return m;
}

/* Absolute eigenvalues of the symmetric n x n matrix K (cyclic Jacobi), ascending. */
inline std::vector<double> Eigenvalues(const double *K, int n)
{
  std::vector<double> a(K, K + n * n);
  const double        s = MaxAbs(K, size_t(n) * n);
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) off += a[n * p + q] * a[n * p + q];
    if (off < 1e-30 * s * s) break;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) {
        const double apq = a[n * p + q];
        if (apq == 0) continue;
        const double theta = (a[n * q + q] - a[n * p + p]) / (2 * apq);
        const double t     = (theta >= 0 ? 1 : -1) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), sn = t * c;
        for (int k = 0; k < n; ++k) {
          const double akp = a[n * k + p], akq = a[n * k + q];
          a[n * k + p] = c * akp - sn * akq;
          a[n * k + q] = sn * akp + c * akq;
        }
        for (int k = 0; k < n; ++k) {
          const double apk = a[n * p + k], aqk = a[n * q + k];
          a[n * p + k] = c * apk - sn * aqk;
          a[n * q + k] = sn * apk + c * aqk;
        }
      }
  }
  std::vector<double> ev;
  for (int i = 0; i < n; ++i) ev.push_back(std::fabs(a[(n + 1) * i]));
  std::sort(ev.begin(), ev.end());
  return ev;
}

/* Nodal dofs of rigid motion `mode` (0-2 translations, 3-5 rotations about `origin`) of nodes X. */
inline std::vector<double> RigidMotion(const std::vector<Vec3> &X, int mode, const Vec3 &origin)
{
  std::vector<double> u(6 * X.size(), 0.0);
  for (size_t n = 0; n < X.size(); ++n) {
    if (mode < 3) {
      u[6 * n + mode] = 1;
      continue;
    }
    Vec3 th{};
    th[mode - 3] = 1;
    const Vec3 r{X[n][0] - origin[0], X[n][1] - origin[1], X[n][2] - origin[2]};
    u[6 * n + 0] = th[1] * r[2] - th[2] * r[1];
    u[6 * n + 1] = th[2] * r[0] - th[0] * r[2];
    u[6 * n + 2] = th[0] * r[1] - th[1] * r[0];
    for (int k = 0; k < 3; ++k) u[6 * n + 3 + k] = th[k];
  }
  return u;
}

/* Largest |K u| over the entries, for the n x n matrix K. */
inline double MaxForce(const double *K, const std::vector<double> &u)
{
  const size_t n = u.size();
  double       m = 0;
  for (size_t i = 0; i < n; ++i) {
    double f = 0;
    for (size_t j = 0; j < n; ++j) f += K[n * i + j] * u[j];
    m = std::max(m, std::fabs(f));
  }
  return m;
}

/* A ply of a carbon/epoxy (T300/914 like) in MPa, mm. */
inline Ply CarbonPly(double angle, double t = 0.125) { return {angle, t, 140000, 10000, 0.3, 5000, 5000, 3500}; }

} // namespace shelltest
