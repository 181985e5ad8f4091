// Resident memory per rank (memory.hpp).
#include "core/memory.hpp"

#include <sys/resource.h>

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

} // namespace boltnet
