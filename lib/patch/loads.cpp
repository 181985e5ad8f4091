#include "patch/loads.hpp"

namespace boltnet {

PetscErrorCode PatchLoadsFromModel(MPI_Comm comm, const Model &model, PetscInt part_id, const ShellPatch *sp, PatchLoads *loads)
{
  PetscFunctionBeginUser;
  loads->prescribed.clear();
  loads->force.clear();
  std::map<PetscInt, size_t> forced_by, held_by; // dof -> the condition (position in model.bcs)
  for (size_t b = 0; b < model.bcs.size(); ++b) {
    const BCDesc &bc = model.bcs[b];
    if (bc.patch != part_id) continue;
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
