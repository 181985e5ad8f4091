// Unit tests of the plate generator, the cut into patches, the fastener footprint and the rigid
// patch coupling (the pieces that do not need the shell element).
#include "patch/rigid.hpp"
#include "mesh/cut.hpp"
#include "mesh/mesh.hpp"
#include "mesh/search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace boltnet;

// Requirement: a generated rectangular plate has the right nodes, elements and
// edge node sets, and its elements are counter-clockwise with the plate's area.
TEST(Mesh, RectanglePlate)
{
  const ShellMesh m = RectanglePlate(10, 20, 150, 20, 15, 4, 1.5);
  EXPECT_EQ(m.x.size(), 16u * 5u);
  EXPECT_EQ(m.elems.size(), 60u);
  EXPECT_EQ(m.node_sets.at("xmin").size(), 5u);
  EXPECT_EQ(m.node_sets.at("ymax").size(), 16u);
  for (int n : m.node_sets.at("xmax")) EXPECT_DOUBLE_EQ(m.x[n][0], 160.0);
  double area = 0;
  for (const auto &q : m.elems) { // shoelace formula, positive when counter-clockwise
    double a = 0;
    for (int k = 0; k < 4; ++k) a += m.x[q[k]][0] * m.x[q[(k + 1) % 4]][1] - m.x[q[(k + 1) % 4]][0] * m.x[q[k]][1];
    EXPECT_GT(a, 0);
    area += 0.5 * a;
  }
  EXPECT_NEAR(area, 150.0 * 20.0, 1e-9);
  EXPECT_THROW(RectanglePlate(0, 0, 1, 1, 0, 1, 0), std::invalid_argument);
}

// The properties every cut must have (docs/architecture.md, "Patches and seams"): each node in one
// patch, no empty patch, each cluster (a footprint and its elements) whole, each patch connected.
void ExpectValidCut(const ShellMesh &m, const PartCut &c, const std::vector<std::vector<int>> &clusters)
{
  ASSERT_EQ(c.patch.size(), m.x.size());
  std::vector<int> count(c.npatches, 0);
  for (int p : c.patch) {
    ASSERT_GE(p, 0);
    ASSERT_LT(p, c.npatches);
    count[p]++;
  }
  for (int n : count) EXPECT_GT(n, 0);
  for (const auto &cl : clusters)
    for (int n : cl) EXPECT_EQ(c.patch[n], c.patch[cl[0]]);
  // Connected: a flood fill through the elements' node pairs within one patch reaches all its nodes.
  std::vector<std::set<int>> adj(m.x.size());
  for (const auto &q : m.elems)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        if (c.patch[q[a]] == c.patch[q[b]] && a != b) adj[q[a]].insert(q[b]);
  for (int p = 0; p < c.npatches; ++p) {
    int start = -1;
    for (size_t i = 0; i < m.x.size() && start < 0; ++i)
      if (c.patch[i] == p) start = (int)i;
    std::set<int>    seen = {start};
    std::vector<int> todo = {start};
    while (!todo.empty()) {
      const int v = todo.back();
      todo.pop_back();
      for (int w : adj[v])
        if (seen.insert(w).second) todo.push_back(w);
    }
    EXPECT_EQ((int)seen.size(), count[p]) << "patch " << p << " is not connected";
  }
}

// Elements whose nodes lie in more than one patch (what the seams and the ports pay for).
int CrossElements(const ShellMesh &m, const PartCut &c)
{
  int n = 0;
  for (const auto &q : m.elems) {
    std::set<int> s;
    for (int k = 0; k < 4; ++k) s.insert(c.patch[q[k]]);
    n += s.size() > 1;
  }
  return n;
}

// A part larger than the patch size is cut by METIS into ceil(nodes / size) patches of about the
// same size, keeping each fastener footprint whole.
TEST(Mesh, CutPart)
{
  const ShellMesh m = RectanglePlate(0, 0, 20, 200, 4, 40, 0); // 5 x 41 nodes, long in y
  const auto     fp = Footprint(m, {10, 102.5, 0}, {0, 0, 1}, 6.0);
  ASSERT_GT(fp.size(), 4u);
  const PartCut c = CutPart(m, {fp}, 50);
  EXPECT_EQ(c.npatches, 5); // ceil(205 / 50)
  ExpectValidCut(m, c, {fp});
  std::vector<int> count(c.npatches, 0);
  for (int p : c.patch) count[p]++;
  for (int n : count) EXPECT_NEAR(n, 41.0, 12.0); // a footprint moves a few nodes
}

// No cut: a size of 0, or a part within the size; one node more than the size makes two patches.
TEST(Mesh, CutPartKeepsSmallParts)
{
  const ShellMesh m = RectanglePlate(0, 0, 20, 20, 4, 4, 0);
  EXPECT_EQ(CutPart(m, {}, 0).npatches, 1);
  EXPECT_EQ(CutPart(m, {}, 25).npatches, 1);
  const PartCut c = CutPart(m, {}, 24);
  EXPECT_EQ(c.npatches, 2);
  ExpectValidCut(m, c, {});
  // A footprint covering the whole plate forbids any cut.
  std::vector<int> all(m.x.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = (int)i;
  EXPECT_EQ(CutPart(m, {all}, 5).npatches, 1);
}

// A graph partitioner, not strips: a square plate cut in four crosses fewer elements than three
// straight cuts across it (the strips' 3 x 40 = 120 elements), which is what keeps the interface
// of condensed patches small.
TEST(Mesh, CutPartBeatsStrips)
{
  const ShellMesh m = RectanglePlate(0, 0, 400, 400, 40, 40, 0); // 41 x 41 nodes
  const PartCut  c = CutPart(m, {}, 421);                     // ceil(1681 / 421) = 4 patches
  EXPECT_EQ(c.npatches, 4);
  ExpectValidCut(m, c, {});
  EXPECT_LT(CrossElements(m, c), 120);
}

// Requirement: the footprint is the set of nodes within the radius, measured in the
// plane normal to the fastener axis (the height of the node along the axis does not matter).
TEST(Mesh, Footprint)
{
  ShellMesh m = RectanglePlate(0, 0, 8, 8, 8, 8, 0);
  const auto f = Footprint(m, {4, 4, 5}, {0, 0, 1}, 1.0);
  std::set<std::array<double, 2>> got;
  for (int n : f) got.insert({m.x[n][0], m.x[n][1]});
  const std::set<std::array<double, 2>> want = {{4, 4}, {3, 4}, {5, 4}, {4, 3}, {4, 5}};
  EXPECT_EQ(got, want);
  EXPECT_TRUE(Footprint(m, {4.5, 4.5, 0}, {0, 0, 1}, 0.5).empty());
}

// The spatial index finds, on a flat part, exactly what the brute-force search of every node finds
// (footprints, containing elements, nearest nodes), for fasteners all over the plate and off it.
TEST(Mesh, FootprintFinderMatchesBruteForce)
{
  const ShellMesh  m = RectanglePlate(-3, 7, 60, 45, 23, 17, 2.0);
  FootprintFinder finder(m, 16.0);
  for (int i = 0; i < 200; ++i) {
    const std::array<double, 3> p    = {-10 + 0.37 * i, 5 + std::fmod(7.3 * i, 50.0), 1.0 + 0.01 * (i % 7)};
    const std::array<double, 3> axis = {0, 0, i % 2 ? 1.0 : -2.0};
    const double                r    = 1.0 + (i % 5);
    EXPECT_EQ(finder.Footprint(p, axis, r), Footprint(m, p, axis, r)) << "point " << i;
    EXPECT_EQ(finder.CouplingFootprint(p, axis, r), CouplingFootprint(m, p, axis, r)) << "point " << i;
    EXPECT_EQ(finder.ContainingElement(p, axis), ContainingElement(m, p, axis)) << "point " << i;
    EXPECT_EQ(finder.NearestNode(p, axis), NearestNode(m, p, axis)) << "point " << i;
  }
}

// On a closed part (a barrel, radius 100) a radial fastener's axis passes through the far side too:
// the brute-force search takes both sides, the finder only the sheet nearest the fastener.
TEST(Mesh, FootprintFinderNearestSheet)
{
  ShellMesh     m;
  const int    nc = 64, nl = 10;
  const double R = 100, pi = std::acos(-1.0);
  for (int j = 0; j <= nl; ++j)
    for (int i = 0; i < nc; ++i) m.x.push_back({R * std::cos(2 * pi * i / nc), R * std::sin(2 * pi * i / nc), 10.0 * j});
  for (int j = 0; j < nl; ++j)
    for (int i = 0; i < nc; ++i) m.elems.push_back({j * nc + i, j * nc + (i + 1) % nc, (j + 1) * nc + (i + 1) % nc, (j + 1) * nc + i});
  const std::array<double, 3> p = {R + 1.0, 0, 50}, axis = {1, 0, 0};
  const auto                  brute = Footprint(m, p, axis, 12.0);
  const auto                  near  = FootprintFinder(m, 16.0).Footprint(p, axis, 12.0);
  ASSERT_FALSE(near.empty());
  for (int n : near) EXPECT_GT(m.x[n][0], 0.9 * R);
  bool far = false;
  for (int n : brute) far = far || m.x[n][0] < -0.9 * R;
  EXPECT_TRUE(far) << "the brute-force search should see the far side";
  EXPECT_LT(near.size(), brute.size());
}

// Requirement: the penalty rigid link does no work on any rigid motion of the pair
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

// Requirement (exact elimination): G maps a rigid motion to zero and the slave's
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

// Requirement: physical surface groups of a Gmsh MSH 4.1 file are the parts, with
// their own node numbering; physical curve groups become node sets of the parts that hold them.
TEST(Gmsh, PartsAndBoundarySets)
{
  const auto parts = ReadGmsh(Data("two-parts.msh"));
  ASSERT_EQ(parts.size(), 2u);
  const ShellMesh &skin = parts.at("skin"), &doubler = parts.at("doubler");
  EXPECT_EQ(skin.x.size(), 6u);
  EXPECT_EQ(skin.elems.size(), 2u);
  EXPECT_EQ(doubler.x.size(), 4u);
  EXPECT_EQ(doubler.elems.size(), 1u);
  for (int n : doubler.elems[0]) EXPECT_DOUBLE_EQ(doubler.x[n][2], 1.0);
  ASSERT_TRUE(skin.node_sets.count("clamp"));
  EXPECT_FALSE(doubler.node_sets.count("clamp"));
  for (int n : skin.node_sets.at("clamp")) EXPECT_DOUBLE_EQ(skin.x[n][0], 0.0);
  EXPECT_EQ(skin.node_sets.at("clamp").size(), 2u);
  // First quad of the skin: nodes (0,0), (1,0), (1,1), (0,1).
  const auto &q = skin.elems[0];
  EXPECT_DOUBLE_EQ(skin.x[q[2]][0], 1.0);
  EXPECT_DOUBLE_EQ(skin.x[q[2]][1], 1.0);
}

// Requirement: a mesh file that does not exist, is not a mesh, or is in another
// MSH version is rejected with a message naming the file and what is wrong (element types other
// than triangles and quadrangles: MeshTriangles.Gmsh).
TEST(Gmsh, BadInput)
{
  EXPECT_NE(ErrorOf(Data("no-such-file.msh")).find("Cannot read the mesh file"), std::string::npos);
  EXPECT_NE(ErrorOf(Data("not-a-mesh.msh")).find("is not a Gmsh mesh"), std::string::npos);
  EXPECT_NE(ErrorOf(Data("msh22.msh")).find("MSH version 2.2 is not supported"), std::string::npos);
}
