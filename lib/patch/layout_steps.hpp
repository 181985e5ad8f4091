// The steps of the layout (layout.hpp), each in its own file, called in order by LayoutCreate
// (layout.cpp): the joints attached to the parts (attach.cpp), the parts cut into patches and the
// nodes each vertex carries chosen (cut_part.cpp), and what the ranks tell each other: which rank
// lays out which part, each holder's joints, the records every rank needs (share.cpp). Not part of
// the layout's interface.
#pragma once

#include "patch/layout.hpp"

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace boltnet {

// A part node's place in the layout: (patch position, node number in the patch).
using NodeMap = std::vector<std::pair<PetscInt, int>>;

// Attach every joint side on a shell part: a joint node with its footprint, or (node coupling) the
// nearest mesh node. On return parts[p] holds its joint nodes and jnode[2 j + side] the node number
// in the part (mesh nodes, then joint nodes).
PetscErrorCode AttachJoints(MPI_Comm comm, Model &m, const LayoutOptions &o, std::map<PetscInt, ShellPatch> &parts, std::vector<PetscInt> &jnode);

// The reference point of joint j's attachment to shell patch sp at its node pnode (JointComp::pa):
// the mesh node itself (-coupling_type node), or the point of the bolt axis at the mean axial
// position of the footprint nodes, which is the mid-surface of the sheet the fastener crosses.
std::array<double, 3> ShellAttachmentPoint(const ShellPatch &sp, const JointComp &j, PetscInt pnode);

// The layout's component of joint d, at position ji in the model. A side on a rigid part is laid out
// on every rank; with `jnode` (d's attachment node in each of its parts, AttachJoints) the sides on
// the shell parts this rank holds are filled too, the others stay -1.
JointComp MakeJointComp(const Model &m, const LayoutOptions &o, const JointDesc &d, PetscInt ji, const std::vector<NodeMap> &nodemap, const PetscInt *jnode, const Layout &L);

// Cut one shell part into patches appended to L (positions first, first + 1, ...); nodemap[n] is
// the (patch position, patch node) of part node n (mesh nodes, then joint nodes).
void CutShellPart(ShellPatch &&part, PetscInt first, long max_nodes, Layout *L, NodeMap &nodemap);

// The nodes each shell vertex carries: all of them, or, for a condensed patch, its ports (joint
// nodes, attachment nodes of node-coupled joints, nodes in elements shared with another patch), in
// increasing node order. Which patches are condensed: o.condense.
void Carry(Layout *L, const LayoutOptions &o);

// The automatic patch size (LayoutOptions::max_nodes -1). A part is cut only to share it between
// ranks: with every patch kept whole, about eight patches per rank, none under 32 nodes; otherwise
// about four per rank, none under 64 nodes (the automatic choice then decides which pieces are
// condensed); no cut on one rank. Cutting a condensed part for its own sake does not pay: the
// sparse factorisation of a whole plate costs about what its pieces cost, while every cut puts a
// band of seam nodes on the interface, where each patch's S is dense over all its ports
// (docs/solver.md, "Patch size": whole plates 11 times faster than 3,000-node pieces).
long AutomaticPatchSize(std::int64_t total, PetscMPIInt size, bool condense);

// Which rank lays out each shell part (-1: a rigid part, which every rank lays out): the largest
// first, each to the rank with the fewest nodes so far (longest processing time first), the lowest
// rank among equals, so that every rank computes the same assignment.
std::vector<PetscMPIInt> AssignParts(const Model &m, PetscMPIInt size);

// Rank 0 holds the model's joints (the scene's fastener table is read there alone, io/scene.cpp; a
// linking code may give them on every rank, and the other ranks' copies are dropped here). Each
// rank receives the joints that attach to the shell parts it holds (`holder`, AssignParts) with
// their positions in the model (`index`); rank 0 keeps the whole list in `all`, to lay out the
// network's graph. Every rank learns the number of joints.
PetscErrorCode ShareJoints(MPI_Comm comm, const std::vector<PetscMPIInt> &holder, Model &m, std::vector<JointDesc> *all, std::vector<PetscInt> *index, PetscInt *njoint);

// The meshes that rank 0 alone holds (ShellPart::on_rank0: a Nastran deck's parts) sent to the
// ranks that lay them out (`holder`), one part at a time, rank 0 dropping each once sent: on return
// each such part's holder has its mesh, node sets and directors in ShellPart::mesh.
PetscErrorCode SendRank0Meshes(MPI_Comm comm, const std::vector<PetscMPIInt> &holder, Model &m);

// What the holders of the parts found, given to every rank: each patch's record (the nodes its
// vertex carries, all its nodes, whether condensed), each seam's ends, a stub (part, section,
// condensed) for every shell patch held elsewhere, the fingerprint. Each joint's attachment on shell
// parts goes to rank 0 alone, which lays out the network's graph (network/build.cpp) with `all`, its
// components of every joint (their shell sides still to be filled): the other ranks drop the
// components of their parts' joints here and receive their own from DMNetworkDistribute. Each value
// has one writer (the holder of its part), so sums gather them.
PetscErrorCode ShareLayout(MPI_Comm comm, const std::map<PetscInt, ShellPatch> &stubs, std::vector<JointComp> &&all, Layout *L);

} // namespace boltnet
