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
Several load cases of one model run on one set-up of it (the mesh, the network and the condensed\n\
patches built once), each from the unloaded state into its own folder <output_dir>/<case>:\n\
  build/bin/boltnet -scene test/scenes/strip-cases.yaml -load_cases tension,bending\n\
(-load_cases and -load_case_<case>_*: docs/scenes.md, \"Load cases\").\n\
\n\
A Nastran deck runs instead of a scene's tables (docs/nastran.md): every subcase into its own folder,\n\
on one set-up for the subcases of one SPC set,\n\
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
#include "io/cases.hpp"
#include "solver/loadpath.hpp"

#include <petsctime.h>

#include <algorithm>
#include <functional>
#include <new>
#include <sstream>
#include <string>

using namespace boltnet;

namespace {

// The assembly (and, in SolveCase, the open result files) are released on every return, an
// error's included, so that a run stopped by bad input leaks nothing (scripts/sanitize checks it).
// Their own errors then are not the one reported.
struct Release {
  BoltnetAssembly a = nullptr;
  ~Release()
  {
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    BoltnetAssemblyDestroy(&a);
    PetscPopErrorHandler();
  }
};

struct DriverOptions {
  std::string dir, ckfile, restart;
  PetscBool     helpOnly = PETSC_FALSE, optionsLeft = PETSC_FALSE;
  FieldsOptions fields;
  JointOutputOptions joints;
  PetscInt      every = 0;
  PetscBool     hasCases = PETSC_FALSE;  // -load_cases given
  std::vector<std::string> cases;        // its names
};

// What a set-up solves: the scene's tables (cases: one made of every condition of the table, or
// those of -load_cases), or a group of subcases of a Nastran deck that hold the same dof.
struct Source {
  nastran::Deck        *deck = nullptr; // rank 0's (the others' is empty)
  bool                  last = false;   // the deck's last set-up: the deck is released once described
  std::vector<PetscInt> subcases;
  nastran::ModelOptions options;
  std::string           fasteners;
};

// Describes the model into a and makes its cases; for a scene with load cases, those of the set-up
// `group` (by order of first appearance of their set-up key) and the number of groups (a deck's
// groups are its caller's: *ngroups is left as it is).
PetscErrorCode DescribeCases(const Source &src, Scene &scene, const DriverOptions &o, const LoadPath &base, size_t group, BoltnetAssembly a, std::vector<LoadCase> *cases, size_t *ngroups)
{
  MPI_Comm comm = PETSC_COMM_WORLD;
  PetscFunctionBeginUser;
  cases->clear();
  if (src.deck) { // a deck's groups of subcases are known before (SceneNastranSetUps)
    std::vector<std::vector<BCDesc>> conditions;
    PetscCall(SceneDescribeNastran(comm, &scene, *src.deck, src.subcases, src.options, src.fasteners, a, &conditions));
    if (src.last) *src.deck = nastran::Deck{}; // not needed past here: its memory goes to the solve
    for (size_t k = 0; k < src.subcases.size(); ++k) {
      LoadCase c;
      c.name    = "subcase-" + std::to_string(src.subcases[k]);
      c.bcs     = std::move(conditions[k]);
      c.path    = base;
      c.setup   = SetUpKey(c.bcs);
      cases->push_back(std::move(c));
    }
  } else {
    PetscCall(SceneDescribeAssembly(comm, &scene, a));
    *ngroups = 1;
    if (!o.hasCases) {
      LoadCase c;
      c.bcs  = a->model.bcs;
      c.path = base;
      cases->push_back(std::move(c));
    } else {
      std::vector<LoadCase> all;
      std::vector<std::string> keys;
      PetscCall(SceneLoadCases(comm, scene, o.cases, a->model.bcs, base, &all));
      for (const LoadCase &c : all)
        if (std::find(keys.begin(), keys.end(), c.setup) == keys.end()) keys.push_back(c.setup);
      *ngroups = keys.size();
      for (LoadCase &c : all)
        if (c.setup == keys[group]) cases->push_back(std::move(c));
    }
  }
  for (LoadCase &c : *cases) {
    const std::int64_t segments = std::max<std::int64_t>(1, (std::int64_t)c.path.breakpoints.size());
    PetscCheck(segments * c.path.steps_per_segment <= limits::kMaxLoadSteps, comm, PETSC_ERR_USER_INPUT, "%s%s%s-load_steps %" PetscInt_FMT " over %lld segment(s) of the load path is more than the limit of %lld steps (docs/scenes.md, \"Limits\")", c.name.empty() ? "" : "load case ", c.name.c_str(), c.name.empty() ? "" : ": ", c.path.steps_per_segment, (long long)segments, (long long)limits::kMaxLoadSteps);
  }
  // The set-up sees every condition of its cases (its checks: footprints, forces on supports), and
  // only those: a scene's other loads may hold other dof.
  if (!(*cases)[0].name.empty()) a->model.bcs = SetUpConditions(*cases);
  PetscFunctionReturn(0);
}

// Solves one case (the k-th of n on its set-up) on the assembly that is set up, and writes its
// results under dir; describe, when given, says what was set up once the result files are open.
// With a reason to skip it, the case is not solved: its summary.json says why, as a failure.
PetscErrorCode SolveCase(BoltnetAssembly a, const LoadCase &c, Scene &scene, const DriverOptions &o, const CheckpointIdentity &ident, const std::string &dir, const std::function<PetscErrorCode()> &describe, size_t k, size_t n, const std::string &skip, int *exitcode, ErrorLog *log, std::string *line)
{
  MPI_Comm comm = PETSC_COMM_WORLD;
  Output   out;
  struct Discard { // the result files, on every return (an error's included)
    Output *o;
    ~Discard()
    {
      PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
      OutputDiscard(o);
      PetscPopErrorHandler();
    }
  } discard{&out};
  PetscLogDouble t0, t1;
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&t0));
  // A restart loads and checks the checkpoint and the results it continues before it writes anything.
  const std::string ckpt = !o.ckfile.empty() ? o.ckfile : dir + "/checkpoint.h5";
  if (o.every > 0 && !o.ckfile.empty()) PetscCall(CheckpointCheckFile(comm, ckpt)); // the default's directory is -output_dir
  if (!o.restart.empty()) {
    PetscCall(CheckpointLoad(a, ident, o.restart.c_str(), &out));
    PetscCall(OutputResume(comm, dir, scene.name, o.fields, o.joints, a, &out));
  } else PetscCall(OutputOpen(comm, dir, scene.name, o.fields, o.joints, a, &out));
  out.identified = "{" + scene.identified + "}";
  out.load_case  = c.name;
  out.continues  = c.continues;
  a->on_step = [&](BoltnetAssembly as, const StepInfo &info) {
    PetscFunctionBeginUser;
    PetscCall(OutputStep(as, info, &out));
    if (o.every > 0 && info.step % o.every == 0) PetscCall(CheckpointWrite(as, ident, out, ckpt)); // after the step's results are on disk
    PetscFunctionReturn(0);
  };
  if (describe) PetscCall(describe());
  if (!c.name.empty()) PetscCall(PetscPrintf(comm, "boltnet: load case %s (%zu of %zu on this set-up)%s%s%s\n", c.name.c_str(), k, n, c.continues.empty() ? "" : ", from the end of ", c.continues.c_str(), c.continues.empty() ? "" : " with its loads held"));
  if (!skip.empty()) {
    PetscCall(PetscPrintf(comm, "boltnet: case %s %s\n", c.name.c_str(), skip.c_str()));
    PetscCall(OutputSummary(a, &out, "failed", "load case " + c.name + " " + skip));
    PetscCall(OutputClose(comm, &out));
    *exitcode = 3;
    *line     = "boltnet: case " + c.name + ": " + skip;
    PetscFunctionReturn(0);
  }
  if (!o.restart.empty()) PetscCall(PetscPrintf(comm, "boltnet: restart from %s at step %zu, load factor %g\n", o.restart.c_str(), a->steps.size(), (double)a->lambda));

  // A step that fails beyond the cut-back bound is reported, recorded in summary.json, and the
  // program exits 3. Any other error (a file that cannot be written, a library failure) goes up
  // with its own message and leaves no summary.json: OutputOpen removed the last run's.
  log->messages.clear();
  PetscErrorCode ierr;
  try {
    ierr = BoltnetAssemblySolveLoadPath(a, (PetscInt)c.path.breakpoints.size(), c.path.breakpoints.data(), c.path.steps_per_segment);
  } catch (const std::bad_alloc &) {
    SETERRQ(comm, PETSC_ERR_MEM, "Out of memory during the load path");
  }
  a->on_step = nullptr;
  if (ierr && a->failure.empty()) {
    const std::string why = ErrorText(*log);
    SETERRQ(comm, ierr, "%s%s%sThe load path stopped at load factor %g: %s", c.name.empty() ? "" : "load case ", c.name.c_str(), c.name.empty() ? "" : ": ", (double)a->lambda, why.empty() ? "PETSc error" : why.c_str());
  }
  log->messages.clear();
  std::ostringstream l;
  l << "boltnet: " << (c.name.empty() ? std::string() : "case " + c.name + ": ");
  if (ierr) {
    PetscCall(PetscPrintf(comm, "boltnet: FAILED: %s\n", a->failure.c_str()));
    PetscCall(OutputSummary(a, &out, "failed", a->failure));
    *exitcode = 3;
    l << "FAILED at load factor " << a->lambda << " after " << a->steps.size() << " steps";
  } else {
    PetscCall(OutputSummary(a, &out, "converged", ""));
    PetscCall(PetscPrintf(comm, "boltnet: %s%s%s%zu steps converged (%" PetscInt_FMT " cut-backs), load factor %g; results in %s/\n", c.name.empty() ? "" : "case ", c.name.c_str(), c.name.empty() ? "" : ": ", a->steps.size(), a->total_cutbacks, (double)a->lambda, dir.c_str()));
    if (out.most_joint >= 0)
      PetscCall(PetscPrintf(comm, "boltnet: most loaded joint %" PetscInt_FMT ": in-plane force %g at step %" PetscInt_FMT " (load %g)\n", out.most_joint, (double)out.most_force, out.most_step, (double)out.most_load));
    l << "converged, " << a->steps.size() << " steps (" << a->total_cutbacks << " cut-backs), load factor " << a->lambda;
    if (out.most_joint >= 0) l << ", most loaded joint " << out.most_joint << " (in-plane force " << out.most_force << " at load " << out.most_load << ")";
  }
  if (a->opt.progress) PetscCall(PetscPrintf(comm, "boltnet: peak resident memory per rank %.0f MB (largest), %.0f MB (smallest)\n", out.peak_mb[1], out.peak_mb[0]));
  PetscCall(OutputClose(comm, &out));
  PetscCall(PetscTime(&t1));
  l.precision(3);
  l << "; " << std::fixed << (t1 - t0) << " s; " << dir << "/";
  *line = l.str();
  PetscFunctionReturn(0);
}

// Describes and sets up the model once, then solves each of its cases from the unloaded state
// (docs/scenes.md, "Load cases"). group: which set-up of a scene's load cases; *ngroups: how many
// there are.
PetscErrorCode RunSetUp(const Source &src, Scene &scene, const DriverOptions &o, const std::string &dir, size_t group, size_t *ngroups, int *exitcode, ErrorLog *log, std::vector<std::string> *lines)
{
  MPI_Comm              comm = PETSC_COMM_WORLD;
  CheckpointIdentity    ident;
  LoadPath              base;
  Release               held;
  BoltnetAssembly      &a = held.a;
  std::vector<LoadCase> cases;
  PetscLogDouble        t0, t1;
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&t0));
  // Everything is read and checked before anything is written.
  PetscCall(BoltnetAssemblyCreate(comm, &a));
  a->opt.progress = PETSC_TRUE; // a run of the driver reports each converged step unless -load_progress false
  PetscCall(LoadPathFromOptions(comm, nullptr, &base));
  PetscCall(DescribeCases(src, scene, o, base, group, a, &cases, ngroups));
  PetscCall(BoltnetAssemblySetFromOptions(a));
  a->opt.keep_layout = o.fields.gather; // the gathering writer reads every patch's mesh on rank 0
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
  PetscCall(PetscTime(&t1));
  // What was set up, said once its first case's result files are open (a run that cannot write them
  // stops with one line).
  auto describe = [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(PetscPrintf(comm, "boltnet: scene %s, %" PetscInt_FMT " parts in %zu patches (%zu seams), %" PetscInt_FMT " joints, %" PetscInt_FMT " dof on %d rank(s) (dof imbalance max/mean %.2f)", scene.name.c_str(), a->layout.nparts, a->layout.patches.size(), a->layout.seams.size(), a->layout.njoints, a->net.ndof_model, a->size, (double)a->net.dof_imbalance));
    if (a->net.ncondensed) PetscCall(PetscPrintf(comm, "; %" PetscInt_FMT " of the patches condensed, onto %" PetscInt_FMT " interface dof", a->net.ncondensed, a->net.ndof_global));
    PetscCall(PetscPrintf(comm, "\n"));
    if (cases.size() > 1 || !cases[0].name.empty()) {
      std::string names;
      for (const LoadCase &c : cases) names += (names.empty() ? "" : ", ") + c.name;
      PetscCall(PetscPrintf(comm, "boltnet: set-up %zu of %zu (%.3f s) for %zu load case(s): %s\n", group + 1, *ngroups, (double)(t1 - t0), cases.size(), names.c_str()));
    }
    PetscFunctionReturn(0);
  };
  // Each case from the unloaded state, with its own loads on the one set-up; a case that continues
  // the one before from where it ended, that case's loads held (docs/scenes.md, "Held loads").
  bool before_converged = true;
  for (size_t k = 0; k < cases.size(); ++k) {
    const LoadCase &c = cases[k];
    std::string     skip; // why the case is not run
    if (c.continues.empty()) {
      if (k > 0) PetscCall(AssemblyReset(a));
      if (k > 0 || !SameConditions(c.bcs, a->model.bcs)) PetscCall(AssemblySetLoads(a, c.bcs));
    } else if (before_converged) {
      PetscCall(AssemblyHoldLoads(a));
      PetscCall(AssemblySetLoads(a, c.path_bcs));
    } else {
      PetscCall(AssemblyReset(a)); // its summary records no step, not those of the case before
      skip = "not run: the case it continues, " + c.continues + ", did not converge";
    }
    std::string line; // for the run's closing summary
    PetscCall(SolveCase(a, c, scene, o, ident, c.name.empty() ? dir : dir + "/" + c.name, k == 0 ? describe : std::function<PetscErrorCode()>(), k + 1, cases.size(), skip, exitcode, log, &line));
    before_converged = skip.empty() && a->failure.empty();
    lines->push_back(line);
  }
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
  PetscBool     bush_offsets = nastran::ModelOptions{}.bush_offsets ? PETSC_TRUE : PETSC_FALSE;
  DriverOptions o;
  Scene         scene;
  PetscFunctionBeginUser;
  PetscCall(BoltnetInitializePackage());
  PetscCall(PetscOptionsHasHelp(nullptr, &o.helpOnly));
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-options_left", &o.optionsLeft, nullptr));
  PetscOptionsBegin(comm, nullptr, "boltnet driver", "boltnet");
  PetscCall(PetscOptionsString("-scene", "Scene file (PETSc YAML options), or the name of a scene that comes with boltnet (fig3c: share/boltnet/scenes/fig3c.yaml of the installation, docs/install.md)", "", file, file, sizeof(file), &hasScene));
  PetscCall(PetscOptionsString("-output_dir", "Directory for joints.csv or joints.h5, summary.json and the fields (default results/<scene name>; a load case: its folder <case> in it; a Nastran deck's subcase N: <output_dir>/subcase-N)", "", outdir, outdir, sizeof(outdir), nullptr));
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
  // The output's options after the scene's, so that a scene's output: section sets them (the
  // junction's generator gives its bypass strip width there) and the command line still wins.
  PetscOptionsBegin(comm, nullptr, "boltnet output", "boltnet");
  PetscCall(FieldsOptionsFromCommandLine(PetscOptionsObject, &o.fields));
  PetscCall(JointOutputOptionsFromCommandLine(PetscOptionsObject, &o.joints));
  PetscOptionsEnd();
  // A Nastran deck (docs/nastran.md, "From a deck to a model"): on the command line or in the
  // scene's nastran: section.
  PetscOptionsBegin(comm, nullptr, "Nastran deck as the model", "boltnet");
  PetscCall(PetscOptionsString("-nastran_deck", "Nastran bulk data deck to run instead of the scene's tables: shell properties become parts, CBUSH/CFAST joints, SPC fixed dof, FORCE/MOMENT/PLOAD4 loads (docs/nastran.md)", "", deckfile, deckfile, sizeof(deckfile), &hasDeck));
  PetscCall(PetscOptionsInt("-nastran_subcase", "Subcase of the deck to run (0: every subcase, each into the folder subcase-N of the output directory)", "", subcase, &subcase, nullptr));
  PetscCall(PetscOptionsString("-nastran_fasteners", "CSV fastener table turning chosen CBUSH/CFAST into joint types: type and first[,last] (element ids) or pid (PBUSH/PFAST id); the others keep their PBUSH/PFAST spring", "", fasteners, fasteners, sizeof(fasteners), nullptr));
  PetscCall(PetscOptionsReal("-nastran_tie_penalty", "Stiffness of the ties that stand for a grid shared by two shell properties and for RBE2: kn = kt = this x the largest membrane stiffness A11 of the deck's shells, kr = this x the largest D11", "", tie_penalty, &tie_penalty, nullptr));
  PetscCall(PetscOptionsBool("-nastran_bush_offsets", "Place a CBUSH's spring at S of GA-GB, each grid carrying it by a rigid lever, as Nastran does (false: at the midpoint, each part loaded at its grid without lever)", "", bush_offsets, &bush_offsets, nullptr));
  PetscOptionsEnd();
  PetscCheck(tie_penalty > 0, comm, PETSC_ERR_USER_INPUT, "-nastran_tie_penalty %g must be > 0", (double)tie_penalty);
  // Load cases (docs/scenes.md, "Load cases"): several loadings of the scene's model on one set-up.
  {
    char     *names[kMaxLoadCases];
    PetscInt  n = kMaxLoadCases;
    PetscBool given = PETSC_FALSE;
    PetscOptionsBegin(comm, nullptr, "boltnet load cases", "boltnet");
    PetscCall(PetscOptionsStringArray("-load_cases", "Load cases of the scene, each into its folder <case> of -output_dir, from the unloaded state on one set-up of the model (comma separated; each case names its loads with -load_case_<case>_loads: docs/scenes.md)", "", names, &n, &given));
    PetscOptionsEnd();
    for (PetscInt i = 0; i < (given ? n : 0); ++i) {
      o.cases.push_back(names[i]);
      PetscCall(PetscFree(names[i]));
    }
    PetscCall(PetscOptionsHasName(nullptr, nullptr, "-load_cases", &o.hasCases)); // also with no value: an empty list
    PetscCall(LoadCaseNames(comm, o.hasCases, o.cases));
    std::vector<std::string> defined;
    PetscCall(DefinedLoadCases(&defined));
    PetscCheck(o.hasCases || defined.empty(), comm, PETSC_ERR_USER_INPUT, "The options define load case '%s' (-load_case_%s_loads) but -load_cases lists no case: give -load_cases (load: cases: in the scene) to run the cases, or leave their options out", defined.empty() ? "" : defined[0].c_str(), defined.empty() ? "" : defined[0].c_str());
  }
  PetscCall(SceneCheckOptionValues(comm));
  if (!hasScene && !hasDeck && o.helpOnly) { // list the options that do not depend on a scene
    LoadPath        path;
    BoltnetAssembly a;
    PetscCall(LoadPathFromOptions(comm, nullptr, &path));
    PetscCall(BoltnetAssemblyCreate(comm, &a));
    a->opt.progress = PETSC_TRUE; // as in RunSetUp
    PetscCall(BoltnetAssemblySetFromOptions(a));
    PetscCall(BoltnetAssemblyDestroy(&a));
    PetscFunctionReturn(0);
  }
  PetscCheck(hasScene || hasDeck, comm, PETSC_ERR_USER_INPUT, "No scene: give -scene <file.yaml> (e.g. -scene share/scenes/fig3c.yaml) or -nastran_deck <file.bdf>; -help lists the options");
  PetscCheck(!(o.hasCases && (o.every > 0 || restart[0])), comm, PETSC_ERR_USER_INPUT, "-checkpoint_every and -restart are not available with -load_cases (each case is a run of its own from the unloaded state)");
  std::vector<std::string> lines;
  size_t                setups = 0;
  if (!hasDeck) {
    const std::string dir = outdir[0] ? std::string(outdir) : "results/" + scene.name;
    size_t            ngroups = 1;
    for (size_t g = 0; g < ngroups; ++g, ++setups) {
      PetscCall(RunSetUp(Source{}, scene, o, dir, g, &ngroups, exitcode, log, &lines));
      if (o.helpOnly || (*exitcode != 0 && *exitcode != 3)) break;
    }
  } else {
    PetscCheck(!o.hasCases, comm, PETSC_ERR_USER_INPUT, "-load_cases is for a scene's tables: a Nastran deck's load cases are its subcases (-nastran_subcase chooses one)");
    PetscCheck(o.every == 0 && !restart[0], comm, PETSC_ERR_USER_INPUT, "-checkpoint_every and -restart are not available with -nastran_deck (a deck's subcases are separate runs)");
    nastran::Deck                      deck;
    std::vector<PetscInt>              ids;
    std::vector<std::vector<PetscInt>> groups;
    char                               name[PETSC_MAX_PATH_LEN] = "";
    const std::string deckpath = scene.from_file.count("nastran_deck") && deckfile[0] != '/' && !scene.dir.empty() ? scene.dir + "/" + deckfile : std::string(deckfile);
    const std::string fastpath = scene.from_file.count("nastran_fasteners") && fasteners[0] && fasteners[0] != '/' && !scene.dir.empty() ? scene.dir + "/" + fasteners : std::string(fasteners);
    PetscCall(NastranReadDeckOnRank0(comm, deckpath.c_str(), nastran::ReadOptions{}, &deck)); // the deck and its model are rank 0's (io/nastran.cpp)
    PetscCall(SceneNastranSubcases(comm, deck, subcase, &ids));
    PetscCall(SceneNastranSetUps(comm, deck, ids, &groups));
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
    // One set-up per SPC set: the subcases that hold the same dof share it (docs/nastran.md).
    for (size_t g = 0; g < groups.size(); ++g) {
      Source src{&deck, g + 1 == groups.size(), groups[g], {}, fastpath};
      src.options.tie_penalty = tie_penalty;
      src.options.bush_offsets = bush_offsets == PETSC_TRUE;
      size_t ngroups = groups.size();
      PetscCall(RunSetUp(src, scene, o, dir, g, &ngroups, exitcode, log, &lines));
      ++setups;
      if (o.helpOnly || (*exitcode != 0 && *exitcode != 3)) break;
    }
  }
  // The closing summary, one line per case, when there were several.
  if (lines.size() > 1) {
    PetscCall(PetscPrintf(comm, "boltnet: %zu load cases on %zu set-up(s):\n", lines.size(), setups));
    for (const std::string &l : lines) PetscCall(PetscPrintf(comm, "%s\n", l.c_str()));
  }
  if (o.optionsLeft && !o.helpOnly && *exitcode == 0) PetscCall(UnusedOptionsAsError(comm, "boltnet", PETSC_FALSE, exitcode)); // an error, not a warning
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv)
{
  return DriverMain("boltnet", &argc, &argv, help, Run);
}
