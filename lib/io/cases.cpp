// Load cases of a scene: io/cases.hpp.
#include "io/cases.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

namespace boltnet {

namespace {

bool SameCondition(const BCDesc &a, const BCDesc &b)
{
  return a.patch == b.patch && a.set == b.set && a.dof == b.dof && a.kind == b.kind && a.value == b.value;
}

} // namespace

PetscErrorCode LoadCaseNames(MPI_Comm comm, PetscBool given, const std::vector<std::string> &names)
{
  PetscFunctionBeginUser;
  if (!given) PetscFunctionReturn(0);
  PetscCheck(!names.empty(), comm, PETSC_ERR_USER_INPUT, "-load_cases is empty: name at least one load case (e.g. -load_cases pull,shear), or leave it out for a run of every condition of the table as one case");
  std::set<std::string> seen;
  for (const std::string &n : names) {
    PetscCheck(!n.empty(), comm, PETSC_ERR_USER_INPUT, "-load_cases: an empty name in the list");
    PetscCheck(n.find_first_not_of(kLoadNameChars) == std::string::npos, comm, PETSC_ERR_USER_INPUT, "-load_cases: '%s' is not a load case name (lower-case letters, digits, '_' and '-': it names the options -load_case_<name>_* and the results folder)", n.c_str());
    PetscCheck(seen.insert(n).second, comm, PETSC_ERR_USER_INPUT, "-load_cases: the case '%s' is named twice (each case has its own results folder)", n.c_str());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode DefinedLoadCases(std::vector<std::string> *names)
{
  char *text;
  PetscFunctionBeginUser;
  names->clear();
  PetscCall(PetscOptionsGetAll(nullptr, &text));
  const std::string opts = text;
  PetscCall(PetscFree(text));
  const std::string head = "load_case_", tail = "_loads";
  for (const auto &[opt, value] : OptionsSplit(opts))
    if (opt.size() > head.size() + tail.size() && opt.compare(0, head.size(), head) == 0 && opt.compare(opt.size() - tail.size(), tail.size(), tail) == 0) {
      const std::string name = opt.substr(head.size(), opt.size() - head.size() - tail.size());
      if (std::find(names->begin(), names->end(), name) == names->end()) names->push_back(name);
    }
  PetscFunctionReturn(0);
}

PetscErrorCode SceneLoadCases(MPI_Comm comm, const Scene &scene, const std::vector<std::string> &names, const std::vector<BCDesc> &rows, const LoadPath &base, std::vector<LoadCase> *cases)
{
  PetscFunctionBeginUser;
  PetscCheck(rows.size() == scene.bc_loads.size(), comm, PETSC_ERR_PLIB, "The model has %zu conditions but the table %s %zu rows", rows.size(), scene.bcs_path.c_str(), scene.bc_loads.size());
  std::set<std::string> defined, used;
  for (const std::string &l : scene.bc_loads)
    if (!l.empty()) defined.insert(l);
  std::string list;
  for (const std::string &l : defined) list += (list.empty() ? "" : ", ") + l;
  // The cases to run, then those the options define (-load_case_<name>_loads) that -load_cases leaves
  // out (a scene run with -load_cases naming some of its cases): those are read and checked too, so
  // that their options are not unknown and their mistakes are found, but not run.
  std::vector<std::string> all = names;
  {
    std::vector<std::string> defined_cases;
    PetscCall(DefinedLoadCases(&defined_cases));
    for (const std::string &name : defined_cases)
      if (std::find(all.begin(), all.end(), name) == all.end()) all.push_back(name);
  }
  cases->clear();
  for (const std::string &name : all) {
    const bool run = std::find(names.begin(), names.end(), name) != names.end();
    PetscCheck(name.find_first_not_of(kLoadNameChars) == std::string::npos, comm, PETSC_ERR_USER_INPUT, "-load_case_%s_loads: '%s' is not a load case name (lower-case letters, digits, '_' and '-')", name.c_str(), name.c_str());
    LoadCase          c;
    char             *loads[kMaxLoadCases];
    PetscInt          nloads = kMaxLoadCases;
    PetscBool         given  = PETSC_FALSE;
    const std::string title = "Load case '" + name + "'", opt = "-load_case_" + name + "_loads";
    char              after[256] = "";
    PetscBool         continues  = PETSC_FALSE;
    const std::string copt       = "-load_case_" + name + "_continues";
    c.name = name;
    PetscOptionsBegin(comm, nullptr, title.c_str(), "boltnet");
    PetscCall(PetscOptionsStringArray(opt.c_str(), "Loads of this case: names in the column 'load' of the boundary condition table (-scene_bcs); its rows with no load are in every case", "", loads, &nloads, &given));
    PetscCall(LoadPathOfCase(PetscOptionsObject, comm, name, base, &c.path));
    PetscCall(PetscOptionsString(copt.c_str(), "Start where this load case ends, its loads held at their final values, and apply this case's loads on top (the case just before it in -load_cases: docs/scenes.md, \"Held loads\")", "", after, after, sizeof(after), &continues));
    PetscOptionsEnd();
    if (continues) {
      c.continues = after;
      const auto me = std::find(names.begin(), names.end(), name);
      PetscCheck(c.continues != name, comm, PETSC_ERR_USER_INPUT, "Load case '%s' (%s): a case cannot continue itself", name.c_str(), copt.c_str());
      PetscCheck(!run || (me != names.begin() && *(me - 1) == c.continues), comm, PETSC_ERR_USER_INPUT, "Load case '%s' (%s %s): the case it continues must be run just before it: '%s' must come right before '%s' in -load_cases", name.c_str(), copt.c_str(), after, after, name.c_str());
    }
    std::set<std::string> mine;
    std::string           bad;
    for (PetscInt i = 0; i < (given ? nloads : 0); ++i) {
      const std::string l = loads[i];
      PetscCall(PetscFree(loads[i]));
      if (!defined.count(l) && bad.empty()) bad = l;
      mine.insert(l);
    }
    PetscCheck(given && nloads > 0, comm, PETSC_ERR_USER_INPUT, "Load case '%s' names no load: give %s (names in the column 'load' of %s%s%s)", name.c_str(), opt.c_str(), scene.bcs_path.c_str(), list.empty() ? ", which has none" : ": ", list.c_str());
    PetscCheck(bad.empty(), comm, PETSC_ERR_USER_INPUT, "Load case '%s' (%s): load '%s' is not in the column 'load' of %s (%s%s)", name.c_str(), opt.c_str(), bad.c_str(), scene.bcs_path.c_str(), list.empty() ? "which has no column 'load' or no name in it" : "its loads: ", list.c_str());
    for (size_t r = 0; r < rows.size(); ++r)
      if (scene.bc_loads[r].empty() || mine.count(scene.bc_loads[r])) c.bcs.push_back(rows[r]);
    if (!c.continues.empty())
      for (size_t r = 0; r < rows.size(); ++r) {
        if (scene.bc_loads[r].empty()) { // held by the case before, with its value: the path adds none
          BCDesc b = rows[r];
          b.value  = 0;
          c.path_bcs.push_back(b);
        } else if (mine.count(scene.bc_loads[r])) c.path_bcs.push_back(rows[r]);
      }
    if (!run) continue;
    used.insert(mine.begin(), mine.end());
    c.setup = SetUpKey(c.bcs);
    cases->push_back(std::move(c));
  }
  // A case that continues another holds the same dof: it runs on the same set-up, from its state.
  for (const LoadCase &c : *cases) {
    if (c.continues.empty()) continue;
    const auto before = std::find_if(cases->begin(), cases->end(), [&](const LoadCase &x) { return x.name == c.continues; });
    PetscCheck(before != cases->end() && before->setup == c.setup, comm, PETSC_ERR_USER_INPUT, "Load case '%s' (-load_case_%s_continues %s) fixes or prescribes other dof than '%s': a case that continues another must hold the same dof (its loads may add forces, pressures and prescribed values on them)", c.name.c_str(), c.name.c_str(), c.continues.c_str(), c.continues.c_str());
  }
  for (const std::string &l : defined)
    if (!used.count(l)) PetscCall(PetscPrintf(comm, "boltnet: note: load '%s' of %s is in no load case of this run (-load_cases)\n", l.c_str(), scene.bcs_path.c_str()));
  PetscFunctionReturn(0);
}

std::string SetUpKey(const std::vector<BCDesc> &bcs)
{
  std::set<std::string> held;
  for (const BCDesc &b : bcs)
    if (b.kind != BOLTNET_BC_FORCE && b.kind != BOLTNET_BC_PRESSURE) held.insert(std::to_string(b.patch) + "/" + b.set + "/" + std::to_string(b.dof));
  std::string key;
  for (const std::string &h : held) key += h + ";";
  return key;
}

std::vector<BCDesc> SetUpConditions(const std::vector<LoadCase> &cases)
{
  std::vector<BCDesc> all;
  for (const LoadCase &c : cases)
    for (const BCDesc &b : c.bcs)
      if (std::none_of(all.begin(), all.end(), [&](const BCDesc &x) { return SameCondition(x, b); })) all.push_back(b);
  return all;
}

bool SameConditions(const std::vector<BCDesc> &a, const std::vector<BCDesc> &b)
{
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (!SameCondition(a[i], b[i])) return false;
  return true;
}

} // namespace boltnet
