#include "identify/options.hpp"

#include <cmath>

namespace boltnet {
namespace identify {

PetscErrorCode FastenerFromOptions(MPI_Comm comm, const char prefix[], const char title[], FastenerOptions *o)
{
  const char *formulaChoices[] = {"huth", "swift", "tate-rosenfeld", "grumman", "boeing", "nelson"};
  const char *typeChoices[]    = {"bolted-metal", "riveted-metal", "bolted-composite"};
  PetscInt    formula = static_cast<PetscInt>(o->formula), type = static_cast<PetscInt>(o->type), n = o->g.n;
  PetscReal   mu      = NAN;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, prefix, title, "boltnet");
  PetscCall(PetscOptionsReal("-d", "Fastener (shank) diameter (mm)", "", o->g.d, &o->g.d, nullptr));
  PetscCall(PetscOptionsReal("-hole", "Hole diameter (mm); the clearance is (hole - d)/2", "", o->g.hole, &o->g.hole, nullptr));
  PetscCall(PetscOptionsReal("-t1", "Thickness of plate 1 (mm); double shear: the middle plate", "", o->g.t1, &o->g.t1, nullptr));
  PetscCall(PetscOptionsReal("-t2", "Thickness of plate 2 (mm); double shear: each outer plate", "", o->g.t2, &o->g.t2, nullptr));
  PetscCall(PetscOptionsReal("-E1", "Modulus of plate 1 (MPa); laminate: its effective bearing modulus", "", o->g.E1, &o->g.E1, nullptr));
  PetscCall(PetscOptionsReal("-E2", "Modulus of plate 2 (MPa); laminate: its effective bearing modulus", "", o->g.E2, &o->g.E2, nullptr));
  PetscCall(PetscOptionsReal("-Ef", "Fastener modulus (MPa)", "", o->g.Ef, &o->g.Ef, nullptr));
  PetscCall(PetscOptionsReal("-nu", "Fastener Poisson ratio (Tate-Rosenfeld, Nelson)", "", o->g.nu_f, &o->g.nu_f, nullptr));
  PetscCall(PetscOptionsInt("-shear_planes", "Shear planes n: 1 single shear, 2 double shear", "", n, &n, nullptr));
  PetscCall(PetscOptionsReal("-torque", "Installation torque T (N mm); Pc = T/(K d)", "", o->g.torque, &o->g.torque, nullptr));
  PetscCall(PetscOptionsReal("-preload", "Bolt preload Pc (N); overrides the torque", "", o->g.preload, &o->g.preload, nullptr));
  PetscCall(PetscOptionsReal("-nut_factor", "Nut factor K in Pc = T/(K d)", "", o->g.K, &o->g.K, nullptr));
  PetscCall(PetscOptionsReal("-mu", "Friction coefficient, in [0, 2] (required)", "", mu, &mu, &o->has_mu));
  PetscCall(PetscOptionsReal("-nf", "Friction interfaces (0: as many as shear planes)", "", o->g.nf, &o->g.nf, nullptr));
  PetscCall(PetscOptionsReal("-offset_t1", "Initial bolt offset in the hole along t1 (mm)", "", o->g.offset[0], &o->g.offset[0], nullptr));
  PetscCall(PetscOptionsReal("-offset_t2", "Initial bolt offset in the hole along t2 (mm)", "", o->g.offset[1], &o->g.offset[1], nullptr));
  PetscCall(PetscOptionsEList("-formula", "Fastener flexibility formula for the bearing stiffness kc", "", formulaChoices, 6, formulaChoices[formula], &formula, nullptr));
  PetscCall(PetscOptionsEList("-type", "Huth's joint type (sets a, b)", "", typeChoices, 3, typeChoices[type], &type, nullptr));
  PetscCall(PetscOptionsReal("-beta", "Nelson et al.: bearing factor (1 + 3 beta)", "", o->g.beta, &o->g.beta, nullptr));
  PetscCall(PetscOptionsReal("-kt", "Stick stiffness ke (N/mm); 0: equal to the bearing stiffness kc", "", o->kt, &o->kt, nullptr));
  PetscCall(PetscOptionsReal("-kg", "Regularisation stiffness while sliding (N/mm)", "", o->kg, &o->kg, nullptr));
  PetscCall(PetscOptionsReal("-kr", "Rotational stiffness (N mm/rad); 0: 1e3 kn d^2 (rigid rotation)", "", o->kr, &o->kr, nullptr));
  PetscOptionsEnd();
  o->g.n     = (int)n;
  o->g.mu    = mu;
  o->formula = static_cast<Formula>(formula);
  o->type    = static_cast<HuthType>(type);
  PetscFunctionReturn(0);
}

PetscErrorCode ShellCorrectionFromOptions(MPI_Comm comm, const char prefix[], const char title[], PetscBool standalone, ShellCorrectionOptions *o)
{
  const char *couplings[] = {"penalty", "exact", "node"}; // as -coupling_type (patch/patch.hpp)
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, prefix, title, "boltnet");
  PetscCall(PetscOptionsBool("-shell_correction", "Subtract from the formula's compliance what the shell mesh and coupling already deliver, measured on a flat coupon (docs/identify.md)", "", o->on, &o->on, nullptr));
  PetscCall(PetscOptionsReal("-shell_h", standalone ? "Shell element size around the fastener (mm), required with the correction" : "Shell element size around the fastener (mm); 0: measured on the joint's patches", "", o->h, &o->h, nullptr));
  PetscCall(PetscOptionsReal("-shell_width", "Width of the correction coupon (mm); 0: 5 d", "", o->width, &o->width, nullptr));
  PetscCall(PetscOptionsReal("-shell_spring", "The coupon's fastener spring, as a multiple of the formula's kc", "", o->spring, &o->spring, nullptr));
  if (standalone) {
    PetscCall(PetscOptionsReal("-shell_nu", "Poisson ratio of the coupon's (isotropic) sheets", "", o->nu, &o->nu, nullptr));
    PetscCall(PetscOptionsEList("-shell_coupling", "Coupling of the coupon's fastener, as -coupling_type of the scene", "", couplings, 3, couplings[o->coupling], &o->coupling, nullptr));
    PetscCall(PetscOptionsReal("-shell_radius", "Footprint radius of the coupon's fastener (mm), as -coupling_radius of the scene", "", o->radius, &o->radius, nullptr));
  }
  PetscOptionsEnd();
  PetscCheck(o->h >= 0 && o->width >= 0 && o->spring > 0 && o->radius > 0, comm, PETSC_ERR_USER_INPUT, "Options -%sshell_*: h (%g) and width (%g) must be >= 0, spring (%g) and radius (%g) > 0", prefix, o->h, o->width, o->spring, o->radius);
  PetscFunctionReturn(0);
}

PetscErrorCode FastenerMacroelement(MPI_Comm comm, const char prefix[], const FastenerOptions &o, Params *p)
{
  PetscFunctionBeginUser;
  PetscCheck(o.has_mu, comm, PETSC_ERR_USER_INPUT, "No friction coefficient: give -%smu (in [0, 2])", prefix);
  const std::string bad = validateGeometry(o.g, o.formula);
  PetscCheck(bad.empty(), comm, PETSC_ERR_USER_INPUT, "Bad fastener geometry (options -%s*): %s", prefix, bad.c_str());
  *p                     = macroelement(o.g, o.formula, o.type, o.kt, o.kg, o.kr);
  const std::string bad2 = validate(*p);
  PetscCheck(bad2.empty(), comm, PETSC_ERR_USER_INPUT, "The macroelement from the geometry of -%s* is not valid: %s", prefix, bad2.c_str());
  PetscFunctionReturn(0);
}

} // namespace identify
} // namespace boltnet
