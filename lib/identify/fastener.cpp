// Fastener flexibility formulas and the macroelement from a fastener's geometry: see fastener.hpp
// and docs/identify.md (sources, variants, assumptions).
#include "identify/fastener.hpp"

#include <cmath>
#include <sstream>

namespace boltnet {
namespace identify {
namespace {
constexpr double pi = 3.14159265358979323846;
}

void huthConstants(HuthType type, double *a, double *b)
{
  switch (type) {
  case HuthType::BoltedMetal: *a = 2.0 / 3.0; *b = 3.0; return;
  case HuthType::RivetedMetal: *a = 2.0 / 5.0; *b = 2.2; return;
  case HuthType::BoltedComposite: *a = 2.0 / 3.0; *b = 4.2; return;
  }
  *a = 2.0 / 3.0;
  *b = 3.0;
}

// Huth (ASTM STP 927, 1986):
//   C = ((t1 + t2) / (2 d))^a (b / n) [1/(t1 E1) + 1/(n t2 E2) + 1/(2 t1 Ef) + 1/(2 n t2 Ef)]
double complianceHuth(const FastenerGeometry &g, HuthType type)
{
  double a, b;
  huthConstants(type, &a, &b);
  const double n = g.n;
  return std::pow((g.t1 + g.t2) / (2 * g.d), a) * (b / n) *
         (1 / (g.t1 * g.E1) + 1 / (n * g.t2 * g.E2) + 1 / (2 * g.t1 * g.Ef) + 1 / (2 * n * g.t2 * g.Ef));
}

// Swift (Douglas; ASTM STP 486, 1971): C = 5 / (d Ef) + 0.8 (1/(t1 E1) + 1/(t2 E2)).
double complianceSwift(const FastenerGeometry &g)
{
  return 5 / (g.d * g.Ef) + 0.8 * (1 / (g.t1 * g.E1) + 1 / (g.t2 * g.E2));
}

// Tate & Rosenfeld (NACA TN 1051, 1946), single shear:
//   C = 1/(Ef t1) + 1/(Ef t2) + 1/(E1 t1) + 1/(E2 t2) + 32 (1 + nu_f) (t1 + t2) / (9 Ef pi d^2)
//       + 8 (t1^3 + 5 t1^2 t2 + 5 t1 t2^2 + t2^3) / (5 Ef pi d^4)
double complianceTateRosenfeld(const FastenerGeometry &g)
{
  const double t1 = g.t1, t2 = g.t2, d = g.d, Ef = g.Ef;
  const double bearing = 1 / (Ef * t1) + 1 / (Ef * t2) + 1 / (g.E1 * t1) + 1 / (g.E2 * t2);
  const double shear   = 32 * (1 + g.nu_f) * (t1 + t2) / (9 * Ef * pi * d * d);
  const double bending = 8 * (t1 * t1 * t1 + 5 * t1 * t1 * t2 + 5 * t1 * t2 * t2 + t2 * t2 * t2) / (5 * Ef * pi * d * d * d * d);
  return bearing + shear + bending;
}

// Grumman (as given by Huth, ASTM STP 927, after an unpublished Grumman report), single shear, the
// dimensionally consistent d^3 form: C = (t1 + t2)^2 / (Ef d^3) + 3.7 (1/(t1 E1) + 1/(t2 E2)).
double complianceGrumman(const FastenerGeometry &g)
{
  const double s = g.t1 + g.t2;
  return s * s / (g.Ef * g.d * g.d * g.d) + 3.7 * (1 / (g.t1 * g.E1) + 1 / (g.t2 * g.E2));
}

// Boeing (D6-29942, 1969, as given by Huth, ASTM STP 927), single shear:
//   C = 2^((t1/d)^0.85) / t1 (1/E1 + 3/(8 Ef)) + 2^((t2/d)^0.85) / t2 (1/E2 + 3/(8 Ef))
double complianceBoeing(const FastenerGeometry &g)
{
  const double c1 = std::pow(2.0, std::pow(g.t1 / g.d, 0.85)) / g.t1 * (1 / g.E1 + 3 / (8 * g.Ef));
  const double c2 = std::pow(2.0, std::pow(g.t2 / g.d, 0.85)) / g.t2 * (1 / g.E2 + 3 / (8 * g.Ef));
  return c1 + c2;
}

// Nelson, Bunin & Hart-Smith (NASA CR-3710, 1983), composite single shear, in the form reproduced
// by the secondary literature (docs/identify.md): shear of the shank (Timoshenko factor 4/3 over
// half the stack), bearing of the fastener, and bearing of the plates multiplied by (1 + 3 beta):
//   C = 2 (t1 + t2) / (3 Gf Af) + 2 (t1 + t2) / (t1 t2 Ef) + (1 + 3 beta) (1/(t1 E1) + 1/(t2 E2)),
//   Gf = Ef / (2 (1 + nu_f)), Af = pi d^2 / 4.
double complianceNelson(const FastenerGeometry &g)
{
  const double Gf = g.Ef / (2 * (1 + g.nu_f));
  const double Af = pi * g.d * g.d / 4;
  return 2 * (g.t1 + g.t2) / (3 * Gf * Af) + 2 * (g.t1 + g.t2) / (g.t1 * g.t2 * g.Ef) +
         (1 + 3 * g.beta) * (1 / (g.t1 * g.E1) + 1 / (g.t2 * g.E2));
}

double compliance(const FastenerGeometry &g, Formula f, HuthType type)
{
  switch (f) {
  case Formula::Huth: return complianceHuth(g, type);
  case Formula::Swift: return complianceSwift(g);
  case Formula::TateRosenfeld: return complianceTateRosenfeld(g);
  case Formula::Grumman: return complianceGrumman(g);
  case Formula::Boeing: return complianceBoeing(g);
  case Formula::Nelson: return complianceNelson(g);
  }
  return NAN;
}

double clearance(const FastenerGeometry &g) { return (g.hole - g.d) / 2; }

double pretension(const FastenerGeometry &g) { return g.preload > 0 ? g.preload : g.torque / (g.K * g.d); }

double frictionInterfaces(const FastenerGeometry &g) { return g.nf > 0 ? g.nf : g.n; }

double axialStiffness(const FastenerGeometry &g) { return g.Ef * (pi * g.d * g.d / 4) / (g.t1 + g.n * g.t2); }

std::string validateGeometry(const FastenerGeometry &g, Formula f)
{
  std::ostringstream m;
  auto positive = [&](const char *name, const char *what, double v) {
    if (!(v > 0) || !std::isfinite(v)) m << name << " (" << what << ") = " << v << " must be a finite number > 0; ";
  };
  positive("d", "fastener diameter", g.d);
  positive("hole", "hole diameter", g.hole);
  positive("t1", "thickness of plate 1", g.t1);
  positive("t2", "thickness of plate 2", g.t2);
  positive("E1", "modulus of plate 1", g.E1);
  positive("E2", "modulus of plate 2", g.E2);
  positive("Ef", "fastener modulus", g.Ef);
  if (std::isfinite(g.hole) && std::isfinite(g.d) && g.hole < g.d)
    m << "the hole (diameter " << g.hole << ") is smaller than the bolt (diameter " << g.d << "): an interference fit has no clearance; ";
  if (!(g.mu >= 0 && g.mu <= 2)) m << "mu (friction coefficient) = " << g.mu << " must lie in [0, 2]; ";
  if (g.n != 1 && g.n != 2) m << "n (shear planes) = " << g.n << " must be 1 (single shear) or 2 (double shear); ";
  if (g.n == 2 && f != Formula::Huth)
    m << "the " << formulaName(f) << " formula is a single-shear formula: use -fastener_formula huth for double shear; ";
  if (!(g.nu_f > -1 && g.nu_f < 0.5)) m << "nu_f (fastener Poisson ratio) = " << g.nu_f << " must lie in (-1, 0.5); ";
  if (!(g.nf >= 0) || g.nf != std::floor(g.nf)) m << "nf (friction interfaces) = " << g.nf << " must be a whole number >= 1 (0: as many as shear planes); ";
  if (!(g.preload >= 0) || !std::isfinite(g.preload)) m << "preload = " << g.preload << " must be a finite number >= 0; ";
  if (!(g.torque >= 0) || !std::isfinite(g.torque)) m << "torque = " << g.torque << " must be a finite number >= 0; ";
  if (g.preload == 0 && g.torque > 0 && !(g.K > 0)) m << "K (nut factor) = " << g.K << " must be > 0 to turn the torque into a preload; ";
  if (f == Formula::Nelson && !(g.beta >= 0)) m << "beta (Nelson bearing factor) = " << g.beta << " must be >= 0; ";
  if (!m.str().empty()) return m.str();
  if (std::hypot(g.offset[0], g.offset[1]) > clearance(g))
    m << "the offset (" << g.offset[0] << ", " << g.offset[1] << ") puts the bolt outside its clearance circle of radius (hole - d)/2 = " << clearance(g) << "; ";
  return m.str();
}

Params macroelement(const FastenerGeometry &g, Formula f, HuthType type, double kt, double kg, double kr)
{
  Params p;
  p.law        = Law::Friction;
  p.kn         = axialStiffness(g);
  p.kc         = 1 / compliance(g, f, type);
  p.kt         = kt > 0 ? kt : p.kc;
  p.kg         = kg;
  p.kr         = kr > 0 ? kr : 1e3 * p.kn * g.d * g.d;
  p.gap        = clearance(g);
  p.mu         = g.mu;
  p.nf         = frictionInterfaces(g);
  p.pretension = pretension(g);
  p.offset[0]  = g.offset[0];
  p.offset[1]  = g.offset[1];
  return p;
}

const char *formulaName(Formula f)
{
  switch (f) {
  case Formula::Huth: return "huth";
  case Formula::Swift: return "swift";
  case Formula::TateRosenfeld: return "tate-rosenfeld";
  case Formula::Grumman: return "grumman";
  case Formula::Boeing: return "boeing";
  case Formula::Nelson: return "nelson";
  }
  return "unknown";
}

bool parseFormula(const std::string &s, Formula *f)
{
  for (int i = 0; i <= static_cast<int>(Formula::Nelson); ++i)
    if (s == formulaName(static_cast<Formula>(i))) {
      *f = static_cast<Formula>(i);
      return true;
    }
  return false;
}

const char *huthTypeName(HuthType t)
{
  switch (t) {
  case HuthType::BoltedMetal: return "bolted-metal";
  case HuthType::RivetedMetal: return "riveted-metal";
  case HuthType::BoltedComposite: return "bolted-composite";
  }
  return "unknown";
}

bool parseHuthType(const std::string &s, HuthType *t)
{
  for (int i = 0; i <= static_cast<int>(HuthType::BoltedComposite); ++i)
    if (s == huthTypeName(static_cast<HuthType>(i))) {
      *t = static_cast<HuthType>(i);
      return true;
    }
  return false;
}

} // namespace identify
} // namespace boltnet
