// Results: joints.csv (one row per joint per converged step), summary.json and the fields
// (io/fields.cpp), written by rank 0.
#include "io/io.hpp"

#include <cmath>
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

} // namespace

PetscErrorCode OutputOpen(MPI_Comm comm, const std::string &dir, const std::string &scene, PetscBool fields, BoltnetAssembly a, Output *out)
{
  PetscMPIInt rank;
  int         ok = 1;
  std::string why;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  out->dir      = dir;
  out->scene    = scene;
  out->fields   = (fields && !a->layout.shells.empty()) ? PETSC_TRUE : PETSC_FALSE;
  out->ff.dir   = dir;
  out->ff.scene = scene;
  if (rank == 0) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    // A summary left by an earlier run must not look like this run's result.
    std::filesystem::remove(dir + "/summary.json", ec);
    std::filesystem::remove(dir + "/fields.xdmf", ec);
    std::filesystem::remove(dir + "/fields.h5", ec);
    out->csv = std::fopen((dir + "/joints.csv").c_str(), "w");
    ok       = out->csv ? 1 : 0;
    if (ok) std::fprintf(out->csv, "step,load,joint,state,du_n,du_t1,du_t2,f_n,f_t1,f_t2,bearing,slip_t1,slip_t2\n");
  }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm));
  PetscCheck(ok, comm, PETSC_ERR_FILE_OPEN, "Cannot write results in the output directory '%s' (-output_dir)", dir.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode OutputStep(BoltnetAssembly a, const StepInfo &info, Output *out)
{
  std::vector<JointRecord> rec;
  PetscFunctionBeginUser;
  if (out->fields) {
    std::vector<PartField> parts;
    std::vector<JointLine> lines;
    PetscErrorCode         ierr = 0;
    PetscCall(AssemblyGatherFields(a, parts, lines));
    if (a->rank == 0) { // rank 0 alone writes: its error is shared before anyone goes on
      PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
      ierr = FieldsWriteStep(&out->ff, info, parts, lines);
      PetscCall(PetscPopErrorHandler());
    }
    PetscCallMPI(MPI_Bcast(&ierr, 1, MPI_INT, 0, a->comm));
    PetscCheck(!ierr, a->comm, PETSC_ERR_FILE_WRITE, "Cannot write the fields of step %" PetscInt_FMT " in %s/fields.h5 (error %d; -output_fields false turns them off)", info.step, out->dir.c_str(), (int)ierr);
  }
  PetscCall(AssemblyGatherRecords(a, rec));
  if (a->rank != 0) PetscFunctionReturn(0);
  for (const JointRecord &r : rec) {
    std::fprintf(out->csv, "%" PetscInt_FMT ",%.17g,%" PetscInt_FMT ",%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%" PetscInt_FMT ",%.17g,%.17g\n", info.step, (double)info.load, r.joint, stateName(static_cast<State>(r.state)), r.jump[0], r.jump[1], r.jump[2], r.force[0], r.force[1], r.force[2], r.bearing, r.slip[0], r.slip[1]);
    const PetscReal ft = std::hypot(r.force[1], r.force[2]);
    if (ft > out->most_force) {
      out->most_force = ft;
      out->most_joint = r.joint;
      out->most_step  = info.step;
      out->most_load  = info.load;
    }
  }
  std::fflush(out->csv);
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
  PetscFunctionBeginUser;
  PetscCall(SNESGetLineSearch(snes, &ls));
  PetscCall(SNESLineSearchGetType(ls, &lstype));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPGetType(ksp, &ktype));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCGetType(pc, &ptype));
  PetscCall(PCFactorGetMatSolverType(pc, &stype));
  if (a->rank != 0) PetscFunctionReturn(0);
  std::ostringstream j;
  j.precision(17);
  j << "{\n  \"scene\": " << JsonString(out->scene) << ",\n  \"status\": " << JsonString(status) << ",\n  \"message\": " << JsonString(message) << ",\n  \"ranks\": " << a->size
    << ",\n  \"parts\": " << a->layout.nparts << ",\n  \"patches\": " << a->layout.patches.size() << ",\n  \"seams\": " << a->layout.seams.size() << ",\n  \"joints\": " << a->layout.joints.size() << ",\n  \"dof\": " << a->net.ndof_model << ",\n  \"interface_dof\": " << a->net.ndof_global << ",\n  \"condensed\": " << (a->opt.condense ? "true" : "false") << ",\n  \"dof_imbalance\": " << a->net.dof_imbalance << ",\n  \"joint_tangent\": " << JsonString(a->opt.tangent == Tangent::Paper ? "paper" : "consistent")
    << ",\n  \"line_search\": " << JsonString(lstype ? lstype : "") << ",\n  \"linear_solver\": " << JsonString(std::string(ktype ? ktype : "") + "+" + (ptype ? ptype : "") + (stype ? std::string("(") + stype + ")" : ""))
    << ",\n  \"steps\": " << a->steps.size() << ",\n  \"final_load\": " << a->lambda << ",\n  \"cutbacks\": " << a->total_cutbacks << ",\n  \"newton_iterations\": [";
  for (size_t i = 0; i < a->steps.size(); ++i) j << (i ? ", " : "") << a->steps[i].newton_its;
  j << "],\n  \"cutbacks_per_step\": [";
  for (size_t i = 0; i < a->steps.size(); ++i) j << (i ? ", " : "") << a->steps[i].cutbacks;
  j << "],\n  \"stuck_linear\": " << (a->opt.stuck_linear ? "true" : "false") << ",\n  \"frozen_share\": " << (a->joints.joint_steps ? (double)a->joints.frozen_joint_steps / (double)a->joints.joint_steps : 0.0)
    << ",\n  \"released\": " << a->joints.released << ",\n  \"jacobians_assembled\": " << a->joints.jac_assembled << ",\n  \"jacobians_reused\": " << a->joints.jac_reused;
  j << ",\n  \"most_loaded_joint\": ";
  if (out->most_joint >= 0) j << "{\"joint\": " << out->most_joint << ", \"step\": " << out->most_step << ", \"load\": " << out->most_load << ", \"in_plane_force\": " << out->most_force << "}";
  else j << "null";
  j << ",\n  \"identified_joint_types\": " << out->identified;
  j << "\n}\n";
  // Write then rename, so that summary.json is either absent or whole.
  const std::string tmp = out->dir + "/summary.json.tmp";
  FILE             *f   = std::fopen(tmp.c_str(), "w");
  PetscCheck(f, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write %s", tmp.c_str());
  std::fputs(j.str().c_str(), f);
  std::fclose(f);
  std::error_code ec;
  std::filesystem::rename(tmp, out->dir + "/summary.json", ec);
  PetscCheck(!ec, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write %s/summary.json", out->dir.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode OutputClose(Output *out)
{
  PetscFunctionBeginUser;
  if (out->csv) std::fclose(out->csv);
  out->csv = nullptr;
  PetscCall(FieldsClose(&out->ff));
  PetscFunctionReturn(0);
}

} // namespace boltnet
