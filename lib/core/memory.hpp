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

// What this process's node can still give to new allocations, in MB: /proc/meminfo's MemAvailable
// (the kernel's estimate of what can be allocated without swapping), within the limit of the
// process's cgroup when it has one (cgroup v2's memory.max less memory.current, as a batch system's
// job allocation sets). 0 where neither can be read. Not collective.
double AvailableMemory();

} // namespace boltnet
