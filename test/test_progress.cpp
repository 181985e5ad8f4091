// The progress line's arithmetic (lib/solver/progress.hpp) against closed forms.
// Requirement: the progress line says which nominal step of the whole load path (every segment) a
// converged step stands for, cut-back sub-steps included, and estimates the time left as elapsed /
// nominal steps done * nominal steps left (docs/scenes.md, "Progress").
#include "solver/loadpath.hpp"
#include "solver/progress.hpp"

#include <gtest/gtest.h>

using namespace boltnet;

// fig3c's path in 3 steps per segment: 0 -> 6000 -> -6000 -> 0, targets 2000 4000 6000 2000 -2000
// -6000 -4000 -2000 0 (9 nominal steps; segments of different lengths, steps of 2000 and 4000).
static std::vector<PetscReal> Fig3cTargets() { return LoadPathTargets(0, {6000, -6000, 0}, 3); }

TEST(Progress, PathFractionCountsEverySegment)
{
  const auto t = Fig3cTargets();
  ASSERT_EQ(t.size(), 9u);
  EXPECT_DOUBLE_EQ(PathFraction(0, t, 0, 0), 0);        // at the start
  EXPECT_DOUBLE_EQ(PathFraction(0, t, 1, 2000), 1);     // step 1 reached, approaching step 2
  EXPECT_DOUBLE_EQ(PathFraction(0, t, 1, 3000), 1.5);   // half of step 2 (2000 -> 4000)
  EXPECT_DOUBLE_EQ(PathFraction(0, t, 4, 2000), 4);     // step 4 reached (6000 -> 2000)
  EXPECT_DOUBLE_EQ(PathFraction(0, t, 4, 1000), 4.25);  // a quarter of step 5 (2000 -> -2000), unloading
  EXPECT_DOUBLE_EQ(PathFraction(0, t, 5, -3000), 5.25); // a quarter of step 6 (-2000 -> -6000)
  EXPECT_DOUBLE_EQ(PathFraction(0, t, 9, 0), 9);        // the end
}

TEST(Progress, PathFractionFromAnotherStart)
{
  // A path taken up at load factor 1 towards 3 in 4 steps: 1.5 2 2.5 3.
  const auto t = LoadPathTargets(1, {3}, 4);
  EXPECT_DOUBLE_EQ(PathFraction(1, t, 0, 1), 0);
  EXPECT_DOUBLE_EQ(PathFraction(1, t, 0, 1.25), 0.5);
  EXPECT_DOUBLE_EQ(PathFraction(1, t, 3, 2.75), 3.5);
}

TEST(Progress, EstimateTimeLeft)
{
  EXPECT_DOUBLE_EQ(EstimateTimeLeft(12, 0, 3, 10), 28);   // 4 s per nominal step, 7 left
  EXPECT_DOUBLE_EQ(EstimateTimeLeft(10, 0, 2.5, 10), 30); // a cut-back sub-step counts as its part
  EXPECT_DOUBLE_EQ(EstimateTimeLeft(10, 2, 4.5, 10), 22); // a restart at step 2: 4 s per step of its own
  EXPECT_DOUBLE_EQ(EstimateTimeLeft(10, 0, 10, 10), 0);   // done
  EXPECT_DOUBLE_EQ(EstimateTimeLeft(10, 3, 3, 10), 0);    // nothing done yet: no estimate
}

TEST(Progress, Line)
{
  Progress p;
  p.step = 3, p.nsteps = 10, p.load = 0.3, p.newton = 4, p.stick = 1180, p.slide = 20, p.bear = 5, p.elapsed = 12.34, p.left = 28.66;
  EXPECT_EQ(FormatProgress(p), "step 3/10  load 0.3  newton 4  stick 1180 slide 20 bear 5  elapsed 12.3 s  left ~28.7 s");
  p.part = 0.5, p.cuts = 1, p.load = 0.25;
  EXPECT_EQ(FormatProgress(p), "step 3/10 at 0.50 (1 cut-back)  load 0.25  newton 4  stick 1180 slide 20 bear 5  elapsed 12.3 s  left ~28.7 s");
  p.part = 0.875, p.cuts = 2; // rounded down: 1.00 only where the nominal step is reached
  EXPECT_EQ(FormatProgress(p).substr(0, 31), "step 3/10 at 0.87 (2 cut-backs)");
  p.part = 1 - 1.0 / 256, p.cuts = 8;
  EXPECT_EQ(FormatProgress(p).substr(0, 31), "step 3/10 at 0.99 (8 cut-backs)");
  p.part = 0.5 - 1e-15, p.cuts = 1;
  EXPECT_EQ(FormatProgress(p).substr(0, 30), "step 3/10 at 0.50 (1 cut-back)");
  p.part = 1, p.cuts = 2, p.load = 0.3;
  EXPECT_EQ(FormatProgress(p), "step 3/10 at 1.00 (2 cut-backs)  load 0.3  newton 4  stick 1180 slide 20 bear 5  elapsed 12.3 s  left ~28.7 s");
}
