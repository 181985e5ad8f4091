// Model cards: grids, coordinate systems, shell elements, shell properties and materials. Field
// positions follow the Nastran Quick Reference Guide (F(line, field), small-field numbering).
#include "nastran/build.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace boltnet::nastran {

namespace {

constexpr double kBlank = std::numeric_limits<double>::quiet_NaN();

std::string Num(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

void Grid_(const CardFields &c, Build &b, const Source &src)
{
  Grid g;
  g.id = c.Id(F(0, 2), "ID");
  g.cp = c.CidOr(F(0, 3), "CP", 0);
  g.input = {c.RealOr(F(0, 4), "X1", 0), c.RealOr(F(0, 5), "X2", 0), c.RealOr(F(0, 6), "X3", 0)};
  g.cd = c.CidOr(F(0, 7), "CD", 0);
  g.ps = c.Dofs(F(0, 8), "PS", false);
  if (c.IntOr(F(0, 9), "SEID", 0) != 0) c.Fail(F(0, 9), "SEID", "superelements are not supported");
  ExpectEnd(c, F(1, 2));
  g.src = src;
  b.grid_blank.push_back({c.Blank(F(0, 3)), c.Blank(F(0, 7)), c.Blank(F(0, 8))});
  b.deck.grids.push_back(g);
}

void GrdSet_(const CardFields &c, Build &b, const Source &src)
{
  if (b.grdset.given) c.FailCard("a second GRDSET (only one is allowed)");
  for (int k : {F(0, 2), F(0, 4), F(0, 5), F(0, 6)})
    if (!c.Blank(k)) c.Fail(k, "blank", "must be blank");
  b.grdset.given = true;
  b.grdset.cp = c.CidOr(F(0, 3), "CP", 0);
  b.grdset.cd = c.CidOr(F(0, 7), "CD", 0);
  b.grdset.ps = c.Dofs(F(0, 8), "PS", false);
  if (c.IntOr(F(0, 9), "SEID", 0) != 0) c.Fail(F(0, 9), "SEID", "superelements are not supported");
  ExpectEnd(c, F(1, 2));
}

void Cord2_(const CardFields &c, Build &b, const Source &src, CoordKind kind)
{
  CoordSystem cs;
  cs.kind = kind;
  cs.id = c.Id(F(0, 2), "CID");
  cs.rid = c.CidOr(F(0, 3), "RID", 0);
  cs.a = {c.RealOr(F(0, 4), "A1", 0), c.RealOr(F(0, 5), "A2", 0), c.RealOr(F(0, 6), "A3", 0)};
  cs.b = {c.RealOr(F(0, 7), "B1", 0), c.RealOr(F(0, 8), "B2", 0), c.RealOr(F(0, 9), "B3", 0)};
  cs.c = {c.RealOr(F(1, 2), "C1", 0), c.RealOr(F(1, 3), "C2", 0), c.RealOr(F(1, 4), "C3", 0)};
  ExpectEnd(c, F(1, 5));
  cs.src = src;
  b.deck.coords.push_back(cs);
}

// THETA (real, degrees) or MCID (integer >= 0) in one field.
void ThetaMcid(const CardFields &c, int k, Shell &e)
{
  if (c.KindOf(k) == Kind::Integer) {
    e.mcid = c.Int(k, "MCID");
    if (e.mcid < 0) c.Fail(k, "MCID", "a material coordinate system must be >= 0");
  } else {
    e.theta = c.RealOr(k, "THETA", 0);
  }
}

void Shell_(const CardFields &c, Build &b, const Source &src, ShellKind kind)
{
  Shell e;
  e.kind = kind;
  const int n = kind == ShellKind::Quad4 ? 4 : 3;
  e.id = c.Id(F(0, 2), "EID");
  e.pid = c.IdOr(F(0, 3), "PID", e.id);
  static const char *g[] = {"G1", "G2", "G3", "G4"};
  for (int i = 0; i < n; ++i) e.grid[i] = c.Id(F(0, 4 + i), g[i]);
  ThetaMcid(c, F(0, 4 + n), e);
  e.zoffs = c.RealOr(F(0, 5 + n), "ZOFFS", 0);
  if (n == 3 && !c.Blank(F(0, 9))) c.Fail(F(0, 9), "blank", "must be blank");
  for (int k : {F(1, 2), F(1, 3)})
    if (!c.Blank(k)) c.Fail(k, "blank", "must be blank");
  e.tflag = c.IntOr(F(1, 4), "TFLAG", 0);
  if (e.tflag != 0 && e.tflag != 1) c.Fail(F(1, 4), "TFLAG", "must be 0 (thicknesses) or 1 (fractions of T)");
  static const char *t[] = {"T1", "T2", "T3", "T4"};
  e.t = {kBlank, kBlank, kBlank, kBlank};
  for (int i = 0; i < n; ++i) {
    e.t[i] = c.RealOr(F(1, 5 + i), t[i], kBlank);
    if (!std::isnan(e.t[i]) && !(e.t[i] > 0)) c.Fail(F(1, 5 + i), t[i], "a thickness must be > 0");
  }
  ExpectEnd(c, F(1, 5 + n));
  e.src = src;
  b.deck.shells.push_back(e);
}

void PShell_(const CardFields &c, Build &b, const Source &src)
{
  PShell p;
  p.id = c.Id(F(0, 2), "PID");
  p.mid1 = c.IdOr(F(0, 3), "MID1", 0);
  p.t = c.RealOr(F(0, 4), "T", kBlank);
  if (!std::isnan(p.t) && !(p.t > 0)) c.Fail(F(0, 4), "T", "the thickness must be > 0");
  p.mid2 = c.IntOr(F(0, 5), "MID2", 0);
  if (p.mid2 < -1) c.Fail(F(0, 5), "MID2", "must be a material id, -1 (plane strain) or blank");
  p.bending = c.RealOr(F(0, 6), "12I/T**3", 1.0);
  if (!(p.bending > 0)) c.Fail(F(0, 6), "12I/T**3", "must be > 0");
  p.mid3 = c.IdOr(F(0, 7), "MID3", 0);
  p.shear = c.RealOr(F(0, 8), "TS/T", 0.833333);
  if (!(p.shear > 0)) c.Fail(F(0, 8), "TS/T", "must be > 0");
  p.nsm = c.RealOr(F(0, 9), "NSM", 0);
  const double half = std::isnan(p.t) ? 0 : p.t / 2;
  p.z1 = c.RealOr(F(1, 2), "Z1", -half);
  p.z2 = c.RealOr(F(1, 3), "Z2", half);
  p.mid4 = c.IdOr(F(1, 4), "MID4", 0);
  ExpectEnd(c, F(1, 5));
  if (p.mid1 == 0 && p.mid2 == 0 && p.mid3 == 0 && p.mid4 == 0) c.FailCard("no material: give MID1 and/or MID2");
  p.src = src;
  b.deck.pshells.push_back(p);
}

void PComp_(const CardFields &c, Build &b, const Source &src)
{
  PComp p;
  p.id = c.Id(F(0, 2), "PID");
  p.z0_given = !c.Blank(F(0, 3));
  p.z0 = c.RealOr(F(0, 3), "Z0", 0);
  p.nsm = c.RealOr(F(0, 4), "NSM", 0);
  p.sb = c.RealOr(F(0, 5), "SB", 0);
  p.ft = c.Word(F(0, 6), "FT");
  if (!p.ft.empty() && p.ft != "HILL" && p.ft != "HOFF" && p.ft != "TSAI" && p.ft != "STRN")
    c.Fail(F(0, 6), "FT", "'" + c.Text(F(0, 6)) + "' is not a failure theory (HILL, HOFF, TSAI, STRN)");
  p.tref = c.RealOr(F(0, 7), "TREF", 0);
  p.ge = c.RealOr(F(0, 8), "GE", 0);
  const std::string lam = c.Word(F(0, 9), "LAM");
  if (lam.empty()) p.lam = Lam::Blank;
  else if (lam == "SYM") p.lam = Lam::Sym;
  else if (lam == "MEM") p.lam = Lam::Mem;
  else if (lam == "BEND") p.lam = Lam::Bend;
  else if (lam == "SMEAR") p.lam = Lam::Smear;
  else if (lam == "SMCORE") p.lam = Lam::Smcore;
  else c.Fail(F(0, 9), "LAM", "'" + c.Text(F(0, 9)) + "' is not a LAM option (blank, SYM, MEM, BEND, SMEAR, SMCORE)");
  // Plies: MIDi Ti THETAi SOUTi, four per half line. A blank MID or T repeats the previous ply's;
  // an all-blank group is no ply.
  Ply prev;
  for (int k = F(1, 2); k < c.Size(); k += 4) {
    if (c.Blank(k) && c.Blank(k + 1) && c.Blank(k + 2) && c.Blank(k + 3)) continue;
    const std::string i = std::to_string(p.plies.size() + 1);
    Ply ply;
    ply.mid = p.plies.empty() ? c.Id(k, ("MID" + i).c_str()) : c.IdOr(k, ("MID" + i).c_str(), prev.mid);
    ply.t = p.plies.empty() ? c.Real(k + 1, ("T" + i).c_str()) : c.RealOr(k + 1, ("T" + i).c_str(), prev.t);
    if (!(ply.t > 0)) c.Fail(k + 1, "T" + i, "a ply thickness must be > 0");
    ply.theta = c.RealOr(k + 2, ("THETA" + i).c_str(), 0);
    const std::string sout = c.Word(k + 3, ("SOUT" + i).c_str());
    if (!sout.empty() && sout != "YES" && sout != "NO") c.Fail(k + 3, "SOUT" + i, "must be YES, NO or blank");
    ply.sout = sout == "YES";
    p.plies.push_back(ply);
    prev = ply;
  }
  if (p.plies.empty()) c.Fail(F(1, 2), "MID1", "a PCOMP needs at least one ply");
  if (!p.z0_given) p.z0 = -p.Thickness() / 2;
  p.src = src;
  b.deck.pcomps.push_back(p);
}

void Mat1_(const CardFields &c, Build &b, const Source &src)
{
  Mat1 m;
  m.id = c.Id(F(0, 2), "MID");
  const bool eb = c.Blank(F(0, 3)), gb = c.Blank(F(0, 4)), nb = c.Blank(F(0, 5));
  m.e = c.RealOr(F(0, 3), "E", 0);
  m.g = c.RealOr(F(0, 4), "G", 0);
  m.nu = c.RealOr(F(0, 5), "NU", 0);
  if (m.e < 0) c.Fail(F(0, 3), "E", "must be >= 0");
  if (m.g < 0) c.Fail(F(0, 4), "G", "must be >= 0");
  if (!nb && !(m.nu > -1 && m.nu <= 0.5)) c.Fail(F(0, 5), "NU", Num(m.nu) + " is outside (-1, 0.5]");
  // Nastran's rule (MAT1 remarks): one of E, G, NU blank is computed from E = 2 (1 + NU) G; with E
  // and NU, or G and NU, both blank, both are 0.
  if (eb && gb) c.Fail(F(0, 3), "E", "E and G are both blank: give E or G");
  if (!eb && !gb && nb) {
    if (m.g == 0) c.Fail(F(0, 4), "G", "G = 0 with NU blank: NU = E/(2G) - 1 is undefined");
    m.nu = m.e / (2 * m.g) - 1;
    if (!(m.nu > -1 && m.nu <= 0.5)) c.Fail(F(0, 5), "NU", "blank, and E and G give NU = E/(2G) - 1 = " + Num(m.nu) + ", outside (-1, 0.5]");
  } else if (!eb && gb && !nb) {
    m.g = m.e / (2 * (1 + m.nu));
  } else if (eb && !gb && !nb) {
    m.e = 2 * (1 + m.nu) * m.g;
  } else if (!eb && gb && nb) {
    b.Note(src, "MAT1 " + std::to_string(m.id) + ": G and NU blank, so G = 0 and NU = 0 (Nastran's rule): no shear stiffness");
  } else if (eb && !gb && nb) {
    b.Note(src, "MAT1 " + std::to_string(m.id) + ": E and NU blank, so E = 0 and NU = 0 (Nastran's rule): shear stiffness only");
  } else if (m.g > 0 && std::abs(m.e / (2 * (1 + m.nu) * m.g) - 1) > 0.01) {
    b.Note(src, "MAT1 " + std::to_string(m.id) + ": E, G and NU are all given and E/(2(1+NU)G) = " + Num(m.e / (2 * (1 + m.nu) * m.g)) +
                  " (Nastran warns above 1% and uses the three values as given)");
  }
  m.rho = c.RealOr(F(0, 6), "RHO", 0);
  m.a = c.RealOr(F(0, 7), "A", 0);
  m.tref = c.RealOr(F(0, 8), "TREF", 0);
  m.ge = c.RealOr(F(0, 9), "GE", 0);
  c.RealOr(F(1, 2), "ST", 0), c.RealOr(F(1, 3), "SC", 0), c.RealOr(F(1, 4), "SS", 0);
  c.CidOr(F(1, 5), "MCSID", 0);
  ExpectEnd(c, F(1, 6));
  m.src = src;
  b.deck.mat1s.push_back(m);
}

void Mat8_(const CardFields &c, Build &b, const Source &src)
{
  Mat8 m;
  m.id = c.Id(F(0, 2), "MID");
  m.e1 = c.Real(F(0, 3), "E1");
  m.e2 = c.Real(F(0, 4), "E2");
  if (!(m.e1 > 0)) c.Fail(F(0, 3), "E1", "must be > 0");
  if (!(m.e2 > 0)) c.Fail(F(0, 4), "E2", "must be > 0");
  m.nu12 = c.Real(F(0, 5), "NU12");
  if (!(m.nu12 * m.nu12 * m.e2 / m.e1 < 1)) c.Fail(F(0, 5), "NU12", "NU12^2 E2/E1 must be < 1 (a positive definite ply)");
  m.g12 = c.RealOr(F(0, 6), "G12", 0);
  m.g1z = c.RealOr(F(0, 7), "G1Z", 0);
  m.g2z = c.RealOr(F(0, 8), "G2Z", 0);
  if (m.g12 < 0) c.Fail(F(0, 6), "G12", "must be >= 0");
  if (m.g1z < 0) c.Fail(F(0, 7), "G1Z", "must be >= 0 (blank: rigid in transverse shear)");
  if (m.g2z < 0) c.Fail(F(0, 8), "G2Z", "must be >= 0 (blank: rigid in transverse shear)");
  m.rho = c.RealOr(F(0, 9), "RHO", 0);
  m.a1 = c.RealOr(F(1, 2), "A1", 0);
  m.a2 = c.RealOr(F(1, 3), "A2", 0);
  m.tref = c.RealOr(F(1, 4), "TREF", 0);
  static const char *allow[] = {"Xt", "Xc", "Yt", "Yc", "S"};
  for (int i = 0; i < 5; ++i) c.RealOr(F(1, 5 + i), allow[i], 0);
  c.RealOr(F(2, 2), "GE", 0), c.RealOr(F(2, 3), "F12", 0), c.RealOr(F(2, 4), "STRN", 0);
  ExpectEnd(c, F(2, 5));
  m.src = src;
  b.deck.mat8s.push_back(m);
}

} // namespace

void ExpectEnd(const CardFields &c, int k)
{
  for (; k < c.Size(); ++k)
    if (!c.Blank(k)) c.Fail(k, "after the last field of " + c.Name(), "unexpected data '" + c.Text(k) + "'");
}

bool ParseModelCard(const CardFields &c, Build &b, const Source &src)
{
  const std::string &n = c.Name();
  if (n == "GRID") Grid_(c, b, src);
  else if (n == "GRDSET") GrdSet_(c, b, src);
  else if (n == "CORD2R") Cord2_(c, b, src, CoordKind::Rectangular);
  else if (n == "CORD2C") Cord2_(c, b, src, CoordKind::Cylindrical);
  else if (n == "CORD2S") Cord2_(c, b, src, CoordKind::Spherical);
  else if (n == "CQUAD4") Shell_(c, b, src, ShellKind::Quad4);
  else if (n == "CTRIA3") Shell_(c, b, src, ShellKind::Tria3);
  else if (n == "PSHELL") PShell_(c, b, src);
  else if (n == "PCOMP") PComp_(c, b, src);
  else if (n == "MAT1") Mat1_(c, b, src);
  else if (n == "MAT8") Mat8_(c, b, src);
  else return false;
  return true;
}

std::vector<Ply> PComp::Stack() const
{
  std::vector<Ply> s = plies;
  if (lam == Lam::Sym) s.insert(s.end(), plies.rbegin(), plies.rend());
  return s;
}

double PComp::Thickness() const
{
  double t = 0;
  for (const Ply &p : plies) t += p.t;
  return lam == Lam::Sym ? 2 * t : t;
}

} // namespace boltnet::nastran
