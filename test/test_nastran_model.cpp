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

// Requirement: a CBUSH becomes a joint between the parts of GA and GB with its PBUSH stiffness.
// Two unit squares (PSHELL 1 at z = 0, PSHELL 2 at z = 1), a CBUSH from grid 3 (1,1,0) to grid 7
// (1,1,1) with X = (1,1,0): element axes x = z, y = (1,1,0)/sqrt2, z = x cross y = (-1,1,0)/sqrt2
// (Nastran's rule). K1..K6 = 10, 20, 40, 1, 2, 6. The joint frame: n = the shell normal at GA = z,
// t1 = the element axis most nearly in the plane (y, the first of the two) so kn = K1 = 10,
// kt = (K2 + K3)/2 = 30, kr = (K4 + K5 + K6)/3 = 3; position the midpoint (1, 1, .5).
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
  const Vec3 x{1, 1, .5}, n{0, 0, 1}, t1{s, s, 0};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(j.x[k], x[k], 1e-14);
    EXPECT_NEAR(j.n[k], n[k], 1e-14);
    EXPECT_NEAR(j.t1[k], t1[k], 1e-14);
  }
  EXPECT_NEAR(j.kn, 10, 1e-12);
  EXPECT_NEAR(j.kt, 30, 1e-12);
  EXPECT_NEAR(j.kr, 3, 1e-12);
  bool noted = false; // the averaging is reported, once for PBUSH 9
  for (const std::string &note : m.notes) noted = noted || note.find("PBUSH 9 (first at CBUSH 20): in-plane stiffnesses 20 and 40 averaged to kt = 30") != std::string::npos;
  EXPECT_TRUE(noted);
  // An unknown subcase names the ones the deck has.
  try {
    ModelOf(d, 3);
    ADD_FAILURE() << "subcase 3 accepted";
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find("no subcase 3 (the deck has subcase(s) 1)"), std::string::npos) << e.what();
  }
}
