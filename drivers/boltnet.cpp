static const char help[] = "boltnet: bolted assemblies with frictional macroelements on a PETSc DMNetwork.\n\
\n\
Runs a scene: a PETSc YAML options file plus the CSV tables it names (patches, fastener table,\n\
boundary conditions), through its load path, and writes results under -output_dir:\n\
joints.csv (one row per joint per converged step), summary.json and, for scenes with shell patches,\n\
fields.h5 + fields.xdmf (shell displacement and rotation, joints as lines with their state, per\n\
step; open fields.xdmf in ParaView: docs/output.md).\n\
\n\
  mpirun -n 2 build/bin/boltnet -scene share/scenes/fig3c.yaml\n\
  mpirun -n 3 build/bin/boltnet -scene share/scenes/fig3c.yaml -load_steps 4 -joint_monitor\n\
  build/bin/boltnet -scene share/scenes/fig3c.yaml -joint_bolt_mu 0.3 -output_dir /tmp/mu03\n\
  build/bin/boltnet -scene share/scenes/fig3c.yaml -help      (every option, with defaults and units)\n\
\n\
Options on the command line override the scene file. With -options_left, an option that nothing\n\
used is an error.\n\n";

#include "core/errors.hpp"
#include "io/io.hpp"
#include "io/limits.hpp"
#include "solver/loadpath.hpp"

#include <cstdio>
#include <exception>
#include <new>
#include <string>

using namespace boltnet;

namespace {

// How long a rank that stopped on an error waits for the others to stop too (seconds). Checks of
// input are collective (every rank raises the same error at the same point) and the ranks then end
// cleanly; an error raised on one rank alone leaves the others waiting in a collective call, and
// only MPI_Abort can end them.
constexpr double kErrorAgreeSeconds = 10;

PetscErrorCode Run(int *exitcode, ErrorLog *log)
{
  MPI_Comm        comm = PETSC_COMM_WORLD;
  char            file[PETSC_MAX_PATH_LEN] = "", outdir[PETSC_MAX_PATH_LEN] = "";
  PetscBool       hasScene, helpOnly, optionsLeft = PETSC_FALSE, fields = PETSC_TRUE;
  Scene           scene;
  LoadPath        path;
  BoltnetAssembly a = nullptr;
  Output          out;
  PetscFunctionBeginUser;
  PetscCall(BoltnetInitializePackage());
  PetscCall(PetscOptionsHasHelp(nullptr, &helpOnly));
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-options_left", &optionsLeft, nullptr));
  PetscOptionsBegin(comm, nullptr, "boltnet driver", "boltnet");
  PetscCall(PetscOptionsString("-scene", "Scene file (PETSc YAML options)", "", file, file, sizeof(file), &hasScene));
  PetscCall(PetscOptionsString("-output_dir", "Directory for joints.csv, summary.json and the fields (default results/<scene name>)", "", outdir, outdir, sizeof(outdir), nullptr));
  PetscCall(PetscOptionsBool("-output_fields", "Write fields.h5 + fields.xdmf per converged step (shell displacement/rotation, joint lines with state); scenes with no shell patch (rigid only) have no fields", "", fields, &fields, nullptr));
  PetscOptionsEnd();
  if (!hasScene && helpOnly) { // list the options that do not depend on a scene
    PetscCall(LoadPathFromOptions(comm, nullptr, &path));
    PetscCall(BoltnetAssemblyCreate(comm, &a));
    PetscCall(BoltnetAssemblySetFromOptions(a));
    PetscCall(BoltnetAssemblyDestroy(&a));
    PetscFunctionReturn(0);
  }
  PetscCheck(hasScene, comm, PETSC_ERR_USER_INPUT, "No scene: give -scene <file.yaml> (e.g. -scene share/scenes/fig3c.yaml); -help lists the options");
  PetscCall(SceneInsertOptionsFile(comm, file, &scene));
  PetscCall(SceneCheckOptionValues(comm));

  // Everything is read and checked before anything is written.
  PetscCall(BoltnetAssemblyCreate(comm, &a));
  PetscCall(SceneDescribeAssembly(comm, &scene, a));
  PetscCall(LoadPathFromOptions(comm, nullptr, &path));
  {
    const std::int64_t segments = std::max<std::int64_t>(1, (std::int64_t)path.breakpoints.size());
    PetscCheck(segments * path.steps_per_segment <= limits::kMaxLoadSteps, comm, PETSC_ERR_USER_INPUT, "-load_steps %" PetscInt_FMT " over %lld segment(s) of the load path is more than the limit of %lld steps (docs/scenes.md, \"Limits\")", path.steps_per_segment, (long long)segments, (long long)limits::kMaxLoadSteps);
  }
  PetscCall(BoltnetAssemblySetFromOptions(a));
  PetscCall(BoltnetAssemblySetUp(a));
  PetscCall(SceneCheckUnusedOptions(comm));
  if (helpOnly) {
    PetscCall(BoltnetAssemblyDestroy(&a));
    PetscFunctionReturn(0);
  }
  // With -options_left, an option nothing has used by now (except those PETSc reads only during or
  // after a solve) stops the run before anything is written.
  if (optionsLeft) {
    PetscCall(UnusedOptionsAsError(comm, "boltnet", PETSC_TRUE, exitcode));
    if (*exitcode) {
      PetscCall(PetscOptionsClearValue(nullptr, "-options_left")); // said above: PETSc's list would repeat it
      PetscCall(BoltnetAssemblyDestroy(&a));
      PetscFunctionReturn(0);
    }
  }

  const std::string dir = outdir[0] ? std::string(outdir) : "results/" + scene.name;
  PetscCall(OutputOpen(comm, dir, scene.name, fields, a, &out));
  out.identified = "{" + scene.identified + "}";
  a->on_step = [&out](BoltnetAssembly as, const StepInfo &info) { return OutputStep(as, info, &out); };
  PetscCall(PetscPrintf(comm, "boltnet: scene %s, %" PetscInt_FMT " parts in %zu patches (%zu seams), %zu joints, %" PetscInt_FMT " dof on %d rank(s) (dof imbalance max/mean %.2f)\n", scene.name.c_str(), a->nparts, a->patches.size(), a->seams.size(), a->joints.size(), a->ndof_global, a->size, (double)a->dof_imbalance));

  // A step that fails beyond the cut-back bound is reported, recorded in summary.json, and the
  // program exits 3. Any other error (a file that cannot be written, a library failure) goes up
  // with its own message and leaves no summary.json: OutputOpen removed the last run's.
  log->messages.clear();
  PetscErrorCode ierr;
  try {
    ierr = BoltnetAssemblySolveLoadPath(a, (PetscInt)path.breakpoints.size(), path.breakpoints.data(), path.steps_per_segment);
  } catch (const std::bad_alloc &) {
    SETERRQ(comm, PETSC_ERR_MEM, "Out of memory during the load path");
  }
  if (ierr && a->failure.empty()) {
    const std::string why = ErrorText(*log);
    SETERRQ(comm, ierr, "The load path stopped at load factor %g: %s", (double)a->lambda, why.empty() ? "PETSc error" : why.c_str());
  }
  log->messages.clear();
  if (ierr) {
    PetscCall(PetscPrintf(comm, "boltnet: FAILED: %s\n", a->failure.c_str()));
    PetscCall(OutputSummary(a, &out, "failed", a->failure));
    *exitcode = 3;
  } else {
    PetscCall(OutputSummary(a, &out, "converged", ""));
    PetscCall(PetscPrintf(comm, "boltnet: %zu steps converged (%" PetscInt_FMT " cut-backs), load factor %g; results in %s/\n", a->steps.size(), a->total_cutbacks, (double)a->lambda, dir.c_str()));
    if (out.most_joint >= 0)
      PetscCall(PetscPrintf(comm, "boltnet: most loaded joint %" PetscInt_FMT ": in-plane force %g at step %" PetscInt_FMT " (load %g)\n", out.most_joint, (double)out.most_force, out.most_step, (double)out.most_load));
  }
  PetscCall(OutputClose(comm, &out));
  PetscCall(BoltnetAssemblyDestroy(&a));

  if (optionsLeft) PetscCall(UnusedOptionsAsError(comm, "boltnet", PETSC_FALSE, exitcode)); // an error, not a warning
  PetscFunctionReturn(0);
}

// The message of the error: PETSc's first message and its outermost context (core/errors.hpp);
// PETSc's complaint about an option's value ("Input string abc has no numeric value") names the
// option(s) with that value.
std::string Describe(const ErrorLog &log)
{
  std::string msg = ErrorText(log);
  if (msg.empty()) msg = "unknown error";
  try {
    // PETSc 3.18's words for a value it cannot convert (PetscOptionsStringToInt, _ToReal, _ToBool).
    std::string value;
    const size_t a = msg.find("Input string "), b = msg.find(" has no "), c = msg.find("Unknown logical value: ");
    if (a != std::string::npos && b != std::string::npos && b > a) value = msg.substr(a + 13, b - a - 13);
    else if (c != std::string::npos) value = msg.substr(c + 23);
    std::string names;
    if (!value.empty() && !OptionsWithValue(value, &names) && !names.empty()) msg = "option " + names + ": " + msg;
  } catch (...) {
  }
  return msg;
}

// One line on rank 0 and a clean exit on every rank when every rank stopped on the error; the
// message of each rank that did and MPI_Abort otherwise (kErrorAgreeSeconds).
int Fail(MPI_Comm agree, const ErrorLog &log)
{
  const std::string msg = Describe(log);
  int               rank = 0, done = 0;
  MPI_Request       req;
  MPI_Comm_rank(agree, &rank);
  MPI_Ibarrier(agree, &req);
  const double t0 = MPI_Wtime();
  while (!done && MPI_Wtime() - t0 < kErrorAgreeSeconds) {
    MPI_Test(&req, &done, MPI_STATUS_IGNORE);
    if (!done) PetscSleep(0.01);
  }
  if (!done) {
    std::fprintf(stderr, "boltnet: error (rank %d): %s\n", rank, msg.c_str());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  }
  if (rank == 0) std::fprintf(stderr, "boltnet: error: %s\n", msg.c_str());
  // Nothing more to say: no list of options left unused by a run that stopped.
  PetscOptionsClearValue(nullptr, "-options_left");
  MPI_Comm_free(&agree);
  PetscPopErrorHandler();
  PetscFinalize();
  return 1;
}

} // namespace

int main(int argc, char **argv)
{
  int      exitcode = 0;
  ErrorLog log;
  MPI_Comm agree = MPI_COMM_NULL;
  if (PetscInitialize(&argc, &argv, nullptr, help)) return 1;
  // Errors are collected, not printed as PETSc's traceback (one line instead of about forty);
  // Fail() prints the message.
  if (PetscPushErrorHandler(CaptureErrorHandler, &log) || MPI_Comm_dup(PETSC_COMM_WORLD, &agree)) return 1;
  PetscErrorCode ierr;
  try {
    ierr = Run(&exitcode, &log);
  } catch (const std::bad_alloc &) {
    log.messages.push_back("Out of memory");
    ierr = PETSC_ERR_MEM;
  } catch (const std::exception &e) {
    log.messages.push_back(std::string("C++ exception: ") + e.what());
    ierr = PETSC_ERR_LIB;
  }
  if (ierr) return Fail(agree, log);
  MPI_Comm_free(&agree);
  PetscPopErrorHandler();
  if (PetscFinalize()) return 1;
  return exitcode;
}
