static const char help[] = "boltnet: bolted assemblies with frictional macroelements on a PETSc DMNetwork.\n\
\n\
Runs a scene: a PETSc YAML options file plus the CSV tables it names (patches, fastener table,\n\
boundary conditions), through its load path, and writes results under -output_dir:\n\
joints.csv (one row per joint per converged step), summary.json and, for scenes with shell patches,\n\
fields.h5, fields.xdmf, joints.xdmf and bypass.csv (shell displacement, rotation and element\n\
results, joints as lines with their state, per step, written in parallel; open the xdmf files in\n\
ParaView: docs/output.md).\n\
\n\
  mpirun -n 2 build/bin/boltnet -scene share/scenes/fig3c.yaml\n\
  mpirun -n 2 boltnet -scene fig3c        (installed: the scene share/boltnet/scenes/fig3c.yaml)\n\
  mpirun -n 3 build/bin/boltnet -scene share/scenes/fig3c.yaml -load_steps 4 -joint_monitor\n\
  build/bin/boltnet -scene share/scenes/fig3c.yaml -joint_bolt_mu 0.3 -output_dir /tmp/mu03\n\
  build/bin/boltnet -scene share/scenes/fig3c.yaml -help      (every option, with defaults and units)\n\
\n\
Each converged load step prints one line: the nominal step of the path, load factor, Newton\n\
iterations, joints sticking, sliding and bearing, elapsed time and an estimate of the time left\n\
(-load_progress false: none; docs/scenes.md, \"Progress\").\n\
\n\
A long run can keep a checkpoint every N converged steps (-checkpoint_every N) and, killed, go on\n\
from it with the same command and -restart <output_dir>/checkpoint.h5 (docs/scenes.md).\n\
\n\
A Nastran deck runs instead of a scene's tables (docs/nastran.md): every subcase into its own folder,\n\
  mpirun -n 2 build/bin/boltnet -nastran_deck model.bdf -output_dir /tmp/model\n\
\n\
Options on the command line override the scene file. With -options_left, an option that nothing\n\
used is an error.\n\n";

#include "driver.hpp"
#include "scene_path.hpp"
#include "io/checkpoint.hpp"
#include "io/io.hpp"
#include "io/limits.hpp"
#include "nastran/petsc.hpp"
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

// What one run solves: the scene's tables, or one subcase of a Nastran deck.
struct Source {
  const nastran::Deck  *deck = nullptr;
  PetscInt              subcase = 0;
  nastran::ModelOptions options;
  std::string           fasteners;
};

struct DriverOptions {
  std::string dir, ckfile, restart;
  PetscBool     helpOnly = PETSC_FALSE, optionsLeft = PETSC_FALSE;
  FieldsOptions fields;
  JointOutputOptions joints;
  PetscInt      every = 0;
};

// Describes, sets up and solves one model, and writes its results under dir.
PetscErrorCode RunOne(const Source &src, Scene &scene, const DriverOptions &o, const std::string &dir, int *exitcode, ErrorLog *log)
{
  MPI_Comm           comm = PETSC_COMM_WORLD;
  CheckpointIdentity ident;
  LoadPath           path;
  Release            held;
  BoltnetAssembly   &a   = held.a;
  Output            &out = held.out;
  PetscFunctionBeginUser;
  // Everything is read and checked before anything is written.
  PetscCall(BoltnetAssemblyCreate(comm, &a));
  a->opt.progress = PETSC_TRUE; // a run of the driver reports each converged step unless -load_progress false
  if (src.deck) PetscCall(SceneDescribeNastran(comm, &scene, *src.deck, src.subcase, src.options, src.fasteners, a));
  else PetscCall(SceneDescribeAssembly(comm, &scene, a));
  PetscCall(LoadPathFromOptions(comm, nullptr, &path));
  {
    const std::int64_t segments = std::max<std::int64_t>(1, (std::int64_t)path.breakpoints.size());
    PetscCheck(segments * path.steps_per_segment <= limits::kMaxLoadSteps, comm, PETSC_ERR_USER_INPUT, "-load_steps %" PetscInt_FMT " over %lld segment(s) of the load path is more than the limit of %lld steps (docs/scenes.md, \"Limits\")", path.steps_per_segment, (long long)segments, (long long)limits::kMaxLoadSteps);
  }
  PetscCall(BoltnetAssemblySetFromOptions(a));
  if (!o.helpOnly && (o.every > 0 || !o.restart.empty())) PetscCall(CheckpointIdentify(a, scene.name, &ident)); // before the set-up takes the meshes
  PetscCall(BoltnetAssemblySetUp(a));
  PetscCall(SceneCheckUnusedOptions(comm));
  if (o.helpOnly) PetscFunctionReturn(0);
  // With -options_left, an option nothing has used by now (except those PETSc reads only during or
  // after a solve) stops the run before anything is written.
  if (o.optionsLeft) {
    PetscCall(UnusedOptionsAsError(comm, "boltnet", PETSC_TRUE, exitcode));
    if (*exitcode) {
      PetscCall(PetscOptionsClearValue(nullptr, "-options_left")); // said above: PETSc's list would repeat it
      PetscFunctionReturn(0);
    }
  }

  // A restart loads and checks the checkpoint and the results it continues before it writes anything.
  const std::string ckpt = !o.ckfile.empty() ? o.ckfile : dir + "/checkpoint.h5";
  if (o.every > 0 && !o.ckfile.empty()) PetscCall(CheckpointCheckFile(comm, ckpt)); // the default's directory is -output_dir
  if (!o.restart.empty()) {
    PetscCall(CheckpointLoad(a, ident, o.restart.c_str(), &out));
    PetscCall(OutputResume(comm, dir, scene.name, o.fields, o.joints, a, &out));
  } else PetscCall(OutputOpen(comm, dir, scene.name, o.fields, o.joints, a, &out));
  out.identified = "{" + scene.identified + "}";
  a->on_step = [&](BoltnetAssembly as, const StepInfo &info) {
    PetscFunctionBeginUser;
    PetscCall(OutputStep(as, info, &out));
    if (o.every > 0 && info.step % o.every == 0) PetscCall(CheckpointWrite(as, ident, out, ckpt)); // after the step's results are on disk
    PetscFunctionReturn(0);
  };
  PetscCall(PetscPrintf(comm, "boltnet: scene %s, %" PetscInt_FMT " parts in %zu patches (%zu seams), %zu joints, %" PetscInt_FMT " dof on %d rank(s) (dof imbalance max/mean %.2f)", scene.name.c_str(), a->layout.nparts, a->layout.patches.size(), a->layout.seams.size(), a->layout.joints.size(), a->net.ndof_model, a->size, (double)a->net.dof_imbalance));
  if (a->opt.condense) PetscCall(PetscPrintf(comm, "; condensed onto %" PetscInt_FMT " interface dof", a->net.ndof_global));
  PetscCall(PetscPrintf(comm, "\n"));
  if (!o.restart.empty()) PetscCall(PetscPrintf(comm, "boltnet: restart from %s at step %zu, load factor %g\n", o.restart.c_str(), a->steps.size(), (double)a->lambda));

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
  PetscFunctionReturn(0);
}

PetscErrorCode Run(int *exitcode, ErrorLog *log)
{
  MPI_Comm      comm = PETSC_COMM_WORLD;
  char          file[PETSC_MAX_PATH_LEN] = "", outdir[PETSC_MAX_PATH_LEN] = "";
  char          ckfile[PETSC_MAX_PATH_LEN] = "", restart[PETSC_MAX_PATH_LEN] = "";
  char          deckfile[PETSC_MAX_PATH_LEN] = "", fasteners[PETSC_MAX_PATH_LEN] = "";
  PetscBool     hasScene, hasDeck;
  PetscInt      subcase = 0;
  PetscReal     tie_penalty = nastran::ModelOptions{}.tie_penalty;
  DriverOptions o;
  Scene         scene;
  PetscFunctionBeginUser;
  PetscCall(BoltnetInitializePackage());
  PetscCall(PetscOptionsHasHelp(nullptr, &o.helpOnly));
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-options_left", &o.optionsLeft, nullptr));
  PetscOptionsBegin(comm, nullptr, "boltnet driver", "boltnet");
  PetscCall(PetscOptionsString("-scene", "Scene file (PETSc YAML options), or the name of a scene that comes with boltnet (fig3c: share/boltnet/scenes/fig3c.yaml of the installation, docs/install.md)", "", file, file, sizeof(file), &hasScene));
  PetscCall(PetscOptionsString("-output_dir", "Directory for joints.csv or joints.h5, summary.json and the fields (default results/<scene name>; a Nastran deck's subcase N: <output_dir>/subcase-N)", "", outdir, outdir, sizeof(outdir), nullptr));
  PetscCall(FieldsOptionsFromCommandLine(PetscOptionsObject, &o.fields));
  PetscCall(JointOutputOptionsFromCommandLine(PetscOptionsObject, &o.joints));
  PetscCall(PetscOptionsInt("-checkpoint_every", "Write a checkpoint (the committed state, for -restart) after every N converged load steps (0: none)", "", o.every, &o.every, nullptr));
  PetscCall(PetscOptionsString("-checkpoint_file", "The checkpoint file (default <output_dir>/checkpoint.h5), replaced whole at every checkpoint", "", ckfile, ckfile, sizeof(ckfile), nullptr));
  PetscCall(PetscOptionsString("-restart", "Go on from this checkpoint: same scene and options (those that change results), results continued in -output_dir", "", restart, restart, sizeof(restart), nullptr));
  PetscOptionsEnd();
  o.ckfile  = ckfile;
  o.restart = restart;
  PetscCheck(o.every >= 0, comm, PETSC_ERR_USER_INPUT, "-checkpoint_every %" PetscInt_FMT " must be >= 0 (0: no checkpoint)", o.every);
  if (hasScene) {
    std::string found;
    PetscCall(FindScene(comm, file, &found));
    PetscCall(SceneInsertOptionsFile(comm, found.c_str(), &scene));
  }
  // A Nastran deck (docs/nastran.md, "From a deck to a model"): on the command line or in the
  // scene's nastran: section.
  PetscOptionsBegin(comm, nullptr, "Nastran deck as the model", "boltnet");
  PetscCall(PetscOptionsString("-nastran_deck", "Nastran bulk data deck to run instead of the scene's tables: shell properties become parts, CBUSH/CFAST joints, SPC fixed dof, FORCE/MOMENT/PLOAD4 loads (docs/nastran.md)", "", deckfile, deckfile, sizeof(deckfile), &hasDeck));
  PetscCall(PetscOptionsInt("-nastran_subcase", "Subcase of the deck to run (0: every subcase, each into the folder subcase-N of the output directory)", "", subcase, &subcase, nullptr));
  PetscCall(PetscOptionsString("-nastran_fasteners", "CSV fastener table turning chosen CBUSH/CFAST into joint types: type and first[,last] (element ids) or pid (PBUSH/PFAST id); the others keep their PBUSH/PFAST spring", "", fasteners, fasteners, sizeof(fasteners), nullptr));
  PetscCall(PetscOptionsReal("-nastran_tie_penalty", "Stiffness of the ties that stand for a grid shared by two shell properties and for RBE2: kn = kt = this x the largest membrane stiffness A11 of the deck's shells, kr = this x the largest D11", "", tie_penalty, &tie_penalty, nullptr));
  PetscOptionsEnd();
  PetscCheck(tie_penalty > 0, comm, PETSC_ERR_USER_INPUT, "-nastran_tie_penalty %g must be > 0", (double)tie_penalty);
  PetscCall(SceneCheckOptionValues(comm));
  if (!hasScene && !hasDeck && o.helpOnly) { // list the options that do not depend on a scene
    LoadPath        path;
    BoltnetAssembly a;
    PetscCall(LoadPathFromOptions(comm, nullptr, &path));
    PetscCall(BoltnetAssemblyCreate(comm, &a));
    a->opt.progress = PETSC_TRUE; // as in RunOne
    PetscCall(BoltnetAssemblySetFromOptions(a));
    PetscCall(BoltnetAssemblyDestroy(&a));
    PetscFunctionReturn(0);
  }
  PetscCheck(hasScene || hasDeck, comm, PETSC_ERR_USER_INPUT, "No scene: give -scene <file.yaml> (e.g. -scene share/scenes/fig3c.yaml) or -nastran_deck <file.bdf>; -help lists the options");
  if (!hasDeck) {
    const std::string dir = outdir[0] ? std::string(outdir) : "results/" + scene.name;
    PetscCall(RunOne(Source{}, scene, o, dir, exitcode, log));
  } else {
    PetscCheck(o.every == 0 && !restart[0], comm, PETSC_ERR_USER_INPUT, "-checkpoint_every and -restart are not available with -nastran_deck (a deck's subcases are separate runs)");
    nastran::Deck         deck;
    std::vector<PetscInt> ids;
    char                  name[PETSC_MAX_PATH_LEN] = "";
    const std::string     deckpath = scene.from_file.count("nastran_deck") && deckfile[0] != '/' && !scene.dir.empty() ? scene.dir + "/" + deckfile : std::string(deckfile);
    const std::string     fastpath = scene.from_file.count("nastran_fasteners") && fasteners[0] && fasteners[0] != '/' && !scene.dir.empty() ? scene.dir + "/" + fasteners : std::string(fasteners);
    PetscCall(NastranReadDeck(comm, deckpath.c_str(), nastran::ReadOptions{}, &deck));
    PetscCall(SceneNastranSubcases(comm, deck, subcase, &ids));
    { // the scene's name, or the deck's file name without its extension
      const size_t      slash = deckpath.find_last_of('/');
      const std::string base  = slash == std::string::npos ? deckpath : deckpath.substr(slash + 1);
      PetscCall(PetscStrncpy(name, hasScene ? scene.name.c_str() : base.substr(0, base.rfind('.')).c_str(), sizeof(name)));
    }
    PetscCall(PetscOptionsGetString(nullptr, nullptr, "-scene_name", name, sizeof(name), nullptr));
    scene.name = name;
    // A CBUSH joins two grids: the joint acts on the nearest node of each part unless the scene or
    // the command line chooses a footprint coupling (docs/coupling.md).
    PetscBool coupling;
    PetscCall(PetscOptionsHasName(nullptr, nullptr, "-coupling_type", &coupling));
    if (!coupling) PetscCall(PetscOptionsSetValue(nullptr, "-coupling_type", "node"));
    const std::string dir = outdir[0] ? std::string(outdir) : "results/" + scene.name;
    for (PetscInt id : ids) {
      Source src{&deck, id, {}, fastpath};
      src.options.tie_penalty = tie_penalty;
      PetscCall(RunOne(src, scene, o, dir + "/subcase-" + std::to_string(id), exitcode, log));
      if (*exitcode || o.helpOnly) break;
    }
  }
  if (o.optionsLeft && !o.helpOnly && *exitcode == 0) PetscCall(UnusedOptionsAsError(comm, "boltnet", PETSC_FALSE, exitcode)); // an error, not a warning
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv)
{
  return DriverMain("boltnet", &argc, &argv, help, Run);
}
