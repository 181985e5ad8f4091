// Shell parts cut into patches, and the nodes each patch's vertex carries (layout_steps.hpp).
#include "patch/layout_steps.hpp"
#include "mesh/cut.hpp"
#include "mesh/search.hpp"

#include <algorithm>
#include <set>

namespace boltnet {

// Cut one shell part into patches appended to L (positions first, first + 1, ...); nodemap[n] is
// the (patch position, patch node) of part node n (mesh nodes, then joint nodes).
void CutShellPart(ShellPatch &&part, PetscInt first, long max_nodes, Layout *L, NodeMap &nodemap)
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
  // The node sets each part node is in (as many entries as the sets have members, however many sets).
  std::vector<const std::string *> set_name;
  std::vector<std::vector<int>>    sets_of(n);
  for (const auto &[name, members] : part.mesh.node_sets) {
    for (int v : members) sets_of[v].push_back((int)set_name.size());
    set_name.push_back(&name);
  }
  for (std::vector<int> &l : sets_of) l.erase(std::unique(l.begin(), l.end()), l.end()); // a node listed twice in a set
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
    std::vector<const std::string *> within; // the node sets holding every node of the element
    for (int set : sets_of[q[0]])
      if (std::all_of(q.begin() + 1, q.begin() + nn, [&](int v) { return std::count(sets_of[v].begin(), sets_of[v].end(), set) > 0; })) within.push_back(set_name[set]);
    for (int s : in) {
      ShellPatch::SharedElement el{geom, {-1, -1, -1, -1}, e, q};
      for (int k = 0; k < nn; ++k) el.node[k] = cut.patch[q[k]] == s ? local[q[k]] : -1;
      for (const std::string *name : within) subs[s].shared_in_set[*name].push_back((int)subs[s].shared.size());
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

} // namespace boltnet
