// Unit tests of the deck-to-model step (lib/nastran/model.hpp, docs/nastran.md "From a deck to a
// model"): PLOAD4 as consistent nodal forces, and a PBUSH stiffness projected on the joint frame.
// References: the load resultant worked by hand in test_nastran.cpp, and a bush frame worked by hand.
#include "nastran/model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <string>

using namespace boltnet::nastran;

namespace {

const std::string kData = BOLTNET_NASTRAN_DATA;

std::string WriteDeck(const std::string &name, const std::string &text)
{
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

} // namespace

// Requirement: PLOAD4 becomes nodal loads without changing the load. LOAD 50 of cards.bdf (FORCE,
// MOMENT, PLOAD4 per corner, THRU, with a direction) has the resultant worked by hand in
// test_nastran.cpp (Cards.SubcaseConstraintsAndLoadResultants); its pressures as nodal forces must
// give the same force and moment about the origin.
TEST(Model, PressuresAsNodalForcesKeepTheResultant)
{
  const Deck d = ReadDeck(kData + "/cards.bdf");
  StaticLoad l = ExpandLoad(d, 50);
  ASSERT_FALSE(l.pressures.empty());
  PressuresToNodal(d, l.pressures, l.nodal);
  l.pressures.clear();
  const Resultant r = LoadResultant(d, l);
  const double m62x = 1 + 17.0 / 12 + 0.375 + 8.5 / 12, m62y = -1 - 15.0 / 12 - 20.5 / 12 - 16.0 / 12;
  const Vec3 f{1.5 * 11.6, 1.5 * 1.2, 1.5 * (-6.5 - 2.5)}, m{1.5 * (-2.4 - m62x - 1.25), 1.5 * (23.2 - m62y + 3.75), 1.5 * (-4.6 + 6)};
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(r.force[j], f[j], 1e-12 * (1 + std::abs(f[j])));
    EXPECT_NEAR(r.moment[j], m[j], 1e-12 * (1 + std::abs(m[j])));
  }
}

// Requirement: a CBUSH becomes a joint between the parts of GA and GB with its PBUSH stiffness,
// whole (no averaging), its spring at S of GA-GB with a lever from each grid.
// Two unit squares (PSHELL 1 at z = 0, PSHELL 2 at z = 1), a CBUSH from grid 3 (1,1,0) to grid 7
// (1,1,1) with X = (1,1,0): element axes x = z, y = (1,1,0)/sqrt2, z = x cross y = (-1,1,0)/sqrt2
// (Nastran's rule). K1..K6 = 10, 20, 40, 1, 2, 6. The joint frame: n = the shell normal at GA = z,
// t1 = the element axis most nearly in the plane (y, the first of the two), t2 = n x t1 = the
// element z: the frame is the element axes, so K = diag(10, 20, 40, 1, 2, 6); the spring at the
// midpoint (1, 1, .5) (S blank: 0.5), levered from GA and GB.
TEST(Model, BushStiffnessOnTheJointFrame)
{
  const std::string path = WriteDeck("bush-frame.bdf", "BEGIN BULK\n"
                                                      "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\n"
                                                      "GRID,5,,0.,0.,1.\nGRID,6,,1.,0.,1.\nGRID,7,,1.,1.,1.\nGRID,8,,0.,1.,1.\n"
                                                      "CQUAD4,1,1,1,2,3,4\nCQUAD4,2,2,5,6,7,8\n"
                                                      "PSHELL,1,1,.1,1\nPSHELL,2,1,.1,1\nMAT1,1,70000.,,.3\n"
                                                      "PBUSH,9,K,10.,20.,40.,1.,2.,6.\nCBUSH,20,9,3,7,1.,1.,0.\nENDDATA\n");
  const Deck      d = ReadDeck(path);
  const DeckModel m = ModelOf(d, 1);
  ASSERT_EQ(m.parts.size(), 2u);
  EXPECT_EQ(m.parts[0].pid, 1);
  EXPECT_EQ(m.parts[0].mesh.elems.size(), 1u);
  ASSERT_EQ(m.joints.size(), 1u);
  const ModelJoint &j = m.joints[0];
  EXPECT_EQ(j.eid, 20);
  EXPECT_EQ(j.part_a, 0);
  EXPECT_EQ(j.part_b, 1);
  const double s = 1 / std::sqrt(2.0);
  const Vec3 x{1, 1, .5}, n{0, 0, 1}, t1{s, s, 0}, ga{1, 1, 0}, gb{1, 1, 1};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(j.x[k], x[k], 1e-14);
    EXPECT_NEAR(j.n[k], n[k], 1e-14);
    EXPECT_NEAR(j.t1[k], t1[k], 1e-14);
    EXPECT_EQ(j.at_a[k], ga[k]);
    EXPECT_EQ(j.at_b[k], gb[k]);
  }
  EXPECT_TRUE(j.full);
  EXPECT_TRUE(j.lever);
  const double diag[6] = {10, 20, 40, 1, 2, 6};
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b) EXPECT_NEAR(j.K[6 * a + b], a == b ? diag[a] : 0, 1e-13) << a << ", " << b;
  bool noted = false; // the lever is reported, once for PBUSH 9
  for (const std::string &note : m.notes) noted = noted || note.find("PBUSH 9 (first at CBUSH 20): springs at S of GA-GB, each grid carrying its spring by a rigid lever (GA-GB up to 1 long)") != std::string::npos;
  EXPECT_TRUE(noted);
  // Without offsets: the midpoint, no lever.
  ModelOptions o;
  o.bush_offsets = false;
  EXPECT_FALSE(ModelOf(d, 1, o).joints[0].lever);
  // An unknown subcase names the ones the deck has.
  try {
    ModelOf(d, 3);
    ADD_FAILURE() << "subcase 3 accepted";
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find("no subcase 3 (the deck has subcase(s) 1)"), std::string::npos) << e.what();
  }
}

// Requirement: the bush's stiffness rotated into the joint frame with its couplings kept, and its
// spring at S of GA-GB. The squares of the test above, the upper one moved by 1 along x: GA 3
// (1,1,0) to GB 7 (2,1,1) is tilted 45 degrees in xz, so no element axis but y is in the plane and
// K couples n and t2; S = 0.25 puts the spring at (1.25, 1, .25). The reference is the sum
// K = sum k_i a_i a_i^T projected on the frame, written out here from Nastran's axis rule.
TEST(Model, TiltedBushKeepsItsCouplings)
{
  const std::string path = WriteDeck("bush-tilt.bdf", "BEGIN BULK\n"
                                                     "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\n"
                                                     "GRID,5,,1.,0.,1.\nGRID,6,,2.,0.,1.\nGRID,7,,2.,1.,1.\nGRID,8,,1.,1.,1.\n"
                                                     "CQUAD4,1,1,1,2,3,4\nCQUAD4,2,2,5,6,7,8\n"
                                                     "PSHELL,1,1,.1,1\nPSHELL,2,1,.1,1\nMAT1,1,70000.,,.3\n"
                                                     "PBUSH,9,K,10.,20.,40.,1.,2.,6.\nCBUSH,20,9,3,7,0.,1.,0.\n,.25\nENDDATA\n");
  const DeckModel m = ModelOf(ReadDeck(path), 1);
  ASSERT_EQ(m.joints.size(), 1u);
  const ModelJoint &j = m.joints[0];
  // Element axes (Nastran): x = (1, 0, 1)/sqrt2 (GA 3 -> GB 7), X = (0, 1, 0) in the xy plane:
  // z = x cross X = (-1, 0, 1)/sqrt2, y = z cross x = (0, 1, 0).
  const double r = 1 / std::sqrt(2.0);
  const Vec3   a[3] = {{r, 0, r}, {0, 1, 0}, {-r, 0, r}};
  const double k[6] = {10, 20, 40, 1, 2, 6};
  // Joint frame: n = z (shell normal at GA), t1 = y (the element axis in the plane), t2 = n x t1 = -x.
  const Vec3 e[3] = {{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}};
  for (int b = 0; b < 2; ++b)
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) {
        double want = 0;
        for (int i = 0; i < 3; ++i) want += k[3 * b + i] * (a[i][0] * e[p][0] + a[i][1] * e[p][1] + a[i][2] * e[p][2]) * (a[i][0] * e[q][0] + a[i][1] * e[q][1] + a[i][2] * e[q][2]);
        EXPECT_NEAR(j.K[6 * (3 * b + p) + 3 * b + q], want, 1e-13) << b << ", " << p << ", " << q;
        EXPECT_EQ(j.K[6 * (3 * b + p) + 3 * (1 - b) + q], 0.0);
      }
  // The n-t2 coupling, by hand: K1 (r)(-r) + K3 (r)(r) = (K3 - K1)/2 = 15: kept, not dropped.
  EXPECT_NEAR(j.K[6 * 0 + 2], 15, 1e-13);
  const Vec3 xs{1.25, 1, .25};
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(j.x[c], xs[c], 1e-14);
}

// Requirement: what boltnet does not model is refused naming the card, its place and the field:
// a CBUSH spring offset in a coordinate system (OCID >= 0).
TEST(Model, BushOffsetInASystemIsRefused)
{
  const std::string path = WriteDeck("bush-ocid.bdf", "BEGIN BULK\n"
                                                     "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\n"
                                                     "GRID,5,,0.,0.,1.\nGRID,6,,1.,0.,1.\nGRID,7,,1.,1.,1.\nGRID,8,,0.,1.,1.\n"
                                                     "CQUAD4,1,1,1,2,3,4\nCQUAD4,2,2,5,6,7,8\n"
                                                     "PSHELL,1,1,.1,1\nPSHELL,2,1,.1,1\nMAT1,1,70000.,,.3\n"
                                                     "PBUSH,9,K,10.,20.,40.,1.,2.,6.\nCBUSH,20,9,3,7,1.,1.,0.\n,,0,.1,.2,.3\n"
                                                     "ENDDATA\n");
  try {
    ModelOf(ReadDeck(path), 1);
    ADD_FAILURE() << "OCID accepted";
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find("bush-ocid.bdf:16: CBUSH 20, field OCID = 0 (S1-S3 0.1, 0.2, 0.3): a spring offset in a coordinate system is not supported"), std::string::npos) << e.what();
  }
}

namespace {

// Forces per grid (basic) that ModelOf put on the parts, keyed by deck grid index.
std::map<int, Vec3> ForcesByGrid(const DeckModel &m)
{
  std::map<int, Vec3> f;
  for (const ModelBC &bc : m.bcs) {
    if (bc.kind != ModelBCKind::Force) continue;
    EXPECT_LT(bc.dof, 3) << "an RBE3 with translational Ci gives forces only";
    const int g = bc.nodes.empty() ? m.parts[bc.part].grids[0] : m.parts[bc.part].grids[bc.nodes[0]];
    f[g][bc.dof] += bc.value;
  }
  return f;
}

Vec3 CrossOf(const Vec3 &a, const Vec3 &b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

// Two bent quadrilaterals (grids 1-6, PSHELL 1), the RBE3 10 card `rbe3`, REFGRID 100 at
// (5, -1, 2) loaded by FORCE (3, -2, 5) and MOMENT (7, 1, -4) in set 1, and `extra` cards.
std::string Rbe3Deck(const std::string &rbe3, const std::string &extra = "")
{
  return "SOL 101\nCEND\nLOAD = 1\nSPC = 1\nBEGIN BULK\n"
         "GRID,1,,0.,0.,0.\nGRID,2,,2.,0.,0.\nGRID,3,,2.,1.,0.\nGRID,4,,0.,1.,0.\nGRID,5,,3.,0.,1.5\nGRID,6,,3.,1.2,1.5\n"
         "GRID,100,,5.,-1.,2.\n"
         "CQUAD4,1,1,1,2,3,4\nCQUAD4,2,1,2,5,6,3\nPSHELL,1,1,.1,1\nMAT1,1,70000.,,.3\nSPC1,1,123456,1\n"
         "FORCE,1,100,0,1.,3.,-2.,5.\nMOMENT,1,100,0,1.,7.,1.,-4.\n" +
         rbe3 + extra + "ENDDATA\n";
}

} // namespace

// Requirement: an RBE3 whose REFGRID carries only loads moves them to its independent grids by
// Nastran's weighted least-squares average (docs/nastran.md, "RBE3"). Reference: the textbook form
// for Ci = 123, f_i = w_i F / W + w_i (J^-1 M_c) x r_i with r_i from the weighted centroid c,
// M_c = M + (x_ref - c) x F and J = sum w_i (|r_i|^2 I - r_i r_i^T), evaluated here with a 3 x 3
// cofactor inverse (the library solves the 6 x 6 system by eigenvectors), to 1e-12 of the largest value. Unequal weights in two
// groups over six grids that are not coplanar; the forces must also sum to F and their moment about
// REFGRID to M, to round-off.
TEST(Model, Rbe3MovesTheLoadByTheWeightedAverage)
{
  const Deck      d = ReadDeck(WriteDeck("rbe3-general.bdf", Rbe3Deck("RBE3,10,,100,123456,1.,123,1,2\n,3,2.5,123,4,5,6\n")));
  const DeckModel m = ModelOf(d, 1);
  EXPECT_EQ(d.unused.count("RBE3"), 0u);
  const std::map<int, Vec3> f = ForcesByGrid(m);
  ASSERT_EQ(f.size(), 6u);
  const Vec3 F{3, -2, 5}, M{7, 1, -4}, xr{5, -1, 2};
  // The textbook reference.
  const std::map<int, double> w{{1, 1}, {2, 1}, {3, 1}, {4, 2.5}, {5, 2.5}, {6, 2.5}};
  double W = 0;
  Vec3   c{};
  for (const auto &[gid, wi] : w) {
    const Vec3 &x = d.grids[d.GridIndex(gid)].x;
    W += wi;
    for (int j = 0; j < 3; ++j) c[j] += wi * x[j];
  }
  for (double &cj : c) cj /= W;
  double J[3][3] = {};
  for (const auto &[gid, wi] : w) {
    const Vec3 &x = d.grids[d.GridIndex(gid)].x;
    const Vec3  r{x[0] - c[0], x[1] - c[1], x[2] - c[2]};
    const double rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) J[a][b] += wi * ((a == b) * rr - r[a] * r[b]);
  }
  const Vec3 off = CrossOf({xr[0] - c[0], xr[1] - c[1], xr[2] - c[2]}, F);
  const Vec3 Mc{M[0] + off[0], M[1] + off[1], M[2] + off[2]};
  const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) + J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
  Vec3 omega{};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const int a1 = (b + 1) % 3, a2 = (b + 2) % 3, b1 = (a + 1) % 3, b2 = (a + 2) % 3; // cofactor (b, a)
      omega[a] += (J[a1][b1] * J[a2][b2] - J[a1][b2] * J[a2][b1]) / det * Mc[b];
    }
  Vec3 sum{}, moment{};
  for (const auto &[gid, wi] : w) {
    const int   g = d.GridIndex(gid);
    const Vec3 &x = d.grids[g].x;
    const Vec3  turn = CrossOf(omega, {x[0] - c[0], x[1] - c[1], x[2] - c[2]});
    ASSERT_TRUE(f.count(g)) << "grid " << gid;
    const Vec3 &got = f.at(g);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(got[j], wi * F[j] / W + wi * turn[j], 1e-13 * 10) << "grid " << gid << " component " << j + 1;
    const Vec3 mm = CrossOf({x[0] - xr[0], x[1] - xr[1], x[2] - xr[2]}, got);
    for (int j = 0; j < 3; ++j) sum[j] += got[j], moment[j] += mm[j];
  }
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(sum[j], F[j], 1e-13 * 10);
    EXPECT_NEAR(moment[j], M[j], 1e-13 * 100);
  }
  bool noted = false;
  for (const std::string &note : m.notes) noted = noted || note.find("RBE3 10: the load on REFGRID 100") != std::string::npos;
  EXPECT_TRUE(noted);
}

// Requirement: components other than 123 as the card defines them. Only component 3 at six grids of
// the plane z = 0 (unequal weights), REFC 345 (what component 3 of grids in a plane can carry): the
// forces are along z, sum to Fz and their moment about REFGRID is M (x and y components). A FORCE along x (component 1, not
// in REFC) is refused: Nastran would leave it on REFGRID.
TEST(Model, Rbe3PartialComponents)
{
  const std::string rbe3 = "RBE3,10,,100,345,1.,3,1,2\n,3,2.,3,4,5,6\n";
  const std::string deck = "SOL 101\nCEND\nLOAD = 1\nBEGIN BULK\n"
                           "GRID,1,,0.,0.,0.\nGRID,2,,2.,0.,0.\nGRID,3,,2.,1.,0.\nGRID,4,,0.,1.,0.\nGRID,5,,3.,0.,0.\nGRID,6,,3.,1.2,0.\nGRID,100,,5.,-1.,2.\n"
                           "CQUAD4,1,1,1,2,3,4\nCQUAD4,2,1,2,5,6,3\nPSHELL,1,1,.1,1\nMAT1,1,70000.,,.3\n"
                           "FORCE,1,100,0,1.,0.,0.,5.\nMOMENT,1,100,0,1.,7.,1.,0.\n" +
                           rbe3 + "ENDDATA\n";
  const Deck      d = ReadDeck(WriteDeck("rbe3-partial.bdf", deck));
  const DeckModel m = ModelOf(d, 1);
  const std::map<int, Vec3> f = ForcesByGrid(m);
  const Vec3 xr{5, -1, 2};
  Vec3 sum{}, moment{};
  for (const auto &[g, got] : f) {
    EXPECT_EQ(got[0], 0);
    EXPECT_EQ(got[1], 0);
    const Vec3 &x = d.grids[g].x;
    const Vec3 mm = CrossOf({x[0] - xr[0], x[1] - xr[1], x[2] - xr[2]}, got);
    for (int j = 0; j < 3; ++j) sum[j] += got[j], moment[j] += mm[j];
  }
  EXPECT_NEAR(sum[2], 5, 1e-13);
  EXPECT_NEAR(moment[0], 7, 1e-12);
  EXPECT_NEAR(moment[1], 1, 1e-12);
  std::string bad = deck;
  const std::string fz = "FORCE,1,100,0,1.,0.,0.,5.";
  bad.replace(bad.find(fz), fz.size(), "FORCE,1,100,0,1.,1.,0.,5.");
  try {
    ModelOf(ReadDeck(WriteDeck("rbe3-partial-bad.bdf", bad)), 1);
    ADD_FAILURE() << "a load component outside REFC accepted";
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find("RBE3 10: subcase 1: REFGRID 100 carries load component 1 (1) which REFC = 345 does not contain"), std::string::npos) << e.what();
  }
}

// Requirement: what boltnet does not model is refused with the card, its place and the reason.
TEST(Model, Rbe3Refusals)
{
  const struct {
    const char *name;
    std::string deck, message;
  } cases[] = {
    {"collinear", Rbe3Deck("RBE3,10,,100,123456,1.,123,1,2\n"), "RBE3 10: its independent components (Ci at the grids Gi,j) cannot carry REFC component(s) 234"},
    {"rotational-ci", Rbe3Deck("RBE3,10,,100,123456,1.,123456,1,2,3\n"), "RBE3 10: C1 = 123456: boltnet supports translational independent components only"},
    {"um", Rbe3Deck("RBE3,10,,100,123,1.,123,1,2,3\n,4,UM,1,123\n"), "RBE3 10: UM (grid 1 component(s) 123)"},
    {"spc", Rbe3Deck("RBE3,10,,100,123456,1.,123,1,2\n,3,4\n", "SPC1,1,3,100\n"), "RBE3 10: REFGRID 100 has components 3 of REFC constrained in subcase 1"},
    {"shell", Rbe3Deck("RBE3,10,,100,123456,1.,123,1,2\n,3,4\n", "CQUAD4,3,1,5,100,6,3\n"), "RBE3 10: REFGRID 100 is a grid of CQUAD4 3 at"},
    {"bush", Rbe3Deck("RBE3,10,,100,123456,1.,123,1,2\n,3,4\n", "PBUSH,7,K,1.\nCBUSH,9,7,100,6,1.,0.,0.\n"), "RBE3 10: REFGRID 100 is a grid of CBUSH 9 at"},
    {"rbe2", Rbe3Deck("RBE3,10,,100,123456,1.,123,1,2\n,3,4\n", "RBE2,11,100,123456,6\n"), "RBE3 10: REFGRID 100 is GN of RBE2 11 at"},
    {"twice", Rbe3Deck("RBE3,10,,100,123456,1.,123,1,2\n,3,4\n", "RBE3,12,,100,123456,1.,123,3,4\n,5,6\n"), "RBE3 12: REFGRID 100 is also REFGRID of RBE3 10 at"},
    {"own-grid", Rbe3Deck("RBE3,10,,100,123456,1.,123,1,2\n,3,100\n"), "RBE3 10: REFGRID 100 is also one of its independent grids"},
  };
  for (const auto &c : cases) {
    try {
      ModelOf(ReadDeck(WriteDeck(std::string("rbe3-") + c.name + ".bdf", c.deck)), 1);
      ADD_FAILURE() << c.name << ": accepted";
    } catch (const Error &e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(c.message), std::string::npos) << c.name << ": " << what;
      EXPECT_NE(what.find(std::string("rbe3-") + c.name + ".bdf:"), std::string::npos) << c.name << ": " << what;
      EXPECT_EQ(e.card, "RBE3") << c.name;
    }
  }
}
