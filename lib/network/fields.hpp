// The displacement field of the assembly gathered to rank 0 for output (io/fields.cpp writes it).
// This is the one place where the field output reads the network's internals (network/fields.cpp):
// how parts map to vertices and where their dof sit in X.
#pragma once

#include "network/assembly.hpp"

#include <array>
#include <vector>

namespace boltnet {

// One shell part as the user described it, whatever patches (network vertices) it was cut into.
struct PartField {
  PetscInt                           id; // user patch id
  std::vector<std::array<double, 3>> x;     // reference node coordinates (mm)
  std::vector<std::array<int, 4>>    elems; // node numbers within the part (a triangle's fourth: -1)
  std::vector<double>                dof;   // 6 per node: ux uy uz rx ry rz (mm, rad)
};

// One joint as a line between its attachment points on its two patches.
struct JointLine {
  PetscInt              id;     // user joint id
  PetscInt              state;  // State at the last converged step (what the joint did in it)
  std::array<double, 3> xa, xb; // reference attachment points: a rigid patch's node; on a shell
                                // patch, the point of the bolt axis on the footprint's mid-surface
  std::array<double, 6> ua, ub; // dof of the joint's nodes on patches a and b (global frame)
  std::array<double, 9> R;      // local frame rows (n, t1, t2)
  std::array<double, 6> jump;   // local jump and force (as in joints.csv)
  std::array<double, 6> force;
};

// Collective on a->comm. On rank 0: every shell part (sorted by patch id) and every joint (sorted
// by joint id) at the last converged point a->X; empty elsewhere.
PetscErrorCode AssemblyGatherFields(BoltnetAssembly a, std::vector<PartField> &parts, std::vector<JointLine> &lines);

} // namespace boltnet
