// Shell patches: the pieces of shell parts carried by the network's vertices. A patch is a set of
// mesh nodes of one part, the elements between them, its share of the elements it has in common
// with other patches of the part, and one extra node per joint attached to it (the joint node, at
// the fastener), whose footprint nodes follow it rigidly (patch/rigid.hpp). The patch is linear: its
// operator is built once, on the rank that owns the vertex, and is either kept whole (every node is
// carried by the vertex) or condensed onto the patch's ports (patch/condense.hpp).
#pragma once

#include "mesh/mesh.hpp"
#include "shell/shell.hpp"

#include <petscsys.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace boltnet {

// One element as the shell kernels take it (shell::ElementStiffness(n, X, V, ...)): n = 3
// (triangle) or 4 (quadrilateral) nodes X[0..n-1], and the mesh's directors V when it passes them
// (mesh/mesh.hpp, ElementDirectors; otherwise the element uses its own normals).
struct ElementGeometry {
  int              n = 4;
  shell::Nodes     X{};
  shell::Directors V{};
  bool             directors = false;
};
// Element e of mesh m.
ElementGeometry GeometryOf(const ShellMesh &m, const MeshElement &e);
// Its stiffness in the quadrilateral's 24 x 24 layout, for triangles and quadrilaterals alike: the
// block of nodes a, b < n at rows 6 a + i, columns 6 b + j; a triangle's rows and columns 18..23
// (no fourth node) are zero. Throws std::invalid_argument (from the element) on a degenerate one.
void ElementMatrixOf(const ElementGeometry &g, const shell::ShellMaterial &mat, double drill, shell::ElementMatrix &K);

struct ShellPatch {
  PetscInt             id = -1; // user id of the part
  ShellMesh            mesh;    // the patch's own nodes (part_node: their number in the part), its
                                // whole elements, its node sets (patch numbering)
  shell::ShellMaterial material;
  double               drill = shell::kDefaultDrill;
  // Elements shared with other patches of the part: node[k] is the patch's number of node k, or -1
  // when node k lies in another patch (or k = 3 of a triangle). The patch adds the stiffness between
  // its own nodes; the seams add the rest.
  struct SharedElement {
    ElementGeometry    geom;
    std::array<int, 4> node;
    int                elem = -1;    // its number in the part (for output, network/fields.cpp)
    std::array<int, 4> part_node{}; // its nodes' numbers in the part
  };
  std::vector<SharedElement> shared;
  // For each node set of the part, the shared elements (positions in `shared`) whose nodes all lie
  // in it: what a pressure on the set loads (patch/loads.hpp). The patch cannot tell alone, since
  // some of their nodes are in other patches; the cut, which has the whole part, records it.
  std::map<std::string, std::vector<int>> shared_in_set;
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
  // Number in the whole part of each element of mesh.elems (empty: the patch is the whole part).
  std::vector<int> part_elem;
  // Whether the patch is condensed onto its ports (patch/condense.hpp) or kept whole; the layout
  // decides it per patch (LayoutOptions::condense).
  bool condensed = false;
  // The nodes the network vertex carries, in order: every node (mesh, then joint nodes) when the
  // patch is kept whole, its ports (the joint nodes and the nodes a seam touches) when condensed.
  std::vector<int> carried;
  std::map<int, int> carried_index; // node -> position in carried

  PetscInt nnodes() const { return (PetscInt)(mesh.x.size() + joint_nodes.size()); }
};

// A seam: the stiffness between the nodes of two patches va and vb (positions in the layout's patch
// list) of one part, from the elements they share. side[k] says whether node k of an element is in
// va (0), vb (1) or a third patch (-1); node[k] is its number in the network vertex (its position in
// that patch's carried nodes). A triangle's absent fourth node has side -1 like a node of a third
// patch: nothing is added for it. A seam adds only the blocks between va and vb.
struct Seam {
  PetscInt             part = -1; // user id of the part
  PetscInt             va = -1, vb = -1;
  shell::ShellMaterial material;
  double               drill = shell::kDefaultDrill;
  struct Element {
    ElementGeometry    geom;
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

// The patch operator A over all the patch's nodes (6 dof each), linear: it enters the residual as
// A u and the Jacobian as A.
//   penalty: the shell stiffness K plus the rigid links of every joint's footprint, with stiffness
//            `penalty` (N/mm) on translations and `penalty * radius^2` on rotations.
//   exact:   u = T v, v the dof of the nodes outside every footprint and of the joint nodes, the
//            footprint (slave) dof u_s = T_s(d) u_m: u_s = u_m + theta_m x d, theta_s = theta_m.
//            The rows of v hold T^T K T (the exact reduced stiffness, no slave column), each slave
//            row holds c (u_s - T_s u_m) = 0 with c the mean translational diagonal of K, so that
//            the slave dof stay in the vector with their true displacement. A node in two
//            footprints must have been given to one joint before (patch/attach.cpp).
//   node:    K alone (the joints attach to mesh nodes).
// K includes the patch's whole elements and its share of the shared ones.
// Throws std::invalid_argument (from the element) on degenerate elements.
PatchOperator BuildShellOperator(const ShellPatch &p, CouplingType type, double penalty, double radius);

// The slaves of exact coupling: for each mesh node of the patch in a footprint, the joint node it
// follows (-1: none) and the 6 x 6 block T with u_s = T u_m (row major).
struct SlaveMap {
  std::vector<PetscInt>               master; // by mesh node
  std::vector<std::array<double, 36>> T;      // by mesh node (unused where master < 0)
};
SlaveMap ExactSlaves(const ShellPatch &p);
// T of one slave at d = x_s - x_m from its joint node: u_s = u_m + theta_m x d, theta_s = theta_m.
std::array<double, 36> SlaveTransform(const std::array<double, 3> &d);

} // namespace boltnet
