// Gather plain-data records from every rank to rank 0 (raw bytes: T must be trivially copyable).
#pragma once

#include <petscsys.h>

#include <type_traits>
#include <vector>

namespace boltnet {

template <typename T>
PetscErrorCode GatherToZero(MPI_Comm comm, const std::vector<T> &mine, std::vector<T> &all)
{
  static_assert(std::is_trivially_copyable<T>::value, "records are gathered as raw bytes");
  PetscMPIInt rank, size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  const PetscMPIInt        nbytes = (PetscMPIInt)(mine.size() * sizeof(T));
  std::vector<PetscMPIInt> counts(size), displs(size);
  PetscCallMPI(MPI_Gather(&nbytes, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm));
  PetscMPIInt total = 0;
  if (rank == 0)
    for (PetscMPIInt i = 0; i < size; ++i) {
      displs[i] = total;
      total += counts[i];
    }
  all.assign(rank == 0 ? total / sizeof(T) : 0, T{});
  PetscCallMPI(MPI_Gatherv(mine.data(), nbytes, MPI_BYTE, all.data(), counts.data(), displs.data(), MPI_BYTE, 0, comm));
  PetscFunctionReturn(0);
}

} // namespace boltnet
