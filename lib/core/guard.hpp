// The error boundary: every function handed to PETSc, and every function of the C API (boltnet.h),
// turns C++ exceptions into PETSc errors, so that an exception (std::bad_alloc from a vector, say)
// cannot escape into C or PETSc code and end the job by std::terminate (docs/architecture.md,
// "Errors").
//
// The error is raised on PETSC_COMM_SELF, by the rank that caught the exception, as PETSc's own
// PetscValidPointer() does: PETSc's default error handler prints an error raised on a larger
// communicator only on its rank 0, and any other rank that raises it sleeps for ten seconds and
// exits without a word (PetscTraceBackErrorHandler()), so an exception on rank 1 of a parallel
// SNES would be lost. Where ranks must agree on the failure, Collective() below does that.
#pragma once
#include <petscsys.h>

#include <exception>
#include <new>
#include <string>

namespace boltnet {

// Runs body() (returning a PetscErrorCode) and turns what it throws into a PETSc error naming
// `where` (the C API function or PETSc callback): PETSC_ERR_MEM for std::bad_alloc, PETSC_ERR_LIB
// with what() for any other exception. The handlers allocate nothing.
template <class F>
PetscErrorCode Guard(const char *where, F &&body) noexcept
{
  try {
    return body();
  } catch (const std::bad_alloc &) {
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_MEM, "%s: out of memory (a C++ allocation failed: std::bad_alloc)", where);
  } catch (const std::exception &e) {
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "%s: C++ exception: %s", where, e.what());
  } catch (...) {
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "%s: unknown C++ exception", where);
  }
}

// The older spelling, for code inside the library that has no function name at hand. The
// communicator is not used (see the top of the file).
template <class F>
PetscErrorCode Guard(MPI_Comm, F &&body) noexcept
{
  return Guard("boltnet", static_cast<F &&>(body));
}

// For work on data that only some ranks hold (their own patches, their own joints), with no
// collective call inside: runs body on every rank and, if it failed on any (a PETSc error or a C++
// exception), raises the first failing rank's error, with its code and message, on every rank of
// comm, so that no rank is left waiting in a later collective call and rank 0 prints it once.
// std::bad_alloc becomes PETSC_ERR_MEM. The message travels in a fixed buffer: reporting an
// out-of-memory error allocates nothing.
template <class F>
PetscErrorCode Collective(MPI_Comm comm, const char *where, F &&body) noexcept
{
  PetscErrorCode ierr = 0, code = PETSC_ERR_LIB;
  char           msg[1024] = "";
  PetscMPIInt    rank, size, first;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  try {
    ierr = body();
  } catch (const std::bad_alloc &) {
    ierr = PETSC_ERR_MEM;
    PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s: out of memory (a C++ allocation failed: std::bad_alloc)", where));
  } catch (const std::exception &e) {
    ierr = PETSC_ERR_LIB;
    PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s: C++ exception: %s", where, e.what()));
  } catch (...) {
    ierr = PETSC_ERR_LIB;
    PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s: unknown C++ exception", where));
  }
  PetscCall(PetscPopErrorHandler());
  if (ierr && !msg[0]) {
    const char *text     = nullptr;
    char       *specific = nullptr;
    PetscCall(PetscErrorMessage(ierr, &text, &specific));
    PetscCall(PetscStrncpy(msg, specific && specific[0] ? specific : (text ? text : "error"), sizeof(msg)));
  }
  PetscMPIInt mine = ierr ? rank : size;
  PetscCallMPI(MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm));
  if (first == size) PetscFunctionReturn(0);
  if (rank == first) code = ierr;
  PetscCallMPI(MPI_Bcast(&code, 1, MPI_INT, first, comm));
  PetscCallMPI(MPI_Bcast(msg, (PetscMPIInt)sizeof(msg), MPI_CHAR, first, comm));
  SETERRQ(comm, code, "%s", msg);
}

template <class F>
PetscErrorCode Collective(MPI_Comm comm, F &&body) noexcept
{
  return Collective(comm, "boltnet", static_cast<F &&>(body));
}

} // namespace boltnet
