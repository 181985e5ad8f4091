// The error boundary: every function handed to PETSc turns C++ exceptions into PETSc errors, so
// that an exception (std::bad_alloc from a vector, say) cannot escape and end the job on every rank.
#pragma once
#include <petscsys.h>
#include <exception>
#include <new>

namespace boltnet {

template <class F>
PetscErrorCode Guard(MPI_Comm comm, F &&body)
{
  try {
    return body();
  } catch (const std::bad_alloc &) {
    SETERRQ(comm, PETSC_ERR_MEM, "Out of memory (a C++ allocation in boltnet failed)");
  } catch (const std::exception &e) {
    SETERRQ(comm, PETSC_ERR_LIB, "C++ exception in boltnet: %s", e.what());
  } catch (...) {
    SETERRQ(comm, PETSC_ERR_LIB, "Unknown C++ exception in boltnet");
  }
}

} // namespace boltnet
