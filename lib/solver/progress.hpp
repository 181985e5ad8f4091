// Progress of a long run: one line per converged load step (-load_progress; docs/scenes.md,
// "Progress"), printed by the stepper (solver/stepper.cpp) after the step's results are out. Pure
// functions: test/test_progress.cpp checks them against closed forms.
#pragma once
#include <petscsys.h>

#include <string>
#include <vector>

namespace boltnet {

// How many nominal steps of the load path (targets = LoadPathTargets(start, ...)) the load factor
// lambda stands for, while targets[next] is the one being approached: the `next` steps before it
// are done, plus the fraction of the way from the one before it (start for the first) to it. A
// cut-back step that reached half-way to target 3 (index 2) stands for 2.5 steps.
PetscReal PathFraction(PetscReal start, const std::vector<PetscReal> &targets, size_t next, PetscReal lambda);

// One progress line, all counts global (summed over ranks).
struct Progress {
  PetscInt  step = 0, nsteps = 0; // the nominal step approached or just reached (1-based), of nsteps
  PetscReal part = 1;             // the fraction of it reached (1: reached)
  PetscInt  cuts = 0;             // halvings on the way to it; 0: the step was taken whole
  PetscReal load = 0;             // load factor
  PetscInt  newton = 0;           // Newton iterations of the converged solve
  PetscInt  stick = 0, slide = 0, bear = 0; // joints in state stick, in state slide, bearing
  PetscReal elapsed = 0, left = 0; // seconds since the load path started, estimate of those left
};

// The line, without its newline:
//   step 3/10  load 0.3  newton 4  stick 1180 slide 20 bear 5  elapsed 12.3 s  left ~28.7 s
// and for a step on the way to a nominal step that needed cut-backs (here half of step 3, after one
// halving):
//   step 3/10 at 0.50 (1 cut-back)  load 0.25  newton 6  ...
std::string FormatProgress(const Progress &p);

// The time left, as an estimate: the time per nominal step of this run so far (elapsed over the
// nominal steps done since it started, from done0) times the steps left (of n).
PetscReal EstimateTimeLeft(PetscReal elapsed, PetscReal done0, PetscReal done, PetscReal n);

} // namespace boltnet
