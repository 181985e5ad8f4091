// From the model the user described to the pieces the network carries: joints attached to their
// parts (footprints), large parts cut into patches joined by seams, and the nodes each network
// vertex carries (every node, or only the ports of a condensed patch). The vertex and edge records
// here are the DMNetwork components: plain structs, copied as raw bytes when the network is
// distributed (docs/architecture.md).
#pragma once

#include "model/model.hpp"
#include "patch/patch.hpp"

#include <map>
#include <vector>

namespace boltnet {

// Vertex component.
struct PatchComp {
  PetscInt  id;     // user id of the part
  PetscInt  index;  // position in the layout's patches
  PetscInt  kind;   // PatchKind
  PetscInt  nnodes; // nodes carried by the vertex (6 dof each)
  PetscReal x[3];   // reference position of node 0
};

// Edge component of a joint. R holds the local frame rows (n, t1, t2).
struct JointComp {
  PetscInt  id;               // user id
  PetscInt  index;            // position in the model's joints (0..njoints-1)
  PetscInt  row;              // position among the model's joints sorted by id: the output tables' row
  PetscInt  patch_a, patch_b; // user ids of the two parts
  PetscInt  va, vb;           // positions in the layout's patches of the two patches
  PetscReal x[3];             // position of the fastener (where shell patches attach it)
  PetscInt  node_a, node_b;   // the attachment nodes, numbered among the nodes their vertex carries
  PetscInt  pnode_a, pnode_b; // the same, numbered in their patch (mesh nodes, then joint nodes)
  // On a rigid patch, where the joint acts relative to the patch's node (its position minus the
  // node's, zero for a joint given no position): the attachment point follows the node as a rigid
  // body, u + theta x d (docs/joint-laws.md, "Where a joint acts").
  PetscReal da[3], db[3];
  // The reference point of each side's attachment, for output: a rigid patch's node plus d; on a
  // shell patch, the point of the bolt axis at the mean axial position of the footprint nodes (the
  // mid-surface), or the mesh node itself (-coupling_type node). Found by the holder of the patch
  // at the layout, so that no other rank needs the patch's mesh.
  PetscReal pa[3], pb[3];
  PetscReal R[9];
  Params    params;
  // 1 when its footprint is a node set the user named (JointDesc::footprint): a tie, an RBE2-like
  // modelling device that carries a load into a part (docs/scenes.md, "Ties"), not a fastener. The
  // most loaded joint of the output leaves ties out.
  PetscInt tie;
};

// Edge component of a seam; the seam's elements are in the layout's `seams`.
struct SeamComp {
  PetscInt index; // position in the layout's seams
  PetscInt part;  // user id of the part
};

// Which shell patches are condensed onto their ports: none, all, or those whose ports are few
// enough for their dense block to be cheaper than keeping the patch whole (CondensePatchPays).
enum class Condense { None, All, Auto };

// The automatic choice. A patch of n dof with nb port dof, condensed, puts a dense nb x nb block on
// the interface, whose factorisation costs nb^3/3 per Newton iteration and nb^2 memory; kept whole,
// its sparse 2D factorisation costs about (c sqrt(n))^3 (nested dissection: the top separator's
// front dominates). Condensing pays while nb <= ratio sqrt(n); the default ratio is measured in
// docs/solver.md ("Which patches are condensed").
bool CondensePatchPays(PetscInt nb, PetscInt n, double ratio);

struct LayoutOptions {
  CouplingType coupling  = CouplingType::Exact;
  double       radius    = 4.0; // footprint radius (mm)
  double       reach     = 0;   // footprint reach along the fastener axis (mm); 0: 4 radius
  long         max_nodes = 0;   // largest patch in nodes (0: no cut; -1: automatic, by the ranks)
  Condense     condense  = Condense::None; // which vertices carry their ports only
  double       condense_ratio = 4;       // Condense::Auto: ports per sqrt(patch dof)
  bool         directors = true;  // curved parts: the elements share the mesh's nodal directors
};

// Each shell part is laid out by one rank, its holder: its joints attached, its cut, its ports. Every
// rank knows every patch's record and every seam's ends; rank 0 alone holds every joint's component
// (`joints`, empty on the other ranks), to lay out the network's graph. The whole patches and seams
// (meshes, elements, footprints) are on their part's holder only, and `shells` holds a stub (part
// id, section, condensed; no mesh) for each of the others, until the network sends each rank the
// patches and seams it needs (network/build.cpp). Once the network is distributed rank 0 empties
// `joints` too (each rank's own are its network edges' components); `njoints` stays.
struct Layout {
  std::vector<PatchComp>         patches;
  std::vector<PetscInt>          part_of;   // position in the model's parts of each patch
  std::vector<PetscMPIInt>       holder;    // the rank that laid out each patch's part (-1: rigid)
  std::vector<PetscInt>          nodes;     // every node of each patch (mesh and joint nodes; 1 if rigid)
  std::map<PetscInt, ShellPatch> shells;    // the shell patches, by position in patches
  std::vector<Seam>              seams;     // every seam's ends and section; its elements on its holder
  std::vector<JointComp>         joints;    // in the model's order, on rank 0 during the set-up
  PetscInt                       njoints = 0; // joints in the model
  std::map<PetscInt, ShellMesh>  cut_parts; // the whole meshes of the parts that were cut, by user id
  PetscInt                       nparts = 0;
  PetscInt                       mesh_nodes = 0;   // mesh nodes over every shell part
  PetscInt                       ncondensed = 0;   // shell patches condensed onto their ports
  PetscInt                       njoint_nodes = 0; // joint nodes over every shell patch
  // A hash (hex) of the whole layout: the patches in order with the nodes they carry, the joints'
  // patches. Two runs whose layouts hash alike number their solution vectors alike, so a checkpoint
  // of one restarts the other (io/checkpoint.cpp). It does not depend on the number of ranks.
  std::string                    fingerprint;
};

// Check the model and lay it out (collective). The shell parts' meshes move from the model: a
// part's into the layout on its holder, the others' are dropped. The joints are rank 0's (model.hpp):
// on return model.joints holds, on each rank, those that attach to the shell parts it holds. Errors
// name the joint, part, node or boundary condition at fault, on every rank.
PetscErrorCode LayoutCreate(MPI_Comm comm, Model &model, const LayoutOptions &o, Layout *L);

// The edge list of the network: the joints (their patches' positions), then the seams.
std::vector<PetscInt> LayoutEdgeList(const Layout &L);

} // namespace boltnet
