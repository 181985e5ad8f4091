#include "patch/loads.hpp"

#include <algorithm>

namespace boltnet {

namespace {
// The consistent nodal forces of pressure p on the patch's elements in node set `set` ("": all)
// added to force: its whole elements with every node in the set, and its share (the rows of its own
// nodes) of the shared elements the cut found inside the set (ShellPatch::shared_in_set). Each
// element's share is added by the patches that hold its nodes, so the part's total is the integral
// of p n over the elements whatever the cut.
void AddPressure(const ShellPatch &sp, const std::string &set, double p, std::map<PetscInt, double> &force)
{
  std::vector<char> in(sp.mesh.x.size(), set.empty());
  if (!set.empty())
    if (auto it = sp.mesh.node_sets.find(set); it != sp.mesh.node_sets.end())
      for (int v : it->second) in[v] = 1;
  double F[24];
  for (const MeshElement &e : sp.mesh.elems) {
    const int n = ElementNodes(e);
    if (!std::all_of(e.begin(), e.begin() + n, [&](int v) { return in[v]; })) continue;
    const ElementGeometry g = GeometryOf(sp.mesh, e);
    shell::ElementPressure(n, g.X.data(), p, F);
    for (int k = 0; k < n; ++k)
      for (int d = 0; d < 3; ++d) force[6 * e[k] + d] += F[6 * k + d];
  }
  std::vector<int> shared;
  if (set.empty()) {
    shared.resize(sp.shared.size());
    for (size_t s = 0; s < shared.size(); ++s) shared[s] = (int)s;
  } else if (auto it = sp.shared_in_set.find(set); it != sp.shared_in_set.end())
    shared = it->second;
  for (int s : shared) {
    const ShellPatch::SharedElement &el = sp.shared[s];
    shell::ElementPressure(el.geom.n, el.geom.X.data(), p, F);
    for (int k = 0; k < el.geom.n; ++k)
      if (el.node[k] >= 0)
        for (int d = 0; d < 3; ++d) force[6 * el.node[k] + d] += F[6 * k + d];
  }
}

// The forces on footprint nodes, which exact coupling makes slaves of their joint node (u_s = T u_m,
// patch.hpp: SlaveTransform), moved to the joint node as T^T f_s: the same virtual work for every
// motion the coupling allows, and the slave rows, which hold the constraint, free of load. Only the
// footprints are visited (AttachJoints has given each node to one joint node).
void MoveToJointNodes(const ShellPatch &sp, std::map<PetscInt, double> &force)
{
  const PetscInt nmesh = (PetscInt)sp.mesh.x.size();
  for (size_t k = 0; k < sp.joint_nodes.size(); ++k) {
    const ShellPatch::JointNode &jn = sp.joint_nodes[k];
    std::array<double, 6>        m{};
    bool                         any = false;
    for (int n : jn.footprint) {
      auto it = force.lower_bound(6 * (PetscInt)n);
      if (it == force.end() || it->first >= 6 * (PetscInt)n + 6) continue;
      const auto T = SlaveTransform({sp.mesh.x[n][0] - jn.x[0], sp.mesh.x[n][1] - jn.x[1], sp.mesh.x[n][2] - jn.x[2]});
      for (; it != force.end() && it->first < 6 * (PetscInt)n + 6; it = force.erase(it))
        for (int j = 0; j < 6; ++j) m[j] += T[6 * (it->first % 6) + j] * it->second;
      any = true;
    }
    if (any)
      for (int j = 0; j < 6; ++j) force[6 * (nmesh + (PetscInt)k) + j] += m[j];
  }
}
} // namespace

PetscErrorCode PatchLoadsFromModel(MPI_Comm comm, const Model &model, PetscInt part_id, const ShellPatch *sp, CouplingType coupling, PatchLoads *loads)
{
  PetscFunctionBeginUser;
  loads->prescribed.clear();
  loads->force.clear();
  std::map<PetscInt, size_t> forced_by, held_by; // dof -> the condition (position in model.bcs)
  for (size_t b = 0; b < model.bcs.size(); ++b) {
    const BCDesc &bc = model.bcs[b];
    if (bc.patch != part_id) continue;
    if (bc.kind == BOLTNET_BC_PRESSURE) {
      PetscCheck(sp, comm, PETSC_ERR_USER_INPUT, "Pressure on patch %" PetscInt_FMT ": it is not a shell patch", part_id);
      std::map<PetscInt, double> f;
      AddPressure(*sp, bc.set, bc.value, f);
      if (coupling == CouplingType::Exact) MoveToJointNodes(*sp, f);
      for (const auto &[dof, v] : f) loads->force[dof] += v;
      continue;
    }
    // The nodes in this patch: a rigid patch's node; a shell patch's share of the named set, or all
    // its mesh nodes. A force is the set's total over the whole part.
    std::vector<int> nodes = {0};
    PetscInt         total = 1;
    if (sp) {
      if (bc.set.empty()) {
        nodes.resize(sp->mesh.x.size());
        for (size_t n = 0; n < nodes.size(); ++n) nodes[n] = (int)n;
      } else {
        auto it = sp->mesh.node_sets.find(bc.set);
        nodes   = it == sp->mesh.node_sets.end() ? std::vector<int>{} : it->second; // checked when the BC was added
      }
      total = sp->part_set_size.at(bc.set);
    }
    for (int n : nodes)
      for (PetscInt d = 0; d < 6; ++d) {
        if (bc.dof >= 0 && d != bc.dof) continue;
        const PetscInt dof = 6 * n + d;
        if (bc.kind == BOLTNET_BC_FORCE) {
          loads->force[dof] += bc.value / (PetscReal)total;
          forced_by[dof] = b;
        } else {
          loads->prescribed[dof] = bc.kind == BOLTNET_BC_FIXED ? 0.0 : bc.value;
          held_by[dof]           = b;
        }
      }
  }
  for (const auto &[dof, b] : forced_by) {
    auto h = held_by.find(dof);
    if (h == held_by.end()) continue;
    const BCDesc &f = model.bcs[b], &p = model.bcs[h->second];
    static const char *const names[] = {"ux", "uy", "uz", "rx", "ry", "rz"};
    SETERRQ(comm, PETSC_ERR_USER_INPUT, "Patch %" PetscInt_FMT ": a force on %s of %s is applied to a dof that is also %s (by the condition on %s): the support would absorb it; check the node sets of the boundary conditions", part_id, names[dof % 6], f.set.empty() ? "the whole patch" : ("node set '" + f.set + "'").c_str(), p.kind == BOLTNET_BC_FIXED ? "fixed" : "prescribed", p.set.empty() ? "the whole patch" : ("node set '" + p.set + "'").c_str());
  }
  PetscFunctionReturn(0);
}

} // namespace boltnet
