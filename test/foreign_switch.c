static const char help[] = "foreign_switch: a PETSc program with a switching nonlinearity that gives the boltnet line search\n\
its states without linking boltnet (requirement: docs/petsc-plugin.md; a plugin user composes a state\n\
function or switch indicators on the SNES, and the line search uses them).\n\
\n\
Problem: a row of n blocks u_0 .. u_{n-1} joined to each other and to two walls by linear springs\n\
(stiffness -spring_k). Each block sits on a yielding support, elastic (stiffness -support_k) up to\n\
|u| = -support_yield and hardening (stiffness -support_kh) beyond, and above a floor at u = -floor_gap\n\
that pushes back with the penalty stiffness -floor_k once the block touches it. The residual is\n\
piecewise linear: its kinks are where a support yields (u = +-yield) or a block touches the floor.\n\
The loads are those whose exact solution is u*_i = load sin(3 pi (i+1)/(n+1)) (the residual is\n\
strongly monotone, so u* is the only solution); the start is -u*: every support yielded the other\n\
way. Full Newton steps (basic) chatter between states; see docs/petsc-plugin.md for the comparison.\n\
\n\
-state none|count|switches|setter: how the program gives the boltnet line search its states\n\
  count:    a state-change count composed on the SNES, \"SNESLineSearchBoltnetStateChange_C\"\n\
  switches: switch indicators composed on the SNES, \"SNESLineSearchBoltnetSwitches_C\" with the Vec\n\
            \"SNESLineSearchBoltnetSwitches\"\n\
  setter:   the count given to the line search's setter, \"SNESLineSearchBoltnetSetStateChangeFunction_C\"\n\
  (switches_no_layout: the switch function without its Vec, an error the line search names)\n\
Other line searches ignore both. Prints the SNES result, the error against u* and the number of\n\
blocks that changed state over the last 10 iterations; exits non-zero when SNES did not converge or u != u*.\n\
\n\
  mpiexec -n 2 build/bin/foreign_switch -dll_append build/lib/libboltnet_snes.so \\\n\
      -snes_linesearch_type boltnet -state switches -snes_view\n\
  mpiexec -n 1 build/bin/foreign_switch -snes_linesearch_type basic     (chatters)\n\n";

/* Built against PETSc only (no boltnet header, no boltnet library). */
#include <petscdmda.h>
#include <petscsnes.h>

typedef enum { STATE_NONE, STATE_COUNT, STATE_SWITCHES, STATE_SETTER, STATE_SWITCHES_NO_LAYOUT } StateMode;
static const char *const StateModes[] = {"none", "count", "switches", "setter", "switches_no_layout", "StateMode", "STATE_", NULL};

typedef struct {
  PetscInt  n;
  PetscReal spring_k, support_k, support_kh, yield, floor_gap, floor_k, load;
  Vec       f;         /* the load */
  PetscInt *history;   /* blocks that changed state at each iteration (rank 0), for the chatter report */
  PetscInt  nhistory;
  Vec       previous;  /* the previous iterate, for the monitor */
} AppCtx;

/* The support's force and tangent: elastic, then linear hardening. */
static PetscReal Support(const AppCtx *c, PetscReal u, PetscReal *k)
{
  if (PetscAbsReal(u) <= c->yield) {
    *k = c->support_k;
    return c->support_k * u;
  }
  *k = c->support_kh;
  return (u > 0 ? 1.0 : -1.0) * (c->support_k * c->yield + c->support_kh * (PetscAbsReal(u) - c->yield));
}

/* The floor's penalty force and tangent: zero above the floor, floor_k times the penetration below. */
static PetscReal Floor(const AppCtx *c, PetscReal u, PetscReal *k)
{
  if (u + c->floor_gap > 0) {
    *k = 0;
    return 0;
  }
  *k = c->floor_k;
  return c->floor_k * (u + c->floor_gap);
}

/* The switch indicators of block u: their signs are the block's state (docs/petsc-plugin.md). */
static void Indicators(const AppCtx *c, PetscReal u, PetscReal s[3])
{
  s[0] = u - c->yield;     /* > 0: yielded upwards */
  s[1] = u + c->yield;     /* <= 0: yielded downwards */
  s[2] = u + c->floor_gap; /* <= 0: on the floor */
}

static PetscInt StateCode(const AppCtx *c, PetscReal u)
{
  PetscReal s[3];
  Indicators(c, u, s);
  return (s[0] > 0) + 2 * (s[1] > 0) + 4 * (s[2] > 0);
}

/* F(u)_i = spring forces + support + floor - f_i, computed on the owned blocks from the ghosted u. */
static PetscErrorCode Residual(AppCtx *c, DM da, Vec U, Vec F, Vec f)
{
  Vec                Ul;
  const PetscScalar *u;
  PetscScalar       *r;
  PetscInt           xs, xm;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(da, &Ul));
  PetscCall(DMGlobalToLocal(da, U, INSERT_VALUES, Ul));
  PetscCall(DMDAVecGetArrayRead(da, Ul, &u));
  PetscCall(DMDAVecGetArray(da, F, &r));
  PetscCall(DMDAGetCorners(da, &xs, NULL, NULL, &xm, NULL, NULL));
  for (PetscInt i = xs; i < xs + xm; ++i) {
    const PetscReal ui = PetscRealPart(u[i]);
    const PetscReal ul = i > 0 ? PetscRealPart(u[i - 1]) : 0.0, ur = i < c->n - 1 ? PetscRealPart(u[i + 1]) : 0.0;
    PetscReal       k;
    r[i] = c->spring_k * (2 * ui - ul - ur) + Support(c, ui, &k) + Floor(c, ui, &k);
  }
  PetscCall(DMDAVecRestoreArray(da, F, &r));
  PetscCall(DMDAVecRestoreArrayRead(da, Ul, &u));
  PetscCall(DMRestoreLocalVector(da, &Ul));
  if (f) PetscCall(VecAXPY(F, -1.0, f));
  PetscFunctionReturn(0);
}

static PetscErrorCode FormFunction(SNES snes, Vec U, Vec F, void *ptr)
{
  DM da;
  PetscFunctionBeginUser;
  PetscCall(SNESGetDM(snes, &da));
  PetscCall(Residual((AppCtx *)ptr, da, U, F, ((AppCtx *)ptr)->f));
  PetscFunctionReturn(0);
}

static PetscErrorCode FormJacobian(SNES snes, Vec U, Mat J, Mat B, void *ptr)
{
  AppCtx            *c = (AppCtx *)ptr;
  DM                 da;
  const PetscScalar *u;
  PetscInt           xs, xm;
  PetscFunctionBeginUser;
  PetscCall(SNESGetDM(snes, &da));
  PetscCall(DMDAGetCorners(da, &xs, NULL, NULL, &xm, NULL, NULL));
  PetscCall(VecGetArrayRead(U, &u));
  for (PetscInt i = xs; i < xs + xm; ++i) {
    PetscReal         ks, kf;
    MatStencil        row = {0}, col[3] = {{0}};
    PetscScalar       v[3];
    PetscInt          nc = 0;
    (void)Support(c, PetscRealPart(u[i - xs]), &ks);
    (void)Floor(c, PetscRealPart(u[i - xs]), &kf);
    row.i = i;
    if (i > 0) {
      col[nc].i = i - 1;
      v[nc++]   = -c->spring_k;
    }
    col[nc].i = i;
    v[nc++]   = 2 * c->spring_k + ks + kf;
    if (i < c->n - 1) {
      col[nc].i = i + 1;
      v[nc++]   = -c->spring_k;
    }
    PetscCall(MatSetValuesStencil(B, 1, &row, nc, col, v, INSERT_VALUES));
  }
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscCall(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
  if (J != B) {
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(0);
}

/* Blocks whose state differs between A and B, summed over ranks. */
static PetscErrorCode CountDifferent(AppCtx *c, Vec A, Vec B, PetscInt *n)
{
  const PetscScalar *a, *b;
  PetscInt           m, local = 0;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(A, &m));
  PetscCall(VecGetArrayRead(A, &a));
  PetscCall(VecGetArrayRead(B, &b));
  for (PetscInt i = 0; i < m; ++i) local += StateCode(c, PetscRealPart(a[i])) != StateCode(c, PetscRealPart(b[i]));
  PetscCall(VecRestoreArrayRead(A, &a));
  PetscCall(VecRestoreArrayRead(B, &b));
  PetscCall(MPIU_Allreduce(&local, n, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)A)));
  PetscFunctionReturn(0);
}

/* -state count: the line search's state-change function, composed on the SNES. Its context is the
   SNES's application context. */
static PetscErrorCode StateChange(SNES snes, Vec ref, Vec x, PetscInt *nchanged, void *ctx)
{
  PetscFunctionBeginUser;
  PetscCall(CountDifferent((AppCtx *)ctx, ref, x, nchanged));
  PetscFunctionReturn(0);
}

/* -state switches: three indicators per owned block, in the layout of the composed Vec. */
static PetscErrorCode Switches(SNES snes, Vec x, Vec s, void *ctx)
{
  AppCtx            *c = (AppCtx *)ctx;
  const PetscScalar *u;
  PetscScalar       *v;
  PetscInt           m;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &m));
  PetscCall(VecGetArrayRead(x, &u));
  PetscCall(VecGetArray(s, &v));
  for (PetscInt i = 0; i < m; ++i) {
    PetscReal ind[3];
    Indicators(c, PetscRealPart(u[i]), ind);
    for (PetscInt k = 0; k < 3; ++k) v[3 * i + k] = ind[k];
  }
  PetscCall(VecRestoreArray(s, &v));
  PetscCall(VecRestoreArrayRead(x, &u));
  PetscFunctionReturn(0);
}

/* Records how many blocks changed state at each iteration (whatever the line search). */
static PetscErrorCode MonitorStates(SNES snes, PetscInt it, PetscReal fnorm, void *ptr)
{
  AppCtx *c = (AppCtx *)ptr;
  Vec     X;
  PetscFunctionBeginUser;
  PetscCall(SNESGetSolution(snes, &X));
  if (it > 0) PetscCall(CountDifferent(c, c->previous, X, &c->history[c->nhistory++]));
  PetscCall(VecCopy(X, c->previous));
  PetscFunctionReturn(0);
}

static PetscErrorCode Run(void)
{
  AppCtx              c;
  DM                  da;
  SNES                snes;
  SNESLineSearch      ls;
  SNESLineSearchType  lstype;
  SNESConvergedReason reason;
  StateMode           mode = STATE_NONE;
  Vec                 U, Uexact, S = NULL;
  PetscInt            its, nfuncs, maxit = 100, xs, xm, last = 0;
  PetscReal           tol = 1e-8, err, ref;
  PetscMPIInt         size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  c.n          = 64;
  c.spring_k   = 1;
  c.support_k  = 10;
  c.support_kh = 0.1;
  c.yield      = 1;
  c.floor_gap  = 2;
  c.floor_k    = 100;
  c.load       = 2;
  PetscOptionsBegin(PETSC_COMM_WORLD, NULL, "foreign_switch options", "");
  PetscCall(PetscOptionsInt("-n", "Number of blocks (unknowns)", "", c.n, &c.n, NULL));
  PetscCall(PetscOptionsReal("-spring_k", "Stiffness of the springs between the blocks and to the walls", "", c.spring_k, &c.spring_k, NULL));
  PetscCall(PetscOptionsReal("-support_k", "Elastic stiffness of each block's support", "", c.support_k, &c.support_k, NULL));
  PetscCall(PetscOptionsReal("-support_kh", "Hardening stiffness of a support once it has yielded", "", c.support_kh, &c.support_kh, NULL));
  PetscCall(PetscOptionsReal("-support_yield", "Displacement at which a support yields", "", c.yield, &c.yield, NULL));
  PetscCall(PetscOptionsReal("-floor_gap", "Distance from the blocks' rest position down to the floor", "", c.floor_gap, &c.floor_gap, NULL));
  PetscCall(PetscOptionsReal("-floor_k", "Penalty stiffness of the floor", "", c.floor_k, &c.floor_k, NULL));
  PetscCall(PetscOptionsReal("-load", "Amplitude of the exact solution u* (the loads are made from it)", "", c.load, &c.load, NULL));
  PetscCall(PetscOptionsEnum("-state", "What the program composes on its SNES for the boltnet line search", "", StateModes, (PetscEnum)mode, (PetscEnum *)&mode, NULL));
  PetscCall(PetscOptionsReal("-tol", "Relative tolerance of the comparison with the exact solution (max norm)", "", tol, &tol, NULL));
  PetscOptionsEnd();
  PetscCheck(c.n >= size, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-n %" PetscInt_FMT " must be >= the number of ranks %d", c.n, (int)size);
  PetscCheck(c.spring_k >= 0 && c.support_k > 0 && c.support_kh > 0 && c.floor_k >= 0, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-spring_k, -floor_k must be >= 0 and -support_k, -support_kh > 0");
  PetscCheck(c.yield > 0 && c.floor_gap > 0, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-support_yield and -floor_gap must be > 0");

  PetscCall(DMDACreate1d(PETSC_COMM_WORLD, DM_BOUNDARY_NONE, c.n, 1, 1, NULL, &da));
  PetscCall(DMSetFromOptions(da));
  PetscCall(DMSetUp(da));
  PetscCall(DMCreateGlobalVector(da, &U));
  PetscCall(VecDuplicate(U, &Uexact));
  PetscCall(VecDuplicate(U, &c.f));
  PetscCall(VecDuplicate(U, &c.previous));
  PetscCall(DMDAGetCorners(da, &xs, NULL, NULL, &xm, NULL, NULL));
  for (PetscInt i = xs; i < xs + xm; ++i) PetscCall(VecSetValue(Uexact, i, c.load * PetscSinReal(3 * PETSC_PI * (i + 1) / (c.n + 1)), INSERT_VALUES));
  PetscCall(VecAssemblyBegin(Uexact));
  PetscCall(VecAssemblyEnd(Uexact));
  PetscCall(Residual(&c, da, Uexact, c.f, NULL)); /* the loads that u* balances */
  PetscCall(VecAXPBY(U, -1.0, 0.0, Uexact));       /* the start: -u* */

  PetscCall(SNESCreate(PETSC_COMM_WORLD, &snes));
  PetscCall(SNESSetDM(snes, da));
  PetscCall(SNESSetType(snes, SNESNEWTONLS));
  PetscCall(SNESSetFunction(snes, NULL, FormFunction, &c));
  PetscCall(SNESSetJacobian(snes, NULL, NULL, FormJacobian, &c));
  PetscCall(SNESSetTolerances(snes, 1e-50, 1e-12, 0.0, maxit, PETSC_DEFAULT));
  PetscCall(SNESSetApplicationContext(snes, &c)); /* the ctx the composed functions receive */
  { /* Exact Newton directions on any number of ranks (LU of the gathered matrix), so that the line
       searches are compared, not linear solvers, and the iterations do not depend on the ranks. */
    KSP ksp;
    PC  pc;
    PetscCall(SNESGetKSP(snes, &ksp));
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCSetType(pc, PCREDUNDANT));
  }
  PetscCall(SNESSetFromOptions(snes));
  PetscCall(SNESGetTolerances(snes, NULL, NULL, NULL, &maxit, NULL));
  PetscCall(PetscCalloc1(maxit + 1, &c.history));
  c.nhistory = 0;
  PetscCall(SNESMonitorSet(snes, MonitorStates, &c, NULL));

  /* The interface: names, not symbols. Composing them costs nothing when the line search is another. */
  if (mode == STATE_COUNT) PetscCall(PetscObjectComposeFunction((PetscObject)snes, "SNESLineSearchBoltnetStateChange_C", StateChange));
  if (mode == STATE_SWITCHES || mode == STATE_SWITCHES_NO_LAYOUT) {
    PetscCall(PetscObjectComposeFunction((PetscObject)snes, "SNESLineSearchBoltnetSwitches_C", Switches));
    if (mode == STATE_SWITCHES) {
      PetscCall(VecCreateMPI(PETSC_COMM_WORLD, 3 * xm, PETSC_DETERMINE, &S));
      PetscCall(PetscObjectCompose((PetscObject)snes, "SNESLineSearchBoltnetSwitches", (PetscObject)S));
      PetscCall(VecDestroy(&S)); /* the SNES holds a reference */
    }
  }
  if (mode == STATE_SETTER) { /* the line search's own setter, found by name once the line search has its type */
    PetscErrorCode (*set)(SNESLineSearch, PetscErrorCode (*)(SNES, Vec, Vec, PetscInt *, void *), void *) = NULL;
    PetscCall(SNESGetLineSearch(snes, &ls));
    PetscCall(PetscObjectQueryFunction((PetscObject)ls, "SNESLineSearchBoltnetSetStateChangeFunction_C", &set));
    if (set) PetscCall((*set)(ls, StateChange, &c)); /* NULL: another line search */
  }

  PetscCall(SNESSolve(snes, NULL, U));
  PetscCall(SNESGetConvergedReason(snes, &reason));
  PetscCall(SNESGetIterationNumber(snes, &its));
  PetscCall(SNESGetNumberFunctionEvals(snes, &nfuncs));
  PetscCall(SNESGetLineSearch(snes, &ls));
  PetscCall(SNESLineSearchGetType(ls, &lstype));
  for (PetscInt k = PetscMax(0, c.nhistory - 10); k < c.nhistory; ++k) last += c.history[k];
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "foreign_switch: %" PetscInt_FMT " blocks on %d ranks, load %g, line search type %s, state %s\n", c.n, (int)size, (double)c.load, lstype, StateModes[mode]));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "foreign_switch: SNES %s after %" PetscInt_FMT " Newton iterations, %" PetscInt_FMT " function evaluations\n", SNESConvergedReasons[reason], its, nfuncs));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "foreign_switch: blocks that changed state over the last %" PetscInt_FMT " iterations: %" PetscInt_FMT "\n", PetscMin(10, c.nhistory), last));
  PetscCall(VecNorm(Uexact, NORM_INFINITY, &ref));
  PetscCall(VecAXPY(U, -1.0, Uexact));
  PetscCall(VecNorm(U, NORM_INFINITY, &err));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "foreign_switch: |u - u*|_inf / |u*|_inf = %.3g (tolerance %g)\n", (double)(err / ref), (double)tol));

  PetscCall(PetscFree(c.history));
  PetscCall(VecDestroy(&c.previous));
  PetscCall(VecDestroy(&c.f));
  PetscCall(VecDestroy(&U));
  PetscCall(VecDestroy(&Uexact));
  PetscCall(SNESDestroy(&snes));
  PetscCall(DMDestroy(&da));

  /* The requirement: Newton converged, and to u*. Every rank checks the same global values. */
  PetscCheck(reason > 0, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "SNES did not converge: %s after %" PetscInt_FMT " iterations", SNESConvergedReasons[reason], its);
  PetscCheck(err <= tol * ref, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "Wrong solution: |u - u*|_inf = %g > %g |u*|_inf", (double)err, (double)tol);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "foreign_switch: PASS\n"));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  PetscErrorCode ierr;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  ierr = Run(); /* an error has printed its traceback; finalize anyway so that mpiexec sees a clean exit code */
  PetscCall(PetscFinalize());
  return ierr ? 1 : 0;
}
