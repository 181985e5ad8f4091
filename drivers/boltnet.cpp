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

#include "driver.hpp"
#include "io/io.hpp"
#include "io/limits.hpp"
#include "solver/loadpath.hpp"

#include <new>
#include <string>

using namespace boltnet;

namespace {

// The assembly and the open result files are released on every return from Run, an error's
// included, so that a run stopped by bad input leaks nothing (scripts/sanitize checks it). Their
// own errors then are not the one reported.
struct Release {
  BoltnetAssembly a = nullptr;
  Output          out;
  ~Release()
  {
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    OutputDiscard(&out);
    BoltnetAssemblyDestroy(&a);
    PetscPopErrorHandler();
  }
};

PetscErrorCode Run(int *exitcode, ErrorLog *log)
{
  MPI_Comm        comm = PETSC_COMM_WORLD;
  char            file[PETSC_MAX_PATH_LEN] = "", outdir[PETSC_MAX_PATH_LEN] = "";
  PetscBool       hasScene, helpOnly, optionsLeft = PETSC_FALSE;
  FieldsOptions   fields;
  Scene           scene;
  LoadPath        path;
  Release         held;
  BoltnetAssembly &a   = held.a;
  Output          &out = held.out;
  PetscFunctionBeginUser;
  PetscCall(BoltnetInitializePackage());
  PetscCall(PetscOptionsHasHelp(nullptr, &helpOnly));
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-options_left", &optionsLeft, nullptr));
  PetscOptionsBegin(comm, nullptr, "boltnet driver", "boltnet");
  PetscCall(PetscOptionsString("-scene", "Scene file (PETSc YAML options)", "", file, file, sizeof(file), &hasScene));
  PetscCall(PetscOptionsString("-output_dir", "Directory for joints.csv, summary.json and the fields (default results/<scene name>)", "", outdir, outdir, sizeof(outdir), nullptr));
  PetscCall(FieldsOptionsFromCommandLine(PetscOptionsObject, &fields));
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
  PetscCall(PetscPrintf(comm, "boltnet: scene %s, %" PetscInt_FMT " parts in %zu patches (%zu seams), %zu joints, %" PetscInt_FMT " dof on %d rank(s) (dof imbalance max/mean %.2f)", scene.name.c_str(), a->layout.nparts, a->layout.patches.size(), a->layout.seams.size(), a->layout.joints.size(), a->net.ndof_model, a->size, (double)a->net.dof_imbalance));
  if (a->opt.condense) PetscCall(PetscPrintf(comm, "; condensed onto %" PetscInt_FMT " interface dof", a->net.ndof_global));
  PetscCall(PetscPrintf(comm, "\n"));

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

} // namespace

int main(int argc, char **argv)
{
  return DriverMain("boltnet", &argc, &argv, help, Run);
}
