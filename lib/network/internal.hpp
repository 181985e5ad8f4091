// Helpers shared by the files of lib/network (not part of the assembly's interface).
#pragma once

#include "network/assembly.hpp"

namespace boltnet {

// The automatic largest size of a condensed patch, in nodes (docs/solver.md, "Patch size").
constexpr long kCondensedPatchNodes = 3000;

// Copy component 0 of network point p (a vertex or an edge) into out (bytes of it; out may be
// null to read the key only). DMNetwork stores components 4-byte aligned: reading a struct of
// doubles in place is undefined behaviour, a copy is not.
PetscErrorCode NetworkComponent(DM dm, PetscInt p, PetscInt *key, void *out, size_t bytes);

// The Jacobian, preallocated exactly (network/jacobian.cpp).
PetscErrorCode AssemblyCreateJacobian(BoltnetAssembly a);
// The lagged interface solve's choice: refactor P from J now, or keep its factorisation.
PetscErrorCode AssemblyLaggedFactorisation(BoltnetAssembly a, Mat J, Mat P);
// The boundary rows of the owned patches (network/boundary.cpp).
PetscErrorCode AssemblySetUpBoundary(BoltnetAssembly a);
// The ghosted local copy of X (collective: every rank must call it, whatever it owns).
PetscErrorCode GetLocalX(BoltnetAssembly a, Vec X, Vec *Xl, const PetscScalar **x);
PetscErrorCode RestoreLocalX(BoltnetAssembly a, Vec *Xl, const PetscScalar **x);

// The 24 dof of a seam element in a vector whose seam vertices start at oa (side 0) and ob (side
// 1); -1 for a node in a third patch and for a triangle's absent fourth node (side -1 both).
void SeamElementDofs(const Seam::Element &el, PetscInt oa, PetscInt ob, PetscInt dofs[24]);
// The offsets (global or local) of the two vertices of seam edge e.
PetscErrorCode SeamOffsets(BoltnetAssembly a, PetscInt e, PetscBool global, PetscInt *oa, PetscInt *ob);
// The seam of edge e.
PetscErrorCode SeamOf(BoltnetAssembly a, PetscInt e, const Seam **seam);

} // namespace boltnet
