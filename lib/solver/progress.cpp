// Progress of a long run: one line per converged load step (docs/scenes.md, "Progress").
#include "solver/progress.hpp"

#include <cmath>
#include <cstdio>

namespace boltnet {

PetscReal PathFraction(PetscReal start, const std::vector<PetscReal> &targets, size_t next, PetscReal lambda)
{
  if (next >= targets.size()) return (PetscReal)targets.size();
  const PetscReal from = next == 0 ? start : targets[next - 1];
  const PetscReal part = (lambda - from) / (targets[next] - from); // targets differ from the one before
  return (PetscReal)next + PetscMin(PetscMax(part, 0.0), 1.0);
}

PetscReal EstimateTimeLeft(PetscReal elapsed, PetscReal done0, PetscReal done, PetscReal n)
{
  if (!(done > done0)) return 0;
  return PetscMax(elapsed / (done - done0) * (n - done), 0.0);
}

std::string FormatProgress(const Progress &p)
{
  char step[96], rest[256];
  // The part reached, rounded down: "at 1.00" only on the sub-step that reaches the nominal step
  // (after 8 halvings a sub-step can stop at 0.996). The epsilon keeps 0.5 computed as 0.4999... at 0.50.
  const double part = p.part >= 1 ? 1.0 : std::floor((double)p.part * 100 + 1e-6) / 100;
  if (p.cuts > 0) std::snprintf(step, sizeof(step), "step %lld/%lld at %.2f (%lld cut-back%s)", (long long)p.step, (long long)p.nsteps, part, (long long)p.cuts, p.cuts == 1 ? "" : "s");
  else std::snprintf(step, sizeof(step), "step %lld/%lld", (long long)p.step, (long long)p.nsteps);
  std::snprintf(rest, sizeof(rest), "  load %g  newton %lld  stick %lld slide %lld bear %lld  elapsed %.1f s  left ~%.1f s", (double)p.load, (long long)p.newton, (long long)p.stick, (long long)p.slide, (long long)p.bear, (double)p.elapsed, (double)p.left);
  return std::string(step) + rest;
}

} // namespace boltnet
