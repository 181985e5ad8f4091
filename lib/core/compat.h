// The one place for PETSc version guards. boltnet is written against PETSc 3.18.
#pragma once
#include <petscversion.h>
#if PETSC_VERSION_LT(3, 18, 0)
#error "boltnet needs PETSc >= 3.18"
#endif
