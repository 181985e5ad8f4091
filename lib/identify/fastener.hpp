// Macroelement parameters from a fastener's geometry: clearance, pretension,
// friction threshold, axial stiffness, and the bearing stiffness from the fastener flexibility
// formulas of aircraft structures. Formulas, sources and assumptions: docs/identify.md.
//
// Pure C++: no PETSc, no global state. Units: any consistent set (N, mm, MPa, N mm in the shipped
// examples; lb, in, psi, lb in in the Huth worked values). Compliances C are length/force (1/k).
#pragma once

#include "joint/law.hpp"

#include <string>

namespace boltnet {
namespace identify {

// Which flexibility formula gives the bearing stiffness kc = 1/C.
enum class Formula : int { Huth = 0, Swift, TateRosenfeld, Grumman, Boeing, Nelson };
// Huth's joint type (sets his exponent a and factor b).
enum class HuthType : int { BoltedMetal = 0, RivetedMetal, BoltedComposite };

struct FastenerGeometry {
  double d    = 0;   // fastener (shank) diameter
  double hole = 0;   // hole diameter (>= d)
  double t1   = 0;   // plate 1 thickness (double shear: the middle plate)
  double t2   = 0;   // plate 2 thickness (double shear: each of the two outer plates)
  double E1   = 0;   // plate 1 modulus (laminate: its effective bearing modulus)
  double E2   = 0;   // plate 2 modulus (laminate: its effective bearing modulus)
  double Ef   = 0;   // fastener modulus
  double nu_f = 0.3; // fastener Poisson ratio (Tate & Rosenfeld, Nelson: shear term)
  int    n    = 1;   // shear planes: 1 single shear (single lap), 2 double shear
  double torque  = 0;   // installation torque T (force x length); used when preload <= 0
  double preload = 0;   // bolt preload Pc, if given (> 0 overrides the torque)
  double K    = 0.2; // nut factor: Pc = T / (K d)
  double mu   = 0;   // friction coefficient, in [0, 2]
  double nf   = 0;   // friction interfaces; 0 means "as many as shear planes"
  double offset[2] = {0, 0}; // initial bolt position in the hole (t1, t2), |offset| <= gap
  double beta = 0.15; // Nelson et al.: bearing factor (1 + 3 beta), 0.15 for torqued protruding-head bolts
};

// Compliance C (1/k) of each formula, written exactly as cited in docs/identify.md.
// Huth (ASTM STP 927, 1986): any n; the others are single-shear formulas (n = 1).
double complianceHuth(const FastenerGeometry &g, HuthType type);
double complianceSwift(const FastenerGeometry &g);
double complianceTateRosenfeld(const FastenerGeometry &g);
double complianceGrumman(const FastenerGeometry &g);
double complianceBoeing(const FastenerGeometry &g);
double complianceNelson(const FastenerGeometry &g);
// Dispatch; the geometry must be valid for the formula (see validateGeometry).
double compliance(const FastenerGeometry &g, Formula f, HuthType type);

// Huth's exponent a and factor b for a joint type.
void huthConstants(HuthType type, double *a, double *b);

// Clearance j = (hole - d) / 2: the radius of the circle the bolt centre can travel in before it
// bears on the hole, i.e. the in-plane slip available before bearing.
double clearance(const FastenerGeometry &g);
// Bolt clamp force: the preload if given, else T / (K d).
double pretension(const FastenerGeometry &g);
// Friction interfaces actually used: nf if > 0, else n.
double frictionInterfaces(const FastenerGeometry &g);
// Axial stiffness of the bolt over its grip: Ef (pi d^2 / 4) / grip, grip = t1 + n t2.
double axialStiffness(const FastenerGeometry &g);

// Checks every input; returns "" when valid, else a message naming the offending input.
// (Hole smaller than the bolt, thickness or modulus <= 0, mu outside [0, 2], no preload nor
// torque, offset outside the clearance, a single-shear formula asked for double shear, ...)
std::string validateGeometry(const FastenerGeometry &g, Formula f);

// The frictional macroelement from the geometry: law friction, kn, kc = 1/C, kt (stick) = kc unless
// kt > 0 is given, kg, kr as given (kr <= 0: 1e3 kn d^2, a rigid rotation), gap, mu, nf, pretension,
// offset.
Params macroelement(const FastenerGeometry &g, Formula f, HuthType type, double kt, double kg, double kr);

const char *formulaName(Formula f);
bool        parseFormula(const std::string &s, Formula *f);
const char *huthTypeName(HuthType t);
bool        parseHuthType(const std::string &s, HuthType *t);

} // namespace identify
} // namespace boltnet
