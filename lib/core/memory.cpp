// Resident memory per rank (memory.hpp).
#include "core/memory.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

namespace boltnet {

PetscErrorCode ResidentMemory(MPI_Comm comm, bool peak, RankRange *mb)
{
  double here = 0;
  PetscFunctionBeginUser;
  if (peak) {
    struct rusage u;
    PetscCheck(getrusage(RUSAGE_SELF, &u) == 0, PETSC_COMM_SELF, PETSC_ERR_SYS, "getrusage failed");
    here = (double)u.ru_maxrss * 1024.0 / 1e6; // Linux counts ru_maxrss in KiB
  } else {
    PetscLogDouble bytes;
    PetscCall(PetscMemoryGetCurrentUsage(&bytes));
    here = bytes / 1e6;
  }
  double lo = -here, hi = here, in[2] = {lo, hi}, out[2];
  PetscCallMPI(MPI_Allreduce(in, out, 2, MPI_DOUBLE, MPI_MAX, comm));
  *mb = {-out[0], out[1]};
  PetscFunctionReturn(0);
}

// A cgroup v2 control file's number, in bytes; negative for "max", a missing file or anything else.
static double CgroupBytes(const std::string &dir, const char *file)
{
  std::ifstream in(dir + "/" + file);
  std::string   word;
  if (!(in >> word) || word.find_first_not_of("0123456789") != std::string::npos) return -1;
  return std::stod(word);
}

double AvailableMemory()
{
  double        mb = 0;
  std::ifstream meminfo("/proc/meminfo");
  std::string   line;
  while (std::getline(meminfo, line)) {
    std::istringstream fields(line);
    std::string        key;
    double             kib;
    if (fields >> key >> kib && key == "MemAvailable:") {
      mb = kib * 1024.0 / 1e6;
      break;
    }
  }
  // The cgroup: /proc/self/cgroup's "0::<path>" line names it under /sys/fs/cgroup; inside a
  // container whose cgroup namespace hides the path, the root directory is the process's own.
  std::ifstream self("/proc/self/cgroup");
  std::string   dirs[2] = {"/sys/fs/cgroup", ""};
  while (std::getline(self, line))
    if (line.rfind("0::", 0) == 0) dirs[1] = "/sys/fs/cgroup" + line.substr(3);
  for (const std::string &dir : dirs) {
    if (dir.empty()) continue;
    const double max = CgroupBytes(dir, "memory.max"), used = CgroupBytes(dir, "memory.current");
    if (max < 0 || used < 0) continue;
    const double left = std::max(0.0, max - used) / 1e6;
    mb                = mb > 0 ? std::min(mb, left) : left;
  }
  return mb;
}

} // namespace boltnet
