static const char help[] = "foreign_snes: a PETSc program that knows nothing of boltnet, used to load the boltnet line search\n\
as a plugin (requirement: any PETSc code gets -snes_linesearch_type boltnet through -dll_append alone).\n\
\n\
Problem: a chain of n nonlinear springs along a line. Node -1 is a wall (x = 0); spring i joins\n\
node i-1 to node i and carries the force s_i = k_i atan(d_i), d_i = x_i - x_{i-1}. Node i carries\n\
the load P_i = s*_i - s*_{i+1} (s*_n = 0), built from a chosen exact elongation d*_i, so that the\n\
exact solution is x*_i = d*_0 + ... + d*_i. The start x0 gives every spring the elongation +-3:\n\
full Newton steps on atan from there overshoot and diverge; a line search has to cut them.\n\
The solution is compared with x* (relative tolerance -tol, default 1e-8, in the max norm).\n\
Prints the line search type that was used; exits non-zero when SNES did not converge or x != x*.\n\
\n\
  mpiexec -n 2 build/bin/foreign_snes -dll_append build/lib/libboltnet_snes.so \\\n\
      -snes_linesearch_type boltnet -snes_linesearch_view -options_left\n\
  mpiexec -n 1 build/bin/foreign_snes -snes_linesearch_type bt -snes_monitor\n\
  mpiexec -n 1 build/bin/foreign_snes -snes_linesearch_type basic      (full steps: diverges)\n\n";

/* Built against PETSc only (no boltnet header, no boltnet library). */
#include <petscsnes.h>

typedef struct {
  PetscInt   n;       /* number of springs = number of unknowns */
  PetscReal *k;       /* stiffness of every spring (replicated: n is small) */
  PetscReal *P;       /* load on every node */
  VecScatter scatter; /* global vector -> x_{rstart-1} .. x_{rend-1} on this rank */
  Vec        xloc;    /* the owned values plus the left neighbour (if any) */
  PetscInt   rstart, rend, lo;
} AppCtx;

static PetscReal Stiffness(PetscInt i) { return 1.0 + (PetscReal)(i % 3); }
/* Exact elongations: mixed signs, |d*| <= 0.6, never 0. */
static PetscReal ExactElongation(PetscInt i) { return 0.6 * PetscSinReal(0.7 * (PetscReal)i + 0.4); }
/* Starting elongations: far out on the flat part of atan. */
static PetscReal StartElongation(PetscInt i) { return (i % 2) ? -3.0 : 3.0; }

/* Gather x_{lo} .. x_{rend-1} (lo = max(rstart-1, 0)) into ctx->xloc. */
static PetscErrorCode GatherLocal(AppCtx *ctx, Vec X)
{
  PetscFunctionBeginUser;
  PetscCall(VecScatterBegin(ctx->scatter, X, ctx->xloc, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(ctx->scatter, X, ctx->xloc, INSERT_VALUES, SCATTER_FORWARD));
  PetscFunctionReturn(0);
}

/* Elongation of spring i from the gathered values; xl[i - lo] is x_i, and x_{-1} = 0. */
static PetscReal Elongation(const AppCtx *ctx, const PetscScalar *xl, PetscInt i)
{
  const PetscReal xi  = PetscRealPart(xl[i - ctx->lo]);
  const PetscReal xim = i > 0 ? PetscRealPart(xl[i - 1 - ctx->lo]) : 0.0;
  return xi - xim;
}

/* R_i = s_i - s_{i+1} - P_i. Each rank evaluates the springs ending at its nodes (spring i needs
   x_{i-1}, gathered) and adds s_i to row i and -s_i to row i-1, which may belong to the rank on
   the left (VecSetValues with ADD_VALUES). */
static PetscErrorCode FormFunction(SNES snes, Vec X, Vec F, void *ptr)
{
  AppCtx            *ctx = (AppCtx *)ptr;
  const PetscScalar *xl;
  PetscFunctionBeginUser;
  PetscCall(GatherLocal(ctx, X));
  PetscCall(VecSet(F, 0.0));
  PetscCall(VecGetArrayRead(ctx->xloc, &xl));
  for (PetscInt i = ctx->rstart; i < ctx->rend; ++i) {
    const PetscReal d = Elongation(ctx, xl, i);
    const PetscReal s = ctx->k[i] * PetscAtanReal(d);
    if (PetscIsInfOrNanReal(s)) { /* a non-finite trial point: let the line search cut the step */
      PetscCall(VecRestoreArrayRead(ctx->xloc, &xl));
      PetscCall(SNESSetFunctionDomainError(snes));
      PetscFunctionReturn(0);
    }
    PetscCall(VecSetValue(F, i, s - ctx->P[i], ADD_VALUES));
    if (i > 0) PetscCall(VecSetValue(F, i - 1, -s, ADD_VALUES));
  }
  PetscCall(VecRestoreArrayRead(ctx->xloc, &xl));
  PetscCall(VecAssemblyBegin(F));
  PetscCall(VecAssemblyEnd(F));
  PetscFunctionReturn(0);
}

static PetscErrorCode FormJacobian(SNES snes, Vec X, Mat J, Mat B, void *ptr)
{
  AppCtx            *ctx = (AppCtx *)ptr;
  const PetscScalar *xl;
  PetscFunctionBeginUser;
  PetscCall(GatherLocal(ctx, X));
  PetscCall(MatZeroEntries(B));
  PetscCall(VecGetArrayRead(ctx->xloc, &xl));
  for (PetscInt i = ctx->rstart; i < ctx->rend; ++i) {
    const PetscReal d = Elongation(ctx, xl, i);
    const PetscReal c = ctx->k[i] / (1.0 + d * d); /* ds_i/dd_i */
    if (i > 0) {                                    /* spring between i-1 and i */
      const PetscInt    idx[2] = {i - 1, i};
      const PetscScalar v[4]   = {c, -c, -c, c};
      PetscCall(MatSetValues(B, 2, idx, 2, idx, v, ADD_VALUES));
    } else PetscCall(MatSetValue(B, i, i, c, ADD_VALUES)); /* spring to the wall */
  }
  PetscCall(VecRestoreArrayRead(ctx->xloc, &xl));
  PetscCall(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
  if (J != B) {
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode Run(void)
{
  AppCtx              ctx;
  SNES                snes;
  SNESLineSearch      ls;
  SNESLineSearchType  lstype;
  SNESConvergedReason reason;
  Vec                 X, Xexact;
  Mat                 J;
  IS                  from;
  PetscInt            its, nloc;
  PetscReal           tol = 1e-8, err, ref;
  PetscMPIInt         size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  ctx.n = 16;
  PetscOptionsBegin(PETSC_COMM_WORLD, NULL, "foreign_snes options", "");
  PetscCall(PetscOptionsInt("-n", "Number of springs (unknowns)", "", ctx.n, &ctx.n, NULL));
  PetscCall(PetscOptionsReal("-tol", "Relative tolerance of the comparison with the exact solution (max norm)", "", tol, &tol, NULL));
  PetscOptionsEnd();
  PetscCheck(ctx.n >= size, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-n %" PetscInt_FMT " must be >= the number of ranks %d", ctx.n, (int)size);

  /* Data, the exact solution and the start (replicated; the problem is small). */
  PetscCall(PetscMalloc2(ctx.n, &ctx.k, ctx.n, &ctx.P));
  for (PetscInt i = 0; i < ctx.n; ++i) ctx.k[i] = Stiffness(i);
  for (PetscInt i = 0; i < ctx.n; ++i) {
    const PetscReal s  = ctx.k[i] * PetscAtanReal(ExactElongation(i));
    const PetscReal sn = i + 1 < ctx.n ? ctx.k[i + 1] * PetscAtanReal(ExactElongation(i + 1)) : 0.0;
    ctx.P[i]           = s - sn;
  }

  PetscCall(VecCreateMPI(PETSC_COMM_WORLD, PETSC_DECIDE, ctx.n, &X));
  PetscCall(VecSetFromOptions(X));
  PetscCall(VecDuplicate(X, &Xexact));
  PetscCall(VecGetOwnershipRange(X, &ctx.rstart, &ctx.rend));
  {
    PetscReal xs = 0, x0 = 0;
    for (PetscInt i = 0; i < ctx.rend; ++i) {
      xs += ExactElongation(i);
      x0 += StartElongation(i);
      if (i >= ctx.rstart) {
        PetscCall(VecSetValue(Xexact, i, xs, INSERT_VALUES));
        PetscCall(VecSetValue(X, i, x0, INSERT_VALUES));
      }
    }
  }
  PetscCall(VecAssemblyBegin(Xexact));
  PetscCall(VecAssemblyEnd(Xexact));
  PetscCall(VecAssemblyBegin(X));
  PetscCall(VecAssemblyEnd(X));

  /* Scatter of x_{lo} .. x_{rend-1}: the owned values and the left neighbour. */
  ctx.lo = ctx.rstart > 0 ? ctx.rstart - 1 : 0;
  nloc   = ctx.rend - ctx.lo;
  PetscCall(ISCreateStride(PETSC_COMM_SELF, nloc, ctx.lo, 1, &from));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, nloc, &ctx.xloc));
  PetscCall(VecScatterCreate(X, from, ctx.xloc, NULL, &ctx.scatter));
  PetscCall(ISDestroy(&from));

  /* Tridiagonal Jacobian: at most 3 entries per row, 1 of them off the diagonal block. */
  PetscCall(MatCreateAIJ(PETSC_COMM_WORLD, ctx.rend - ctx.rstart, ctx.rend - ctx.rstart, ctx.n, ctx.n, 3, NULL, 1, NULL, &J));
  PetscCall(MatSetFromOptions(J));

  PetscCall(SNESCreate(PETSC_COMM_WORLD, &snes));
  PetscCall(SNESSetType(snes, SNESNEWTONLS));
  PetscCall(SNESSetFunction(snes, NULL, FormFunction, &ctx));
  PetscCall(SNESSetJacobian(snes, J, J, FormJacobian, &ctx));
  PetscCall(SNESSetTolerances(snes, 1e-50, 1e-13, 0.0, 100, PETSC_DEFAULT));
  PetscCall(SNESSetFromOptions(snes));
  PetscCall(SNESSolve(snes, NULL, X));

  PetscCall(SNESGetConvergedReason(snes, &reason));
  PetscCall(SNESGetIterationNumber(snes, &its));
  PetscCall(SNESGetLineSearch(snes, &ls));
  PetscCall(SNESLineSearchGetType(ls, &lstype));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "foreign_snes: %" PetscInt_FMT " springs on %d ranks, line search type %s\n", ctx.n, (int)size, lstype));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "foreign_snes: SNES %s after %" PetscInt_FMT " Newton iterations\n", SNESConvergedReasons[reason], its));
  PetscCall(VecNorm(Xexact, NORM_INFINITY, &ref));
  PetscCall(VecAXPY(X, -1.0, Xexact));
  PetscCall(VecNorm(X, NORM_INFINITY, &err));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "foreign_snes: |x - x*|_inf / |x*|_inf = %.3g (tolerance %g)\n", (double)(err / ref), (double)tol));

  PetscCall(VecScatterDestroy(&ctx.scatter));
  PetscCall(VecDestroy(&ctx.xloc));
  PetscCall(PetscFree2(ctx.k, ctx.P));
  PetscCall(VecDestroy(&X));
  PetscCall(VecDestroy(&Xexact));
  PetscCall(MatDestroy(&J));
  PetscCall(SNESDestroy(&snes));

  /* The requirement: Newton converged and to the exact solution. Checked on every rank (the values
     are global), so that every rank exits with the same code. */
  PetscCheck(reason > 0, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "SNES did not converge: %s after %" PetscInt_FMT " iterations", SNESConvergedReasons[reason], its);
  PetscCheck(err <= tol * ref, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "Wrong solution: |x - x*|_inf = %g > %g |x*|_inf", (double)err, (double)tol);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "foreign_snes: PASS\n"));
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
