// Helpers shared by the files of lib/network (not part of the assembly's interface).
#pragma once

#include "network/assembly.hpp"

namespace boltnet {

// Copy component 0 of network point p (a vertex or an edge) into out (bytes of it; out may be
// null to read the key only). DMNetwork stores components 4-byte aligned: reading a struct of
// doubles in place is undefined behaviour, a copy is not.
PetscErrorCode NetworkComponent(DM dm, PetscInt p, PetscInt *key, void *out, size_t bytes);

// The whole shell patches and seams this rank owns (all of them with keep_layout), from the ranks
// that laid them out (collective; network/fetch.cpp).
PetscErrorCode AssemblyFetchLayout(BoltnetAssembly a);
// The Jacobian, preallocated exactly (network/jacobian.cpp).
PetscErrorCode AssemblyCreateJacobian(BoltnetAssembly a);
// The lagged interface solve's choice: refactor J now, or keep the PC's factorisation.
PetscErrorCode AssemblyLaggedFactorisation(BoltnetAssembly a);
// The boundary rows of the owned patches (network/boundary.cpp).
PetscErrorCode AssemblySetUpBoundary(BoltnetAssembly a);
// The ghosted local copy of X (collective: every rank must call it, whatever it owns).
PetscErrorCode GetLocalX(BoltnetAssembly a, Vec X, Vec *Xl, const PetscScalar **x);
PetscErrorCode RestoreLocalX(BoltnetAssembly a, Vec *Xl, const PetscScalar **x);

} // namespace boltnet
