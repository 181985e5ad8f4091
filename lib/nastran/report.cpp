// The deck summary (report.hpp). Its lines are stable: scripts and tests read them
// (scripts/verify-nastran-decks, test/check_nastran_wingbox.py).
#include "nastran/report.hpp"

#include "nastran/expand.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace boltnet::nastran {

Box BoundingBox(const Deck &d)
{
  Box b;
  for (const Grid &g : d.grids)
    for (int j = 0; j < 3; ++j) {
      b.lo[j] = b.empty ? g.x[j] : std::min(b.lo[j], g.x[j]);
      b.hi[j] = b.empty ? g.x[j] : std::max(b.hi[j], g.x[j]);
      if (j == 2) b.empty = false;
    }
  return b;
}

namespace {

std::string G(double v)
{
  char s[32];
  std::snprintf(s, sizeof s, "%.12g", v == 0 ? 0.0 : v); // no "-0"
  return s;
}

std::string V(const Vec3 &v) { return "[" + G(v[0]) + ", " + G(v[1]) + ", " + G(v[2]) + "]"; }

void PrintUnused(std::ostringstream &o, const Deck &d, const std::map<std::string, Unused> &m)
{
  for (const auto &[name, u] : m) {
    o << "  " << name << " " << u.count << " (first at " << d.Where(u.first) << ")";
    if (!u.details.empty()) {
      o << ":";
      for (const std::string &s : u.details) o << " " << s;
    }
    o << "\n";
  }
}

} // namespace

std::string Summary(const Deck &d)
{
  std::ostringstream o;
  o << "Nastran deck " << d.files[0] << " (" << d.files.size() << " file" << (d.files.size() > 1 ? "s" : "") << ")\n";
  for (size_t i = 1; i < d.files.size(); ++i) o << "  INCLUDE " << d.files[i] << "\n";
  o << "solution: " << (d.sol.empty() ? "(none given)" : "SOL " + d.sol) << "\n";
  int used = 0, unused = 0;
  for (const auto &[n, c] : d.used) used += c;
  for (const auto &[n, u] : d.unused) unused += u.count;
  o << "cards used: " << used << "\n";
  for (const auto &[name, count] : d.used) o << "  " << name << " " << count << "\n";
  o << "cards not used: " << unused << "\n";
  PrintUnused(o, d, d.unused);
  int unused_case = 0;
  for (const auto &[n, u] : d.unused_case) unused_case += u.count;
  o << "case control commands not used: " << unused_case << "\n";
  PrintUnused(o, d, d.unused_case);
  const Box b = BoundingBox(d);
  if (b.empty) o << "bounding box: (no grids)\n";
  else o << "bounding box: x [" << G(b.lo[0]) << ", " << G(b.hi[0]) << "] y [" << G(b.lo[1]) << ", " << G(b.hi[1]) << "] z [" << G(b.lo[2]) << ", " << G(b.hi[2]) << "]\n";
  int quads = 0;
  for (const Shell &e : d.shells) quads += e.kind == ShellKind::Quad4;
  o << "model: " << d.grids.size() << " grids, " << quads << " CQUAD4, " << d.shells.size() - quads << " CTRIA3, " << d.bushes.size() << " CBUSH, "
    << d.fasts.size() << " CFAST, " << d.rbe2s.size() << " RBE2, " << d.rbe3s.size() << " RBE3\n";
  o << "subcases: " << d.subcases.size() << "\n";
  for (const Subcase &s : d.subcases) {
    const auto spc = ExpandSpc(d, s.spc);
    int dofs = 0;
    for (const Constraint &c : spc)
      for (int i = 0; i < 6; ++i) dofs += (c.dofs >> i) & 1u;
    const StaticLoad load = ExpandLoad(d, s.load);
    const Resultant r = LoadResultant(d, load);
    o << "  subcase " << s.id << (s.label.empty() ? "" : " '" + s.label + "'") << ": SPC " << s.spc << " (" << spc.size() << " grids, " << dofs
      << " dof), LOAD " << s.load << " (" << load.nodal.size() << " loaded grids, " << load.pressures.size() << " pressures)\n";
    o << "    force " << V(r.force) << " moment about the origin " << V(r.moment) << "\n";
  }
  o << "notes: " << d.notes.size() << "\n";
  for (const std::string &n : d.notes) o << "  " << n << "\n";
  return o.str();
}

} // namespace boltnet::nastran
