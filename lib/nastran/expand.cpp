// Subcase constraints and loads (expand.hpp).
#include "nastran/expand.hpp"

#include <cmath>
#include <map>
#include <sstream>

namespace boltnet::nastran {

namespace {

Vec3 Cross(const Vec3 &a, const Vec3 &b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

[[noreturn]] void Fail(const Deck &d, const Source &at, const std::string &card, const std::string &what)
{
  throw Error(d.Where(at) + ": " + what, at.file >= 0 ? d.files[at.file] : "", at.line, card, 0);
}

} // namespace

std::vector<Constraint> ExpandSpc(const Deck &d, int sid)
{
  std::map<int, Constraint> by_node;
  std::map<std::pair<int, int>, Source> set_by; // (node, component) -> the card that set it
  const auto add = [&](int node, DofSet dofs, double value, const Source &src, const char *card) {
    Constraint &c = by_node[node];
    c.node = node;
    for (int i = 0; i < 6; ++i) {
      if (!(dofs & (1u << i))) continue;
      if ((c.dofs & (1u << i)) && c.value[i] != value) {
        std::ostringstream m;
        m << card << ": grid " << d.grids[node].id << " component " << i + 1 << " is enforced to " << value << " here and to " << c.value[i]
          << " at " << d.Where(set_by[{node, i}]);
        Fail(d, src, card, m.str());
      }
      c.dofs |= 1u << i;
      c.value[i] = value;
      set_by[{node, i}] = src;
    }
  };
  for (size_t i = 0; i < d.grids.size(); ++i)
    if (d.grids[i].ps) add(static_cast<int>(i), d.grids[i].ps, 0, d.grids[i].src, "GRID PS");
  if (sid) {
    std::vector<int> sets{sid};
    for (const SpcAdd &a : d.spcadds)
      if (a.sid == sid) sets = a.sets;
    for (int s : sets)
      for (const Spc &c : d.spcs)
        if (c.sid == s) add(d.GridIndex(c.grid), c.dofs, c.value, c.src, "SPC");
  }
  std::vector<Constraint> out;
  for (auto &[node, c] : by_node) out.push_back(c);
  return out;
}

StaticLoad ExpandLoad(const Deck &d, int sid)
{
  StaticLoad out;
  if (!sid) return out;
  std::vector<std::pair<double, int>> sets{{1.0, sid}};
  for (const LoadCombination &l : d.load_combinations)
    if (l.sid == sid) {
      sets.clear();
      for (size_t i = 0; i < l.sets.size(); ++i) sets.push_back({l.scale * l.scales[i], l.sets[i]});
    }
  std::map<int, NodalLoad> nodal;
  for (const auto &[scale, set] : sets) {
    for (const PointLoad &l : d.point_loads) {
      if (l.sid != set) continue;
      NodalLoad &n = nodal[d.GridIndex(l.grid)];
      n.node = d.GridIndex(l.grid);
      Vec3 &v = l.moment ? n.moment : n.force;
      for (int j = 0; j < 3; ++j) v[j] += scale * l.basic[j];
    }
    for (const Pressure &p : d.pressures) {
      if (p.sid != set) continue;
      ShellPressure s;
      s.shell = p.shell;
      for (int i = 0; i < 4; ++i) s.p[i] = scale * p.p[i];
      if (p.has_direction) {
        // N in system CID, directions taken at the element's centre for a curvilinear system.
        const Shell &e = d.shells[p.shell];
        Vec3 centre{};
        for (int i = 0; i < e.Nodes(); ++i)
          for (int j = 0; j < 3; ++j) centre[j] += d.grids[e.node[i]].x[j] / e.Nodes();
        Axes axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
        if (p.cid) {
          try {
            axes = DirectionsAt(d.coords[d.coord_index.at(p.cid)], centre);
          } catch (const std::domain_error &x) {
            Fail(d, p.src, "PLOAD4", "PLOAD4 on element " + std::to_string(p.element) + ": " + x.what());
          }
        }
        Vec3 v{};
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) v[j] += p.n[i] * axes[i][j];
        const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        s.has_direction = true;
        s.direction = {v[0] / n, v[1] / n, v[2] / n};
      }
      out.pressures.push_back(s);
    }
  }
  for (auto &[node, n] : nodal) out.nodal.push_back(n);
  return out;
}

Resultant LoadResultant(const Deck &d, const StaticLoad &load)
{
  Resultant r;
  const auto add = [&r](const Vec3 &x, const Vec3 &f) {
    const Vec3 m = Cross(x, f);
    for (int j = 0; j < 3; ++j) r.force[j] += f[j], r.moment[j] += m[j];
  };
  for (const NodalLoad &n : load.nodal) {
    add(d.grids[n.node].x, n.force);
    for (int j = 0; j < 3; ++j) r.moment[j] += n.moment[j];
  }
  for (const ShellPressure &s : load.pressures) {
    const Shell &e = d.shells[s.shell];
    std::array<Vec3, 4> X;
    for (int i = 0; i < e.Nodes(); ++i) X[i] = d.grids[e.node[i]].x;
    // f dA at a point: p (X_xi x X_eta) dxi deta, or p |X_xi x X_eta| N along a given direction.
    const auto at = [&](const std::array<double, 4> &N, const Vec3 &dxi, const Vec3 &deta, double w) {
      Vec3 x{}, a = Cross(dxi, deta);
      double p = 0;
      for (int i = 0; i < e.Nodes(); ++i) {
        p += N[i] * s.p[i];
        for (int j = 0; j < 3; ++j) x[j] += N[i] * X[i][j];
      }
      if (s.has_direction) {
        const double area = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        a = {s.direction[0] * area, s.direction[1] * area, s.direction[2] * area};
      }
      add(x, {w * p * a[0], w * p * a[1], w * p * a[2]});
    };
    if (e.kind == ShellKind::Quad4) {
      // 2 x 2 Gauss points: exact for the cubic integrands of bilinear x, p and X_xi x X_eta.
      const double g = 1 / std::sqrt(3.0);
      for (double xi : {-g, g})
        for (double eta : {-g, g}) {
          const std::array<double, 4> N{(1 - xi) * (1 - eta) / 4, (1 + xi) * (1 - eta) / 4, (1 + xi) * (1 + eta) / 4, (1 - xi) * (1 + eta) / 4};
          Vec3 dxi{}, deta{};
          const double dNxi[4] = {-(1 - eta) / 4, (1 - eta) / 4, (1 + eta) / 4, -(1 + eta) / 4};
          const double dNeta[4] = {-(1 - xi) / 4, -(1 + xi) / 4, (1 + xi) / 4, (1 - xi) / 4};
          for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 3; ++j) dxi[j] += dNxi[i] * X[i][j], deta[j] += dNeta[i] * X[i][j];
          at(N, dxi, deta, 1.0);
        }
    } else {
      // Edge midpoints, weight 1/3 of the area (exact for quadratics: x p on a linear triangle).
      Vec3 e1{}, e2{};
      for (int j = 0; j < 3; ++j) e1[j] = X[1][j] - X[0][j], e2[j] = X[2][j] - X[0][j];
      for (const std::array<double, 4> &N : {std::array<double, 4>{.5, .5, 0, 0}, {0, .5, .5, 0}, {.5, 0, .5, 0}}) at(N, e1, e2, 1.0 / 6);
    }
  }
  return r;
}

} // namespace boltnet::nastran
