// Test harness for the shell elements (test code: the network assembly has its own): meshes of
// quadrilaterals, triangles or both, sequential PETSc AIJ assembly through the mixed-element entry
// point of lib/shell (ElementStiffness(n, X, V, ...)), boundary conditions by row and column
// elimination, penalties for skew constraints, LU solve.
#pragma once

#include "shell/shell.hpp"

#include <functional>
#include <map>
#include <vector>

namespace shelltest {

using namespace boltnet::shell;

constexpr double kPi = 3.14159265358979323846;
enum { UX = 0, UY, UZ, RX, RY, RZ };

/* Element kinds of a mesh: quadrilaterals, each quadrilateral split into two triangles, or both
   (a checkerboard: quadrilaterals next to triangle pairs). */
enum class MeshKind { Quads, Triangles, Mixed };
const char *KindName(MeshKind k);

struct Mesh {
  std::vector<Vec3>             X;
  std::vector<std::vector<int>> elems; // 3 or 4 nodes, counter-clockwise about the normal
  int  nx = 0, ny = 0;                 // structured meshes: node (i, j) = j (nx + 1) + i
  bool periodic = false;               // in t: row ny is row 0 (a closed cylinder or sphere)
  int  Node(int i, int j) const { return (periodic ? j % ny : j) * (nx + 1) + i; }
};

/* Quadrilaterals of `quads` kept or split into triangles: Triangles splits every one, Mixed every
   other one (parity[e] = 1). The diagonal alternates with the parity of (e + diag[e]), so that a
   structured mesh is symmetric about its grid lines. */
Mesh Split(const Mesh &quads, MeshKind kind, const std::vector<int> &parity, const std::vector<int> &diag);

/* A structured nx x ny mesh of the map (s, t) in [0,1]^2 -> R^3, elements counter-clockwise in
   (s, t); periodic: t = 1 is t = 0 (the map must agree), the mesh closes on itself. Cell (i, j) is
   split like a checkerboard ((i + j) odd for Mixed), its diagonal alternating with (i + j). */
Mesh Grid(int nx, int ny, const std::function<Vec3(double, double)> &map, MeshKind kind = MeshKind::Quads, bool periodic = false);

/* How the benchmarks are run: element kinds, element options, directors (the elements' own normals,
   or the smooth surface's normal at each node, passed to the elements). */
struct Discretization {
  MeshKind       kind = MeshKind::Quads;
  ElementOptions opt{};
  bool           surface_directors = false;
};

struct Problem {
  Mesh                              mesh;
  ShellMaterial                     mat;
  ElementOptions                    opt;
  std::function<Vec3(const Vec3 &)> normal;  // the surface normal at a point (for surface directors)
  std::vector<double>               F;       // nodal forces, 6 per node
  std::map<long, double>            fixed;   // prescribed dof -> value
  struct Penalty {
    int                   node;
    std::array<double, 6> c;
    double                k;
  };
  std::vector<Penalty> penalties; // k (c . u_node)^2 added to the energy (skew constraints)
  Problem(Mesh m, ShellMaterial s, const Discretization &setup = {});
  bool surface_directors = false;
  void Fix(int node, int comp, double value = 0) { fixed[6 * node + comp] = value; }
  void FixAll(int node, std::initializer_list<int> comps)
  {
    for (int c : comps) Fix(node, c);
  }
  /* The directors handed to the elements (empty: their own normals). */
  std::vector<Vec3> Directors() const;
  /* Force per unit area q (global) on every element. */
  void SurfaceLoad(const Vec3 &q);
};

/* Assemble K, eliminate prescribed dofs (rows and columns), solve by LU. Returns all nodal dofs. */
std::vector<double> Solve(const Problem &p);

/* The element's nodal dofs. */
std::vector<double> Gather(const std::vector<double> &u, const std::vector<int> &elem);

/* Generalised strains of element e of p at natural coordinates (a, b), from the solution u. */
GeneralisedStrains Strains(const Problem &p, const std::vector<double> &u, size_t e, double a, double b);

} // namespace shelltest
