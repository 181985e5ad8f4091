// A Nastran deck as a scene source (docs/nastran.md, "From a deck to a model"): the model of one
// subcase (nastran/model.hpp) described into an assembly, with the fastener table that turns
// chosen CBUSH/CFAST into macroelements of a joint type (-joint_<type>_*, as a scene's joints).
#include "io/io.hpp"
#include "core/bcast.hpp"
#include "core/guard.hpp"
#include "io/input.hpp"
#include "io/table.hpp"
#include "nastran/model.hpp"
#include "nastran/petsc.hpp"

#include <array>
#include <cstdint>
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
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(ReadFileCollective(comm, path, "Nastran fastener table (-nastran_fasteners)", &text, false));
  PetscCall(Collective(comm, "reading the Nastran fastener table", [&]() -> PetscErrorCode {
    if (rank) return 0;
    return Input(PETSC_COMM_SELF, "turning the Nastran deck into a model", [&] {
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
    });
  }));
  PetscFunctionReturn(0);
}

// What every rank needs of a part of rank 0's model: the mesh itself stays on rank 0 until it is
// sent to the rank that lays the part out (patch/layout_steps.hpp, SendRank0Meshes).
struct PartHead {
  PetscInt              pid, rigid;
  std::array<double, 3> x; // a rigid part's node; a shell part's first mesh node
  std::int64_t          nodes;
  shell::ShellMaterial  material;
};

// A condition as bytes, its node set's name (`set` characters) in a string beside.
struct BCHead {
  PetscInt      pid, dof;
  BoltnetBCKind kind;
  PetscReal     value;
  std::int64_t  set;
};

// Rank 0's conditions of each subcase given to every rank.
PetscErrorCode BcastConditions(MPI_Comm comm, std::vector<std::vector<BCDesc>> *c)
{
  std::vector<std::int64_t> counts;
  std::vector<BCHead>       heads;
  std::string               names;
  PetscFunctionBeginUser;
  for (const std::vector<BCDesc> &k : *c) {
    counts.push_back((std::int64_t)k.size());
    for (const BCDesc &b : k) {
      heads.push_back(BCHead{b.patch, b.dof, b.kind, b.value, (std::int64_t)b.set.size()});
      names += b.set;
    }
  }
  PetscCall(BcastVector(comm, &counts));
  PetscCall(BcastVector(comm, &heads));
  PetscCall(BcastString(comm, &names));
  c->assign(counts.size(), {});
  size_t h = 0, at = 0;
  for (size_t k = 0; k < counts.size(); ++k)
    for (std::int64_t i = 0; i < counts[k]; ++i, ++h) {
      const BCHead &b = heads[h];
      (*c)[k].push_back(BCDesc{b.pid, names.substr(at, (size_t)b.set), b.dof, b.kind, b.value});
      at += (size_t)b.set;
    }
  PetscFunctionReturn(0);
}

} // namespace

// The deck is rank 0's alone (NastranReadDeckOnRank0): what the subcases and set-ups are is found
// there and given to every rank, with rank 0's error, if any, raised on all of them.
PetscErrorCode SceneNastranSubcases(MPI_Comm comm, const nastran::Deck &deck, PetscInt chosen, std::vector<PetscInt> *ids)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  ids->clear();
  PetscCall(Collective(comm, "turning the Nastran deck into a model", [&]() -> PetscErrorCode {
    if (rank) return 0;
    if (chosen > 0) {
      PetscCall(Input(PETSC_COMM_SELF, "turning the Nastran deck into a model", [&] {
        try {
          (void)nastran::FindSubcase(deck, (int)chosen);
        } catch (const nastran::Error &e) {
          throw std::invalid_argument(std::string("-nastran_subcase ") + std::to_string(chosen) + ": " + e.what());
        }
      }));
      ids->push_back(chosen);
    } else
      for (const nastran::Subcase &s : deck.subcases) ids->push_back(s.id);
    return 0;
  }));
  PetscCall(BcastVector(comm, ids));
  PetscFunctionReturn(0);
}

PetscErrorCode SceneNastranSetUps(MPI_Comm comm, const nastran::Deck &deck, const std::vector<PetscInt> &ids, std::vector<std::vector<PetscInt>> *groups)
{
  PetscMPIInt           rank;
  std::vector<PetscInt> group(ids.size(), 0); // each id's set-up
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(Collective(comm, "turning the Nastran deck into a model", [&]() -> PetscErrorCode {
    if (rank) return 0;
    std::map<int, PetscInt> by_spc; // SPC set id -> group
    for (size_t k = 0; k < ids.size(); ++k) {
      int spc = 0;
      PetscCall(Input(PETSC_COMM_SELF, "turning the Nastran deck into a model", [&] { spc = nastran::FindSubcase(deck, (int)ids[k]).spc; }));
      group[k] = by_spc.emplace(spc, (PetscInt)by_spc.size()).first->second;
    }
    return 0;
  }));
  PetscCall(BcastVector(comm, &group));
  groups->clear();
  for (size_t k = 0; k < ids.size(); ++k) {
    if (group[k] >= (PetscInt)groups->size()) groups->resize((size_t)group[k] + 1);
    (*groups)[(size_t)group[k]].push_back(ids[k]);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode SceneDescribeNastran(MPI_Comm comm, Scene *scene, const nastran::Deck &deck, const std::vector<PetscInt> &subcases, const nastran::ModelOptions &options, const std::string &fasteners, BoltnetAssembly a, std::vector<std::vector<BCDesc>> *conditions)
{
  PetscMPIInt                                rank;
  nastran::DeckModel                         m;   // rank 0: the first subcase's model
  std::vector<std::vector<nastran::ModelBC>> bcs(subcases.size()); // rank 0: each subcase's conditions
  std::vector<FastenerRule>                  rules;
  std::vector<PartHead>                      heads;
  std::vector<std::pair<std::string, FirstJoint>> firsts; // the joint types, in the order of first use
  std::vector<int>                           jtype;      // rank 0: each joint's (in firsts), or -1
  PetscFunctionBeginUser;
  PetscCheck(!subcases.empty(), comm, PETSC_ERR_ARG_WRONG, "No subcase to describe");
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  // Rank 0 alone turns the deck into a model: the other ranks receive what every rank describes
  // (the parts' heads, the joint types, the conditions), the meshes go to the ranks that lay them
  // out (AssemblyAddShellOnRank0) and the joints to the holders of their parts (patch/layout.cpp).
  PetscCall(Collective(comm, "turning the Nastran deck into a model", [&]() -> PetscErrorCode {
    std::set<std::string> said;
    PetscFunctionBeginUser;
    if (rank) PetscFunctionReturn(0);
    for (size_t k = 0; k < subcases.size(); ++k) {
      nastran::DeckModel mk;
      PetscCall(Input(PETSC_COMM_SELF, "turning the Nastran deck into a model", [&] { mk = nastran::ModelOf(deck, (int)subcases[k], options); }));
      for (const std::string &n : mk.notes)
        if (said.insert(n).second) PetscCall(PetscPrintf(PETSC_COMM_SELF, "boltnet: nastran: %s\n", n.c_str()));
      // The subcases of one set-up hold the same dof (the same SPC set), so they have the same parts
      // (a constrained grid joined by a CBUSH is a rigid part): the model is the first one's, and of
      // the others only their conditions are kept.
      bool same = mk.parts.size() == (k ? m.parts.size() : mk.parts.size()) && mk.joints.size() == (k ? m.joints.size() : mk.joints.size());
      for (size_t i = 0; same && k > 0 && i < mk.parts.size(); ++i) same = mk.parts[i].pid == m.parts[i].pid;
      PetscCheck(same, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Subcases %" PetscInt_FMT " and %" PetscInt_FMT " make different models", subcases[0], subcases[k]);
      bcs[k] = std::move(mk.bcs);
      if (k == 0) m = std::move(mk);
    }
    PetscFunctionReturn(0);
  }));
  if (!fasteners.empty()) PetscCall(ReadFastenerTable(comm, fasteners, &rules));

  // On rank 0: node sets are made once per part and name (for the conditions of every subcase: a
  // name is a grid, "grid<id>", or a set of the SPC set, "spc<components>", the same in each), in
  // the part's mesh; each subcase's conditions; the parts' heads; each joint's type, the first
  // matching row of the fastener table's.
  conditions->assign(subcases.size(), {});
  PetscCall(Collective(comm, "turning the Nastran deck into a model", [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (rank) PetscFunctionReturn(0);
    std::map<std::pair<PetscInt, std::string>, std::vector<int>> made;
    const BoltnetBCKind kinds[] = {BOLTNET_BC_FIXED, BOLTNET_BC_DISPLACEMENT, BOLTNET_BC_FORCE};
    for (size_t k = 0; k < subcases.size(); ++k)
      for (const nastran::ModelBC &b : bcs[k]) {
        nastran::ModelPart &p   = m.parts[b.part];
        const PetscInt      pid = p.pid;
        if (!b.set.empty()) {
          auto it = made.find({pid, b.set});
          if (it == made.end()) {
            PetscCheck(!p.rigid, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Node set '%s': patch %" PetscInt_FMT " is not a shell patch", b.set.c_str(), pid);
            for (int n : b.nodes) PetscCheck(n >= 0 && n < (int)p.mesh.x.size(), PETSC_COMM_SELF, PETSC_ERR_PLIB, "Node set '%s' of patch %" PetscInt_FMT ": node %d does not exist", b.set.c_str(), pid, n);
            std::vector<int> &set = p.mesh.node_sets[b.set];
            set.insert(set.end(), b.nodes.begin(), b.nodes.end());
            made[{pid, b.set}] = b.nodes;
          } else PetscCheck(it->second == b.nodes, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Subcase %" PetscInt_FMT ": node set '%s' of part %" PetscInt_FMT " differs from subcase %" PetscInt_FMT "'s", subcases[k], b.set.c_str(), pid, subcases[0]);
        }
        (*conditions)[k].push_back(BCDesc{pid, b.set, b.dof, kinds[(int)b.kind], b.value});
      }
    for (const nastran::ModelPart &p : m.parts) heads.push_back(PartHead{p.pid, p.rigid, p.rigid || p.mesh.x.empty() ? p.x : p.mesh.x[0], (std::int64_t)p.mesh.x.size(), p.material});
    // Joints keep their PBUSH/PFAST spring (the full stiffness, with its levers) unless the first
    // matching row of the fastener table names a joint type, whose options (-joint_<type>_*) then
    // give every parameter (a macroelement between GA and GB, without lever). Ties (pid 0) keep theirs.
    std::map<std::string, int> seen;
    for (const nastran::ModelJoint &j : m.joints) {
      FastenerRule *rule = nullptr;
      for (FastenerRule &r : rules)
        if (j.pid != 0 && ((r.pid >= 0 && r.pid == j.pid) || (r.first >= 0 && j.eid >= r.first && j.eid <= r.last))) {
          rule = &r;
          break;
        }
      jtype.push_back(-1);
      if (!rule) continue;
      rule->used = true;
      auto it    = seen.find(rule->type);
      if (it == seen.end()) {
        it = seen.emplace(rule->type, (int)firsts.size()).first;
        firsts.push_back({rule->type, FirstJoint{j.eid, m.parts[j.part_a].pid, m.parts[j.part_b].pid, {j.n[0], j.n[1], j.n[2]}, {j.t1[0], j.t1[1], j.t1[2]}, {j.x[0], j.x[1], j.x[2]}}});
      }
      jtype.back() = it->second;
    }
    for (const FastenerRule &r : rules)
      PetscCheck(r.used, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s line %d: no CBUSH or CFAST of the deck matches (%s %" PetscInt_FMT "%s)", fasteners.c_str(), r.line, r.pid >= 0 ? "pid" : "elements", r.pid >= 0 ? r.pid : r.first, r.pid >= 0 || r.last == r.first ? "" : (" to " + std::to_string(r.last)).c_str());
    PetscFunctionReturn(0);
  }));

  // Every rank describes the parts (rank 0 with their meshes), the joint types (each rank reads
  // their options) and the first subcase's conditions; rank 0 alone the joints.
  PetscCall(BcastVector(comm, &heads));
  PetscCall(BcastConditions(comm, conditions));
  PetscCall(Collective(comm, "turning the Nastran deck into a model", [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    for (size_t i = 0; i < heads.size(); ++i) {
      const PartHead &h = heads[i];
      if (h.rigid) PetscCall(BoltnetAssemblyAddRigidPatch(a, h.pid, h.x.data()));
      else PetscCall(AssemblyAddShellOnRank0(a, h.pid, h.x, h.nodes, rank ? ShellMesh{} : std::move(m.parts[i].mesh), h.material));
    }
    PetscFunctionReturn(0);
  }));
  std::vector<BoltnetJointParams> types;
  PetscCall(SceneJointTypes(comm, a, &firsts, &types, scene));
  PetscCall(Collective(comm, "turning the Nastran deck into a model", [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (rank) PetscFunctionReturn(0);
    for (size_t k = 0; k < m.joints.size(); ++k) {
      const nastran::ModelJoint &j  = m.joints[k];
      const PetscInt             pa = m.parts[j.part_a].pid, pb = m.parts[j.part_b].pid;
      BoltnetJointParams         p;
      if (jtype[k] >= 0) p = types[(size_t)jtype[k]];
      else if (j.full) { // a bush: its whole stiffness, levered from GA and GB when they differ
        PetscCall(AssemblyAddFullSpring(a, j.eid, pa, pb, j.K, j.n.data(), j.t1.data(), j.x.data(), j.lever ? j.at_a.data() : nullptr, j.lever ? j.at_b.data() : nullptr));
        continue;
      } else {
        PetscCall(BoltnetJointParamsSetDefault(BOLTNET_LAW_SPRING, &p));
        p.kn = j.kn, p.kt = j.kt, p.kr = j.kr;
      }
      PetscCall(BoltnetAssemblyAddJointAt(a, j.eid, pa, pb, &p, j.n.data(), j.t1.data(), j.x.data()));
    }
    PetscFunctionReturn(0);
  }));
  for (const BCDesc &b : (*conditions)[0]) PetscCall(BoltnetAssemblyAddBCOnSet(a, b.patch, b.set.c_str(), b.dof, b.kind, b.value));
  size_t nrigid = 0;
  for (const PartHead &h : heads) nrigid += h.rigid;
  std::int64_t njoint = (std::int64_t)m.joints.size(); // rank 0's
  PetscCallMPI(MPI_Bcast(&njoint, 1, MPI_INT64_T, 0, comm));
  for (size_t k = 0; k < subcases.size(); ++k)
    PetscCall(PetscPrintf(comm, "boltnet: nastran subcase %" PetscInt_FMT ": %zu shell parts (properties), %zu rigid parts (grids), %lld joints, %zu conditions\n", subcases[k], heads.size() - nrigid, nrigid, (long long)njoint, (*conditions)[k].size()));
  PetscFunctionReturn(0);
}

} // namespace boltnet
