// Triangles and mixed meshes in lib/mesh: the split plate, the element search against brute force,
// the cut, nodal directors and the Gmsh reader (pure C++, no PETSc).
#include "mesh/cut.hpp"
#include "mesh/gmsh.hpp"
#include "mesh/mesh.hpp"
#include "mesh/search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>

using namespace boltnet;

namespace {

using Vec = std::array<double, 3>;
const double kPi = std::acos(-1.0);

Vec Sub(const Vec &a, const Vec &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec Cross(const Vec &a, const Vec &b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double Dot(const Vec &a, const Vec &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double Norm(const Vec &a) { return std::sqrt(Dot(a, a)); }
double Angle(const Vec &a, const Vec &b) { return std::atan2(Norm(Cross(a, b)), Dot(a, b)); }

// A small deterministic generator (the same points on every machine).
struct Lcg {
  unsigned long long s = 12345;
  double             operator()()
  {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(s >> 11) / 9007199254740992.0;
  }
};

// The reference the search is checked against, written independently of mesh.cpp: p lies in
// element e (projected along the unit axis n) when its barycentric coordinates in one of the
// element's triangles (a quadrilateral as the two triangles of a diagonal: the plates here are
// convex) are all >= -tol; among those, the smallest |mean axial distance|, the lowest number first.
int BruteContaining(const ShellMesh &m, const Vec &p, const Vec &n)
{
  auto inTriangle = [&](const Vec &a, const Vec &b, const Vec &c) {
    const Vec    ab = Sub(b, a), ac = Sub(c, a), ap = Sub(p, a);
    const double area = Dot(Cross(ab, ac), n); // twice the projected area, signed
    const double l1 = Dot(Cross(ap, ac), n) / area, l2 = Dot(Cross(ab, ap), n) / area;
    return l1 >= -1e-9 && l2 >= -1e-9 && 1 - l1 - l2 >= -1e-9;
  };
  int    best  = -1;
  double bestd = 0;
  for (size_t e = 0; e < m.elems.size(); ++e) {
    const auto &q  = m.elems[e];
    const int   nn = ElementNodes(q);
    bool        in = inTriangle(m.x[q[0]], m.x[q[1]], m.x[q[2]]) || (nn == 4 && inTriangle(m.x[q[0]], m.x[q[2]], m.x[q[3]]));
    if (!in) continue;
    double d = 0;
    for (int k = 0; k < nn; ++k) d += Dot(Sub(m.x[q[k]], p), n) / nn;
    if (best < 0 || std::fabs(d) < bestd - 1e-12) best = (int)e, bestd = std::fabs(d);
  }
  return best;
}

// The mesh turned by a rotation about (1, 2, 2)/3 and moved, so that the searches work in 3D.
ShellMesh Tilted(ShellMesh m, Vec *normal)
{
  const double c = std::cos(0.7), s = std::sin(0.7), u[3] = {1.0 / 3, 2.0 / 3, 2.0 / 3};
  double       R[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R[i][j] = (i == j ? c : 0) + (1 - c) * u[i] * u[j];
  R[0][1] -= s * u[2], R[0][2] += s * u[1], R[1][0] += s * u[2], R[1][2] -= s * u[0], R[2][0] -= s * u[1], R[2][1] += s * u[0];
  for (auto &x : m.x) {
    const Vec y = x;
    for (int i = 0; i < 3; ++i) x[i] = R[i][0] * y[0] + R[i][1] * y[1] + R[i][2] * y[2] + 10.0 * (i + 1);
  }
  *normal = {R[0][2], R[1][2], R[2][2]};
  return m;
}

} // namespace

// Requirement: a plate split into triangles (or mixed) covers the same area with counter-clockwise
// elements, two triangles per cell (one per odd cell when mixed), the same nodes and node sets as the
// quadrilateral plate; the triangles' diagonals alternate, so the split plate is symmetric about its
// centre lines.
TEST(MeshTriangles, SplitPlate)
{
  const ShellMesh q = RectanglePlate(10, 20, 150, 20, 12, 4, 1.5);
  for (PlateElements kind : {PlateElements::Triangles, PlateElements::Mixed}) {
    const ShellMesh m = RectanglePlate(10, 20, 150, 20, 12, 4, 1.5, kind);
    EXPECT_EQ(m.x, q.x);
    EXPECT_EQ(m.node_sets, q.node_sets);
    int ntri = 0, nquad = 0;
    double area = 0;
    for (const auto &e : m.elems) {
      const int nn = ElementNodes(e);
      (nn == 3 ? ntri : nquad)++;
      double a = 0;
      for (int k = 0; k < nn; ++k) a += m.x[e[k]][0] * m.x[e[(k + 1) % nn]][1] - m.x[e[(k + 1) % nn]][0] * m.x[e[k]][1];
      EXPECT_GT(a, 0);
      area += 0.5 * a;
    }
    EXPECT_NEAR(area, 150.0 * 20.0, 1e-9);
    EXPECT_EQ(ntri, kind == PlateElements::Triangles ? 96 : 48);
    EXPECT_EQ(nquad, kind == PlateElements::Triangles ? 0 : 24);
    // Symmetry about x = 85 and y = 30: each element's mirror image is an element.
    std::set<std::set<std::array<long, 2>>> shapes, mirrored;
    for (const auto &e : m.elems) {
      std::set<std::array<long, 2>> s, t;
      for (int k = 0; k < ElementNodes(e); ++k) {
        const long x = std::lround(m.x[e[k]][0] * 8), y = std::lround(m.x[e[k]][1] * 8);
        s.insert({x, y});
        t.insert({2 * 85 * 8 - x, 2 * 30 * 8 - y});
      }
      shapes.insert(s);
      mirrored.insert(t);
    }
    if (kind == PlateElements::Triangles) {
      EXPECT_EQ(shapes, mirrored);
    }
  }
}

// Requirement: the element containing a fastener is found on triangle and mixed meshes as the
// barycentric brute force finds it (random points in and around a tilted plate; at every node, one
// of the elements touching it), by the mesh function and by the spatial index; the
// coupling footprint's fallback takes the three nodes of a containing triangle.
TEST(MeshTriangles, ContainingElementMatchesBruteForce)
{
  for (PlateElements kind : {PlateElements::Triangles, PlateElements::Mixed}) {
    Vec             n;
    const ShellMesh m = Tilted(RectanglePlate(-3, 7, 60, 45, 13, 9, 0.0, kind), &n);
    FootprintFinder finder(m, 16.0);
    Lcg             rnd;
    int             inside = 0;
    for (int i = 0; i < 400; ++i) {
      // A point of the plate's plane, up to 5 mm outside it, then off the plane along the normal.
      const double a = -8 + 70 * rnd(), b = 2 + 55 * rnd(), h = 3 * (rnd() - 0.5);
      Vec          p;
      const Vec    o = m.x[0], ex = Sub(m.x[1], m.x[0]), ey = Sub(m.x[14], m.x[0]);
      for (int k = 0; k < 3; ++k) p[k] = o[k] + (a + 3) / (60.0 / 13) * ex[k] + (b - 7) / (45.0 / 9) * ey[k] + h * n[k];
      const Vec axis = i % 2 ? n : Vec{-2 * n[0], -2 * n[1], -2 * n[2]};
      const int want = BruteContaining(m, p, n);
      inside += want >= 0;
      EXPECT_EQ(ContainingElement(m, p, axis), want) << "point " << i;
      EXPECT_EQ(finder.ContainingElement(p, axis), want) << "point " << i;
      if (want >= 0 && ElementNodes(m.elems[want]) == 3) {
        std::vector<int> three(m.elems[want].begin(), m.elems[want].begin() + 3);
        std::sort(three.begin(), three.end());
        EXPECT_EQ(CouplingFootprint(m, p, axis, 1e-3), three) << "point " << i;
        EXPECT_EQ(finder.CouplingFootprint(p, axis, 1e-3), three) << "point " << i;
      }
    }
    EXPECT_GT(inside, 250);
    EXPECT_LT(inside, 400);
    // At a node every element touching it contains it, at the same distance but for round-off.
    const auto touching = NodeElements(m);
    for (size_t v = 0; v < m.x.size(); ++v) {
      const std::set<int> t(touching[v].begin(), touching[v].end());
      EXPECT_TRUE(t.count(ContainingElement(m, m.x[v], n))) << "node " << v;
      EXPECT_TRUE(t.count(finder.ContainingElement(m.x[v], n))) << "node " << v;
    }
  }
}

// Requirement: the spatial index gives on triangle and mixed meshes what the brute-force searches
// give (footprints, coupling footprints, nearest nodes).
TEST(MeshTriangles, FootprintFinderMatchesBruteForce)
{
  for (PlateElements kind : {PlateElements::Triangles, PlateElements::Mixed}) {
    const ShellMesh m = RectanglePlate(-3, 7, 60, 45, 23, 17, 2.0, kind);
    FootprintFinder finder(m, 16.0);
    for (int i = 0; i < 200; ++i) {
      const Vec    p    = {-10 + 0.37 * i, 5 + std::fmod(7.3 * i, 50.0), 1.0 + 0.01 * (i % 7)};
      const Vec    axis = {0, 0, i % 2 ? 1.0 : -2.0};
      const double r    = 0.5 + (i % 5);
      EXPECT_EQ(finder.Footprint(p, axis, r), Footprint(m, p, axis, r)) << "point " << i;
      EXPECT_EQ(finder.CouplingFootprint(p, axis, r), CouplingFootprint(m, p, axis, r)) << "point " << i;
      EXPECT_EQ(finder.NearestNode(p, axis), NearestNode(m, p, axis)) << "point " << i;
    }
  }
}

// Requirement: a triangle or mixed part is cut like a quadrilateral one: every node in one patch,
// patches connected through the elements, each footprint cluster whole, and about equal sizes.
TEST(MeshTriangles, CutPart)
{
  for (PlateElements kind : {PlateElements::Triangles, PlateElements::Mixed}) {
    const ShellMesh m  = RectanglePlate(0, 0, 40, 400, 8, 80, 0, kind); // 9 x 81 nodes
    const auto      fp = Footprint(m, {20, 202.5, 0}, {0, 0, 1}, 6.0);
    const PartCut   c  = CutPart(m, {fp}, 150);
    EXPECT_EQ(c.npatches, 5); // ceil(729 / 150)
    for (int v : fp) EXPECT_EQ(c.patch[v], c.patch[fp[0]]);
    std::vector<int> count(c.npatches, 0);
    for (int p : c.patch) count[p]++;
    for (int nodes : count) EXPECT_NEAR(nodes, 729.0 / 5, 30.0);
    // Connected: a flood fill through the edges of elements within one patch.
    std::vector<std::set<int>> adj(m.x.size());
    for (const auto &q : m.elems)
      for (int a = 0; a < ElementNodes(q); ++a)
        for (int b = 0; b < ElementNodes(q); ++b)
          if (a != b && c.patch[q[a]] == c.patch[q[b]]) adj[q[a]].insert(q[b]);
    for (int p = 0; p < c.npatches; ++p) {
      int start = 0;
      while (c.patch[start] != p) ++start;
      std::set<int>    seen = {start};
      std::vector<int> todo = {start};
      while (!todo.empty()) {
        const int v = todo.back();
        todo.pop_back();
        for (int w : adj[v])
          if (seen.insert(w).second) todo.push_back(w);
      }
      EXPECT_EQ((int)seen.size(), count[p]) << "patch " << p;
    }
  }
}

namespace {
// A quarter cylinder of radius R along y (the surface x^2 + z^2 = R^2, 0 <= theta <= pi/2), n by n
// cells of the given kind, counter-clockwise about the inward normal -(x, 0, z) / R. The cells are
// graded along the arc (a uniform grid would give the exact normal inside by symmetry).
ShellMesh Cylinder(int n, PlateElements kind, double R)
{
  ShellMesh m = RectanglePlate(0, 0, 1, 1, n, n, 0, kind);
  for (auto &x : m.x) {
    const double th = kPi / 2 * (x[0] + 0.25 * std::sin(kPi * x[0])), y = 10 * x[1]; // graded
    x               = {R * std::cos(th), y, R * std::sin(th)};
  }
  return m;
}
} // namespace

// Requirement (docs/shell.md, "Warped elements and kinks"): on a curved mesh of triangles and
// quadrilaterals the nodal directors are the surface normal, all on one side of it: inside to second
// order in the element size (the largest angle falls by about 4 when the mesh is refined twice), on
// the free edges within half an element's angle (the mean is one-sided there); an element numbered
// clockwise changes none of them and receives them turned to its own side; a flat mesh gets none.
TEST(MeshTriangles, NodalDirectorsOnACylinder)
{
  EXPECT_TRUE(NodalDirectors(RectanglePlate(0, 0, 3, 2, 6, 4, 1.0, PlateElements::Mixed)).empty());
  double inner[2] = {0, 0};
  for (int level = 0; level < 2; ++level) {
    const int    n = 8 << level;
    const double h = kPi / 2 * 1.8 / n; // the largest angle of an element
    ShellMesh    m = Cylinder(n, PlateElements::Mixed, 5.0);
    const auto   V = NodalDirectors(m);
    ASSERT_EQ(V.size(), m.x.size());
    for (size_t v = 0; v < V.size(); ++v) {
      EXPECT_NEAR(Norm(V[v]), 1.0, 1e-14);
      const Vec exact = {-m.x[v][0] / 5.0, 0, -m.x[v][2] / 5.0};
      EXPECT_GT(Dot(V[v], exact), 0) << "node " << v << ": the mesh is counter-clockwise about the inward normal";
      const bool edge = m.x[v][2] < 1e-12 || m.x[v][0] < 1e-12; // theta = 0 or pi/2
      if (edge) EXPECT_LE(Angle(V[v], exact), h / 2 * (1 + 1e-12)) << "node " << v;
      else inner[level] = std::max(inner[level], Angle(V[v], exact));
    }
    if (level == 1) {
      // An element inside numbered clockwise: the same directors, turned to its side for it.
      const int e = (int)m.elems.size() / 2 + 5;
      std::swap(m.elems[e][1], m.elems[e][ElementNodes(m.elems[e]) - 1]);
      const auto W = NodalDirectors(m);
      for (size_t v = 0; v < V.size(); ++v) EXPECT_LT(Norm(Sub(W[v], V[v])), 1e-15) << "node " << v;
      m.directors = W;
      std::array<Vec, 4> D;
      ASSERT_TRUE(ElementDirectors(m, m.elems[e], D));
      for (int k = 0; k < ElementNodes(m.elems[e]); ++k) {
        EXPECT_LT(Dot(D[k], W[m.elems[e][k]]), -1 + 1e-15);
        EXPECT_GT(Dot(D[k], CornerNormal(m, m.elems[e], k)), 0);
      }
    }
  }
  const double h = kPi / 2 * 1.8 / 8;
  EXPECT_LT(inner[0], 0.2 * h * h) << "largest element angle " << h;
  EXPECT_GT(inner[0] / inner[1], 3.5) << inner[0] << " then " << inner[1];
  std::printf("cylinder directors, largest angle to the normal inside: %.3g, then %.3g refined\n", inner[0], inner[1]);
}

// Requirement: at a fold (two flat sheets at 90 deg, a flange) every element keeps its own normal:
// the fold's nodes get no director and no element is handed directors; a kink of 10 deg (a faceted
// curve) is averaged: both facets get the bisector at the kink.
TEST(MeshTriangles, NodalDirectorsAtFoldsAndKinks)
{
  for (double kink : {90.0, 10.0}) {
    ShellMesh         m = RectanglePlate(0, 0, 2, 1, 4, 2, 0, PlateElements::Mixed);
    const double      a = kink * kPi / 180;
    std::vector<char> fold(m.x.size());
    for (size_t v = 0; v < m.x.size(); ++v) {
      auto &x = m.x[v];
      fold[v] = x[0] == 1;
      if (x[0] > 1) x = {1 + (x[0] - 1) * std::cos(a), x[1], (x[0] - 1) * std::sin(a)};
    }
    const auto V = NodalDirectors(m);
    ASSERT_EQ(V.size(), m.x.size());
    m.directors = V;
    for (size_t v = 0; v < m.x.size(); ++v) {
      const bool onFold = fold[v];
      if (kink > 45) {
        EXPECT_NEAR(Norm(V[v]), onFold ? 0.0 : 1.0, 1e-15) << "node " << v;
      } else if (onFold) {
        EXPECT_LT(Angle(V[v], {-std::sin(a / 2), 0, std::cos(a / 2)}), 1e-14) << "node " << v;
      }
    }
    int handed = 0, touching = 0;
    for (const auto &e : m.elems) {
      std::array<Vec, 4> D;
      handed += ElementDirectors(m, e, D);
      bool t = false;
      for (int k = 0; k < ElementNodes(e); ++k) t = t || fold[e[k]];
      touching += t;
    }
    EXPECT_EQ(handed, kink > 45 ? 0 : touching) << "kink " << kink;
  }
}

namespace {
std::string GmshError(const std::string &text)
{
  try {
    ParseGmsh("test.msh", text);
  } catch (const std::runtime_error &e) {
    return e.what();
  }
  return "";
}

// A Gmsh MSH 4.1 file with one surface "skin" of the given element block (type, then one line per
// element) over the four nodes of the unit square and its centre.
std::string OneSurface(int type, const std::vector<std::string> &elements)
{
  std::string s = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n2 1 \"skin\"\n$EndPhysicalNames\n"
                  "$Entities\n0 0 1 0\n1 0 0 0 1 1 0 1 1 0\n$EndEntities\n"
                  "$Nodes\n1 5 1 5\n2 1 0 5\n1\n2\n3\n4\n5\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0\n$EndNodes\n";
  s += "$Elements\n1 " + std::to_string(elements.size()) + " 1 " + std::to_string(elements.size()) + "\n2 1 " + std::to_string(type) + " " + std::to_string(elements.size()) + "\n";
  for (const auto &e : elements) s += e + "\n";
  return s + "$EndElements\n";
}
} // namespace

#ifndef BOLTNET_TEST_DATA
#error "BOLTNET_TEST_DATA must name test/data"
#endif

// Requirement: Gmsh parts of 3-node triangles (type 2) and of both kinds are read, with their node
// sets; other element types in a part, a triangle naming a node twice and a node tag that is not
// positive are refused with a message naming the file, the line and the type.
TEST(MeshTriangles, Gmsh)
{
  const auto tri = ReadGmsh(std::string(BOLTNET_TEST_DATA) + "/triangles.msh");
  ASSERT_EQ(tri.at("skin").elems.size(), 2u);
  EXPECT_EQ(tri.at("skin").x.size(), 5u);
  for (const auto &e : tri.at("skin").elems) EXPECT_EQ(ElementNodes(e), 3);
  EXPECT_EQ(ElementNodes(tri.at("doubler").elems.at(0)), 4);
  const auto mixed = ReadGmsh(std::string(BOLTNET_TEST_DATA) + "/tri-lap.msh");
  const auto &skin = mixed.at("skin");
  ASSERT_EQ(skin.elems.size(), 3u);
  EXPECT_EQ(ElementNodes(skin.elems[0]) + ElementNodes(skin.elems[1]) + ElementNodes(skin.elems[2]), 10);
  EXPECT_EQ(skin.node_sets.at("clamp").size(), 2u);
  double area = 0; // counter-clockwise about +z, the unit squares' area
  for (const auto &e : skin.elems)
    for (int k = 0; k < ElementNodes(e); ++k) area += 0.5 * Cross(skin.x[e[k]], skin.x[e[(k + 1) % ElementNodes(e)]])[2];
  EXPECT_NEAR(area, 2.0, 1e-14);

  const auto fan = ParseGmsh("fan.msh", OneSurface(2, {"1 1 2 5", "2 2 3 5", "3 3 4 5", "4 4 1 5"}));
  EXPECT_EQ(fan.at("skin").elems.size(), 4u);
  const std::string second = GmshError(OneSurface(9, {"1 1 2 3 5 5 5"}));
  EXPECT_NE(second.find("test.msh' line 28: element type 9 (6-node triangles) is not supported"), std::string::npos) << second;
  const std::string twice = GmshError(OneSurface(2, {"1 1 2 2"}));
  EXPECT_NE(twice.find("line 29: a triangle names the same node twice"), std::string::npos) << twice;
  const std::string negative = GmshError(OneSurface(3, {"1 1 2 3 -4"}));
  EXPECT_NE(negative.find("line 29: element node tag -4 is not positive"), std::string::npos) << negative;
  const std::string hexa = GmshError(OneSurface(5, {"1 1 2 3 4 1 2 3 4"}));
  EXPECT_NE(hexa.find("element type 5 (8-node hexahedra)"), std::string::npos) << hexa;
}
