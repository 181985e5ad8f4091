// Results: joints.csv (one row per joint per converged step, written by rank 0) and/or joints.h5
// (io/joint_table.cpp, every rank its rows), summary.json (rank 0) and the fields (io/fields.cpp).
#include "io/io.hpp"
#include "core/errors.hpp"
#include "core/log.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace boltnet {
namespace {

std::string JsonString(const std::string &s)
{
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\', o += c;
    else if (c == '\n') o += "\\n";
    else if ((unsigned char)c < 0x20) o += ' ';
    else o += c;
  }
  return o + "\"";
}

// A number for JSON, which has no NaN or infinity: those are written as null.
std::string JsonNumber(double x)
{
  if (!std::isfinite(x)) return "null";
  std::ostringstream o;
  o.precision(17);
  o << x;
  return o.str();
}

// Rank 0's write error (empty: none) becomes the same error on every rank: ranks go on or stop
// together, and the message names the file and the reason.
PetscErrorCode ShareError(MPI_Comm comm, const std::string &error)
{
  PetscMPIInt rank;
  int         len = 0;
  std::string msg = error;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) len = (int)msg.size();
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, 0, comm));
  if (!len) PetscFunctionReturn(0);
  msg.resize((size_t)len);
  PetscCallMPI(MPI_Bcast(msg.data(), len, MPI_CHAR, 0, comm));
  SETERRQ(comm, PETSC_ERR_FILE_WRITE, "%s", msg.c_str());
}

// The first failing rank's error (empty: none) becomes every rank's: a collective write that
// failed on some ranks stops all of them with one message.
PetscErrorCode ShareAnyError(MPI_Comm comm, const std::string &error)
{
  PetscMPIInt rank, size, first;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  const PetscMPIInt mine = error.empty() ? size : rank;
  PetscCallMPI(MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm));
  if (first == size) PetscFunctionReturn(0);
  int len = (int)error.size();
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, first, comm));
  std::string msg = error;
  msg.resize((size_t)len);
  PetscCallMPI(MPI_Bcast(msg.data(), len, MPI_CHAR, first, comm));
  SETERRQ(comm, PETSC_ERR_FILE_WRITE, "%s", msg.c_str());
}

std::string Why(const std::string &path)
{
  return "Cannot write " + path + ": " + std::strerror(errno);
}

// The most loaded joint of the step (largest in-plane force, the smallest id among equals) from each
// rank's own records, kept when it is more loaded than every earlier step's: two reductions, no
// gather. Ties are left out: they carry whole loads into parts (a rigid patch's), and the question
// is which fastener is most loaded. mine[k] is the record of the k-th local joint.
PetscErrorCode MostLoaded(BoltnetAssembly a, const StepInfo &info, const std::vector<JointRecord> &mine, Output *out)
{
  PetscReal most = -1, gmost;
  PetscInt  joint = PETSC_MAX_INT, gjoint;
  PetscFunctionBeginUser;
  PetscCheck(mine.size() == a->joints.size(), PETSC_COMM_SELF, PETSC_ERR_PLIB, "%zu joint records for %zu local joints", mine.size(), a->joints.size());
  auto counts = [&](size_t k) { return !a->joints.comp[k].tie; };
  for (size_t k = 0; k < mine.size(); ++k)
    if (counts(k)) most = std::max(most, std::hypot(mine[k].force[1], mine[k].force[2]));
  PetscCall(MPIU_Allreduce(&most, &gmost, 1, MPIU_REAL, MPIU_MAX, a->comm));
  for (size_t k = 0; k < mine.size(); ++k)
    if (counts(k) && std::hypot(mine[k].force[1], mine[k].force[2]) == gmost) joint = std::min(joint, mine[k].joint);
  PetscCall(MPIU_Allreduce(&joint, &gjoint, 1, MPIU_INT, MPI_MIN, a->comm));
  if (gjoint != PETSC_MAX_INT && gmost > out->most_force) {
    out->most_force = gmost;
    out->most_joint = gjoint;
    out->most_step  = info.step;
    out->most_load  = info.load;
  }
  PetscFunctionReturn(0);
}

std::string FieldsError(const Output *out, const StepInfo &info, const ErrorLog &log)
{
  return "Cannot write the fields of step " + std::to_string(info.step) + " in " + out->dir + "/fields.h5 or its xdmf files (-output_fields false turns them off): " + ErrorText(log);
}

} // namespace

// The whole of `text` into `path` through `path`.tmp and a rename: on disk the file is either absent
// (or the previous one) or whole. Every step is checked (a full disk fails at the flush or the
// close, not at fputs); on failure the temporary file is removed. Returns the error, "" if none.
std::string WriteFileWhole(const std::string &path, const std::string &text)
{
  const std::string tmp = path + ".tmp";
  std::error_code   ec;
  FILE             *f = std::fopen(tmp.c_str(), "w");
  if (!f) return Why(tmp);
  errno         = 0;
  std::string e = std::fputs(text.c_str(), f) < 0 || std::fflush(f) != 0 ? Why(tmp) : "";
  if (std::fclose(f) != 0 && e.empty()) e = Why(tmp);
  if (e.empty()) {
    std::filesystem::rename(tmp, path, ec);
    if (ec) e = "Cannot write " + path + ": " + ec.message();
  }
  if (!e.empty()) std::filesystem::remove(tmp, ec);
  return e;
}

PetscErrorCode OutputOpen(MPI_Comm comm, const std::string &dir, const std::string &scene, const FieldsOptions &fields, const JointOutputOptions &joints, BoltnetAssembly a, Output *out)
{
  PetscMPIInt rank;
  int         ok = 1;
  std::string why;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  out->dir      = dir;
  out->scene    = scene;
  out->files    = JointFilesFor(joints, (size_t)a->layout.njoints);
  out->fields   = (fields.fields && !a->layout.shells.empty()) ? PETSC_TRUE : PETSC_FALSE;
  out->ff.dir   = dir;
  out->ff.scene = scene;
  out->ff.opt   = fields;
  out->ff.bypass_csv = out->files.csv; // a model large enough for joints.h5 has its bypass in fields.h5 only
  if (out->fields && fields.gather) {
    PetscInt tri = -1, any; // the id of a part with triangles
    for (const auto &[index, sp] : a->layout.shells)
      for (const MeshElement &e : sp.mesh.elems)
        if (ElementNodes(e) == 3) tri = sp.id;
    PetscCall(MPIU_Allreduce(&tri, &any, 1, MPIU_INT, MPI_MAX, comm));
    PetscCheck(any < 0, comm, PETSC_ERR_SUP, "-output_fields_gather writes quadrilaterals only (the former writer, kept to measure against): part %" PetscInt_FMT " has triangles", any);
  }
  if (rank == 0) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    // The directory must take new files before an earlier run's are removed: a run that cannot
    // write leaves them as they were.
    const std::string probe = dir + "/.boltnet-write-test";
    FILE             *f     = std::fopen(probe.c_str(), "w");
    ok                      = f ? 1 : 0;
    if (f) std::fclose(f);
    std::filesystem::remove(probe, ec);
  }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm));
  PetscCheck(ok, comm, PETSC_ERR_FILE_OPEN, "Cannot write results in the output directory '%s' (-output_dir)", dir.c_str());
  if (rank == 0) {
    std::error_code ec;
    // A summary left by an earlier run must not look like this run's result, nor a joint file of
    // the kind this run does not write (those it writes are truncated when opened).
    for (const char *name : {"summary.json", "fields.xdmf", "joints.xdmf", "bypass.csv", "fields.h5"}) std::filesystem::remove(dir + "/" + name, ec);
    if (!out->files.csv) std::filesystem::remove(dir + "/joints.csv", ec);
    if (!out->files.hdf5) std::filesystem::remove(dir + "/joints.h5", ec);
    if (out->files.csv) {
      errno    = 0;
      out->csv = std::fopen((dir + "/joints.csv").c_str(), "w");
      if (!out->csv || std::fprintf(out->csv, "%s\n", kJointsHeader) < 0 || std::fflush(out->csv) != 0) why = Why(dir + "/joints.csv");
    }
  }
  PetscCall(ShareError(comm, why));
  if (out->files.hdf5) {
    ErrorLog log;
    PetscCall(PetscPushErrorHandler(CaptureErrorHandler, &log));
    const PetscErrorCode ierr = JointTableCreate(a, scene, dir + "/joints.h5", &out->table);
    PetscCall(PetscPopErrorHandler());
    PetscCall(ShareAnyError(comm, ierr ? "Cannot write the joint table " + dir + "/joints.h5 (-output_joints): " + ErrorText(log) : ""));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode OutputStep(BoltnetAssembly a, const StepInfo &info, Output *out)
{
  std::vector<JointRecord> rec;
  PetscFunctionBeginUser;
  // -log_view: the field output's time is BoltnetOutput (scripts/bench-output measures it), and
  // the whole step's output is the stage "Boltnet Output".
  PetscCall(PetscLogStagePush(Events().output_stage));
  PetscCall(PetscLogEventBegin(Events().output, 0, 0, 0, 0));
  if (out->fields && out->ff.opt.gather) {
    std::vector<PartField> parts;
    std::vector<JointLine> lines;
    PetscErrorCode         ierr = 0;
    PetscCall(AssemblyGatherFields(a, parts, lines));
    std::string            why;
    if (a->rank == 0) { // rank 0 alone writes: its error is shared before anyone goes on
      ErrorLog log;
      PetscCall(PetscPushErrorHandler(CaptureErrorHandler, &log));
      ierr = FieldsWriteStepGather(&out->ff, info, parts, lines);
      PetscCall(PetscPopErrorHandler());
      if (ierr) why = FieldsError(out, info, log);
    }
    PetscCall(ShareError(a->comm, why));
  } else if (out->fields) { // every rank writes its rows; rank 0 the xdmf files
    ErrorLog log;
    PetscCall(PetscPushErrorHandler(CaptureErrorHandler, &log));
    const PetscErrorCode ierr = FieldsWriteStep(a, &out->ff, info);
    PetscCall(PetscPopErrorHandler());
    PetscCall(ShareAnyError(a->comm, ierr ? FieldsError(out, info, log) : ""));
  }
  PetscCall(PetscLogEventEnd(Events().output, 0, 0, 0, 0));
  std::vector<JointRecord> mine;
  PetscCall(AssemblyJointRecords(a, mine)); // collective: the ranks start the joint output together
  // -log_view: the joint output's time is BoltnetJointOutput (scripts/bench-output --joints).
  PetscCall(PetscLogEventBegin(Events().joint_output, 0, 0, 0, 0));
  PetscCall(MostLoaded(a, info, mine, out));
  if (out->files.hdf5) {
    ErrorLog log;
    PetscCall(PetscPushErrorHandler(CaptureErrorHandler, &log));
    const PetscErrorCode ierr = JointTableWriteStep(a, &out->table, info, mine);
    PetscCall(PetscPopErrorHandler());
    PetscCall(ShareAnyError(a->comm, ierr ? "Cannot write step " + std::to_string(info.step) + " of the joint table " + out->table.path + " (-output_joints): " + ErrorText(log) : ""));
  }
  std::string why;
  if (out->files.csv) {
    PetscCall(GatherJointRecords(a, mine, rec));
    for (const JointRecord &r : rec) { // rank 0 has the records, the others none
      errno = 0;
      if (std::fprintf(out->csv, "%" PetscInt_FMT ",%.17g,%" PetscInt_FMT ",%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%" PetscInt_FMT ",%.17g,%.17g\n", info.step, (double)info.load, r.joint, stateName(static_cast<State>(r.state)), r.jump[0], r.jump[1], r.jump[2], r.force[0], r.force[1], r.force[2], r.bearing, r.slip[0], r.slip[1]) < 0) {
        why = Why(out->dir + "/joints.csv");
        break;
      }
    }
    // Each step is on disk (or its failure known) before the next is solved.
    if (a->rank == 0 && why.empty()) {
      errno = 0;
      if (std::fflush(out->csv) != 0) why = Why(out->dir + "/joints.csv");
    }
  }
  PetscCall(PetscLogEventEnd(Events().joint_output, 0, 0, 0, 0));
  PetscCall(ShareError(a->comm, why));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

PetscErrorCode OutputSummary(BoltnetAssembly a, Output *out, const std::string &status, const std::string &message)
{
  SNES           snes  = a->snes;
  SNESLineSearch ls;
  KSP            ksp;
  PC             pc;
  SNESLineSearchType lstype;
  KSPType        ktype;
  PCType         ptype;
  MatSolverType  stype = nullptr;
  PetscBool      ew;
  PetscFunctionBeginUser;
  PetscCall(SNESGetLineSearch(snes, &ls));
  PetscCall(SNESLineSearchGetType(ls, &lstype));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPGetType(ksp, &ktype));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCGetType(pc, &ptype));
  PetscCall(PCFactorGetMatSolverType(pc, &stype));
  PetscCall(SNESKSPGetUseEW(snes, &ew));
  PetscCall(ResidentMemory(a->comm, true, &out->peak_mb));
  std::string why;
  if (a->rank == 0) {
    std::ostringstream j;
    j.precision(17);
    j << "{\n  \"scene\": " << JsonString(out->scene);
    if (!out->load_case.empty()) j << ",\n  \"load_case\": " << JsonString(out->load_case);
    if (!out->continues.empty()) j << ",\n  \"continues\": " << JsonString(out->continues);
    j << ",\n  \"status\": " << JsonString(status) << ",\n  \"message\": " << JsonString(message) << ",\n  \"ranks\": " << a->size
      << ",\n  \"parts\": " << a->layout.nparts << ",\n  \"patches\": " << a->layout.patches.size() << ",\n  \"seams\": " << a->layout.seams.size() << ",\n  \"joints\": " << a->layout.njoints << ",\n  \"dof\": " << a->net.ndof_model << ",\n  \"interface_dof\": " << a->net.ndof_global << ",\n  \"condensed\": " << (a->net.ncondensed > 0 ? "true" : "false") << ",\n  \"condensed_patches\": " << a->net.ncondensed << ",\n  \"dof_imbalance\": " << JsonNumber(a->net.dof_imbalance) << ",\n  \"joint_tangent\": " << JsonString(a->opt.tangent == Tangent::Paper ? "paper" : "consistent")
      << ",\n  \"line_search\": " << JsonString(lstype ? lstype : "") << ",\n  \"linear_solver\": " << JsonString(std::string(ktype ? ktype : "") + "+" + (ptype ? ptype : "") + (stype ? std::string("(") + stype + ")" : ""))
      << ",\n  \"steps\": " << a->steps.size() << ",\n  \"final_load\": " << JsonNumber(a->lambda) << ",\n  \"cutbacks\": " << a->total_cutbacks << ",\n  \"newton_iterations\": [";
    for (size_t i = 0; i < a->steps.size(); ++i) j << (i ? ", " : "") << a->steps[i].newton_its;
    j << "],\n  \"cutbacks_per_step\": [";
    for (size_t i = 0; i < a->steps.size(); ++i) j << (i ? ", " : "") << a->steps[i].cutbacks;
    j << "],\n  \"stuck_linear\": " << (a->opt.stuck_linear ? "true" : "false") << ",\n  \"frozen_share\": " << JsonNumber(a->joints.joint_steps ? (double)a->joints.frozen_joint_steps / (double)a->joints.joint_steps : 0.0)
      << ",\n  \"released\": " << a->joints.released << ",\n  \"jacobians_assembled\": " << a->joints.jac_assembled << ",\n  \"jacobians_reused\": " << a->joints.jac_reused
      << ",\n  \"interface_solve\": " << JsonString(a->isolve.P ? "bddc" : a->isolve.lagged ? "lagged" : "direct") << ",\n  \"linear_solves\": " << a->isolve.linear_solves << ",\n  \"krylov_iterations\": " << a->isolve.krylov_its << ",\n  \"ksp_ew\": " << (ew ? "true" : "false") << ",\n  \"factor_flops_per_entry\": " << a->isolve.flops_per_entry << ",\n  \"lagged_factorisations\": " << a->isolve.factorisations << ",\n  \"jacobians_kept\": " << a->isolve.kept << ",\n  \"factors_on_disk\": " << (a->isolve.factors_on_disk ? "true" : "false");
    j << ",\n  \"most_loaded_joint\": ";
    if (out->most_joint >= 0) j << "{\"joint\": " << out->most_joint << ", \"step\": " << out->most_step << ", \"load\": " << JsonNumber(out->most_load) << ", \"in_plane_force\": " << JsonNumber(out->most_force) << "}";
    else j << "null";
    j << ",\n  \"identified_joint_types\": " << out->identified;
    // Resident MB per rank, [smallest, largest]: at the end of each phase of the set-up, and the peak.
    j << ",\n  \"memory_mb\": {";
    auto mb = [](const RankRange &r) { return "[" + std::to_string(std::llround(r[0])) + ", " + std::to_string(std::llround(r[1])) + "]"; };
    for (const MemoryMark &m : a->memory) j << JsonString(m.phase) << ": " << mb(m.mb) << ", ";
    j << "\"peak\": " << mb(out->peak_mb) << "}";
    j << "\n}\n";
    // Written last, whole or not at all: a summary on disk is never a cut one.
    why = WriteFileWhole(out->dir + "/summary.json", j.str());
  }
  PetscCall(ShareError(a->comm, why));
  PetscFunctionReturn(0);
}

void OutputDiscard(Output *out)
{
  if (out->csv) std::fclose(out->csv);
  out->csv = nullptr;
  JointTableClose(&out->table);
  FieldsClose(&out->ff);
}

PetscErrorCode OutputClose(MPI_Comm comm, Output *out)
{
  std::string why;
  PetscFunctionBeginUser;
  errno = 0;
  if (out->csv && std::fclose(out->csv) != 0) why = Why(out->dir + "/joints.csv");
  out->csv = nullptr;
  PetscCall(JointTableClose(&out->table));
  PetscCall(FieldsClose(&out->ff));
  PetscCall(ShareError(comm, why));
  PetscFunctionReturn(0);
}

} // namespace boltnet
