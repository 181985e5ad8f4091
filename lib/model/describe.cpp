// The description part of the public API of boltnet.h: parts, joints and boundary conditions go
// into the assembly's model (model/model.hpp), unchecked against each other until set-up.
#include "network/assembly.hpp"
#include "core/check.hpp"
#include "core/guard.hpp"
#include "io/limits.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

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

PetscErrorCode CheckNotSetUp(BoltnetAssembly a, const char *where)
{
  PetscFunctionBeginUser;
  PetscCheck(!a->net.dm, a->comm, PETSC_ERR_ORDER, "%s: the assembly is already set up: describe it before BoltnetAssemblySetUp()", where);
  PetscFunctionReturn(0);
}

// Ids of patches and joints: what a scene accepts (io/limits.hpp), so that a negative id (a typo, or
// an unset variable) is refused where it is given.
PetscErrorCode CheckId(BoltnetAssembly a, const char *where, int argnum, const char *name, PetscInt id)
{
  PetscFunctionBeginUser;
  PetscCheck(id >= 0 && id <= limits::kMaxId, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: argument %d (%s) = %" PetscInt_FMT " is not an id in 0..%lld", where, argnum, name, id, (long long)limits::kMaxId);
  PetscFunctionReturn(0);
}

} // namespace

// Every entry point below: the arguments checked (core/check.hpp), then the work inside Guard()
// (core/guard.hpp), which turns a C++ exception (std::bad_alloc from the model's vectors) into a
// PETSc error naming the function.

PetscErrorCode BoltnetAssemblyAddRigidPatch(BoltnetAssembly a, PetscInt id, const PetscReal x[3])
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  PetscCall(CheckNotSetUp(a, __func__));
  PetscCall(CheckId(a, __func__, 2, "id", id));
  PetscCall(Guard(__func__, [&] {
    a->model.parts.push_back(PartDesc{id, PatchKind::Rigid, {x ? x[0] : 0.0, x ? x[1] : 0.0, x ? x[2] : 0.0}});
    return PetscErrorCode(0);
  }));
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyAddJoint(BoltnetAssembly a, PetscInt id, PetscInt patch_a, PetscInt patch_b, const BoltnetJointParams *bp, const PetscReal normal[3], const PetscReal t1[3])
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  BoltnetCheckPointer(bp, 5, "BoltnetJointParams");
  PetscCall(BoltnetAssemblyAddJointAt(a, id, patch_a, patch_b, bp, normal, t1, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyAddJointAt(BoltnetAssembly a, PetscInt id, PetscInt patch_a, PetscInt patch_b, const BoltnetJointParams *bp, const PetscReal normal[3], const PetscReal t1[3], const PetscReal x[3])
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  BoltnetCheckPointer(bp, 5, "BoltnetJointParams");
  PetscCall(CheckNotSetUp(a, __func__));
  PetscCall(CheckId(a, __func__, 2, "id", id));
  PetscCall(CheckId(a, __func__, 3, "patch_a", patch_a));
  PetscCall(CheckId(a, __func__, 4, "patch_b", patch_b));
  PetscCall(Guard(__func__, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    JointDesc j{};
    j.id     = id;
    j.part_a = patch_a;
    j.part_b = patch_b;
    for (int k = 0; k < 3; ++k) j.x[k] = x ? x[k] : 0.0;
    j.positioned = x != nullptr;
    Params &p    = j.params;
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
    PetscCall(JointFrame(a->comm, id, normal ? normal : ndef, t1 ? t1 : tdef, j.R.data()));
    a->model.joints.push_back(j);
    PetscFunctionReturn(0);
  }));
  PetscFunctionReturn(0);
}

namespace {
PetscErrorCode AddBC(BoltnetAssembly a, const char *where, PetscInt patch, const char set[], PetscInt dof, BoltnetBCKind kind, PetscReal value)
{
  PetscFunctionBeginUser;
  PetscCall(CheckNotSetUp(a, where));
  PetscCall(CheckId(a, where, 2, "patch", patch));
  PetscCheck(dof >= -1 && dof < 6, a->comm, PETSC_ERR_USER_INPUT, "Boundary condition on patch %" PetscInt_FMT ": dof %" PetscInt_FMT " is not in 0..5 (ux uy uz rx ry rz) or -1 (all)", patch, dof);
  PetscCheck(kind >= BOLTNET_BC_FIXED && kind <= BOLTNET_BC_PRESSURE, a->comm, PETSC_ERR_USER_INPUT, "Boundary condition on patch %" PetscInt_FMT ": unknown kind %d", patch, (int)kind);
  PetscCheck(std::isfinite(value), a->comm, PETSC_ERR_USER_INPUT, "Boundary condition on patch %" PetscInt_FMT ": value is not finite", patch);
  PetscCheck(kind != BOLTNET_BC_PRESSURE || dof == -1, a->comm, PETSC_ERR_USER_INPUT, "Pressure on patch %" PetscInt_FMT ": a pressure acts along the elements' normals, so its dof is -1 (all), not %" PetscInt_FMT, patch, dof);
  PetscCall(Guard(where, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    // A patch not (yet) described is reported where the model is laid out (patch/layout.cpp).
    PetscCheck(kind != BOLTNET_BC_PRESSURE || a->model.Find(patch) < 0 || a->model.shells.count(a->model.Find(patch)), a->comm, PETSC_ERR_USER_INPUT, "Pressure on patch %" PetscInt_FMT ": it is not a shell patch (a pressure loads a shell patch's elements)", patch);
    if (set && set[0]) {
      const PetscInt   pos = a->model.Find(patch);
      const ShellPart *sp  = a->model.shells.count(pos) ? &a->model.shells.at(pos) : nullptr;
      PetscCheck(sp, a->comm, PETSC_ERR_USER_INPUT, "Boundary condition on set '%s': patch %" PetscInt_FMT " is not a shell patch", set, patch);
      // A part read later, or held by rank 0 alone, is checked where it is laid out (patch/layout.cpp).
      PetscCheck(sp->read || sp->on_rank0 || sp->mesh.node_sets.count(set), a->comm, PETSC_ERR_USER_INPUT, "Boundary condition on patch %" PetscInt_FMT ": it has no node set '%s'", patch, set);
    }
    a->model.bcs.push_back(BCDesc{patch, set ? set : "", dof, kind, value});
    PetscFunctionReturn(0);
  }));
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode BoltnetAssemblyAddBC(BoltnetAssembly a, PetscInt patch, PetscInt dof, BoltnetBCKind kind, PetscReal value)
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  PetscCall(AddBC(a, __func__, patch, nullptr, dof, kind, value));
  PetscFunctionReturn(0);
}

namespace boltnet {
// Called inside a Guard() (the C API's AddShellPatch below, the scene reader's).
PetscErrorCode AssemblyAddShell(BoltnetAssembly a, PetscInt id, ShellMesh &&mesh, const shell::ShellMaterial &material)
{
  PetscFunctionBeginUser;
  PetscCall(CheckNotSetUp(a, "AssemblyAddShell"));
  PetscCheck(!mesh.elems.empty(), a->comm, PETSC_ERR_USER_INPUT, "Shell patch %" PetscInt_FMT ": a mesh needs at least one element", id);
  const PetscInt pos = (PetscInt)a->model.parts.size();
  a->model.parts.push_back(PartDesc{id, PatchKind::Shell, mesh.x[0]});
  ShellPart &sp = a->model.shells[pos];
  sp.mesh       = std::move(mesh);
  sp.material   = material;
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyAddShellRead(BoltnetAssembly a, PetscInt id, std::int64_t size, std::function<PetscErrorCode(ShellMesh *)> read, const shell::ShellMaterial &material)
{
  PetscFunctionBeginUser;
  PetscCall(CheckNotSetUp(a, "AssemblyAddShellRead"));
  const PetscInt pos = (PetscInt)a->model.parts.size();
  a->model.parts.push_back(PartDesc{id, PatchKind::Shell, {0.0, 0.0, 0.0}});
  ShellPart &sp = a->model.shells[pos];
  sp.read       = std::move(read);
  sp.size       = size;
  sp.material   = material;
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyAddShellOnRank0(BoltnetAssembly a, PetscInt id, const std::array<double, 3> &x0, std::int64_t size, ShellMesh &&mesh, const shell::ShellMaterial &material)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCall(CheckNotSetUp(a, "AssemblyAddShellOnRank0"));
  PetscCallMPI(MPI_Comm_rank(a->comm, &rank));
  PetscCheck(rank || !mesh.elems.empty(), a->comm, PETSC_ERR_USER_INPUT, "Shell patch %" PetscInt_FMT ": a mesh needs at least one element", id);
  PetscCheck(rank || (std::int64_t)mesh.x.size() == size, a->comm, PETSC_ERR_PLIB, "Shell patch %" PetscInt_FMT ": %zu nodes given as %lld", id, mesh.x.size(), (long long)size);
  const PetscInt pos = (PetscInt)a->model.parts.size();
  a->model.parts.push_back(PartDesc{id, PatchKind::Shell, x0});
  ShellPart &sp = a->model.shells[pos];
  if (rank == 0) sp.mesh = std::move(mesh);
  sp.on_rank0 = true;
  sp.size     = size;
  sp.material = material;
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblySetJointFootprint(BoltnetAssembly a, PetscInt id, const char set[])
{
  PetscFunctionBeginUser;
  const size_t n = std::strlen(set);
  PetscCheck(n > 0 && n < JointDesc::kFootprintMax, a->comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT ": footprint set '%s' must be a node set's name of 1 to %zu characters", id, set, JointDesc::kFootprintMax - 1);
  // Rank 0 holds the model's joints (the others may hold none: model.hpp).
  for (auto it = a->model.joints.rbegin(); it != a->model.joints.rend(); ++it)
    if (it->id == id) {
      std::copy(set, set + n + 1, it->footprint.begin());
      break;
    }
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyAddFullSpring(BoltnetAssembly a, PetscInt id, PetscInt patch_a, PetscInt patch_b, const std::array<double, 36> &K, const PetscReal normal[3], const PetscReal t1[3], const PetscReal x[3], const PetscReal *at_a, const PetscReal *at_b)
{
  BoltnetJointParams p;
  PetscFunctionBeginUser;
  PetscCall(BoltnetJointParamsSetDefault(BOLTNET_LAW_SPRING, &p));
  PetscCall(BoltnetAssemblyAddJointAt(a, id, patch_a, patch_b, &p, normal, t1, x));
  JointDesc &j = a->model.joints.back();
  j.params.full = 1;
  std::copy(K.begin(), K.end(), j.params.K);
  const std::string bad = validate(j.params);
  if (!bad.empty()) a->model.joints.pop_back(); // a refused call leaves the assembly unchanged
  PetscCheck(bad.empty(), a->comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " (spring with a full stiffness): %s", id, bad.c_str());
  j.lever = at_a && at_b;
  for (int k = 0; k < 3 && j.lever; ++k) j.at_a[k] = at_a[k], j.at_b[k] = at_b[k];
  PetscFunctionReturn(0);
}
} // namespace boltnet

namespace {
// The shell patch of the C API: 4 entries per element, a triangle's fourth -1 where triangles are
// allowed (BoltnetAssemblyAddShellPatchElements), every node in range and named once per element.
// The counts are bounded by what a scene accepts (io/limits.hpp) before anything is allocated.
PetscErrorCode AddShellPatch(BoltnetAssembly a, const char *where, PetscInt id, PetscInt nnodes, const PetscReal xyz[], PetscInt nelems, const PetscInt elems[], PetscReal E, PetscReal nu, PetscReal t, bool triangles)
{
  const char *what = triangles ? "element" : "quadrangle";
  PetscFunctionBeginUser;
  PetscCall(CheckNotSetUp(a, where));
  PetscCall(CheckId(a, where, 2, "id", id));
  PetscCheck(nnodes >= 0 && nnodes <= limits::kMaxSceneNodes, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: argument 3 (nnodes) = %" PetscInt_FMT " is not a node count in 0..%lld", where, nnodes, (long long)limits::kMaxSceneNodes);
  PetscCheck(nelems >= 0 && nelems <= 2 * limits::kMaxSceneNodes, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: argument 5 (%s) = %" PetscInt_FMT " is not an element count in 0..%lld", where, triangles ? "nelems" : "nquads", nelems, (long long)(2 * limits::kMaxSceneNodes));
  PetscCheck(nnodes >= (triangles ? 3 : 4) && nelems >= 1, a->comm, PETSC_ERR_USER_INPUT, "Shell patch %" PetscInt_FMT ": a mesh needs at least one %s (it has %" PetscInt_FMT " nodes and %" PetscInt_FMT " elements)", id, what, nnodes, nelems);
  BoltnetCheckPointerIn(where, xyz, 4, "xyz");
  BoltnetCheckPointerIn(where, elems, 6, triangles ? "elems" : "quads");
  PetscCall(Guard(where, [&]() -> PetscErrorCode {
    ShellMesh            mesh;
    shell::ShellMaterial mat;
    PetscFunctionBeginUser;
    try {
      mat = shell::IsotropicMaterial(E, nu, t);
    } catch (const std::invalid_argument &e) {
      SETERRQ(a->comm, PETSC_ERR_USER_INPUT, "Shell patch %" PetscInt_FMT ": %s", id, e.what());
    }
    mesh.x.reserve((size_t)nnodes);
    mesh.elems.reserve((size_t)nelems);
    for (PetscInt i = 0; i < nnodes; ++i) mesh.x.push_back({xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
    for (PetscInt e = 0; e < nelems; ++e) {
      MeshElement    q  = {-1, -1, -1, -1};
      const PetscInt nn = triangles && elems[4 * e + 3] == -1 ? 3 : 4;
      for (int k = 0; k < nn; ++k) {
        const PetscInt v = elems[4 * e + k];
        PetscCheck(v >= 0 && v < nnodes, a->comm, PETSC_ERR_USER_INPUT, "Shell patch %" PetscInt_FMT ": %s %" PetscInt_FMT " names node %" PetscInt_FMT ", not in 0..%" PetscInt_FMT "%s", id, what, e, v, nnodes - 1, triangles && k < 3 ? "" : triangles ? " (or -1: a triangle)" : "");
        for (int j = 0; j < k; ++j) PetscCheck(q[j] != v, a->comm, PETSC_ERR_USER_INPUT, "Shell patch %" PetscInt_FMT ": %s %" PetscInt_FMT " names node %" PetscInt_FMT " twice", id, what, e, v);
        q[k] = (int)v;
      }
      mesh.elems.push_back(q);
    }
    PetscCall(AssemblyAddShell(a, id, std::move(mesh), mat));
    PetscFunctionReturn(0);
  }));
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode BoltnetAssemblyAddShellPatch(BoltnetAssembly a, PetscInt id, PetscInt nnodes, const PetscReal xyz[], PetscInt nquads, const PetscInt quads[], PetscReal E, PetscReal nu, PetscReal t)
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  PetscCall(AddShellPatch(a, __func__, id, nnodes, xyz, nquads, quads, E, nu, t, false));
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyAddShellPatchElements(BoltnetAssembly a, PetscInt id, PetscInt nnodes, const PetscReal xyz[], PetscInt nelems, const PetscInt elems[], PetscReal E, PetscReal nu, PetscReal t)
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  PetscCall(AddShellPatch(a, __func__, id, nnodes, xyz, nelems, elems, E, nu, t, true));
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyAddNodeSet(BoltnetAssembly a, PetscInt patch, const char name[], PetscInt n, const PetscInt nodes[])
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  BoltnetCheckPointer(name, 3, "name");
  PetscCall(CheckNotSetUp(a, __func__));
  PetscCall(CheckId(a, __func__, 2, "patch", patch));
  PetscCheck(n >= 0 && n <= limits::kMaxSceneNodes, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: argument 4 (n) = %" PetscInt_FMT " is not a node count in 0..%lld", __func__, n, (long long)limits::kMaxSceneNodes);
  if (n > 0) BoltnetCheckPointer(nodes, 5, "nodes");
  PetscCall(Guard(__func__, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    const PetscInt pos = a->model.Find(patch);
    ShellPart     *sp  = a->model.shells.count(pos) ? &a->model.shells[pos] : nullptr;
    PetscCheck(sp, a->comm, PETSC_ERR_USER_INPUT, "Node set '%s': patch %" PetscInt_FMT " is not a shell patch", name, patch);
    PetscCheck(!sp->read, a->comm, PETSC_ERR_USER_INPUT, "Node set '%s': patch %" PetscInt_FMT " is read from its scene when the model is laid out; give the set in its mesh", name, patch);
    PetscCheck(!sp->on_rank0, a->comm, PETSC_ERR_USER_INPUT, "Node set '%s': patch %" PetscInt_FMT "'s mesh is held by rank 0 alone; give the set in its mesh", name, patch);
    std::vector<int> add; // checked in full before the set changes: a refused call changes nothing
    add.reserve((size_t)n);
    for (PetscInt i = 0; i < n; ++i) {
      PetscCheck(nodes[i] >= 0 && nodes[i] < (PetscInt)sp->mesh.x.size(), a->comm, PETSC_ERR_USER_INPUT, "Node set '%s' of patch %" PetscInt_FMT ": node %" PetscInt_FMT " does not exist", name, patch, nodes[i]);
      add.push_back((int)nodes[i]);
    }
    std::vector<int> &set = sp->mesh.node_sets[name];
    set.insert(set.end(), add.begin(), add.end());
    PetscFunctionReturn(0);
  }));
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetAssemblyAddBCOnSet(BoltnetAssembly a, PetscInt patch, const char set[], PetscInt dof, BoltnetBCKind kind, PetscReal value)
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(a, 1, "BoltnetAssembly");
  PetscCall(AddBC(a, __func__, patch, set, dof, kind, value));
  PetscFunctionReturn(0);
}
