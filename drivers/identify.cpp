static const char help[] = "boltnet-identify: the frictional macroelement's parameters from a fastener's geometry or from a test curve.\n\
\n\
Geometry mode (the default): clearance, pretension, friction threshold, axial stiffness and the bearing\n\
stiffness from a fastener flexibility formula, printed as the YAML of a scene's joint type section:\n\
  boltnet-identify -fastener_d 6.35 -fastener_hole 6.45 -fastener_t1 3 -fastener_t2 4 -fastener_E1 72000\n\
      -fastener_E2 72000 -fastener_Ef 110000 -fastener_torque 8000 -fastener_mu 0.3 -fastener_formula huth\n\
      -fastener_type bolted-metal\n\
Curve mode: least-squares fit of ke, G, kg, j, kc to a load-slip curve (CSV with columns load,slip and an\n\
optional time column that must increase), with standard errors and the residual:\n\
  boltnet-identify -curve test/data/identify/cyclic.csv\n\
Shell correction (geometry mode, -fastener_shell_correction -fastener_shell_h <mm>): subtract the\n\
compliance the shell mesh and coupling already deliver, measured on a flat coupon.\n\
\n\
Units: any consistent set (N, mm, MPa, N mm in the examples). Formulas, sources and assumptions:\n\
docs/identify.md. Bad input stops with a message naming it and a non-zero exit.\n\n";

#include "core/guard.hpp"
#include "driver.hpp"
#include "identify/coupon.hpp"
#include "identify/curve.hpp"
#include "identify/fastener.hpp"
#include "identify/options.hpp"
#include "io/io.hpp"

#include <boltnet.h>
#include <petscsys.h>

#include <cmath>
#include <string>

using namespace boltnet;
using namespace boltnet::identify;

namespace {

const char *const formulaChoices[] = {"huth", "swift", "tate-rosenfeld", "grumman", "boeing", "nelson"};
const char *const typeChoices[]    = {"bolted-metal", "riveted-metal", "bolted-composite"};

const char *formulaSource(Formula f)
{
  switch (f) {
  case Formula::Huth: return "Huth, ASTM STP 927 (1986)";
  case Formula::Swift: return "Swift (Douglas), ASTM STP 486 (1971)";
  case Formula::TateRosenfeld: return "Tate & Rosenfeld, NACA TN 1051 (1946)";
  case Formula::Grumman: return "Grumman (as given by Huth, ASTM STP 927), d^3 form";
  case Formula::Boeing: return "Boeing D6-29942 (1969, as given by Huth, ASTM STP 927)";
  case Formula::Nelson: return "Nelson, Bunin & Hart-Smith, NASA CR-3710 (1983)";
  }
  return "";
}

PetscErrorCode PrintJoint(MPI_Comm comm, const char *type, const Params &p)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "joint:\n  %s:\n    law: friction\n", type));
  PetscCall(PetscPrintf(comm, "    kn: %.8g\n    kt: %.8g\n    kr: %.8g\n    kc: %.8g\n    kg: %.8g\n", p.kn, p.kt, p.kr, p.kc, p.kg));
  PetscCall(PetscPrintf(comm, "    gap: %.8g\n    mu: %.8g\n    nf: %.8g\n    pretension: %.8g\n", p.gap, p.mu, p.nf, p.pretension));
  if (p.offset[0] != 0 || p.offset[1] != 0) PetscCall(PetscPrintf(comm, "    offset_t1: %.8g\n    offset_t2: %.8g\n", p.offset[0], p.offset[1]));
  PetscFunctionReturn(0);
}

PetscErrorCode GeometryMode(MPI_Comm comm, const char *jointType)
{
  FastenerOptions o;
  Params          p;
  PetscBool       helpOnly;
  PetscFunctionBeginUser;
  ShellCorrectionOptions sc;
  PetscCall(FastenerFromOptions(comm, "fastener_", "boltnet-identify: fastener geometry (geometry mode)", &o));
  PetscCall(ShellCorrectionFromOptions(comm, "fastener_", "boltnet-identify: shell correction (geometry mode)", PETSC_TRUE, &sc));
  PetscCall(PetscOptionsHasHelp(nullptr, &helpOnly));
  if (helpOnly) PetscFunctionReturn(0);
  PetscCall(FastenerMacroelement(comm, "fastener_", o, &p));
  const Params p0 = p;
  CouponSpec   spec;
  CouponResult res;
  if (sc.on) {
    PetscCheck(sc.h > 0, comm, PETSC_ERR_USER_INPUT, "The shell correction needs the shell element size around the fastener: give -fastener_shell_h <mm>");
    PetscCheck(o.g.n == 1, comm, PETSC_ERR_USER_INPUT, "The shell correction's coupon is a single lap of two sheets: it needs -fastener_shear_planes 1 (got %d)", o.g.n);
    PetscCall(Guard(comm, [&] {
      spec.sheet[0] = shell::IsotropicMaterial(o.g.E1, sc.nu, o.g.t1);
      spec.sheet[1] = shell::IsotropicMaterial(o.g.E2, sc.nu, o.g.t2);
      return PetscErrorCode(0);
    }));
    spec.hx[0] = spec.hy[0] = spec.hx[1] = spec.hy[1] = sc.h;
    spec.d        = o.g.d;
    spec.width    = sc.width;
    spec.coupling = static_cast<CouplingType>(sc.coupling);
    spec.radius   = sc.radius;
    spec.kspring  = sc.spring * p.kc;
    PetscCall(CouponCompliance(spec, &res));
    char what[160];
    PetscCall(PetscSNPrintf(what, sizeof(what), "Shell correction (-fastener_shell_h %g, %s coupling, radius %g)", sc.h, kCouplingTypeNames[sc.coupling], sc.radius));
    PetscCall(ApplyShellCorrection(comm, what, res.Cc, &p));
  }
  const FastenerGeometry &g  = o.g;
  const Formula           f  = o.formula;
  const HuthType          t  = o.type;
  const double            kt = o.kt;

  const double C = compliance(g, f, t);
  PetscCall(PetscPrintf(comm, "# boltnet-identify: frictional macroelement from the fastener geometry (docs/identify.md)\n"));
  if (f == Formula::Huth) {
    double a, b;
    huthConstants(t, &a, &b);
    PetscCall(PetscPrintf(comm, "# bearing: formula huth, type %s (a = %g, b = %g, n = %d): %s\n", huthTypeName(t), a, b, g.n, formulaSource(f)));
  } else PetscCall(PetscPrintf(comm, "# bearing: formula %s: %s\n", formulaName(f), formulaSource(f)));
  PetscCall(PetscPrintf(comm, "#   compliance C = %.8g, kc = 1/C = %.8g; stick kt = %s\n", C, p.kc, kt > 0 ? "given" : "kc"));
  PetscCall(PetscPrintf(comm, "# clearance: gap = (hole - d)/2 = %.8g (radius of the clearance circle)\n", p.gap));
  if (g.preload > 0) PetscCall(PetscPrintf(comm, "# pretension: the given preload Pc = %.8g\n", p.pretension));
  else if (g.torque > 0) PetscCall(PetscPrintf(comm, "# pretension: Pc = T/(K d) = %.8g/(%.8g x %.8g) = %.8g\n", g.torque, g.K, g.d, p.pretension));
  else PetscCall(PetscPrintf(comm, "# pretension: no preload nor torque given: Pc = 0, the joint slides at once\n"));
  PetscCall(PetscPrintf(comm, "# friction threshold: G = mu nf Pc = %.8g\n", p.mu * p.nf * p.pretension));
  PetscCall(PetscPrintf(comm, "# axial: kn = Ef (pi d^2/4) / (t1 + n t2) = %.8g\n", p.kn));
  if (sc.on) {
    PetscCall(PetscPrintf(comm, "# shell correction: flat coupon %g x %g mm sheets, edge distance %g, %d x %d and %d x %d elements (h = %g), %s coupling, radius %g\n", res.length, res.width, res.edge, res.nx[0], res.ny[0], res.nx[1], res.ny[1], sc.h, kCouplingTypeNames[sc.coupling], sc.radius));
    PetscCall(PetscPrintf(comm, "#   delta/F = %.8g, bare sheets C_b = %.8g, spring 1/%.6g: C_c = %.8g (%.4f / kc)\n", res.compliance, res.Cb, spec.kspring, res.Cc, res.Cc * p0.kc));
    PetscCall(PetscPrintf(comm, "#   corrected: kc = 1/(1/%.8g - C_c) = %.8g, kt = 1/(1/%.8g - C_c) = %.8g\n", p0.kc, p.kc, p0.kt, p.kt));
  }
  PetscCall(PrintJoint(comm, jointType, p));
  PetscFunctionReturn(0);
}

PetscErrorCode CurveMode(MPI_Comm comm, const char *file, const char *jointType)
{
  Curve     c;
  FitResult r;
  PetscFunctionBeginUser;
  const std::string bad = readCurve(file, &c);
  PetscCheck(bad.empty(), comm, PETSC_ERR_USER_INPUT, "Bad curve (-curve): %s", bad.c_str());
  const std::string msg = fitFriction(c, &r);
  PetscCheck(msg.empty(), comm, PETSC_ERR_USER_INPUT, "Cannot identify the macroelement (-curve): %s", msg.c_str());
  PetscCall(PetscPrintf(comm, "# boltnet-identify: frictional macroelement fitted to '%s' (%d points; docs/identify.md)\n", file, r.n));
  PetscCall(PetscPrintf(comm, "fit:\n"));
  for (int k = 0; k < NPARAM; ++k)
    PetscCall(PetscPrintf(comm, "  %s: %.8g   # standard error %.3g (initial guess %.6g)\n", paramName(k), r.theta[k], r.stderr_[k], r.guess[k]));
  PetscCall(PetscPrintf(comm, "  residual_norm: %.6g   # sqrt(sum of squared load residuals)\n", std::sqrt(r.rss)));
  PetscCall(PetscPrintf(comm, "  residual_rms: %.6g\n  sigma: %.6g   # noise estimate sqrt(RSS/(n - 5))\n", r.rms, r.sigma));
  PetscCall(PetscPrintf(comm, "  iterations: %d\n  converged: %s\n", r.iterations, r.converged ? "true" : "false"));
  PetscCall(PetscPrintf(comm, "  rows: {stick: %d, slide: %d, bearing: %d}\n", r.n_stick, r.n_slide, r.n_bearing));
  if (!r.warning.empty()) PetscCall(PetscPrintf(comm, "# WARNING: %s\n", r.warning.c_str()));
  Params p = frictionParams(r.theta);
  PetscCall(PetscPrintf(comm, "# only G = mu nf Pc is identified: mu = nf = 1, pretension = G below; kn and kr are not\n# identified by an in-plane curve (kn = 0, kr = 0 here: set them from the geometry)\n"));
  PetscCall(PrintJoint(comm, jointType, p));
  PetscFunctionReturn(0);
}

PetscErrorCode Run(int *exitcode)
{
  MPI_Comm  comm = PETSC_COMM_WORLD;
  char      file[PETSC_MAX_PATH_LEN] = "", jointType[64] = "bolt";
  PetscBool hasCurve = PETSC_FALSE, optionsLeft = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(BoltnetInitializePackage());
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-options_left", &optionsLeft, nullptr));
  PetscOptionsBegin(comm, nullptr, "boltnet-identify", "boltnet");
  PetscCall(PetscOptionsString("-curve", "Load-slip curve (CSV: load,slip[,time]) to fit: curve mode", "", file, file, sizeof(file), &hasCurve));
  PetscCall(PetscOptionsString("-identify_joint_type", "Joint type name in the printed YAML (joint: <type>:)", "", jointType, jointType, sizeof(jointType), nullptr));
  PetscOptionsEnd();
  PetscBool helpOnly;
  PetscCall(PetscOptionsHasHelp(nullptr, &helpOnly));
  if (helpOnly) { // list every option of both modes, run nothing
    PetscCall(GeometryMode(comm, jointType));
    PetscFunctionReturn(0);
  }
  if (hasCurve) PetscCall(CurveMode(comm, file, jointType));
  else PetscCall(GeometryMode(comm, jointType));
  if (optionsLeft) PetscCall(UnusedOptionsAsError(comm, "boltnet-identify", PETSC_FALSE, exitcode)); // an error, not a warning
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv)
{
  return DriverMain("boltnet-identify", &argc, &argv, help, [](int *exitcode, ErrorLog *) { return Run(exitcode); });
}
