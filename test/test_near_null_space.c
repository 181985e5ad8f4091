/* The Jacobian's near-null space (docs/solver.md, "Iterative solvers"), through the public API.

   Requirement: the uncondensed path hands GAMG and BoomerAMG block size 6 and the six rigid-body
   modes of its nodes (three translations; three rotations, u = theta x (x - c) with the rotation
   dof set to theta) as the near-null space of the Jacobian. The independent reference is
   mechanics: a rigid motion of a structure with no support strains nothing, so the unconstrained
   stiffness K maps each mode z to zero up to round-off, ||K z|| <= tol ||K|| ||z|| (inf-norms).
   K here is the Jacobian at X = 0 of a curved (cylindrical) shell panel of quadrilaterals and a
   flat plate of triangles, joined by two fasteners (a spring and a frictional joint, through exact
   footprint coupling), and a rigid patch joined to the panel off its reference point (so that the
   lever arm of the joint on it counts). The model must be supported, so the rigid patch is fixed:
   its six rows are then identity rows (MatZeroRows), which are no stiffness and are left out; every
   other row, shell and joint terms included, is the unconstrained stiffness. Modes built from wrong
   coordinates, a wrong sign of a rotation or a dof out of place give ||K z|| of the order of
   ||K|| ||z|| instead.
   Also checked: the six vectors are orthonormal (MatNullSpaceCreate needs it), the block size is
   6, and -interface_near_null_space false attaches none. Run at 1, 2 and 3 ranks (the patches then
   sit on different ranks and are cut into patches joined by seams), kept whole and condensed. */
#include <boltnet.h>
#include <math.h>

#define NX 8
#define NY 6

/* Zero the entries of v at the rows of J that are identity rows (a fixed dof); *n: their count. */
static PetscErrorCode ZeroFixedRows(Mat J, Vec v, PetscInt *n)
{
  PetscInt     rstart, rend, mine = 0;
  PetscScalar *x;
  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(J, &rstart, &rend));
  PetscCall(VecGetArray(v, &x));
  for (PetscInt i = rstart; i < rend; ++i) {
    PetscInt           ncols;
    const PetscInt    *cols;
    const PetscScalar *vals;
    PetscBool          identity = PETSC_TRUE;
    PetscCall(MatGetRow(J, i, &ncols, &cols, &vals));
    for (PetscInt k = 0; k < ncols; ++k)
      if (vals[k] != (cols[k] == i ? 1.0 : 0.0)) identity = PETSC_FALSE;
    PetscCall(MatRestoreRow(J, i, &ncols, &cols, &vals));
    if (identity) x[i - rstart] = 0, ++mine;
  }
  PetscCall(VecRestoreArray(v, &x));
  PetscCallMPI(MPI_Allreduce(&mine, n, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)J)));
  PetscFunctionReturn(0);
}

static PetscErrorCode AddPanel(BoltnetAssembly a)
{
  /* A 60 x 48 mm panel curved about x (radius 80 mm), quadrilaterals. */
  PetscReal xyz[3 * (NX + 1) * (NY + 1)];
  PetscInt  quads[4 * NX * NY];
  PetscFunctionBeginUser;
  for (PetscInt j = 0; j <= NY; ++j)
    for (PetscInt i = 0; i <= NX; ++i) {
      const PetscReal phi = (48.0 * j / NY - 24.0) / 80.0;
      xyz[3 * (j * (NX + 1) + i) + 0] = 60.0 * i / NX;
      xyz[3 * (j * (NX + 1) + i) + 1] = 80.0 * sin(phi);
      xyz[3 * (j * (NX + 1) + i) + 2] = 80.0 * (cos(phi) - 1.0);
    }
  for (PetscInt j = 0; j < NY; ++j)
    for (PetscInt i = 0; i < NX; ++i) {
      PetscInt *q = quads + 4 * (j * NX + i);
      q[0] = j * (NX + 1) + i, q[1] = q[0] + 1, q[2] = q[1] + NX + 1, q[3] = q[0] + NX + 1;
    }
  PetscCall(BoltnetAssemblyAddShellPatch(a, 1, (NX + 1) * (NY + 1), xyz, NX * NY, quads, 72000, 0.33, 2.0));
  PetscFunctionReturn(0);
}

static PetscErrorCode AddPlate(BoltnetAssembly a)
{
  /* A flat 40 x 48 mm plate of triangles at z = 2, overlapping the panel's end x in [48, 60]. */
  PetscReal xyz[3 * (NX + 1) * (NY + 1)];
  PetscInt  tris[2 * 4 * NX * NY];
  PetscFunctionBeginUser;
  for (PetscInt j = 0; j <= NY; ++j)
    for (PetscInt i = 0; i <= NX; ++i) {
      xyz[3 * (j * (NX + 1) + i) + 0] = 48.0 + 40.0 * i / NX;
      xyz[3 * (j * (NX + 1) + i) + 1] = 48.0 * j / NY - 24.0;
      xyz[3 * (j * (NX + 1) + i) + 2] = 2.0;
    }
  for (PetscInt j = 0; j < NY; ++j)
    for (PetscInt i = 0; i < NX; ++i) {
      const PetscInt n0 = j * (NX + 1) + i, n1 = n0 + 1, n2 = n1 + NX + 1, n3 = n0 + NX + 1;
      PetscInt      *t  = tris + 8 * (j * NX + i);
      t[0] = n0, t[1] = n1, t[2] = n2, t[3] = -1;
      t[4] = n0, t[5] = n2, t[6] = n3, t[7] = -1;
    }
  PetscCall(BoltnetAssemblyAddShellPatchElements(a, 2, (NX + 1) * (NY + 1), xyz, 2 * NX * NY, tris, 72000, 0.33, 2.0));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  BoltnetAssembly    a;
  BoltnetJointParams spring, friction;
  SNES               snes;
  DM                 dm;
  Mat                J, P;
  Vec                X, Kz;
  MatNullSpace       nsp;
  PetscBool          has_const, want = PETSC_TRUE;
  PetscInt           nvec, bs;
  const Vec         *z;
  PetscReal          Knorm, tol = 1e-11;

  PetscCall(PetscInitialize(&argc, &argv, NULL, "The near-null space of the Jacobian against the kernel of the unconstrained stiffness\n"));
  PetscOptionsBegin(PETSC_COMM_WORLD, NULL, "test_near_null_space", NULL);
  PetscCall(PetscOptionsReal("-test_tol", "Largest ||K z|| / (||K|| ||z||) accepted", NULL, tol, &tol, NULL));
  PetscOptionsEnd();
  PetscCall(BoltnetAssemblyCreate(PETSC_COMM_WORLD, &a));
  PetscCall(AddPanel(a));
  PetscCall(AddPlate(a));
  const PetscReal xr[3] = {0, 0, 10}, xj[3] = {6, 3, 5}, n[3] = {0, 0, 1}, t1[3] = {1, 0, 0};
  PetscCall(BoltnetAssemblyAddRigidPatch(a, 3, xr));
  PetscCall(BoltnetJointParamsSetDefault(BOLTNET_LAW_SPRING, &spring));
  PetscCall(BoltnetJointParamsSetDefault(BOLTNET_LAW_FRICTION, &friction));
  spring.kn = 2e5, spring.kt = 1.5e5, spring.kr = 1e9;
  friction.kn = 2e5, friction.kt = 1.5e5, friction.kr = 1e9, friction.kc = 4e4, friction.kg = 2000, friction.gap = 0.05, friction.mu = 0.3, friction.nf = 1, friction.pretension = 3000;
  const PetscReal f1[3] = {54, -12, 1}, f2[3] = {54, 12, 1};
  PetscCall(BoltnetAssemblyAddJointAt(a, 10, 1, 2, &spring, n, t1, f1));
  PetscCall(BoltnetAssemblyAddJointAt(a, 11, 1, 2, &friction, n, t1, f2));
  PetscCall(BoltnetAssemblyAddJointAt(a, 12, 1, 3, &spring, n, t1, xj));
  PetscCall(BoltnetAssemblyAddBC(a, 3, -1, BOLTNET_BC_FIXED, 0));
  PetscCall(BoltnetAssemblySetFromOptions(a));
  PetscCall(BoltnetAssemblySetUp(a));
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-interface_near_null_space", &want, NULL));

  PetscCall(BoltnetAssemblyGetSNES(a, &snes));
  PetscCall(BoltnetAssemblyGetDM(a, &dm));
  PetscCall(SNESSetUp(snes));
  PetscCall(SNESGetJacobian(snes, &J, &P, NULL, NULL));
  PetscCall(DMCreateGlobalVector(dm, &X));
  PetscCall(VecDuplicate(X, &Kz));
  PetscCall(VecSet(X, 0.0));
  PetscCall(SNESComputeJacobian(snes, X, J, P));
  PetscCall(MatGetBlockSize(J, &bs));
  PetscCheck(bs == 6, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "Jacobian block size %" PetscInt_FMT ", expected 6", bs);
  PetscCall(MatGetNearNullSpace(J, &nsp));
  if (!want) {
    PetscCheck(!nsp, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "-interface_near_null_space false, yet a near-null space is attached");
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "no near-null space attached, as asked\n"));
  } else {
    PetscCheck(nsp, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "no near-null space attached to the Jacobian");
    PetscCall(MatNullSpaceGetVecs(nsp, &has_const, &nvec, &z));
    PetscCheck(nvec == 6 && !has_const, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "near-null space of %" PetscInt_FMT " vectors (constant: %d), expected the 6 rigid-body modes", nvec, (int)has_const);
    PetscCall(MatNorm(J, NORM_INFINITY, &Knorm));
    PetscReal worst = 0;
    for (PetscInt i = 0; i < nvec; ++i) {
      PetscReal zn, kn;
      for (PetscInt j = 0; j <= i; ++j) {
        PetscScalar d;
        PetscCall(VecDot(z[i], z[j], &d));
        PetscCheck(PetscAbsScalar(d - (i == j ? 1.0 : 0.0)) < 1e-12, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "near-null vectors %" PetscInt_FMT ", %" PetscInt_FMT " not orthonormal: dot %g", i, j, (double)PetscRealPart(d));
      }
      PetscInt nfixed;
      PetscCall(MatMult(J, z[i], Kz));
      PetscCall(ZeroFixedRows(J, Kz, &nfixed));
      PetscCheck(nfixed == 6, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "%" PetscInt_FMT " identity rows, expected the 6 of the fixed rigid patch", nfixed);
      PetscCall(VecNorm(z[i], NORM_INFINITY, &zn));
      PetscCall(VecNorm(Kz, NORM_INFINITY, &kn));
      const PetscReal r = kn / (Knorm * zn);
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "mode %" PetscInt_FMT ": ||K z|| / (||K|| ||z||) = %.2e\n", i, (double)r));
      worst = PetscMax(worst, r);
      /* The same vector with its rotation dof negated is no rigid motion: the check must see it (the
         translations, 0 to 2, have no rotation dof to negate). */
      {
        Vec          w;
        PetscScalar *x;
        PetscInt     lo, hi;
        PetscReal    wn, kw;
        PetscCall(VecDuplicate(z[i], &w));
        PetscCall(VecCopy(z[i], w));
        PetscCall(VecGetOwnershipRange(w, &lo, &hi));
        PetscCall(VecGetArray(w, &x));
        for (PetscInt k = lo; k < hi; ++k)
          if (k % 6 >= 3) x[k - lo] = -x[k - lo];
        PetscCall(VecRestoreArray(w, &x));
        PetscCall(MatMult(J, w, Kz));
        PetscCall(ZeroFixedRows(J, Kz, &nfixed));
        PetscCall(VecNorm(w, NORM_INFINITY, &wn));
        PetscCall(VecNorm(Kz, NORM_INFINITY, &kw));
        PetscCall(PetscPrintf(PETSC_COMM_WORLD, "   control (rotations negated): %.2e\n", (double)(kw / (Knorm * wn))));
        PetscCheck(i < 3 || kw / (Knorm * wn) > 1e5 * tol, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "the check cannot tell mode %" PetscInt_FMT " with its rotations negated from a rigid motion", i);
        PetscCall(VecDestroy(&w));
      }
    }
    PetscCheck(worst <= tol, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "a near-null vector is not a rigid-body mode: ||K z|| / (||K|| ||z||) = %g > %g", (double)worst, (double)tol);
  }
  PetscCall(VecDestroy(&Kz));
  PetscCall(VecDestroy(&X));
  PetscCall(BoltnetAssemblyDestroy(&a));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "test_near_null_space: PASS\n"));
  PetscCall(PetscFinalize());
  return 0;
}
