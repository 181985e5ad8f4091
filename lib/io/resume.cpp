// The results of a run continued after a restart (io/checkpoint.hpp, OutputResume): joints.csv and
// bypass.csv cut after the checkpoint's step, fields.h5 and joints.h5 reopened without the steps
// after it. Rank 0 checks them before any is changed; fields.h5 and joints.h5, written by every
// rank, are then reopened by every rank.
#include "core/errors.hpp"
#include "io/checkpoint_file.hpp"
#include "io/h5id.hpp"

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <vector>

namespace boltnet {
namespace {

// The length of joints.csv up to the end of the last row of step k (rows of later steps, or a row cut
// short by the kill, come after it), or why the file cannot be continued: it must hold the header
// and one row per joint for each of steps 1 to k.
std::string JointsLength(const std::string &path, PetscInt k, size_t njoints, std::uintmax_t *length)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) return "Cannot restart: there is no " + path + " to continue (-output_dir must name the directory of the run that wrote the checkpoint)";
  std::string    line;
  std::uintmax_t at = 0, end = 0;
  size_t         rows = 0;
  PetscInt       last = 0;
  bool           header = true;
  while (std::getline(in, line)) {
    if (in.eof()) break; // no newline: a row cut short
    at += line.size() + 1;
    if (header) {
      if (line != kJointsHeader) return "Cannot restart: " + path + " does not start with the header of joints.csv";
      header = false, end = at;
      continue;
    }
    const PetscInt step = (PetscInt)std::strtol(line.c_str(), nullptr, 10);
    if (step > k) break;
    if (step < last || step < 1) return "Cannot restart: " + path + " has rows out of step order";
    last = step, end = at, ++rows;
  }
  if (header || last != k || rows != (size_t)k * njoints)
    return "Cannot restart: " + path + " holds " + std::to_string(rows) + " rows up to step " + std::to_string(last) + ", the checkpoint is at step " + std::to_string(k) + " of " + std::to_string(njoints) + " joints (-output_dir must name the directory of the run that wrote the checkpoint)";
  *length = end;
  return "";
}

// The length of bypass.csv up to the end of the rows of steps 1 to k (its rows are by step; a step
// may have none: a fastener on no shell part), or why the file cannot be continued.
std::string BypassLength(const std::string &path, PetscInt k, std::uintmax_t *length)
{
  std::ifstream  in(path, std::ios::binary);
  std::string    line;
  std::uintmax_t at = 0, end = 0;
  PetscInt       last = 0;
  if (!in || !std::getline(in, line) || in.eof() || line.rfind("step,", 0) != 0) return "Cannot restart: " + path + " does not start with the header of bypass.csv";
  at = end = line.size() + 1;
  while (std::getline(in, line)) {
    if (in.eof()) break; // no newline: a row cut short
    at += line.size() + 1;
    const PetscInt step = (PetscInt)std::strtol(line.c_str(), nullptr, 10);
    if (step > k) break;
    if (step < last || step < 1) return "Cannot restart: " + path + " has rows out of step order";
    last = step, end = at;
  }
  *length = end;
  return "";
}

// Rank 0: fields.h5 opened to read, with step k in it, and the sizes of its model; the steps after
// k are not yet dropped (TrimFields).
PetscErrorCode OpenFields(FieldsFile *ff, PetscInt k)
{
  PetscBool has;
  PetscInt  bs, n;
  PetscFunctionBeginUser;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // HDF5's own error stack: the message says it
  PetscCall(PetscViewerHDF5Open(PETSC_COMM_SELF, (ff->dir + "/fields.h5").c_str(), FILE_MODE_READ, &ff->viewer));
  PetscCall(PetscViewerHDF5HasGroup(ff->viewer, FieldsStepGroup(k).c_str(), &has));
  PetscCheck(has, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "it holds no step %" PetscInt_FMT, k);
  PetscCall(PetscViewerHDF5PushGroup(ff->viewer, "/joints"));
  PetscCall(PetscViewerHDF5ReadSizes(ff->viewer, "id", &bs, &n));
  ff->njoints = n / bs;
  PetscCall(PetscViewerHDF5PopGroup(ff->viewer));
  PetscCall(PetscViewerHDF5HasGroup(ff->viewer, "/shells", &has));
  if (has) {
    PetscCall(PetscViewerHDF5PushGroup(ff->viewer, "/shells"));
    PetscCall(PetscViewerHDF5ReadSizes(ff->viewer, "coordinates", &bs, &n));
    ff->nnodes = n / 3;
    PetscCall(PetscViewerHDF5ReadSizes(ff->viewer, "part", &bs, &n));
    ff->nquads = n / bs; // the former writer's quadrilaterals; every element with the parallel one
    PetscCall(PetscViewerHDF5PopGroup(ff->viewer));
  }
  PetscFunctionReturn(0);
}

// fields.h5 rebuilt without the steps after k: its groups but /steps, and /steps up to step k,
// copied object by object (H5Ocopy) into path.tmp, which then replaces it. "" or why not (path.tmp
// removed, path as it was). The steps up to k were flushed whole before the checkpoint was written
// (OutputStep precedes CheckpointWrite), so a kill while a later step was written leaves them
// readable even where that step's own objects are not.
std::string RebuildFields(const std::string &path, PetscInt k)
{
  const std::string tmp = path + ".tmp";
  bool              ok  = true;
  {
    H5Id src(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (src < 0) return "HDF5 cannot open it";
    H5Id dst(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    if (dst < 0) return "HDF5 cannot create " + tmp;
    std::vector<std::string> top;
    auto                     collect = [](hid_t, const char *name, const H5L_info_t *, void *names) -> herr_t {
      static_cast<std::vector<std::string> *>(names)->push_back(name);
      return 0;
    };
    ok = H5Literate(src, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, collect, &top) >= 0;
    for (const std::string &name : top)
      if (ok && name != "steps") ok = H5Ocopy(src, name.c_str(), dst, name.c_str(), H5P_DEFAULT, H5P_DEFAULT) >= 0;
    if (ok) {
      H5Id steps(H5Gcreate2(dst, "steps", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
      ok = steps >= 0;
    }
    for (PetscInt s = 1; ok && s <= k; ++s) ok = H5Ocopy(src, FieldsStepGroup(s).c_str(), dst, FieldsStepGroup(s).c_str(), H5P_DEFAULT, H5P_DEFAULT) >= 0;
  }
  std::error_code ec;
  if (ok) std::filesystem::rename(tmp, path, ec);
  if (!ok || ec) {
    std::filesystem::remove(tmp, ec);
    return ok ? "cannot replace it by " + tmp : "HDF5 cannot copy its steps 1 to " + std::to_string(k) + " into " + tmp;
  }
  return "";
}

// Rank 0: the steps after k out of fields.h5 (a killed run may have written some), with serial
// HDF5 before any rank opens the file to write. In place where HDF5 can remove them; a kill while
// HDF5 wrote a step can leave that step's objects inconsistent (H5Ldelete then fails: "link count
// would be negative"), and the file is then rebuilt from the steps it keeps. "" or why not.
std::string TrimFields(const std::string &path, PetscInt k)
{
  bool ok = true, any = false;
  {
    H5Id file(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
    if (file < 0) return "HDF5 cannot open it to write";
    for (PetscInt s = k + 1; ok; ++s) { // OpenFields found /steps, with step k in it
      const std::string g   = FieldsStepGroup(s);
      const htri_t      has = H5Lexists(file, g.c_str(), H5P_DEFAULT);
      if (has == 0) break;
      any = true;
      ok  = has > 0 && H5Ldelete(file, g.c_str(), H5P_DEFAULT) >= 0;
    }
    if (any && ok) ok = H5Fflush(file, H5F_SCOPE_GLOBAL) >= 0;
  }
  return ok ? "" : RebuildFields(path, k);
}

// Rank 0: everything checked, then changed; "" or why not. table: JointTableCheck's verdict on
// joints.h5 (collective, made before).
std::string Resume(BoltnetAssembly a, Output *out, const std::string &table)
{
  const PetscInt    k    = (PetscInt)a->steps.size();
  const std::string csv  = out->dir + "/joints.csv";
  std::uintmax_t    keep = 0;
  std::string       why  = out->files.csv ? JointsLength(csv, k, (size_t)a->layout.njoints, &keep) : "";
  if (why.empty()) why = table;
  if (!why.empty()) return why;
  // A kill while a step's fields were written can leave fields.h5 shorter than its superblock says;
  // extended to that end, HDF5 opens it, and the step is removed below with the others after k.
  if (out->fields) {
    why = ExtendShortHDF5(out->dir + "/fields.h5");
    if (!why.empty()) return "Cannot continue the fields in " + out->dir + "/fields.h5: " + why + " (-output_fields false restarts without fields)";
  }
  ErrorLog log;
  if (PetscPushErrorHandler(CaptureErrorHandler, &log)) return "PETSc error";
  if (out->fields && OpenFields(&out->ff, k)) why = "Cannot continue the fields in " + out->dir + "/fields.h5: " + ErrorText(log) + " (-output_fields false restarts without fields)";
  PetscViewerDestroy(&out->ff.viewer); // a viewer whose file did not open fails to close too: not the error to report
  PetscPopErrorHandler();
  if (!why.empty()) return why;
  // bypass.csv (the element results' companion) goes on after step k, if the run wrote one.
  const std::string bypass = out->dir + "/bypass.csv";
  std::uintmax_t    bkeep  = 0;
  std::error_code   ec;
  const bool        withBypass = out->fields && out->ff.opt.results && !out->ff.opt.gather && std::filesystem::exists(bypass, ec);
  if (withBypass) {
    why = BypassLength(bypass, k, &bkeep);
    if (!why.empty()) return why;
  }
  // Everything checked: fields.h5 first, the one change that can still fail for a reason of its own.
  if (out->fields) {
    const std::string trim = TrimFields(out->dir + "/fields.h5", k);
    if (!trim.empty()) return "Cannot remove the steps after step " + std::to_string(k) + " from " + out->dir + "/fields.h5: " + trim + " (-output_fields false restarts without fields)";
    // The former writer's rank 0 writes the file alone: it reopens it (every rank does, in
    // OutputResume, for the parallel one).
    if (out->ff.opt.gather) {
      if (PetscPushErrorHandler(CaptureErrorHandler, &log)) return "PETSc error";
      if (PetscViewerHDF5Open(PETSC_COMM_SELF, (out->dir + "/fields.h5").c_str(), FILE_MODE_APPEND, &out->ff.viewer)) why = "Cannot continue the fields in " + out->dir + "/fields.h5: " + ErrorText(log);
      PetscPopErrorHandler();
      if (!why.empty()) return why;
    }
  }
  std::filesystem::remove(out->dir + "/summary.json", ec); // this run writes its own at the end
  if (out->files.csv) {
    std::filesystem::resize_file(csv, keep, ec);
    if (ec) return "Cannot restart: cannot cut " + csv + " after step " + std::to_string(k) + ": " + ec.message();
    out->csv = std::fopen(csv.c_str(), "a");
    if (!out->csv) return "Cannot restart: cannot append to " + csv;
  }
  if (withBypass) {
    std::filesystem::resize_file(bypass, bkeep, ec);
    if (ec) return "Cannot restart: cannot cut " + bypass + " after step " + std::to_string(k) + ": " + ec.message();
    out->ff.bypass = std::fopen(bypass.c_str(), "a");
    if (!out->ff.bypass) return "Cannot restart: cannot append to " + bypass;
  }
  return "";
}

} // namespace

PetscErrorCode OutputResume(MPI_Comm comm, const std::string &dir, const std::string &scene, const FieldsOptions &fields, const JointOutputOptions &joints, BoltnetAssembly a, Output *out)
{
  PetscMPIInt rank;
  std::string why;
  PetscFunctionBeginUser;
  PetscCheck(!a->steps.empty(), comm, PETSC_ERR_ORDER, "OutputResume() comes after CheckpointLoad()");
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  out->dir      = dir;
  out->scene    = scene;
  out->files    = JointFilesFor(joints, (size_t)a->layout.njoints);
  out->fields   = (fields.fields && !a->layout.shells.empty()) ? PETSC_TRUE : PETSC_FALSE;
  out->ff.dir   = dir;
  out->ff.scene = scene;
  out->ff.opt   = fields;
  out->ff.bypass_csv = out->files.csv; // a model large enough for joints.h5 has its bypass in fields.h5 only
  std::string table;
  if (out->files.hdf5) PetscCall(JointTableCheck(a, dir + "/joints.h5", (PetscInt)a->steps.size(), &table));
  if (rank == 0) {
    try {
      why = Resume(a, out, table);
    } catch (const std::exception &e) {
      why = std::string("Cannot restart: ") + e.what();
    }
    if (!why.empty()) {
      PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
      OutputDiscard(out);
      PetscPopErrorHandler();
    }
  }
  PetscCall(ckpt::ShareText(comm, &why));
  PetscCheck(why.empty(), comm, PETSC_ERR_FILE_UNEXPECTED, "%s", why.c_str());
  // Every rank: the steps written (the next step writes no mesh), and fields.h5, which rank 0 found
  // holding step k, opened by all for the parallel writer.
  for (const StepInfo &s : a->steps) out->ff.steps.emplace_back(s.step, s.load);
  if (out->fields && !out->ff.opt.gather) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    PetscCall(PetscViewerHDF5Open(comm, (dir + "/fields.h5").c_str(), FILE_MODE_APPEND, &out->ff.viewer));
  }
  if (out->files.hdf5) PetscCall(JointTableReopen(a, dir + "/joints.h5", (PetscInt)a->steps.size(), &out->table));
  PetscFunctionReturn(0);
}

} // namespace boltnet
