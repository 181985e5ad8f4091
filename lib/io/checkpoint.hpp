// Checkpoint and restart (docs/scenes.md, "Checkpoint and restart"): the committed state after a
// converged load step in an HDF5 file written by every rank through PETSc's HDF5 viewer, and a
// restart that loads it into a freshly set-up assembly and goes on along the load path, the result
// files continued as if the run had not stopped.
//
// The file holds only what does not follow from the model: the network's solution (the interface
// dof of condensed patches: their condensation is rebuilt at set-up and recovers the interior), every
// joint's history and the state that chooses the next step's linear springs, the position on the load
// path, the record of the steps, the counters of summary.json. Every array is in an order that does
// not depend on the ranks (patches in layout order, joints by id), so a restart may use another
// number of ranks as long as the network is laid out the same.
#pragma once
#include "io/io.hpp"

#include <string>
#include <utility>
#include <vector>

namespace boltnet {

// What a checkpoint belongs to. A restart refuses a checkpoint whose identity differs from its own
// and names what differs.
struct CheckpointIdentity {
  std::string scene;   // -scene_name
  std::string options; // "name value" lines, sorted: every option that can change results
  std::string parts, joints, bcs; // hashes of the model's parts (meshes, sections), joints, boundary conditions
};

// The identity of this run: call after the scene is described and before BoltnetAssemblySetUp
// (which moves the meshes out of the model description). Collective.
PetscErrorCode CheckpointIdentify(BoltnetAssembly a, const std::string &scene, CheckpointIdentity *id);
// The options that can change results, as (name without '-', value), sorted by name: every option
// set except those that only choose what is printed or written (io/identity.cpp lists them).
std::vector<std::pair<std::string, std::string>> ResultOptions(const std::string &all);
// "" when the two option lists ("name value" lines) agree (numbers compared as numbers), else the
// options that differ: "-joint_bolt_mu 0.2 (checkpoint: 0.3), -load_steps not given (checkpoint: 20)".
std::string OptionsDifference(const std::string &now, const std::string &saved);

// Collective: the committed state after the last converged step into `file`, through `file`.tmp and a
// rename, so that a job killed during the write leaves the previous checkpoint whole. `out` gives
// the results so far that summary.json reports (the most loaded joint).
PetscErrorCode CheckpointWrite(BoltnetAssembly a, const CheckpointIdentity &id, const Output &out, const std::string &file);
// Collective: an error now, not at the first checkpoint, when the directory of `file` does not exist
// or cannot be written.
PetscErrorCode CheckpointCheckFile(MPI_Comm comm, const std::string &file);
// Collective, after BoltnetAssemblySetUp and before anything is solved: the state of `file` into the
// assembly, which the next BoltnetAssemblySolveLoadPath continues (same path: it is checked), and
// the most loaded joint so far into `out`. A file that is not a whole checkpoint, or that belongs to
// another scene, model, set of options or layout, is refused with a message naming what differs.
PetscErrorCode CheckpointLoad(BoltnetAssembly a, const CheckpointIdentity &id, const std::string &file, Output *out);

// After CheckpointLoad, instead of OutputOpen: the results of the run that wrote the checkpoint,
// continued in dir (io/resume.cpp). joints.csv and bypass.csv keep their rows up to the checkpoint's step and take
// the next ones after them, joints.h5 its steps up to it; fields.h5 drops any step after it and takes the next ones; fields.xdmf
// is rewritten with the next step. Everything is checked before anything is changed.
PetscErrorCode OutputResume(MPI_Comm comm, const std::string &dir, const std::string &scene, const FieldsOptions &fields, const JointOutputOptions &joints, BoltnetAssembly a, Output *out);

} // namespace boltnet
