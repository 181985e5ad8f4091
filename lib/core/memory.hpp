// Resident memory per rank, as the operating system counts it: what summary.json reports after each
// phase of the set-up and at its peak, so that a run says where its memory went on every rank
// (docs/performance.md, "Memory per rank").
#pragma once
#include <petscsys.h>

#include <array>
#include <string>

namespace boltnet {

// The smallest and the largest over the ranks of comm, in MB (1e6 bytes).
using RankRange = std::array<double, 2>;

struct MemoryMark {
  std::string phase;
  RankRange   mb;
};

// The resident set now (PetscMemoryGetCurrentUsage) or the largest it has been since the process
// started (getrusage's ru_maxrss: the kernel's high-water mark, which no sampling misses), over the
// ranks of comm. Collective.
PetscErrorCode ResidentMemory(MPI_Comm comm, bool peak, RankRange *mb);

} // namespace boltnet
