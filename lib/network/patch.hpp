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
  // Number in the whole part of each mesh node of this patch (empty: the patch is the whole part).
  std::vector<int> part_node;
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

// How a joint attaches to a shell patch (-coupling_type, docs/coupling.md).
//   penalty: the footprint nodes tied to the joint node by stiff rigid links (energy penalty);
//   exact:   the footprint nodes' dof eliminated as rigid-body slaves of the joint node;
//   node:    no footprint and no joint node: the joint attaches to the nearest mesh node (the
//            classic spring between two shell nodes, kept as the baseline to compare with).
enum class CouplingType : int { Penalty = 0, Exact = 1, Node = 2 };
extern const char *const kCouplingTypeNames[3]; // "penalty", "exact", "node"

// Sparse matrix in compressed rows, local dof numbering of one patch (symmetric except for the
// constraint rows of exact coupling).
struct PatchOperator {
  PetscInt              n = 0;
  std::vector<PetscInt> rowptr, cols;
  std::vector<double>   vals;
};

// The patch operator A, linear: it enters the residual as A u and the Jacobian as A.
//   penalty: the shell stiffness K plus the rigid links of every joint's footprint, with stiffness
//            `penalty` (N/mm) on translations and `penalty * radius^2` on rotations.
//   exact:   u = T v, v the dof of the nodes outside every footprint and of the joint nodes, the
//            footprint (slave) dof u_s = T_s(d) u_m: u_s = u_m + theta_m x d, theta_s = theta_m.
//            The rows of v hold T^T K T (the exact reduced stiffness, no slave column), each slave
//            row holds c (u_s - T_s u_m) = 0 with c the mean translational diagonal of K, so that
//            the slave dof stay in the vector with their true displacement. A node in two
//            footprints must have been given to one joint before (AssemblyBuildNetwork).
//   node:    K alone (the joints attach to mesh nodes).
// Throws std::invalid_argument (from the element) on degenerate elements.
PatchOperator BuildShellOperator(const ShellPatch &p, CouplingType type, double penalty, double radius);

} // namespace boltnet
