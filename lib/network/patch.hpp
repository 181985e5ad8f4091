// Shell patches: the plates carried by the network's vertices (issue 3). A patch is a quadrilateral
// shell mesh plus one extra node per joint attached to it (the joint node, at the fastener); the
// fastener's footprint nodes follow the joint node rigidly (lib/coupling). The patch is linear: its
// stiffness is built once, on the rank that owns the vertex, as a sparse matrix in the patch's own
// dof numbering (6 per node), and enters the residual as K u and the Jacobian as K.
#pragma once

#include "mesh/mesh.hpp"
#include "shell/shell.hpp"

#include <petscsys.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace boltnet {

struct ShellPatch {
  PetscInt             id = -1;
  QuadMesh             mesh;
  shell::ShellMaterial material;
  double               drill = shell::kDefaultDrill;
  // Joint nodes: node mesh.x.size() + k is the k-th joint attached to this patch.
  struct JointNode {
    std::array<double, 3> x, axis;
    std::vector<int>      footprint;
  };
  std::vector<JointNode> joint_nodes;
  // Node counts of the whole part this patch was cut from, by node set ("" : every node): a force
  // on a set is spread over the set's nodes in every patch of the part.
  std::map<std::string, PetscInt> part_set_size;
  PetscInt nnodes() const { return (PetscInt)(mesh.x.size() + joint_nodes.size()); }
};

// A seam: the elements of a part whose nodes lie in two of its patches (va and vb, positions in the
// assembly's patch list). It is a network edge; its elements' stiffness is added where the edge
// lives. side[k] says whether node k of an element is in patch vb (1) or va (0), node[k] its number
// there.
struct Seam {
  PetscInt             part = -1; // user id of the part
  PetscInt             va = -1, vb = -1;
  shell::ShellMaterial material;
  double               drill = shell::kDefaultDrill;
  struct Element {
    shell::Nodes       X;
    std::array<int, 4> side, node;
  };
  std::vector<Element> elems;
};

// Sparse symmetric matrix in compressed rows, local dof numbering of one patch.
struct PatchOperator {
  PetscInt              n = 0;
  std::vector<PetscInt> rowptr, cols;
  std::vector<double>   vals;
};

// The patch stiffness: shell elements plus the rigid links of every joint's footprint, by penalty
// with stiffness `penalty` (N/mm) on translations and `penalty * radius^2` on rotations.
// Throws std::invalid_argument (from the element) on degenerate elements.
PatchOperator BuildShellOperator(const ShellPatch &p, double penalty, double radius);

} // namespace boltnet
