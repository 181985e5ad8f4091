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

#include "io/io.hpp"
#include "solver/loadpath.hpp"

#include <string>

using namespace boltnet;

namespace {

PetscErrorCode Run(int *exitcode)
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

  // Everything is read and checked before anything is written.
  PetscCall(BoltnetAssemblyCreate(comm, &a));
  PetscCall(SceneDescribeAssembly(comm, &scene, a));
  PetscCall(LoadPathFromOptions(comm, nullptr, &path));
  PetscCall(BoltnetAssemblySetFromOptions(a));
  PetscCall(BoltnetAssemblySetUp(a));
  PetscCall(SceneCheckUnusedOptions(comm));
  if (helpOnly) {
    PetscCall(BoltnetAssemblyDestroy(&a));
    PetscFunctionReturn(0);
  }

  const std::string dir = outdir[0] ? std::string(outdir) : "results/" + scene.name;
  PetscCall(OutputOpen(comm, dir, scene.name, fields, a, &out));
  out.identified = "{" + scene.identified + "}";
  a->on_step = [&out](BoltnetAssembly as, const StepInfo &info) { return OutputStep(as, info, &out); };
  PetscCall(PetscPrintf(comm, "boltnet: scene %s, %" PetscInt_FMT " parts in %zu patches (%zu seams), %zu joints, %" PetscInt_FMT " dof on %d rank(s) (dof imbalance max/mean %.2f)", scene.name.c_str(), a->layout.nparts, a->layout.patches.size(), a->layout.seams.size(), a->layout.joints.size(), a->net.ndof_model, a->size, (double)a->net.dof_imbalance));
  if (a->opt.condense) PetscCall(PetscPrintf(comm, "; condensed onto %" PetscInt_FMT " interface dof", a->net.ndof_global));
  PetscCall(PetscPrintf(comm, "\n"));

  // A step that fails beyond the cut-back bound is reported, recorded in summary.json, and the
  // program exits non-zero.
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  PetscErrorCode ierr = BoltnetAssemblySolveLoadPath(a, (PetscInt)path.breakpoints.size(), path.breakpoints.data(), path.steps_per_segment);
  PetscCall(PetscPopErrorHandler());
  if (ierr) {
    PetscCheck(!a->failure.empty(), comm, ierr == PETSC_ERR_NOT_CONVERGED ? PETSC_ERR_NOT_CONVERGED : PETSC_ERR_LIB, "The load path failed (error %d)", (int)ierr);
    PetscCall(PetscPrintf(comm, "boltnet: FAILED: %s\n", a->failure.c_str()));
    PetscCall(OutputSummary(a, &out, "failed", a->failure));
    *exitcode = 3;
  } else {
    PetscCall(OutputSummary(a, &out, "converged", ""));
    PetscCall(PetscPrintf(comm, "boltnet: %zu steps converged (%" PetscInt_FMT " cut-backs), load factor %g; results in %s/\n", a->steps.size(), a->total_cutbacks, (double)a->lambda, dir.c_str()));
    if (out.most_joint >= 0)
      PetscCall(PetscPrintf(comm, "boltnet: most loaded joint %" PetscInt_FMT ": in-plane force %g at step %" PetscInt_FMT " (load %g)\n", out.most_joint, (double)out.most_force, out.most_step, (double)out.most_load));
  }
  PetscCall(OutputClose(&out));
  PetscCall(BoltnetAssemblyDestroy(&a));

  if (optionsLeft) PetscCall(UnusedOptionsAsError(comm, "boltnet", exitcode)); // an error, not a warning
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv)
{
  int exitcode = 0;
  PetscCall(PetscInitialize(&argc, &argv, nullptr, help));
  // An error returns from main at once with PETSc's message (mpiexec then ends every rank), so an
  // error raised on one rank alone cannot leave the others waiting.
  PetscCall(Run(&exitcode));
  PetscCall(PetscFinalize());
  return exitcode;
}
