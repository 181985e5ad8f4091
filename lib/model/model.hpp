// What the user described: parts (rigid bodies and shell parts), fasteners (the joints between
// them) and boundary conditions, in the user's own ids and numbering. Nothing here knows about
// patches, ranks or PETSc objects: lib/patch/layout.hpp turns a model into patches and seams, and
// lib/network puts those on a DMNetwork.
#pragma once

#include "boltnet.h"
#include "joint/law.hpp"
#include "mesh/mesh.hpp"
#include "shell/shell.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace boltnet {

// Patch kinds. A rigid patch is one 6-dof node; a shell patch is a piece of a meshed shell part.
enum class PatchKind : PetscInt { Rigid = 0, Shell = 1 };

struct PartDesc {
  PetscInt              id;   // user id
  PatchKind             kind;
  std::array<double, 3> x;    // rigid: the node; shell: the first mesh node (zero for a part read later)
};

struct ShellPart {
  ShellMesh            mesh; // node sets included
  shell::ShellMaterial material;
  double               drill = shell::kDefaultDrill;
  // A part that only the rank laying it out reads (the scene's plates and Gmsh parts: patch/layout.hpp):
  // until then `mesh` is empty, `read` makes it (on PETSC_COMM_SELF, its errors naming the input) and
  // `size` stands for its size in the assignment of parts to ranks (a plate's nodes, the nodes its
  // Gmsh file declares). Empty `read`: the mesh was given whole (the C API, a Nastran deck).
  std::function<PetscErrorCode(ShellMesh *)> read;
  std::int64_t                               size = 0;
  // A part that rank 0 alone was given (a Nastran deck is read there: io/nastran.cpp): `mesh` is
  // empty on the other ranks and `size` is its node count; rank 0 sends the mesh to the rank that
  // lays the part out (patch/layout_steps.hpp, SendRank0Meshes) and keeps no copy.
  bool on_rank0 = false;
};

struct JointDesc {
  PetscInt              id;             // user id
  PetscInt              part_a, part_b; // user ids of the parts it joins
  std::array<double, 3> x;              // fastener position (where it attaches to shell parts)
  std::array<double, 9> R;              // local frame rows (n, t1, t2)
  Params                params;
  bool                  positioned = false; // x was given: on a rigid patch the joint acts there
  // A lever (AssemblyAddFullSpring): side a attaches at at_a (node coupling: the nearest node), b at
  // at_b, each carrying the joint at x through a rigid lever (docs/joint-laws.md, "Where a joint acts").
  bool                  lever = false;
  std::array<double, 3> at_a{}, at_b{};
  // A footprint named by the user (AssemblySetJointFootprint): on each shell part it joins, the nodes
  // of this node set follow the joint node rigidly, instead of the nodes that -coupling_radius finds:
  // a rigid patch tied to a whole section (an RBE2), e.g. to load a wing box's tip. Empty: found.
  // A fixed array, since joint descriptions travel between ranks as bytes (patch/share.cpp).
  static constexpr size_t kFootprintMax = 48;
  std::array<char, kFootprintMax> footprint{};
};

struct BCDesc {
  PetscInt      patch; // user id of the part
  std::string   set;   // node set of a shell part ("" : every node of the part)
  PetscInt      dof;   // 0..5, or -1 for all six
  BoltnetBCKind kind;
  PetscReal     value; // per unit load factor (fixed: ignored); a force is the set's total
};

struct Model {
  std::vector<PartDesc>         parts;  // in the order described
  std::map<PetscInt, ShellPart> shells; // the shell parts, by position in parts
  std::vector<JointDesc>        joints; // rank 0's are the model's (other ranks: a copy, or none)
  std::vector<BCDesc>           bcs;
  // Position in parts of the part with user id `id`, or -1.
  PetscInt Find(PetscInt id) const
  {
    for (size_t i = 0; i < parts.size(); ++i)
      if (parts[i].id == id) return (PetscInt)i;
    return -1;
  }
};

} // namespace boltnet
