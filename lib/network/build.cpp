// The network (assembly.hpp): the layout put on a DMNetwork, distributed, and the operators of what
// each rank owns built there.
#include "core/guard.hpp"
#include "core/log.hpp"
#include "network/assembly.hpp"
#include "network/internal.hpp"
#include "partition/balance.hpp"

#include <algorithm>
#include <cstring>
#include <set>

namespace boltnet {
namespace {

// Rank 0 lays the whole network out (the graph and its plain components only: no mesh), then
// DMNetworkDistribute spreads it with the partition of SetPatchPartition.
PetscErrorCode CreateNetwork(BoltnetAssembly a)
{
  Layout &L = a->layout;
  PetscFunctionBeginUser;
  const PetscInt        njoint = (PetscInt)L.joints.size(), nseam = (PetscInt)L.seams.size();
  std::vector<PetscInt> edgelist = LayoutEdgeList(L);
  PetscCall(DMNetworkCreate(a->comm, &a->net.dm));
  DM dm = a->net.dm;
  PetscCall(DMNetworkSetNumSubNetworks(dm, PETSC_DECIDE, 1));
  PetscCall(DMNetworkRegisterComponent(dm, "patch", sizeof(PatchComp), &a->net.keyPatch));
  PetscCall(DMNetworkRegisterComponent(dm, "joint", sizeof(JointComp), &a->net.keyJoint));
  PetscCall(DMNetworkRegisterComponent(dm, "seam", sizeof(SeamComp), &a->net.keySeam));
  const PetscInt ne = a->rank == 0 ? njoint + nseam : 0;
  PetscCall(DMNetworkAddSubnetwork(dm, "assembly", ne, a->rank == 0 ? edgelist.data() : nullptr, nullptr));
  PetscCall(DMNetworkLayoutSetUp(dm));
  std::vector<SeamComp> seamcomps(nseam);
  if (a->rank == 0) {
    PetscInt        nv, nee;
    const PetscInt *vtx, *edges;
    PetscCall(DMNetworkGetSubnetwork(dm, 0, &nv, &nee, &vtx, &edges));
    for (PetscInt i = 0; i < njoint; ++i) PetscCall(DMNetworkAddComponent(dm, edges[i], a->net.keyJoint, &L.joints[i], 0));
    for (PetscInt i = 0; i < nseam; ++i) {
      seamcomps[i] = SeamComp{i, L.seams[i].part};
      PetscCall(DMNetworkAddComponent(dm, edges[njoint + i], a->net.keySeam, &seamcomps[i], 0));
    }
    for (PetscInt i = 0; i < nv; ++i) {
      PetscInt gidx;
      PetscCall(DMNetworkGetGlobalVertexIndex(dm, vtx[i], &gidx));
      PatchComp &p = L.patches[gidx];
      PetscCall(DMNetworkAddComponent(dm, vtx[i], a->net.keyPatch, &p, 6 * p.nnodes));
    }
  }
  PetscCall(DMNetworkFinalizeComponents(dm));
  if (a->size > 1 && a->opt.balance) {
    std::vector<PetscInt> weights; // every dof of the patch: the work of building (condensing) it
    if (a->rank == 0)
      for (PetscInt n : L.nodes) weights.push_back(6 * n);
    PetscCall(SetPatchPartition(dm, weights, a->rank == 0 ? edgelist : std::vector<PetscInt>{}));
  }
  PetscCall(DMNetworkDistribute(&a->net.dm, 0));
  PetscCall(DMNetworkGetVertexRange(a->net.dm, &a->net.vStart, &a->net.vEnd));
  PetscCall(DMNetworkGetEdgeRange(a->net.dm, &a->net.eStart, &a->net.eEnd));
  PetscFunctionReturn(0);
}

// The owned patches, the local joints (aligned copies of their components with their offsets) and
// the local seams.
PetscErrorCode LocalViews(BoltnetAssembly a)
{
  DM dm = a->net.dm;
  PetscFunctionBeginUser;
  a->patches.owned.clear();
  for (PetscInt v = a->net.vStart; v < a->net.vEnd; ++v) {
    PetscBool ghost;
    PetscCall(DMNetworkIsGhostVertex(dm, v, &ghost));
    if (ghost) continue;
    PatchComp p;
    PetscCall(NetworkComponent(dm, v, nullptr, &p, sizeof p));
    OwnedPatch op;
    op.v     = v;
    op.index = p.index;
    op.shell = p.kind == static_cast<PetscInt>(PatchKind::Shell);
    PetscCall(DMNetworkGetGlobalVecOffset(dm, v, ALL_COMPONENTS, &op.goff));
    PetscCall(DMNetworkGetLocalVecOffset(dm, v, ALL_COMPONENTS, &op.loff));
    a->patches.owned.push_back(std::move(op));
  }
  JointSet &js = a->joints;
  js       = JointSet{};
  a->net.sedges.clear();
  for (PetscInt e = a->net.eStart; e < a->net.eEnd; ++e) {
    PetscInt key;
    PetscCall(NetworkComponent(dm, e, &key, nullptr, 0));
    if (key == a->net.keySeam) {
      a->net.sedges.push_back(e);
      continue;
    }
    JointComp       j;
    const PetscInt *cone;
    PetscInt        la, lb, ga, gb;
    PetscCall(NetworkComponent(dm, e, nullptr, &j, sizeof j));
    PetscCall(DMNetworkGetConnectedVertices(dm, e, &cone));
    PetscCall(DMNetworkGetLocalVecOffset(dm, cone[0], ALL_COMPONENTS, &la));
    PetscCall(DMNetworkGetLocalVecOffset(dm, cone[1], ALL_COMPONENTS, &lb));
    PetscCall(DMNetworkGetGlobalVecOffset(dm, cone[0], ALL_COMPONENTS, &ga));
    PetscCall(DMNetworkGetGlobalVecOffset(dm, cone[1], ALL_COMPONENTS, &gb));
    std::array<PetscInt, 12> rows;
    for (int i = 0; i < 6; ++i) {
      rows[i]     = ga + 6 * j.node_a + i;
      rows[6 + i] = gb + 6 * j.node_b + i;
    }
    js.comp.push_back(j);
    js.edge.push_back(e);
    js.oa.push_back(la + 6 * j.node_a);
    js.ob.push_back(lb + 6 * j.node_b);
    js.rows.push_back(rows);
  }
  js.committed.assign(js.size(), History{});
  PetscFunctionReturn(0);
}

// The operators of the owned shell patches (kept whole or condensed) and of the owned seams.
PetscErrorCode BuildOperators(BoltnetAssembly a)
{
  PetscFunctionBeginUser;
  const double penalty_factor = a->opt.coupling_penalty;
  PetscCall(PetscLogStagePush(Events().condense_stage));
  PetscCall(PetscLogEventBegin(Events().condense, 0, 0, 0, 0));
  PetscCall(Collective(a->comm, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    a->patches.condensed_bytes = 0;
    for (OwnedPatch &op : a->patches.owned) {
      if (!op.shell) continue;
      const ShellPatch &sp      = a->layout.shells.at(op.index);
      const double      penalty = penalty_factor * sp.material.A[0];
      if (!sp.condensed) {
        op.op = BuildShellOperator(sp, a->opt.coupling_type, penalty, a->opt.coupling_radius);
        continue;
      }
      PatchLoads loads;
      PetscCall(PatchLoadsFromModel(PETSC_COMM_SELF, a->model, sp.id, &sp, a->opt.coupling_type, &loads));
      PetscCall(CondensePatch(sp, a->opt.coupling_type, penalty, a->opt.coupling_radius, loads, &op.cond));
      a->patches.condensed_bytes += op.cond.bytes;
    }
    for (PetscInt e : a->net.sedges) {
      SeamComp sc;
      PetscCall(NetworkComponent(a->net.dm, e, nullptr, &sc, sizeof sc));
      const Seam &seam = a->layout.seams.at(sc.index);
      auto       &Ks   = a->patches.seam_ops[e];
      Ks.resize(seam.elems.size());
      for (size_t k = 0; k < seam.elems.size(); ++k) ElementMatrixOf(seam.elems[k].geom, seam.material, seam.drill, Ks[k]);
    }
    PetscFunctionReturn(0);
  }));
  PetscCall(PetscLogEventEnd(Events().condense, 0, 0, 0, 0));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

// Once the operators are built, what the rank keeps of the layout: the shell patches and the seams
// it owns. Of every other shell patch only its record stays (which part, whether condensed): code
// that asks whether a patch is a shell finds it. The whole meshes of the cut parts and the
// model's joint descriptions and the layout's joint components (each rank's own are its network
// edges' components) go too, so that past the set-up no rank holds the whole model
// (docs/performance.md, "Memory per rank").
PetscErrorCode ReleaseUnowned(BoltnetAssembly a)
{
  std::set<PetscInt> keep, mine;
  PetscFunctionBeginUser;
  for (const OwnedPatch &op : a->patches.owned) keep.insert(op.index);
  for (auto &[pos, sp] : a->layout.shells) {
    if (keep.count(pos)) continue;
    ShellPatch stub;
    stub.id        = sp.id;
    stub.material  = sp.material;
    stub.drill     = sp.drill;
    stub.condensed = sp.condensed;
    sp             = std::move(stub);
  }
  for (PetscInt e : a->net.sedges) {
    SeamComp sc;
    PetscCall(NetworkComponent(a->net.dm, e, nullptr, &sc, sizeof sc));
    mine.insert(sc.index);
  }
  for (size_t s = 0; s < a->layout.seams.size(); ++s)
    if (!mine.count((PetscInt)s)) std::vector<Seam::Element>().swap(a->layout.seams[s].elems);
  a->layout.cut_parts.clear();
  std::vector<JointDesc>().swap(a->model.joints); // laid out: the network's joint components hold them
  std::vector<JointComp>().swap(a->layout.joints); // each rank's own are its edges' components
  // What is left with a mesh, whatever the rule above kept: nodes or elements (a patch of a cut
  // part may have nodes whose elements all straddle the cut, in its shared list).
  std::size_t whole = 0, nodes = 0;
  for (const auto &[pos, sp] : a->layout.shells)
    if (!sp.mesh.x.empty() || !sp.mesh.elems.empty() || !sp.shared.empty()) {
      ++whole;
      nodes += sp.mesh.x.size();
    }
  PetscCall(PetscInfo(nullptr, "Kept the meshes of %zu of %zu shell patches (%zu nodes) on this rank past the set-up\n", whole, a->layout.shells.size(), nodes));
  PetscCall(PetscInfo(nullptr, "Kept the components of %zu of %" PetscInt_FMT " joints on this rank past the set-up\n", a->joints.size(), a->layout.njoints));
  PetscFunctionReturn(0);
}

// The resident memory over the ranks at the end of a phase of the set-up.
PetscErrorCode MarkMemory(BoltnetAssembly a, const char *phase)
{
  MemoryMark m{phase, {0, 0}};
  PetscFunctionBeginUser;
  PetscCall(ResidentMemory(a->comm, false, &m.mb));
  PetscCall(PetscInfo(nullptr, "Resident memory after the set-up's %s: %.0f to %.0f MB per rank\n", phase, m.mb[0], m.mb[1]));
  a->memory.push_back(m);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode NetworkComponent(DM dm, PetscInt p, PetscInt *key, void *out, size_t bytes)
{
  PetscInt k, nvar;
  void    *data;
  PetscFunctionBeginUser;
  PetscCall(DMNetworkGetComponent(dm, p, 0, &k, &data, &nvar));
  if (key) *key = k;
  if (out) std::memcpy(out, data, bytes); // the component storage is not aligned for doubles
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyBuildNetwork(BoltnetAssembly a)
{
  PetscFunctionBeginUser;
  a->memory.clear();
  PetscCall(MarkMemory(a, "model"));
  PetscCall(PetscLogStagePush(Events().setup_stage));
  PetscCall(PetscLogEventBegin(Events().layout, 0, 0, 0, 0));
  LayoutOptions lo;
  lo.coupling  = a->opt.coupling_type;
  lo.radius    = a->opt.coupling_radius;
  lo.reach     = a->opt.coupling_reach;
  lo.max_nodes = a->opt.patch_max_nodes < 0 ? -1 : a->opt.patch_max_nodes;
  lo.condense  = a->opt.condense;
  lo.condense_ratio = a->opt.condense_ratio;
  lo.directors = a->opt.shell_directors;
  PetscInt nrigid = 0;
  for (const PartDesc &p : a->model.parts) nrigid += p.kind == PatchKind::Rigid;
  PetscCall(LayoutCreate(a->comm, a->model, lo, &a->layout));
  a->net.ndof_model = 6 * (nrigid + a->layout.mesh_nodes + a->layout.njoint_nodes);
  a->net.ncondensed = a->layout.ncondensed;
  PetscCall(PetscLogEventEnd(Events().layout, 0, 0, 0, 0));
  PetscCall(MarkMemory(a, "layout"));

  PetscCall(PetscLogEventBegin(Events().network, 0, 0, 0, 0));
  PetscCall(CreateNetwork(a));
  PetscCall(LocalViews(a));
  PetscCall(AssemblyFetchLayout(a));
  PetscCall(PetscLogEventEnd(Events().network, 0, 0, 0, 0));
  PetscCall(PetscLogStagePop());
  PetscCall(MarkMemory(a, "network"));
  PetscCall(BuildOperators(a));
  PetscCall(MarkMemory(a, "operators"));

  PetscCall(DMCreateGlobalVector(a->net.dm, &a->X));
  PetscCall(VecGetSize(a->X, &a->net.ndof_global));
  {
    PetscInt mine = 0, nmax;
    for (const OwnedPatch &op : a->patches.owned) mine += 6 * (op.shell ? a->layout.shells.at(op.index).nnodes() : 1);
    PetscCallMPI(MPI_Allreduce(&mine, &nmax, 1, MPIU_INT, MPI_MAX, a->comm));
    a->net.dof_imbalance = a->net.ndof_model > 0 ? (PetscReal)nmax * a->size / (PetscReal)a->net.ndof_model : 1;
  }
  PetscCall(VecSet(a->X, 0.0));
  PetscCall(AssemblyCreateJacobian(a));
  PetscCall(AssemblySetUpBoundary(a));
  if (!a->opt.keep_layout) PetscCall(ReleaseUnowned(a));
  PetscCall(MarkMemory(a, "setup"));
  PetscFunctionReturn(0);
}

} // namespace boltnet
