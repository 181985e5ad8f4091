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

PetscErrorCode SceneDescribeNastran(MPI_Comm comm, Scene *scene, const nastran::Deck &deck, PetscInt subcase, const nastran::ModelOptions &options, const std::string &fasteners, BoltnetAssembly a)
{
  nastran::DeckModel        m;
  std::vector<FastenerRule> rules;
  PetscFunctionBeginUser;
  PetscCall(Input(comm, "turning the Nastran deck into a model", [&] { m = nastran::ModelOf(deck, (int)subcase, options); }));
  for (const std::string &n : m.notes) PetscCall(PetscPrintf(comm, "boltnet: nastran: %s\n", n.c_str()));
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

  // Node sets are made once per part and name; then one condition per dof.
  std::set<std::pair<PetscInt, std::string>> made;
  const BoltnetBCKind kinds[] = {BOLTNET_BC_FIXED, BOLTNET_BC_DISPLACEMENT, BOLTNET_BC_FORCE};
  for (const nastran::ModelBC &b : m.bcs) {
    const PetscInt pid = m.parts[b.part].pid;
    if (!b.set.empty() && made.insert({pid, b.set}).second) {
      std::vector<PetscInt> nodes(b.nodes.begin(), b.nodes.end());
      PetscCall(BoltnetAssemblyAddNodeSet(a, pid, b.set.c_str(), (PetscInt)nodes.size(), nodes.data()));
    }
    PetscCall(BoltnetAssemblyAddBCOnSet(a, pid, b.set.c_str(), b.dof, kinds[(int)b.kind], b.value));
  }
  size_t nrigid = 0;
  for (const nastran::ModelPart &p : m.parts) nrigid += p.rigid;
  PetscCall(PetscPrintf(comm, "boltnet: nastran subcase %" PetscInt_FMT ": %zu shell parts (properties), %zu rigid parts (grids), %zu joints, %zu conditions\n", subcase, m.parts.size() - nrigid, nrigid, m.joints.size(), m.bcs.size()));
  PetscFunctionReturn(0);
}

} // namespace boltnet
