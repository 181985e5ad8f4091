// The layout of a checkpoint file, shared by its writer (io/checkpoint.cpp) and its reader
// (io/restart.cpp). Through PETSc's HDF5 viewer, on every rank:
//   /solution  the network's solution, patches in layout order (6 dof per carried node)
//   /joints    one row of kRow per joint, joints sorted by id
//   /steps     one row (step, load factor, Newton iterations, cut-backs) per converged step
// and the scalars (Saved) as attributes of the root group. Two checksums find a damaged file: one of
// the scalars, one of the arrays (core/hash.hpp); neither depends on the number of ranks.
#pragma once
#include "io/checkpoint.hpp"
#include "core/hash.hpp"

#include <petsclayouthdf5.h> // PetscViewerHDF5ReadSizes
#include <petscviewerhdf5.h>

#include <string>
#include <vector>

namespace boltnet {
namespace ckpt {

// Format 2 adds the secant predictor's point (previous_solution, previous_load, has_previous).
constexpr const char *kFormat = "boltnet checkpoint 2";
// A joint's row: id, committed slip (t1, t2) and state, utilization now and at the step before
// (AssemblyFreezeStuck), and the accepted response that joints.csv and the fields show: state,
// bearing, force (6), jump (6).
constexpr PetscInt kRow     = 20;
constexpr PetscInt kStepRow = 4;

// Every scalar of a checkpoint, written as an attribute of the root group under its name.
struct Saved {
  std::string format, scene, options, parts, joints, bcs, layout, data_checksum, scalars_checksum;
  PetscInt    ranks = 0, npatches = 0, ndof = 0, njoints = 0, nsteps = 0, ntargets = 0, target = 0, halved = 0;
  PetscInt    cutbacks = 0, jac_assembled = 0, jac_reused = 0, frozen_joint_steps = 0, joint_steps = 0, released = 0;
  PetscInt    most_joint = -1, most_step = 0, has_prev = 0;
  PetscReal   load = 0, start = 0, sub = 0, force_scale_seen = 0, last_increment = 0, most_force = -1, most_load = 0, prev_load = 0;
};

// The scalars by name, for the writer, the reader and the checksum (which covers all but itself).
template <class T, class S, class I, class R>
void ForEach(T &s, S text, I ints, R reals)
{
  text("format", s.format), text("scene", s.scene), text("options", s.options), text("model_parts", s.parts);
  text("model_joints", s.joints), text("model_bcs", s.bcs), text("layout", s.layout), text("data_checksum", s.data_checksum);
  ints("ranks", s.ranks), ints("patches", s.npatches), ints("network_dof", s.ndof), ints("joints", s.njoints);
  ints("steps", s.nsteps), ints("path_targets", s.ntargets), ints("path_target", s.target), ints("path_halved", s.halved);
  ints("cutbacks", s.cutbacks), ints("jacobians_assembled", s.jac_assembled), ints("jacobians_reused", s.jac_reused);
  ints("frozen_joint_steps", s.frozen_joint_steps), ints("joint_steps", s.joint_steps), ints("released", s.released);
  ints("most_loaded_joint", s.most_joint), ints("most_loaded_step", s.most_step), ints("has_previous", s.has_prev);
  reals("load", s.load), reals("path_start", s.start), reals("path_sub", s.sub), reals("force_scale_seen", s.force_scale_seen);
  reals("last_increment", s.last_increment), reals("most_loaded_force", s.most_force), reals("most_loaded_load", s.most_load);
  reals("previous_load", s.prev_load);
}

std::string ScalarsChecksum(Saved &s);

// A viewer closed on every way out of a function (an error's included).
struct ViewerHold {
  PetscViewer v = nullptr;
  ~ViewerHold()
  {
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    PetscViewerDestroy(&v);
    PetscPopErrorHandler();
  }
};

// The solution in the file's order: patch p (layout order) from 6 x (the nodes carried by the patches
// before it). NaturalScatter takes X (DMNetwork order: by owning rank) to such a vector.
PetscErrorCode CreateNatural(BoltnetAssembly a, Vec *xnat);
PetscErrorCode NaturalScatter(BoltnetAssembly a, Vec xnat, VecScatter *sc);
// The row of each local joint (a->joints order) among the joints sorted by id.
std::vector<PetscInt> JointRows(BoltnetAssembly a);
// The checksum (hex) of the four arrays: the solution, the joints, the steps and the solution before.
PetscErrorCode DataChecksum(Vec x, Vec j, Vec s, Vec xp, std::string *hex);
// Rank 0's text on every rank.
PetscErrorCode ShareText(MPI_Comm comm, std::string *text);

} // namespace ckpt
} // namespace boltnet
