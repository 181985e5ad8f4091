// The boltnet SNES plugin. Any PETSc program loads it without linking boltnet:
//
//   ./app -dll_append /path/to/libboltnet_snes.so -snes_linesearch_type boltnet
//
// PETSc opens the library and calls PetscDLLibraryRegister_<name>, <name> being the file name
// without "lib" and the extension.
#include "boltnet.h"

PETSC_EXTERN PetscErrorCode PetscDLLibraryRegister_boltnet_snes(void)
{
  PetscFunctionBeginUser;
  PetscCall(BoltnetInitializePackage());
  PetscFunctionReturn(0);
}
