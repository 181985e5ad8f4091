// Input errors as PETSc errors: the C++ readers (io/table.hpp, io/scene_yaml.hpp, lib/nastran) throw
// std::runtime_error with a message naming the file, line and field; every rank reads the same text,
// so the error is raised collectively, with that message.
#pragma once

#include <petscsys.h>

#include <exception>
#include <new>

namespace boltnet {

// Runs body(); an exception becomes PETSC_ERR_USER_INPUT with its message, std::bad_alloc
// PETSC_ERR_MEM "Out of memory while <what>".
template <class F>
PetscErrorCode Input(MPI_Comm comm, const char what[], F &&body)
{
  try {
    body();
  } catch (const std::bad_alloc &) {
    SETERRQ(comm, PETSC_ERR_MEM, "Out of memory while %s", what);
  } catch (const std::exception &e) {
    SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s", e.what());
  }
  return 0;
}

} // namespace boltnet
