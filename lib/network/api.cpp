// The public assembly API of boltnet.h: description, options, set-up, results.
#include "network/assembly.hpp"
#include "core/guard.hpp"

#include <cmath>
#include <cstring>

using namespace boltnet;

namespace {

// Build the rows (n, t1, t2) of the joint frame from the bolt axis and a first in-plane direction.
PetscErrorCode JointFrame(MPI_Comm comm, PetscInt id, const PetscReal n[3], const PetscReal t[3], PetscReal R[9])
{
  PetscFunctionBeginUser;
  const double nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  PetscCheck(nn > 0, comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT ": the bolt axis (normal) is the zero vector", id);
  double e0[3] = {n[0] / nn, n[1] / nn, n[2] / nn};
  // Remove the normal part of t so that a roughly in-plane direction is enough.
  const double d  = t[0] * e0[0] + t[1] * e0[1] + t[2] * e0[2];
  double       e1[3] = {t[0] - d * e0[0], t[1] - d * e0[1], t[2] - d * e0[2]};
  const double tn = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  PetscCheck(tn > 1e-8 * std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]) && tn > 0, comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT ": the in-plane direction t1 is parallel to the bolt axis", id);
  for (double &c : e1) c /= tn;
  const double e2[3] = {e0[1] * e1[2] - e0[2] * e1[1], e0[2] * e1[0] - e0[0] * e1[2], e0[0] * e1[1] - e0[1] * e1[0]};
  for (int k = 0; k < 3; ++k) {
    R[k]     = e0[k];
    R[3 + k] = e1[k];
    R[6 + k] = e2[k];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CheckNotSetUp(BoltnetAssembly a)
{
  PetscFunctionBeginUser;
  PetscCheck(!a->dm, a->comm, PETSC_ERR_ORDER, "The assembly is already set up: describe it before BoltnetAssemblySetUp()");
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode BoltnetAssemblyCreate(MPI_Comm comm, BoltnetAssembly *a)
{
  PetscFunctionBeginUser;
  PetscCheck(a, comm, PETSC_ERR_ARG_NULL, "Null BoltnetAssembly pointer");
  PetscCall(BoltnetInitializePackage());
  *a = new _p_BoltnetAssembly();
  PetscCallMPI(MPI_Comm_dup(comm, &(*a)->comm));
  PetscCallMPI(MPI_Comm_rank((*a)->comm, &(*a)->rank));
  PetscCallMPI(MPI_Comm_size((*a)->comm, &(*a)->size));
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyDestroy(BoltnetAssembly *a)
{
  PetscFunctionBeginUser;
  if (!a || !*a) PetscFunctionReturn(0);
  PetscCall(SNESDestroy(&(*a)->snes));
  PetscCall(MatDestroy(&(*a)->J));
  PetscCall(VecDestroy(&(*a)->X));
  PetscCall(DMDestroy(&(*a)->dm));
  PetscCallMPI(MPI_Comm_free(&(*a)->comm));
  delete *a;
  *a = nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblySetOptionsPrefix(BoltnetAssembly a, const char prefix[])
{
  PetscFunctionBeginUser;
  a->prefix = prefix ? prefix : "";
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyAddRigidPatch(BoltnetAssembly a, PetscInt id, const PetscReal x[3])
{
  PetscFunctionBeginUser;
  PetscCall(CheckNotSetUp(a));
  PatchComp p{};
  p.id     = id;
  p.index  = (PetscInt)a->patches.size();
  p.kind   = static_cast<PetscInt>(PatchKind::Rigid);
  p.nnodes = 1;
  for (int k = 0; k < 3; ++k) p.x[k] = x ? x[k] : 0.0;
  a->patches.push_back(p);
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyAddJoint(BoltnetAssembly a, PetscInt id, PetscInt patch_a, PetscInt patch_b, const BoltnetJointParams *bp, const PetscReal normal[3], const PetscReal t1[3])
{
  PetscFunctionBeginUser;
  PetscCall(BoltnetAssemblyAddJointAt(a, id, patch_a, patch_b, bp, normal, t1, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyAddJointAt(BoltnetAssembly a, PetscInt id, PetscInt patch_a, PetscInt patch_b, const BoltnetJointParams *bp, const PetscReal normal[3], const PetscReal t1[3], const PetscReal x[3])
{
  PetscFunctionBeginUser;
  PetscCall(CheckNotSetUp(a));
  PetscCheck(bp, a->comm, PETSC_ERR_ARG_NULL, "Joint %" PetscInt_FMT ": null parameters", id);
  JointComp j{};
  j.id      = id;
  j.index   = (PetscInt)a->joints.size();
  j.patch_a = patch_a;
  j.patch_b = patch_b;
  j.node_a = j.node_b = 0; // rigid patches: their single node; shell patches: set at set-up
  for (int k = 0; k < 3; ++k) j.x[k] = x ? x[k] : 0.0;
  Params &p           = j.params;
  PetscCheck(bp->law >= BOLTNET_LAW_SPRING && bp->law <= BOLTNET_LAW_FRICTION, a->comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT ": unknown law %d", id, (int)bp->law);
  p.law            = static_cast<Law>(bp->law);
  p.kn             = bp->kn;
  p.kt             = bp->kt;
  p.kr             = bp->kr;
  p.kc             = bp->kc;
  p.kg             = bp->kg;
  p.gap            = bp->gap;
  p.mu             = bp->mu;
  p.nf             = bp->nf;
  p.pretension     = bp->pretension;
  p.clamp_coupling = bp->clamp_coupling;
  p.offset[0]      = bp->offset[0];
  p.offset[1]      = bp->offset[1];
  const std::string bad = validate(p);
  PetscCheck(bad.empty(), a->comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " (%s law): %s", id, lawName(p.law), bad.c_str());
  const PetscReal ndef[3] = {0, 0, 1}, tdef[3] = {1, 0, 0};
  PetscCall(JointFrame(a->comm, id, normal ? normal : ndef, t1 ? t1 : tdef, j.R));
  a->joints.push_back(j);
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyAddBC(BoltnetAssembly a, PetscInt patch, PetscInt dof, BoltnetBCKind kind, PetscReal value)
{
  PetscFunctionBeginUser;
  PetscCall(CheckNotSetUp(a));
  PetscCheck(dof >= -1 && dof < 6, a->comm, PETSC_ERR_USER_INPUT, "Boundary condition on patch %" PetscInt_FMT ": dof %" PetscInt_FMT " is not in 0..5 (ux uy uz rx ry rz) or -1 (all)", patch, dof);
  PetscCheck(kind >= BOLTNET_BC_FIXED && kind <= BOLTNET_BC_FORCE, a->comm, PETSC_ERR_USER_INPUT, "Boundary condition on patch %" PetscInt_FMT ": unknown kind %d", patch, (int)kind);
  PetscCheck(std::isfinite(value), a->comm, PETSC_ERR_USER_INPUT, "Boundary condition on patch %" PetscInt_FMT ": value is not finite", patch);
  a->bcs.push_back(BCDesc{patch, "", dof, kind, value});
  PetscFunctionReturn(0);
}

namespace boltnet {
PetscErrorCode AssemblyAddShell(BoltnetAssembly a, PetscInt id, QuadMesh &&mesh, const shell::ShellMaterial &material)
{
  PetscFunctionBeginUser;
  PetscCall(CheckNotSetUp(a));
  PetscCheck(!mesh.quads.empty(), a->comm, PETSC_ERR_USER_INPUT, "Shell patch %" PetscInt_FMT ": a mesh needs at least one quadrangle", id);
  ShellPatch sp;
  sp.id       = id;
  sp.mesh     = std::move(mesh);
  sp.material = material;
  PatchComp p{};
  p.id     = id;
  p.index  = (PetscInt)a->patches.size();
  p.kind   = static_cast<PetscInt>(PatchKind::Shell);
  p.nnodes = (PetscInt)sp.mesh.x.size();
  for (int k = 0; k < 3; ++k) p.x[k] = sp.mesh.x[0][k];
  a->shells[p.index] = std::move(sp);
  a->patches.push_back(p);
  PetscFunctionReturn(0);
}
} // namespace boltnet

PetscErrorCode BoltnetAssemblyAddShellPatch(BoltnetAssembly a, PetscInt id, PetscInt nnodes, const PetscReal xyz[], PetscInt nquads, const PetscInt quads[], PetscReal E, PetscReal nu, PetscReal t)
{
  QuadMesh             mesh;
  shell::ShellMaterial mat;
  PetscFunctionBeginUser;
  PetscCheck(nnodes >= 4 && nquads >= 1 && xyz && quads, a->comm, PETSC_ERR_USER_INPUT, "Shell patch %" PetscInt_FMT ": a mesh needs at least one quadrangle", id);
  for (PetscInt i = 0; i < nnodes; ++i) mesh.x.push_back({xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
  for (PetscInt e = 0; e < nquads; ++e) {
    std::array<int, 4> q;
    for (int k = 0; k < 4; ++k) {
      PetscCheck(quads[4 * e + k] >= 0 && quads[4 * e + k] < nnodes, a->comm, PETSC_ERR_USER_INPUT, "Shell patch %" PetscInt_FMT ": quadrangle %" PetscInt_FMT " names node %" PetscInt_FMT ", not in 0..%" PetscInt_FMT, id, e, quads[4 * e + k], nnodes - 1);
      q[k] = (int)quads[4 * e + k];
    }
    mesh.quads.push_back(q);
  }
  PetscCall(Guard(a->comm, [&] {
    mat = shell::IsotropicMaterial(E, nu, t);
    return PetscErrorCode(0);
  }));
  PetscCall(AssemblyAddShell(a, id, std::move(mesh), mat));
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyAddNodeSet(BoltnetAssembly a, PetscInt patch, const char name[], PetscInt n, const PetscInt nodes[])
{
  PetscFunctionBeginUser;
  PetscCall(CheckNotSetUp(a));
  ShellPatch *sp = nullptr;
  for (auto &kv : a->shells)
    if (kv.second.id == patch) sp = &kv.second;
  PetscCheck(sp, a->comm, PETSC_ERR_USER_INPUT, "Node set '%s': patch %" PetscInt_FMT " is not a shell patch", name, patch);
  std::vector<int> &set = sp->mesh.node_sets[name];
  for (PetscInt i = 0; i < n; ++i) {
    PetscCheck(nodes[i] >= 0 && nodes[i] < (PetscInt)sp->mesh.x.size(), a->comm, PETSC_ERR_USER_INPUT, "Node set '%s' of patch %" PetscInt_FMT ": node %" PetscInt_FMT " does not exist", name, patch, nodes[i]);
    set.push_back((int)nodes[i]);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyAddBCOnSet(BoltnetAssembly a, PetscInt patch, const char set[], PetscInt dof, BoltnetBCKind kind, PetscReal value)
{
  PetscFunctionBeginUser;
  PetscCall(BoltnetAssemblyAddBC(a, patch, dof, kind, value));
  if (set && set[0]) {
    const ShellPatch *sp = nullptr;
    for (auto &kv : a->shells)
      if (kv.second.id == patch) sp = &kv.second;
    PetscCheck(sp, a->comm, PETSC_ERR_USER_INPUT, "Boundary condition on set '%s': patch %" PetscInt_FMT " is not a shell patch", set, patch);
    PetscCheck(sp->mesh.node_sets.count(set), a->comm, PETSC_ERR_USER_INPUT, "Boundary condition on patch %" PetscInt_FMT ": it has no node set '%s'", patch, set);
    a->bcs.back().set = set;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblySetFromOptions(BoltnetAssembly a)
{
  const char *tangents[] = {"paper", "consistent"};
  PetscInt    t          = static_cast<PetscInt>(a->tangent);
  PetscInt    ct         = static_cast<PetscInt>(a->coupling_type);
  PetscFunctionBeginUser;
  PetscOptionsBegin(a->comm, a->prefix.c_str(), "boltnet solver options", "boltnet");
  PetscCall(PetscOptionsEList("-joint_tangent", "Joint tangent in the Jacobian: the paper's state-switched one or the consistent one", "BoltnetAssemblySetFromOptions", tangents, 2, tangents[t], &t, nullptr));
  PetscCall(PetscOptionsInt("-load_max_cuts", "Step cut-backs (halvings) allowed per load step before the solve stops", "BoltnetAssemblySolveLoadPath", a->max_cuts, &a->max_cuts, nullptr));
  PetscCall(PetscOptionsEList("-coupling_type", "How a joint attaches to a shell patch: its footprint tied rigidly to the joint node by penalty links, or eliminated exactly (rigid-body slaves), or the joint on the nearest mesh node (no footprint)", "BoltnetAssemblySetFromOptions", kCouplingTypeNames, 3, kCouplingTypeNames[ct], &ct, nullptr));
  PetscCall(PetscOptionsReal("-coupling_radius", "Footprint radius of a fastener on a shell patch (mm): nodes within it follow the joint node rigidly", "BoltnetAssemblySetFromOptions", a->coupling_radius, &a->coupling_radius, nullptr));
  PetscCall(PetscOptionsInt("-patch_max_nodes", "Largest shell patch in nodes: a larger part is cut into strips joined by seam edges so that ranks can share it (0: never cut; -1: automatic, about eight patches per rank, none under 32 nodes, no cut on one rank)", "BoltnetAssemblySetFromOptions", a->patch_max_nodes, &a->patch_max_nodes, nullptr));
  PetscCall(PetscOptionsBool("-patch_balance", "Distribute the patches over the ranks by dof with METIS (false: PETSc's partitioner, by edge count)", "BoltnetAssemblySetFromOptions", a->balance, &a->balance, nullptr));
  PetscCall(PetscOptionsReal("-coupling_penalty", "Penalty of the rigid footprint links, as a multiple of the shell's membrane stiffness A11 (N/mm)", "BoltnetAssemblySetFromOptions", a->coupling_penalty, &a->coupling_penalty, nullptr));
  PetscCall(PetscOptionsBool("-joint_stuck_linear", "Solve joints that stay stuck as linear springs (no state logic) and keep the Jacobian and its factorisation while no joint's tangent changes; every such joint is checked with the full law before a step is accepted", "BoltnetAssemblySetFromOptions", a->stuck_linear, &a->stuck_linear, nullptr));
  PetscCall(PetscOptionsReal("-joint_stuck_margin", "Solve a joint as a linear spring in a step when its predicted utilization (trial force / friction threshold, or jump / clearance) stays below this", "BoltnetAssemblySetFromOptions", a->stuck_margin, &a->stuck_margin, nullptr));
  PetscCall(PetscOptionsBool("-joint_monitor", "Print, per Newton iteration, the joints in each state and how many changed (summed over ranks)", "BoltnetAssemblySetFromOptions", a->monitor_states, &a->monitor_states, nullptr));
  PetscOptionsEnd();
  PetscCheck(a->coupling_radius > 0, a->comm, PETSC_ERR_USER_INPUT, "-coupling_radius %g must be > 0", (double)a->coupling_radius);
  PetscCheck(a->patch_max_nodes >= -1, a->comm, PETSC_ERR_USER_INPUT, "-patch_max_nodes %" PetscInt_FMT " must be -1 (automatic), 0 (never cut) or a positive node count", a->patch_max_nodes);
  PetscCheck(a->coupling_penalty > 0, a->comm, PETSC_ERR_USER_INPUT, "-coupling_penalty %g must be > 0", (double)a->coupling_penalty);
  PetscCheck(a->stuck_margin >= 0 && a->stuck_margin <= 1, a->comm, PETSC_ERR_USER_INPUT, "-joint_stuck_margin %g must lie in [0, 1] (0: no joint is frozen)", (double)a->stuck_margin);
  PetscCheck(a->max_cuts >= 0 && a->max_cuts <= 60, a->comm, PETSC_ERR_USER_INPUT, "-load_max_cuts %" PetscInt_FMT " must lie in [0, 60]", a->max_cuts);
  a->tangent               = static_cast<Tangent>(t);
  a->coupling_type         = static_cast<CouplingType>(ct);
  a->setfromoptions_called = PETSC_TRUE;
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblySetUp(BoltnetAssembly a)
{
  PetscFunctionBeginUser;
  if (a->dm) PetscFunctionReturn(0);
  if (!a->setfromoptions_called) PetscCall(BoltnetAssemblySetFromOptions(a));
  PetscCall(AssemblyBuildNetwork(a));
  PetscCall(AssemblySetUpSolver(a));
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyGetDM(BoltnetAssembly a, DM *dm)
{
  PetscFunctionBeginUser;
  *dm = a->dm;
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyGetSNES(BoltnetAssembly a, SNES *snes)
{
  PetscFunctionBeginUser;
  *snes = a->snes;
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyGetLoadFactor(BoltnetAssembly a, PetscReal *lambda)
{
  PetscFunctionBeginUser;
  *lambda = a->lambda;
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyGetJointResult(BoltnetAssembly a, PetscInt id, PetscReal force[6], PetscReal jump[6], BoltnetJointState *state)
{
  std::vector<JointRecord> rec;
  PetscFunctionBeginUser;
  PetscCheck(a->dm, a->comm, PETSC_ERR_ORDER, "Call BoltnetAssemblySetUp() first");
  PetscCall(AssemblyGatherRecords(a, rec));
  JointRecord found{};
  PetscInt    ok = 0;
  for (const JointRecord &r : rec)
    if (r.joint == id) {
      found = r;
      ok    = 1;
    }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPIU_INT, 0, a->comm));
  PetscCheck(ok, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "No joint with id %" PetscInt_FMT, id);
  PetscCallMPI(MPI_Bcast(&found, sizeof(JointRecord), MPI_BYTE, 0, a->comm));
  for (int i = 0; i < 6; ++i) {
    if (force) force[i] = found.force[i];
    if (jump) jump[i] = found.jump[i];
  }
  if (state) *state = static_cast<BoltnetJointState>(found.state);
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyGetPatchDisplacement(BoltnetAssembly a, PetscInt patch, PetscReal u[6])
{
  PetscFunctionBeginUser;
  PetscCheck(a->dm, a->comm, PETSC_ERR_ORDER, "Call BoltnetAssemblySetUp() first");
  PetscReal loc[7] = {0, 0, 0, 0, 0, 0, 0}, glob[7];
  for (PetscInt v = a->vStart; v < a->vEnd; ++v) {
    PetscBool ghost;
    PetscInt  key, nvar, goff, rstart;
    void     *data;
    PetscCall(DMNetworkIsGhostVertex(a->dm, v, &ghost));
    if (ghost) continue;
    PetscCall(DMNetworkGetComponent(a->dm, v, 0, &key, &data, &nvar));
    if (static_cast<PatchComp *>(data)->id != patch) continue;
    const PetscScalar *x;
    PetscCall(DMNetworkGetGlobalVecOffset(a->dm, v, ALL_COMPONENTS, &goff));
    PetscCall(VecGetOwnershipRange(a->X, &rstart, nullptr));
    PetscCall(VecGetArrayRead(a->X, &x));
    for (int i = 0; i < 6; ++i) loc[i] = x[goff - rstart + i];
    loc[6] = 1;
    PetscCall(VecRestoreArrayRead(a->X, &x));
  }
  PetscCall(MPIU_Allreduce(loc, glob, 7, MPIU_REAL, MPIU_SUM, a->comm));
  PetscCheck(glob[6] == 1, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "No patch with id %" PetscInt_FMT, patch);
  for (int i = 0; i < 6; ++i) u[i] = glob[i];
  PetscFunctionReturn(0);
}
