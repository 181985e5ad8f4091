// Scenes (PETSc YAML options + CSV tables) and results (joints.csv, summary.json).
#pragma once
#include "core/memory.hpp"
#include "network/assembly.hpp"
#include "network/fields.hpp"
#include "io/joint_table.hpp"
#include "nastran/model.hpp"

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace boltnet {

struct Scene {
  std::string           file;       // the -scene file ("" when the scene comes from options only)
  std::string           dir;        // its directory, against which the scene's relative paths resolve
  std::string           name;       // -scene_name
  std::set<std::string> from_file;  // option names (without '-') that the scene file set
  std::string           identified; // JSON object: joint types identified from their geometry
  // The boundary condition table (-scene_bcs) as read, and the load each of its rows belongs to (its
  // optional column `load`; "" for none), in the order of the model's conditions: load cases pick
  // their rows by these names (io/cases.hpp).
  std::string              bcs_path;
  std::vector<std::string> bc_loads;
};

// Insert the options of a YAML scene file; options already given (command line) win.
PetscErrorCode SceneInsertOptionsFile(MPI_Comm comm, const char file[], Scene *scene);
// Read -scene_* options and the CSV tables they name, and describe the assembly.
PetscErrorCode SceneDescribeAssembly(MPI_Comm comm, Scene *scene, BoltnetAssembly a);
// The first joint of a joint type: where a type identified from its fastener geometry measures the
// shell mesh for its shell correction (docs/identify.md, "Stiffness already in the shells").
struct FirstJoint {
  PetscInt  id, patch_a, patch_b;
  PetscReal n[3], t1[3], x[3];
};
// Rank 0's joint types, each with its first joint, given to every rank (*firsts on return), and the
// parameters of each from -joint_<type>_* (given, or identified from the fastener geometry):
// (*types)[k] for (*firsts)[k], on every rank, which each read the options. Collective.
PetscErrorCode SceneJointTypes(MPI_Comm comm, BoltnetAssembly a, std::vector<std::pair<std::string, FirstJoint>> *firsts, std::vector<BoltnetJointParams> *types, Scene *scene);
// A Nastran deck as the scene (io/nastran.cpp, docs/nastran.md "From a deck to a model"): the ids
// of the subcases to run (chosen > 0: that one, checked; else every subcase of the deck); those
// ids grouped by the set-up they can share (the same SPC set: the same dof held), in the order of
// ids; and the model of a group of subcases described into the assembly (the first subcase's
// model, with the node sets of every subcase's conditions, and its conditions as the model's),
// with the fastener table (CSV: type and first [, last] or pid; "" for none) turning chosen
// CBUSH/CFAST into joints of a type. conditions[k]: the conditions of subcases[k]. The deck is rank
// 0's alone (NastranReadDeckOnRank0; the others pass an empty one): these find their answers there
// and give them to every rank, the meshes staying on rank 0 until the layout sends them to their
// holders (docs/nastran.md, "On several ranks"). Collective.
PetscErrorCode SceneNastranSubcases(MPI_Comm comm, const nastran::Deck &deck, PetscInt chosen, std::vector<PetscInt> *ids);
PetscErrorCode SceneNastranSetUps(MPI_Comm comm, const nastran::Deck &deck, const std::vector<PetscInt> &ids, std::vector<std::vector<PetscInt>> *groups);
PetscErrorCode SceneDescribeNastran(MPI_Comm comm, Scene *scene, const nastran::Deck &deck, const std::vector<PetscInt> &subcases, const nastran::ModelOptions &options, const std::string &fasteners, BoltnetAssembly a, std::vector<std::vector<BCDesc>> *conditions);
// Errors for options in boltnet's own namespaces (scene_, joint_, load_) that nothing used:
// a misspelled boltnet option stops the run before it starts.
PetscErrorCode SceneCheckUnusedOptions(MPI_Comm comm);
// boltnet's integer options (-load_steps, -load_max_cuts, -patch_max_nodes, ...) as 64-bit
// integers in PetscInt's range, before PETSc reads them (it would truncate 99999999999 silently).
PetscErrorCode SceneCheckOptionValues(MPI_Comm comm);
// Names ("-a, -b") of the options whose value is `value`: to name the option behind PETSc's "Input
// string abc has no numeric value".
PetscErrorCode OptionsWithValue(const std::string &value, std::string *names);
// PetscOptionsGetAll()'s "-name value -name value" as (name without '-', value) pairs.
std::vector<std::pair<std::string, std::string>> OptionsSplit(const std::string &all);
// With -options_left the drivers make an option that nothing used an error rather than PETSc's
// warning (Debian's PETSc otherwise ignores typos): prints them and sets *exitcode = 2. Before the
// solve (before_solve true), the options PETSc reads only during or after a solve are not counted.
PetscErrorCode UnusedOptionsAsError(MPI_Comm comm, const char program[], PetscBool before_solve, int *exitcode);

// Fields (io/fields.cpp): fields.h5, fields.xdmf and joints.xdmf under dir, one step at a time,
// written in parallel (each rank its own rows) through PETSc's HDF5 viewer (docs/output.md).
struct FieldsOptions {
  PetscBool fields  = PETSC_TRUE;  // -output_fields
  PetscBool results = PETSC_TRUE;  // -output_stresses: element resultants, strains and stresses
  PetscBool results_cache = PETSC_TRUE; // -output_stresses_cache: keep each element's condensed modes
  PetscBool gather  = PETSC_FALSE; // -output_fields_gather: the writer that gathers to rank 0
  PetscReal bypass_width = 0;      // -output_bypass_width (mm); 0: 6 -coupling_radius (3 diameters)
  PetscReal bypass_length = 0;     // -output_bypass_length (mm); 0: half the width
};
struct FieldsFile {
  std::string   dir, scene;
  FieldsOptions opt;
  PetscInt      nnodes = 0, nquads = 0, njoints = 0;   // fixed by the first step
  std::vector<std::pair<PetscInt, PetscReal>> steps;   // (step, load factor) written so far
  PetscViewer   viewer = nullptr;                      // fields.h5, open from the first step on
  FieldMap      map;                                   // the parallel writer's numbering
  bool          mapped = false;
  FILE         *bypass = nullptr;                      // bypass.csv (rank 0), with the element results
  bool          bypass_csv = true;                     // write bypass.csv (with joints.csv); fields.h5 always has the bypass
};
// Collective: the step's fields into fields.h5, then (rank 0) the xdmf files rewritten for every
// step so far.
PetscErrorCode FieldsWriteStep(BoltnetAssembly a, FieldsFile *ff, const StepInfo &info);
// Rank 0 only: the same from the fields gathered to rank 0 (io/fields_gather.cpp).
PetscErrorCode FieldsWriteStepGather(FieldsFile *ff, const StepInfo &info, const std::vector<PartField> &parts, const std::vector<JointLine> &lines);
PetscErrorCode FieldsClose(FieldsFile *ff);
// Reads -output_fields, -output_stresses, -output_bypass_width, -output_bypass_length, -output_fields_gather (inside the
// caller's PetscOptionsBegin/End, so that -help lists them).
PetscErrorCode FieldsOptionsFromCommandLine(PetscOptionItems *PetscOptionsObject, FieldsOptions *o);
// The group of fields.h5 that holds a step's fields ("/steps/000012"): a restart drops those after
// its checkpoint (io/resume.cpp).
std::string FieldsStepGroup(PetscInt step);

// The header line of joints.csv (docs/output.md).
constexpr const char *kJointsHeader = "step,load,joint,state,du_n,du_t1,du_t2,f_n,f_t1,f_t2,bearing,slip_t1,slip_t2";

// Results under dir: joints.csv (rank 0, from the records gathered to it) and/or joints.h5 (every
// rank its rows: io/joint_table.hpp), as -output_joints chooses; summary.json (rank 0); the fields.
struct Output {
  std::string dir;
  std::string scene;
  JointFiles  files;            // which joint files (OutputOpen decides)
  FILE       *csv = nullptr;    // joints.csv, rank 0
  JointTable  table;            // joints.h5
  // Most loaded joint: largest in-plane force magnitude over all joints and steps.
  PetscInt  most_joint = -1, most_step = 0;
  PetscReal most_force = -1, most_load = 0;
  std::string identified = "{}"; // joint types identified from geometry at start-up (Scene)
  RankRange   peak_mb    = {0, 0}; // peak resident MB over the ranks, [smallest, largest] (OutputSummary)
  std::string load_case;         // the load case's name, "" for a run of one case (summary.json)
  std::string continues;         // the case it continues, its loads held (summary.json), or ""
  PetscBool   fields     = PETSC_FALSE; // write the fields (OutputOpen decides)
  FieldsFile  ff;
};
// The fields are written only when fields.fields is true and the assembly has a shell patch (a
// rigid-only scene has no field to show).
PetscErrorCode OutputOpen(MPI_Comm comm, const std::string &dir, const std::string &scene, const FieldsOptions &fields, const JointOutputOptions &joints, BoltnetAssembly a, Output *out);
PetscErrorCode OutputStep(BoltnetAssembly a, const StepInfo &info, Output *out);
PetscErrorCode OutputSummary(BoltnetAssembly a, Output *out, const std::string &status, const std::string &message);
// Collective: rank 0's error closing joints.csv is every rank's.
PetscErrorCode OutputClose(MPI_Comm comm, Output *out);
// Closes what is open without checking or communicating: the cleanup of a run stopped by an error.
void OutputDiscard(Output *out);
// Rank 0: `text` into `path` through `path`.tmp, checked at every step, then renamed; on failure
// the temporary file is removed and the message (file and reason) returned; "" on success.
std::string WriteFileWhole(const std::string &path, const std::string &text);

// Read a whole text file on rank 0 and broadcast it (or, with broadcast false, keep it on rank 0
// alone); a missing or unreadable file is an error naming `what` and the path, on every rank.
PetscErrorCode ReadFileCollective(MPI_Comm comm, const std::string &path, const char what[], std::string *text, bool broadcast = true);

} // namespace boltnet
