// Unit tests of the deck-to-model step (lib/nastran/model.hpp, docs/nastran.md "From a deck to a
// model"): PLOAD4 as consistent nodal forces, and a PBUSH stiffness projected on the joint frame.
// References: the load resultant worked by hand in test_nastran.cpp, and a bush frame worked by hand.
#include "nastran/model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
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
