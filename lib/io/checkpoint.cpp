// Checkpoints written (io/checkpoint.hpp; the file's layout: io/checkpoint_file.hpp).
#include "core/errors.hpp"
#include "core/guard.hpp"
#include "io/checkpoint_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <sstream>

namespace boltnet {
namespace ckpt {

std::string ScalarsChecksum(Saved &s)
{
  Hasher h;
  ForEach(
    s, [&](const char *n, const std::string &v) { h.Add(std::string(n)), h.Add(v); }, [&](const char *n, PetscInt v) { h.Add(std::string(n)), h.Add(v); },
    [&](const char *n, PetscReal v) { h.Add(std::string(n)), h.Add(v); });
  return h.Hex();
}

PetscErrorCode CreateNatural(BoltnetAssembly a, Vec *xnat)
{
  PetscFunctionBeginUser;
  PetscCall(VecCreate(a->comm, xnat));
  PetscCall(VecSetSizes(*xnat, PETSC_DECIDE, a->net.ndof_global));
  PetscCall(VecSetBlockSize(*xnat, 6));
  PetscCall(VecSetType(*xnat, VECSTANDARD));
  PetscCall(PetscObjectSetName((PetscObject)*xnat, "solution"));
  PetscFunctionReturn(0);
}

PetscErrorCode NaturalScatter(BoltnetAssembly a, Vec xnat, VecScatter *sc)
{
  const Layout &L = a->layout;
  PetscInt      n, rstart;
  IS            from, to;
  PetscFunctionBeginUser;
  std::vector<PetscInt> noff(L.patches.size() + 1, 0);
  for (size_t p = 0; p < L.patches.size(); ++p) noff[p + 1] = noff[p] + 6 * L.patches[p].nnodes;
  PetscCheck(noff.back() == a->net.ndof_global, a->comm, PETSC_ERR_PLIB, "The patches carry %" PetscInt_FMT " dof, the network has %" PetscInt_FMT, noff.back(), a->net.ndof_global);
  PetscCall(VecGetLocalSize(a->X, &n));
  PetscCall(VecGetOwnershipRange(a->X, &rstart, nullptr));
  std::vector<PetscInt> nat(n, -1);
  for (const OwnedPatch &op : a->patches.owned)
    for (PetscInt i = 0; i < 6 * L.patches[op.index].nnodes; ++i) nat[op.goff - rstart + i] = noff[op.index] + i;
  PetscCheck(std::find(nat.begin(), nat.end(), -1) == nat.end(), PETSC_COMM_SELF, PETSC_ERR_PLIB, "A row of the solution belongs to no owned patch");
  PetscCall(ISCreateStride(PETSC_COMM_SELF, n, rstart, 1, &from));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, n, nat.data(), PETSC_COPY_VALUES, &to));
  PetscCall(VecScatterCreate(a->X, from, xnat, to, sc));
  PetscCall(ISDestroy(&from));
  PetscCall(ISDestroy(&to));
  PetscFunctionReturn(0);
}

// The row of each local joint among the joints sorted by id (JointComp::row).
std::vector<PetscInt> JointRows(BoltnetAssembly a)
{
  std::vector<PetscInt> mine;
  mine.reserve(a->joints.size());
  for (const JointComp &c : a->joints.comp) mine.push_back(c.row);
  return mine;
}

// Sum over the ranks of the checksum terms of v's entries (core/hash.hpp).
static PetscErrorCode Checksum(Vec v, std::uint64_t tag, std::uint64_t *sum)
{
  const PetscScalar *x;
  PetscInt           n, rstart;
  std::uint64_t      mine = 0;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetOwnershipRange(v, &rstart, nullptr));
  PetscCall(VecGetArrayRead(v, &x));
  for (PetscInt i = 0; i < n; ++i) mine += ChecksumTerm(tag, (std::uint64_t)(rstart + i), PetscRealPart(x[i]));
  PetscCall(VecRestoreArrayRead(v, &x));
  PetscCallMPI(MPI_Allreduce(&mine, sum, 1, MPI_UINT64_T, MPI_SUM, PetscObjectComm((PetscObject)v)));
  PetscFunctionReturn(0);
}

PetscErrorCode DataChecksum(Vec x, Vec j, Vec s, Vec xp, std::string *hex)
{
  std::uint64_t c[4];
  PetscFunctionBeginUser;
  PetscCall(Checksum(x, 1, &c[0]));
  PetscCall(Checksum(j, 2, &c[1]));
  PetscCall(Checksum(s, 3, &c[2]));
  PetscCall(Checksum(xp, 4, &c[3]));
  Hasher h;
  for (std::uint64_t v : c) h.Add(v);
  *hex = h.Hex();
  PetscFunctionReturn(0);
}

PetscErrorCode ShareText(MPI_Comm comm, std::string *text)
{
  int len = (int)text->size();
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, 0, comm));
  text->resize((size_t)len);
  if (len) PetscCallMPI(MPI_Bcast(text->data(), len, MPI_CHAR, 0, comm));
  PetscFunctionReturn(0);
}

} // namespace ckpt

namespace {
using namespace ckpt;

// The arrays of the committed state, in the file's order.
PetscErrorCode StateVectors(BoltnetAssembly a, Vec *x, Vec *j, Vec *s, Vec *xp)
{
  const JointSet &js = a->joints;
  VecScatter      sc;
  PetscFunctionBeginUser;
  PetscCall(CreateNatural(a, x));
  PetscCall(CreateNatural(a, xp));
  PetscCall(PetscObjectSetName((PetscObject)*xp, "previous_solution"));
  PetscCall(NaturalScatter(a, *x, &sc));
  PetscCall(VecScatterBegin(sc, a->X, *x, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, a->X, *x, INSERT_VALUES, SCATTER_FORWARD));
  if (a->has_prev) { // the same layout: the same scatter
    PetscCall(VecScatterBegin(sc, a->Xprev, *xp, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(sc, a->Xprev, *xp, INSERT_VALUES, SCATTER_FORWARD));
  } else PetscCall(VecSet(*xp, 0.0));
  PetscCall(VecScatterDestroy(&sc));

  PetscCall(VecCreate(a->comm, j));
  PetscCall(VecSetSizes(*j, PETSC_DECIDE, kRow * a->layout.njoints));
  PetscCall(VecSetBlockSize(*j, kRow));
  PetscCall(VecSetType(*j, VECSTANDARD));
  PetscCall(PetscObjectSetName((PetscObject)*j, "joints"));
  const std::vector<PetscInt> rows = JointRows(a);
  for (size_t k = 0; k < js.size(); ++k) {
    const Response &re  = js.accepted.at(k);
    PetscScalar     r[kRow] = {(PetscScalar)js.comp[k].id, js.committed[k].slip[0], js.committed[k].slip[1], (PetscScalar)js.committed[k].state,
                               k < js.util_now.size() ? js.util_now[k] : 0.0, k < js.util_before.size() ? js.util_before[k] : 0.0,
                               (PetscScalar) static_cast<int>(re.state), re.bearing ? 1.0 : 0.0};
    for (int i = 0; i < 6; ++i) r[8 + i] = re.force[i], r[14 + i] = js.accepted_jump.at(k)[i];
    PetscCall(VecSetValuesBlocked(*j, 1, &rows[k], r, INSERT_VALUES));
  }
  PetscCall(VecAssemblyBegin(*j));
  PetscCall(VecAssemblyEnd(*j));

  const PetscInt nsteps = a->rank == 0 ? (PetscInt)a->steps.size() : 0;
  PetscCall(VecCreate(a->comm, s));
  PetscCall(VecSetSizes(*s, kStepRow * nsteps, PETSC_DETERMINE));
  PetscCall(VecSetBlockSize(*s, kStepRow));
  PetscCall(VecSetType(*s, VECSTANDARD));
  PetscCall(PetscObjectSetName((PetscObject)*s, "steps"));
  PetscScalar *v;
  PetscCall(VecGetArray(*s, &v));
  for (PetscInt i = 0; i < nsteps; ++i) {
    const StepInfo &st = a->steps[i];
    v[kStepRow * i]     = (PetscScalar)st.step;
    v[kStepRow * i + 1] = st.load;
    v[kStepRow * i + 2] = (PetscScalar)st.newton_its;
    v[kStepRow * i + 3] = (PetscScalar)st.cutbacks;
  }
  PetscCall(VecRestoreArray(*s, &v));
  PetscFunctionReturn(0);
}

PetscErrorCode WriteFile(MPI_Comm comm, const std::string &path, Saved &s, Vec x, Vec j, Vec st, Vec xp)
{
  ViewerHold h;
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5Open(comm, path.c_str(), FILE_MODE_WRITE, &h.v));
  PetscCall(VecView(x, h.v));
  PetscCall(VecView(j, h.v));
  PetscCall(VecView(st, h.v));
  PetscCall(VecView(xp, h.v));
  PetscErrorCode ierr = 0;
  ForEach(
    s, [&](const char *n, const std::string &v) { if (!ierr) ierr = PetscViewerHDF5WriteAttribute(h.v, "/", n, PETSC_STRING, v.c_str()); },
    [&](const char *n, PetscInt v) { if (!ierr) ierr = PetscViewerHDF5WriteAttribute(h.v, "/", n, PETSC_INT, &v); },
    [&](const char *n, PetscReal v) { if (!ierr) ierr = PetscViewerHDF5WriteAttribute(h.v, "/", n, PETSC_REAL, &v); });
  PetscCall(ierr);
  PetscCall(PetscViewerHDF5WriteAttribute(h.v, "/", "scalars_checksum", PETSC_STRING, s.scalars_checksum.c_str()));
  PetscCall(PetscViewerDestroy(&h.v));
  PetscFunctionReturn(0);
}

// Rank 0: the written file onto the disk, then in the place of the previous checkpoint (rename is
// atomic), then the directory entry onto the disk. "" or the reason it failed.
std::string Commit(const std::string &tmp, const std::string &file)
{
  const int fd = open(tmp.c_str(), O_RDONLY);
  if (fd < 0 || fsync(fd) != 0) {
    const std::string why = std::strerror(errno);
    if (fd >= 0) close(fd);
    return why;
  }
  close(fd);
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) return ec.message();
  const std::string dir = std::filesystem::path(file).parent_path().string();
  const int         dd  = open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (dd >= 0) {
    fsync(dd); // best effort: some file systems refuse fsync on a directory
    close(dd);
  }
  return "";
}

} // namespace

PetscErrorCode CheckpointWrite(BoltnetAssembly a, const CheckpointIdentity &id, const Output &out, const std::string &file)
{
  Vec   x, j, st, xp;
  Saved s;
  PetscFunctionBeginUser;
  PetscCheck(!a->steps.empty(), a->comm, PETSC_ERR_ORDER, "A checkpoint is written after a converged step");
  s.format = kFormat, s.scene = id.scene, s.options = id.options, s.parts = id.parts, s.joints = id.joints, s.bcs = id.bcs;
  s.layout = a->layout.fingerprint, s.ranks = a->size, s.npatches = (PetscInt)a->layout.patches.size();
  s.ndof = a->net.ndof_global, s.njoints = a->layout.njoints, s.nsteps = (PetscInt)a->steps.size();
  s.ntargets = a->path.ntargets, s.target = a->path.target, s.halved = a->path.halved, s.start = a->path.start, s.sub = a->path.sub;
  s.cutbacks = a->total_cutbacks, s.jac_assembled = a->joints.jac_assembled, s.jac_reused = a->joints.jac_reused;
  s.frozen_joint_steps = a->joints.frozen_joint_steps, s.joint_steps = a->joints.joint_steps, s.released = a->joints.released;
  s.load = a->lambda, s.force_scale_seen = a->checks.force_scale_seen, s.last_increment = a->joints.last_increment;
  s.has_prev = a->has_prev ? 1 : 0, s.prev_load = a->has_prev ? a->lambda_prev : 0;
  // The most loaded joint so far is rank 0's (OutputStep); every rank writes the same attributes.
  PetscInt  mi[2] = {out.most_joint, out.most_step};
  PetscReal mr[2] = {out.most_force, out.most_load};
  PetscCallMPI(MPI_Bcast(mi, 2, MPIU_INT, 0, a->comm));
  PetscCallMPI(MPI_Bcast(mr, 2, MPIU_REAL, 0, a->comm));
  s.most_joint = mi[0], s.most_step = mi[1], s.most_force = mr[0], s.most_load = mr[1];
  PetscCheck(s.options.size() < 60000, a->comm, PETSC_ERR_SUP, "The options of this run take %zu characters: more than a checkpoint attribute holds (60000)", s.options.size());

  PetscCall(StateVectors(a, &x, &j, &st, &xp));
  PetscCall(DataChecksum(x, j, st, xp, &s.data_checksum));
  s.scalars_checksum = ScalarsChecksum(s);
  const std::string tmp = file + ".tmp";
  ErrorLog          log;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // HDF5's own error stack: the message below says it
  PetscCall(PetscPushErrorHandler(CaptureErrorHandler, &log));
  PetscErrorCode ierr = WriteFile(a->comm, tmp, s, x, j, st, xp);
  PetscCall(PetscPopErrorHandler());
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&xp));
  PetscCall(VecDestroy(&j));
  PetscCall(VecDestroy(&st));
  // The file is closed on every rank: rank 0 finishes it, or removes it after an error on any rank.
  int failed = ierr ? 1 : 0, anyfailed;
  PetscCallMPI(MPI_Allreduce(&failed, &anyfailed, 1, MPI_INT, MPI_MAX, a->comm));
  std::string why = ierr ? ErrorText(log) : "";
  if (anyfailed && why.empty()) why = "the HDF5 viewer failed on another rank";
  if (a->rank == 0) {
    if (why.empty()) why = Commit(tmp, file);
    if (!why.empty()) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
    }
  }
  PetscCall(ShareText(a->comm, &why));
  PetscCheck(why.empty(), a->comm, PETSC_ERR_FILE_WRITE, "Cannot write the checkpoint %s (-checkpoint_file) after step %zu: %s", file.c_str(), a->steps.size(), why.c_str());
  PetscCall(PetscInfo(nullptr, "Checkpoint of step %zu (load factor %g) in %s\n", a->steps.size(), (double)a->lambda, file.c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode CheckpointCheckFile(MPI_Comm comm, const std::string &file)
{
  PetscMPIInt rank;
  std::string why;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    const std::string dir = std::filesystem::path(file).parent_path().string();
    std::error_code   ec;
    if (!std::filesystem::is_directory(dir.empty() ? "." : dir, ec)) why = "its directory '" + dir + "' does not exist";
    else if (access(dir.empty() ? "." : dir.c_str(), W_OK) != 0) why = "its directory '" + dir + "' cannot be written: " + std::strerror(errno);
  }
  PetscCall(ShareText(comm, &why));
  PetscCheck(why.empty(), comm, PETSC_ERR_USER_INPUT, "Cannot write the checkpoint %s (-checkpoint_file): %s", file.c_str(), why.c_str());
  PetscFunctionReturn(0);
}

} // namespace boltnet
