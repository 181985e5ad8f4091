// Argument checks at the entry points of the C API (boltnet.h), in the manner of PETSc's
// PetscValidPointer(): the message names the function and the argument.
//
// A NULL pointer is a fact about one rank, so it is raised on PETSC_COMM_SELF, as PETSc does (an
// error raised on a larger communicator is printed by its rank 0 only; core/guard.hpp). Counts,
// ids and ranges are the same on every rank (every rank passes the same description) and are
// checked on the assembly's communicator, so that one error prints one message.
#pragma once
#include <petscsys.h>

// p must not be NULL: argument number argnum (from 1), called name in boltnet.h, of the function
// where (a helper gets the entry point's name from it).
#define BoltnetCheckPointerIn(where, p, argnum, name) \
  PetscCheck((p) != nullptr, PETSC_COMM_SELF, PETSC_ERR_ARG_NULL, "%s: argument %d (%s) is NULL", where, (int)(argnum), name)
// The same, in the entry point itself.
#define BoltnetCheckPointer(p, argnum, name) BoltnetCheckPointerIn(__func__, p, argnum, name)
