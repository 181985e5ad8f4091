// The joint table joints.h5 (docs/output.md, "The joint table"): joints.csv's quantities for every
// converged step, written in parallel: each rank writes the rows of the joints it owns, after one
// VecScatter that puts them in joint-id order (each rank then holds a contiguous block of as many
// rows as it owns); no rank ever holds the whole table. Datasets of shape (steps, joints[, k]), the
// step dimension unlimited, so that a step is appended by extending them and a restart cuts them.
#pragma once
#include "network/assembly.hpp"
#include "network/fields.hpp"

#include <string>
#include <vector>

namespace boltnet {

// Which joint files a run writes (-output_joints).
enum class JointOutput : int { Auto = 0, Csv = 1, Hdf5 = 2, Both = 3 };
struct JointOutputOptions {
  JointOutput mode  = JointOutput::Auto; // -output_joints
  PetscInt    limit = 10000;             // -output_joints_auto_limit: auto writes joints.h5 from this many joints on
};
// Reads -output_joints and -output_joints_auto_limit (inside the caller's PetscOptionsBegin/End, so
// that -help lists them).
PetscErrorCode JointOutputOptionsFromCommandLine(PetscOptionItems *PetscOptionsObject, JointOutputOptions *o);
// The files for a model of njoints joints: auto is joints.csv below the limit, joints.h5 from it on.
struct JointFiles {
  bool csv = true, hdf5 = false;
};
JointFiles JointFilesFor(const JointOutputOptions &o, size_t njoints);

struct JointTable {
  std::string path;             // <output_dir>/joints.h5
  PetscViewer viewer = nullptr; // the file, open from OutputOpen (or OutputResume) to OutputClose
  FieldSpace  rows;             // the owned joints (JointSet order) and their rows (joint-id order)
  PetscInt    nsteps = 0;       // steps in the file
};

// Collective: a new joints.h5 at path with the joint ids, the state names and the column attributes,
// no step yet.
PetscErrorCode JointTableCreate(BoltnetAssembly a, const std::string &scene, const std::string &path, JointTable *t);
// Collective (a restart, before anything is changed): why, on every rank, is "" when the table at
// path can be continued after step k (it holds the model's joints and steps 1..k, perhaps more),
// else why not. Each rank reads the ids of its own rows.
PetscErrorCode JointTableCheck(BoltnetAssembly a, const std::string &path, PetscInt k, std::string *why);
// Collective, after JointTableCheck: the table reopened and cut after step k.
PetscErrorCode JointTableReopen(BoltnetAssembly a, const std::string &path, PetscInt k, JointTable *t);
// Collective: the step's rows (records of the joints this rank owns, in JointSet order), appended.
PetscErrorCode JointTableWriteStep(BoltnetAssembly a, JointTable *t, const StepInfo &info, const std::vector<JointRecord> &mine);
PetscErrorCode JointTableClose(JointTable *t);

} // namespace boltnet
