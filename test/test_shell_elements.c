/* A mixed shell mesh through the public API only: BoltnetAssemblyAddShellPatchElements.

   Requirement: a caller gives a shell patch of triangles and quadrilaterals (four entries per
   element, -1 as the fourth of a triangle) and gets the same closed form as for quadrilaterals
   (test_shell_network.c): an aluminium strip (E = 72000 MPa, nu = 0, t = 1.27 mm, w = 20 mm,
   L = 150 mm) clamped at x = 0, meshed in 12 x 4 cells, quadrilaterals and triangle pairs like a
   checkerboard, carries at x = L a spring joint (kt along x) to a rigid patch pulled by F along x.
   The joint's footprint (radius w/2) is the end edge, eliminated exactly (the default coupling), so
   the rigid patch moves by u = F L / (E w t) + F / kt (uniform tension, reproduced exactly by both
   element kinds); the tolerance, 1e-9 relative, is the solve's round-off.
   Bad element arrays are refused with a message naming the patch and the element. The test runs at
   1, 2 and 3 ranks. */
#include <boltnet.h>
#include <math.h>
#include <string.h>

/* Expect call to fail with PETSC_ERR_USER_INPUT and a message containing want. */
#define EXPECT_INPUT_ERROR(call, want) \
  do { \
    PetscErrorCode e_; \
    const char    *text_; \
    char          *msg_ = NULL; \
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL)); \
    e_ = (call); \
    PetscCall(PetscPopErrorHandler()); \
    PetscCall(PetscErrorMessage(e_, &text_, &msg_)); \
    PetscCheck(e_ == PETSC_ERR_USER_INPUT && msg_ && strstr(msg_, want), PETSC_COMM_WORLD, PETSC_ERR_PLIB, "expected an input error '%s', got %d '%s'", want, (int)e_, msg_ ? msg_ : "(none)"); \
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "refused: %s\n", msg_)); \
  } while (0)

int main(int argc, char **argv)
{
  const PetscReal    E = 72000, t = 1.27, w = 20, L = 150, kt = 5000, F = 1000;
  enum { nx = 12, ny = 4 };
  BoltnetAssembly    a;
  BoltnetJointParams p;
  PetscReal          xyz[3 * (nx + 1) * (ny + 1)], u[6];
  PetscInt           elems[4 * 2 * nx * ny], xmin[ny + 1], ne = 0, ntri = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, "A mixed shell mesh through the public API against the closed form of a strip in tension\n"));
  for (PetscInt j = 0; j <= ny; ++j)
    for (PetscInt i = 0; i <= nx; ++i) {
      xyz[3 * (j * (nx + 1) + i) + 0] = L * i / nx;
      xyz[3 * (j * (nx + 1) + i) + 1] = w * j / ny;
      xyz[3 * (j * (nx + 1) + i) + 2] = 0;
    }
  for (PetscInt j = 0; j < ny; ++j)
    for (PetscInt i = 0; i < nx; ++i) {
      const PetscInt n0 = j * (nx + 1) + i, n1 = n0 + 1, n2 = n1 + nx + 1, n3 = n0 + nx + 1;
      if ((i + j) % 2 == 0) { /* a quadrilateral */
        PetscInt *q = elems + 4 * ne++;
        q[0] = n0, q[1] = n1, q[2] = n2, q[3] = n3;
      } else { /* two triangles, counter-clockwise, -1 as the fourth entry */
        PetscInt *a0 = elems + 4 * ne++, *a1 = elems + 4 * ne++;
        a0[0] = n0, a0[1] = n1, a0[2] = n2, a0[3] = -1;
        a1[0] = n0, a1[1] = n2, a1[2] = n3, a1[3] = -1;
        ntri += 2;
      }
    }
  for (PetscInt j = 0; j <= ny; ++j) xmin[j] = j * (nx + 1);

  PetscCall(BoltnetAssemblyCreate(PETSC_COMM_WORLD, &a));
  {
    /* Bad arrays: -1 before the fourth entry, a triangle naming a node twice, a node out of range,
       a triangle given to the quadrilateral-only function. */
    const PetscInt bad1[8] = {0, 1, 14, 13, 0, -1, 14, -1}, bad2[4] = {0, 1, 1, -1}, bad3[4] = {0, 1, 99, -1}, bad4[4] = {0, 1, 14, -1};
    EXPECT_INPUT_ERROR(BoltnetAssemblyAddShellPatchElements(a, 1, (nx + 1) * (ny + 1), xyz, 2, bad1, E, 0.0, t), "Shell patch 1: element 1 names node -1, not in 0..64");
    EXPECT_INPUT_ERROR(BoltnetAssemblyAddShellPatchElements(a, 2, (nx + 1) * (ny + 1), xyz, 1, bad2, E, 0.0, t), "Shell patch 2: element 0 names node 1 twice");
    EXPECT_INPUT_ERROR(BoltnetAssemblyAddShellPatchElements(a, 3, (nx + 1) * (ny + 1), xyz, 1, bad3, E, 0.0, t), "Shell patch 3: element 0 names node 99, not in 0..64");
    EXPECT_INPUT_ERROR(BoltnetAssemblyAddShellPatch(a, 4, (nx + 1) * (ny + 1), xyz, 1, bad4, E, 0.0, t), "Shell patch 4: quadrangle 0 names node -1, not in 0..64");
  }
  PetscCall(BoltnetAssemblyAddShellPatchElements(a, 10, (nx + 1) * (ny + 1), xyz, ne, elems, E, 0.0, t));
  PetscCall(BoltnetAssemblyAddNodeSet(a, 10, "clamp", ny + 1, xmin));
  const PetscReal xr[3] = {L, w / 2, 0}, n[3] = {0, 0, 1}, t1[3] = {1, 0, 0};
  PetscCall(BoltnetAssemblyAddRigidPatch(a, 20, xr));
  PetscCall(BoltnetJointParamsSetDefault(BOLTNET_LAW_SPRING, &p));
  p.kn = 1e5, p.kt = kt, p.kr = 1e9;
  PetscCall(BoltnetAssemblyAddJointAt(a, 1, 10, 20, &p, n, t1, xr));
  PetscCall(BoltnetAssemblyAddBCOnSet(a, 10, "clamp", -1, BOLTNET_BC_FIXED, 0));
  PetscCall(BoltnetAssemblyAddBC(a, 20, 0, BOLTNET_BC_FORCE, F));
  for (PetscInt d = 1; d < 6; ++d) PetscCall(BoltnetAssemblyAddBC(a, 20, d, BOLTNET_BC_FIXED, 0));
  PetscCall(PetscOptionsSetValue(NULL, "-coupling_radius", "10"));
  PetscCall(BoltnetAssemblySetFromOptions(a));
  PetscCall(BoltnetAssemblySetUp(a));
  const PetscReal one = 1.0;
  PetscCall(BoltnetAssemblySolveLoadPath(a, 1, &one, 1));
  PetscCall(BoltnetAssemblyGetPatchDisplacement(a, 20, u));
  const PetscReal ref = F * L / (E * w * t) + F / kt;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%" PetscInt_FMT " elements (%" PetscInt_FMT " triangles): u_x = %.12g mm, closed form %.12g mm, relative error %.2e\n", ne, ntri, (double)u[0], (double)ref, (double)(fabs(u[0] - ref) / ref)));
  PetscCheck(fabs(u[0] - ref) <= 1e-9 * ref, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "mixed strip in tension: u_x %g, expected %g", (double)u[0], (double)ref);
  PetscCall(BoltnetAssemblyDestroy(&a));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "test_shell_elements: PASS\n"));
  PetscCall(PetscFinalize());
  return 0;
}
