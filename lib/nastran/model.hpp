// A deck and one of its subcases turned into what boltnet's model describes (docs/nastran.md,
// "From a deck to a model"): one shell part per shell property, joints from CBUSH and CFAST,
// fixed dofs from SPC/SPC1/GRID PS and nodal loads from FORCE, MOMENT and PLOAD4 (loads on an RBE3's
// REFGRID moved to its independent grids). Pure C++: no PETSc; throws nastran::Error naming the
// card (or the subcase) for what boltnet cannot represent.
// lib/io/nastran.cpp puts the result into an assembly.
#pragma once

#include "mesh/mesh.hpp"
#include "nastran/deck.hpp"
#include "nastran/expand.hpp"
#include "shell/shell.hpp"

#include <string>
#include <vector>

namespace boltnet::nastran {

// Ids of what the model adds to the deck's own: a grid on no shell that a CBUSH or an RBE2 names
// becomes a rigid part (a 6-dof node) with id kRigidPartBase + the grid id; a tie (below) is a joint
// with id kTieJointBase + 1, 2, ... (Nastran ids are at most 99999999).
constexpr int kRigidPartBase = 100000000;
constexpr int kTieJointBase  = 100000000;

// A shell part: the elements of one PSHELL or PCOMP (grids[i] is the deck grid index of mesh node
// i), or a rigid part at one grid (grids = {that grid}, mesh empty).
struct ModelPart {
  int                  pid = 0; // the property id, or kRigidPartBase + the grid id
  bool                 rigid = false;
  Vec3                 x{};     // a rigid part's node
  ShellMesh            mesh;
  shell::ShellMaterial material;
  std::vector<int>     grids;
};

// A CBUSH or CFAST between two parts (positions in DeckModel::parts), or a tie. A bush's stiffness
// is its PBUSH/PFAST's K = sum K_i a_i a_i^T over its element axes a_i, rotated into the joint frame
// (n, t1, t2 = n x t1) and kept whole (`K`, 6 x 6 row major: translations then rotations); a tie
// is boltnet's isotropic spring (kn, kt, kr).
struct ModelJoint {
  int    eid = 0, pid = 0; // pid 0: a tie
  bool   fast = false;     // CFAST (else CBUSH or a tie)
  int    part_a = -1, part_b = -1;
  Vec3   x{}, n{}, t1{};   // x: where the spring acts (a CBUSH's point S of GA-GB)
  double kn = 0, kt = 0, kr = 0;  // a tie's spring
  bool   full = false;            // a bush: K below
  std::array<double, 36> K{};
  // A CBUSH whose grids differ: each side attaches at its grid (at_a = GA, at_b = GB) and carries
  // the spring at x through a rigid lever, as Nastran's CBUSH does (ModelOptions::bush_offsets).
  bool   lever = false;
  Vec3   at_a{}, at_b{};
};

enum class ModelBCKind { Fixed, Displacement, Force };
// A condition on one dof (0..5, basic axes) of a node set of a part: value is the set's total force
// (Force) or the enforced displacement (Displacement); nodes are mesh node indices (a rigid part:
// set "" and no nodes).
struct ModelBC {
  int              part = -1;
  std::string      set;
  std::vector<int> nodes;
  int              dof = 0;
  ModelBCKind      kind = ModelBCKind::Fixed;
  double           value = 0;
};

struct DeckModel {
  int                     subcase = 1;
  std::vector<ModelPart>  parts;  // by increasing property id
  std::vector<ModelJoint> joints; // CBUSH then CFAST, each by increasing element id
  std::vector<ModelBC>    bcs;
  std::vector<std::string> notes; // what the model assumed (stiffness averaged, grids skipped, ...)
};

// The subcase with id `id` (throws naming the ids the deck has).
const Subcase &FindSubcase(const Deck &deck, int id);

// Ties stand for what Nastran makes rigid and boltnet's model cannot: a grid shared by the shells
// of two properties (each part has its own node there, tied to the first part's), and an RBE2
// (its GN a rigid part, tied to each GM grid). A tie is a spring joint with kn = kt = penalty x
// the largest membrane stiffness A11 of the deck's shell parts and kr = penalty x their largest D11.
// bush_offsets: a CBUSH's spring acts at S of GA-GB (Nastran's offset, OCID = -1), each grid
// carrying it through a rigid lever (a shear F then loads GA and GB with the moments of F about
// them); false: at the midpoint, each part loaded at its grid without lever (a scene's node-coupled
// joint).
struct ModelOptions {
  double tie_penalty = 1000;
  bool   bush_offsets = true;
};

// The model of subcase `subcase`. An RBE3 whose REFGRID nothing else connects moves the loads on
// REFGRID to its independent grids (rbe3.hpp). Throws nastran::Error for what boltnet does not model
// (an RBE3 whose REFGRID is connected to anything else, an RBE2 with CM other than 123456 or GN on a
// shell, grounded CBUSH), a fastener grid on no shell.
DeckModel ModelOf(const Deck &deck, int subcase, const ModelOptions &options = {});

// PLOAD4 pressures as consistent nodal forces (2 x 2 Gauss points on the bilinear quadrilateral,
// 3 midside points on the triangle: exact for the load's resultant and moment), summed per grid
// into `nodal` (sorted by grid index on return).
void PressuresToNodal(const Deck &deck, const std::vector<ShellPressure> &pressures, std::vector<NodalLoad> &nodal);

} // namespace boltnet::nastran
