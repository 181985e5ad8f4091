// RBE3 as a load distribution (rbe3.hpp; docs/nastran.md, "RBE3").
#include "nastran/rbe3.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace boltnet::nastran {

namespace {

using Vec6 = std::array<double, 6>;
using Mat6 = std::array<Vec6, 6>;

Vec3   Cross(const Vec3 &a, const Vec3 &b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double Dot(const Vec3 &a, const Vec3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3   Sub(const Vec3 &a, const Vec3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

[[noreturn]] void Fail(const Deck &d, const Rbe3 &e, const std::string &what)
{
  throw Error(d.Where(e.src) + ": RBE3 " + std::to_string(e.id) + ": " + what, e.src.file >= 0 ? d.files[e.src.file] : "", e.src.line, "RBE3", 0);
}

// One independent component k: its grid (index), weight w_k, direction d_k (basic) and its row
// s_k = (d_k, (r_k x d_k) / L) of the rigid-body map from the scaled motion (u, L theta) of the
// point c below to that component (r_k = x_k - c).
struct Component {
  int    node = -1;
  double w = 0;
  Vec3   d{};
  Vec6   s{};
};

// The least-squares system of an RBE3, written about the components' weighted centroid c (where
// translations and rotations decouple for Ci = 123) in the unknowns (u, L theta), L the weighted
// root-mean-square distance of the components from c (1 if they all sit on it), so that A's
// eigenvalues compare forces with forces: A = sum w_k s_k s_k^T = V diag(lambda) V^T.
struct System {
  std::vector<Component> comps;
  Vec3                   c{};
  double                 length = 1;
  Vec6                   lambda{};
  Mat6                   v{}; // v[i][j]: component i of eigenvector j
  double                 tol = 0;
};

// Eigenvalues and eigenvectors of a symmetric 6 x 6 matrix by cyclic Jacobi rotations (Golub and
// Van Loan, Matrix Computations, 8.5): converges to round-off in a few sweeps at this size.
void Eigen(Mat6 a, Vec6 &lambda, Mat6 &v)
{
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) v[i][j] = i == j;
  for (int sweep = 0; sweep < 50; ++sweep) {
    double off = 0, diag = 0;
    for (int i = 0; i < 6; ++i) {
      diag += a[i][i] * a[i][i];
      for (int j = i + 1; j < 6; ++j) off += a[i][j] * a[i][j];
    }
    if (off <= 1e-32 * diag) break;
    for (int p = 0; p < 6; ++p)
      for (int q = p + 1; q < 6; ++q) {
        if (a[p][q] == 0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const double t = (theta >= 0 ? 1 : -1) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < 6; ++k) { // columns p, q of A J
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq, a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 6; ++k) { // rows p, q of J^T (A J)
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk, a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 6; ++k) {
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq, v[k][q] = s * vkp + c * vkq;
        }
      }
  }
  for (int i = 0; i < 6; ++i) lambda[i] = a[i][i];
}

System Build(const Deck &d, const Rbe3 &e)
{
  System sys;
  double wsum = 0;
  for (const Rbe3::Group &g : e.groups)
    for (int gid : g.grids)
      for (int c = 0; c < 3; ++c) {
        if (!(g.c >> c & 1u)) continue;
        Component k;
        k.node = d.GridIndex(gid), k.w = g.weight, k.d = d.grids[k.node].cd_axes[c];
        sys.comps.push_back(k);
        wsum += k.w;
        for (int j = 0; j < 3; ++j) sys.c[j] += k.w * d.grids[k.node].x[j];
      }
  if (!(wsum > 0)) return sys;
  for (double &cj : sys.c) cj /= wsum;
  double wr2 = 0;
  for (const Component &k : sys.comps) {
    const Vec3 r = Sub(d.grids[k.node].x, sys.c);
    wr2 += k.w * Dot(r, r);
  }
  if (wr2 > 0) sys.length = std::sqrt(wr2 / wsum);
  Mat6 a{};
  for (Component &k : sys.comps) {
    const Vec3 m = Cross(Sub(d.grids[k.node].x, sys.c), k.d);
    k.s = {k.d[0], k.d[1], k.d[2], m[0] / sys.length, m[1] / sys.length, m[2] / sys.length};
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) a[i][j] += k.w * k.s[i] * k.s[j];
  }
  Eigen(a, sys.lambda, sys.v);
  sys.tol = 1e-10 * *std::max_element(sys.lambda.begin(), sys.lambda.end());
  return sys;
}

// A load (F, M) on REFGRID as the scaled load (F, (M + (x_ref - c) x F) / L) about c.
Vec6 AboutCentroid(const Deck &d, const Rbe3 &e, const System &sys, const Vec3 &f, const Vec3 &m)
{
  const Vec3 arm = Cross(Sub(d.grids[d.GridIndex(e.refgrid)].x, sys.c), f);
  return {f[0], f[1], f[2], (m[0] + arm[0]) / sys.length, (m[1] + arm[1]) / sys.length, (m[2] + arm[2]) / sys.length};
}

// The unit direction (translation or rotation) of REFGRID's component c (0..5) in the basic system.
Vec3 RefAxis(const Deck &d, const Rbe3 &e, int c) { return d.grids[d.GridIndex(e.refgrid)].cd_axes[c % 3]; }

} // namespace

void CheckRbe3(const Deck &d, const Rbe3 &e)
{
  for (size_t i = 0; i < e.groups.size(); ++i)
    if (e.groups[i].c & ~7u)
      Fail(d, e, "C" + std::to_string(i + 1) + " = " + DofString(e.groups[i].c) +
                   ": boltnet supports translational independent components only (Ci within 123, which the Quick Reference Guide recommends for most uses); rotations at the Gi,j would need their weights put against the translations' through a length, which the card leaves open");
  if (!e.um.empty())
    Fail(d, e, "UM (grid " + std::to_string(e.um[0].first) + " component(s) " + DofString(e.um[0].second) +
                 "): boltnet uses an RBE3 only to move loads from a REFGRID that nothing else connects, where moving the dependent components changes nothing; remove the UM fields");
  for (const Rbe3::Group &g : e.groups)
    for (int gid : g.grids)
      if (gid == e.refgrid) Fail(d, e, "REFGRID " + std::to_string(e.refgrid) + " is also one of its independent grids");
  const System sys = Build(d, e);
  if (!(sys.tol > 0)) Fail(d, e, "its independent components have no weight");
  // Each REFC component, as a unit load on REFGRID, must lie in the range of A (orthogonal to its
  // null space); then so does every load on REFC, and its distribution is unique.
  std::string missing;
  for (int c = 0; c < 6; ++c) {
    if (!(e.refc >> c & 1u)) continue;
    const Vec3 a = RefAxis(d, e, c), zero{};
    Vec6       dir = c < 3 ? AboutCentroid(d, e, sys, a, zero) : AboutCentroid(d, e, sys, zero, a);
    double     norm = 0;
    for (double x : dir) norm += x * x;
    for (int j = 0; j < 6; ++j) {
      if (sys.lambda[j] > sys.tol) continue;
      double p = 0;
      for (int i = 0; i < 6; ++i) p += sys.v[i][j] * dir[i];
      if (std::fabs(p) > 1e-6 * std::sqrt(norm)) {
        missing += std::to_string(c + 1);
        break;
      }
    }
  }
  if (!missing.empty())
    Fail(d, e, "its independent components (Ci at the grids Gi,j) cannot carry REFC component(s) " + missing + " of REFGRID " + std::to_string(e.refgrid) +
                 ": the weighted least-squares fit of REFGRID's motion is singular there (Nastran: the Ci must react the rigid-body motion of REFC; grids on one line with translations only carry no moment about that line)");
}

std::vector<NodalLoad> DistributeRbe3(const Deck &d, const Rbe3 &e, const Vec3 &force, const Vec3 &moment, int subcase)
{
  const System sys = Build(d, e);
  // Components outside REFC (in REFGRID's displacement system) would stay on REFGRID.
  const double scale = std::sqrt(Dot(force, force)) + std::sqrt(Dot(moment, moment)) / sys.length;
  for (int c = 0; c < 6; ++c) {
    if (e.refc >> c & 1u) continue;
    const double pc = Dot(RefAxis(d, e, c), c < 3 ? force : moment);
    if (std::fabs(pc) > 1e-12 * scale) {
      std::ostringstream m;
      m << "subcase " << subcase << ": REFGRID " << e.refgrid << " carries load component " << c + 1 << " (" << pc << ") which REFC = " << DofString(e.refc)
        << " does not contain: Nastran leaves it on REFGRID, which nothing else connects; add the component to REFC or load other grids";
      Fail(d, e, m.str());
    }
  }
  // v = A^-1 P on the range of A (CheckRbe3 made sure REFC, hence P, lies in it); f_k = w_k s_k . v.
  const Vec6 p = AboutCentroid(d, e, sys, force, moment);
  Vec6       v{};
  for (int j = 0; j < 6; ++j) {
    if (sys.lambda[j] <= sys.tol) continue;
    double c = 0;
    for (int i = 0; i < 6; ++i) c += sys.v[i][j] * p[i];
    for (int i = 0; i < 6; ++i) v[i] += c / sys.lambda[j] * sys.v[i][j];
  }
  std::map<int, NodalLoad> by;
  for (const Component &k : sys.comps) {
    double f = 0;
    for (int i = 0; i < 6; ++i) f += k.s[i] * v[i];
    f *= k.w;
    NodalLoad &l = by[k.node];
    l.node = k.node;
    for (int j = 0; j < 3; ++j) l.force[j] += f * k.d[j];
  }
  std::vector<NodalLoad> out;
  for (auto &[node, l] : by) out.push_back(l);
  return out;
}

std::map<int, const Rbe3 *> Rbe3ByRefgrid(const Deck &d, const std::vector<bool> &on_shell, const std::vector<Constraint> &spc, const Subcase &sc)
{
  std::map<int, const Rbe3 *> by;
  const auto fail = [&](const Rbe3 &e, const std::string &what) {
    Fail(d, e, "REFGRID " + std::to_string(e.refgrid) + " " + what +
                 ": boltnet supports an RBE3 whose REFGRID is connected to nothing else and only carries loads (FORCE, MOMENT), which it moves to the independent grids (docs/nastran.md, \"RBE3\")");
  };
  const auto check = [&](int g, const std::string &what) {
    const auto it = g >= 0 ? by.find(g) : by.end();
    if (it != by.end()) fail(*it->second, what);
  };
  for (const Rbe3 &e : d.rbe3s) {
    CheckRbe3(d, e);
    const int g = d.GridIndex(e.refgrid);
    const auto [it, fresh] = by.emplace(g, &e);
    if (!fresh) fail(e, "is also REFGRID of RBE3 " + std::to_string(it->second->id) + " at " + d.Where(it->second->src));
  }
  for (const Shell &s : d.shells)
    for (int i = 0; i < s.Nodes(); ++i)
      if (on_shell[s.node[i]]) check(s.node[i], std::string("is a grid of ") + (s.kind == ShellKind::Quad4 ? "CQUAD4 " : "CTRIA3 ") + std::to_string(s.id) + " at " + d.Where(s.src));
  for (const Rbe3 &e : d.rbe3s)
    for (const Rbe3::Group &grp : e.groups)
      for (int gid : grp.grids) check(d.GridIndex(gid), "is an independent grid of RBE3 " + std::to_string(e.id) + " at " + d.Where(e.src));
  for (const Bush &b : d.bushes)
    for (int g : {b.na, b.nb}) check(g, "is a grid of CBUSH " + std::to_string(b.id) + " at " + d.Where(b.src));
  for (const Rbe2 &r : d.rbe2s) {
    check(d.GridIndex(r.gn), "is GN of RBE2 " + std::to_string(r.id) + " at " + d.Where(r.src));
    for (int gid : r.gm) check(d.GridIndex(gid), "is a GM grid of RBE2 " + std::to_string(r.id) + " at " + d.Where(r.src));
  }
  for (const Constraint &c : spc) {
    const auto it = by.find(c.node);
    if (it != by.end() && (c.dofs & it->second->refc))
      fail(*it->second, "has components " + DofString(c.dofs & it->second->refc) + " of REFC constrained in subcase " + std::to_string(sc.id) + " (SPC " + std::to_string(sc.spc) +
                          " or GRID PS; Nastran refuses a constraint on a dependent component unless UM makes it independent)");
  }
  return by;
}

void MoveRbe3Loads(const Deck &d, const std::map<int, const Rbe3 *> &by_refgrid, int subcase, std::vector<NodalLoad> &nodal, std::vector<std::string> &notes)
{
  if (by_refgrid.empty()) return;
  std::map<int, NodalLoad> by;
  const auto add = [&](const NodalLoad &l) {
    NodalLoad &t = by[l.node];
    t.node = l.node;
    for (int j = 0; j < 3; ++j) t.force[j] += l.force[j], t.moment[j] += l.moment[j];
  };
  for (const NodalLoad &l : nodal) {
    const auto it = by_refgrid.find(l.node);
    if (it == by_refgrid.end()) {
      add(l);
      continue;
    }
    const Rbe3                  &e = *it->second;
    const std::vector<NodalLoad> shares = DistributeRbe3(d, e, l.force, l.moment, subcase);
    for (const NodalLoad &f : shares) add(f);
    std::ostringstream note;
    note << "subcase " << subcase << ": RBE3 " << e.id << ": the load on REFGRID " << e.refgrid << " (force [" << l.force[0] << ", " << l.force[1] << ", " << l.force[2] << "], moment [" << l.moment[0] << ", " << l.moment[1]
         << ", " << l.moment[2] << "]) moved to its " << shares.size() << " independent grid(s)";
    notes.push_back(note.str());
  }
  nodal.clear();
  for (const auto &[node, l] : by) nodal.push_back(l);
}

} // namespace boltnet::nastran
