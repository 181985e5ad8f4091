// The error boundary: every function handed to PETSc turns C++ exceptions into PETSc errors, so
// that an exception (std::bad_alloc from a vector, say) cannot escape and end the job on every rank.
#pragma once
#include <petscsys.h>

#include <exception>
#include <new>
#include <string>

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

// For work on data that only some ranks hold (their own patches, their own joints): runs body on
// every rank and, if it failed on any, raises the first failing rank's error, with its message, on
// every rank of comm, so that no rank is left waiting in a later collective call.
template <class F>
PetscErrorCode Collective(MPI_Comm comm, F &&body)
{
  PetscErrorCode ierr = 0, code = PETSC_ERR_LIB;
  std::string    msg;
  PetscMPIInt    rank, size, first;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  try {
    ierr = body();
  } catch (const std::exception &e) {
    ierr = PETSC_ERR_LIB;
    msg  = std::string("C++ exception in boltnet: ") + e.what();
  } catch (...) {
    ierr = PETSC_ERR_LIB;
    msg  = "Unknown C++ exception in boltnet";
  }
  PetscCall(PetscPopErrorHandler());
  if (ierr && msg.empty()) {
    const char *text     = nullptr;
    char       *specific = nullptr;
    PetscCall(PetscErrorMessage(ierr, &text, &specific));
    msg = specific && specific[0] ? specific : (text ? text : "error");
  }
  PetscMPIInt mine = ierr ? rank : size;
  PetscCallMPI(MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm));
  if (first == size) PetscFunctionReturn(0);
  long len = (long)msg.size();
  if (rank == first) code = ierr;
  PetscCallMPI(MPI_Bcast(&code, 1, MPI_INT, first, comm));
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_LONG, first, comm));
  msg.resize(len);
  PetscCallMPI(MPI_Bcast(msg.data(), (PetscMPIInt)len, MPI_CHAR, first, comm));
  SETERRQ(comm, code, "%s", msg.c_str());
}

} // namespace boltnet
