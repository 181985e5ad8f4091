// Internal to lib/shell: the shell kinematics the quadrilateral and the triangle share (not public API).
//
// Both elements are continuum-based (degenerated-solid) shells in resultant form: the mid-surface is
// interpolated from the nodes, X(z) = X + z V with V = sum N_i V_i the interpolated director, and the
// displacement through the thickness is U(z) = u + z D with D = sum N_i (theta_i x V_i), the change
// of the nodal directors (Dvorkin & Bathe 1984; Lee & Bathe 2004). The linear strain expanded in z
// gives, in a local orthonormal tangent frame (e1, e2) at the point,
//   membrane     eps_kl = sym(e_k . u_,l)
//   curvature    kap_kl = sym(e_k . D_,l + V_,k . u_,l)
//   shear (cov.) gamma_a = a_a . D + V . u_,a   (a_a the covariant tangents; tied by the MITC rules)
// Rigid motions (u = c + theta x X, theta_i = theta) give zero strain exactly for any directors, and
// a rotation about a node's own director changes no director, so it cannot bend or shear the shell.
// The drilling rotation enters only through the membrane (Hughes-Brezzi term or the triangle's
// drilling membrane), measured about the mid-surface normal n: theta . n - omega.
#pragma once

#include "shell/shell.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace boltnet::shell::detail {

inline Vec3   Sub(const Vec3 &a, const Vec3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3   Add(const Vec3 &a, const Vec3 &b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3   Scale(double s, const Vec3 &a) { return {s * a[0], s * a[1], s * a[2]}; }
inline double Dot(const Vec3 &a, const Vec3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3   Cross(const Vec3 &a, const Vec3 &b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double Norm(const Vec3 &a) { return std::sqrt(Dot(a, a)); }

/* The section in an element frame: the material reference direction projected on the plane (e1, e2);
   a direction along the normal keeps e1. */
inline ShellMaterial SectionInFrame(const ShellMaterial &mat, const Vec3 &e1, const Vec3 &e2)
{
  const Vec3  &r = mat.direction;
  const double c = Dot(r, e1), s = Dot(r, e2);
  if (std::hypot(c, s) <= 1e-8 * Norm(r)) return mat;
  return RotateMaterial(mat, std::atan2(s, c));
}

/* The rotation-invariant membrane shear stiffness (A11 + A22 - 2 A12 + 4 A66) / 8 (= G t isotropic). */
inline double MembraneShear(const ShellMaterial &m) { return (m.A[0] + m.A[4] - 2 * m.A[1] + 4 * m.A[8]) / 8; }

/* A point of the mid-surface: covariant tangents a[0], a[1], unit normal n, local orthonormal frame
   e[0] (the element's reference axis projected on the tangent plane), e[1] = n x e[0], the 2x2
   Jacobian J[a][k] = a_a . e_k, its inverse and determinant (the area factor). */
struct SurfacePoint {
  Vec3   a[2], n, e[2];
  double J[2][2], Ji[2][2], detJ;
};

/* e1ref, e3ref: the element's axes; a tangent plane whose normal turns against e3ref means an inverted
   or folded element (what names the element kind in the message). */
inline SurfacePoint MakeSurfacePoint(const Vec3 &a0, const Vec3 &a1, const Vec3 &e1ref, const Vec3 &e3ref, const char *what)
{
  SurfacePoint p;
  p.a[0] = a0;
  p.a[1] = a1;
  const Vec3   c  = Cross(a0, a1);
  const double cn = Norm(c);
  if (!(cn > 0) || !(Dot(c, e3ref) > 0))
    throw std::invalid_argument(std::string("Shell element: degenerate or inverted ") + what +
                                " (its surface normal vanishes or turns over at an integration point); number the nodes counter-clockwise");
  p.n = Scale(1 / cn, c);
  Vec3 t = Sub(e1ref, Scale(Dot(e1ref, p.n), p.n));
  p.e[0] = Scale(1 / Norm(t), t);
  p.e[1] = Cross(p.n, p.e[0]);
  for (int a = 0; a < 2; ++a)
    for (int k = 0; k < 2; ++k) p.J[a][k] = Dot(p.a[a], p.e[k]);
  p.detJ = p.J[0][0] * p.J[1][1] - p.J[0][1] * p.J[1][0];
  p.Ji[0][0] = p.J[1][1] / p.detJ;
  p.Ji[0][1] = -p.J[0][1] / p.detJ;
  p.Ji[1][0] = -p.J[1][0] / p.detJ;
  p.Ji[1][1] = p.J[0][0] / p.detJ;
  return p;
}

/* Cartesian derivatives (d/dx1, d/dx2) of a function with natural derivatives (d/dxi, d/deta). */
inline void Cartesian(const SurfacePoint &p, double dxi, double deta, double d[2])
{
  d[0] = p.Ji[0][0] * dxi + p.Ji[0][1] * deta;
  d[1] = p.Ji[1][0] * dxi + p.Ji[1][1] * deta;
}

/* Strain rows (columns: global dofs, row-major with stride ncol). Each adds one node's part.
   Membrane rows m[3] (eps11, eps22, 2 eps12) of a translation u_i with Cartesian derivatives dN. */
inline void AddMembrane(const SurfacePoint &p, const double dN[2], double *m, int ncol, int col_u)
{
  for (int k = 0; k < 3; ++k) {
    m[col_u + k] += dN[0] * p.e[0][k];
    m[ncol + col_u + k] += dN[1] * p.e[1][k];
    m[2 * ncol + col_u + k] += dN[1] * p.e[0][k] + dN[0] * p.e[1][k];
  }
}

/* Curvature rows b[3] of a rotation theta whose director change is theta x V (columns col_t, 3
   components), weighted by a function with Cartesian derivatives df: e_k . D_,l. */
inline void AddDirectorBending(const SurfacePoint &p, const double df[2], const Vec3 &V, double *b, int ncol, int col_t)
{
  const Vec3 v1 = Cross(V, p.e[0]), v2 = Cross(V, p.e[1]); // e_k . (theta x V) = theta . (V x e_k)
  for (int k = 0; k < 3; ++k) {
    b[col_t + k] += df[0] * v1[k];
    b[ncol + col_t + k] += df[1] * v2[k];
    b[2 * ncol + col_t + k] += df[1] * v1[k] + df[0] * v2[k];
  }
}

/* Curvature rows of a translation u_i (Cartesian derivatives dN) through the director gradient
   dV[k] = V_,k: V_,k . u_,l (zero on flat elements with one director). */
inline void AddDirectorCurvature(const double dN[2], const Vec3 dV[2], double *b, int ncol, int col_u)
{
  for (int k = 0; k < 3; ++k) {
    b[col_u + k] += dN[0] * dV[0][k];
    b[ncol + col_u + k] += dN[1] * dV[1][k];
    b[2 * ncol + col_u + k] += dN[1] * dV[0][k] + dN[0] * dV[1][k];
  }
}

/* Covariant transverse shear gamma_a = a_a . D + V . u_,a along the tangent a (one row): the
   rotation part f (theta x V_i), the translation part dNa (the natural derivative along a) times V. */
inline void AddShearRotation(const Vec3 &a, double f, const Vec3 &Vi, double *row, int col_t)
{
  const Vec3 v = Cross(Vi, a);
  for (int k = 0; k < 3; ++k) row[col_t + k] += f * v[k];
}
inline void AddShearTranslation(const Vec3 &V, double dNa, double *row, int col_u)
{
  for (int k = 0; k < 3; ++k) row[col_u + k] += dNa * V[k];
}

/* Drilling defect theta . n - omega, omega = (e2 . u_,1 - e1 . u_,2) / 2: one node's part. */
inline void AddDrill(const SurfacePoint &p, double N, const double dN[2], double *d, int col_u, int col_t)
{
  for (int k = 0; k < 3; ++k) {
    d[col_t + k] += N * p.n[k];
    d[col_u + k] += -0.5 * (dN[0] * p.e[1][k] - dN[1] * p.e[0][k]);
  }
}

/* Unit director from a user value: finite, non-zero, on the side of the element normal. */
inline Vec3 CheckedDirector(const Vec3 &V, const Vec3 &e3, int node, const char *what)
{
  const double n = Norm(V);
  if (!(n > 0) || !std::isfinite(n) || !(Dot(V, e3) > 0.1 * n))
    throw std::invalid_argument(std::string("Shell element: director of ") + what + " node " + std::to_string(node) +
                                " must be a non-zero vector within 84 degrees of the element normal (same side)");
  return Scale(1 / n, V);
}

} // namespace boltnet::shell::detail
