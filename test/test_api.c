static const char help[] = "test_api: the public C API of boltnet (boltnet.h only) against closed forms.\n\
\n\
Requirement: a PETSc code in C builds an assembly through boltnet.h alone, solves a load path and\n\
reads joint results that match the paper's closed forms, at any number of ranks.\n\
\n\
1. Friction (the fig3c scene, share/scenes/fig3c.yaml): patch 0 clamped (dof -1), a force of 1 N per\n\
   unit load factor in x on patch 1, one frictional bolt (n = z, t1 = x). With G = mu nf Pc = 3000 N,\n\
   ke = kt, u the jump in t1:\n\
     stick    u = F/ke                              F <= G\n\
     slide    u = G/ke + (F - G)/kg                 while the slip (F - G)/kg < j\n\
     bearing  u = G/ke + j + (F - G - kg j)/kc      (state contact)\n\
   then unloading from Fmax: stick with slope ke until the force has dropped by 2G,\n\
   u = umax - (Fmax - F)/ke, and reverse slip after: u = -G/ke + j + (F + G - kg j)/kc (still bearing).\n\
2. Spring law (t1 at 30 degrees to x, so the local frame is exercised): F = kt u.\n\
3. Contact law: F = k u for u <= j, k j + k' (u - j) after (states open, contact).\n\
Every check: relative tolerance 1e-9; the patch displacement agrees with the jump (patch 0 fixed).\n\
Prints nothing but a PASS line unless a check fails (then a PETSc error naming it, exit code 1).\n\
\n\
  mpiexec -n 3 build/bin/test_api -options_left -malloc_debug -malloc_dump\n\n";

#include <boltnet.h>
#include <math.h>

#define TOL 1e-9

/* |a - b| <= TOL max(|b|, scale): relative to the expected value, or to `scale` where that is 0. */
static PetscBool Close(PetscReal a, PetscReal b, PetscReal scale)
{
  return PetscAbsReal(a - b) <= TOL * PetscMax(PetscAbsReal(b), scale) ? PETSC_TRUE : PETSC_FALSE;
}

/* Check joint `id` of assembly `a` at the last converged step: the local force is (0, Ft1, Ft2, 0, 0, 0),
   the local jump (0, ut1, ut2, 0, 0, 0), the state `state`, and the displacement of patch `pb`
   (the loaded one, the other fixed) is the jump rotated back by the frame rows t1, t2. */
static PetscErrorCode CheckJoint(BoltnetAssembly a, const char *what, PetscInt id, PetscInt pa, PetscInt pb, const PetscReal t1[3], const PetscReal t2[3], PetscReal Ft1, PetscReal Ft2, PetscReal ut1, PetscReal ut2, BoltnetJointState state)
{
  PetscReal         f[6], u[6], ua[6], ub[6];
  BoltnetJointState s;
  const PetscReal   fexp[6] = {0, Ft1, Ft2, 0, 0, 0}, uexp[6] = {0, ut1, ut2, 0, 0, 0};
  const PetscReal   fscale = PetscMax(PetscAbsReal(Ft1), PetscAbsReal(Ft2)), uscale = PetscMax(PetscAbsReal(ut1), PetscAbsReal(ut2));

  PetscFunctionBeginUser;
  PetscCall(BoltnetAssemblyGetJointResult(a, id, f, u, &s));
  PetscCheck(s == state, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "%s: joint %" PetscInt_FMT " is in state %s, expected %s", what, id, BoltnetJointStateName(s), BoltnetJointStateName(state));
  for (int i = 0; i < 6; ++i) {
    PetscCheck(Close(f[i], fexp[i], fscale), PETSC_COMM_WORLD, PETSC_ERR_PLIB, "%s: joint %" PetscInt_FMT " force[%d] = %.15g, expected %.15g (relative tolerance %g)", what, id, i, (double)f[i], (double)fexp[i], TOL);
    PetscCheck(Close(u[i], uexp[i], uscale), PETSC_COMM_WORLD, PETSC_ERR_PLIB, "%s: joint %" PetscInt_FMT " jump[%d] = %.15g, expected %.15g (relative tolerance %g)", what, id, i, (double)u[i], (double)uexp[i], TOL);
  }
  PetscCall(BoltnetAssemblyGetPatchDisplacement(a, pa, ua));
  PetscCall(BoltnetAssemblyGetPatchDisplacement(a, pb, ub));
  for (int i = 0; i < 6; ++i) {
    const PetscReal expect = i < 3 ? ut1 * t1[i] + ut2 * t2[i] : 0.0;
    PetscCheck(Close(ua[i], 0.0, uscale), PETSC_COMM_WORLD, PETSC_ERR_PLIB, "%s: the fixed patch %" PetscInt_FMT " moved: u[%d] = %g", what, pa, i, (double)ua[i]);
    PetscCheck(Close(ub[i], expect, uscale), PETSC_COMM_WORLD, PETSC_ERR_PLIB, "%s: patch %" PetscInt_FMT " u[%d] = %.15g, but the jump gives %.15g", what, pb, i, (double)ub[i], (double)expect);
  }
  PetscFunctionReturn(0);
}

/* Solve from the current load factor to `target` in `steps` steps and check that it got there. */
static PetscErrorCode LoadTo(BoltnetAssembly a, PetscReal target, PetscInt steps)
{
  PetscReal lambda;
  PetscFunctionBeginUser;
  PetscCall(BoltnetAssemblySolveLoadPath(a, 1, &target, steps));
  PetscCall(BoltnetAssemblyGetLoadFactor(a, &lambda));
  PetscCheck(lambda == target, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "Load factor %g after the solve, expected %g", (double)lambda, (double)target);
  PetscFunctionReturn(0);
}

/* 1. The frictional bolt of fig3c through stick, slide, bearing, elastic unloading, reverse slip. */
static PetscErrorCode TestFriction(void)
{
  BoltnetAssembly    a;
  BoltnetJointParams p;
  const PetscReal    x0[3] = {0, 0, 0}, n[3] = {0, 0, 1}, ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0};
  PetscReal          G, ke, kg, kc, j, F, umax;

  PetscFunctionBeginUser;
  PetscCall(BoltnetJointParamsSetDefault(BOLTNET_LAW_FRICTION, &p)); /* fig3c.yaml, joint type "bolt" */
  p.kn         = 2.0e5;
  p.kt         = 1.5e5;
  p.kr         = 1.0e9;
  p.kg         = 500;
  p.kc         = 4.0e4;
  p.gap        = 0.05;
  p.mu         = 0.3;
  p.nf         = 1;
  p.pretension = 1.0e4;
  G            = p.mu * p.nf * p.pretension; /* 3000 N */
  ke           = p.kt;
  kg           = p.kg;
  kc           = p.kc;
  j            = p.gap;

  PetscCall(BoltnetAssemblyCreate(PETSC_COMM_WORLD, &a));
  PetscCall(BoltnetAssemblySetOptionsPrefix(a, "fric_"));
  PetscCall(BoltnetAssemblyAddRigidPatch(a, 0, x0));
  PetscCall(BoltnetAssemblyAddRigidPatch(a, 1, x0));
  PetscCall(BoltnetAssemblyAddJoint(a, 0, 0, 1, &p, n, ex));
  PetscCall(BoltnetAssemblyAddBC(a, 0, -1, BOLTNET_BC_FIXED, 0));
  PetscCall(BoltnetAssemblyAddBC(a, 1, 0, BOLTNET_BC_FORCE, 1.0));
  PetscCall(BoltnetAssemblySetFromOptions(a));
  PetscCall(BoltnetAssemblySetUp(a));

  /* Loading. */
  F = 2000; /* stick */
  PetscCall(LoadTo(a, F, 4));
  PetscCall(CheckJoint(a, "friction, loading, stick", 0, 0, 1, ex, ey, F, 0, F / ke, 0, BOLTNET_STATE_STICK));
  F = G + 0.4 * kg * j; /* slide, slip 0.4 j */
  PetscCall(LoadTo(a, F, 4));
  PetscCall(CheckJoint(a, "friction, loading, slide", 0, 0, 1, ex, ey, F, 0, G / ke + (F - G) / kg, 0, BOLTNET_STATE_SLIDE));
  F = 6000; /* bearing */
  PetscCall(LoadTo(a, F, 10));
  umax = G / ke + j + (F - G - kg * j) / kc;
  PetscCall(CheckJoint(a, "friction, loading, bearing", 0, 0, 1, ex, ey, F, 0, umax, 0, BOLTNET_STATE_CONTACT));

  /* Unloading: elastic (stick, slope ke) at every 500 N and just before the force has dropped by 2G. */
  {
    const PetscReal Fmax = F;
    for (PetscInt k = 1; k <= 12; ++k) {
      const PetscReal drop = k < 12 ? 500.0 * (PetscReal)k : 2 * G - 50;
      F                    = Fmax - drop;
      PetscCall(LoadTo(a, F, 1));
      PetscCall(CheckJoint(a, "friction, unloading by less than 2G", 0, 0, 1, ex, ey, F, 0, umax - drop / ke, 0, BOLTNET_STATE_STICK));
    }
    /* Just past 2G: reverse slip, the slip still beyond the clearance (bearing: state contact). */
    F = Fmax - 2 * G - 50;
    PetscCall(LoadTo(a, F, 1));
    PetscCall(CheckJoint(a, "friction, unloading by more than 2G", 0, 0, 1, ex, ey, F, 0, -G / ke + j + (F + G - kg * j) / kc, 0, BOLTNET_STATE_CONTACT));
  }
  PetscCall(BoltnetAssemblyDestroy(&a));
  PetscCheck(!a, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "BoltnetAssemblyDestroy() did not zero the handle");
  PetscFunctionReturn(0);
}

/* 2 and 3. A spring-law joint (patches 10, 11) and a contact-law joint (patches 20, 21) in one
   assembly; both loaded by the same load factor. */
static PetscErrorCode TestSpringAndContact(void)
{
  BoltnetAssembly    a;
  BoltnetJointParams ps, pc;
  const PetscReal    x0[3] = {0, 0, 0}, n[3] = {0, 0, 1}, ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0};
  const PetscReal    c = PetscCosReal(PETSC_PI / 6), s = PetscSinReal(PETSC_PI / 6);
  const PetscReal    t1[3] = {c, s, 0}, t2[3] = {-s, c, 0}; /* spring frame: t2 = n x t1 */
  const PetscReal    Fs = 2.0, Fc = 1.0;                     /* force per unit load factor, in x */
  PetscReal          k, kp, j, lambda;

  PetscFunctionBeginUser;
  PetscCall(BoltnetJointParamsSetDefault(BOLTNET_LAW_SPRING, &ps));
  ps.kn = 1e4;
  ps.kt = 800;
  ps.kr = 1e7;
  PetscCall(BoltnetJointParamsSetDefault(BOLTNET_LAW_CONTACT, &pc));
  pc.kn  = 1e4;
  pc.kt  = 1000; /* k */
  pc.kc  = 1e5;  /* k' */
  pc.gap = 0.01; /* j: contact at F = k j = 10 */
  pc.kr  = 1e7;
  k      = pc.kt;
  kp     = pc.kc;
  j      = pc.gap;

  PetscCall(BoltnetAssemblyCreate(PETSC_COMM_WORLD, &a));
  PetscCall(BoltnetAssemblySetOptionsPrefix(a, "lin_"));
  PetscCall(BoltnetAssemblyAddRigidPatch(a, 10, x0));
  PetscCall(BoltnetAssemblyAddRigidPatch(a, 11, x0));
  PetscCall(BoltnetAssemblyAddRigidPatch(a, 20, x0));
  PetscCall(BoltnetAssemblyAddRigidPatch(a, 21, x0));
  PetscCall(BoltnetAssemblyAddJoint(a, 1, 10, 11, &ps, n, t1));
  PetscCall(BoltnetAssemblyAddJoint(a, 2, 20, 21, &pc, n, ex));
  PetscCall(BoltnetAssemblyAddBC(a, 10, -1, BOLTNET_BC_FIXED, 0));
  PetscCall(BoltnetAssemblyAddBC(a, 20, -1, BOLTNET_BC_FIXED, 0));
  PetscCall(BoltnetAssemblyAddBC(a, 11, 0, BOLTNET_BC_FORCE, Fs));
  PetscCall(BoltnetAssemblyAddBC(a, 21, 0, BOLTNET_BC_FORCE, Fc));
  PetscCall(BoltnetAssemblySetFromOptions(a));
  PetscCall(BoltnetAssemblySetUp(a));

  /* Before contact. The spring: global force Fs lambda along x, so local (Fs c, -Fs s) lambda. */
  lambda = 5;
  PetscCall(LoadTo(a, lambda, 2));
  PetscCall(CheckJoint(a, "spring", 1, 10, 11, t1, t2, Fs * lambda * c, -Fs * lambda * s, Fs * lambda * c / ps.kt, -Fs * lambda * s / ps.kt, BOLTNET_STATE_LINEAR));
  PetscCall(CheckJoint(a, "contact law, before contact", 2, 20, 21, ex, ey, Fc * lambda, 0, Fc * lambda / k, 0, BOLTNET_STATE_OPEN));
  /* After contact: F = k j + k' (u - j). One step across the kink. */
  lambda = 50;
  PetscCall(LoadTo(a, lambda, 1));
  PetscCall(CheckJoint(a, "spring", 1, 10, 11, t1, t2, Fs * lambda * c, -Fs * lambda * s, Fs * lambda * c / ps.kt, -Fs * lambda * s / ps.kt, BOLTNET_STATE_LINEAR));
  PetscCall(CheckJoint(a, "contact law, in contact", 2, 20, 21, ex, ey, Fc * lambda, 0, j + (Fc * lambda - k * j) / kp, 0, BOLTNET_STATE_CONTACT));
  /* Back out of contact: the contact law is elastic. */
  lambda = 8;
  PetscCall(LoadTo(a, lambda, 1));
  PetscCall(CheckJoint(a, "contact law, back out of contact", 2, 20, 21, ex, ey, Fc * lambda, 0, Fc * lambda / k, 0, BOLTNET_STATE_OPEN));
  PetscCall(BoltnetAssemblyDestroy(&a));
  PetscFunctionReturn(0);
}

static PetscErrorCode Run(void)
{
  PetscFunctionBeginUser;
  PetscCall(BoltnetInitializePackage());
  PetscCall(BoltnetInitializePackage()); /* idempotent */
  PetscCall(TestFriction());
  PetscCall(TestSpringAndContact());
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "test_api: PASS\n"));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  PetscErrorCode ierr;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  ierr = Run(); /* a failed check has printed its message; finalize so that mpiexec sees exit code 1 */
  PetscCall(PetscFinalize());
  return ierr ? 1 : 0;
}
