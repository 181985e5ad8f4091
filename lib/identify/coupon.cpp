#include "identify/coupon.hpp"

#include "core/guard.hpp"
#include "network/assembly.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace boltnet {
namespace identify {

namespace {

// (A^-1)_11: the membrane compliance per unit width under a uniaxial force along x (free
// contraction across), 1/(E t) for an isotropic sheet.
double AxialCompliance(const shell::Mat3 &A)
{
  const double det = A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) + A[2] * (A[3] * A[7] - A[4] * A[6]);
  return (A[4] * A[8] - A[5] * A[7]) / det;
}

PetscErrorCode SolveCoupon(const CouponSpec &s, const CouponResult &geo, double delta, double *force)
{
  BoltnetAssembly a;
  PetscFunctionBeginUser;
  PetscCall(BoltnetAssemblyCreate(PETSC_COMM_SELF, &a));
  // Its own options prefix: nothing given for the structure (SNES, load, coupling options) reaches
  // the coupon; the coupling is set below from the spec.
  PetscCall(BoltnetAssemblySetOptionsPrefix(a, "boltnet_coupon_"));
  const double L = geo.length, e = geo.edge, w = geo.width;
  // Sheet 1 on [0, L], sheet 2 on [L - 2e, 2L - 2e], both in z = 0, the fastener in the middle of
  // the overlap on the centre line.
  for (int i = 0; i < 2; ++i) PetscCall(AssemblyAddShell(a, i + 1, RectanglePlate(i * (L - 2 * e), 0.0, L, w, geo.nx[i], geo.ny[i], 0.0), s.sheet[i]));
  BoltnetJointParams p;
  PetscCall(BoltnetJointParamsSetDefault(BOLTNET_LAW_SPRING, &p));
  p.kt = s.kspring;
  p.kn = s.kspring;
  p.kr = s.kspring * s.d * s.d;
  const PetscReal n[3] = {0, 0, 1}, t1[3] = {1, 0, 0}, x[3] = {L - e, w / 2, 0};
  PetscCall(BoltnetAssemblyAddJointAt(a, 1, 1, 2, &p, n, t1, x));
  // As the test specimen (and scripts/study-coupling): sheet 1 clamped, sheet 2 gripped and pulled.
  PetscCall(BoltnetAssemblyAddBCOnSet(a, 1, "xmin", -1, BOLTNET_BC_FIXED, 0));
  for (PetscInt dof = 1; dof < 6; ++dof) PetscCall(BoltnetAssemblyAddBCOnSet(a, 2, "xmax", dof, BOLTNET_BC_FIXED, 0));
  PetscCall(BoltnetAssemblyAddBCOnSet(a, 2, "xmax", 0, BOLTNET_BC_DISPLACEMENT, delta));
  a->opt.coupling_type    = s.coupling;
  a->opt.coupling_radius  = s.radius;
  a->opt.coupling_penalty = s.penalty;
  a->opt.patch_max_nodes  = 0; // one patch per sheet, on this rank
  a->opt.balance          = PETSC_FALSE;
  PetscCall(BoltnetAssemblySetFromOptions(a));
  PetscCall(BoltnetAssemblySetUp(a));
  const PetscReal one = 1.0;
  PetscCall(BoltnetAssemblySolveLoadPath(a, 1, &one, 1));
  PetscReal f[6];
  PetscCall(BoltnetAssemblyGetJointResult(a, 1, f, nullptr, nullptr));
  *force = std::fabs(f[1]);
  PetscCall(BoltnetAssemblyDestroy(&a));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode CouponCompliance(const CouponSpec &s, CouponResult *r)
{
  PetscFunctionBeginUser;
  PetscCheck(s.d > 0 && s.kspring > 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Shell correction coupon: needs the fastener diameter (%g) and the spring stiffness (%g) > 0", s.d, s.kspring);
  for (int i = 0; i < 2; ++i) PetscCheck(s.hx[i] > 0 && s.hy[i] > 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Shell correction coupon: element size of sheet %d must be > 0 (got %g x %g mm)", i + 1, s.hx[i], s.hy[i]);
  *r       = CouponResult();
  r->width = s.width > 0 ? s.width : 5 * s.d;
  r->edge  = r->width / 2; // 2.5 d for the default width, as the usual edge distance
  // Four widths, and long enough that the fastener's element is at least three elements from the
  // clamped and the loaded ends (so that the footprint never meets a boundary condition).
  const double hmax = std::max(std::max(s.hx[0], s.hx[1]), std::max(s.hy[0], s.hy[1]));
  r->length         = std::max(4 * r->width, 2 * r->edge + 4 * hmax);
  for (int i = 0; i < 2; ++i) {
    r->nx[i] = std::max(1, (int)std::lround(r->length / s.hx[i]));
    r->ny[i] = std::max(1, (int)std::lround(r->width / s.hy[i]));
  }
  const double delta = 0.01 * r->width; // the coupon is linear: any delta gives the same delta/F
  PetscCall(SolveCoupon(s, *r, delta, &r->force));
  PetscCheck(r->force > 0 && std::isfinite(r->force), PETSC_COMM_SELF, PETSC_ERR_PLIB, "Shell correction coupon: no force through the fastener (%g)", r->force);
  r->compliance = delta / r->force;
  // Each sheet carries the load from the fastener to its clamped or loaded end: length - edge.
  // (A laminate's membrane stiffness in the coupon's axes: its reference direction at phi from x.)
  double a11[2];
  for (int i = 0; i < 2; ++i) {
    const shell::Vec3 &dir = s.sheet[i].direction;
    a11[i]                 = AxialCompliance(shell::RotateMaterial(s.sheet[i], std::atan2(dir[1], dir[0])).A);
  }
  r->Cb = (r->length - r->edge) * (a11[0] + a11[1]) / r->width;
  r->Cc = r->compliance - r->Cb - 1.0 / s.kspring;
  PetscFunctionReturn(0);
}

PetscErrorCode FootprintElementSize(MPI_Comm comm, const ShellMesh &m, const double p[3], const double axis[3], const double t1[3], double radius, double *hx, double *hy)
{
  PetscFunctionBeginUser;
  const std::array<double, 3> P = {p[0], p[1], p[2]}, N = {axis[0], axis[1], axis[2]};
  // In-plane unit directions: t1 without its axial part, and axis x t1.
  const double nn = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
  double       n[3] = {N[0] / nn, N[1] / nn, N[2] / nn}, a[3], b[3];
  const double dn = t1[0] * n[0] + t1[1] * n[1] + t1[2] * n[2];
  for (int k = 0; k < 3; ++k) a[k] = t1[k] - dn * n[k];
  const double an = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  for (double &c : a) c /= an;
  b[0] = n[1] * a[2] - n[2] * a[1], b[1] = n[2] * a[0] - n[0] * a[2], b[2] = n[0] * a[1] - n[1] * a[0];
  const std::vector<int> fp = CouplingFootprint(m, P, N, radius);
  PetscCheck(!fp.empty(), comm, PETSC_ERR_USER_INPUT, "The fastener at (%g, %g, %g) is outside its patch: no element size to measure", p[0], p[1], p[2]);
  const std::set<int> in(fp.begin(), fp.end());
  double   sx = 0, sy = 0;
  PetscInt count = 0;
  for (const auto &q : m.elems) {
    bool touches = false;
    for (int k = 0; k < ElementNodes(q); ++k) touches = touches || in.count(q[k]);
    if (!touches) continue;
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (int k = 0; k < ElementNodes(q); ++k) {
      const auto  &x  = m.x[q[k]];
      const double pa = x[0] * a[0] + x[1] * a[1] + x[2] * a[2], pb = x[0] * b[0] + x[1] * b[1] + x[2] * b[2];
      lo[0] = std::min(lo[0], pa), hi[0] = std::max(hi[0], pa);
      lo[1] = std::min(lo[1], pb), hi[1] = std::max(hi[1], pb);
    }
    sx += hi[0] - lo[0], sy += hi[1] - lo[1], ++count;
  }
  PetscCheck(count > 0, comm, PETSC_ERR_PLIB, "No element around the fastener at (%g, %g, %g)", p[0], p[1], p[2]);
  *hx = sx / count;
  *hy = sy / count;
  PetscFunctionReturn(0);
}

PetscErrorCode ApplyShellCorrection(MPI_Comm comm, const std::string &what, double Cc, Params *q)
{
  PetscFunctionBeginUser;
  const double ckc = 1 / q->kc - Cc, ckt = 1 / q->kt - Cc;
  PetscCheck(ckc > 0, comm, PETSC_ERR_USER_INPUT,
             "%s: the shell mesh and coupling alone already add a compliance C_c = %g mm/N, at least the formula's whole joint compliance 1/kc = %g mm/N (the mesh is softer than the formula): no positive spring can give the formula's stiffness; refine the mesh around the fastener or switch the shell correction off",
             what.c_str(), Cc, 1 / q->kc);
  PetscCheck(ckt > 0, comm, PETSC_ERR_USER_INPUT, "%s: the shell mesh and coupling alone already add a compliance C_c = %g mm/N, at least the stick compliance 1/kt = %g mm/N: no positive stick stiffness can give it; refine the mesh around the fastener or switch the shell correction off", what.c_str(), Cc, 1 / q->kt);
  q->kc = 1 / ckc;
  q->kt = 1 / ckt;
  PetscFunctionReturn(0);
}

} // namespace identify
} // namespace boltnet
