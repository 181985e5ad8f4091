// Connection, constraint and load cards: PBUSH, CBUSH, PFAST, CFAST, RBE2, RBE3, CONM2, SPC, SPC1,
// SPCADD, FORCE, MOMENT, LOAD, PLOAD4. References are checked later (resolve.cpp).
#include "nastran/build.hpp"

#include <algorithm>
#include <set>

namespace boltnet::nastran {

namespace {

void PBush_(const CardFields &c, Build &b, const Source &src)
{
  PBush p;
  p.id = c.Id(F(0, 2), "PID");
  // One keyword line after another: K (stiffness) is used; B, GE, RCV, M (damping, structural
  // damping, stress recovery, mass) are dynamics or output and are noted.
  bool k_seen = false;
  for (int line = 0; F(line, 2) < c.Size(); ++line) {
    if (line > 0 && !c.Blank(F(line, 2))) c.Fail(F(line, 2), "blank", "must be blank");
    const std::string key = c.Word(F(line, 3), "keyword");
    if (key.empty()) {
      ExpectEnd(c, F(line, 3)); // a blank keyword ends the card: nothing may follow
      break;
    }
    if (key == "K") {
      if (k_seen) c.Fail(F(line, 3), "keyword", "a second K line");
      k_seen = true;
      static const char *names[] = {"K1", "K2", "K3", "K4", "K5", "K6"};
      for (int i = 0; i < 6; ++i) {
        p.k_given[i] = !c.Blank(F(line, 4 + i));
        p.k[i] = c.RealOr(F(line, 4 + i), names[i], 0);
      }
    } else if (key == "B" || key == "GE" || key == "RCV" || key == "M") {
      for (int i = 0; i < 6; ++i) c.RealOr(F(line, 4 + i), (key + std::to_string(i + 1)).c_str(), 0);
      b.Note(src, "PBUSH " + std::to_string(p.id) + ": the " + key + " line is read and not used in statics");
    } else {
      c.Fail(F(line, 3), "keyword", "'" + c.Text(F(line, 3)) + "' is not a PBUSH line (K, B, GE, RCV, M)");
    }
  }
  if (!k_seen) c.FailCard("no K line: a bush without stiffness");
  p.src = src;
  b.deck.pbushes.push_back(p);
}

void CBush_(const CardFields &c, Build &b, const Source &src)
{
  Bush e;
  e.id = c.Id(F(0, 2), "EID");
  e.pid = c.IdOr(F(0, 3), "PID", e.id);
  e.ga = c.Id(F(0, 4), "GA");
  e.gb = c.IdOr(F(0, 5), "GB", 0);
  if (c.KindOf(F(0, 6)) == Kind::Integer) {
    e.go = c.Id(F(0, 6), "GO");
    for (int k : {F(0, 7), F(0, 8)})
      if (!c.Blank(k)) c.Fail(k, k == F(0, 7) ? "X2" : "X3", "must be blank when GO (a grid) gives the orientation");
  } else if (!c.Blank(F(0, 6)) || !c.Blank(F(0, 7)) || !c.Blank(F(0, 8))) {
    e.has_x = true;
    e.x = {c.RealOr(F(0, 6), "X1", 0), c.RealOr(F(0, 7), "X2", 0), c.RealOr(F(0, 8), "X3", 0)};
  }
  e.cid = c.CidOr(F(0, 9), "CID", -1);
  e.s = c.RealOr(F(1, 2), "S", 0.5);
  if (!(e.s >= 0 && e.s <= 1)) c.Fail(F(1, 2), "S", "must lie in [0, 1]");
  e.ocid = c.IntOr(F(1, 3), "OCID", -1);
  if (e.ocid < -1) c.Fail(F(1, 3), "OCID", "must be -1 or a coordinate system id");
  e.offset = {c.RealOr(F(1, 4), "S1", 0), c.RealOr(F(1, 5), "S2", 0), c.RealOr(F(1, 6), "S3", 0)};
  ExpectEnd(c, F(1, 7));
  e.src = src;
  b.deck.bushes.push_back(e);
}

void PFast_(const CardFields &c, Build &b, const Source &src)
{
  PFast p;
  p.id = c.Id(F(0, 2), "PID");
  p.d = c.Real(F(0, 3), "D");
  if (!(p.d > 0)) c.Fail(F(0, 3), "D", "the fastener diameter must be > 0");
  p.mcid = c.IntOr(F(0, 4), "MCID", -1);
  if (p.mcid < -1) c.Fail(F(0, 4), "MCID", "must be -1 or a coordinate system id");
  p.mflag = c.IntOr(F(0, 5), "MFLAG", 0);
  if (p.mflag != 0 && p.mflag != 1) c.Fail(F(0, 5), "MFLAG", "must be 0 or 1");
  static const char *names[] = {"KT1", "KT2", "KT3", "KR1", "KR2", "KR3"};
  static const int   ks[] = {F(0, 6), F(0, 7), F(0, 8), F(0, 9), F(1, 2), F(1, 3)};
  for (int i = 0; i < 6; ++i) {
    p.k[i] = i < 3 ? c.Real(ks[i], names[i]) : c.RealOr(ks[i], names[i], 0);
    if (p.k[i] < 0) c.Fail(ks[i], names[i], "a stiffness must be >= 0");
  }
  p.mass = c.RealOr(F(1, 4), "MASS", 0);
  p.ge = c.RealOr(F(1, 5), "GE", 0);
  ExpectEnd(c, F(1, 6));
  p.src = src;
  b.deck.pfasts.push_back(p);
}

void CFast_(const CardFields &c, Build &b, const Source &src)
{
  Fast e;
  e.id = c.Id(F(0, 2), "EID");
  e.pid = c.IdOr(F(0, 3), "PID", e.id);
  const std::string type = c.Word(F(0, 4), "TYPE");
  if (type != "PROP" && type != "ELEM") c.Fail(F(0, 4), "TYPE", "must be PROP or ELEM");
  e.by_element = type == "ELEM";
  e.ida = c.Id(F(0, 5), "IDA");
  e.idb = c.Id(F(0, 6), "IDB");
  if (e.ida == e.idb) c.Fail(F(0, 6), "IDB", "IDA and IDB must differ");
  e.gs = c.IdOr(F(0, 7), "GS", 0);
  e.ga = c.IdOr(F(0, 8), "GA", 0);
  e.gb = c.IdOr(F(0, 9), "GB", 0);
  const bool xs = !c.Blank(F(1, 2)) || !c.Blank(F(1, 3)) || !c.Blank(F(1, 4));
  e.xs = {c.RealOr(F(1, 2), "XS", 0), c.RealOr(F(1, 3), "YS", 0), c.RealOr(F(1, 4), "ZS", 0)};
  if (e.gs == 0 && !xs) c.Fail(F(0, 7), "GS", "give the fastener's location: GS or XS, YS, ZS");
  if (e.gs != 0 && xs) c.Fail(F(1, 2), "XS", "give GS or XS, YS, ZS, not both");
  ExpectEnd(c, F(1, 5));
  e.src = src;
  b.deck.fasts.push_back(e);
}

void Rbe2_(const CardFields &c, Build &b, const Source &src)
{
  Rbe2 e;
  e.id = c.Id(F(0, 2), "EID");
  e.gn = c.Id(F(0, 3), "GN");
  e.cm = c.Dofs(F(0, 4), "CM", true);
  // GM1 GM2 ... (or GM1 THRU GM2), then optionally ALPHA (a real) and TREF.
  int k = F(0, 5);
  for (; k < c.Size(); ++k) {
    const Kind kind = c.KindOf(k);
    if (kind == Kind::Blank) continue;
    if (kind == Kind::Real) break;
    if (kind == Kind::Word && c.Word(k, "THRU") == "THRU") {
      if (e.gm.empty() || c.KindOf(k + 1) != Kind::Integer) c.Fail(k, "THRU", "THRU needs a grid before and after it");
      const int last = c.Id(k + 1, "GM");
      if (last <= e.gm.back()) c.Fail(k + 1, "GM", "the end of a THRU range must exceed its start");
      if (last - e.gm.back() > 1000000) c.Fail(k + 1, "GM", "a THRU range of more than 1,000,000 grids (every one must exist)");
      for (int g = e.gm.back() + 1; g <= last; ++g) e.gm.push_back(g);
      ++k;
      continue;
    }
    e.gm.push_back(c.Id(k, "GM"));
  }
  if (e.gm.empty()) c.Fail(F(0, 5), "GM1", "an RBE2 needs at least one dependent grid");
  if (k < c.Size()) {
    e.alpha = c.Real(k, "ALPHA");
    c.RealOr(k + 1, "TREF", 0);
    ExpectEnd(c, k + 2);
  }
  e.src = src;
  b.deck.rbe2s.push_back(e);
}

void Rbe3_(const CardFields &c, Build &b, const Source &src)
{
  Rbe3 e;
  e.id = c.Id(F(0, 2), "EID");
  if (!c.Blank(F(0, 3))) c.Fail(F(0, 3), "blank", "must be blank");
  e.refgrid = c.Id(F(0, 4), "REFGRID");
  e.refc = c.Dofs(F(0, 5), "REFC", true);
  // WT1 C1 G1,1 G1,2 ... WT2 C2 ..., then "UM" GM1 CM1 ..., then "ALPHA" ALPHA TREF.
  enum { Groups, Um, Alpha } part = Groups;
  int k = F(0, 6);
  while (k < c.Size()) {
    const Kind kind = c.KindOf(k);
    if (kind == Kind::Blank) {
      ++k;
      continue;
    }
    if (kind == Kind::Word) {
      const std::string w = c.Word(k, "keyword");
      if (w == "UM" && part == Groups) part = Um;
      else if (w == "ALPHA" && part != Alpha) part = Alpha;
      else c.Fail(k, "keyword", "'" + c.Text(k) + "' is out of place (RBE3: weights and grids, then UM, then ALPHA)");
      ++k;
      continue;
    }
    if (part == Groups) {
      if (kind == Kind::Real) {
        Rbe3::Group g;
        const std::string i = std::to_string(e.groups.size() + 1);
        g.weight = c.Real(k, ("WT" + i).c_str());
        if (!(g.weight > 0)) c.Fail(k, "WT" + i, "a weight must be > 0");
        g.c = c.Dofs(k + 1, ("C" + i).c_str(), true);
        e.groups.push_back(g);
        k += 2;
        continue;
      }
      if (e.groups.empty()) c.Fail(k, "WT1", "'" + c.Text(k) + "' is not a weight (a real, e.g. 1.)");
      e.groups.back().grids.push_back(c.Id(k, "G"));
      ++k;
    } else if (part == Um) {
      const int g = c.Id(k, "GM");
      e.um.push_back({g, c.Dofs(k + 1, "CM", true)});
      k += 2;
    } else {
      e.alpha = c.Real(k, "ALPHA");
      c.RealOr(k + 1, "TREF", 0);
      ExpectEnd(c, k + 2);
      break;
    }
  }
  if (e.groups.empty()) c.Fail(F(0, 6), "WT1", "an RBE3 needs at least one weighted group");
  for (size_t i = 0; i < e.groups.size(); ++i)
    if (e.groups[i].grids.empty()) c.FailCard("weighted group " + std::to_string(i + 1) + " has no grid");
  e.src = src;
  b.deck.rbe3s.push_back(e);
}

void Conm2_(const CardFields &c, Build &b, const Source &src)
{
  Conm2 m;
  m.id = c.Id(F(0, 2), "EID");
  m.g = c.Id(F(0, 3), "G");
  m.cid = c.IntOr(F(0, 4), "CID", 0);
  if (m.cid < -1) c.Fail(F(0, 4), "CID", "must be -1 or a coordinate system id");
  m.m = c.RealOr(F(0, 5), "M", 0);
  m.x = {c.RealOr(F(0, 6), "X1", 0), c.RealOr(F(0, 7), "X2", 0), c.RealOr(F(0, 8), "X3", 0)};
  static const char *names[] = {"I11", "I21", "I22", "I31", "I32", "I33"};
  for (int i = 0; i < 6; ++i) m.i[i] = c.RealOr(F(1, 2 + i), names[i], 0);
  ExpectEnd(c, F(1, 8));
  m.src = src;
  b.deck.conm2s.push_back(m);
  b.Unused("CONM2", src, "read and checked; mass is not used in statics");
}

void Spc_(const CardFields &c, Build &b, const Source &src)
{
  const int sid = c.Id(F(0, 2), "SID");
  for (int j = 0; j < 2; ++j) {
    const int k = F(0, 3 + 3 * j);
    const std::string i = std::to_string(j + 1);
    if (j == 1 && c.Blank(k) && c.Blank(k + 1) && c.Blank(k + 2)) break;
    Spc s;
    s.sid = sid;
    s.grid = c.Id(k, ("G" + i).c_str());
    s.dofs = c.Dofs(k + 1, ("C" + i).c_str(), true);
    s.value = c.RealOr(k + 2, ("D" + i).c_str(), 0);
    s.src = src;
    b.deck.spcs.push_back(s);
  }
  ExpectEnd(c, F(0, 9));
}

void Spc1_(const CardFields &c, Build &b, const Source &src)
{
  Build::Spc1 s;
  s.sid = c.Id(F(0, 2), "SID");
  s.dofs = c.Dofs(F(0, 3), "C", true);
  for (int k = F(0, 4); k < c.Size(); ++k) {
    if (c.Blank(k)) continue;
    if (c.KindOf(k) == Kind::Word && c.Word(k, "THRU") == "THRU") {
      if (s.grids.empty() || c.KindOf(k + 1) != Kind::Integer) c.Fail(k, "THRU", "THRU needs a grid before and after it");
      const int last = c.Id(k + 1, "G");
      if (last <= s.grids.back()) c.Fail(k + 1, "G", "the end of a THRU range must exceed its start");
      s.ranges.push_back({s.grids.back(), last});
      s.grids.pop_back();
      ++k;
      continue;
    }
    s.grids.push_back(c.Id(k, "G"));
  }
  if (s.grids.empty() && s.ranges.empty()) c.Fail(F(0, 4), "G1", "an SPC1 needs at least one grid");
  s.src = src;
  b.spc1.push_back(s);
}

void SpcAdd_(const CardFields &c, Build &b, const Source &src)
{
  SpcAdd a;
  a.sid = c.Id(F(0, 2), "SID");
  for (int k = F(0, 3); k < c.Size(); ++k)
    if (!c.Blank(k)) a.sets.push_back(c.Id(k, "S"));
  if (a.sets.empty()) c.Fail(F(0, 3), "S1", "an SPCADD needs at least one set");
  a.src = src;
  b.deck.spcadds.push_back(a);
}

void PointLoad_(const CardFields &c, Build &b, const Source &src, bool moment)
{
  PointLoad l;
  l.moment = moment;
  l.sid = c.Id(F(0, 2), "SID");
  l.grid = c.Id(F(0, 3), "G");
  l.cid = c.CidOr(F(0, 4), "CID", 0);
  l.scale = c.Real(F(0, 5), moment ? "M" : "F");
  l.n = {c.RealOr(F(0, 6), "N1", 0), c.RealOr(F(0, 7), "N2", 0), c.RealOr(F(0, 8), "N3", 0)};
  ExpectEnd(c, F(0, 9));
  l.src = src;
  b.deck.point_loads.push_back(l);
}

void Load_(const CardFields &c, Build &b, const Source &src)
{
  LoadCombination l;
  l.sid = c.Id(F(0, 2), "SID");
  l.scale = c.Real(F(0, 3), "S");
  for (int k = F(0, 4); k < c.Size(); k += 2) {
    if (c.Blank(k) && c.Blank(k + 1)) continue;
    const std::string i = std::to_string(l.sets.size() + 1);
    l.scales.push_back(c.Real(k, ("S" + i).c_str()));
    const int set = c.Id(k + 1, ("L" + i).c_str());
    if (std::find(l.sets.begin(), l.sets.end(), set) != l.sets.end()) c.Fail(k + 1, "L" + i, "load set " + std::to_string(set) + " is listed twice");
    l.sets.push_back(set);
  }
  if (l.sets.empty()) c.Fail(F(0, 4), "S1", "a LOAD needs at least one (scale, set) pair");
  l.src = src;
  b.deck.load_combinations.push_back(l);
}

void Pload4_(const CardFields &c, Build &b, const Source &src)
{
  Build::Pload4 r;
  Pressure &p = r.proto;
  p.sid = c.Id(F(0, 2), "SID");
  r.eid1 = r.eid2 = c.Id(F(0, 3), "EID");
  p.p[0] = c.Real(F(0, 4), "P1");
  p.p[1] = c.RealOr(F(0, 5), "P2", p.p[0]);
  p.p[2] = c.RealOr(F(0, 6), "P3", p.p[0]);
  p.p[3] = c.RealOr(F(0, 7), "P4", p.p[0]);
  if (c.KindOf(F(0, 8)) == Kind::Word) {
    if (c.Word(F(0, 8), "THRU") != "THRU") c.Fail(F(0, 8), "THRU", "'" + c.Text(F(0, 8)) + "' is not THRU");
    r.eid2 = c.Id(F(0, 9), "EID2");
    if (r.eid2 <= r.eid1) c.Fail(F(0, 9), "EID2", "the end of a THRU range must exceed its start");
  } else if (!c.Blank(F(0, 8)) || !c.Blank(F(0, 9))) {
    c.Fail(c.Blank(F(0, 8)) ? F(0, 9) : F(0, 8), c.Blank(F(0, 8)) ? "G3" : "G1", "G1 and G3 are for solid elements; a load on shells leaves them blank");
  }
  p.cid = c.CidOr(F(1, 2), "CID", 0);
  p.n = {c.RealOr(F(1, 3), "N1", 0), c.RealOr(F(1, 4), "N2", 0), c.RealOr(F(1, 5), "N3", 0)};
  p.has_direction = p.n != Vec3{0, 0, 0};
  const std::string sorl = c.Word(F(1, 6), "SORL");
  if (sorl == "LINE") c.Fail(F(1, 6), "SORL", "line loads on shell edges (SORL = LINE) are not supported");
  if (!sorl.empty() && sorl != "SURF") c.Fail(F(1, 6), "SORL", "must be SURF, LINE or blank");
  const std::string ldir = c.Word(F(1, 7), "LDIR");
  if (!ldir.empty() && ldir != "NORM" && ldir != "X" && ldir != "Y" && ldir != "Z" && ldir != "TANG")
    c.Fail(F(1, 7), "LDIR", "must be NORM, X, Y, Z, TANG or blank");
  ExpectEnd(c, F(1, 8));
  p.src = src;
  b.pload4.push_back(r);
}

} // namespace

bool ParseConnectionOrLoadCard(const CardFields &c, Build &b, const Source &src)
{
  const std::string &n = c.Name();
  if (n == "PBUSH") PBush_(c, b, src);
  else if (n == "CBUSH") CBush_(c, b, src);
  else if (n == "PFAST") PFast_(c, b, src);
  else if (n == "CFAST") CFast_(c, b, src);
  else if (n == "RBE2") Rbe2_(c, b, src);
  else if (n == "RBE3") Rbe3_(c, b, src);
  else if (n == "CONM2") Conm2_(c, b, src);
  else if (n == "SPC") Spc_(c, b, src);
  else if (n == "SPC1") Spc1_(c, b, src);
  else if (n == "SPCADD") SpcAdd_(c, b, src);
  else if (n == "FORCE") PointLoad_(c, b, src, false);
  else if (n == "MOMENT") PointLoad_(c, b, src, true);
  else if (n == "LOAD") Load_(c, b, src);
  else if (n == "PLOAD4") Pload4_(c, b, src);
  else return false;
  return true;
}

void ParseBulkCard(Build &b, int index)
{
  const CardFields c(b.cards[index], b.deck.files);
  const Source src = c.Src(index);
  if (ParseModelCard(c, b, src) || ParseConnectionOrLoadCard(c, b, src)) {
    if (c.Name() != "CONM2") ++b.deck.used[c.Name()];
    return;
  }
  // Not used by boltnet: counted, with the parameter's name for PARAM.
  std::string detail;
  if (c.Name() == "PARAM" && c.Size() > 0) detail = Upper(c.Text(0));
  b.Unused(c.Name(), src, detail);
}

} // namespace boltnet::nastran
