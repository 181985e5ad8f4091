// Stiffness already in the shells: the compliance that the shell mesh and the patch
// coupling add to a joint, measured on a virtual coupon, and the fastener stiffness corrected for it.
//
// A fastener formula (Huth, Swift, ...) gives the compliance of the whole joint as measured on a test
// specimen, minus the bare sheets' axial compliance: it contains the sheets' own local (bearing, load
// spreading) flexibility around the hole. A shell model joined through a footprint already delivers
// part of that flexibility, a part that depends on the mesh. The coupon measures it, with the
// library's own elements and coupling: two sheets in one plane (no eccentricity, so secondary bending
// stays in the structure), meshed like the joint's patches, joined by a stiff spring, one end clamped,
// the other pulled. C_c = delta/F - C_b - 1/k_spring; the corrected stiffness k = 1/(1/k_formula - C_c)
// makes spring + shells as compliant as the formula says. docs/identify.md, "Stiffness already in the
// shells".
#pragma once

#include "joint/law.hpp"
#include "patch/patch.hpp"

#include <petscsys.h>

#include <string>

namespace boltnet {
namespace identify {

struct CouponSpec {
  shell::ShellMaterial sheet[2];     // sections of the two sheets (plate 1 / patch a, plate 2 / patch b)
  double               hx[2] = {0, 0}, hy[2] = {0, 0}; // element size of each sheet along / across the load
  double               d       = 0;  // fastener diameter
  double               width   = 0;  // coupon width; 0: 5 d
  CouplingType         coupling = CouplingType::Exact;
  double               radius   = 4.0, penalty = 1e3; // as -coupling_radius, -coupling_penalty
  double               kspring  = 0; // the stiff spring standing for the fastener (N/mm)
};

struct CouponResult {
  double Cc = 0;         // compliance added by the shells and the coupling (mm/N)
  double Cb = 0;         // bare sheets' axial compliance along the load path
  double compliance = 0; // delta / F
  double force = 0;      // F at the prescribed delta
  double length = 0, edge = 0, width = 0; // sheet length, edge distance (fastener to sheet end), width
  int    nx[2] = {0, 0}, ny[2] = {0, 0};   // elements per sheet
};

// Builds and solves the coupon on PETSC_COMM_SELF (every rank the same, no communication).
PetscErrorCode CouponCompliance(const CouponSpec &spec, CouponResult *res);

// Mean extent, along t1 and along axis x t1, of the elements holding a node of the coupling
// footprint of a fastener at p (the element containing p when there is none). Errors (on comm) when
// p is outside the mesh.
PetscErrorCode FootprintElementSize(MPI_Comm comm, const ShellMesh &m, const double p[3], const double axis[3], const double t1[3], double radius, double *hx, double *hy);

// k = 1/(1/k_formula - C_c) for the bearing stiffness kc and the stick stiffness kt of q (both
// measure the whole joint). An error naming `what` when the shells alone are already at least as
// compliant as the formula (1/k - C_c <= 0): no positive spring can then give the formula's stiffness.
PetscErrorCode ApplyShellCorrection(MPI_Comm comm, const std::string &what, double Cc, Params *q);

} // namespace identify
} // namespace boltnet
