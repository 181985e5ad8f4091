// Section results of a shell element from its nodal displacements: stress resultants, surface strains
// and, for a homogeneous section, surface stresses, at the element's centroid (docs/output.md,
// "Stresses and section forces"). Pure C++, no PETSc; the stiffness (shell.hpp) is not touched.
//
// Frames. The element frame is the one ElementStrains works in: at the centroid, e1 along the
// element's first natural axis (X_xi of the quadrilateral, X2 - X1 of the triangle), e3 the unit
// normal (counter-clockwise node order), e2 = e3 x e1. The material frame is the frame of the
// section law: x along the material reference direction (ShellMaterial::direction, global X by
// default) projected on the element's plane, z = e3; where that direction is along the normal the
// element frame is kept (as the stiffness does, kinematics.hpp SectionInFrame).
//
// Conventions (shell.hpp): N = A eps + B kappa, M = B eps + D kappa, Q = H gamma with the generalised
// strains at the centroid; the strain at height z along e3 is eps + z kappa, so "top" is z = +t/2 on
// the side e3 points to, "bottom" z = -t/2. Shear strains are engineering (gamma_xy = 2 eps_xy).
// Stresses are given only for a homogeneous section (B = 0 and D = A t^2 / 12: one material through
// the thickness, isotropic or not): sigma(z) = (A / t) (eps + z kappa). A laminate gets NaN stresses;
// its ply stresses need the ply stack, which ShellMaterial no longer holds (out of scope): it gets
// resultants and surface strains.
#pragma once

#include "shell/shell.hpp"

#include <array>

namespace boltnet::shell {

struct SectionResults {
  Vec3                  e1, e2, e3;                   // the frame of every component below
  std::array<double, 3> N, M;                         // Nxx Nyy Nxy (N/mm), Mxx Myy Mxy (N mm/mm)
  std::array<double, 2> Q;                            // Qxz Qyz (N/mm)
  std::array<double, 3> strain_top, strain_bottom;    // eps_xx eps_yy gamma_xy at z = +t/2, -t/2
  bool                  homogeneous;                  // stresses below are defined
  std::array<double, 3> stress_top, stress_bottom;    // sigma_xx sigma_yy tau_xy (MPa); NaN otherwise
};

// At the centroid (xi = eta = 0; r = s = 1/3), in the element frame, with the element options and
// directors the stiffness uses. Throws std::invalid_argument like ElementStrains.
// `kept`: the element's ElementCondensedModes (shell.hpp), when the caller keeps them between steps.
SectionResults ElementResults(const Nodes &X, const Directors *V, const ShellMaterial &mat, const ElementOptions &options, const ElementVector &u,
                              const CondensedModes *kept = nullptr);
SectionResults ElementResults(const TriNodes &X, const TriDirectors *V, const ShellMaterial &mat, const ElementOptions &options, const TriVector &u,
                              const CondensedModes *kept = nullptr);

// The same results in axes turned by phi (radians) about e3: x' = cos(phi) e1 + sin(phi) e2.
SectionResults Rotated(const SectionResults &r, double phi);
// The angle from r's e1 to the material frame's x axis (0 where the reference direction is along e3).
double MaterialAngle(const SectionResults &r, const ShellMaterial &mat);

// One material through the thickness: B = 0 and D = A t^2 / 12 to round-off.
bool HomogeneousSection(const ShellMaterial &mat);

// Plane stress (sigma_xx, sigma_yy, tau_xy): von Mises sqrt(sx^2 - sx sy + sy^2 + 3 txy^2) and the
// principal stresses (largest first).
double                VonMises(const std::array<double, 3> &s);
std::array<double, 2> Principal(const std::array<double, 3> &s);

} // namespace boltnet::shell
