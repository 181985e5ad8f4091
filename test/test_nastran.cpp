// Unit tests of the Nastran reader (lib/nastran, docs/nastran.md): numbers, the three field formats,
// continuations, INCLUDE, every supported card, coordinate transforms, subcase loads and
// constraints, sections, the unused-card report. Errors: test_nastran_errors.cpp.
//
// References are independent of the reader: positions, axes and load resultants worked out by hand
// from the deck text (the working is in the comments), closed forms of the sections, and the same
// model written in the other field formats.
#include "nastran/deck.hpp"
#include "nastran/expand.hpp"
#include "nastran/fields.hpp"
#include "nastran/report.hpp"
#include "nastran/section.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

using namespace boltnet::nastran;

namespace {

const std::string kData = BOLTNET_NASTRAN_DATA;
constexpr double  kTol = 1e-12;
const double      r2 = std::sqrt(2.0), r5 = std::sqrt(5.0), r10 = std::sqrt(10.0);

void ExpectVec(const Vec3 &got, const Vec3 &want, double tol = kTol)
{
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(got[j], want[j], tol * (1 + std::abs(want[j]))) << "component " << j;
}

const Grid &GridOf(const Deck &d, int id) { return d.grids.at(d.GridIndex(id)); }

// Everything the reader makes of a deck but where it was read: equal for the same model in any format.
std::string Canon(const Deck &d)
{
  std::ostringstream o;
  o.precision(17);
  for (const CoordSystem &c : d.coords) o << "C" << c.id << " " << int(c.kind) << " " << c.rid << " " << c.origin[0] << " " << c.axes[0][0] << " " << c.axes[2][2] << "\n";
  for (const Grid &g : d.grids)
    o << "G" << g.id << " " << g.cp << " " << g.cd << " " << g.ps << " " << g.x[0] << " " << g.x[1] << " " << g.x[2] << " " << g.cd_axes[0][0] << " " << g.cd_axes[1][1] << "\n";
  for (const Shell &e : d.shells) {
    o << "E" << e.id << " " << int(e.kind) << " " << e.pid << " " << e.mcid << " " << e.theta << " " << e.zoffs << " " << e.tflag;
    for (int i = 0; i < e.Nodes(); ++i) o << " " << e.node[i] << ":" << e.t[i];
    o << "\n";
  }
  for (const PShell &p : d.pshells) o << "P" << p.id << " " << p.mid1 << " " << p.t << " " << p.mid2 << " " << p.bending << " " << p.mid3 << " " << p.shear << "\n";
  for (const Mat1 &m : d.mat1s) o << "M" << m.id << " " << m.e << " " << m.g << " " << m.nu << "\n";
  for (const Spc &s : d.spcs) o << "S" << s.sid << " " << s.grid << " " << s.dofs << " " << s.value << "\n";
  for (const PointLoad &l : d.point_loads) o << "L" << l.moment << " " << l.sid << " " << l.grid << " " << l.basic[0] << " " << l.basic[1] << " " << l.basic[2] << "\n";
  for (const Pressure &p : d.pressures) o << "Q" << p.sid << " " << p.element << " " << p.p[0] << " " << p.p[1] << " " << p.p[2] << " " << p.p[3] << "\n";
  for (const LoadCombination &l : d.load_combinations) o << "LOAD" << l.sid << " " << l.scale << " " << l.scales.size() << "\n";
  for (const Subcase &s : d.subcases) o << "SUB" << s.id << " " << s.load << " " << s.spc << " " << s.label << "\n";
  for (const auto &[n, c] : d.used) o << "U " << n << " " << c << "\n";
  for (const auto &[n, u] : d.unused) o << "X " << n << " " << u.count << "\n";
  for (const auto &[n, u] : d.unused_case) o << "Y " << n << " " << u.count << "\n";
  return o.str();
}

} // namespace

// Requirement 1: Nastran's real forms (1.5, 1.5+3, 1.5-3, 1.5D3, .5, -5.) and integers; anything else
// is not a number.
TEST(Numbers, NastranRealForms)
{
  const std::pair<const char *, double> good[] = {{"1.5", 1.5},   {"1.5+3", 1500},  {"1.5-3", 0.0015}, {"1.5D3", 1500},  {"1.5d-2", 0.015},
                                                 {"1.5E+3", 1500}, {".5", 0.5},      {"-5.", -5},       {"+.7E1", 7},     {"1e-10", 1e-10},
                                                 {"-.25", -0.25},  {"7.+4", 70000}, {"1.-5", 1e-5},    {"0.", 0}};
  for (const auto &[text, value] : good) {
    double v = -1;
    EXPECT_TRUE(ParseReal(text, v)) << text;
    EXPECT_DOUBLE_EQ(v, value) << text;
    EXPECT_EQ(ClassifyField(text), Kind::Real) << text;
  }
  for (const char *bad : {"1+3", "1.5.3", "abc", "", "1.5e", "--1.", "1. 5", ".", "E3", "inf", "nan", "1.5+", "1,5", "+", "1.5E3.0"}) {
    double v;
    EXPECT_FALSE(ParseReal(bad, v)) << bad;
  }
  int i = 0;
  EXPECT_TRUE(ParseInteger("12", i));
  EXPECT_EQ(i, 12);
  EXPECT_TRUE(ParseInteger("-3", i));
  EXPECT_EQ(i, -3);
  EXPECT_TRUE(ParseInteger("+4", i));
  EXPECT_EQ(i, 4);
  for (const char *bad : {"1.", "1e3", "12a", "+-5", "-", "", "99999999999"}) EXPECT_FALSE(ParseInteger(bad, i)) << bad;
  EXPECT_EQ(ClassifyField("THRU"), Kind::Word);
  EXPECT_EQ(ClassifyField("1+3"), Kind::Bad);
}

// Requirement 1: the same model in small field (explicit + markers), large field ('*' lines) and
// free field (commas, blank-first-field continuations) reads to the same deck.
TEST(Formats, SameModelInSmallLargeAndFreeField)
{
  const Deck s = ReadDeck(kData + "/formats-small.bdf"), l = ReadDeck(kData + "/formats-large.bdf"), f = ReadDeck(kData + "/formats-free.bdf");
  EXPECT_EQ(s.grids.size(), 6u);
  EXPECT_EQ(s.shells.size(), 2u);
  EXPECT_EQ(s.subcases.size(), 2u);
  const std::string cs = Canon(s);
  EXPECT_EQ(cs, Canon(l));
  EXPECT_EQ(cs, Canon(f));
}

// Requirement 2: positions in CORD2R, a CORD2C defined in that CORD2R (a chain), and CORD2S, against
// hand-computed positions; the CD axes kept per grid.
TEST(Coordinates, ChainedSystemsAgainstHandPositions)
{
  const Deck d = ReadDeck(kData + "/formats-small.bdf");
  // CORD2R 1: A = (10,0,0), B = (10,0,1), C = (11,1,0): e3 = z, e2 = e3 x (C - A) = (-1,1,0)/r2,
  // e1 = e2 x e3 = (1,1,0)/r2.
  const CoordSystem &c1 = d.coords.at(d.coord_index.at(1));
  ExpectVec(c1.origin, {10, 0, 0});
  ExpectVec(c1.axes[0], {1 / r2, 1 / r2, 0});
  ExpectVec(c1.axes[1], {-1 / r2, 1 / r2, 0});
  ExpectVec(GridOf(d, 1).x, {10, 0, 0});
  ExpectVec(GridOf(d, 2).x, {10 + 15 / r2, 15 / r2, 0}); // x1 = 1.5+1 = 15 along e1
  // CORD2C 2 in system 1: A, B, C = (0,0,0), (0,0,1), (1,0,0) of system 1: the same axes and origin.
  // GRID 3 at (R, theta, z) = (2, 90, 0): 2 e2 from the origin; CD 2 there: e_r = e2, e_theta = -e1.
  const Grid &g3 = GridOf(d, 3);
  ExpectVec(g3.x, {10 - r2, r2, 0});
  ExpectVec(g3.cd_axes[0], {-1 / r2, 1 / r2, 0});
  ExpectVec(g3.cd_axes[1], {-1 / r2, -1 / r2, 0});
  ExpectVec(g3.cd_axes[2], {0, 0, 1});
  ExpectVec(GridOf(d, 4).x, {-5, 15, 0.5}); // 1.5D1
  // CORD2S 3: origin (0,0,5), basic axes. GRID 5 at (R, theta, phi) = (2, 90, 0): (2, 0, 5); CD 3 there:
  // e_r = x, e_theta = -z, e_phi = y.
  const Grid &g5 = GridOf(d, 5);
  ExpectVec(g5.x, {2, 0, 5});
  ExpectVec(g5.cd_axes[0], {1, 0, 0});
  ExpectVec(g5.cd_axes[1], {0, 0, -1});
  ExpectVec(g5.cd_axes[2], {0, 1, 0});
  EXPECT_EQ(GridOf(d, 6).ps, 0b111100u); // PS 3456
  // MOMENT 20 at GRID 3, CID 2, N = (0,1,0): 10 e_theta.
  const StaticLoad m = ExpandLoad(d, 20);
  ASSERT_EQ(m.nodal.size(), 1u);
  ExpectVec(m.nodal[0].moment, {-10 / r2, -10 / r2, 0});
}

// Requirement 1: continuations without a marker, markers with a comment line between, tabs, lower
// case names, a free-field + marker, a one-line large-field card, lines after ENDDATA.
TEST(Formats, Continuations)
{
  const Deck d = ReadDeck(kData + "/continuations.bdf");
  const CoordSystem &c = d.coords.at(0);
  ExpectVec(c.axes[0], {1, 0, 0}); // C = (1,0,0) on the implicit continuation
  const PComp &p = d.pcomps.at(0);
  ASSERT_EQ(p.plies.size(), 2u);
  EXPECT_EQ(p.plies[1].mid, 8); // blank MID2 repeats MID1
  EXPECT_DOUBLE_EQ(p.plies[1].t, 0.5);
  EXPECT_DOUBLE_EQ(p.plies[1].theta, -45);
  EXPECT_TRUE(p.plies[0].sout);
  EXPECT_FALSE(p.plies[1].sout);
  EXPECT_EQ(p.lam, Lam::Sym);
  ASSERT_EQ(p.Stack().size(), 4u);
  EXPECT_DOUBLE_EQ(p.Stack()[3].theta, 45); // mirrored
  EXPECT_DOUBLE_EQ(p.Thickness(), 1.5);
  EXPECT_DOUBLE_EQ(p.z0, -0.75);            // Z0 blank: -T/2
  const PShell &ps = d.pshells.at(0);       // tab separated
  EXPECT_EQ(ps.id, 6);
  EXPECT_EQ(ps.mid1, 9);
  EXPECT_DOUBLE_EQ(ps.t, 1.0);
  EXPECT_EQ(ps.mid2, 9);
  EXPECT_DOUBLE_EQ(d.mat1s.at(0).e, 7e4);
  EXPECT_EQ(d.shells.at(d.ShellIndex(1)).mcid, 1); // an integer in THETA/MCID
  EXPECT_EQ(d.shells.at(d.ShellIndex(2)).pid, 6);  // free field
  ASSERT_EQ(d.rbe2s.size(), 1u);
  EXPECT_EQ(d.rbe2s[0].gm, (std::vector<int>{2, 3, 4}));
  ExpectVec(GridOf(d, 7).x, {2, 3, 0}); // GRID* on one line: X3 absent
  EXPECT_EQ(GridOf(d, 1).id, 1);        // lower case "grid"
  EXPECT_EQ(GridOf(d, 4).cd, 1);
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_NE(d.notes[0].find("2 lines after ENDDATA are ignored"), std::string::npos) << d.notes[0];
  EXPECT_EQ(d.GridIndex(99), -1);
}

// Requirement 1: INCLUDE in case control and bulk data, quoted (over two lines) and unquoted, nested
// and relative to the including file.
TEST(Include, NestedRelativeAndContinued)
{
  const Deck d = ReadDeck(kData + "/include/main.bdf");
  ASSERT_EQ(d.files.size(), 5u);
  EXPECT_NE(d.files[1].find("include/case.inc"), std::string::npos);
  EXPECT_NE(d.files[2].find("include/mesh/plate.bdf"), std::string::npos);
  EXPECT_NE(d.files[3].find("include/props/plate.bdf"), std::string::npos);
  EXPECT_NE(d.files[4].find("include/loads.bdf"), std::string::npos);
  ASSERT_EQ(d.subcases.size(), 1u);
  EXPECT_EQ(d.subcases[0].load, 1);
  EXPECT_EQ(d.subcases[0].spc, 2);
  EXPECT_EQ(d.subcases[0].title, "included case control");
  EXPECT_DOUBLE_EQ(d.pshells.at(0).t, 0.5);
  EXPECT_EQ(d.Where(d.grids.at(1).src), d.files[2] + ":3");
  // FORCE 1: 5 z at GRID 3 = (2, 1, 0): moment (1*5, -2*5, 0).
  const Resultant r = LoadResultant(d, ExpandLoad(d, 1));
  ExpectVec(r.force, {0, 0, 5});
  ExpectVec(r.moment, {5, -10, 0});
}

// Requirement 2: every card of test/data/nastran/cards.bdf, with its Nastran defaults and rules.
TEST(Cards, GridsElementsPropertiesMaterials)
{
  const Deck d = ReadDeck(kData + "/cards.bdf");
  // GRDSET CD 5 on grids with blank CD. CORD2C 5: origin (-1,-1,0), basic axes; GRID 2 at (1,0,0)
  // is at (2,1) from the axis: e_r = (2,1,0)/r5, e_theta = (-1,2,0)/r5.
  EXPECT_EQ(GridOf(d, 2).cd, 5);
  EXPECT_EQ(GridOf(d, 12).cd, 0);
  ExpectVec(GridOf(d, 2).cd_axes[0], {2 / r5, 1 / r5, 0});
  ExpectVec(GridOf(d, 2).cd_axes[1], {-1 / r5, 2 / r5, 0});
  const Shell &q1 = d.shells.at(d.ShellIndex(1)), &q2 = d.shells.at(d.ShellIndex(2)), &t12 = d.shells.at(d.ShellIndex(12));
  EXPECT_DOUBLE_EQ(q1.zoffs, 0.05);
  EXPECT_EQ(q1.mcid, -1);
  EXPECT_EQ(q2.mcid, 5);
  EXPECT_EQ(t12.kind, ShellKind::Tria3);
  EXPECT_EQ(t12.node[3], -1);
  EXPECT_EQ(d.grids.at(t12.node[2]).id, 16);
  EXPECT_TRUE(std::isnan(q1.t[0])); // blank: the property's T
  const PShell &p1 = d.pshells.at(d.pshell_index.at(1)), &p2 = d.pshells.at(d.pshell_index.at(2));
  EXPECT_DOUBLE_EQ(p1.z1, -0.06);
  EXPECT_DOUBLE_EQ(p1.bending, 1.0);
  EXPECT_DOUBLE_EQ(p1.shear, 0.833333);
  EXPECT_DOUBLE_EQ(p2.bending, 0.8);
  EXPECT_DOUBLE_EQ(p2.shear, 0.9);
  EXPECT_DOUBLE_EQ(p2.nsm, 0.01);
  EXPECT_DOUBLE_EQ(p2.z2, 0.05); // blank: T/2
  // MAT1: one of E, G, NU blank is computed from E = 2 (1 + NU) G.
  const Mat1 &m1 = d.mat1s.at(d.mat1_index.at(1)), &m2 = d.mat1s.at(d.mat1_index.at(2)), &m3 = d.mat1s.at(d.mat1_index.at(3));
  EXPECT_DOUBLE_EQ(m1.g, 7e4 / 2.6);
  EXPECT_DOUBLE_EQ(m2.nu, 7e4 / (2 * 2.6e4) - 1);
  EXPECT_DOUBLE_EQ(m3.e, 2 * 1.3 * 2.6e4);
  const Mat8 &m8 = d.mat8s.at(0);
  EXPECT_DOUBLE_EQ(m8.e1, 1.4e5);
  EXPECT_DOUBLE_EQ(m8.g1z, 4e3);
  EXPECT_DOUBLE_EQ(m8.g2z, 0); // blank: rigid in Nastran
  const PComp &pc = d.pcomps.at(0);
  EXPECT_DOUBLE_EQ(pc.z0, -0.2);
  EXPECT_EQ(pc.Stack().size(), 4u);
  EXPECT_DOUBLE_EQ(pc.Thickness(), 0.2);
}

// Requirement 2: CBUSH orientation by GO, by X (in GA's displacement system), by CID, and axial only;
// CFAST at a grid and at a point.
TEST(Cards, BushAxesAgainstHandFrames)
{
  const Deck d = ReadDeck(kData + "/cards.bdf");
  const auto bush = [&](int id) -> const Bush & {
    for (const Bush &b : d.bushes)
      if (b.id == id) return b;
    throw std::runtime_error("no bush");
  };
  // 21: GA 1 (0,0,0), GB 11 (0,0,1): x = z; v = GO 20 - GA = (1,.5,2); z = x cross v = (-.5,1,0),
  // y = z cross x = (1,.5,0), both over sqrt(1.25).
  const double s = std::sqrt(1.25);
  ExpectVec(bush(21).axes[0], {0, 0, 1});
  ExpectVec(bush(21).axes[1], {1 / s, .5 / s, 0});
  ExpectVec(bush(21).axes[2], {-.5 / s, 1 / s, 0});
  EXPECT_DOUBLE_EQ(bush(21).s, 0.3);
  EXPECT_DOUBLE_EQ(bush(21).length, 1);
  // 22: X = (1,0,0) in GA's CD (CORD2C 5 at GRID 2): v = e_r = (2,1,0)/r5; y = v, z = (-1,2,0)/r5.
  ExpectVec(bush(22).axes[1], {2 / r5, 1 / r5, 0});
  ExpectVec(bush(22).axes[2], {-1 / r5, 2 / r5, 0});
  // 23: CID 5 at GA 3 (2,0,0), (3,1) from the axis: e_r = (3,1,0)/r10, e_theta = (-1,3,0)/r10, z.
  ExpectVec(bush(23).axes[0], {3 / r10, 1 / r10, 0});
  ExpectVec(bush(23).axes[1], {-1 / r10, 3 / r10, 0});
  ExpectVec(bush(23).axes[2], {0, 0, 1});
  // 24: no orientation, PBUSH 8 has K1 and K4 only: axial along GA-GB.
  EXPECT_TRUE(bush(24).axial_only);
  ExpectVec(bush(24).axes[0], {0, 0, 1});
  const PBush &pb = d.pbushes.at(d.pbush_index.at(7));
  EXPECT_DOUBLE_EQ(pb.k[5], 6e3);
  EXPECT_TRUE(d.pbushes.at(d.pbush_index.at(8)).k_given[3]);
  EXPECT_FALSE(d.pbushes.at(d.pbush_index.at(8)).k_given[1]);
  ASSERT_EQ(d.fasts.size(), 2u);
  ExpectVec(d.fasts[0].position, {1, .5, 2}); // GS 20
  EXPECT_FALSE(d.fasts[0].by_element);
  ExpectVec(d.fasts[1].position, {1.5, .5, .5}); // XS
  EXPECT_TRUE(d.fasts[1].by_element);
  const PFast &pf = d.pfasts.at(0);
  EXPECT_DOUBLE_EQ(pf.d, 0.5);
  EXPECT_DOUBLE_EQ(pf.k[4], 20);
  EXPECT_DOUBLE_EQ(pf.k[5], 30);
}

// Requirement 2: RBE2 (THRU, ALPHA), RBE3 (weighted groups, UM, ALPHA), CONM2 (read, reported unused).
TEST(Cards, RigidElementsAndMass)
{
  const Deck d = ReadDeck(kData + "/cards.bdf");
  const Rbe2 &r2e = d.rbe2s.at(0);
  EXPECT_EQ(r2e.gn, 20);
  EXPECT_EQ(r2e.cm, 0b111111u);
  EXPECT_EQ(r2e.gm, (std::vector<int>{14, 15, 16}));
  EXPECT_DOUBLE_EQ(r2e.alpha, 1e-5);
  const Rbe3 &r3 = d.rbe3s.at(0);
  EXPECT_EQ(r3.refgrid, 20);
  ASSERT_EQ(r3.groups.size(), 2u);
  EXPECT_DOUBLE_EQ(r3.groups[0].weight, 1);
  EXPECT_EQ(r3.groups[0].c, 0b111u);
  EXPECT_EQ(r3.groups[0].grids, (std::vector<int>{1, 2, 3}));
  EXPECT_DOUBLE_EQ(r3.groups[1].weight, 2.5);
  EXPECT_EQ(r3.groups[1].c, 0b11u);
  EXPECT_EQ(r3.groups[1].grids, (std::vector<int>{4, 5}));
  ASSERT_EQ(r3.um.size(), 1u);
  EXPECT_EQ(r3.um[0].first, 1);
  EXPECT_EQ(r3.um[0].second, 0b111000u);
  EXPECT_DOUBLE_EQ(r3.alpha, 2e-5);
  ASSERT_EQ(d.conm2s.size(), 1u);
  EXPECT_DOUBLE_EQ(d.conm2s[0].m, 1.5);
}

// Requirements 2 and 3: SPCADD of SPC1 (THRU) and SPC sets, GRID PS, and LOAD combinations of FORCE,
// MOMENT and PLOAD4 (uniform, per corner, THRU, with a direction), against hand resultants.
TEST(Cards, SubcaseConstraintsAndLoadResultants)
{
  const Deck d = ReadDeck(kData + "/cards.bdf");
  ASSERT_EQ(d.subcases.size(), 2u);
  EXPECT_EQ(d.subcases[0].spc, 100);
  EXPECT_EQ(d.subcases[0].load, 50);
  EXPECT_EQ(d.subcases[1].load, 62);
  EXPECT_EQ(d.subcases[1].title, "every card"); // inherited from above the first SUBCASE
  // SPCADD 100 = SPC1 1 (grids 1-4, 123456) + SPC 3 (grid 20, component 6 to .01).
  const auto spc = ExpandSpc(d, 100);
  ASSERT_EQ(spc.size(), 5u);
  EXPECT_EQ(d.grids.at(spc[0].node).id, 1);
  EXPECT_EQ(spc[0].dofs, 0b111111u);
  EXPECT_EQ(d.grids.at(spc[4].node).id, 20);
  EXPECT_EQ(spc[4].dofs, 0b100000u);
  EXPECT_DOUBLE_EQ(spc[4].value[5], 0.01);
  // SPC1 4: 5 THRU 11, of which 5, 6 and 11 exist.
  EXPECT_EQ(ExpandSpc(d, 4).size(), 3u);
  // LOAD 50 = 1.5 (set 60 + 2 set 61 - set 62 + .5 set 63), worked by hand:
  //  60: FORCE 10 x at GRID 20 (1,.5,2), plus 2 e_r of CORD2C 5 there (rel. (2,1.5)): (1.6,1.2,0).
  //      Force (11.6, 1.2, 0), moment r x F = (-2.4, 23.2, -4.6).
  //  61: MOMENT 3 z.
  //  62: PLOAD4 2 on quad 1 (unit square at z 0, normal +z): F (0,0,2), M (1,-1,0); quad 11 (z 1)
  //      with corner pressures 1,2,3,4: F (0,0,2.5), M = (int y p, -int x p) = (17/12, -15/12);
  //      triangles 12 and 13 (area 1/2, mean pressure 2): F (0,0,1) each, M (.375, -1.708333...)
  //      and (.708333..., -1.333333...) by the edge-midpoint rule. Sum: F (0,0,6.5), M (3.5, -5.291666...).
  //  63: 5 on quad 2 along -z (the given direction): F (0,0,-5), M = (1.5,.5,0) x F = (-2.5, 7.5, 0).
  const Resultant r = LoadResultant(d, ExpandLoad(d, 50));
  const double m62x = 1 + 17.0 / 12 + 0.375 + 8.5 / 12, m62y = -1 - 15.0 / 12 - 20.5 / 12 - 16.0 / 12;
  ExpectVec(r.force, {1.5 * 11.6, 1.5 * 1.2, 1.5 * (-6.5 - 2.5)});
  ExpectVec(r.moment, {1.5 * (-2.4 - m62x - 1.25), 1.5 * (23.2 - m62y + 3.75), 1.5 * (-4.6 + 6)});
  const StaticLoad l62 = ExpandLoad(d, 62);
  ASSERT_EQ(l62.pressures.size(), 4u); // one + THRU 11..13
  EXPECT_DOUBLE_EQ(l62.pressures[1].p[3], 4);
  const StaticLoad l63 = ExpandLoad(d, 63);
  ASSERT_EQ(l63.pressures.size(), 1u);
  EXPECT_TRUE(l63.pressures[0].has_direction);
  ExpectVec(l63.pressures[0].direction, {0, 0, -1});
}

// Requirement 3: every card boltnet does not use is counted and reported with its first place;
// so are unused case control commands and the parts of used cards that statics ignores.
TEST(Report, UnusedCardsCountedAndNamed)
{
  const Deck d = ReadDeck(kData + "/cards.bdf");
  ASSERT_EQ(d.unused.size(), 4u);
  EXPECT_EQ(d.unused.at("CBAR").count, 1);
  EXPECT_EQ(d.unused.at("MPC").count, 1);
  EXPECT_EQ(d.unused.at("PARAM").count, 2);
  EXPECT_EQ(d.unused.at("PARAM").details, (std::set<std::string>{"AUTOSPC", "POST"}));
  EXPECT_EQ(d.unused.at("CONM2").count, 1);
  EXPECT_EQ(d.Where(d.unused.at("CBAR").first), kData + "/cards.bdf:85");
  EXPECT_EQ(d.unused_case.at("MPC").count, 1);
  EXPECT_EQ(d.used.at("GRID"), 13);
  EXPECT_EQ(d.used.at("CQUAD4"), 3);
  EXPECT_EQ(d.used.at("PLOAD4"), 3);
  EXPECT_EQ(d.used.count("CONM2"), 0u);
  const std::string s = Summary(d);
  for (const char *line : {"cards not used: 5\n", "  CBAR 1 (first at", "  PARAM 2 (first at", ": AUTOSPC POST\n", "CONM2 1", "mass is not used in statics",
                           "case control commands not used: 1\n", "  MPC 1", "PBUSH 7: the B line is read and not used in statics",
                           "bounding box: x [0, 2] y [0, 1] z [0, 2]", "force [17.4, 1.8, -13.5]"})
    EXPECT_NE(s.find(line), std::string::npos) << line << "\n" << s;
}

// Sections for boltnet's shell (docs/nastran.md): PSHELL resultants T G1, (12I/T^3) T^3/12 G2,
// (TS/T) T G3; PCOMP by lamination theory about Z0; unsupported combinations refused.
TEST(Sections, PShellAndPCompAgainstClosedForms)
{
  const Deck d = ReadDeck(kData + "/cards.bdf");
  std::vector<std::string> notes;
  // PSHELL 2: MAT1 2 (E 7e4, G 2.6e4, NU = E/2G - 1), T .1, 12I/T^3 .8, TS/T .9.
  const double E = 7e4, G = 2.6e4, nu = E / (2 * G) - 1, t = 0.1, c = E / (1 - nu * nu);
  const auto s2 = SectionOf(d, 2, NAN, notes);
  EXPECT_NEAR(s2.A[0], c * t, 1e-9 * c);
  EXPECT_NEAR(s2.A[1], nu * c * t, 1e-9 * c);
  EXPECT_NEAR(s2.A[8], G * t, 1e-9 * c);
  EXPECT_NEAR(s2.D[0], 0.8 * c * t * t * t / 12, 1e-12 * c);
  EXPECT_NEAR(s2.H[0], 0.9 * G * t, 1e-9 * G);
  EXPECT_NEAR(s2.H[3], 0.9 * G * t, 1e-9 * G);
  EXPECT_EQ(notes.size(), 0u);
  // Element thickness given: the section at that thickness.
  EXPECT_NEAR(SectionOf(d, 2, 0.2, notes).A[0], c * 0.2, 1e-9 * c);
  // PCOMP 3: SYM [0, 90] of MAT8 8, plies .05: stack 0/90/90/0 from z = -.1 (mid-plane frame), and
  // Z0 = -.2 puts the reference plane d = .1 above the mid-plane: B = -d A, D = D_mid + d^2 A.
  const double E1 = 1.4e5, E2 = 1e4, n12 = 0.3, den = 1 - n12 * n12 * E2 / E1;
  const double Q11 = E1 / den, Q22 = E2 / den, h = 0.05;
  const auto s3 = SectionOf(d, 3, NAN, notes);
  const double A11 = 2 * h * (Q11 + Q22), D11 = 2 * (Q11 * (0.1 * 0.1 * 0.1 - h * h * h) + Q22 * h * h * h) / 3;
  EXPECT_NEAR(s3.A[0], A11, 1e-9 * A11);
  EXPECT_NEAR(s3.B[0], -0.1 * A11, 1e-9 * A11);
  EXPECT_NEAR(s3.D[0], D11 + 0.01 * A11, 1e-9 * D11);
  ASSERT_EQ(notes.size(), 1u); // MAT8 8 has G2Z blank
  EXPECT_NE(notes[0].find("G1Z or G2Z blank"), std::string::npos);
  // Offset is its own inverse with the opposite distance.
  const auto back = Offset(Offset(s3, 0.3), -0.3);
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(back.D[i], s3.D[i], 1e-12 * std::abs(D11));
}
