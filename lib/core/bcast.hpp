// Rank 0's small descriptions given to every rank: a vector of plain records, or a string. What one
// rank reads (a fastener table, a Nastran deck: io/scene.cpp, io/nastran.cpp) reaches the others
// this way, as bytes, in one message each; a description larger than one MPI message can count
// (INT_MAX bytes) is refused on every rank rather than cut.
#pragma once
#include <petscsys.h>

#include <climits>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace boltnet {

// Broadcasts rank 0's *v (its size, then its bytes) into *v on every rank of comm. Collective.
template <class T>
PetscErrorCode BcastVector(MPI_Comm comm, std::vector<T> *v)
{
  static_assert(std::is_trivially_copyable<T>::value, "a broadcast record travels as bytes");
  PetscMPIInt  rank;
  std::int64_t n = (std::int64_t)v->size();
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Bcast(&n, 1, MPI_INT64_T, 0, comm));
  PetscCheck(n <= (std::int64_t)(INT_MAX / sizeof(T)), comm, PETSC_ERR_SUP, "A description of %lld records of %zu bytes is more than one message can carry to the ranks (%d bytes)", (long long)n, sizeof(T), INT_MAX);
  if (rank) v->resize((size_t)n);
  if (n) PetscCallMPI(MPI_Bcast(v->data(), (PetscMPIInt)(n * (std::int64_t)sizeof(T)), MPI_BYTE, 0, comm));
  PetscFunctionReturn(0);
}

// Broadcasts rank 0's *s into *s on every rank of comm. Collective.
inline PetscErrorCode BcastString(MPI_Comm comm, std::string *s)
{
  std::vector<char> c(s->begin(), s->end());
  PetscFunctionBeginUser;
  PetscCall(BcastVector(comm, &c));
  s->assign(c.begin(), c.end());
  PetscFunctionReturn(0);
}

} // namespace boltnet
