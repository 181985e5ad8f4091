// Shell sections: isotropic and laminated (classical lamination theory), and their rotation.
#include "shell/shell.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace boltnet::shell {

namespace {

// Engineering-strain rotation: strains in axes at angle phi from the current x axis are T eps.
Mat3 StrainRotation(double phi)
{
  const double c = std::cos(phi), s = std::sin(phi);
  return {c * c, s * s, c * s, s * s, c * c, -c * s, -2 * c * s, 2 * c * s, c * c - s * s};
}

// T^T C T for 3x3 matrices.
Mat3 Congruent3(const Mat3 &C, const Mat3 &T)
{
  Mat3 CT{}, R{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) CT[3 * i + j] += C[3 * i + k] * T[3 * k + j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) R[3 * i + j] += T[3 * k + i] * CT[3 * k + j];
  return R;
}

// S^T H S for the transverse shear pair, S = [[c, s], [-s, c]].
Mat2 Congruent2(const Mat2 &H, double phi)
{
  const double c = std::cos(phi), s = std::sin(phi);
  const Mat2 S{c, s, -s, c};
  Mat2 HS{}, R{};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) HS[2 * i + j] += H[2 * i + k] * S[2 * k + j];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) R[2 * i + j] += S[2 * k + i] * HS[2 * k + j];
  return R;
}

[[noreturn]] void Reject(const std::string &what) { throw std::invalid_argument(what); }

std::string Num(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

} // namespace

ShellMaterial IsotropicMaterial(double E, double nu, double t)
{
  if (!(E > 0) || !std::isfinite(E)) Reject("Isotropic shell: Young's modulus E = " + Num(E) + " must be a finite number > 0");
  if (!(nu > -1 && nu <= 0.5)) Reject("Isotropic shell: Poisson's ratio nu = " + Num(nu) + " must lie in (-1, 0.5]");
  if (!(t > 0) || !std::isfinite(t)) Reject("Isotropic shell: thickness t = " + Num(t) + " must be a finite number > 0");
  ShellMaterial m;
  m.thickness = t;
  const double q = E / (1 - nu * nu), G = E / (2 * (1 + nu));
  const Mat3 Q{q, nu * q, 0, nu * q, q, 0, 0, 0, G};
  for (int k = 0; k < 9; ++k) {
    m.A[k] = Q[k] * t;
    m.D[k] = Q[k] * t * t * t / 12;
  }
  m.H = {5.0 / 6.0 * G * t, 0, 0, 5.0 / 6.0 * G * t};
  return m;
}

ShellMaterial LaminateMaterial(const std::vector<Ply> &plies, double shear_correction)
{
  if (plies.empty()) Reject("Laminate: no plies (a laminate needs at least one ply)");
  if (!(shear_correction > 0 && shear_correction <= 1))
    Reject("Laminate: shear correction factor = " + Num(shear_correction) + " must lie in (0, 1]");
  double h = 0;
  for (size_t k = 0; k < plies.size(); ++k) {
    const Ply &p = plies[k];
    const std::string name = "Laminate ply " + std::to_string(k) + ": ";
    if (!(p.thickness > 0) || !std::isfinite(p.thickness)) Reject(name + "thickness = " + Num(p.thickness) + " must be a finite number > 0");
    if (!std::isfinite(p.angle_deg)) Reject(name + "angle = " + Num(p.angle_deg) + " must be finite");
    const double moduli[] = {p.E1, p.E2, p.G12, p.G13, p.G23};
    const char *names[] = {"E1", "E2", "G12", "G13", "G23"};
    for (int i = 0; i < 5; ++i)
      if (!(moduli[i] > 0) || !std::isfinite(moduli[i])) Reject(name + names[i] + " = " + Num(moduli[i]) + " must be a finite number > 0");
    if (!(p.nu12 * p.nu12 * p.E2 / p.E1 < 1) || !std::isfinite(p.nu12))
      Reject(name + "nu12 = " + Num(p.nu12) + " makes the ply stiffness indefinite (nu12^2 E2/E1 must be < 1)");
    h += p.thickness;
  }
  ShellMaterial m;
  m.thickness = h;
  double z0 = -h / 2;
  for (const Ply &p : plies) {
    const double z1 = z0 + p.thickness;
    const double nu21 = p.nu12 * p.E2 / p.E1, den = 1 - p.nu12 * nu21;
    const Mat3 Q{p.E1 / den, p.nu12 * p.E2 / den, 0, p.nu12 * p.E2 / den, p.E2 / den, 0, 0, 0, p.G12};
    const double th = p.angle_deg * M_PI / 180;
    const Mat3 Qb = Congruent3(Q, StrainRotation(th)); // ply axis 1 at angle th from the reference
    for (int k = 0; k < 9; ++k) {
      m.A[k] += Qb[k] * (z1 - z0);
      m.B[k] += Qb[k] * (z1 * z1 - z0 * z0) / 2;
      m.D[k] += Qb[k] * (z1 * z1 * z1 - z0 * z0 * z0) / 3;
    }
    const Mat2 Hs = Congruent2(Mat2{p.G13, 0, 0, p.G23}, th);
    for (int k = 0; k < 4; ++k) m.H[k] += shear_correction * Hs[k] * p.thickness;
    z0 = z1;
  }
  return m;
}

ShellMaterial RotateMaterial(const ShellMaterial &m, double phi)
{
  ShellMaterial r = m;
  const Mat3 T = StrainRotation(phi);
  r.A = Congruent3(m.A, T);
  r.B = Congruent3(m.B, T);
  r.D = Congruent3(m.D, T);
  r.H = Congruent2(m.H, phi);
  return r;
}

} // namespace boltnet::shell
