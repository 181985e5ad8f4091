// Unit tests of the plate generator, the cut into patches, the fastener footprint and the rigid
// patch coupling (issue 3 items 2 and 3: the pieces that do not need the shell element).
#include "coupling/rigid.hpp"
#include "mesh/mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace boltnet;

// Requirement (issue 3 item 2): a generated rectangular plate has the right nodes, elements and
// edge node sets, and its elements are counter-clockwise with the plate's area.
TEST(Mesh, RectanglePlate)
{
  const QuadMesh m = RectanglePlate(10, 20, 150, 20, 15, 4, 1.5);
  EXPECT_EQ(m.x.size(), 16u * 5u);
  EXPECT_EQ(m.quads.size(), 60u);
  EXPECT_EQ(m.node_sets.at("xmin").size(), 5u);
  EXPECT_EQ(m.node_sets.at("ymax").size(), 16u);
  for (int n : m.node_sets.at("xmax")) EXPECT_DOUBLE_EQ(m.x[n][0], 160.0);
  double area = 0;
  for (const auto &q : m.quads) { // shoelace formula, positive when counter-clockwise
    double a = 0;
    for (int k = 0; k < 4; ++k) a += m.x[q[k]][0] * m.x[q[(k + 1) % 4]][1] - m.x[q[(k + 1) % 4]][0] * m.x[q[k]][1];
    EXPECT_GT(a, 0);
    area += 0.5 * a;
  }
  EXPECT_NEAR(area, 150.0 * 20.0, 1e-9);
  EXPECT_THROW(RectanglePlate(0, 0, 1, 1, 0, 1, 0), std::invalid_argument);
}

// Requirement (issue 3 item 2): a part is cut into patches of at most size x size elements, every
// element in exactly one patch, patches contiguous blocks.
TEST(Mesh, CutIntoPatches)
{
  int        np;
  const auto p = CutIntoPatches(10, 7, 4, &np);
  EXPECT_EQ(np, 3 * 2);
  std::vector<int> count(np, 0);
  for (int v : p) count.at(v)++;
  EXPECT_EQ(count[0], 16); // full 4 x 4 block
  EXPECT_EQ(count[2], 2 * 4); // last column: 2 elements wide
  EXPECT_EQ(count[5], 2 * 3); // corner: 2 x 3
  EXPECT_EQ(p[0], 0);
  EXPECT_EQ(p[9 + 6 * 10], 5);
  EXPECT_THROW(CutIntoPatches(4, 4, 0, &np), std::invalid_argument);
}

// Requirement (issue 3 item 3): the footprint is the set of nodes within the radius, measured in the
// plane normal to the fastener axis (the height of the node along the axis does not matter).
TEST(Mesh, Footprint)
{
  QuadMesh m = RectanglePlate(0, 0, 8, 8, 8, 8, 0);
  const auto f = Footprint(m, {4, 4, 5}, {0, 0, 1}, 1.0);
  std::set<std::array<double, 2>> got;
  for (int n : f) got.insert({m.x[n][0], m.x[n][1]});
  const std::set<std::array<double, 2>> want = {{4, 4}, {3, 4}, {5, 4}, {4, 3}, {4, 5}};
  EXPECT_EQ(got, want);
  EXPECT_TRUE(Footprint(m, {4.5, 4.5, 0}, {0, 0, 1}, 0.5).empty());
}

// Requirement (issue 3 item 3): the penalty rigid link does no work on any rigid motion of the pair
// (six of them), is symmetric, and resists every relative motion: its null space is exactly the
// six rigid motions (rank 6 of 12).
TEST(Coupling, RigidLinkPenaltyRigidModes)
{
  const std::array<double, 3> d = {2.5, -1.0, 0.75};
  const double                k = 1e6, kr = 3e7;
  const auto                  K = RigidLinkPenalty(d, k, kr);
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) EXPECT_DOUBLE_EQ(K[12 * i + j], K[12 * j + i]);
  // Rigid motion: translation a and rotation w about the master: u = a + w x (x - x_m).
  for (int mode = 0; mode < 6; ++mode) {
    double a[3] = {0, 0, 0}, w[3] = {0, 0, 0};
    (mode < 3 ? a[mode] : w[mode - 3]) = 1.0;
    std::array<double, 12> u{};
    const double           wxd[3] = {w[1] * d[2] - w[2] * d[1], w[2] * d[0] - w[0] * d[2], w[0] * d[1] - w[1] * d[0]};
    for (int i = 0; i < 3; ++i) {
      u[i]     = a[i] + wxd[i]; // slave at d
      u[3 + i] = w[i];
      u[6 + i] = a[i]; // master at 0
      u[9 + i] = w[i];
    }
    for (int i = 0; i < 12; ++i) {
      double f = 0;
      for (int j = 0; j < 12; ++j) f += K[12 * i + j] * u[j];
      EXPECT_NEAR(f, 0.0, 1e-9 * kr) << "mode " << mode << " row " << i;
    }
  }
  // A relative translation of the slave costs k per unit, a relative rotation k_r.
  std::array<double, 12> u{};
  u[1] = 1.0;
  double e = 0;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) e += u[i] * K[12 * i + j] * u[j];
  EXPECT_NEAR(e, k, 1e-9 * k);
}

// Requirement (issue 3 item 3, exact elimination): G maps a rigid motion to zero and the slave's
// dof to themselves (G's slave block is the identity).
TEST(Coupling, RigidLinkConstraint)
{
  const std::array<double, 3> d = {0.0, 3.0, 0.0};
  const auto                  G = RigidLinkConstraint(d);
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) EXPECT_EQ(G[12 * r + c], r == c ? 1.0 : 0.0);
  // Rotation of the master about z by w: the slave at (0, 3, 0) moves by w x d = (-3 w, 0, 0).
  std::array<double, 12> u{};
  u[11] = 0.01;
  u[0]  = -0.03;
  u[5]  = 0.01;
  for (int r = 0; r < 6; ++r) {
    double g = 0;
    for (int c = 0; c < 12; ++c) g += G[12 * r + c] * u[c];
    EXPECT_NEAR(g, 0.0, 1e-15);
  }
}

#include "mesh/gmsh.hpp"

#ifndef BOLTNET_TEST_DATA
#error "BOLTNET_TEST_DATA must name test/data"
#endif

namespace {
std::string Data(const char *f) { return std::string(BOLTNET_TEST_DATA) + "/" + f; }

std::string ErrorOf(const std::string &path)
{
  try {
    ReadGmsh(path);
  } catch (const std::runtime_error &e) {
    return e.what();
  }
  return "";
}
} // namespace

// Requirement (issue 3 item 2): physical surface groups of a Gmsh MSH 4.1 file are the parts, with
// their own node numbering; physical curve groups become node sets of the parts that hold them.
TEST(Gmsh, PartsAndBoundarySets)
{
  const auto parts = ReadGmsh(Data("two-parts.msh"));
  ASSERT_EQ(parts.size(), 2u);
  const QuadMesh &skin = parts.at("skin"), &doubler = parts.at("doubler");
  EXPECT_EQ(skin.x.size(), 6u);
  EXPECT_EQ(skin.quads.size(), 2u);
  EXPECT_EQ(doubler.x.size(), 4u);
  EXPECT_EQ(doubler.quads.size(), 1u);
  for (int n : doubler.quads[0]) EXPECT_DOUBLE_EQ(doubler.x[n][2], 1.0);
  ASSERT_TRUE(skin.node_sets.count("clamp"));
  EXPECT_FALSE(doubler.node_sets.count("clamp"));
  for (int n : skin.node_sets.at("clamp")) EXPECT_DOUBLE_EQ(skin.x[n][0], 0.0);
  EXPECT_EQ(skin.node_sets.at("clamp").size(), 2u);
  // First quad of the skin: nodes (0,0), (1,0), (1,1), (0,1).
  const auto &q = skin.quads[0];
  EXPECT_DOUBLE_EQ(skin.x[q[2]][0], 1.0);
  EXPECT_DOUBLE_EQ(skin.x[q[2]][1], 1.0);
}

// Requirement (issue 3 item 8): a mesh file that does not exist, is not a mesh, is in another MSH
// version, or has triangles is rejected with a message naming the file and what is wrong.
TEST(Gmsh, BadInput)
{
  EXPECT_NE(ErrorOf(Data("no-such-file.msh")).find("Cannot read the mesh file"), std::string::npos);
  EXPECT_NE(ErrorOf(Data("not-a-mesh.msh")).find("is not a Gmsh mesh"), std::string::npos);
  EXPECT_NE(ErrorOf(Data("msh22.msh")).find("MSH version 2.2 is not supported"), std::string::npos);
  const std::string tri = ErrorOf(Data("triangles.msh"));
  EXPECT_NE(tri.find("triangles.msh"), std::string::npos);
  EXPECT_NE(tri.find("part 'skin' has triangles"), std::string::npos);
}
