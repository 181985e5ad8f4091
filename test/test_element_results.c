/* Element results through the public API against closed forms (docs/output.md, "Stresses and section
   forces"; checks the requirement that resultants and surface stresses are right, in both frames).

   A strip (E = 72000 MPa, nu = 0, t = 2 mm, w = 20 mm, L = 150 mm, 12 x 4 elements) clamped at x = 0
   carries at x = L a stiff joint to a rigid patch; the joint's footprint is the end edge, which it
   moves rigidly. With nu = 0 the strip has no Poisson or anticlastic effect, so the clamp and the
   rigid edge are exactly what these closed forms assume (beam theory is then exact for the strip):
     tension, P along x:          N_xx = P / w,  sigma_xx = P / (w t) on both faces, all else 0;
     pure bending, moment C about y: M_xx = C / w, sigma_xx = +-6 M_xx / t^2 (top +), all else 0;
     cantilever, P along z:       M_xx(x) = -P (L - x) / w (hogging: the shell's M = D kappa with
                                  kappa = d theta_y / dx), Q_xz = dM_xx/dx = P / w, at every centroid.
   Every other element numbers its nodes from its second corner, so that its element frame is turned
   by 90 degrees (x along global y): its element-frame N_yy is the global N_xx, while the material
   frame (x along global X projected, the default) is the global frame for every element.
   The linear solve is exact up to round-off: the tolerance is 1e-8 of each quantity's scale, far
   above the round-off of the stiff joint (1e6 N/mm against the strip's E w t / L = 19200 N/mm) and
   far below any modelling error. Runs at 1, 2 and 3 ranks: the strip is then cut into patches, and
   elements on the cut need nodes of the other patch. */
#include <boltnet.h>
#include <math.h>

#define NX 12
#define NY 4

static const PetscReal E = 72000, t = 2, w = 20, L = 150;

typedef enum { TENSION, BENDING, CANTILEVER } Case;

static PetscErrorCode Solve(Case c, PetscReal load, BoltnetAssembly *a)
{
  BoltnetJointParams p;
  PetscReal          xyz[3 * (NX + 1) * (NY + 1)];
  PetscInt           quads[4 * NX * NY], xmin[NY + 1];
  const PetscReal    xr[3] = {L, w / 2, 0}, n[3] = {0, 0, 1}, t1[3] = {1, 0, 0}, one = 1.0;

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j <= NY; ++j)
    for (PetscInt i = 0; i <= NX; ++i) {
      xyz[3 * (j * (NX + 1) + i) + 0] = L * i / NX;
      xyz[3 * (j * (NX + 1) + i) + 1] = w * j / NY;
      xyz[3 * (j * (NX + 1) + i) + 2] = 0;
    }
  for (PetscInt j = 0; j < NY; ++j)
    for (PetscInt i = 0; i < NX; ++i) {
      PetscInt *q = quads + 4 * (j * NX + i);
      const PetscInt c[4] = {j * (NX + 1) + i, j * (NX + 1) + i + 1, (j + 1) * (NX + 1) + i + 1, (j + 1) * (NX + 1) + i};
      const PetscInt s    = (i + j) % 2; /* turned elements: first node at the second corner */
      for (PetscInt k = 0; k < 4; ++k) q[k] = c[(k + s) % 4];
    }
  for (PetscInt j = 0; j <= NY; ++j) xmin[j] = j * (NX + 1);
  PetscCall(BoltnetAssemblyCreate(PETSC_COMM_WORLD, a));
  PetscCall(BoltnetAssemblyAddShellPatch(*a, 10, (NX + 1) * (NY + 1), xyz, NX * NY, quads, E, 0.0, t));
  PetscCall(BoltnetAssemblyAddNodeSet(*a, 10, "clamp", NY + 1, xmin));
  PetscCall(BoltnetAssemblyAddRigidPatch(*a, 20, xr));
  PetscCall(BoltnetJointParamsSetDefault(BOLTNET_LAW_SPRING, &p));
  p.kn = 1e6, p.kt = 1e6, p.kr = 1e9;
  PetscCall(BoltnetAssemblyAddJointAt(*a, 1, 10, 20, &p, n, t1, xr));
  PetscCall(BoltnetAssemblyAddBCOnSet(*a, 10, "clamp", -1, BOLTNET_BC_FIXED, 0));
  PetscCall(BoltnetAssemblyAddBC(*a, 20, c == TENSION ? 0 : c == BENDING ? 4 : 2, BOLTNET_BC_FORCE, load));
  PetscCall(PetscOptionsSetValue(NULL, "-coupling_radius", "10.01"));
  PetscCall(BoltnetAssemblySetFromOptions(*a));
  PetscCall(BoltnetAssemblySetUp(*a));
  PetscCall(BoltnetAssemblySolveLoadPath(*a, 1, &one, 1));
  PetscFunctionReturn(0);
}

/* |got - want| <= 1e-8 scale, else an error naming the case, element and component. */
static PetscErrorCode Expect(const char what[], PetscInt e, PetscReal got, PetscReal want, PetscReal scale, PetscReal *worst)
{
  PetscFunctionBeginUser;
  const PetscReal d = fabs(got - want) / scale;
  if (d > *worst) *worst = d;
  PetscCheck(d <= 1e-8, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "%s of element %" PetscInt_FMT ": %.12g, closed form %.12g", what, e, (double)got, (double)want);
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  BoltnetAssembly      a;
  BoltnetElementResult r;
  const PetscReal      P = 1000, C = 5000;
  PetscReal            worst = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, "Element resultants and stresses against closed forms\n"));
  /* Tension. */
  PetscCall(Solve(TENSION, P, &a));
  for (PetscInt e = 0; e < NX * NY; ++e) {
    const PetscReal N = P / w, s = P / (w * t);
    const PetscBool turned = ((e % NX) + (e / NX)) % 2 ? PETSC_TRUE : PETSC_FALSE;
    PetscCall(BoltnetAssemblyGetElementResult(a, 10, e, BOLTNET_FRAME_ELEMENT, &r));
    PetscCall(Expect("tension N_xx, element frame", e, r.N[0], turned ? 0 : N, N, &worst));
    PetscCall(Expect("tension N_yy, element frame", e, r.N[1], turned ? N : 0, N, &worst));
    PetscCall(Expect("tension sigma_yy top, element frame", e, r.stress_top[1], turned ? s : 0, s, &worst));
    PetscCheck(fabs(r.axes[turned ? 1 : 0] - 1) < 1e-14 && fabs(r.axes[8] - 1) < 1e-14, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "element %" PetscInt_FMT ": element frame", e);
    PetscCall(BoltnetAssemblyGetElementResult(a, 10, e, BOLTNET_FRAME_MATERIAL, &r));
    PetscCall(Expect("tension N_xx", e, r.N[0], N, N, &worst));
    PetscCall(Expect("tension N_yy", e, r.N[1], 0, N, &worst));
    PetscCall(Expect("tension N_xy", e, r.N[2], 0, N, &worst));
    PetscCall(Expect("tension M_xx", e, r.M[0], 0, N * t, &worst));
    PetscCall(Expect("tension sigma_xx top", e, r.stress_top[0], s, s, &worst));
    PetscCall(Expect("tension sigma_xx bottom", e, r.stress_bottom[0], s, s, &worst));
    PetscCall(Expect("tension von Mises", e, r.von_mises_top, s, s, &worst));
    PetscCall(Expect("tension strain", e, r.strain_top[0], s / E, s / E, &worst));
    PetscCheck(r.homogeneous && fabs(r.axes[0] - 1) < 1e-14 && fabs(r.axes[4] - 1) < 1e-14, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "element %" PetscInt_FMT ": material frame or section kind", e);
  }
  PetscCall(BoltnetAssemblyDestroy(&a));

  /* Pure bending. */
  PetscCall(Solve(BENDING, C, &a));
  for (PetscInt e = 0; e < NX * NY; ++e) {
    const PetscReal M = C / w, s = 6 * M / (t * t);
    PetscCall(BoltnetAssemblyGetElementResult(a, 10, e, BOLTNET_FRAME_MATERIAL, &r));
    PetscCall(Expect("bending M_xx", e, r.M[0], M, M, &worst));
    PetscCall(Expect("bending M_yy", e, r.M[1], 0, M, &worst));
    PetscCall(Expect("bending M_xy", e, r.M[2], 0, M, &worst));
    PetscCall(Expect("bending N_xx", e, r.N[0], 0, M / t, &worst));
    PetscCall(Expect("bending Q_xz", e, r.Q[0], 0, M / t, &worst));
    PetscCall(Expect("bending sigma_xx top", e, r.stress_top[0], s, s, &worst));
    PetscCall(Expect("bending sigma_xx bottom", e, r.stress_bottom[0], -s, s, &worst));
    PetscCall(Expect("bending von Mises bottom", e, r.von_mises_bottom, s, s, &worst));
  }
  PetscCall(BoltnetAssemblyDestroy(&a));

  /* Cantilever. */
  PetscCall(Solve(CANTILEVER, P, &a));
  for (PetscInt e = 0; e < NX * NY; ++e) {
    const PetscReal xc = L * ((e % NX) + 0.5) / NX, M = -P * (L - xc) / w, Mmax = P * L / w;
    PetscCall(BoltnetAssemblyGetElementResult(a, 10, e, BOLTNET_FRAME_MATERIAL, &r));
    PetscCall(Expect("cantilever M_xx", e, r.M[0], M, Mmax, &worst));
    PetscCall(Expect("cantilever M_yy", e, r.M[1], 0, Mmax, &worst));
    PetscCall(Expect("cantilever Q_xz", e, r.Q[0], P / w, P / w, &worst));
    PetscCall(Expect("cantilever Q_yz", e, r.Q[1], 0, P / w, &worst));
    PetscCall(Expect("cantilever sigma_xx top", e, r.stress_top[0], 6 * M / (t * t), 6 * Mmax / (t * t), &worst));
  }
  PetscCall(BoltnetAssemblyDestroy(&a));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "largest difference from the closed forms: %.2e of the scale\n", (double)worst));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "test_element_results: PASS\n"));
  PetscCall(PetscFinalize());
  return 0;
}
