// boltnet shell element kernels: pure C++, no PETSc, no global state.
//
// Two elements with 6 dof per node (u_x, u_y, u_z, theta_x, theta_y, theta_z in global axes), the same
// section (resultant law N, M, Q = [A B; B D], H) and the same director kinematics (kinematics.hpp):
//   - the four-node quadrilateral: MITC4 (Dvorkin & Bathe 1984) transverse shear, bilinear membrane
//     with Wilson-Taylor incompatible modes, a Hughes-Brezzi drilling term;
//   - the three-node triangle: MITC3+ (Lee, Lee & Bathe 2014) bending and transverse shear (MITC3,
//     Lee & Bathe 2004, as an option), the constant-strain membrane with the same Hughes-Brezzi
//     drilling term (straight edges like the quadrilateral's, so meshes may mix both), or, for
//     all-triangle meshes, Felippa's optimal ANDES membrane with drilling freedoms (OPT, Felippa 2003).
// Bending and transverse shear use the change of nodal directors theta_i x V_i: by default V_i is
// the element's own normal at node i (the flat facet's normal; on a warped quadrilateral, the normal
// of its bilinear surface at the node); a mesh may pass its own directors (the smooth surface's
// normals, shared by the elements around a node). See docs/shell.md for the formulation, the sign
// conventions and the verification.
//
// Conventions (local frame e1, e2, e3 at a point of the mid-surface; z along e3):
//   displacement through the thickness u(z) = u + z theta x e3, i.e. u_x(z) = u + z theta_y,
//   u_y(z) = v - z theta_x;
//   membrane strain  eps = (du/dx, dv/dy, du/dy + dv/dx)                    (engineering shear)
//   curvature        kappa = (dtheta_y/dx, -dtheta_x/dy, dtheta_y/dy - dtheta_x/dx)
//   transverse shear gamma = (dw/dx + theta_y, dw/dy - theta_x)
//   resultants       N = A eps + B kappa, M = B eps + D kappa, Q = H gamma
//   so that the strain at height z is eps + z kappa.
// Quadrilateral: nodes counter-clockwise about the intended normal, natural coordinates
// (xi, eta) = (-1,-1), (1,-1), (1,1), (-1,1); element normal e3 = X_xi x X_eta at the centre.
// Triangle: nodes counter-clockwise about the intended normal, natural coordinates (r, s) =
// (0,0), (1,0), (0,1); element normal e3 = (X2 - X1) x (X3 - X1), e1 along X2 - X1.
//
// Errors (bad material data, a degenerate element, a bad director) throw std::invalid_argument with a
// message naming the input; callers inside PETSc callbacks turn them into PETSc errors
// (lib/core/guard.hpp).
#pragma once

#include <array>
#include <vector>

namespace boltnet::shell {

using Vec3 = std::array<double, 3>;
using Nodes = std::array<Vec3, 4>;   // the four node positions, global coordinates
using Mat3 = std::array<double, 9>;  // 3x3, row-major, Voigt order (xx, yy, xy)
using Mat2 = std::array<double, 4>;  // 2x2, row-major, order (xz, yz)
using ElementMatrix = std::array<double, 576>; // 24x24, row-major, dof 6*node + component
using ElementVector = std::array<double, 24>;
using Directors = std::array<Vec3, 4>;         // nodal directors of a quadrilateral (unit or not)
using TriNodes = std::array<Vec3, 3>;          // the three node positions of a triangle
using TriMatrix = std::array<double, 324>;     // 18x18, row-major, dof 6*node + component
using TriVector = std::array<double, 18>;
using TriDirectors = std::array<Vec3, 3>;

/* One ply of a laminate: fibre angle (degrees, about the shell normal, from the material reference
   direction), thickness, and the orthotropic ply moduli in the ply axes (1 = fibre). */
struct Ply {
  double angle_deg, thickness, E1, E2, nu12, G12, G13, G23;
};

/* Shell section: stress resultants per unit length against generalised strains, in the material
   frame (x axis = the material reference direction projected on the element plane). */
struct ShellMaterial {
  Mat3 A{}, B{}, D{}; // membrane, coupling, bending stiffness
  Mat2 H{};           // transverse shear stiffness (shear correction included)
  double thickness = 0;
  Vec3 direction{1, 0, 0}; // material reference direction (global); projected on each element
};

/* Isotropic shell: A = E t / (1 - nu^2) [..], D = E t^3 / (12 (1 - nu^2)) [..], B = 0,
   H = 5/6 G t I. Throws on E <= 0, t <= 0 or nu outside (-1, 0.5]. */
ShellMaterial IsotropicMaterial(double E, double nu, double t);

/* Laminate by classical lamination theory; plies listed from the bottom (z = -h/2, h the total
   thickness) to the top. H = k sum_k Qs_k t_k with the shear correction factor k (5/6 default).
   Throws, naming the ply and the value, on no plies or a non-positive thickness or modulus. */
ShellMaterial LaminateMaterial(const std::vector<Ply> &plies, double shear_correction = 5.0 / 6.0);

/* The same section seen in axes rotated by phi (radians) about the normal: if the material x axis
   lies at angle phi from the new x axis, returns A' = T^T A T (likewise B, D; H' = S^T H S), with
   T the engineering-strain rotation by phi. */
ShellMaterial RotateMaterial(const ShellMaterial &m, double phi);

/* The element frame: centre (mean of the nodes), e1 along X_xi, e3 = unit(X_xi x X_eta) at the centre,
   e2 = e3 x e1; node coordinates x, y in the mean plane and offsets h along e3 (warping). */
struct ElementFrame {
  Vec3 centre, e1, e2, e3;
  std::array<double, 4> x, y, h;
};
ElementFrame MakeElementFrame(const Nodes &X);

/* The triangle's frame: centre (mean of the nodes), e1 along X2 - X1, e3 the unit normal, e2 = e3 x e1,
   node coordinates x, y in that plane. Throws on a degenerate triangle. */
struct TriFrame {
  Vec3 centre, e1, e2, e3;
  std::array<double, 3> x, y;
};
TriFrame MakeElementFrame(const TriNodes &X);

/* Default drilling factor: the Hughes-Brezzi penalty is gamma = drill * G_m, with G_m the invariant
   membrane shear stiffness (A11 + A22 - 2 A12 + 4 A66) / 8 (= G t for an isotropic shell). 1e-2 lies
   on the plateau where the benchmarks do not depend on it (docs/shell-convergence.md): below about
   1e-3 the normal rotation is nearly free and curved shells become too soft as the mesh is refined;
   near 1 the penalty stiffens coarse meshes of curved shells. */
constexpr double kDefaultDrill = 1e-2;

/* Quadrilateral membrane: Bilinear (the plain bilinear membrane of MITC4), or Incompatible: bilinear
   enriched with the Wilson-Taylor incompatible modes 1 - xi^2, 1 - eta^2 (QM6, condensed inside the
   element, Taylor's correction so that the patch test passes on any quadrilateral), which removes
   the bilinear membrane's locking in in-plane bending. */
enum class Membrane { Bilinear, Incompatible };

/* Quadrilateral geometry: Directors (default) uses the bilinear mid-surface through the nodes and the
   director kinematics, exact for rigid motions and blind to rotations about the directors; RigidLinks
   is the flat element in the mean plane tied to the nodes by rigid offsets (MacNeal's warping
   correction), the formulation before the director kinematics, kept for comparison: on twisted
   shells its drilling rotation leaks into bending and the answer depends on the drilling factor
   (docs/shell.md, "Warped elements"). Identical on flat elements. */
enum class Warping { Directors, RigidLinks };

/* Triangle membrane: Linear (default), the constant-strain triangle with the quadrilateral's
   Hughes-Brezzi drilling term: its edges stay straight like the quadrilateral's, so meshes may mix both
   (patch tests exact), but it locks in in-plane bending (docs/shell.md); or Optimal, Felippa's ANDES OPT
   element with drilling freedoms: exact in in-plane pure bending of rectangular units, its own drilling
   stiffness (the drilling factor does not apply), but its constant-stress nodal forces include drilling
   moments that no bilinear edge matches, so it is for all-triangle meshes only, with edge loads that
   include those moments (a mesh mixing it with quadrilaterals fails the patch test by 20 %). */
enum class TriangleMembrane { Linear, Optimal };

/* Triangle bending and transverse shear: MITC3Plus (cubic bubble on the rotations, condensed; the
   MITC3+ tying scheme) or MITC3 (linear rotations, tangential shear tied at the edge midpoints). */
enum class TriangleShear { MITC3Plus, MITC3 };

struct ElementOptions {
  double drill = kDefaultDrill; // >= 0, scales the Hughes-Brezzi drilling penalty
  Membrane membrane = Membrane::Incompatible;
  Warping warping = Warping::Directors;
  TriangleMembrane triangle_membrane = TriangleMembrane::Linear;
  TriangleShear triangle_shear = TriangleShear::MITC3Plus;
};

/* 24x24 element stiffness in global coordinates, dof order (u_x, u_y, u_z, th_x, th_y, th_z) per
   node; V: nodal directors (nullptr: the element's own normals; normalised here; each within 84 deg
   of the element normal). Throws std::invalid_argument on a degenerate element, a bad director or a
   negative drilling factor. */
void ElementStiffness(const Nodes &X, const Directors *V, const ShellMaterial &mat, const ElementOptions &options, ElementMatrix &K);
void ElementStiffness(const Nodes &X, const ShellMaterial &mat, const ElementOptions &options, ElementMatrix &K);
/* The same with the default options but the given drilling factor. */
void ElementStiffness(const Nodes &X, const ShellMaterial &mat, double drill, ElementMatrix &K);

/* 18x18 triangle stiffness, same conventions. */
void ElementStiffness(const TriNodes &X, const TriDirectors *V, const ShellMaterial &mat, const ElementOptions &options, TriMatrix &K);
void ElementStiffness(const TriNodes &X, const ShellMaterial &mat, const ElementOptions &options, TriMatrix &K);

/* Consistent nodal forces for a force per unit area q (global vector: self weight, a distributed
   load), integrated over the mid-surface (bilinear for the quadrilateral). Rotation entries are zero. */
void ElementLoad(const Nodes &X, const Vec3 &q, ElementVector &F);
void ElementLoad(const TriNodes &X, const Vec3 &q, TriVector &F);

/* Consistent nodal forces for a pressure p acting along +n, n the unit normal of the mid-surface
   oriented like e3 (quadrilateral: n dA = X_xi x X_eta dxi deta). */
void ElementPressure(const Nodes &X, double p, ElementVector &F);
void ElementPressure(const TriNodes &X, double p, TriVector &F);

/* Any element of a mixed mesh, for a patch operator that loops over quadrilaterals and triangles:
   n = 3 (triangle) or 4 (quadrilateral) nodes X[0..n-1], directors V (nullptr: the element's own),
   K with (6n)^2 entries, F with 6n. Throws on another n. */
void ElementStiffness(int n, const Vec3 *X, const Vec3 *V, const ShellMaterial &mat, const ElementOptions &options, double *K);
void ElementLoad(int n, const Vec3 *X, const Vec3 &q, double *F);
void ElementPressure(int n, const Vec3 *X, double p, double *F);

/* Generalised strains at a point of the element, in the local frame there (e1 = the element's e1
   projected on the tangent plane; the element frame on a flat element), from global nodal
   displacements: membrane strain (with the condensed incompatible modes or the OPT higher-order
   strain), curvature (with the condensed bubble of MITC3+), the tied transverse shear, and the
   drilling defect theta . n - omega (omega = (dv/dx - du/dy) / 2 of the compatible field).
   Quadrilateral at (xi, eta), triangle at (r, s). */
struct GeneralisedStrains {
  std::array<double, 3> membrane, curvature;
  std::array<double, 2> shear;
  double drill;
};
/* The element's condensed internal modes in terms of its nodal dof, which is what ElementStrains
   integrates the element for (most of its cost): a quadrilateral's four incompatible membrane modes
   alpha = -Y u_q (Y = Kaa^-1 Kau, 4 x 24, u_q the dof of the element as integrated: the flat
   element's under Warping::RigidLinks), a triangle's two bubble rotations q = P u (P = -Kbb^-1 Kbu,
   2 x 18, the first 36 values). `any` is false where the element condenses nothing. They depend on
   the geometry and the section only: a caller that evaluates the same element at every load step
   keeps them (776 bytes) and passes them to ElementStrains, which then integrates nothing. */
struct CondensedModes {
  std::array<double, 96> Y{};
  bool                   any = false;
};
CondensedModes ElementCondensedModes(const Nodes &X, const Directors *V, const ShellMaterial &mat, const ElementOptions &options);
CondensedModes ElementCondensedModes(const TriNodes &X, const TriDirectors *V, const ShellMaterial &mat, const ElementOptions &options);
GeneralisedStrains ElementStrains(const Nodes &X, const Directors *V, const ShellMaterial &mat, const ElementOptions &options,
                                  const ElementVector &u, double xi, double eta, const CondensedModes *kept = nullptr);
GeneralisedStrains ElementStrains(const Nodes &X, const ShellMaterial &mat, const ElementOptions &options,
                                  const ElementVector &u, double xi, double eta);
/* The nodal (compatible, bilinear) part only: no material needed. */
GeneralisedStrains ElementStrains(const Nodes &X, const ElementVector &u, double xi, double eta);
GeneralisedStrains ElementStrains(const TriNodes &X, const TriDirectors *V, const ShellMaterial &mat, const ElementOptions &options,
                                  const TriVector &u, double r, double s, const CondensedModes *kept = nullptr);

} // namespace boltnet::shell
