// The displacement field gathered to rank 0 (network/fields.hpp): the writer before the parallel one,
// kept to measure against (docs/output.md). Each rank recovers the whole
// displacement of the shell patches it owns (the interior of a condensed patch included) and the
// dof of the joints it holds; rank 0 puts them back into the user's parts.
#include "network/fields.hpp"
#include "core/log.hpp"
#include "network/gather.hpp"
#include "network/internal.hpp"

#include <algorithm>
#include <map>

namespace boltnet {
namespace {

// The dof of a joint's two attachment nodes.
struct JointDof {
  PetscInt  index; // position in the layout's joints
  PetscReal ua[6], ub[6];
};

} // namespace

PetscErrorCode AssemblyGatherFields(BoltnetAssembly a, std::vector<PartField> &parts, std::vector<JointLine> &lines)
{
  std::vector<double>      mine, all; // per owned shell patch: index, size, its dof
  std::vector<JointDof>    jmine, jall;
  std::vector<JointRecord> rec;
  Vec                      Xl;
  const PetscScalar       *x;
  PetscFunctionBeginUser;
  parts.clear();
  lines.clear();
  PetscCall(GetLocalX(a, a->X, &Xl, &x));
  std::vector<double> u;
  for (const OwnedPatch &op : a->patches.owned) {
    if (!op.shell) continue;
    PetscCall(AssemblyPatchDisplacement(a, op, x, a->lambda, u));
    mine.push_back((double)op.index);
    mine.push_back((double)u.size());
    mine.insert(mine.end(), u.begin(), u.end());
  }
  const JointSet &js = a->joints;
  for (size_t k = 0; k < js.size(); ++k) {
    JointDof d;
    d.index = js.comp[k].index;
    std::copy(x + js.oa[k], x + js.oa[k] + 6, d.ua);
    std::copy(x + js.ob[k], x + js.ob[k] + 6, d.ub);
    jmine.push_back(d);
  }
  PetscCall(RestoreLocalX(a, &Xl, &x));
  PetscCall(GatherToZero(a->comm, mine, all));
  PetscCall(GatherToZero(a->comm, jmine, jall));
  PetscCall(AssemblyGatherRecords(a, rec));
  if (a->rank != 0) PetscFunctionReturn(0);
  // Parts in the user's numbering, whatever patches they were cut into: a cut part's patches put
  // their mesh nodes back at their numbers in the part.
  std::map<PetscInt, PartField> byPart;
  for (size_t pos = 0; pos < all.size();) {
    const PetscInt    index = (PetscInt)all[pos], n = (PetscInt)all[pos + 1];
    const double     *dof   = all.data() + pos + 2;
    const ShellPatch &sp    = a->layout.shells.at(index);
    PartField        &f     = byPart[sp.id];
    if (f.x.empty()) {
      auto            cut = a->layout.cut_parts.find(sp.id);
      const ShellMesh &m  = cut == a->layout.cut_parts.end() ? sp.mesh : cut->second;
      f.id                = sp.id;
      f.x                 = m.x;
      f.elems             = m.elems;
      f.dof.assign(6 * m.x.size(), 0.0);
    }
    for (size_t l = 0; l < sp.mesh.x.size(); ++l) {
      const size_t node = sp.part_node.empty() ? l : (size_t)sp.part_node[l];
      std::copy(dof + 6 * l, dof + 6 * (l + 1), f.dof.begin() + 6 * node);
    }
    pos += 2 + n;
  }
  for (auto &kv : byPart) parts.push_back(std::move(kv.second));
  std::map<PetscInt, const JointRecord *> byId;
  for (const JointRecord &r : rec) byId[r.joint] = &r;
  for (const JointDof &d : jall) {
    const JointComp &j = a->layout.joints.at(d.index);
    JointLine        l;
    l.id = j.id;
    l.xa = {j.pa[0], j.pa[1], j.pa[2]};
    l.xb = {j.pb[0], j.pb[1], j.pb[2]};
    std::copy(d.ua, d.ua + 6, l.ua.begin());
    std::copy(d.ub, d.ub + 6, l.ub.begin());
    std::copy(j.R, j.R + 9, l.R.begin());
    const JointRecord *r = byId.at(j.id);
    l.state              = r->state;
    l.bearing            = r->bearing;
    l.slip               = {r->slip[0], r->slip[1]};
    std::copy(r->jump, r->jump + 6, l.jump.begin());
    std::copy(r->force, r->force + 6, l.force.begin());
    lines.push_back(l);
  }
  std::sort(lines.begin(), lines.end(), [](const JointLine &l, const JointLine &r) { return l.id < r.id; });
  PetscFunctionReturn(0);
}

} // namespace boltnet
