// A pressure on a shell part as consistent nodal forces (patch/loads.hpp): their resultant and its
// moment against the closed forms p A n and p A n x c (A the loaded area, c its centroid), on
// quadrilaterals, triangles and a mix, flat and tilted, on the whole part and on a node set; and
// the same nodal forces, node by node, once the part is cut into patches (the elements on the cuts
// are shared by several patches, each adding the rows of its own nodes); with exact coupling, the
// share of a footprint moved to its joint node with the same resultant and moment.
#include "patch/layout_steps.hpp"
#include "patch/loads.hpp"
#include "mesh/mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace boltnet;

namespace {

using Vec3 = std::array<double, 3>;

constexpr double kP = 0.2;                // MPa
constexpr double kLx = 100, kLy = 60;     // mm
constexpr double kLeft = 40;              // the node set "left": x <= 40 mm
constexpr PetscInt kPart = 5;

// The plate turned about the x axis by angle a (its normal (0, -sin a, cos a)).
Vec3 Turn(const Vec3 &x, double a) { return {x[0], std::cos(a) * x[1] - std::sin(a) * x[2], std::sin(a) * x[1] + std::cos(a) * x[2]}; }

ShellPatch Plate(PlateElements kind, double angle)
{
  ShellPatch p;
  p.id   = kPart;
  p.mesh = RectanglePlate(0, 0, kLx, kLy, 10, 6, 0, kind);
  std::vector<int> &left = p.mesh.node_sets["left"];
  for (size_t v = 0; v < p.mesh.x.size(); ++v)
    if (p.mesh.x[v][0] <= kLeft + 1e-9) left.push_back((int)v);
  for (Vec3 &x : p.mesh.x) x = Turn(x, angle);
  p.material = shell::IsotropicMaterial(70000, 0.3, 2);
  return p;
}

Model PressureOn(const std::string &set)
{
  Model m;
  m.parts.push_back({kPart, PatchKind::Shell, {0, 0, 0}});
  m.bcs.push_back({kPart, set, -1, BOLTNET_BC_PRESSURE, kP});
  return m;
}

// The nodal forces of `loads` by part node (part_node maps the patch's nodes; empty: the same).
void AddByPartNode(const ShellPatch &p, const PatchLoads &loads, std::vector<double> &f)
{
  for (const auto &[dof, value] : loads.force) {
    const PetscInt node = dof / 6;
    ASSERT_LT(node, (PetscInt)p.mesh.x.size()) << "a pressure loads mesh nodes only";
    const int part_node = p.part_node.empty() ? (int)node : p.part_node[node];
    f[6 * part_node + dof % 6] += value;
  }
}

struct Case {
  PlateElements kind;
  double        angle;
};

class PressureLoads : public ::testing::TestWithParam<Case> {};

TEST_P(PressureLoads, ResultantAndMomentAreClosedForm)
{
  const Case c = GetParam();
  for (const std::string set : {"", "left"}) {
    const ShellPatch whole = Plate(c.kind, c.angle);
    const Model      m     = PressureOn(set);
    PatchLoads       loads;
    ASSERT_EQ(PatchLoadsFromModel(PETSC_COMM_SELF, m, kPart, &whole, CouplingType::Node, &loads), 0);
    std::vector<double> f(6 * whole.mesh.x.size(), 0.0);
    AddByPartNode(whole, loads, f);
    const double lx = set.empty() ? kLx : kLeft;
    const double A  = lx * kLy;
    const Vec3   n  = Turn({0, 0, 1}, c.angle), centroid = Turn({lx / 2, kLy / 2, 0}, c.angle);
    Vec3         F{}, M{};
    for (size_t v = 0; v < whole.mesh.x.size(); ++v) {
      const Vec3 &x = whole.mesh.x[v];
      const Vec3  fv{f[6 * v], f[6 * v + 1], f[6 * v + 2]};
      for (int k = 0; k < 3; ++k) F[k] += fv[k];
      M[0] += x[1] * fv[2] - x[2] * fv[1], M[1] += x[2] * fv[0] - x[0] * fv[2], M[2] += x[0] * fv[1] - x[1] * fv[0];
      for (int k = 3; k < 6; ++k) EXPECT_EQ(f[6 * v + k], 0.0) << "no moment at a node";
    }
    const Vec3 Mref{kP * A * (centroid[1] * n[2] - centroid[2] * n[1]), kP * A * (centroid[2] * n[0] - centroid[0] * n[2]), kP * A * (centroid[0] * n[1] - centroid[1] * n[0])};
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(F[k], kP * A * n[k], 1e-12 * kP * A) << "set '" << set << "', force component " << k;
      EXPECT_NEAR(M[k], Mref[k], 1e-12 * kP * A * kLx) << "set '" << set << "', moment component " << k;
    }

    // Cut into patches of at most 12 nodes: the same nodal forces, whatever patch adds them.
    ShellPatch part = Plate(c.kind, c.angle);
    Layout     L;
    NodeMap    nodemap;
    CutShellPart(std::move(part), 0, 12, &L, nodemap);
    ASSERT_GT(L.shells.size(), 3u);
    size_t shared = 0;
    std::vector<double> g(f.size(), 0.0);
    for (const auto &[pos, sp] : L.shells) {
      PatchLoads pl;
      ASSERT_EQ(PatchLoadsFromModel(PETSC_COMM_SELF, m, kPart, &sp, CouplingType::Node, &pl), 0);
      AddByPartNode(sp, pl, g);
      shared += sp.shared.size();
    }
    EXPECT_GT(shared, 0u) << "the cut shares elements between patches";
    for (size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(g[i], f[i], 1e-12 * kP * A) << "set '" << set << "', part dof " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Elements, PressureLoads,
                         ::testing::Values(Case{PlateElements::Quads, 0}, Case{PlateElements::Triangles, 0}, Case{PlateElements::Mixed, 0}, Case{PlateElements::Quads, 0.7},
                                           Case{PlateElements::Mixed, -2.1}));

// With exact coupling the footprint nodes are slaves of their joint node: the pressure's forces on
// them go to the joint node, with the same resultant and moment (p A n and its moment about the
// origin, the joint node's position the lever of what it receives); no footprint row keeps a load.
TEST(PressureLoads, FootprintShareGoesToTheJointNode)
{
  ShellPatch        p = Plate(PlateElements::Mixed, 0.7);
  const Vec3        at = Turn({52, 31, 0}, 0.7), axis = Turn({0, 0, 1}, 0.7);
  const std::vector<int> fp = CouplingFootprint(p.mesh, at, axis, 12);
  ASSERT_GE(fp.size(), 4u);
  p.joint_nodes.push_back({at, axis, fp});
  const Model m = PressureOn("");
  PatchLoads  loads;
  ASSERT_EQ(PatchLoadsFromModel(PETSC_COMM_SELF, m, kPart, &p, CouplingType::Exact, &loads), 0);
  const PetscInt nmesh = (PetscInt)p.mesh.x.size();
  Vec3           F{}, M{};
  for (const auto &[dof, f] : loads.force) {
    const PetscInt node = dof / 6, i = dof % 6;
    for (int v : fp) EXPECT_NE(node, v) << "a footprint node keeps a load";
    const Vec3 &x = node < nmesh ? p.mesh.x[node] : p.joint_nodes[node - nmesh].x;
    if (i < 3) {
      F[i] += f;
      Vec3 e{}, xf;
      e[i] = f;
      xf   = {x[1] * e[2] - x[2] * e[1], x[2] * e[0] - x[0] * e[2], x[0] * e[1] - x[1] * e[0]};
      for (int k = 0; k < 3; ++k) M[k] += xf[k];
    } else M[i - 3] += f;
  }
  EXPECT_TRUE(loads.force.count(6 * nmesh + 2) || loads.force.count(6 * nmesh + 1)) << "the joint node receives the footprint's share";
  const double A = kLx * kLy;
  const Vec3   n = Turn({0, 0, 1}, 0.7), c = Turn({kLx / 2, kLy / 2, 0}, 0.7);
  const Vec3   Mref{kP * A * (c[1] * n[2] - c[2] * n[1]), kP * A * (c[2] * n[0] - c[0] * n[2]), kP * A * (c[0] * n[1] - c[1] * n[0])};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(F[k], kP * A * n[k], 1e-12 * kP * A) << "force component " << k;
    EXPECT_NEAR(M[k], Mref[k], 1e-12 * kP * A * kLx) << "moment component " << k;
  }
}

// A node set of a curve holds no element: the pressure on it loads nothing, and the layout refuses
// it (HasElementIn).
TEST(PressureLoads, CurveSetHoldsNoElement)
{
  const ShellPatch p = Plate(PlateElements::Quads, 0);
  EXPECT_FALSE(HasElementIn(p.mesh, "xmin"));
  EXPECT_TRUE(HasElementIn(p.mesh, "left"));
  EXPECT_FALSE(HasElementIn(p.mesh, "no such set"));
}

} // namespace

int main(int argc, char **argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  if (PetscInitialize(&argc, &argv, nullptr, nullptr)) return 1;
  const int rc = RUN_ALL_TESTS();
  if (PetscFinalize()) return 1;
  return rc;
}
