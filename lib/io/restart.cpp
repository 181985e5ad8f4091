// Checkpoints read (io/checkpoint.hpp; the file's layout: io/checkpoint_file.hpp): the file is read
// whole and checked (its checksums, then what it belongs to) before the assembly is touched.
#include "core/errors.hpp"
#include "core/guard.hpp"
#include "io/checkpoint_file.hpp"
#include "io/limits.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>

namespace boltnet {
namespace {
using namespace ckpt;

PetscErrorCode ReadScalars(PetscViewer v, Saved *s, bool *is_checkpoint)
{
  PetscBool has;
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5HasAttribute(v, "/", "format", &has));
  *is_checkpoint = has;
  if (!has) PetscFunctionReturn(0);
  PetscErrorCode ierr = 0;
  auto text = [&](const char *n, std::string &val) {
    char *c = nullptr;
    if (!ierr) ierr = PetscViewerHDF5ReadAttribute(v, "/", n, PETSC_STRING, nullptr, &c);
    if (!ierr) val = c ? c : "";
    if (!ierr) ierr = PetscFree(c);
  };
  ForEach(
    *s, text, [&](const char *n, PetscInt &val) { if (!ierr) ierr = PetscViewerHDF5ReadAttribute(v, "/", n, PETSC_INT, nullptr, &val); },
    [&](const char *n, PetscReal &val) { if (!ierr) ierr = PetscViewerHDF5ReadAttribute(v, "/", n, PETSC_REAL, nullptr, &val); });
  text("scalars_checksum", s->scalars_checksum);
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

// What the checkpoint belongs to against this run: the first difference, named.
PetscErrorCode CheckIdentity(BoltnetAssembly a, const CheckpointIdentity &id, const Saved &s, const char file[])
{
  PetscFunctionBeginUser;
  PetscCheck(s.scene == id.scene, a->comm, PETSC_ERR_USER_INPUT, "The checkpoint %s (-restart) is of scene '%s', this run is scene '%s'", file, s.scene.c_str(), id.scene.c_str());
  const std::string diff = OptionsDifference(id.options, s.options);
  PetscCheck(diff.empty(), a->comm, PETSC_ERR_USER_INPUT, "The checkpoint %s (-restart) was written with other options that change results: %s. A restart takes the options of the run that wrote the checkpoint", file, diff.c_str());
  std::string model;
  if (s.parts != id.parts) model += "the parts (patches, meshes, sections)";
  if (s.joints != id.joints) model += std::string(model.empty() ? "" : ", ") + "the joints (fasteners and their parameters)";
  if (s.bcs != id.bcs) model += std::string(model.empty() ? "" : ", ") + "the boundary conditions";
  PetscCheck(model.empty(), a->comm, PETSC_ERR_USER_INPUT, "The checkpoint %s (-restart) was written for another model: %s of this scene differ from those of the run that wrote it (a table or mesh file changed)", file, model.c_str());
  if (s.layout != a->layout.fingerprint) {
    PetscCheck(s.ranks == a->size, a->comm, PETSC_ERR_USER_INPUT, "The checkpoint %s (-restart) was written on %" PetscInt_FMT " rank(s), this run has %d, and the network is laid out differently on them (%" PetscInt_FMT " patches then, %zu now): -patch_max_nodes -1 (automatic) cuts the parts by the number of ranks. Restart on %" PetscInt_FMT " rank(s); a run that may move to another number of ranks needs an explicit -patch_max_nodes", file, s.ranks, a->size, s.npatches, a->layout.patches.size(), s.ranks);
    SETERRQ(a->comm, PETSC_ERR_USER_INPUT, "The checkpoint %s (-restart) belongs to a network laid out differently (%" PetscInt_FMT " patches then, %zu now)", file, s.npatches, a->layout.patches.size());
  }
  PetscCheck(s.ndof == a->net.ndof_global && s.njoints == a->layout.njoints && s.nsteps >= 1 && s.nsteps <= limits::kMaxLoadSteps, a->comm, PETSC_ERR_FILE_UNEXPECTED, "The checkpoint %s (-restart) is damaged: %" PetscInt_FMT " dof, %" PetscInt_FMT " joints and %" PetscInt_FMT " steps, for a network of %" PetscInt_FMT " dof and %" PetscInt_FMT " joints", file, s.ndof, s.njoints, s.nsteps, a->net.ndof_global, a->layout.njoints);
  PetscFunctionReturn(0);
}

// An array of the file into v (its size set), checked against the size the scalars give.
PetscErrorCode ReadArray(PetscViewer viewer, const char name[], PetscInt bs, PetscInt n, Vec v)
{
  PetscInt fbs, fn;
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5ReadSizes(viewer, name, &fbs, &fn));
  PetscCheck(fn == n && fbs == bs, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "/%s holds %" PetscInt_FMT " values in rows of %" PetscInt_FMT ", not %" PetscInt_FMT " in rows of %" PetscInt_FMT, name, fn, fbs, n, bs);
  PetscCall(PetscObjectSetName((PetscObject)v, name));
  PetscCall(VecLoad(v, viewer));
  PetscFunctionReturn(0);
}

PetscErrorCode CreateArray(MPI_Comm comm, PetscInt bs, PetscInt n, Vec *v)
{
  PetscFunctionBeginUser;
  PetscCall(VecCreate(comm, v));
  PetscCall(VecSetSizes(*v, PETSC_DECIDE, n));
  PetscCall(VecSetBlockSize(*v, bs));
  PetscCall(VecSetType(*v, VECSTANDARD));
  PetscFunctionReturn(0);
}

PetscErrorCode ReadArrays(PetscViewer v, const Saved &s, Vec x, Vec j, Vec st, Vec xp)
{
  PetscFunctionBeginUser;
  PetscCall(ReadArray(v, "solution", 6, s.ndof, x));
  PetscCall(ReadArray(v, "previous_solution", 6, s.ndof, xp));
  PetscCall(ReadArray(v, "joints", kRow, kRow * s.njoints, j));
  PetscCall(ReadArray(v, "steps", kStepRow, kStepRow * s.nsteps, st));
  PetscFunctionReturn(0);
}

// The checked file into the assembly: the solution, each local joint's row, the steps and scalars.
PetscErrorCode Apply(BoltnetAssembly a, const Saved &s, Vec x, Vec j, Vec st, Vec xp, const char file[])
{
  JointSet          &js = a->joints;
  VecScatter         sc;
  Vec                loc;
  IS                 is;
  const PetscScalar *r;
  PetscFunctionBeginUser;
  PetscCall(NaturalScatter(a, x, &sc));
  PetscCall(VecScatterBegin(sc, x, a->X, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(sc, x, a->X, INSERT_VALUES, SCATTER_REVERSE));
  if (!a->Xprev) PetscCall(VecDuplicate(a->X, &a->Xprev));
  PetscCall(VecScatterBegin(sc, xp, a->Xprev, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(sc, xp, a->Xprev, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterDestroy(&sc));

  const std::vector<PetscInt> rows = JointRows(a);
  std::vector<PetscInt>       idx;
  for (PetscInt row : rows)
    for (PetscInt c = 0; c < kRow; ++c) idx.push_back(kRow * row + c);
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)idx.size(), idx.data(), PETSC_COPY_VALUES, &is));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, (PetscInt)idx.size(), &loc));
  PetscCall(VecScatterCreate(j, is, loc, nullptr, &sc));
  PetscCall(VecScatterBegin(sc, j, loc, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, j, loc, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(ISDestroy(&is));
  PetscCall(VecGetArrayRead(loc, &r));
  PetscInt bad = 0, anybad;
  js.accepted.assign(js.size(), Response{});
  js.accepted_jump.assign(js.size(), Vec6{});
  js.util_now.assign(js.size(), 0);
  js.util_before.assign(js.size(), 0);
  for (size_t k = 0; k < js.size(); ++k) {
    const PetscScalar *w = r + kRow * k;
    if (w[0] != (PetscScalar)js.comp[k].id || !(w[3] >= 0 && w[3] <= 4) || !(w[6] >= 0 && w[6] <= 4)) {
      ++bad;
      continue;
    }
    History h;
    h.slip[0] = w[1], h.slip[1] = w[2], h.state = (int)w[3];
    js.committed[k]  = h;
    js.util_now[k]   = w[4];
    js.util_before[k] = w[5];
    Response &re = js.accepted[k];
    re.state     = static_cast<State>((int)w[6]);
    re.bearing   = w[7] != 0;
    re.trial     = h;
    for (int i = 0; i < 6; ++i) re.force[i] = w[8 + i], js.accepted_jump[k][i] = w[14 + i];
  }
  PetscCall(VecRestoreArrayRead(loc, &r));
  PetscCall(VecDestroy(&loc));
  PetscCallMPI(MPI_Allreduce(&bad, &anybad, 1, MPIU_INT, MPI_SUM, a->comm));
  PetscCheck(!anybad, a->comm, PETSC_ERR_FILE_UNEXPECTED, "The checkpoint %s (-restart) is damaged: %" PetscInt_FMT " joint rows name another joint or no state", file, anybad);

  Vec all;
  PetscCall(VecScatterCreateToAll(st, &sc, &all));
  PetscCall(VecScatterBegin(sc, st, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, st, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(VecGetArrayRead(all, &r));
  a->steps.clear();
  for (PetscInt i = 0; i < s.nsteps; ++i) {
    const PetscScalar *w = r + kStepRow * i;
    if (w[0] != i + 1 || !(w[2] >= 0 && w[2] < PETSC_MAX_INT) || !(w[3] >= 0 && w[3] < PETSC_MAX_INT)) {
      ++bad;
      break;
    }
    a->steps.push_back(StepInfo{i + 1, w[1], (PetscInt)w[2], (PetscInt)w[3]});
  }
  PetscCall(VecRestoreArrayRead(all, &r));
  PetscCall(VecDestroy(&all));
  PetscCheck(!bad && !a->steps.empty() && a->steps.back().load == s.load, a->comm, PETSC_ERR_FILE_UNEXPECTED, "The checkpoint %s (-restart) is damaged: its steps are not numbered 1 to %" PetscInt_FMT " or do not end at its load factor", file, s.nsteps);

  a->lambda = a->lambda_target = s.load;
  a->checks.force_scale_seen          = s.force_scale_seen;
  a->total_cutbacks            = s.cutbacks;
  js.last_increment            = s.last_increment;
  a->has_prev                  = s.has_prev ? PETSC_TRUE : PETSC_FALSE;
  a->lambda_prev               = s.prev_load;
  js.util_ready                = PETSC_TRUE;
  js.frozen.clear();
  js.jac_assembled = s.jac_assembled, js.jac_reused = s.jac_reused;
  js.frozen_joint_steps = s.frozen_joint_steps, js.joint_steps = s.joint_steps, js.released = s.released;
  a->path   = PathPosition{s.start, s.ntargets, s.target, s.sub, s.halved};
  a->resume = PETSC_TRUE;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode CheckpointLoad(BoltnetAssembly a, const CheckpointIdentity &id, const std::string &file, Output *out)
{
  ViewerHold  h;
  Saved       s;
  ErrorLog    log;
  bool        is_checkpoint = false;
  Vec         x, j, st, xp;
  const char *f = file.c_str();
  PetscFunctionBeginUser;
  PetscCheck(a->net.dm && a->steps.empty(), a->comm, PETSC_ERR_ORDER, "CheckpointLoad() comes after BoltnetAssemblySetUp() and before any solve");
  int exists = 0;
  if (a->rank == 0) {
    std::error_code ec;
    exists = std::filesystem::is_regular_file(file, ec) ? 1 : 0;
  }
  PetscCallMPI(MPI_Bcast(&exists, 1, MPI_INT, 0, a->comm));
  PetscCheck(exists, a->comm, PETSC_ERR_FILE_OPEN, "No checkpoint file %s (-restart)", f);

  // The scalars, and whether they are whole.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // HDF5's own error stack: the messages below say it
  PetscCall(PetscPushErrorHandler(CaptureErrorHandler, &log));
  PetscErrorCode ierr = PetscViewerHDF5Open(a->comm, f, FILE_MODE_READ, &h.v);
  if (!ierr) ierr = ReadScalars(h.v, &s, &is_checkpoint);
  PetscCall(PetscPopErrorHandler());
  PetscCheck(!ierr, a->comm, PETSC_ERR_FILE_READ, "Cannot read the checkpoint %s (-restart): it is damaged, cut short or not a checkpoint (%s)", f, ErrorText(log).c_str());
  PetscCheck(is_checkpoint, a->comm, PETSC_ERR_FILE_UNEXPECTED, "%s (-restart) is an HDF5 file but not a boltnet checkpoint", f);
  PetscCheck(s.format == kFormat, a->comm, PETSC_ERR_FILE_UNEXPECTED, "%s (-restart) is a checkpoint of format '%s'; this boltnet reads '%s'", f, s.format.c_str(), kFormat);
  PetscCheck(ScalarsChecksum(s) == s.scalars_checksum, a->comm, PETSC_ERR_FILE_UNEXPECTED, "The checkpoint %s (-restart) is damaged: its scalars do not match their checksum", f);

  // What it belongs to, then its arrays, whole.
  PetscCall(CheckIdentity(a, id, s, f));
  PetscCall(CreateNatural(a, &x));
  PetscCall(CreateNatural(a, &xp));
  PetscCall(CreateArray(a->comm, kRow, kRow * s.njoints, &j));
  PetscCall(CreateArray(a->comm, kStepRow, kStepRow * s.nsteps, &st));
  log.messages.clear();
  PetscCall(PetscPushErrorHandler(CaptureErrorHandler, &log));
  ierr = ReadArrays(h.v, s, x, j, st, xp);
  PetscCall(PetscPopErrorHandler());
  std::string    sum;
  PetscErrorCode aerr = 0;
  if (!ierr) aerr = DataChecksum(x, j, st, xp, &sum);
  if (!ierr && !aerr && sum == s.data_checksum) aerr = Apply(a, s, x, j, st, xp, f);
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&xp));
  PetscCall(VecDestroy(&j));
  PetscCall(VecDestroy(&st));
  PetscCall(aerr);
  PetscCheck(!ierr, a->comm, PETSC_ERR_FILE_READ, "Cannot read the checkpoint %s (-restart): it is damaged or cut short (%s)", f, ErrorText(log).c_str());
  PetscCheck(sum == s.data_checksum, a->comm, PETSC_ERR_FILE_UNEXPECTED, "The checkpoint %s (-restart) is damaged: its arrays do not match their checksum", f);
  out->most_joint = s.most_joint, out->most_step = s.most_step, out->most_force = s.most_force, out->most_load = s.most_load;
  PetscCall(PetscInfo(nullptr, "Restart from %s: step %" PetscInt_FMT ", load factor %g, written on %" PetscInt_FMT " rank(s)\n", f, s.nsteps, (double)s.load, s.ranks));
  PetscFunctionReturn(0);
}

} // namespace boltnet
