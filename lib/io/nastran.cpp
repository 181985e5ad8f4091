// A Nastran deck as a scene source (docs/nastran.md, "From a deck to a model"): the model of one
// subcase (nastran/model.hpp) described into an assembly, with the fastener table that turns
// chosen CBUSH/CFAST into macroelements of a joint type (-joint_<type>_*, as a scene's joints).
#include "io/io.hpp"
#include "io/input.hpp"
#include "io/table.hpp"
#include "nastran/model.hpp"
#include "nastran/petsc.hpp"

#include <map>
#include <set>
#include <stdexcept>

namespace boltnet {

namespace {

// A row of the fastener table: elements first..last (inclusive) or property pid -> joint type.
struct FastenerRule {
  PetscInt    first = -1, last = -1, pid = -1;
  std::string type;
  int         line = 0;
  bool        used = false;
};

PetscErrorCode ReadFastenerTable(MPI_Comm comm, const std::string &path, std::vector<FastenerRule> *rules)
{
  std::string text;
  PetscFunctionBeginUser;
  PetscCall(ReadFileCollective(comm, path, "Nastran fastener table (-nastran_fasteners)", &text));
  PetscCall(Input(comm, "turning the Nastran deck into a model", [&] {
    const Table t = ParseTable(path, text, {"type"});
    const bool  by_element = t.Has("first"), by_pid = t.Has("pid");
    if (!by_element && !by_pid) throw std::runtime_error(path + ": the fastener table needs a column 'first' (element id, with 'last' for a range) or 'pid' (PBUSH/PFAST id)");
    for (size_t r = 0; r < t.rows.size(); ++r) {
      FastenerRule f;
      f.line = t.lines[r];
      f.type = TableCell(t, r, "type");
      if (f.type.empty() || f.type.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789") != std::string::npos)
        throw std::runtime_error(path + " line " + std::to_string(f.line) + ": joint type '" + f.type + "' must be lower-case letters and digits (it names the options -joint_<type>_*)");
      const bool has_first = by_element && !TableCell(t, r, "first").empty(), has_pid = by_pid && !TableCell(t, r, "pid").empty();
      if (has_first == has_pid) throw std::runtime_error(path + " line " + std::to_string(f.line) + ": give either 'first' (and 'last') or 'pid', not both nor neither");
      if (has_pid) f.pid = (PetscInt)TableInt(t, r, "pid", 1, 99999999);
      else {
        f.first = (PetscInt)TableInt(t, r, "first", 1, 99999999);
        f.last  = t.Has("last") && !TableCell(t, r, "last").empty() ? (PetscInt)TableInt(t, r, "last", f.first, 99999999) : f.first;
      }
      rules->push_back(f);
    }
  }));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode SceneNastranSubcases(MPI_Comm comm, const nastran::Deck &deck, PetscInt chosen, std::vector<PetscInt> *ids)
{
  PetscFunctionBeginUser;
  ids->clear();
  if (chosen > 0) {
    PetscCall(Input(comm, "turning the Nastran deck into a model", [&] {
      try {
        (void)nastran::FindSubcase(deck, (int)chosen);
      } catch (const nastran::Error &e) {
        throw std::invalid_argument(std::string("-nastran_subcase ") + std::to_string(chosen) + ": " + e.what());
      }
    }));
    ids->push_back(chosen);
  } else
    for (const nastran::Subcase &s : deck.subcases) ids->push_back(s.id);
  PetscFunctionReturn(0);
}

PetscErrorCode SceneDescribeNastran(MPI_Comm comm, Scene *scene, const nastran::Deck &deck, const std::vector<PetscInt> &subcases, const nastran::ModelOptions &options, const std::string &fasteners, BoltnetAssembly a, std::vector<std::vector<BCDesc>> *conditions)
{
  nastran::DeckModel                       m;          // the first subcase's model
  std::vector<std::vector<nastran::ModelBC>> bcs(subcases.size()); // each subcase's conditions
  std::vector<FastenerRule>                rules;
  std::set<std::string>                    said;
  PetscFunctionBeginUser;
  PetscCheck(!subcases.empty(), comm, PETSC_ERR_ARG_WRONG, "No subcase to describe");
  for (size_t k = 0; k < subcases.size(); ++k) {
    nastran::DeckModel mk;
    PetscCall(Input(comm, "turning the Nastran deck into a model", [&] { mk = nastran::ModelOf(deck, (int)subcases[k], options); }));
    for (const std::string &n : mk.notes)
      if (said.insert(n).second) PetscCall(PetscPrintf(comm, "boltnet: nastran: %s\n", n.c_str()));
    // The subcases of one set-up hold the same dof (the same SPC set), so they have the same parts
    // (a constrained grid joined by a CBUSH is a rigid part): the model is the first one's, and of
    // the others only their conditions are kept.
    bool same = mk.parts.size() == (k ? m.parts.size() : mk.parts.size()) && mk.joints.size() == (k ? m.joints.size() : mk.joints.size());
    for (size_t i = 0; same && k > 0 && i < mk.parts.size(); ++i) same = mk.parts[i].pid == m.parts[i].pid;
    PetscCheck(same, comm, PETSC_ERR_PLIB, "Subcases %" PetscInt_FMT " and %" PetscInt_FMT " make different models", subcases[0], subcases[k]);
    bcs[k] = std::move(mk.bcs);
    if (k == 0) m = std::move(mk);
  }
  if (!fasteners.empty()) PetscCall(ReadFastenerTable(comm, fasteners, &rules));
  for (nastran::ModelPart &p : m.parts) {
    if (p.rigid) PetscCall(BoltnetAssemblyAddRigidPatch(a, p.pid, p.x.data()));
    else PetscCall(AssemblyAddShell(a, p.pid, std::move(p.mesh), p.material));
  }
  // Joints keep their PBUSH/PFAST spring (the full stiffness, with its levers) unless the first
  // matching row of the fastener table names a joint type, whose options (-joint_<type>_*) then give
  // every parameter (a macroelement between GA and GB, without lever). Ties (pid 0) keep theirs.
  std::map<std::string, BoltnetJointParams> types;
  for (const nastran::ModelJoint &j : m.joints) {
    const PetscInt pa = m.parts[j.part_a].pid, pb = m.parts[j.part_b].pid;
    FastenerRule  *rule = nullptr;
    for (FastenerRule &r : rules)
      if (j.pid != 0 && ((r.pid >= 0 && r.pid == j.pid) || (r.first >= 0 && j.eid >= r.first && j.eid <= r.last))) {
        rule = &r;
        break;
      }
    BoltnetJointParams p;
    if (rule) {
      rule->used = true;
      if (!types.count(rule->type)) PetscCall(SceneJointType(comm, a, rule->type, j.eid, pa, pb, j.n.data(), j.t1.data(), j.x.data(), &types[rule->type], scene));
      p = types[rule->type];
    } else if (j.full) { // a bush: its whole stiffness, levered from GA and GB when they differ
      PetscCall(AssemblyAddFullSpring(a, j.eid, pa, pb, j.K, j.n.data(), j.t1.data(), j.x.data(), j.lever ? j.at_a.data() : nullptr, j.lever ? j.at_b.data() : nullptr));
      continue;
    } else {
      PetscCall(BoltnetJointParamsSetDefault(BOLTNET_LAW_SPRING, &p));
      p.kn = j.kn, p.kt = j.kt, p.kr = j.kr;
    }
    PetscCall(BoltnetAssemblyAddJointAt(a, j.eid, pa, pb, &p, j.n.data(), j.t1.data(), j.x.data()));
  }
  for (const FastenerRule &r : rules)
    PetscCheck(r.used, comm, PETSC_ERR_USER_INPUT, "%s line %d: no CBUSH or CFAST of the deck matches (%s %" PetscInt_FMT "%s)", fasteners.c_str(), r.line, r.pid >= 0 ? "pid" : "elements", r.pid >= 0 ? r.pid : r.first, r.pid >= 0 || r.last == r.first ? "" : (" to " + std::to_string(r.last)).c_str());

  // Node sets are made once per part and name (for the conditions of every subcase: a name is a
  // grid, "grid<id>", or a set of the SPC set, "spc<components>", the same in each); then the
  // first subcase's conditions, one per dof, and the others' as they are.
  std::map<std::pair<PetscInt, std::string>, std::vector<int>> made;
  const BoltnetBCKind kinds[] = {BOLTNET_BC_FIXED, BOLTNET_BC_DISPLACEMENT, BOLTNET_BC_FORCE};
  conditions->assign(subcases.size(), {});
  for (size_t k = 0; k < subcases.size(); ++k)
    for (const nastran::ModelBC &b : bcs[k]) {
      const PetscInt pid = m.parts[b.part].pid;
      if (!b.set.empty()) {
        auto it = made.find({pid, b.set});
        if (it == made.end()) {
          std::vector<PetscInt> nodes(b.nodes.begin(), b.nodes.end());
          PetscCall(BoltnetAssemblyAddNodeSet(a, pid, b.set.c_str(), (PetscInt)nodes.size(), nodes.data()));
          made[{pid, b.set}] = b.nodes;
        } else PetscCheck(it->second == b.nodes, comm, PETSC_ERR_PLIB, "Subcase %" PetscInt_FMT ": node set '%s' of part %" PetscInt_FMT " differs from subcase %" PetscInt_FMT "'s", subcases[k], b.set.c_str(), pid, subcases[0]);
      }
      if (k == 0) PetscCall(BoltnetAssemblyAddBCOnSet(a, pid, b.set.c_str(), b.dof, kinds[(int)b.kind], b.value));
      (*conditions)[k].push_back(BCDesc{pid, b.set, b.dof, kinds[(int)b.kind], b.value});
    }
  size_t nrigid = 0;
  for (const nastran::ModelPart &p : m.parts) nrigid += p.rigid;
  for (size_t k = 0; k < subcases.size(); ++k)
    PetscCall(PetscPrintf(comm, "boltnet: nastran subcase %" PetscInt_FMT ": %zu shell parts (properties), %zu rigid parts (grids), %zu joints, %zu conditions\n", subcases[k], m.parts.size() - nrigid, nrigid, m.joints.size(), bcs[k].size()));
  PetscFunctionReturn(0);
}

PetscErrorCode SceneNastranSetUps(MPI_Comm comm, const nastran::Deck &deck, const std::vector<PetscInt> &ids, std::vector<std::vector<PetscInt>> *groups)
{
  PetscFunctionBeginUser;
  groups->clear();
  std::map<int, size_t> by_spc; // SPC set id -> group
  for (PetscInt id : ids) {
    int spc = 0;
    PetscCall(Input(comm, "turning the Nastran deck into a model", [&] { spc = nastran::FindSubcase(deck, (int)id).spc; }));
    auto it = by_spc.find(spc);
    if (it == by_spc.end()) {
      it = by_spc.emplace(spc, groups->size()).first;
      groups->emplace_back();
    }
    (*groups)[it->second].push_back(id);
  }
  PetscFunctionReturn(0);
}

} // namespace boltnet
