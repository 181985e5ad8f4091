// A deck's subcase as boltnet's model (model.hpp; docs/nastran.md, "From a deck to a model").
#include "nastran/model.hpp"
#include "nastran/rbe3.hpp"
#include "nastran/section.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace boltnet::nastran {

namespace {

Vec3   Cross(const Vec3 &a, const Vec3 &b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double Dot(const Vec3 &a, const Vec3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3   Sub(const Vec3 &a, const Vec3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3   Unit(const Vec3 &a)
{
  const double n = std::sqrt(Dot(a, a));
  return n > 0 ? Vec3{a[0] / n, a[1] / n, a[2] / n} : Vec3{0, 0, 0};
}
// A unit vector normal to the unit vector n (n x X, or n x Y where n is nearly X).
Vec3 NormalTo(const Vec3 &n) { return Unit(Cross(n, std::fabs(n[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0})); }

std::string Num(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

[[noreturn]] void Fail(const Deck &d, const Source &at, const std::string &card, const std::string &what)
{
  throw Error(d.Where(at) + ": " + what, at.file >= 0 ? d.files[at.file] : "", at.line, card, 0);
}

// The unit normal of a shell element (G1, G2, G3 right-handed; a quadrilateral's from its diagonals).
Vec3 ElementNormal(const Deck &d, const Shell &e)
{
  const auto X = [&](int i) { return d.grids[e.node[i]].x; };
  if (e.kind == ShellKind::Quad4) return Unit(Cross(Sub(X(2), X(0)), Sub(X(3), X(1))));
  return Unit(Cross(Sub(X(1), X(0)), Sub(X(2), X(0))));
}

// A bush's stiffness in a joint frame (n, t1, t2 = n x t1): K = sum k_i a_i a_i^T over its element
// axes a_i (k 1-3 translations, 4-6 rotations, Nastran's K1-K6), K_frame = E K E^T with E the
// frame's rows, per 3 x 3 block; nothing averaged or dropped (docs/nastran.md, "From a deck to a model").
std::array<double, 36> FrameStiffness(const Axes &axes, const std::array<double, 6> &k, const Vec3 &n, const Vec3 &t1)
{
  const Vec3             e[3] = {n, t1, Cross(n, t1)};
  std::array<double, 36> K{};
  for (int b = 0; b < 2; ++b)
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) { // the upper triangle, mirrored: symmetric to the bit
        double s = 0;
        for (int m = 0; m < 3; ++m) s += k[3 * b + m] * Dot(axes[m], e[i]) * Dot(axes[m], e[j]);
        K[6 * (3 * b + i) + 3 * b + j] = K[6 * (3 * b + j) + 3 * b + i] = s;
      }
  return K;
}

// A joint frame: n the shell normal at the grid (mean of the normals of part `part`'s elements on
// it), t1 the element axis most nearly in the plane (projected), else any in-plane direction.
void Frame(const Vec3 &normal, const Axes &axes, Vec3 &n, Vec3 &t1)
{
  n = normal;
  int best = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(Dot(axes[i], n)) < std::fabs(Dot(axes[best], n))) best = i;
  Vec3 t = axes[best];
  const double d = Dot(t, n);
  t1 = Unit({t[0] - d * n[0], t[1] - d * n[1], t[2] - d * n[2]});
  if (Dot(t1, t1) < 0.5) t1 = NormalTo(n);
}

} // namespace

const Subcase &FindSubcase(const Deck &d, int id)
{
  std::string ids;
  for (const Subcase &s : d.subcases) {
    if (s.id == id) return s;
    ids += (ids.empty() ? "" : ", ") + std::to_string(s.id);
  }
  throw Error((d.files.empty() ? std::string("deck") : d.files[0]) + ": no subcase " + std::to_string(id) + " (the deck has subcase(s) " + ids + ")", d.files.empty() ? "" : d.files[0], 0, "SUBCASE", 0);
}

void PressuresToNodal(const Deck &d, const std::vector<ShellPressure> &pressures, std::vector<NodalLoad> &nodal)
{
  std::map<int, NodalLoad> by;
  for (NodalLoad &l : nodal) by[l.node] = l;
  for (const ShellPressure &s : pressures) {
    const Shell &e = d.shells[s.shell];
    std::array<Vec3, 4> X{};
    for (int i = 0; i < e.Nodes(); ++i) X[i] = d.grids[e.node[i]].x;
    // f dA = p (X_xi x X_eta) dxi deta, or p |X_xi x X_eta| along a given direction; node i gets N_i f dA.
    const auto at = [&](const std::array<double, 4> &N, const Vec3 &dxi, const Vec3 &deta, double w) {
      Vec3   a = Cross(dxi, deta);
      double p = 0;
      for (int i = 0; i < e.Nodes(); ++i) p += N[i] * s.p[i];
      if (s.has_direction) {
        const double area = std::sqrt(Dot(a, a));
        a = {s.direction[0] * area, s.direction[1] * area, s.direction[2] * area};
      }
      for (int i = 0; i < e.Nodes(); ++i) {
        NodalLoad &l = by[e.node[i]];
        l.node = e.node[i];
        for (int j = 0; j < 3; ++j) l.force[j] += w * N[i] * p * a[j];
      }
    };
    if (e.kind == ShellKind::Quad4) {
      const double g = 1 / std::sqrt(3.0);
      for (double xi : {-g, g})
        for (double eta : {-g, g}) {
          const std::array<double, 4> N{(1 - xi) * (1 - eta) / 4, (1 + xi) * (1 - eta) / 4, (1 + xi) * (1 + eta) / 4, (1 - xi) * (1 + eta) / 4};
          const double dNxi[4] = {-(1 - eta) / 4, (1 - eta) / 4, (1 + eta) / 4, -(1 + eta) / 4};
          const double dNeta[4] = {-(1 - xi) / 4, -(1 + xi) / 4, (1 + xi) / 4, (1 - xi) / 4};
          Vec3 dxi{}, deta{};
          for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 3; ++j) dxi[j] += dNxi[i] * X[i][j], deta[j] += dNeta[i] * X[i][j];
          at(N, dxi, deta, 1.0);
        }
    } else {
      const Vec3 e1 = Sub(X[1], X[0]), e2 = Sub(X[2], X[0]);
      for (const std::array<double, 4> &N : {std::array<double, 4>{.5, .5, 0, 0}, {0, .5, .5, 0}, {.5, 0, .5, 0}}) at(N, e1, e2, 1.0 / 6);
    }
  }
  nodal.clear();
  for (auto &[node, l] : by) nodal.push_back(l);
}

// ModelOf's steps, in the order of the data path: shell parts, rigid parts, joints (CBUSH, CFAST,
// ties), supports, loads. Each step reads the deck and what the steps before it built; the order
// is also the order in which bad input is found, so that a deck with several faults always names
// the same one.
namespace {

using ShellsByPid = std::map<int, std::vector<int>>; // property id -> its shells' indices

// Where each deck grid (by index) lies: owner is the first part that has it (-1: none), copies the
// other shell parts that have it (a grid shared by the shells of several properties: each part has
// its own node there, tied to the owner's by Ties).
struct GridParts {
  std::vector<int>              owner;
  std::vector<std::vector<int>> copies;
};

template <class T>
void Append(std::vector<T> &to, const std::vector<T> &from) { to.insert(to.end(), from.begin(), from.end()); }

// The shells of each property, by increasing property id: one shell part each.
ShellsByPid ShellsByProperty(const Deck &d)
{
  ShellsByPid by_pid;
  for (size_t s = 0; s < d.shells.size(); ++s) by_pid[d.shells[s].pid].push_back((int)s);
  return by_pid;
}

// Whether property pid's section depends on the material axes (a PCOMP, or a PSHELL with a MAT8).
bool Oriented(const Deck &d, int pid)
{
  if (d.pcomp_index.count(pid)) return true;
  if (!d.pshell_index.count(pid)) return false;
  const PShell &ps = d.pshells[d.pshell_index.at(pid)];
  bool oriented = false;
  for (int mid : {ps.mid1, ps.mid2, ps.mid3})
    if (d.mat8_index.count(mid)) oriented = true;
  return oriented;
}

// A shell element's material axis: its MCID system's x (rectangular systems only), G1-G2 turned
// by THETA about the normal nrm (MCID blank), or the basic x (MCID 0).
Vec3 MaterialAxis(const Deck &d, const Shell &e, const Vec3 &nrm, const std::string &card, const std::string &what)
{
  Vec3 ax{1, 0, 0};
  if (e.mcid > 0) {
    const CoordSystem &cs = d.coords[d.coord_index.at(e.mcid)];
    if (cs.kind != CoordKind::Rectangular) Fail(d, e.src, card, what + ": MCID " + std::to_string(e.mcid) + " is curvilinear: not supported for an orthotropic section");
    ax = cs.axes[0];
  } else if (e.mcid < 0) {
    const Vec3   g12 = Unit(Sub(d.grids[e.node[1]].x, d.grids[e.node[0]].x)), o = Cross(nrm, g12);
    const double th = e.theta * M_PI / 180;
    for (int j = 0; j < 3; ++j) ax[j] = std::cos(th) * g12[j] + std::sin(th) * o[j];
  }
  return ax;
}

// The material direction of the part of property pid (its first shell's material axis; the basic
// x if the section has no axes), once every shell of it is checked to have the first one's section:
// boltnet gives a part one thickness, one reference plane and one projected direction.
Vec3 PartDirection(const Deck &d, int pid, const std::vector<int> &shells)
{
  const Shell &first = d.shells[shells[0]];
  const bool   oriented = Oriented(d, pid);
  Vec3         direction{1, 0, 0};
  for (size_t k = 0; k < shells.size(); ++k) {
    const Shell &e = d.shells[shells[k]];
    const std::string card = e.kind == ShellKind::Quad4 ? "CQUAD4" : "CTRIA3", what = card + " " + std::to_string(e.id);
    const std::string same = " (same property " + std::to_string(pid) + " as element " + std::to_string(first.id) + ")";
    for (int i = 0; i < e.Nodes(); ++i) {
      const double t0 = first.t[0], ti = e.t[i];
      if ((std::isnan(t0) != std::isnan(ti)) || (!std::isnan(ti) && ti != t0) || e.tflag != first.tflag)
        Fail(d, e.src, card, what + ": its corner thicknesses differ from those of element " + std::to_string(first.id) + same + ": a boltnet part has one section");
    }
    if (e.zoffs != first.zoffs) Fail(d, e.src, card, what + ": ZOFFS " + Num(e.zoffs) + " differs from " + Num(first.zoffs) + same + ": a boltnet part has one reference plane");
    if (!oriented) continue;
    // boltnet projects one reference direction on every element (shell::ShellMaterial): the
    // element's material axis (MCID's x projected, or G1-G2 turned by THETA) must be that.
    const Vec3 nrm = ElementNormal(d, e);
    const Vec3 ax = MaterialAxis(d, e, nrm, card, what);
    if (k == 0) direction = ax;
    const auto in_plane = [&](const Vec3 &v) {
      const double dn = Dot(v, nrm);
      return Unit({v[0] - dn * nrm[0], v[1] - dn * nrm[1], v[2] - dn * nrm[2]});
    };
    const double c = Dot(in_plane(direction), in_plane(ax));
    if (c < std::cos(M_PI / 180))
      Fail(d, e.src, card, what + ": its material axis is " + Num(std::acos(std::max(-1.0, std::min(1.0, c))) * 180 / M_PI) + " degrees from the direction of element " + std::to_string(first.id) + " projected on it" + same + ": boltnet projects one direction per part (use MCID with one rectangular system)");
  }
  return direction;
}

// Part number `part`'s mesh from its shells: nodes in the order the shells first name their grids
// (p.grids[i] the grid of node i), one element per shell; gp records the part on each grid.
void AddShellMesh(const Deck &d, const std::vector<int> &shells, int part, ModelPart &p, GridParts &gp)
{
  std::map<int, int> local; // grid index -> node
  for (int s : shells) {
    const Shell &e = d.shells[s];
    MeshElement  q{-1, -1, -1, -1};
    for (int i = 0; i < e.Nodes(); ++i) {
      const int g = e.node[i];
      auto      it = local.find(g);
      if (it == local.end()) {
        it = local.emplace(g, (int)p.grids.size()).first;
        p.grids.push_back(g);
        p.mesh.x.push_back(d.grids[g].x);
        if (gp.owner[g] < 0) gp.owner[g] = part;
        else gp.copies[g].push_back(part);
      }
      q[i] = it->second;
    }
    p.mesh.elems.push_back(q);
  }
}

// The shell parts, one per property by increasing id: mesh, section (SectionOf; its assumptions
// go to notes) at the shells' offset, material direction.
std::vector<ModelPart> ShellParts(const Deck &d, const ShellsByPid &by_pid, GridParts &gp, std::vector<std::string> &notes)
{
  std::vector<ModelPart> parts;
  for (const auto &[pid, shells] : by_pid) {
    ModelPart p;
    p.pid = pid;
    const Vec3 direction = PartDirection(d, pid, shells);
    AddShellMesh(d, shells, (int)parts.size(), p, gp);
    const Shell &first = d.shells[shells[0]];
    const double t = first.t[0];
    if (first.tflag != 0 && !std::isnan(t)) Fail(d, first.src, "CQUAD4", "element " + std::to_string(first.id) + ": TFLAG 1 (relative corner thicknesses) is not supported");
    p.material = SectionOf(d, pid, t, notes);
    if (first.zoffs != 0) p.material = Offset(p.material, -first.zoffs);
    p.material.direction = direction;
    parts.push_back(std::move(p));
  }
  return parts;
}

// Rigid parts (appended to parts): the grids on no shell that are an RBE2's GN, or that a CBUSH
// joins and the subcase constrains (a grounding spring, as in Femap's decks). Any other CBUSH grid
// on no shell is an error.
void AddRigidParts(const Deck &d, const Subcase &sc, const std::vector<Constraint> &spc, std::vector<ModelPart> &parts, GridParts &gp)
{
  std::vector<bool> constrained(d.grids.size(), false);
  for (const Constraint &c : spc) constrained[c.node] = true;
  const auto rigid = [&](int g) {
    if (gp.owner[g] >= 0) return;
    ModelPart p;
    p.pid = kRigidPartBase + d.grids[g].id, p.rigid = true, p.x = d.grids[g].x, p.grids = {g};
    gp.owner[g] = (int)parts.size();
    parts.push_back(std::move(p));
  };
  for (const Rbe2 &r : d.rbe2s) {
    const int gn = d.GridIndex(r.gn);
    if (gp.owner[gn] >= 0) Fail(d, r.src, "RBE2", "RBE2 " + std::to_string(r.id) + ": GN = grid " + std::to_string(r.gn) + " is on a shell: boltnet makes an RBE2 a rigid part at GN tied to its GM grids, so GN must be a grid of no shell");
    if (r.cm != 0b111111u) Fail(d, r.src, "RBE2", "RBE2 " + std::to_string(r.id) + ": CM = " + DofString(r.cm) + ": boltnet ties all six components (CM = 123456)");
    rigid(gn);
  }
  for (const Bush &b : d.bushes) {
    if (b.nb < 0) Fail(d, b.src, "CBUSH", "CBUSH " + std::to_string(b.id) + ": grounded (GB blank): boltnet joins two parts; give GB a grid and fix it with SPC");
    for (const auto &[g, field] : {std::pair<int, const char *>{b.na, "GA"}, {b.nb, "GB"}}) {
      if (gp.owner[g] < 0 && constrained[g]) rigid(g);
      if (gp.owner[g] < 0)
        Fail(d, b.src, "CBUSH", "CBUSH " + std::to_string(b.id) + ": " + field + " = grid " + std::to_string(d.grids[g].id) + " is on no shell element (CQUAD4/CTRIA3), is no RBE2's GN and has no SPC in subcase " + std::to_string(sc.id) + ": a boltnet joint attaches to shell parts or to rigid parts (docs/nastran.md)");
    }
  }
}

// Refuses an RBE3 with an independent grid on no part: its loads would reach nothing.
void CheckRbe3Grids(const Deck &d, const GridParts &gp)
{
  for (const Rbe3 &e : d.rbe3s)
    for (const Rbe3::Group &grp : e.groups)
      for (int gid : grp.grids)
        if (gp.owner[d.GridIndex(gid)] < 0)
          Fail(d, e.src, "RBE3", "RBE3 " + std::to_string(e.id) + ": independent grid " + std::to_string(gid) + " is on no shell element and no rigid part: boltnet moves the RBE3's loads to parts");
}

// The node of grid g in part p (p.grids.size() if it has none).
int LocalNode(const ModelPart &p, int g) { return (int)(std::find(p.grids.begin(), p.grids.end(), g) - p.grids.begin()); }

// The shell normal of a shell part at its grid g: the mean of the normals of the part's elements on g.
Vec3 NormalAt(const Deck &d, const ShellsByPid &by_pid, const ModelPart &p, int g)
{
  Vec3 n{};
  for (int s : by_pid.at(p.pid)) {
    const Shell &e = d.shells[s];
    if (std::find(e.node.begin(), e.node.begin() + e.Nodes(), g) == e.node.begin() + e.Nodes()) continue;
    const Vec3 en = ElementNormal(d, e);
    for (int j = 0; j < 3; ++j) n[j] += en[j];
  }
  return Unit(n);
}

// A CBUSH's joint between the parts of GA and GB: its spring acts at the point S of GA-GB
// (Nastran's offset; the midpoint without bush_offsets), each grid carrying it by a rigid lever;
// n is the shell normal at GA (at GB if GA is a rigid part; the element x axis between two rigid
// parts); K the PBUSH's, whole, in that frame.
ModelJoint BushJoint(const Deck &d, const Bush &b, const std::vector<ModelPart> &parts, const ShellsByPid &by_pid, const GridParts &gp, const ModelOptions &options)
{
  const std::string what = "CBUSH " + std::to_string(b.id);
  if (gp.owner[b.na] == gp.owner[b.nb]) Fail(d, b.src, "CBUSH", what + ": GA and GB (grids " + std::to_string(b.ga) + ", " + std::to_string(b.gb) + ") are both on shells of property " + std::to_string(parts[gp.owner[b.na]].pid) + ": a boltnet joint joins two different parts");
  // OCID >= 0 places the spring at S1-S3 in that system: not modelled (refused, never dropped).
  if (b.ocid >= 0 && options.bush_offsets)
    Fail(d, b.src, "CBUSH", what + ", field OCID = " + std::to_string(b.ocid) + " (S1-S3 " + Num(b.offset[0]) + ", " + Num(b.offset[1]) + ", " + Num(b.offset[2]) +
                                "): a spring offset in a coordinate system is not supported; boltnet places the spring at S of GA-GB (OCID = -1, docs/nastran.md)");
  ModelJoint j;
  j.eid = b.id, j.pid = b.pid, j.part_a = gp.owner[b.na], j.part_b = gp.owner[b.nb];
  const Vec3   xa = d.grids[b.na].x, xb = d.grids[b.nb].x;
  const double s  = options.bush_offsets ? b.s : 0.5;
  for (int k = 0; k < 3; ++k) j.x[k] = xa[k] + s * (xb[k] - xa[k]);
  j.lever = options.bush_offsets && b.length > 0, j.at_a = xa, j.at_b = xb;
  const ModelPart &pa = parts[j.part_a], &pb = parts[j.part_b];
  const Vec3       n = !pa.rigid ? NormalAt(d, by_pid, pa, b.na) : !pb.rigid ? NormalAt(d, by_pid, pb, b.nb) : b.axes[0];
  Frame(n, b.axes, j.n, j.t1);
  const PBush &prop = d.pbushes[d.pbush_index.at(b.pid)];
  j.full = true, j.K = FrameStiffness(b.axes, prop.k, j.n, j.t1);
  return j;
}

// The CBUSH joints by increasing element id; notes, per PBUSH, the springs carried by levers.
std::vector<ModelJoint> BushJoints(const Deck &d, const std::vector<ModelPart> &parts, const ShellsByPid &by_pid, const GridParts &gp, const ModelOptions &options, std::vector<std::string> &notes)
{
  std::map<int, std::pair<int, double>> levers; // PBUSH id -> CBUSH with a lever, the longest GA-GB
  std::vector<const Bush *> bushes;
  for (const Bush &b : d.bushes) bushes.push_back(&b);
  std::sort(bushes.begin(), bushes.end(), [](const Bush *a, const Bush *b) { return a->id < b->id; });
  std::vector<ModelJoint> joints;
  for (const Bush *b : bushes) {
    joints.push_back(BushJoint(d, *b, parts, by_pid, gp, options));
    if (joints.back().lever) {
      auto &l = levers.emplace(b->pid, std::pair<int, double>{b->id, 0}).first->second;
      l.second = std::max(l.second, b->length);
    }
  }
  for (const auto &[pid, l] : levers)
    notes.push_back("PBUSH " + std::to_string(pid) + " (first at CBUSH " + std::to_string(l.first) + "): springs at S of GA-GB, each grid carrying its spring by a rigid lever (GA-GB up to " + Num(l.second) + " long)");
  return joints;
}

// A CFAST's joint: it joins its two properties (TYPE PROP) or the properties of its two elements
// (ELEM) at GS/XS; n is the normal of part A at its nearest grid; PFAST KT1 acts along n.
ModelJoint FastJoint(const Deck &d, const Fast &f, const std::vector<ModelPart> &parts, const ShellsByPid &by_pid)
{
  const std::string what = "CFAST " + std::to_string(f.id);
  int               sides[2];
  for (int s = 0; s < 2; ++s) {
    int pid = s ? f.idb : f.ida;
    if (f.by_element) pid = d.shells[d.ShellIndex(pid)].pid;
    auto it = std::find_if(parts.begin(), parts.end(), [&](const ModelPart &p) { return !p.rigid && p.pid == pid; });
    if (it == parts.end()) Fail(d, f.src, "CFAST", what + ": property " + std::to_string(pid) + " has no shell element");
    sides[s] = (int)(it - parts.begin());
  }
  if (sides[0] == sides[1]) Fail(d, f.src, "CFAST", what + ": both sides are property " + std::to_string(parts[sides[0]].pid) + ": a boltnet joint joins two different parts");
  ModelJoint j;
  j.eid = f.id, j.pid = f.pid, j.fast = true, j.part_a = sides[0], j.part_b = sides[1], j.x = f.position;
  int    near = -1;
  double best = HUGE_VAL;
  for (int g : parts[sides[0]].grids) {
    const Vec3 r = Sub(d.grids[g].x, f.position);
    if (Dot(r, r) < best) best = Dot(r, r), near = g;
  }
  const Vec3 n = NormalAt(d, by_pid, parts[sides[0]], near);
  Axes       axes{{n, NormalTo(n), {}}};
  axes[2] = Cross(axes[0], axes[1]);
  Frame(n, axes, j.n, j.t1);
  const PFast &pf = d.pfasts[d.pfast_index.at(f.pid)];
  if (pf.mcid >= 0) Fail(d, pf.src, "PFAST", "PFAST " + std::to_string(pf.id) + ", field MCID = " + std::to_string(pf.mcid) + ": stiffness axes from a coordinate system are not supported (boltnet: KT1 along the shell normal at GS, docs/nastran.md)");
  j.full = true, j.K = FrameStiffness(axes, pf.k, j.n, j.t1);
  return j;
}

// The CFAST joints by increasing element id; notes, per PFAST, how the model places its spring.
std::vector<ModelJoint> FastJoints(const Deck &d, const std::vector<ModelPart> &parts, const ShellsByPid &by_pid, std::vector<std::string> &notes)
{
  std::map<int, std::string> changed; // PFAST id -> what the model assumed for it
  std::vector<const Fast *>  fasts;
  for (const Fast &f : d.fasts) fasts.push_back(&f);
  std::sort(fasts.begin(), fasts.end(), [](const Fast *a, const Fast *b) { return a->id < b->id; });
  std::vector<ModelJoint> joints;
  for (const Fast *f : fasts) {
    joints.push_back(FastJoint(d, *f, parts, by_pid));
    const PFast &pf = d.pfasts[d.pfast_index.at(f->pid)];
    std::string &c = changed[f->pid];
    if (c.empty())
      c = "PFAST " + std::to_string(f->pid) + " (first at CFAST " + std::to_string(f->id) + "): the spring acts between the nodes of the two parts nearest GS/XS, without lever" +
          (pf.k[1] != pf.k[2] || pf.k[4] != pf.k[5] ? std::string("; KT2/KT3 (KR2/KR3) along n x X (or n x Y) and n x that (MCID = -1 taken so)") : std::string());
  }
  for (const auto &[pid, c] : changed) notes.push_back(c);
  return joints;
}

// The ties (joints kTieJointBase + 1, 2, ...): each copy of a shared grid to the owner's node, then
// each RBE2 GM grid to GN's rigid part, at the grid, with the penalty stiffness of ModelOptions
// (times the largest A11 and D11 of the shell parts); notes how many and how stiff.
std::vector<ModelJoint> Ties(const Deck &d, const std::vector<ModelPart> &parts, const ShellsByPid &by_pid, const GridParts &gp, const ModelOptions &options, std::vector<std::string> &notes)
{
  double a11 = 0, d11 = 0;
  for (const ModelPart &p : parts)
    if (!p.rigid) a11 = std::max(a11, p.material.A[0]), d11 = std::max(d11, p.material.D[0]);
  std::vector<ModelJoint> ties;
  int                     nshared = 0;
  const auto tie = [&](int part_a, int part_b, int g) {
    ModelJoint j;
    j.eid = kTieJointBase + (int)ties.size() + 1, j.part_a = part_a, j.part_b = part_b, j.x = d.grids[g].x;
    const int  shell = !parts[part_a].rigid ? part_a : part_b;
    const Vec3 n = NormalAt(d, by_pid, parts[shell], g);
    Frame(n, Axes{{n, NormalTo(n), {}}}, j.n, j.t1);
    j.kn = j.kt = options.tie_penalty * a11, j.kr = options.tie_penalty * d11;
    ties.push_back(j);
  };
  for (size_t g = 0; g < d.grids.size(); ++g)
    for (int c : gp.copies[g]) tie(gp.owner[g], c, (int)g), ++nshared;
  for (const Rbe2 &r : d.rbe2s)
    for (int gid : r.gm) {
      const int g = d.GridIndex(gid);
      if (gp.owner[g] < 0 || parts[gp.owner[g]].rigid) Fail(d, r.src, "RBE2", "RBE2 " + std::to_string(r.id) + ": GM grid " + std::to_string(gid) + " is on no shell element: boltnet ties an RBE2's GM grids to shell parts");
      tie(gp.owner[d.GridIndex(r.gn)], gp.owner[g], g);
    }
  const int nties = (int)ties.size();
  if (nties)
    notes.push_back(std::to_string(nties) + " tie(s) (joints " + std::to_string(kTieJointBase + 1) + " to " + std::to_string(kTieJointBase + nties) + "): " + std::to_string(nshared) + " for grids shared by the shells of two properties, " + std::to_string(nties - nshared) +
                    " for RBE2 GM grids; spring kn = kt = " + Num(options.tie_penalty * a11) + ", kr = " + Num(options.tie_penalty * d11) + " (penalty " + Num(options.tie_penalty) + " x the largest A11 and D11)");
  return ties;
}

// A condition on dof `dof` of node `node` of part `part`, in node set `set`; a rigid part's is on
// the part (no set, no nodes).
ModelBC Condition(const std::vector<ModelPart> &parts, int part, const std::string &set, int node, int dof, ModelBCKind kind, double value)
{
  if (parts[part].rigid) return {part, "", {}, dof, kind, value};
  return {part, set, {node}, dof, kind, value};
}

// Whether the axes are the basic ones (to 1e-12).
bool BasicAxes(const Axes &a)
{
  bool basic = true;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) basic = basic && std::fabs(a[i][j] - (i == j)) < 1e-12;
  return basic;
}

// The supports of the subcase (spc: its SPC, SPC1 and GRID PS): enforced values per grid
// ("grid<id>"), then zero values grouped per part and component set into node sets
// "spc<components>" (every copy of a shared grid); a rigid part's on the part. Components are in
// the grid's CD system: a CD other than the basic axes is accepted where the components cover all
// three translations or rotations with value 0. A constraint on a grid of no part is skipped (noted).
std::vector<ModelBC> Supports(const Deck &d, const Subcase &sc, const std::vector<Constraint> &spc, const std::vector<ModelPart> &parts, const GridParts &gp, std::vector<std::string> &notes)
{
  std::vector<ModelBC>                               bcs;
  std::map<std::pair<int, DofSet>, std::vector<int>> fixed;
  std::set<int>                                      skipped;
  for (const Constraint &c : spc) {
    const Grid &g = d.grids[c.node];
    if (gp.owner[c.node] < 0) {
      skipped.insert(g.id);
      continue;
    }
    bool nonzero = false;
    for (int i = 0; i < 6; ++i) nonzero = nonzero || ((c.dofs >> i & 1u) && c.value[i] != 0);
    const DofSet tr = c.dofs & 7u, rot = (c.dofs >> 3) & 7u;
    if (!BasicAxes(g.cd_axes) && (nonzero || (tr != 0 && tr != 7) || (rot != 0 && rot != 7)))
      Fail(d, g.src, "GRID", "grid " + std::to_string(g.id) + " (SPC components " + DofString(c.dofs) + "): its displacement system CD " + std::to_string(g.cd) + " is not the basic axes; boltnet constrains basic components (all three translations or rotations, fixed, are accepted in any system)");
    std::vector<int> holders{gp.owner[c.node]};
    holders.insert(holders.end(), gp.copies[c.node].begin(), gp.copies[c.node].end());
    for (int part : holders) {
      const int node = LocalNode(parts[part], c.node);
      for (int i = 0; i < 6; ++i) {
        if (!(c.dofs >> i & 1u)) continue;
        if (c.value[i] != 0) bcs.push_back(Condition(parts, part, "grid" + std::to_string(g.id), node, i, ModelBCKind::Displacement, c.value[i]));
        else if (parts[part].rigid) bcs.push_back(Condition(parts, part, "", 0, i, ModelBCKind::Fixed, 0));
      }
      DofSet zero = 0;
      for (int i = 0; i < 6; ++i)
        if ((c.dofs >> i & 1u) && c.value[i] == 0) zero |= 1u << i;
      if (zero && !parts[part].rigid) fixed[{part, zero}].push_back(node);
    }
  }
  for (const auto &[key, nodes] : fixed)
    for (int i = 0; i < 6; ++i)
      if (key.second >> i & 1u) bcs.push_back({key.first, "spc" + DofString(key.second), nodes, i, ModelBCKind::Fixed, 0});
  if (!skipped.empty()) notes.push_back("subcase " + std::to_string(sc.id) + ": constraints on " + std::to_string(skipped.size()) + " grid(s) on no shell element and no joint skipped (first: grid " + std::to_string(*skipped.begin()) + ")");
  return bcs;
}

// The loads of the subcase: FORCE, MOMENT and PLOAD4 (as consistent nodal forces), those on an
// RBE3's REFGRID moved to its independent grids (refgrid: Rbe3ByRefgrid), per grid in the basic
// system, on the grid's first part.
std::vector<ModelBC> Loads(const Deck &d, const Subcase &sc, const std::map<int, const Rbe3 *> &refgrid, const std::vector<ModelPart> &parts, const GridParts &gp, std::vector<std::string> &notes)
{
  StaticLoad load = ExpandLoad(d, sc.load);
  PressuresToNodal(d, load.pressures, load.nodal);
  MoveRbe3Loads(d, refgrid, sc.id, load.nodal, notes);
  std::vector<ModelBC> bcs;
  for (const NodalLoad &l : load.nodal) {
    const Grid &g = d.grids[l.node];
    bool any = false;
    for (int i = 0; i < 3; ++i) any = any || l.force[i] != 0 || l.moment[i] != 0;
    if (!any) continue;
    if (gp.owner[l.node] < 0) Fail(d, g.src, "GRID", "grid " + std::to_string(g.id) + " carries a load in subcase " + std::to_string(sc.id) + " (LOAD " + std::to_string(sc.load) + ") but is on no shell element and no joint: boltnet loads parts");
    const int part = gp.owner[l.node], node = LocalNode(parts[part], l.node);
    for (int i = 0; i < 6; ++i) {
      const double v = i < 3 ? l.force[i] : l.moment[i - 3];
      if (v != 0) bcs.push_back(Condition(parts, part, "grid" + std::to_string(g.id), node, i, ModelBCKind::Force, v));
    }
  }
  return bcs;
}

} // namespace

DeckModel ModelOf(const Deck &d, int subcase_id, const ModelOptions &options)
{
  const Subcase &sc = FindSubcase(d, subcase_id);
  DeckModel      m;
  m.subcase = sc.id;
  const ShellsByPid by_pid = ShellsByProperty(d);
  GridParts         gp{std::vector<int>(d.grids.size(), -1), std::vector<std::vector<int>>(d.grids.size())};
  m.parts = ShellParts(d, by_pid, gp, m.notes);

  const std::vector<Constraint> spc = ExpandSpc(d, sc.spc);
  // RBE3: only as a load distribution from a REFGRID that nothing else connects (rbe3.hpp), checked
  // against the shells before the rigid parts exist.
  std::vector<bool> on_shell(d.grids.size());
  for (size_t g = 0; g < d.grids.size(); ++g) on_shell[g] = gp.owner[g] >= 0;
  const std::map<int, const Rbe3 *> refgrid = Rbe3ByRefgrid(d, on_shell, spc, sc);
  AddRigidParts(d, sc, spc, m.parts, gp);
  CheckRbe3Grids(d, gp);

  m.joints = BushJoints(d, m.parts, by_pid, gp, options, m.notes); // CBUSH then CFAST (model.hpp)
  Append(m.joints, FastJoints(d, m.parts, by_pid, m.notes));
  Append(m.joints, Ties(d, m.parts, by_pid, gp, options, m.notes));

  m.bcs = Supports(d, sc, spc, m.parts, gp, m.notes);
  Append(m.bcs, Loads(d, sc, refgrid, m.parts, gp, m.notes));
  return m;
}

} // namespace boltnet::nastran
