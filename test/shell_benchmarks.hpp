// Shell benchmark problems and exact solutions (test code), each run on quadrilaterals, triangles or
// mixed meshes (Discretization). Each benchmark returns the quantity its reference quotes, with the reference's
// sign. n = elements per side of the symmetry model; refine = subdivisions of each element of a
// MacNeal-Harder mesh. References and their sources: docs/shell.md ("Verification").
#pragma once

#include "shell_harness.hpp"

#include <array>

namespace shelltest {

// ---- Reference values -----------------------------------------------------------------------------
// MacNeal & Harder 1985 (docs/shell.md cites each; some are replaced where the shell theory the
// element solves differs from the reference's theory, with the derivation in docs/shell.md).
constexpr double kScordelisLo = 0.3024, kPinchedCylinder = 1.8248e-5, kHemisphere = 0.094;
constexpr double kPlateSS = 0.00406, kPlateClamped = 0.00126;
constexpr double kCantilever[4] = {3.0e-5, 0.1081, 0.4321, 0.03208}; // extension, in-plane, out-of-plane, twist
constexpr double kCurvedBeam[2] = {0.08734, 0.5022};                 // in-plane, out-of-plane
constexpr double kTwistedBeam[2] = {5.424e-3, 1.754e-3};             // in-plane, out-of-plane (t = 0.32)
constexpr double kMorleyMoment = 0.0191; // Morley 1963: max principal moment / (q L^2), 30 deg skew plate (NAFEMS LE6)

/* Saint-Venant torsion of the straight cantilever's 0.2 x 0.1 section (Timoshenko & Goodier §109,
   J = k1 b t^3, k1 from the series for b/t = 2): tip rotation M L / (G J). */
double CantileverTwistSaintVenant();
/* The Reissner-Mindlin plate strip in uniform torsion (the model the element solves; derivation in
   docs/shell.md): G J = G b t^3 / 3 (1 - 2 tanh(lambda b / 2) / (lambda b)), lambda^2 = 12 k / t^2. */
double CantileverTwistMindlin();
/* Plane-stress elasticity of the curved cantilever bar (Timoshenko & Goodier §31): tip deflection
   under the in-plane radial load, exact for the annular sector 4.12 < r < 4.32. */
double CurvedBeamInPlaneElasticity();
/* Kirchhoff plates by series: the simply supported rectangle a x b (Navier), centre deflection under a
   uniform load q (w D / (q a^4)) or a central point load P (w D / (P a^2)). */
double NavierCentre(double aspect, bool point);
/* The infinite strip of width a, clamped or simply supported on both edges (Fourier transform along
   the strip, the plate equation across): deflection under a point load on the centre line,
   w D / (P a^2). The clamped strip under a uniform load: 1/384 exactly. */
double StripPoint(bool clamped);

// ---- Benchmarks -----------------------------------------------------------------------------------
struct RoofOptions {
  bool   full              = false; // the whole roof instead of the quarter
  bool   free_crown_normal = false; // quarter model without theta_z = 0 on the crown plane y = 0 (wrong)
  double distortion        = 0;     // interior nodes moved along the surface by up to this fraction of an element
};
double ScordelisLo(int n, const Discretization &s, RoofOptions r = {});
double PinchedCylinder(int n, const Discretization &s, bool full = false);
double Hemisphere(int n, const Discretization &s, bool full = false);
/* Square plate a/t = 100, quarter model: w_c D / (q a^4). */
double SquarePlate(int n, bool clamped, const Discretization &s = {});
/* MacNeal-Harder rectangular plate: a = 2, b = aspect a, t = 1e-4, quarter model n x n, simply
   supported (hard) or clamped, uniform load (w_c D / (q a^4)) or central point load (w_c D / (P a^2)). */
double RectPlate(int n, double aspect, bool clamped, bool point, const Discretization &s = {});

/* MacNeal-Harder straight cantilever, 6 x 1 elements (refine: 6 refine x refine): regular,
   trapezoidal or parallelogram elements; load 0 extension, 1 in-plane shear, 2 out-of-plane shear,
   3 twist (tip rotation under a unit moment). */
enum class CantileverShape { Regular, Trapezoidal, Parallelogram };
const char *ShapeName(CantileverShape c);
double      Cantilever(int load, CantileverShape shape, int refine, const Discretization &s = {});
/* MacNeal-Harder curved beam (6 x 1 elements times refine): load 0 in-plane, 1 out-of-plane. */
double CurvedBeam(int load, int refine, const Discretization &s = {});
/* MacNeal-Harder twisted beam (12 x 2 elements times refine): load 0 in-plane, 1 out-of-plane. */
double TwistedBeam(int load, int refine, const Discretization &s = {});
/* Morley's 30 deg skew plate (NAFEMS LE6: L = 1, t = 0.01, q = 700, hard simple support), n x n
   parallelograms: the largest principal bending moment at the centre / (q L^2). */
double SkewPlateMoment(int n, const Discretization &s = {}, double angle_deg = 30, double grading = 3);

// ---- Exact solutions (round-off) ------------------------------------------------------------------
Ply Carbon(double angle, double t = 0.125);
/* The MacNeal-Harder patch on a tilted plane, boundary dofs prescribed from the field of constant
   membrane strain eps, curvature kap and in-plane rotation omega; largest relative error of the
   interior dofs and of the strains at interior points of every element. */
double PatchTestError(const ShellMaterial &mat, const std::array<double, 3> &eps, const std::array<double, 3> &kap, double omega,
                      const Discretization &s = {});
/* Free laminated plate under edge resultants Nx, Nxy and moment Mx, one corner fixed: largest nodal
   error against the CLT field (ABD inverse), relative to the field's scale. */
double LaminatePlateError(const ShellMaterial &mat, double Nx, double Nxy, double Mx, const Discretization &s = {});

/* Prints the convergence tables (markdown; shell_tables.cpp). */
int PrintTables();

} // namespace shelltest
