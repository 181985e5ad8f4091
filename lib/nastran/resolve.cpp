// After every card is read: unique ids, references, coordinate systems (chains and cycles), grid
// positions and displacement axes, bush axes, THRU ranges. Each failure names the field that holds
// the bad id.
#include "nastran/build.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

namespace boltnet::nastran {

namespace {

const CoordSystem &Basic()
{
  static const CoordSystem basic{};
  return basic;
}

Vec3 Sub(const Vec3 &a, const Vec3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 Cross(const Vec3 &a, const Vec3 &b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double Norm(const Vec3 &a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
Vec3 Scale(const Vec3 &a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

// The data field of a card that holds the integer id (for messages about lists), from field k on.
int FieldOf(const CardFields &c, int id, int k = 0)
{
  for (; k < c.Size(); ++k) {
    int v;
    if (ParseInteger(c.Text(k), v) && v == id) return k;
  }
  return 0;
}

struct Resolver {
  Build &b;
  Deck  &d;

  // Fills `index` from the records' ids; a repeated id fails on the later card. `space` holds the
  // ids of every kind that shares the id space (elements, properties, materials).
  template <class T, class IdOf>
  void Index(const std::vector<T> &v, std::unordered_map<int, int> &index, std::map<int, Source> &space, IdOf id_of, int k)
  {
    for (size_t i = 0; i < v.size(); ++i) {
      const int id = id_of(v[i]);
      auto [it, fresh] = space.emplace(id, v[i].src);
      if (!fresh) {
        const CardFields first = b.Fields(it->second);
        b.Fields(v[i].src).Fail(k, "ID", "duplicate id: " + first.Title() + " is already defined at " + d.Where(it->second));
      }
      index[id] = static_cast<int>(i);
    }
  }

  const CoordSystem &Cs(int cid, const Source &src, int k, const char *what)
  {
    if (cid == 0) return Basic();
    const int i = Deck::Find(d.coord_index, cid);
    if (i < 0) b.Fields(src).Fail(k, what, "coordinate system " + std::to_string(cid) + " is not defined (CORD2R, CORD2C or CORD2S)");
    return d.coords[i];
  }

  int GridAt(int id, const Source &src, int k, const char *what)
  {
    const int i = d.GridIndex(id);
    if (i < 0) b.Fields(src).Fail(k, what, "grid " + std::to_string(id) + " is not defined");
    return i;
  }

  void Ids()
  {
    // Id spaces as Nastran keeps them: elastic elements, rigid elements and masses apart (Simcenter
    // Nastran runs a deck whose RBE2 shares an id with a CQUAD4), properties, materials.
    std::map<int, Source> grids, coords, elements, rigid, masses, properties, materials;
    Index(d.grids, d.grid_index, grids, [](const Grid &g) { return g.id; }, F(0, 2));
    Index(d.coords, d.coord_index, coords, [](const CoordSystem &c) { return c.id; }, F(0, 2));
    std::unordered_map<int, int> scratch;
    Index(d.shells, d.shell_index, elements, [](const Shell &e) { return e.id; }, F(0, 2));
    Index(d.bushes, scratch, elements, [](const Bush &e) { return e.id; }, F(0, 2));
    Index(d.fasts, scratch, elements, [](const Fast &e) { return e.id; }, F(0, 2));
    Index(d.rbe2s, scratch, rigid, [](const Rbe2 &e) { return e.id; }, F(0, 2));
    Index(d.rbe3s, scratch, rigid, [](const Rbe3 &e) { return e.id; }, F(0, 2));
    Index(d.conm2s, scratch, masses, [](const Conm2 &e) { return e.id; }, F(0, 2));
    Index(d.pshells, d.pshell_index, properties, [](const PShell &p) { return p.id; }, F(0, 2));
    Index(d.pcomps, d.pcomp_index, properties, [](const PComp &p) { return p.id; }, F(0, 2));
    Index(d.pbushes, d.pbush_index, properties, [](const PBush &p) { return p.id; }, F(0, 2));
    Index(d.pfasts, d.pfast_index, properties, [](const PFast &p) { return p.id; }, F(0, 2));
    Index(d.mat1s, d.mat1_index, materials, [](const Mat1 &m) { return m.id; }, F(0, 2));
    Index(d.mat8s, d.mat8_index, materials, [](const Mat8 &m) { return m.id; }, F(0, 2));
    std::map<int, Source> loads, spcadds;
    Index(d.load_combinations, scratch, loads, [](const LoadCombination &l) { return l.sid; }, F(0, 2));
    Index(d.spcadds, scratch, spcadds, [](const SpcAdd &a) { return a.sid; }, F(0, 2));
  }

  void Coords()
  {
    std::vector<int> state(d.coords.size(), 0), chain; // 0: to do, 1: in progress, 2: done
    std::function<void(int)> resolve = [&](int i) {
      CoordSystem &cs = d.coords[i];
      if (state[i] == 2) return;
      if (state[i] == 1) {
        std::string cycle;
        bool in = false;
        for (int j : chain) {
          in = in || j == i;
          if (in) cycle += std::to_string(d.coords[j].id) + " -> ";
        }
        b.Fields(cs.src).Fail(F(0, 3), "RID", "coordinate systems " + cycle + std::to_string(cs.id) + " reference each other in a cycle");
      }
      state[i] = 1;
      chain.push_back(i);
      if (cs.rid != 0) {
        const int j = Deck::Find(d.coord_index, cs.rid);
        if (j < 0) b.Fields(cs.src).Fail(F(0, 3), "RID", "coordinate system " + std::to_string(cs.rid) + " is not defined");
        resolve(j);
      }
      const CoordSystem &ref = cs.rid ? d.coords[Deck::Find(d.coord_index, cs.rid)] : Basic();
      const Vec3 A = ToBasic(ref, cs.a), B = ToBasic(ref, cs.b), C = ToBasic(ref, cs.c);
      const Vec3 ab = Sub(B, A), ac = Sub(C, A);
      if (Norm(ab) == 0) b.Fields(cs.src).Fail(F(0, 7), "B1", "B coincides with A: the z axis is undefined");
      const Vec3 e3 = Scale(ab, 1 / Norm(ab)), y = Cross(e3, ac);
      if (Norm(y) <= 1e-10 * Norm(ac) || Norm(ac) == 0) b.Fields(cs.src).Fail(F(1, 2), "C1", "C lies on the line through A and B: the xz plane is undefined");
      const Vec3 e2 = Scale(y, 1 / Norm(y));
      cs.origin = A;
      cs.axes = {Cross(e2, e3), e2, e3};
      state[i] = 2;
      chain.pop_back();
    };
    for (size_t i = 0; i < d.coords.size(); ++i) resolve(static_cast<int>(i));
  }

  void Grids()
  {
    for (size_t i = 0; i < d.grids.size(); ++i) {
      Grid &g = d.grids[i];
      if (b.grdset.given) {
        if (b.grid_blank[i][0]) g.cp = b.grdset.cp;
        if (b.grid_blank[i][1]) g.cd = b.grdset.cd;
        if (b.grid_blank[i][2]) g.ps = b.grdset.ps;
      }
      g.x = ToBasic(Cs(g.cp, g.src, F(0, 3), "CP"), g.input);
      const CoordSystem &cd = Cs(g.cd, g.src, F(0, 7), "CD");
      try {
        g.cd_axes = DirectionsAt(cd, g.x);
      } catch (const std::domain_error &e) {
        b.Fields(g.src).Fail(F(0, 7), "CD", std::string("the grid's displacement directions are undefined: ") + e.what());
      }
    }
  }

  void Shells()
  {
    std::map<int, std::pair<int, Source>> missing; // property id -> (shells, the first)
    for (Shell &e : d.shells) {
      static const char *g[] = {"G1", "G2", "G3", "G4"};
      for (int i = 0; i < e.Nodes(); ++i) {
        e.node[i] = GridAt(e.grid[i], e.src, F(0, 4 + i), g[i]);
        for (int j = 0; j < i; ++j)
          if (e.grid[j] == e.grid[i]) b.Fields(e.src).Fail(F(0, 4 + i), g[i], "grid " + std::to_string(e.grid[i]) + " appears twice in the element");
      }
      const bool pshell = d.pshell_index.count(e.pid), pcomp = d.pcomp_index.count(e.pid);
      if (!pshell && !pcomp) {
        if (!b.options.allow_missing_properties) b.Fields(e.src).Fail(F(0, 3), "PID", "property " + std::to_string(e.pid) + " is not a PSHELL or PCOMP");
        auto &m = missing[e.pid];
        if (m.first++ == 0) m.second = e.src;
      }
      if (e.mcid >= 0) Cs(e.mcid, e.src, F(0, 4 + e.Nodes()), "MCID");
      if (pshell && std::isnan(d.pshells[d.pshell_index.at(e.pid)].t))
        for (int i = 0; i < e.Nodes(); ++i)
          if (std::isnan(e.t[i]) || e.tflag == 1)
            b.Fields(e.src).Fail(F(1, 5 + i), "T" + std::to_string(i + 1),
                                 "PSHELL " + std::to_string(e.pid) + " has no thickness T: the element must give its corner thicknesses (TFLAG 0)");
    }
    if (!missing.empty()) {
      int shells = 0;
      std::string ids;
      for (const auto &[pid, m] : missing) {
        shells += m.first;
        if (ids.size() < 60) ids += (ids.empty() ? "" : ", ") + std::to_string(pid);
        else if (ids.back() != '.') ids += ", ...";
      }
      b.Note(missing.begin()->second.second, std::to_string(missing.size()) + " properties of " + std::to_string(shells) +
                                               " shells are not PSHELL or PCOMP cards of the deck (allowed by ReadOptions::allow_missing_properties; those shells have no section): " + ids);
    }
  }

  void Material(int mid, const Source &src, int k, const std::string &what)
  {
    if (mid > 0 && !d.mat1_index.count(mid) && !d.mat8_index.count(mid))
      b.Fields(src).Fail(k, what, "material " + std::to_string(mid) + " is not a MAT1 or MAT8");
  }

  void Properties()
  {
    for (const PShell &p : d.pshells) {
      Material(p.mid1, p.src, F(0, 3), "MID1");
      Material(p.mid2, p.src, F(0, 5), "MID2");
      Material(p.mid3, p.src, F(0, 7), "MID3");
      Material(p.mid4, p.src, F(1, 4), "MID4");
    }
    for (const PComp &p : d.pcomps) {
      const CardFields c = b.Fields(p.src);
      for (size_t i = 0; i < p.plies.size(); ++i) {
        // The MID field of this ply (blank MIDs repeat the previous ply's: name the PCOMP then).
        int k = 0, seen = 0;
        for (int kk = F(1, 2); kk < c.Size(); kk += 4)
          if (!(c.Blank(kk) && c.Blank(kk + 1) && c.Blank(kk + 2) && c.Blank(kk + 3)) && seen++ == static_cast<int>(i)) k = kk;
        Material(p.plies[i].mid, p.src, k, "MID" + std::to_string(i + 1));
      }
    }
  }

  void Bushes()
  {
    for (Bush &e : d.bushes) {
      const CardFields c = b.Fields(e.src);
      if (!d.pbush_index.count(e.pid)) c.Fail(F(0, 3), "PID", "property " + std::to_string(e.pid) + " is not a PBUSH");
      const PBush &p = d.pbushes[d.pbush_index.at(e.pid)];
      e.na = GridAt(e.ga, e.src, F(0, 4), "GA");
      if (e.gb) e.nb = GridAt(e.gb, e.src, F(0, 5), "GB");
      if (e.gb == e.ga) c.Fail(F(0, 5), "GB", "GA and GB are the same grid");
      if (e.ocid >= 0) Cs(e.ocid, e.src, F(1, 3), "OCID");
      const Vec3 xa = d.grids[e.na].x;
      e.length = e.nb >= 0 ? Norm(Sub(d.grids[e.nb].x, xa)) : 0;
      // Nastran's rules (CBUSH remarks): CID >= 0 gives the axes (at GA for a curvilinear system);
      // else x runs from GA to GB and GO or X (in GA's displacement system) lies in the xy plane;
      // coincident grids (closer than 1e-4) or a grounded bush need CID.
      if (e.cid >= 0) {
        try {
          e.axes = DirectionsAt(Cs(e.cid, e.src, F(0, 9), "CID"), xa);
        } catch (const std::domain_error &x) {
          c.Fail(F(0, 9), "CID", std::string("GA locates the element axes, but ") + x.what());
        }
        continue;
      }
      if (e.nb < 0 || e.length < 1e-4)
        c.Fail(F(0, 9), "CID", std::string(e.nb < 0 ? "GB is blank (a grounded bush)" : "GA and GB coincide (closer than 1e-4)") +
                                 ": the element axes need CID (Nastran's rule)");
      const Vec3 ex = Scale(Sub(d.grids[e.nb].x, xa), 1 / e.length);
      Vec3 v{};
      if (e.go) {
        v = Sub(d.grids[GridAt(e.go, e.src, F(0, 6), "GO")].x, xa);
      } else if (e.has_x) {
        const Axes &cd = d.grids[e.na].cd_axes;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) v[j] += e.x[i] * cd[i][j];
      } else {
        // Axial only: valid with K1 and K4 alone; y and z are then any pair normal to x.
        for (int i : {1, 2, 4, 5})
          if (p.k[i] != 0) c.Fail(F(0, 6), "GO/X1", "no orientation (GO, X or CID) but PBUSH " + std::to_string(p.id) + " has K" + std::to_string(i + 1) + " (only K1 and K4 need no orientation)");
        e.axial_only = true;
        const int m = std::abs(ex[0]) <= std::abs(ex[1]) && std::abs(ex[0]) <= std::abs(ex[2]) ? 0 : std::abs(ex[1]) <= std::abs(ex[2]) ? 1 : 2;
        v = {0, 0, 0};
        v[m] = 1;
      }
      const Vec3 z = Cross(ex, v);
      if (Norm(z) <= 1e-8 * Norm(v) || Norm(v) == 0)
        c.Fail(F(0, 6), e.go ? "GO" : "X1", "the orientation vector is parallel to the line from GA to GB");
      const Vec3 ez = Scale(z, 1 / Norm(z));
      e.axes = {ex, Cross(ez, ex), ez};
    }
  }

  void Fasteners()
  {
    for (Fast &e : d.fasts) {
      const CardFields c = b.Fields(e.src);
      if (!d.pfast_index.count(e.pid)) c.Fail(F(0, 3), "PID", "property " + std::to_string(e.pid) + " is not a PFAST");
      for (int j = 0; j < 2; ++j) {
        const int id = j ? e.idb : e.ida, k = F(0, 5 + j);
        const char *what = j ? "IDB" : "IDA";
        if (e.by_element && d.ShellIndex(id) < 0) c.Fail(k, what, "element " + std::to_string(id) + " is not a CQUAD4 or CTRIA3");
        if (!e.by_element && !d.pshell_index.count(id) && !d.pcomp_index.count(id))
          c.Fail(k, what, "property " + std::to_string(id) + " is not a PSHELL or PCOMP");
      }
      if (e.ga) GridAt(e.ga, e.src, F(0, 8), "GA");
      if (e.gb) GridAt(e.gb, e.src, F(0, 9), "GB");
      e.position = e.gs ? d.grids[GridAt(e.gs, e.src, F(0, 7), "GS")].x : e.xs;
    }
    for (const PFast &p : d.pfasts)
      if (p.mcid >= 0) Cs(p.mcid, p.src, F(0, 4), "MCID");
  }

  void Rigid()
  {
    for (const Rbe2 &e : d.rbe2s) {
      const CardFields c = b.Fields(e.src);
      GridAt(e.gn, e.src, F(0, 3), "GN");
      std::set<int> seen;
      for (int g : e.gm) {
        const int k = FieldOf(c, g, F(0, 5));
        if (d.GridIndex(g) < 0) c.Fail(k ? k : F(0, 5), "GM", "grid " + std::to_string(g) + " is not defined");
        if (g == e.gn) c.Fail(k, "GM", "the independent grid GN is also dependent");
        if (!seen.insert(g).second) c.Fail(k, "GM", "grid " + std::to_string(g) + " is listed twice");
      }
    }
    for (const Rbe3 &e : d.rbe3s) {
      const CardFields c = b.Fields(e.src);
      GridAt(e.refgrid, e.src, F(0, 4), "REFGRID");
      for (const auto &grp : e.groups)
        for (int g : grp.grids)
          if (d.GridIndex(g) < 0) c.Fail(FieldOf(c, g, F(0, 6)), "G", "grid " + std::to_string(g) + " is not defined");
      for (const auto &[g, cm] : e.um)
        if (d.GridIndex(g) < 0) c.Fail(FieldOf(c, g, F(0, 6)), "GM", "grid " + std::to_string(g) + " is not defined");
    }
    for (const Conm2 &m : d.conm2s) {
      GridAt(m.g, m.src, F(0, 3), "G");
      if (m.cid > 0) Cs(m.cid, m.src, F(0, 4), "CID");
    }
  }

  void Constraints()
  {
    std::vector<int> grid_ids;
    for (const Grid &g : d.grids) grid_ids.push_back(g.id);
    std::sort(grid_ids.begin(), grid_ids.end());
    for (const Spc &s : d.spcs) {
      const CardFields c = b.Fields(s.src);
      GridAt(s.grid, s.src, FieldOf(c, s.grid, F(0, 3)), "G");
    }
    for (const Build::Spc1 &s : b.spc1) {
      const CardFields c = b.Fields(s.src);
      for (int g : s.grids) {
        GridAt(g, s.src, FieldOf(c, g, F(0, 4)), "G");
        d.spcs.push_back(Spc{s.sid, g, s.dofs, 0, s.src});
      }
      // Nastran: grids of a THRU range need not exist; those that do not are skipped. Only the
      // grids that exist are visited (a range may span the whole id space).
      for (const auto &r : s.ranges) {
        const auto lo = std::lower_bound(grid_ids.begin(), grid_ids.end(), r[0]), hi = std::upper_bound(grid_ids.begin(), grid_ids.end(), r[1]);
        for (auto it = lo; it != hi; ++it) d.spcs.push_back(Spc{s.sid, *it, s.dofs, 0, s.src});
        const long long found = hi - lo, span = static_cast<long long>(r[1]) - r[0] + 1;
        const int k = FieldOf(c, r[0], F(0, 4));
        if (!found) c.Fail(k, "G", "no grid of the range " + std::to_string(r[0]) + " THRU " + std::to_string(r[1]) + " exists");
        if (found < span)
          b.Note(s.src, "SPC1 " + std::to_string(s.sid) + ": " + std::to_string(span - found) + " grids of " + std::to_string(r[0]) +
                          " THRU " + std::to_string(r[1]) + " do not exist and are skipped");
      }
    }
    std::set<int> spc_sets;
    for (const Spc &s : d.spcs) spc_sets.insert(s.sid);
    std::set<int> adds;
    for (const SpcAdd &a : d.spcadds) adds.insert(a.sid);
    for (const SpcAdd &a : d.spcadds) {
      const CardFields c = b.Fields(a.src);
      if (spc_sets.count(a.sid)) c.Fail(F(0, 2), "SID", "set " + std::to_string(a.sid) + " is both an SPCADD and an SPC/SPC1 set");
      for (int s : a.sets) {
        const int k = FieldOf(c, s, F(0, 3));
        if (adds.count(s)) c.Fail(k, "S", "an SPCADD cannot include another SPCADD (" + std::to_string(s) + ")");
        if (!spc_sets.count(s)) c.Fail(k, "S", "no SPC or SPC1 set " + std::to_string(s));
      }
    }
  }

  void Loads()
  {
    for (PointLoad &l : d.point_loads) {
      const int g = GridAt(l.grid, l.src, F(0, 3), "G");
      Axes dir = Basic().axes;
      try {
        dir = DirectionsAt(Cs(l.cid, l.src, F(0, 4), "CID"), d.grids[g].x);
      } catch (const std::domain_error &x) {
        b.Fields(l.src).Fail(F(0, 4), "CID", std::string("at grid ") + std::to_string(l.grid) + ": " + x.what());
      }
      l.basic = {0, 0, 0};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) l.basic[j] += l.scale * l.n[i] * dir[i][j];
    }
    std::vector<int> shell_ids;
    for (const Shell &e : d.shells) shell_ids.push_back(e.id);
    std::sort(shell_ids.begin(), shell_ids.end());
    for (const Build::Pload4 &r : b.pload4) {
      const CardFields c = b.Fields(r.proto.src);
      if (r.proto.has_direction) Cs(r.proto.cid, r.proto.src, F(1, 2), "CID");
      const auto lo = std::lower_bound(shell_ids.begin(), shell_ids.end(), r.eid1), hi = std::upper_bound(shell_ids.begin(), shell_ids.end(), r.eid2);
      for (auto it = lo; it != hi; ++it) {
        Pressure p = r.proto;
        p.element = *it;
        p.shell = d.ShellIndex(*it);
        d.pressures.push_back(p);
      }
      const long long found = hi - lo, span = static_cast<long long>(r.eid2) - r.eid1 + 1;
      if (r.eid1 == r.eid2 && !found) c.Fail(F(0, 3), "EID", "element " + std::to_string(r.eid1) + " is not a CQUAD4 or CTRIA3");
      if (!found) c.Fail(F(0, 3), "EID", "no CQUAD4 or CTRIA3 in " + std::to_string(r.eid1) + " THRU " + std::to_string(r.eid2));
      if (found < span)
        b.Note(r.proto.src, "PLOAD4 " + std::to_string(r.proto.sid) + ": " + std::to_string(span - found) + " ids of " +
                              std::to_string(r.eid1) + " THRU " + std::to_string(r.eid2) + " are not shells and are skipped");
    }
    std::set<int> direct, combos;
    for (const PointLoad &l : d.point_loads) direct.insert(l.sid);
    for (const Pressure &p : d.pressures) direct.insert(p.sid);
    for (const LoadCombination &l : d.load_combinations) combos.insert(l.sid);
    for (const LoadCombination &l : d.load_combinations) {
      const CardFields c = b.Fields(l.src);
      if (direct.count(l.sid)) c.Fail(F(0, 2), "SID", "set " + std::to_string(l.sid) + " is both a LOAD combination and a FORCE/MOMENT/PLOAD4 set");
      for (size_t i = 0; i < l.sets.size(); ++i) {
        const int k = FieldOf(c, l.sets[i], F(0, 5));
        const std::string what = "L" + std::to_string(i + 1);
        if (combos.count(l.sets[i])) c.Fail(k, what, "a LOAD cannot include another LOAD (" + std::to_string(l.sets[i]) + ")");
        if (!direct.count(l.sets[i])) c.Fail(k, what, "no FORCE, MOMENT or PLOAD4 set " + std::to_string(l.sets[i]));
      }
    }
  }

  void CaseControl()
  {
    std::set<int> loads, spcs;
    for (const PointLoad &l : d.point_loads) loads.insert(l.sid);
    for (const Pressure &p : d.pressures) loads.insert(p.sid);
    for (const LoadCombination &l : d.load_combinations) loads.insert(l.sid);
    for (const Spc &s : d.spcs) spcs.insert(s.sid);
    for (const SpcAdd &a : d.spcadds) spcs.insert(a.sid);
    const auto fail = [&](const Source &at, const std::string &key, const std::string &what) {
      throw Error(d.Where(at) + ": " + what, d.files[at.file], at.line, key, 0);
    };
    for (const Subcase &s : d.subcases) {
      const std::string sc = " (subcase " + std::to_string(s.id) + ")";
      if (s.load && !loads.count(s.load))
        fail(s.load_src, "LOAD", "LOAD = " + std::to_string(s.load) + sc + ": no LOAD, FORCE, MOMENT or PLOAD4 set " + std::to_string(s.load) + " in the bulk data");
      if (s.spc && !spcs.count(s.spc))
        fail(s.spc_src, "SPC", "SPC = " + std::to_string(s.spc) + sc + ": no SPCADD, SPC or SPC1 set " + std::to_string(s.spc) + " in the bulk data");
    }
  }
};

} // namespace

void Resolve(Build &b)
{
  Resolver r{b, b.deck};
  r.Ids();
  r.Coords();
  r.Grids();
  r.Shells();
  r.Properties();
  r.Bushes();
  r.Fasteners();
  r.Rigid();
  r.Constraints();
  r.Loads();
  r.CaseControl();
}

} // namespace boltnet::nastran
