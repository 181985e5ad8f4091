// The layout (layout.hpp): checks of the model, joint attachment, cutting, ports.
#include "patch/layout.hpp"
#include "core/guard.hpp"
#include "core/hash.hpp"
#include "io/limits.hpp"
#include "mesh/cut.hpp"
#include "mesh/search.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <functional>
#include <memory>
#include <numeric>
#include <set>
#include <type_traits>

namespace boltnet {
namespace {

// The model's ids, references and supports, on rank 0, which holds every joint (the other ranks hold
// the same parts and conditions; the meshes are read later, each by one rank).
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

// The automatic patch size (LayoutOptions::max_nodes -1). A part is cut only to share it between
// ranks: with every patch kept whole, about eight patches per rank, none under 32 nodes; otherwise
// about four per rank, none under 64 nodes (the automatic choice then decides which pieces are
// condensed); no cut on one rank. Cutting a condensed part for its own sake does not pay: the
// sparse factorisation of a whole plate costs about what its pieces cost, while every cut puts a
// band of seam nodes on the interface, where each patch's S is dense over all its ports
// (docs/solver.md, "Patch size": whole plates 11 times faster than 3,000-node pieces).
long AutomaticPatchSize(std::int64_t total, PetscMPIInt size, bool condense)
{
  if (size == 1) return 0;
  const long per_rank = condense ? 4 : 8, smallest = condense ? 64 : 32;
  return std::max<long>(smallest, (long)((total + per_rank * size - 1) / (per_rank * size)));
}

// Which rank lays out each shell part (-1: a rigid part, which every rank lays out): the largest
// first, each to the rank with the fewest nodes so far (longest processing time first), the lowest
// rank among equals, so that every rank computes the same assignment.
std::vector<PetscMPIInt> AssignParts(const Model &m, PetscMPIInt size)
{
  std::vector<PetscMPIInt> holder(m.parts.size(), -1);
  std::vector<std::pair<std::size_t, PetscInt>> bysize;
  for (const auto &[pos, sp] : m.shells) bysize.push_back({sp.read ? (std::size_t)sp.size : sp.mesh.x.size(), pos});
  std::stable_sort(bysize.begin(), bysize.end(), [](const auto &a, const auto &b) { return a.first > b.first; });
  std::vector<std::size_t> load(size, 0);
  for (const auto &[n, pos] : bysize) {
    const PetscMPIInt r = (PetscMPIInt)(std::min_element(load.begin(), load.end()) - load.begin());
    holder[pos]         = r;
    load[r] += n;
  }
  return holder;
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

// What the holders of the parts found, given to every rank: each patch's record (the nodes its
// vertex carries, all its nodes, whether condensed), each seam's ends, a stub (part, section,
// condensed) for every shell patch held elsewhere, the fingerprint. Each joint's attachment on shell
// parts goes to rank 0 alone, which lays out the network's graph (network/build.cpp) with `all`, its
// components of every joint (their shell sides still to be filled): the other ranks drop the
// components of their parts' joints here and receive their own from DMNetworkDistribute. Each value
// has one writer (the holder of its part), so sums gather them.
PetscErrorCode ShareLayout(MPI_Comm comm, const std::map<PetscInt, ShellPatch> &stubs, std::vector<JointComp> &&all, Layout *L)
{
  PetscFunctionBeginUser;
  const PetscInt np = (PetscInt)L->patches.size(), ns = (PetscInt)L->seams.size(), nj = L->njoints;
  constexpr int  kP = 6; // id, kind, nodes carried, all nodes, condensed, joint nodes
  std::vector<PetscInt>      pi(kP * np, 0), si(3 * ns, 0), ji(6 * nj, 0);
  std::vector<PetscReal>     px(3 * np, 0), jx(12 * nj, 0); // per joint side: d, attachment point
  std::vector<std::uint64_t> digest(np, 0);
  for (const auto &[pos, sp] : L->shells) {
    PetscInt *q = &pi[kP * pos];
    q[0] = sp.id, q[1] = static_cast<PetscInt>(PatchKind::Shell), q[2] = (PetscInt)sp.carried.size();
    q[3] = sp.nnodes(), q[4] = sp.condensed, q[5] = (PetscInt)sp.joint_nodes.size();
    for (int k = 0; k < 3; ++k) px[3 * pos + k] = sp.mesh.x[0][k];
    Hasher h;
    h.Add(sp.part_node);
    h.Add(sp.carried);
    digest[pos] = h.h;
  }
  for (PetscInt s = 0; s < ns; ++s) {
    const Seam &sm = L->seams[s];
    if (sm.part < 0) continue; // held elsewhere
    si[3 * s] = sm.part, si[3 * s + 1] = sm.va, si[3 * s + 2] = sm.vb;
  }
  for (const JointComp &c : L->joints) // this rank's parts' joints, at their place in the model
    for (int side = 0; side < 2; ++side) {
      const PetscInt j = c.index, v = side ? c.vb : c.va;
      if (v < 0 || !L->shells.count(v)) continue; // held elsewhere, or a rigid part's (known to all)
      PetscInt *q = &ji[6 * j + 3 * side];
      q[0] = v + 1, q[1] = side ? c.pnode_b : c.pnode_a, q[2] = side ? c.node_b : c.node_a;
      const std::array<double, 3> at = ShellAttachmentPoint(L->shells.at(v), c, q[1]);
      for (int k = 0; k < 3; ++k) {
        jx[12 * j + 6 * side + k]     = side ? c.db[k] : c.da[k];
        jx[12 * j + 6 * side + 3 + k] = at[k];
      }
    }
  std::vector<JointComp>().swap(L->joints); // rank 0's are `all`; the others' come from the network
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, pi.data(), (PetscMPIInt)pi.size(), MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, px.data(), (PetscMPIInt)px.size(), MPIU_REAL, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, digest.data(), (PetscMPIInt)digest.size(), MPI_UINT64_T, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, si.data(), (PetscMPIInt)si.size(), MPIU_INT, MPI_SUM, comm));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Reduce(rank == 0 ? MPI_IN_PLACE : ji.data(), ji.data(), (PetscMPIInt)ji.size(), MPIU_INT, MPI_SUM, 0, comm));
  PetscCallMPI(MPI_Reduce(rank == 0 ? MPI_IN_PLACE : jx.data(), jx.data(), (PetscMPIInt)jx.size(), MPIU_REAL, MPI_SUM, 0, comm));

  L->nodes.assign(np, 1);
  L->ncondensed = L->njoint_nodes = 0;
  for (PetscInt pos = 0; pos < np; ++pos) {
    if (L->holder[pos] < 0) continue; // a rigid patch: laid out everywhere
    const PetscInt *q = &pi[kP * pos];
    L->patches[pos]   = PatchComp{q[0], pos, q[1], q[2], {px[3 * pos], px[3 * pos + 1], px[3 * pos + 2]}};
    L->nodes[pos]     = q[3];
    L->ncondensed += q[4];
    L->njoint_nodes += q[5];
    if (L->shells.count(pos)) continue;
    ShellPatch stub  = stubs.at(L->part_of[pos]);
    stub.condensed   = q[4] != 0;
    L->shells[pos]   = std::move(stub);
  }
  for (PetscInt s = 0; s < ns; ++s) {
    Seam &sm = L->seams[s];
    if (sm.part >= 0) continue;
    sm.part = si[3 * s], sm.va = si[3 * s + 1], sm.vb = si[3 * s + 2];
    const ShellPatch &stub = stubs.at(L->part_of[sm.va]);
    sm.material = stub.material, sm.drill = stub.drill;
  }
  PetscInt unattached = -1; // the first joint not attached on both sides (rank 0's count)
  if (rank == 0) {
    L->joints = std::move(all);
    { // the output tables' rows: the joints by increasing id (CheckModel refused an id given twice)
      std::vector<PetscInt> order(L->joints.size());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](PetscInt l, PetscInt r) { return L->joints[l].id < L->joints[r].id; });
      for (size_t r = 0; r < order.size(); ++r) L->joints[order[r]].row = (PetscInt)r;
    }
    for (PetscInt j = 0; j < nj; ++j)
      for (int side = 0; side < 2; ++side) {
        const PetscInt *q = &ji[6 * j + 3 * side];
        if (q[0] == 0) continue;
        JointComp &c = L->joints[j];
        (side ? c.vb : c.va)           = q[0] - 1;
        (side ? c.pnode_b : c.pnode_a) = q[1];
        (side ? c.node_b : c.node_a)   = q[2];
        for (int k = 0; k < 3; ++k) {
          (side ? c.db : c.da)[k] = jx[12 * j + 6 * side + k];
          (side ? c.pb : c.pa)[k] = jx[12 * j + 6 * side + 3 + k];
        }
      }
    for (JointComp &c : L->joints) // the sides on rigid patches, laid out everywhere
      for (int side = 0; side < 2; ++side) {
        const PetscInt v = side ? c.vb : c.va;
        if (v < 0 || L->holder[v] >= 0) continue;
        for (int k = 0; k < 3; ++k) (side ? c.pb : c.pa)[k] = L->patches[v].x[k] + (side ? c.db : c.da)[k];
      }
    for (const JointComp &c : L->joints)
      if (unattached < 0 && (c.va < 0 || c.vb < 0)) unattached = c.id;
  }
  PetscCallMPI(MPI_Bcast(&unattached, 1, MPIU_INT, 0, comm));
  PetscCheck(unattached < 0, comm, PETSC_ERR_PLIB, "Joint %" PetscInt_FMT " was not attached on every side", unattached);

  // The fingerprint (rank 0's, given to all): the patches in order with the nodes they carry, the
  // joints with their patches.
  char hex[64] = {0};
  if (rank == 0) {
    Hasher h;
    h.Add((std::uint64_t)np);
    for (PetscInt p = 0; p < np; ++p) {
      h.Add(L->patches[p].id);
      h.Add(L->patches[p].kind);
      h.Add(L->patches[p].nnodes);
      h.Add(digest[p]);
    }
    h.Add((std::uint64_t)nj);
    for (const JointComp &c : L->joints) {
      h.Add(c.id);
      h.Add(c.va);
      h.Add(c.vb);
    }
    std::strncpy(hex, h.Hex().c_str(), sizeof hex - 1);
  }
  PetscCallMPI(MPI_Bcast(hex, (PetscMPIInt)sizeof hex, MPI_CHAR, 0, comm));
  L->fingerprint = hex;
  PetscFunctionReturn(0);
}

// Rank 0 holds the model's joints (the scene's fastener table is read there alone, io/scene.cpp; a
// linking code may give them on every rank, and the other ranks' copies are dropped here). Each
// rank receives the joints that attach to the shell parts it holds (`holder`, AssignParts) with
// their positions in the model (`index`); rank 0 keeps the whole list in `all`, to lay out the
// network's graph. Every rank learns the number of joints.
PetscErrorCode ShareJoints(MPI_Comm comm, const std::vector<PetscMPIInt> &holder, Model &m, std::vector<JointDesc> *all, std::vector<PetscInt> *index, PetscInt *njoint)
{
  static_assert(std::is_trivially_copyable<JointDesc>::value, "joint descriptions travel as bytes");
  struct Sent {
    PetscInt  index;
    JointDesc d;
  };
  PetscMPIInt rank, size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<std::vector<Sent>> to(rank == 0 ? size : 0);
  std::vector<int>               counts(size, 0), displs(size, 0);
  std::vector<Sent>              packed;
  if (rank == 0) {
    *all = std::move(m.joints);
    for (size_t ji = 0; ji < all->size(); ++ji) {
      const JointDesc &d = (*all)[ji];
      const PetscMPIInt ra = holder[m.Find(d.part_a)], rb = holder[m.Find(d.part_b)];
      if (ra >= 0) to[ra].push_back(Sent{(PetscInt)ji, d});
      if (rb >= 0 && rb != ra) to[rb].push_back(Sent{(PetscInt)ji, d});
    }
    size_t end  = 0; // bytes packed so far: one MPI message, counted in int bytes, carries them all
    bool   fits = true;
    for (PetscMPIInt r = 0; r < size && fits; ++r) {
      const size_t bytes = to[r].size() * sizeof(Sent);
      fits               = end + bytes <= (size_t)INT_MAX;
      if (!fits) break;
      counts[r] = (int)bytes;
      displs[r] = (int)end;
      end += bytes;
      packed.insert(packed.end(), to[r].begin(), to[r].end());
    }
    std::vector<std::vector<Sent>>().swap(to);
    *njoint = fits ? (PetscInt)all->size() : -1;
  } else std::vector<JointDesc>().swap(m.joints);
  PetscCallMPI(MPI_Bcast(njoint, 1, MPIU_INT, 0, comm));
  PetscCheck(*njoint >= 0, comm, PETSC_ERR_SUP, "The model's joints are more than one message can carry to the ranks (%d bytes)", INT_MAX);
  int mine = 0;
  PetscCallMPI(MPI_Scatter(counts.data(), 1, MPI_INT, &mine, 1, MPI_INT, 0, comm));
  std::vector<Sent> got(mine / sizeof(Sent));
  PetscCallMPI(MPI_Scatterv(packed.data(), counts.data(), displs.data(), MPI_BYTE, got.data(), mine, MPI_BYTE, 0, comm));
  m.joints.clear();
  index->clear();
  for (const Sent &s : got) {
    m.joints.push_back(s.d);
    index->push_back(s.index);
  }
  std::int64_t sides = 0;
  for (const JointDesc &d : m.joints) sides += (holder[m.Find(d.part_a)] == rank) + (holder[m.Find(d.part_b)] == rank);
  PetscCall(PetscInfo(nullptr, "Attaching %zu of %" PetscInt_FMT " joints (%lld joint sides) on this rank's shell parts\n", m.joints.size(), *njoint, (long long)sides));
  PetscFunctionReturn(0);
}

// The layout's component of joint d, at position ji in the model. A side on a rigid part is laid out
// on every rank; with `jnode` (d's attachment node in each of its parts, AttachJoints) the sides on
// the shell parts this rank holds are filled too, the others stay -1.
JointComp MakeJointComp(const Model &m, const LayoutOptions &o, const JointDesc &d, PetscInt ji, const std::vector<std::vector<std::pair<PetscInt, int>>> &nodemap, const PetscInt *jnode, const Layout &L)
{
  JointComp j{};
  j.id      = d.id;
  j.index   = ji;
  j.patch_a = d.part_a;
  j.patch_b = d.part_b;
  for (int k = 0; k < 3; ++k) j.x[k] = d.x[k];
  for (int k = 0; k < 9; ++k) j.R[k] = d.R[k];
  j.params = d.params;
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

} // namespace

PetscErrorCode LayoutCreate(MPI_Comm comm, Model &m, const LayoutOptions &o, Layout *L)
{
  PetscMPIInt rank, size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(Collective(comm, "checking the model", [&]() { return rank == 0 ? CheckModel(comm, m) : PetscErrorCode(0); }));
  const PetscInt                 npart  = (PetscInt)m.parts.size();
  const std::vector<PetscMPIInt> holder = AssignParts(m, size);
  // From here m.joints is this rank's share, `all` rank 0's whole list (model/model.hpp).
  std::vector<JointDesc> all;
  std::vector<PetscInt>  jindex; // each joint of the share: its position in the model
  PetscInt               njoint = 0;
  PetscCall(ShareJoints(comm, holder, m, &all, &jindex, &njoint));

  // The shell parts this rank lays out, read (ShellPart::read) and checked, as patches before any
  // cut; of the others, what a stub needs.
  std::map<PetscInt, ShellPatch> parts, stubs;
  std::vector<std::int64_t>      meshnodes(npart, 0);
  PetscCall(Collective(comm, "reading the parts", [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    for (auto &[pos, sp] : m.shells) {
      ShellPatch p;
      p.id       = m.parts[pos].id;
      p.material = sp.material;
      p.drill    = sp.drill;
      if (holder[pos] != rank) {
        stubs[pos] = std::move(p);
        continue;
      }
      if (sp.read) PetscCall(sp.read(&sp.mesh));
      PetscCheck(!sp.mesh.elems.empty(), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Shell patch %" PetscInt_FMT ": a mesh needs at least one element", p.id);
      for (const BCDesc &bc : m.bcs) PetscCheck(bc.patch != p.id || bc.set.empty() || sp.mesh.node_sets.count(bc.set), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Boundary condition on patch %" PetscInt_FMT ": it has no node set '%s'", p.id, bc.set.c_str());
      meshnodes[pos] = (std::int64_t)sp.mesh.x.size();
      p.mesh         = std::move(sp.mesh);
      parts[pos]     = std::move(p);
    }
    PetscFunctionReturn(0);
  }));
  m.shells.clear();
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, meshnodes.data(), (PetscMPIInt)npart, MPI_INT64_T, MPI_SUM, comm));
  std::int64_t mesh_nodes = 0;
  for (std::int64_t n : meshnodes) mesh_nodes += n;
  PetscCheck(mesh_nodes <= limits::kMaxSceneNodes, comm, PETSC_ERR_USER_INPUT, "The shell parts have %lld nodes, more than the limit of %lld (docs/scenes.md, \"Limits\")", (long long)mesh_nodes, (long long)limits::kMaxSceneNodes);
  {
    std::int64_t mine = 0;
    for (const auto &[pos, p] : parts) mine += meshnodes[pos];
    PetscCall(PetscInfo(nullptr, "Read and laid out %zu of %zu shell parts (%lld of %lld mesh nodes) on this rank\n", parts.size(), parts.size() + stubs.size(), (long long)mine, (long long)mesh_nodes));
  }
  const long max_nodes = o.max_nodes >= 0 ? o.max_nodes : AutomaticPatchSize(mesh_nodes, size, o.condense != Condense::None);

  // Attach the joints and cut the parts, each part into a layout of its own with patch positions
  // from 0. Only the holder of a part knows it: errors are raised on every rank (Collective).
  std::vector<PetscInt>                               jnode;
  std::map<PetscInt, Layout>                          cuts;
  std::vector<std::vector<std::pair<PetscInt, int>>> nodemap(npart);
  std::vector<PetscInt>                               count(2 * npart, 0); // patches, seams of each part
  PetscCall(Collective(comm, "laying out the parts", [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    for (auto &[pos, p] : parts)
      if (o.directors) p.mesh.directors = NodalDirectors(p.mesh); // empty on a flat part
    PetscCall(AttachJoints(comm, m, o, parts, jnode));
    for (auto &[pos, p] : parts) {
      Layout &one = cuts[pos];
      CutShellPart(std::move(p), 0, max_nodes, &one, nodemap[pos]);
      count[2 * pos]     = (PetscInt)one.shells.size();
      count[2 * pos + 1] = (PetscInt)one.seams.size();
    }
    PetscFunctionReturn(0);
  }));
  parts.clear();
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, count.data(), (PetscMPIInt)count.size(), MPIU_INT, MPI_SUM, comm));

  // Every part's first patch and seam, the same on every rank.
  *L            = Layout{};
  L->nparts     = npart;
  L->mesh_nodes = (PetscInt)mesh_nodes;
  std::vector<PetscInt> first(npart), sfirst(npart);
  PetscInt              npatch = 0, nseam = 0;
  for (PetscInt i = 0; i < npart; ++i) {
    const bool shell = m.parts[i].kind == PatchKind::Shell;
    first[i]         = npatch;
    sfirst[i]        = nseam;
    npatch += shell ? count[2 * i] : 1;
    nseam += shell ? count[2 * i + 1] : 0;
    for (PetscInt s = first[i]; s < npatch; ++s) {
      L->part_of.push_back(i);
      L->holder.push_back(shell ? holder[i] : -1);
    }
  }
  L->patches.assign(npatch, PatchComp{});
  L->seams.resize(nseam);
  for (PetscInt i = 0; i < npart; ++i) {
    if (m.parts[i].kind == PatchKind::Shell) continue;
    L->patches[first[i]] = PatchComp{m.parts[i].id, first[i], static_cast<PetscInt>(PatchKind::Rigid), 1, {m.parts[i].x[0], m.parts[i].x[1], m.parts[i].x[2]}};
    nodemap[i]           = {{first[i], 0}};
  }
  for (auto &[pos, one] : cuts) { // this rank's parts, placed
    for (auto &[k, sp] : one.shells) L->shells[first[pos] + k] = std::move(sp);
    for (size_t s = 0; s < one.seams.size(); ++s) {
      Seam &sm = one.seams[s];
      sm.va += first[pos];
      sm.vb += first[pos];
      L->seams[sfirst[pos] + s] = std::move(sm);
    }
    for (auto &kv : one.cut_parts) L->cut_parts[kv.first] = std::move(kv.second);
    for (auto &nm : nodemap[pos]) nm.first += first[pos];
  }
  cuts.clear();
  // The components of this rank's parts' joints, attached on the sides it holds; rank 0 also makes
  // one of every joint, whose shell sides ShareLayout fills from the holders' attachments.
  for (size_t k = 0; k < m.joints.size(); ++k) L->joints.push_back(MakeJointComp(m, o, m.joints[k], jindex[k], nodemap, &jnode[2 * k], *L));
  std::vector<JointComp> full;
  for (size_t ji = 0; ji < all.size(); ++ji) full.push_back(MakeJointComp(m, o, all[ji], (PetscInt)ji, nodemap, nullptr, *L));
  std::vector<JointDesc>().swap(all);
  L->njoints = njoint;
  Carry(L, o);
  PetscCall(ShareLayout(comm, stubs, std::move(full), L));
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
