// The results of the assembly in the file's numbering, computed where they live (docs/output.md).
// This is the one place where the field output reads the network's internals (network/fields.cpp):
// how parts map to patches and vertices, where their dof sit in X, which rank holds what.
//
// The file's (natural) numbering: shell parts by increasing id; within a part its nodes and its
// elements in the user's own numbering, whatever patches the part was cut into and whatever rank
// holds them; joints in the order of the model's joint list. Natural node n of part p is
// node_off[p] + (its number in the part); every rank computes that for the nodes of its own patches
// from part-wise counts (one MPI_Allreduce), so no rank ever holds the whole field: each rank
// computes what it owns, and a VecScatter per block size puts owned values in natural order, each
// rank holding a contiguous piece of as many rows as it owns.
#pragma once

#include "network/assembly.hpp"
#include "shell/resultants.hpp"

#include <array>
#include <map>
#include <vector>

namespace boltnet {

// Items (nodes, elements or joints) this rank owns and their natural numbers.
struct FieldSpace {
  PetscInt                       nlocal = 0, nglobal = 0, start = 0; // start: exclusive scan of nlocal
  std::vector<PetscInt>          natural;                            // by owned item
  std::map<PetscInt, VecScatter> scatter;                            // owned -> natural, by block size
  std::map<PetscInt, std::array<Vec, 2>> vecs;                       // (owned, natural), by block size
};
// Collective: nlocal, start and nglobal from natural (filled by the caller).
PetscErrorCode FieldSpaceSetUp(MPI_Comm comm, FieldSpace &s);
// Its scatters and Vecs destroyed; s emptied.
PetscErrorCode FieldSpaceDestroy(FieldSpace &s);

// An element this rank writes (network/fields.cpp ElementsOf: the only code that enumerates them).
// XDMF cell type codes: 5 quadrilateral (nn = 4), 4 triangle (nn = 3).
struct FieldElement {
  PetscInt              part;    // user id
  PetscInt              elem;    // number in the part
  PetscInt              owned;   // position in a->patches.owned of the patch that writes it
  int                   type, nn;
  std::array<PetscInt, 4> node;  // natural node numbers
  std::array<int, 4>    local;   // the patch's own node number, or -1 (a node of another patch)
  ElementGeometry       geom;    // nodes and directors as the stiffness has them (patch/operator.cpp)
};

struct FieldMap {
  std::vector<PetscInt>              part_ids;         // shell parts, increasing
  std::map<PetscInt, PetscInt>       node_off, elem_off; // by part id
  FieldSpace                         nodes, elems, joints;
  PetscInt                           ntriangles = 0;   // over all ranks: the rest are quadrilaterals
  std::vector<std::array<PetscInt, 2>> node_src;       // by owned node: (position in owned patches, patch node)
  std::vector<FieldElement>          elements;         // by owned element
  std::vector<shell::CondensedModes> modes;            //   and its condensed modes, once AssemblyStepFields keeps them
  std::vector<PetscInt>              ghosts;           // natural numbers of the other patches' nodes
  std::map<PetscInt, PetscInt>       ghost_index;      //   and their positions
  VecScatter                         ghost_scatter = nullptr; // natural (block 6) -> ghosts
  Vec                                ghost_dof = nullptr;     // 6 per ghost node
  // Bypass (network/fields_bypass.cpp): the joint sides whose bands may hold this rank's elements
  // (slot: 2 joint index + side), the elements that may lie in them, the scatter of each step's
  // fastener forces to this rank and of the band sums to the joints' ranks.
  struct BypassSide {
    PetscInt                           slot;
    std::array<double, 3>              t1, t2;    // the joint's in-plane axes
    std::vector<std::array<double, 2>> footprint; // its footprint's nodes (t1, t2 from the fastener), on the rank holding them
  };
  struct BypassMember {
    PetscInt                            elem, side; // owned element, position in bypass_sides
    int                                 nn;
    std::array<std::array<double, 2>, 4> p;         // the element's nodes (t1, t2 from the fastener)
  };
  double                    bypass_width = 0, bypass_length = 0;
  double                    bypass_peak = 0; // the largest bearing load so far, over all joints and steps
  std::vector<BypassSide>   bypass_sides;
  std::vector<BypassMember> bypass_members;
  VecScatter                bypass_scatter = nullptr, bypass_force_scatter = nullptr; // the second also for the reach
  Vec                       bypass_sums = nullptr, bypass_local = nullptr, bypass_force = nullptr, bypass_force_local = nullptr;
  Vec                       bypass_reach = nullptr, bypass_reach_local = nullptr; // the footprint's reach ahead and behind
};

// Collective. The map of the assembly's shell output (nothing to write when part_ids is empty).
PetscErrorCode FieldMapCreate(BoltnetAssembly a, FieldMap *m);
PetscErrorCode FieldMapDestroy(FieldMap *m);

// Columns [first, first + bs) of a natural Vec of block size K (from FieldSpaceNatural) as a natural
// Vec of block size bs, also borrowed from s (K == bs: packed itself). Collective only the first
// time a block size is asked for: several datasets of one space travel in one scatter, side by side.
PetscErrorCode FieldSpaceColumns(FieldSpace &s, Vec packed, PetscInt K, PetscInt first, PetscInt bs, Vec *out);

// The Vecs and the scatter of block size bs destroyed (collective, as their creation): for packs
// written once (the mesh), which would otherwise be kept for the whole run.
PetscErrorCode FieldSpaceRelease(FieldSpace &s, PetscInt bs);
// Collective: a natural-order Vec (block size bs, as many rows as the rank owns) holding `owned`
// (bs values per owned item of s, in owned order). Borrowed: it belongs to s and is overwritten by
// the next call with the same block size (kept, so that a step creates no Vec: every creation is
// a collective layout set-up).
PetscErrorCode FieldSpaceNatural(MPI_Comm comm, FieldSpace &s, PetscInt bs, const std::vector<double> &owned, Vec *natural);

// A joint as a line between its attachment points on its two patches.
struct JointLine {
  PetscInt              id;     // user joint id
  PetscInt              state;  // State at the last converged step (what the joint did in it)
  PetscInt              bearing;
  std::array<double, 3> xa, xb; // reference attachment points: a rigid patch's node; on a shell
                                // patch, the point of the bolt axis on the footprint's mid-surface
  std::array<double, 6> ua, ub; // dof of the joint's nodes on patches a and b (global frame)
  std::array<double, 9> R;      // local frame rows (n, t1, t2)
  std::array<double, 6> jump;   // local jump and force (as in joints.csv)
  std::array<double, 6> force;
  std::array<double, 2> slip;
};

// One converged step, in owned order (dof: 6 per owned node; results per owned element, in the
// element frame; lines per owned joint, in the order of the rank's JointSet).
struct StepFields {
  std::vector<double>                dof; // 6 per owned node: ux uy uz rx ry rz
  Vec                                dof_natural = nullptr; // set when computed (borrowed from the map)
  std::vector<shell::SectionResults> results;
  std::vector<JointLine>             lines;
};
// Collective: the last converged point a->X. With results false, no element results. With
// keep_modes, the elements' condensed modes are computed once, kept in m.modes and used from then on
// (the field writer asks for it from its second step: a run of one step would only pay the memory);
// without, every element is integrated afresh.
PetscErrorCode AssemblyStepFields(BoltnetAssembly a, FieldMap &m, bool results, bool keep_modes, StepFields *f);

// The bypass load beside each fastener (docs/output.md, "Bypass"), one row per joint side on a shell
// part, for the joints this rank owns.
struct BypassRow {
  PetscInt joint, side, part, elements; // side 0: patch a, 1: patch b; elements averaged (both bands)
  double   bearing;                     // |in-plane force between the fastener and the sheet| (N)
  double   d[3];                        // the direction the sheet bears on the fastener (global), t1 when it is zero
  double   width, length;               // the bands: w across d, L along it (mm)
  double   n_in, flux, load;            // d.N.d of the loaded band and of the bypass band (N/mm), flux w (N)
  double   balance;                     // (n_+ - n_-) w - bearing (N): the bands' force balance, NaN with one band
};
// Collective. The bands' candidate elements (once: width w, length L in mm) and each step's rows
// from f's results.
PetscErrorCode FieldMapBypassRegions(BoltnetAssembly a, FieldMap &m, double width, double length);
PetscErrorCode AssemblyBypass(BoltnetAssembly a, FieldMap &m, const StepFields &f, std::vector<BypassRow> &rows);

// The material frame of an owned element (the section law's, resultants.hpp).
const shell::ShellMaterial &FieldElementMaterial(BoltnetAssembly a, const FieldElement &e);
// The results at the centroid of a quadrilateral or triangle (u: 6 dof per node, a triangle's in
// the first 18), with the directors and drilling factor of its stiffness.
// `kept`: the element's CondensedModesOf, kept by the caller between steps.
shell::SectionResults ElementResultsOf(const ElementGeometry &g, const shell::ShellMaterial &mat, double drill, const shell::ElementVector &u,
                                       const shell::CondensedModes *kept = nullptr);
// The part of the results' work that does not depend on u (shell::ElementCondensedModes).
shell::CondensedModes CondensedModesOf(const ElementGeometry &g, const shell::ShellMaterial &mat, double drill);
// The element frame's axes e1, e2, e3 (shell::MakeElementFrame) and the element's area.
std::array<shell::Vec3, 3> ElementAxesOf(const ElementGeometry &g);
double                     ElementArea(const ElementGeometry &g);

// --- The gather-to-rank-0 writer, kept to measure against (network/fields_gather.cpp). ---
struct PartField {
  PetscInt                           id;
  std::vector<std::array<double, 3>> x;
  std::vector<std::array<int, 4>>    elems; // a triangle's fourth node: -1
  std::vector<double>                dof; // 6 per node
};
// On rank 0: every shell part and every joint (sorted by id); empty elsewhere.
PetscErrorCode AssemblyGatherFields(BoltnetAssembly a, std::vector<PartField> &parts, std::vector<JointLine> &lines);

} // namespace boltnet
