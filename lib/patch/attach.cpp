// Joints attached to shell parts (layout_steps.hpp): each side's joint node and footprint found
// in its part by the part's holder, the side's reference point, and the joint's network component.
#include "patch/layout_steps.hpp"
#include "core/guard.hpp"
#include "mesh/search.hpp"

#include <algorithm>
#include <memory>
#include <string>

namespace boltnet {
namespace {

// The nodes of a shell part that a boundary condition names.
std::vector<int> BCNodes(const BCDesc &bc, const ShellMesh &mesh)
{
  if (bc.set.empty()) {
    std::vector<int> all(mesh.x.size());
    for (size_t n = 0; n < all.size(); ++n) all[n] = (int)n;
    return all;
  }
  auto it = mesh.node_sets.find(bc.set);
  return it == mesh.node_sets.end() ? std::vector<int>{} : it->second;
}

} // namespace

// Attach every joint side on a shell part: a joint node with its footprint, or (node coupling) the
// nearest mesh node. On return parts[p] holds its joint nodes and jnode[2 j + side] the node number
// in the part (mesh nodes, then joint nodes).
PetscErrorCode AttachJoints(MPI_Comm comm, Model &m, const LayoutOptions &o, std::map<PetscInt, ShellPatch> &parts, std::vector<PetscInt> &jnode)
{
  PetscFunctionBeginUser;
  const double                                   reach = o.reach > 0 ? o.reach : 4 * o.radius;
  std::map<PetscInt, std::unique_ptr<FootprintFinder>> finders;
  std::map<PetscInt, std::vector<std::array<PetscInt, 2>>> jointOf; // part -> (joint, side) per joint node
  jnode.assign(2 * m.joints.size(), 0);
  for (size_t ji = 0; ji < m.joints.size(); ++ji) {
    const JointDesc &j = m.joints[ji];
    for (int side = 0; side < 2; ++side) {
      const PetscInt pid = side ? j.part_b : j.part_a, pos = m.Find(pid);
      auto           sh  = parts.find(pos);
      if (sh == parts.end()) continue; // a rigid patch: its node 0
      auto &finder = finders[pos];
      if (!finder) PetscCall(Guard(comm, [&] {
          finder = std::make_unique<FootprintFinder>(sh->second.mesh, reach);
          return PetscErrorCode(0);
        }));
      ShellPatch::JointNode jn;
      jn.x    = j.x;
      jn.axis = {j.R[0], j.R[1], j.R[2]};
      const std::string named(j.footprint.data());
      PetscCheck(named.empty() || o.coupling != CouplingType::Node, comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT ": its footprint is node set '%s', which needs -coupling_type exact or penalty (node coupling has no footprint)", j.id, named.c_str());
      if (o.coupling == CouplingType::Node) {
        // A levered joint attaches at its side's own point (a CBUSH's GA or GB), not at x.
        const std::array<double, 3> at = j.lever ? (side ? j.at_b : j.at_a) : jn.x;
        const int nd = finder->NearestNode(at, jn.axis);
        PetscCheck(nd >= 0 && (finder->ContainingElement(jn.x, jn.axis) >= 0 || !finder->Footprint(jn.x, jn.axis, o.radius).empty()), comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " at (%g, %g, %g) mm: no element of patch %" PetscInt_FMT " contains it and no node lies within %g mm (-coupling_radius): the joint is outside the part", j.id, j.x[0], j.x[1], j.x[2], pid, o.radius);
        jnode[2 * ji + side] = nd;
        continue;
      }
      if (!named.empty()) {
        // A footprint the user named: the set's nodes, however far from the joint (a tie).
        auto set = sh->second.mesh.node_sets.find(named);
        PetscCheck(set != sh->second.mesh.node_sets.end(), comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT ": its footprint is node set '%s', which patch %" PetscInt_FMT " does not have", j.id, named.c_str(), pid);
        jn.footprint = set->second;
        std::sort(jn.footprint.begin(), jn.footprint.end());
        jn.footprint.erase(std::unique(jn.footprint.begin(), jn.footprint.end()), jn.footprint.end());
      } else {
        jn.footprint = finder->CouplingFootprint(jn.x, jn.axis, o.radius);
        PetscCheck(!jn.footprint.empty(), comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " at (%g, %g, %g) mm: no node of patch %" PetscInt_FMT " lies within the footprint radius %g mm (-coupling_radius) on a sheet within %g mm of it along its axis (-coupling_reach): the joint is outside the part", j.id, j.x[0], j.x[1], j.x[2], pid, o.radius, reach);
      }
      jnode[2 * ji + side] = sh->second.nnodes();
      sh->second.joint_nodes.push_back(jn);
      jointOf[pos].push_back({(PetscInt)ji, side});
    }
  }
  if (o.coupling != CouplingType::Exact) PetscFunctionReturn(0);
  for (auto &[pos, sp] : parts) {
    // A node in two footprints follows the nearer joint (the first one at equal distance); a
    // joint left with no node is an error naming both joints.
    const auto           &jo = jointOf[pos];
    std::map<int, size_t> taken; // node -> joint node k
    for (size_t k = 0; k < sp.joint_nodes.size(); ++k)
      for (int nd : sp.joint_nodes[k].footprint) {
        auto dist = [&](size_t kk) {
          double r2 = 0;
          for (int c = 0; c < 3; ++c) r2 += (sp.mesh.x[nd][c] - sp.joint_nodes[kk].x[c]) * (sp.mesh.x[nd][c] - sp.joint_nodes[kk].x[c]);
          return r2;
        };
        auto it = taken.find(nd);
        if (it == taken.end()) taken[nd] = k;
        else if (dist(k) < dist(it->second) * (1 - 1e-12)) it->second = k;
      }
    std::vector<std::vector<int>> kept(sp.joint_nodes.size());
    for (auto &[nd, k] : taken) kept[k].push_back(nd);
    for (size_t k = 0; k < sp.joint_nodes.size(); ++k) {
      if (kept[k].empty()) {
        const PetscInt other = m.joints[jo[taken[sp.joint_nodes[k].footprint[0]]][0]].id;
        SETERRQ(comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " on patch %" PetscInt_FMT ": every node of its footprint is nearer to joint %" PetscInt_FMT " (-coupling_type exact gives a shared node to the nearer joint): the two fasteners are too close for this mesh; refine the mesh or reduce -coupling_radius", m.joints[jo[k][0]].id, sp.id, other);
      }
      sp.joint_nodes[k].footprint = kept[k];
    }
    // A footprint node follows its joint node: it cannot also carry a boundary condition. A
    // pressure can: its share on the footprint goes to the joint node (patch/loads.hpp).
    for (const BCDesc &bc : m.bcs) {
      if (bc.patch != sp.id || bc.kind == BOLTNET_BC_PRESSURE) continue;
      for (int nd : BCNodes(bc, sp.mesh)) {
        auto it = taken.find(nd);
        if (it == taken.end()) continue;
        SETERRQ(comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT ": node %d of patch %" PetscInt_FMT " at (%g, %g, %g) mm is in its footprint and also carries a boundary condition (%s): with -coupling_type exact a footprint node follows the joint node and cannot be fixed, prescribed or loaded; move the condition, reduce -coupling_radius, or use -coupling_type penalty", m.joints[jo[it->second][0]].id, nd, sp.id, sp.mesh.x[nd][0], sp.mesh.x[nd][1], sp.mesh.x[nd][2], bc.set.empty() ? "on the whole patch" : ("node set '" + bc.set + "'").c_str());
      }
    }
  }
  PetscFunctionReturn(0);
}

// The reference point of joint j's attachment to shell patch sp at its node pnode (JointComp::pa):
// the mesh node itself (-coupling_type node), or the point of the bolt axis at the mean axial
// position of the footprint nodes, which is the mid-surface of the sheet the fastener crosses.
std::array<double, 3> ShellAttachmentPoint(const ShellPatch &sp, const JointComp &j, PetscInt pnode)
{
  const ShellMesh &m = sp.mesh;
  if (pnode < (PetscInt)m.x.size()) return m.x[pnode];
  const ShellPatch::JointNode &jn = sp.joint_nodes.at(pnode - (PetscInt)m.x.size());
  double                       s  = 0;
  for (int k : jn.footprint)
    for (int d = 0; d < 3; ++d) s += j.R[d] * (m.x[k][d] - j.x[d]);
  if (!jn.footprint.empty()) s /= (double)jn.footprint.size();
  return {j.x[0] + s * j.R[0], j.x[1] + s * j.R[1], j.x[2] + s * j.R[2]};
}

// The layout's component of joint d, at position ji in the model. A side on a rigid part is laid out
// on every rank; with `jnode` (d's attachment node in each of its parts, AttachJoints) the sides on
// the shell parts this rank holds are filled too, the others stay -1.
JointComp MakeJointComp(const Model &m, const LayoutOptions &o, const JointDesc &d, PetscInt ji, const std::vector<NodeMap> &nodemap, const PetscInt *jnode, const Layout &L)
{
  JointComp j{};
  j.id      = d.id;
  j.index   = ji;
  j.patch_a = d.part_a;
  j.patch_b = d.part_b;
  for (int k = 0; k < 3; ++k) j.x[k] = d.x[k];
  for (int k = 0; k < 9; ++k) j.R[k] = d.R[k];
  j.params = d.params;
  j.tie    = d.footprint[0] != '\0';
  j.va = j.vb = -1; // a side on a part another rank holds: filled in ShareLayout
  for (int side = 0; side < 2; ++side) {
    const PetscInt  pos  = m.Find(side ? d.part_b : d.part_a);
    const PartDesc &part = m.parts[pos];
    PetscReal      *off  = side ? j.db : j.da;
    for (int k = 0; k < 3; ++k) off[k] = (part.kind == PatchKind::Rigid && d.positioned) ? d.x[k] - part.x[k] : 0.0;
    if (nodemap[pos].empty() || (part.kind == PatchKind::Shell && !jnode)) continue;
    const auto &[v, pn] = nodemap[pos][part.kind == PatchKind::Rigid ? 0 : jnode[side]];
    (side ? j.vb : j.va)           = v;
    (side ? j.pnode_b : j.pnode_a) = pn;
    // A levered joint on a shell part with node coupling: the node carries x by a rigid lever,
    // as a rigid patch's node does (with a footprint the joint node is at x already).
    if (part.kind == PatchKind::Shell && d.lever && o.coupling == CouplingType::Node) {
      const ShellPatch &sp = L.shells.at(v);
      for (int k = 0; k < 3; ++k) off[k] = d.x[k] - sp.mesh.x[pn][k];
    }
  }
  return j;
}

} // namespace boltnet
