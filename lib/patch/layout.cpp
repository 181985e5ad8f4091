// The layout (layout.hpp): checks of the model, joint attachment, cutting, ports.
#include "patch/layout.hpp"
#include "core/guard.hpp"
#include "core/hash.hpp"
#include "mesh/cut.hpp"
#include "mesh/search.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <set>

namespace boltnet {
namespace {

// The model's ids, references and supports (collective: every rank holds the same model).
PetscErrorCode CheckModel(MPI_Comm comm, const Model &m)
{
  PetscFunctionBeginUser;
  const PetscInt npart = (PetscInt)m.parts.size(), njoint = (PetscInt)m.joints.size();
  PetscCheck(npart > 0 && njoint > 0, comm, PETSC_ERR_USER_INPUT, "The assembly needs at least one patch and one joint (it has %" PetscInt_FMT " patches, %" PetscInt_FMT " joints)", npart, njoint);
  std::map<PetscInt, PetscInt> index;
  for (PetscInt i = 0; i < npart; ++i) {
    PetscCheck(!index.count(m.parts[i].id), comm, PETSC_ERR_USER_INPUT, "Patch id %" PetscInt_FMT " is given twice", m.parts[i].id);
    index[m.parts[i].id] = i;
  }
  std::set<PetscInt>    seen;
  std::vector<PetscInt> degree(npart, 0), group(npart);
  for (const JointDesc &j : m.joints) {
    PetscCheck(!seen.count(j.id), comm, PETSC_ERR_USER_INPUT, "Joint id %" PetscInt_FMT " is given twice", j.id);
    seen.insert(j.id);
    auto ia = index.find(j.part_a), ib = index.find(j.part_b);
    PetscCheck(ia != index.end(), comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " names patch %" PetscInt_FMT " which does not exist", j.id, j.part_a);
    PetscCheck(ib != index.end(), comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " names patch %" PetscInt_FMT " which does not exist", j.id, j.part_b);
    PetscCheck(ia->second != ib->second, comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " joins patch %" PetscInt_FMT " to itself", j.id, j.part_a);
    degree[ia->second]++;
    degree[ib->second]++;
  }
  for (PetscInt i = 0; i < npart; ++i) PetscCheck(degree[i] > 0, comm, PETSC_ERR_USER_INPUT, "Patch %" PetscInt_FMT " is not joined to anything: every patch needs at least one joint", m.parts[i].id);
  for (const BCDesc &bc : m.bcs) PetscCheck(index.count(bc.patch), comm, PETSC_ERR_USER_INPUT, "A boundary condition names patch %" PetscInt_FMT " which does not exist", bc.patch);
  // Every group of parts joined by joints needs a prescribed displacement somewhere, else it can
  // move as a rigid body and the model is singular. Partial supports are not checked here: the
  // factorisations report what is left.
  for (PetscInt i = 0; i < npart; ++i) group[i] = i;
  std::function<PetscInt(PetscInt)> root = [&](PetscInt i) { return group[i] == i ? i : group[i] = root(group[i]); };
  for (const JointDesc &j : m.joints) group[root(index[j.part_a])] = root(index[j.part_b]);
  std::vector<char> supported(npart, 0);
  for (const BCDesc &bc : m.bcs)
    if (bc.kind != BOLTNET_BC_FORCE) supported[root(index[bc.patch])] = 1;
  std::string free;
  for (PetscInt i = 0; i < npart; ++i)
    if (!supported[root(i)]) free += (free.empty() ? "" : ", ") + std::to_string(m.parts[i].id);
  PetscCheck(free.empty(), comm, PETSC_ERR_USER_INPUT, "Patch(es) %s and the joints between them have no fixed or prescribed dof: the model is singular (a rigid-body motion); fix or prescribe a dof of one of them", free.c_str());
  PetscFunctionReturn(0);
}

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
      if (o.coupling == CouplingType::Node) {
        // A levered joint attaches at its side's own point (a CBUSH's GA or GB), not at x.
        const std::array<double, 3> at = j.lever ? (side ? j.at_b : j.at_a) : jn.x;
        const int nd = finder->NearestNode(at, jn.axis);
        PetscCheck(nd >= 0 && (finder->ContainingElement(jn.x, jn.axis) >= 0 || !finder->Footprint(jn.x, jn.axis, o.radius).empty()), comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " at (%g, %g, %g) mm: no element of patch %" PetscInt_FMT " contains it and no node lies within %g mm (-coupling_radius): the joint is outside the part", j.id, j.x[0], j.x[1], j.x[2], pid, o.radius);
        jnode[2 * ji + side] = nd;
        continue;
      }
      jn.footprint = finder->CouplingFootprint(jn.x, jn.axis, o.radius);
      PetscCheck(!jn.footprint.empty(), comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " at (%g, %g, %g) mm: no node of patch %" PetscInt_FMT " lies within the footprint radius %g mm (-coupling_radius) on a sheet within %g mm of it along its axis (-coupling_reach): the joint is outside the part", j.id, j.x[0], j.x[1], j.x[2], pid, o.radius, reach);
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
    // A footprint node follows its joint node: it cannot also carry a boundary condition.
    for (const BCDesc &bc : m.bcs) {
      if (bc.patch != sp.id) continue;
      for (int nd : BCNodes(bc, sp.mesh)) {
        auto it = taken.find(nd);
        if (it == taken.end()) continue;
        SETERRQ(comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT ": node %d of patch %" PetscInt_FMT " at (%g, %g, %g) mm is in its footprint and also carries a boundary condition (%s): with -coupling_type exact a footprint node follows the joint node and cannot be fixed, prescribed or loaded; move the condition, reduce -coupling_radius, or use -coupling_type penalty", m.joints[jo[it->second][0]].id, nd, sp.id, sp.mesh.x[nd][0], sp.mesh.x[nd][1], sp.mesh.x[nd][2], bc.set.empty() ? "on the whole patch" : ("node set '" + bc.set + "'").c_str());
      }
    }
  }
  PetscFunctionReturn(0);
}

// Cut one shell part into patches appended to L (positions first, first + 1, ...); nodemap[n] is
// the (patch position, patch node) of part node n (mesh nodes, then joint nodes).
void CutShellPart(ShellPatch &&part, PetscInt first, long max_nodes, Layout *L, std::vector<std::pair<PetscInt, int>> &nodemap)
{
  const int n = (int)part.mesh.x.size();
  part.part_set_size[""] = n;
  for (const auto &kv : part.mesh.node_sets) part.part_set_size[kv.first] = (PetscInt)kv.second.size();
  // A footprint and every element touching it stay in one patch: no seam may touch a footprint
  // node, since exact coupling eliminates those nodes inside the patch's operator.
  std::vector<std::vector<int>> clusters;
  if (!part.joint_nodes.empty()) {
    const auto touching = NodeElements(part.mesh);
    for (const auto &jn : part.joint_nodes) {
      std::set<int> c(jn.footprint.begin(), jn.footprint.end());
      for (int v : jn.footprint)
        for (int e : touching[v]) c.insert(part.mesh.elems[e].begin(), part.mesh.elems[e].begin() + ElementNodes(part.mesh.elems[e]));
      clusters.emplace_back(c.begin(), c.end());
    }
  }
  const PartCut cut = CutPart(part.mesh, clusters, max_nodes);
  nodemap.resize(part.nnodes());
  if (cut.npatches == 1) {
    for (int v = 0; v < part.nnodes(); ++v) nodemap[v] = {first, v};
    L->shells[first] = std::move(part);
    return;
  }
  std::vector<ShellPatch> subs(cut.npatches);
  for (ShellPatch &sub : subs) {
    sub.id            = part.id;
    sub.material      = part.material;
    sub.drill         = part.drill;
    sub.part_set_size = part.part_set_size;
    for (const auto &kv : part.mesh.node_sets) sub.mesh.node_sets[kv.first]; // every set exists in every patch
  }
  std::vector<int> local(n);
  for (int v = 0; v < n; ++v) {
    ShellPatch &sub = subs[cut.patch[v]];
    local[v]        = (int)sub.mesh.x.size();
    sub.mesh.x.push_back(part.mesh.x[v]);
    if (!part.mesh.directors.empty()) sub.mesh.directors.push_back(part.mesh.directors[v]);
    sub.part_node.push_back(v);
    nodemap[v] = {first + cut.patch[v], local[v]};
  }
  std::map<std::pair<int, int>, Seam> seams;
  for (int e = 0; e < (int)part.mesh.elems.size(); ++e) {
    const MeshElement &q  = part.mesh.elems[e];
    const int          nn = ElementNodes(q);
    std::set<int> in;
    for (int k = 0; k < nn; ++k) in.insert(cut.patch[q[k]]);
    if (in.size() == 1) {
      MeshElement own = {-1, -1, -1, -1};
      for (int k = 0; k < nn; ++k) own[k] = local[q[k]];
      subs[*in.begin()].mesh.elems.push_back(own);
      subs[*in.begin()].part_elem.push_back(e);
      continue;
    }
    // The geometry and directors of the whole part: a shared element is the same element in every
    // patch and seam that adds a share of it.
    const ElementGeometry geom = GeometryOf(part.mesh, q);
    for (int s : in) {
      ShellPatch::SharedElement el{geom, {-1, -1, -1, -1}, e, q};
      for (int k = 0; k < nn; ++k) el.node[k] = cut.patch[q[k]] == s ? local[q[k]] : -1;
      subs[s].shared.push_back(el);
    }
    for (int s : in)
      for (int t : in) {
        if (t <= s) continue;
        Seam::Element el{geom, {-1, -1, -1, -1}, {-1, -1, -1, -1}};
        for (int k = 0; k < nn; ++k) {
          const int p = cut.patch[q[k]];
          el.side[k]  = p == s ? 0 : p == t ? 1 : -1;
          el.node[k]  = el.side[k] < 0 ? -1 : local[q[k]];
        }
        seams[{s, t}].elems.push_back(el);
      }
  }
  for (const auto &kv : part.mesh.node_sets)
    for (int v : kv.second) subs[cut.patch[v]].mesh.node_sets[kv.first].push_back(local[v]);
  for (size_t k = 0; k < part.joint_nodes.size(); ++k) { // the whole footprint is in one patch (CutPart)
    ShellPatch::JointNode jn = part.joint_nodes[k];
    const int             s  = cut.patch[jn.footprint.empty() ? 0 : jn.footprint[0]];
    for (int &v : jn.footprint) v = local[v];
    nodemap[n + k] = {first + s, (int)(subs[s].mesh.x.size() + subs[s].joint_nodes.size())};
    subs[s].joint_nodes.push_back(jn);
  }
  for (int s = 0; s < cut.npatches; ++s) L->shells[first + s] = std::move(subs[s]);
  for (auto &[st, sm] : seams) {
    sm.part     = part.id;
    sm.va       = first + st.first;
    sm.vb       = first + st.second;
    sm.material = part.material;
    sm.drill    = part.drill;
    L->seams.push_back(std::move(sm));
  }
  L->cut_parts[part.id] = std::move(part.mesh);
}

// The nodes each shell vertex carries: all of them, or, for a condensed patch, its ports (joint
// nodes, attachment nodes of node-coupled joints, nodes in elements shared with another patch), in
// increasing node order. Which patches are condensed: o.condense.
void Carry(Layout *L, const LayoutOptions &o)
{
  std::map<PetscInt, std::set<int>> ports;
  for (const JointComp &j : L->joints) {
    if (L->shells.count(j.va)) ports[j.va].insert((int)j.pnode_a);
    if (L->shells.count(j.vb)) ports[j.vb].insert((int)j.pnode_b);
  }
  for (const auto &[pos, sp] : L->shells)
    for (const auto &el : sp.shared)
      for (int k = 0; k < 4; ++k)
        if (el.node[k] >= 0) ports[pos].insert(el.node[k]);
  for (auto &[pos, sp] : L->shells) {
    const std::set<int> &pp = ports[pos];
    switch (o.condense) {
    case Condense::None: sp.condensed = false; break;
    case Condense::All: sp.condensed = true; break;
    case Condense::Auto: sp.condensed = CondensePatchPays(6 * (PetscInt)pp.size(), 6 * sp.nnodes(), o.condense_ratio); break;
    }
    sp.carried.clear();
    sp.carried_index.clear();
    if (sp.condensed) sp.carried.assign(pp.begin(), pp.end());
    else
      for (int v = 0; v < sp.nnodes(); ++v) sp.carried.push_back(v);
    for (size_t i = 0; i < sp.carried.size(); ++i) sp.carried_index[sp.carried[i]] = (int)i;
    L->patches[pos].nnodes = (PetscInt)sp.carried.size();
  }
  for (JointComp &j : L->joints) {
    j.node_a = L->shells.count(j.va) ? L->shells[j.va].carried_index.at((int)j.pnode_a) : 0;
    j.node_b = L->shells.count(j.vb) ? L->shells[j.vb].carried_index.at((int)j.pnode_b) : 0;
  }
  for (Seam &sm : L->seams)
    for (auto &el : sm.elems)
      for (int k = 0; k < 4; ++k)
        if (el.side[k] >= 0) el.node[k] = L->shells[el.side[k] ? sm.vb : sm.va].carried_index.at(el.node[k]);
}

// Layout::fingerprint: the patches with the nodes they carry, the joints with their patches.
std::string Fingerprint(const Layout &L)
{
  Hasher h;
  h.Add((std::uint64_t)L.patches.size());
  for (size_t p = 0; p < L.patches.size(); ++p) {
    h.Add(L.patches[p].id);
    h.Add(L.patches[p].kind);
    h.Add(L.patches[p].nnodes);
    const auto sh = L.shells.find((PetscInt)p);
    if (sh == L.shells.end()) continue;
    h.Add(sh->second.part_node);
    h.Add(sh->second.carried);
  }
  h.Add((std::uint64_t)L.joints.size());
  for (const JointComp &j : L.joints) {
    h.Add(j.id);
    h.Add(j.va);
    h.Add(j.vb);
  }
  return h.Hex();
}

} // namespace

PetscErrorCode LayoutCreate(MPI_Comm comm, Model &m, const LayoutOptions &o, Layout *L)
{
  PetscFunctionBeginUser;
  PetscCall(CheckModel(comm, m));
  // The shell parts as patches, before any cut.
  std::map<PetscInt, ShellPatch> parts;
  for (auto &[pos, sp] : m.shells) {
    ShellPatch p;
    p.id       = m.parts[pos].id;
    p.mesh     = std::move(sp.mesh);
    if (o.directors) p.mesh.directors = NodalDirectors(p.mesh); // empty on a flat part
    p.material = sp.material;
    p.drill    = sp.drill;
    parts[pos] = std::move(p);
  }
  m.shells.clear();
  std::vector<PetscInt> jnode;
  PetscCall(AttachJoints(comm, m, o, parts, jnode));

  // Cut the parts; every part becomes one or more patches.
  *L        = Layout{};
  L->nparts = (PetscInt)m.parts.size();
  std::vector<std::vector<std::pair<PetscInt, int>>> nodemap(m.parts.size());
  for (size_t i = 0; i < m.parts.size(); ++i) {
    const PetscInt first = (PetscInt)L->patches.size();
    auto           sh    = parts.find((PetscInt)i);
    if (sh == parts.end()) {
      L->patches.push_back(PatchComp{m.parts[i].id, first, static_cast<PetscInt>(PatchKind::Rigid), 1, {m.parts[i].x[0], m.parts[i].x[1], m.parts[i].x[2]}});
      L->part_of.push_back((PetscInt)i);
      nodemap[i] = {{first, 0}};
      continue;
    }
    PetscCall(Guard(comm, [&] {
      CutShellPart(std::move(sh->second), first, o.max_nodes, L, nodemap[i]);
      return PetscErrorCode(0);
    }));
    for (PetscInt s = first; L->shells.count(s); ++s) { // the patches the part was cut into
      const ShellPatch &sp = L->shells.at(s);
      PatchComp         q{m.parts[i].id, s, static_cast<PetscInt>(PatchKind::Shell), sp.nnodes(), {sp.mesh.x[0][0], sp.mesh.x[0][1], sp.mesh.x[0][2]}};
      L->patches.push_back(q);
      L->part_of.push_back((PetscInt)i);
    }
  }
  for (size_t ji = 0; ji < m.joints.size(); ++ji) {
    const JointDesc &d = m.joints[ji];
    JointComp        j{};
    j.id      = d.id;
    j.index   = (PetscInt)ji;
    j.patch_a = d.part_a;
    j.patch_b = d.part_b;
    for (int k = 0; k < 3; ++k) j.x[k] = d.x[k];
    for (int k = 0; k < 9; ++k) j.R[k] = d.R[k];
    j.params                    = d.params;
    std::tie(j.va, j.pnode_a)   = nodemap[m.Find(d.part_a)][jnode[2 * ji]];
    std::tie(j.vb, j.pnode_b)   = nodemap[m.Find(d.part_b)][jnode[2 * ji + 1]];
    for (int side = 0; side < 2; ++side) {
      const PartDesc &part = m.parts[m.Find(side ? d.part_b : d.part_a)];
      PetscReal      *off  = side ? j.db : j.da;
      for (int k = 0; k < 3; ++k) off[k] = (part.kind == PatchKind::Rigid && d.positioned) ? d.x[k] - part.x[k] : 0.0;
      // A levered joint on a shell part with node coupling: the node carries x by a rigid lever,
      // as a rigid patch's node does (with a footprint the joint node is at x already).
      if (part.kind == PatchKind::Shell && d.lever && o.coupling == CouplingType::Node) {
        const ShellPatch &sp = L->shells.at(side ? j.vb : j.va);
        const PetscInt    pn = side ? j.pnode_b : j.pnode_a;
        for (int k = 0; k < 3; ++k) off[k] = d.x[k] - sp.mesh.x[pn][k];
      }
    }
    L->joints.push_back(j);
  }
  Carry(L, o);
  L->fingerprint = Fingerprint(*L);
  PetscFunctionReturn(0);
}

bool CondensePatchPays(PetscInt nb, PetscInt n, double ratio)
{
  return (double)nb <= ratio * std::sqrt((double)n);
}

std::vector<PetscInt> LayoutEdgeList(const Layout &L)
{
  std::vector<PetscInt> e;
  e.reserve(2 * (L.joints.size() + L.seams.size()));
  for (const JointComp &j : L.joints) e.insert(e.end(), {j.va, j.vb});
  for (const Seam &s : L.seams) e.insert(e.end(), {s.va, s.vb});
  return e;
}

} // namespace boltnet
