// Load cases (docs/scenes.md, "Load cases"): several loadings of one model in one run, each from
// the unloaded state into its own results folder, on one set-up of the model
// (network/cases.cpp). A scene lists them in -load_cases; a Nastran deck's subcases are its cases.
#pragma once
#include "io/io.hpp"
#include "solver/loadpath.hpp"

#include <string>
#include <vector>

namespace boltnet {

// The characters of a load or load case name: they make option names (-load_case_<name>_loads)
// and folder names.
constexpr const char *kLoadNameChars = "abcdefghijklmnopqrstuvwxyz0123456789_-";
// At most this many names in -load_cases, and loads in a case's -load_case_<name>_loads.
constexpr int kMaxLoadCases = 1000;

struct LoadCase {
  std::string         name;        // its folder under -output_dir ("subcase-<id>" for a deck's); "" for a run of one case
  std::vector<BCDesc> bcs;         // its boundary conditions, per unit load factor
  LoadPath            path;
  // A case that continues another (-load_case_<name>_continues, docs/scenes.md "Held loads") starts
  // where the case just before it in -load_cases ended, with that case's loads held; its path then
  // scales only the rows of its own loads (path_bcs: its rows of no load, which the case before
  // holds, with value 0). Empty for a case from the unloaded state.
  std::string         continues;
  std::vector<BCDesc> path_bcs;
  // Cases with the same key share one set-up: the key lists the conditions that hold dof (fixed or
  // prescribed: patch, node set, dof), which the set-up depends on; loads differ freely.
  std::string setup;
};

// The names in -load_cases (read by the driver: the option is listed by its -help), checked: at least
// one, each made of kLoadNameChars, none twice. given: whether -load_cases was set at all.
PetscErrorCode LoadCaseNames(MPI_Comm comm, PetscBool given, const std::vector<std::string> &names);

// The cases of a scene whose boundary condition table has been read into `rows` (the model's
// conditions, one per row, the load of each in scene.bc_loads): for each name, the rows of no load
// and those of the loads that -load_case_<name>_loads names, and the load path of
// -load_case_<name>_* over the scene's (base). A load that no row of the table names is an error
// naming the case, the option and the table. The cases that options define (-load_case_<x>_loads)
// but `names` leaves out are read and checked the same way, not returned.
PetscErrorCode SceneLoadCases(MPI_Comm comm, const Scene &scene, const std::vector<std::string> &names, const std::vector<BCDesc> &rows, const LoadPath &base, std::vector<LoadCase> *cases);

// The cases that options define: the names <x> of the options -load_case_<x>_loads given.
PetscErrorCode DefinedLoadCases(std::vector<std::string> *names);

// The set-up key of a list of conditions (LoadCase::setup).
std::string SetUpKey(const std::vector<BCDesc> &bcs);

// The conditions a set-up for `cases` is built with: every condition of every case, once (so that the
// set-up's checks, footprints against conditions and forces against supports, see them all).
// Conditions equal in every field count once.
std::vector<BCDesc> SetUpConditions(const std::vector<LoadCase> &cases);

bool SameConditions(const std::vector<BCDesc> &a, const std::vector<BCDesc> &b);

} // namespace boltnet
