// A Nastran bulk data deck read into plain C++ structs (docs/nastran.md). Pure C++: no PETSc, no
// global state; ReadDeck throws nastran::Error naming the file, the line and the field.
//
// What a later step needs to build boltnet patches and joints is here, resolved and checked:
// grid positions in the basic system and each grid's displacement axes (CD), shell elements with
// grid indices, their sections (section.hpp), bushes and fasteners with their element axes, rigid
// elements, and per subcase the constraints and loads (expand.hpp). Cards that boltnet does not use
// are counted in Deck::unused, never dropped silently.
#pragma once

#include <array>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace boltnet::nastran {

using Vec3 = std::array<double, 3>;
using Axes = std::array<Vec3, 3>; // rows: unit vectors of directions 1, 2, 3 in the basic system

// Where a card was read: Deck::files[file], 1-based line; card: its place among the deck's bulk
// data cards in reading order (0-based).
struct Source {
  int file = -1;
  int line = 0;
  int card = -1;
};

// Every error of the reader: a message naming file, line, card and field. file, line and field
// (1-based field number on that line, 0 when the error is not about one field) are kept apart for
// callers and tests.
class Error : public std::runtime_error {
public:
  Error(const std::string &message, std::string file_, int line_, std::string card_, int field_)
    : std::runtime_error(message), file(std::move(file_)), line(line_), card(std::move(card_)), field(field_) {}
  std::string file;
  int         line;
  std::string card;
  int         field;
};

// Degree-of-freedom sets ("123456") as bit masks: bit i is component i + 1.
using DofSet = unsigned;
std::string DofString(DofSet dofs); // "1246"

enum class CoordKind { Rectangular, Cylindrical, Spherical };

// CORD2R, CORD2C, CORD2S: points A (origin), B (on the z axis), C (in the xz plane) given in the
// system RID. origin/axes are resolved in the basic system (system 0 is the basic system itself).
struct CoordSystem {
  int       id = 0;
  CoordKind kind = CoordKind::Rectangular;
  int       rid = 0;
  Vec3      a{}, b{}, c{};
  Source    src;
  Vec3      origin{};                      // resolved
  Axes      axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}; // resolved
};
// Coordinates (x1, x2, x3) of a point in the system (cylindrical: R, theta deg, z; spherical: R,
// theta deg from the z axis, phi deg about it) to the basic system.
Vec3 ToBasic(const CoordSystem &cs, const Vec3 &x);
// The unit directions of components 1, 2, 3 of the system at a point given in the basic system
// (cylindrical: r, theta, z; spherical: r, theta, phi). Throws std::domain_error where they are
// undefined (on the axis of a cylindrical or spherical system).
Axes DirectionsAt(const CoordSystem &cs, const Vec3 &basic_point);

struct Grid {
  int    id = 0;
  int    cp = 0;    // system of the input position
  Vec3   input{};   // position as written (in CP)
  int    cd = 0;    // displacement system: SPC dof, FORCE/MOMENT with CID = CD, results
  DofSet ps = 0;    // permanent single-point constraints (in CD)
  Source src;
  Vec3   x{};       // resolved: position in the basic system
  Axes   cd_axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}; // resolved: CD directions at the grid, basic
};

enum class ShellKind { Quad4, Tria3 };

// CQUAD4 and CTRIA3. node[] are indices into Deck::grids (node[3] = -1 for a triangle).
struct Shell {
  int                   id = 0;
  ShellKind             kind = ShellKind::Quad4;
  int                   pid = 0;     // PSHELL or PCOMP
  std::array<int, 4>    grid{};      // grid ids as written
  std::array<int, 4>    node{-1, -1, -1, -1};
  int                   mcid = -1;   // material system (>= 0 when given instead of THETA)
  double                theta = 0;   // material angle, degrees from the G1-G2 side (when mcid < 0)
  double                zoffs = 0;   // offset of the reference plane from the grids along the normal
  int                   tflag = 0;   // 0: t are thicknesses, 1: fractions of the property's T
  std::array<double, 4> t{};         // corner thicknesses; NaN = blank (the property's T)
  Source                src;
  int Nodes() const { return kind == ShellKind::Quad4 ? 4 : 3; }
};

// PSHELL. Blank material ids are 0; mid2 = -1 is Nastran's plane strain.
struct PShell {
  int    id = 0;
  int    mid1 = 0, mid2 = 0, mid3 = 0, mid4 = 0;
  double t = 0;            // NaN = blank (elements must give their thickness)
  double bending = 1.0;    // 12I/T^3
  double shear = 0.833333; // TS/T
  double nsm = 0;
  double z1 = 0, z2 = 0;   // fibre distances for stress recovery (default -T/2, T/2)
  Source src;
};

enum class Lam { Blank, Sym, Mem, Bend, Smear, Smcore };
struct Ply {
  int    mid = 0;
  double t = 0;
  double theta = 0; // degrees
  bool   sout = false;
};
// PCOMP: plies as listed (blank MID/T repeat the previous ply's, resolved here).
struct PComp {
  int               id = 0;
  double            z0 = 0;     // distance from the reference plane to the bottom surface
  bool              z0_given = false;
  double            nsm = 0, sb = 0, tref = 0, ge = 0;
  std::string       ft;         // failure theory (HILL, HOFF, TSAI, STRN or blank)
  Lam               lam = Lam::Blank;
  std::vector<Ply>  plies;
  Source            src;
  std::vector<Ply>  Stack() const;     // bottom to top, SYM mirrored
  double            Thickness() const; // of the full stack
};

// MAT1 after Nastran's rule for E, G, NU when one or two are blank (docs/nastran.md).
struct Mat1 {
  int    id = 0;
  double e = 0, g = 0, nu = 0;
  double rho = 0, a = 0, tref = 0, ge = 0;
  Source src;
};

// MAT8: g1z/g2z = 0 when blank (Nastran: rigid in transverse shear).
struct Mat8 {
  int    id = 0;
  double e1 = 0, e2 = 0, nu12 = 0, g12 = 0, g1z = 0, g2z = 0, rho = 0;
  double a1 = 0, a2 = 0, tref = 0;
  Source src;
};

// PBUSH: the K line (stiffness in the element axes: 1-3 forces, 4-6 moments); B, GE, RCV and other
// lines are recorded as read but unused in statics.
struct PBush {
  int                   id = 0;
  std::array<double, 6> k{};
  std::array<bool, 6>   k_given{};
  Source                src;
};

// CBUSH. gb = 0: grounded. axes: the element axes in the basic system, resolved with Nastran's
// rules (CID; else x from GA to GB with the orientation vector GO or X in the xy plane).
struct Bush {
  int    id = 0, pid = 0;
  int    ga = 0, gb = 0;
  int    na = -1, nb = -1;   // grid indices (nb = -1 when grounded)
  int    go = 0;             // orientation grid (0: none)
  Vec3   x{};                // orientation vector in GA's displacement system
  bool   has_x = false;
  int    cid = -1;           // element system (-1: blank)
  double s = 0.5;            // spring location from GA (fraction of the length)
  int    ocid = -1;
  Vec3   offset{};           // S1, S2, S3 in OCID (when ocid >= 0)
  Source src;
  Axes   axes{};             // resolved
  bool   axial_only = false; // x from GA to GB only: valid with K1/K4 only (Nastran)
  double length = 0;         // resolved |GB - GA|
};

// PFAST and CFAST: a fastener between two patches (TYPE PROP: property ids; ELEM: element ids),
// located by grid GS or the point XS (basic); GA, GB optional.
struct PFast {
  int                   id = 0;
  double                d = 0;
  int                   mcid = -1;
  int                   mflag = 0;
  std::array<double, 6> k{}; // KT1 KT2 KT3 KR1 KR2 KR3
  double                mass = 0, ge = 0;
  Source                src;
};
struct Fast {
  int    id = 0, pid = 0;
  bool   by_element = false; // TYPE ELEM (else PROP)
  int    ida = 0, idb = 0;
  int    gs = 0, ga = 0, gb = 0;
  Vec3   xs{};
  Source src;
  Vec3   position{};         // resolved: GS or XS, basic
};

// RBE2: GM follow GN rigidly in the components CM.
struct Rbe2 {
  int              id = 0, gn = 0;
  DofSet           cm = 0;
  std::vector<int> gm;
  double           alpha = 0;
  Source           src;
};
// RBE3: REFGRID's motion is the weighted average of the groups' grids.
struct Rbe3 {
  struct Group {
    double           weight = 0;
    DofSet           c = 0;
    std::vector<int> grids;
  };
  int                              id = 0, refgrid = 0;
  DofSet                           refc = 0;
  std::vector<Group>               groups;
  std::vector<std::pair<int, DofSet>> um; // UM grids and components
  double                           alpha = 0;
  Source                           src;
};

// CONM2: read and checked (its grid), reported as not used in statics.
struct Conm2 {
  int                   id = 0, g = 0, cid = 0;
  double                m = 0;
  Vec3                  x{};
  std::array<double, 6> i{};
  Source                src;
};

// SPC and SPC1, one record per grid (SPC1 THRU ranges expanded).
struct Spc {
  int    sid = 0, grid = 0;
  DofSet dofs = 0;
  double value = 0; // enforced displacement (SPC only)
  Source src;
};
struct SpcAdd {
  int              sid = 0;
  std::vector<int> sets;
  Source           src;
};

// FORCE and MOMENT: scale * n in system CID (0: basic; directions taken at the grid).
struct PointLoad {
  bool   moment = false;
  int    sid = 0, grid = 0, cid = 0;
  double scale = 0;
  Vec3   n{};
  Source src;
  Vec3   basic{}; // resolved: scale * n in the basic system
};

// LOAD: scale * sum(scales[i] * set sets[i]).
struct LoadCombination {
  int                 sid = 0;
  double              scale = 0;
  std::vector<double> scales;
  std::vector<int>    sets;
  Source              src;
};

// PLOAD4 on one shell (the THRU form gives one record per element). p: corner pressures (blank
// P2..P4 = P1). Positive along the element normal (G1, G2, G3 right-handed) unless a direction
// (CID, N) is given.
struct Pressure {
  int                   sid = 0, element = 0;
  int                   shell = -1; // index into Deck::shells
  std::array<double, 4> p{};
  bool                  has_direction = false;
  int                   cid = 0;
  Vec3                  n{};
  Source                src;
};

// Case control: values before the first SUBCASE are the defaults of every subcase. Without any
// SUBCASE there is one subcase, id 1.
struct Subcase {
  int         id = 1;
  std::string title, subtitle, label;
  int         load = 0, spc = 0; // 0: none
  Source      src, load_src, spc_src; // the SUBCASE line, and where LOAD = and SPC = were set
};

// A card (or case control command) that boltnet does not use: how many, where the first was,
// and details (PARAM names, the unused lines of PBUSH, ...).
struct Unused {
  int                   count = 0;
  Source                first;
  std::set<std::string> details;
};

struct Deck {
  std::vector<std::string> files;  // the main file first, then INCLUDEd files as read
  std::string              sol;    // executive control SOL, as written ("101", "SESTATIC"), or ""
  std::vector<Subcase>     subcases;

  std::vector<CoordSystem>     coords;
  std::vector<Grid>            grids;
  std::vector<Shell>           shells;
  std::vector<PShell>          pshells;
  std::vector<PComp>           pcomps;
  std::vector<Mat1>            mat1s;
  std::vector<Mat8>            mat8s;
  std::vector<PBush>           pbushes;
  std::vector<Bush>            bushes;
  std::vector<PFast>           pfasts;
  std::vector<Fast>            fasts;
  std::vector<Rbe2>            rbe2s;
  std::vector<Rbe3>            rbe3s;
  std::vector<Conm2>           conm2s;
  std::vector<Spc>             spcs;
  std::vector<SpcAdd>          spcadds;
  std::vector<PointLoad>       point_loads;
  std::vector<LoadCombination> load_combinations;
  std::vector<Pressure>        pressures;

  std::map<std::string, int>    used;         // cards read into the structs above: name -> count
  std::map<std::string, Unused> unused;       // bulk data cards not used
  std::map<std::string, Unused> unused_case;  // case control commands not used
  std::vector<std::string>      notes;        // what the reader assumed or skipped, with where

  // Id -> index lookups (filled by ReadDeck).
  std::unordered_map<int, int> grid_index, coord_index, shell_index, pshell_index, pcomp_index,
    mat1_index, mat8_index, pbush_index, pfast_index;

  int         GridIndex(int id) const { return Find(grid_index, id); }
  int         ShellIndex(int id) const { return Find(shell_index, id); }
  std::string Where(const Source &s) const; // "file:line"
  static int  Find(const std::unordered_map<int, int> &m, int id)
  {
    auto it = m.find(id);
    return it == m.end() ? -1 : it->second;
  }
};

struct ReadOptions {
  // Shells whose PID is neither a PSHELL nor a PCOMP are kept (with a note) instead of stopping the
  // read: for meshes whose properties come from elsewhere (TACS assigns them in Python).
  bool allow_missing_properties = false;
};

// Reads a deck: executive control (SOL kept), case control (SUBCASE, LOAD, SPC, TITLE, SUBTITLE,
// LABEL), BEGIN BULK ... ENDDATA, with INCLUDE anywhere (relative to the including file). A file
// with neither CEND nor BEGIN BULK is bulk data only. Throws nastran::Error.
Deck ReadDeck(const std::string &path, const ReadOptions &options = {});

} // namespace boltnet::nastran
