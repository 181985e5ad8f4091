// The displacement field gathered to rank 0 (network/fields.hpp). X is scattered whole to rank 0;
// each rank names, for the vertices it owns and the edges it holds, where their dof start in X.
#include "network/fields.hpp"
#include "network/gather.hpp"

#include <algorithm>
#include <map>

namespace boltnet {
namespace {

constexpr PetscInt kNodeDof = 6;

// Where the dof of a patch or of a joint's two nodes start in the global vector.
struct Offsets {
  PetscInt index;  // position in a->patches, or in a->joints
  PetscInt a, b;   // global offsets (b: joints only)
  PetscInt pa, pb; // joints: positions in a->patches of the patches of their two nodes
};

// The reference point of a joint's attachment to one side: a rigid patch's node; on a shell patch,
// the point of the bolt axis at the mean axial position of the footprint nodes (the mid-surface).
std::array<double, 3> AttachmentPoint(BoltnetAssembly a, const JointComp &j, PetscInt pos, PetscInt node)
{
  auto sh = a->shells.find(pos);
  if (sh == a->shells.end()) return {a->patches[pos].x[0], a->patches[pos].x[1], a->patches[pos].x[2]};
  const QuadMesh &m = sh->second.mesh;
  if (node < (PetscInt)m.x.size()) return m.x[node]; // attached to a mesh node (-coupling_type node)
  const ShellPatch::JointNode &jn = sh->second.joint_nodes.at(node - (PetscInt)m.x.size());
  double                       s  = 0;
  for (int k : jn.footprint)
    for (int d = 0; d < 3; ++d) s += j.R[d] * (m.x[k][d] - j.x[d]);
  if (!jn.footprint.empty()) s /= (double)jn.footprint.size();
  return {j.x[0] + s * j.R[0], j.x[1] + s * j.R[1], j.x[2] + s * j.R[2]};
}

} // namespace

PetscErrorCode AssemblyGatherFields(BoltnetAssembly a, std::vector<PartField> &parts, std::vector<JointLine> &lines)
{
  std::vector<Offsets>     vmine, emine, vall, eall;
  std::vector<JointRecord> rec;
  VecScatter               scatter;
  Vec                      X0;
  PetscFunctionBeginUser;
  parts.clear();
  lines.clear();
  for (PetscInt v = a->vStart; v < a->vEnd; ++v) {
    PetscBool ghost;
    PetscInt  key, nvar, goff;
    void     *data;
    PetscCall(DMNetworkIsGhostVertex(a->dm, v, &ghost));
    if (ghost) continue;
    PetscCall(DMNetworkGetComponent(a->dm, v, 0, &key, &data, &nvar));
    const PatchComp *p = static_cast<const PatchComp *>(data);
    if (p->kind != static_cast<PetscInt>(PatchKind::Shell)) continue;
    PetscCall(DMNetworkGetGlobalVecOffset(a->dm, v, ALL_COMPONENTS, &goff));
    vmine.push_back({p->index, goff, -1, -1, -1});
  }
  for (PetscInt e : a->jedges) {
    PetscInt        key, nvar, ga, gb;
    void           *data, *va, *vb;
    const PetscInt *cone;
    PetscCall(DMNetworkGetComponent(a->dm, e, 0, &key, &data, &nvar));
    PetscCall(DMNetworkGetConnectedVertices(a->dm, e, &cone));
    PetscCall(DMNetworkGetComponent(a->dm, cone[0], 0, &key, &va, &nvar));
    PetscCall(DMNetworkGetComponent(a->dm, cone[1], 0, &key, &vb, &nvar));
    const JointComp *j = static_cast<const JointComp *>(data);
    PetscCall(DMNetworkGetGlobalVecOffset(a->dm, cone[0], ALL_COMPONENTS, &ga));
    PetscCall(DMNetworkGetGlobalVecOffset(a->dm, cone[1], ALL_COMPONENTS, &gb));
    emine.push_back({j->index, ga + kNodeDof * j->node_a, gb + kNodeDof * j->node_b, static_cast<const PatchComp *>(va)->index, static_cast<const PatchComp *>(vb)->index});
  }
  PetscCall(GatherToZero(a->comm, vmine, vall));
  PetscCall(GatherToZero(a->comm, emine, eall));
  PetscCall(AssemblyGatherRecords(a, rec));
  PetscCall(VecScatterCreateToZero(a->X, &scatter, &X0));
  PetscCall(VecScatterBegin(scatter, a->X, X0, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(scatter, a->X, X0, INSERT_VALUES, SCATTER_FORWARD));
  if (a->rank == 0) {
    const PetscScalar *x;
    PetscCall(VecGetArrayRead(X0, &x));
    // Parts in the user's numbering, whatever patches they were cut into: a cut part's patches put
    // their mesh nodes back at their numbers in the part (patch mesh nodes first, then joint nodes).
    std::map<PetscInt, PartField> byPart;
    for (const Offsets &o : vall) {
      const ShellPatch &sp = a->shells.at(o.index);
      PartField        &f  = byPart[sp.id];
      if (f.x.empty()) {
        auto cut = a->cut_parts.find(sp.id);
        const QuadMesh &m = cut == a->cut_parts.end() ? sp.mesh : cut->second;
        f.id    = sp.id;
        f.x     = m.x;
        f.quads = m.quads;
        f.dof.assign(kNodeDof * m.x.size(), 0.0);
      }
      for (size_t l = 0; l < sp.mesh.x.size(); ++l) {
        const size_t n = sp.part_node.empty() ? l : (size_t)sp.part_node[l];
        std::copy(x + o.a + kNodeDof * l, x + o.a + kNodeDof * (l + 1), f.dof.begin() + kNodeDof * n);
      }
    }
    for (auto &kv : byPart) parts.push_back(std::move(kv.second));
    std::map<PetscInt, const JointRecord *> byId;
    for (const JointRecord &r : rec) byId[r.joint] = &r;
    for (const Offsets &o : eall) {
      const JointComp &j = a->joints.at(o.index);
      JointLine        l;
      l.id = j.id;
      l.xa = AttachmentPoint(a, j, o.pa, j.node_a);
      l.xb = AttachmentPoint(a, j, o.pb, j.node_b);
      for (int i = 0; i < kNodeDof; ++i) {
        l.ua[i] = x[o.a + i];
        l.ub[i] = x[o.b + i];
      }
      std::copy(j.R, j.R + 9, l.R.begin());
      const JointRecord *r = byId.at(j.id);
      l.state              = r->state;
      std::copy(r->jump, r->jump + 6, l.jump.begin());
      std::copy(r->force, r->force + 6, l.force.begin());
      lines.push_back(l);
    }
    std::sort(lines.begin(), lines.end(), [](const JointLine &l, const JointLine &r) { return l.id < r.id; });
    PetscCall(VecRestoreArrayRead(X0, &x));
  }
  PetscCall(VecScatterDestroy(&scatter));
  PetscCall(VecDestroy(&X0));
  PetscFunctionReturn(0);
}

} // namespace boltnet
