// The patch operator (patch.hpp): the shell stiffness of a patch plus its footprint couplings.
#include "patch/operator.hpp"
#include "patch/rigid.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>

namespace boltnet {

const char *const kCouplingTypeNames[3] = {"penalty", "exact", "node"};

std::array<double, 36> SlaveTransform(const std::array<double, 3> &d)
{
  const auto             G = RigidLinkConstraint(d); // g = u_s - [I, -[d]x ...] u_m: T = -G_m
  std::array<double, 36> T;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) T[6 * i + j] = -G[12 * i + 6 + j];
  return T;
}

SlaveMap ExactSlaves(const ShellPatch &p)
{
  const PetscInt nmesh = (PetscInt)p.mesh.x.size();
  SlaveMap       s;
  s.master.assign(nmesh, -1);
  s.T.resize(nmesh);
  for (size_t k = 0; k < p.joint_nodes.size(); ++k) {
    const auto &jn = p.joint_nodes[k];
    for (int n : jn.footprint) {
      if (s.master[n] >= 0) throw std::logic_error("a footprint node is the slave of two joint nodes");
      s.master[n] = nmesh + (PetscInt)k;
      s.T[n]      = SlaveTransform({p.mesh.x[n][0] - jn.x[0], p.mesh.x[n][1] - jn.x[1], p.mesh.x[n][2] - jn.x[2]});
    }
  }
  return s;
}

ElementGeometry GeometryOf(const ShellMesh &m, const MeshElement &e)
{
  ElementGeometry g;
  g.n = ElementNodes(e);
  for (int k = 0; k < g.n; ++k) g.X[k] = m.x[e[k]];
  g.directors = ElementDirectors(m, e, g.V);
  return g;
}

void ElementMatrixOf(const ElementGeometry &g, const shell::ShellMaterial &mat, double drill, shell::ElementMatrix &K)
{
  shell::ElementOptions o;
  o.drill              = drill;
  const shell::Vec3 *V = g.directors ? g.V.data() : nullptr;
  if (g.n == 4) {
    shell::ElementStiffness(4, g.X.data(), V, mat, o, K.data());
    return;
  }
  shell::TriMatrix Kt;
  shell::ElementStiffness(g.n, g.X.data(), V, mat, o, Kt.data()); // throws unless n = 3
  K.fill(0.0);
  for (int r = 0; r < 18; ++r)
    for (int c = 0; c < 18; ++c) K[24 * r + c] = Kt[18 * r + c];
}

Triplets ShellTriplets(const ShellPatch &p)
{
  Triplets t;
  t.reserve((p.mesh.elems.size() + p.shared.size()) * 576);
  shell::ElementMatrix K;
  for (const auto &q : p.mesh.elems) {
    const ElementGeometry g = GeometryOf(p.mesh, q);
    ElementMatrixOf(g, p.material, p.drill, K);
    for (int a = 0; a < g.n; ++a)
      for (int i = 0; i < 6; ++i)
        for (int b = 0; b < g.n; ++b)
          for (int j = 0; j < 6; ++j) t.emplace_back(6 * q[a] + i, 6 * q[b] + j, K[24 * (6 * a + i) + 6 * b + j]);
  }
  for (const auto &el : p.shared) { // the blocks between the patch's own nodes
    ElementMatrixOf(el.geom, p.material, p.drill, K);
    for (int a = 0; a < el.geom.n; ++a)
      for (int b = 0; b < el.geom.n; ++b) {
        if (el.node[a] < 0 || el.node[b] < 0) continue;
        for (int i = 0; i < 6; ++i)
          for (int j = 0; j < 6; ++j) t.emplace_back(6 * el.node[a] + i, 6 * el.node[b] + j, K[24 * (6 * a + i) + 6 * b + j]);
      }
  }
  return t;
}

Triplets EliminateSlaves(const ShellPatch &p, const SlaveMap &s, const Triplets &t, bool constraint_rows)
{
  const PetscInt nmesh = (PetscInt)p.mesh.x.size();
  // The scale of the constraint rows: the mean translational diagonal of K.
  double diag = 0;
  int    ndiag = 0;
  for (const auto &[r, c, v] : t)
    if (r == c && r % 6 < 3) diag += v, ndiag++;
  const double scale = ndiag ? diag / ndiag : 1.0;

  Triplets out;
  out.reserve(t.size() * 2);
  auto expand = [&](PetscInt i, auto &&f) { // dof i of u as a combination of the dof of v
    const PetscInt node = i / 6, comp = i % 6;
    if (node < nmesh && s.master[node] >= 0) {
      for (int j = 0; j < 6; ++j)
        if (s.T[node][6 * comp + j] != 0) f(6 * s.master[node] + j, s.T[node][6 * comp + j]);
    } else f(i, 1.0);
  };
  for (const auto &[r, c, v] : t)
    expand(r, [&](PetscInt R, double a) { expand(c, [&](PetscInt C, double b) { out.emplace_back(R, C, a * b * v); }); });
  if (constraint_rows)
    for (PetscInt node = 0; node < nmesh; ++node) {
      if (s.master[node] < 0) continue;
      for (int comp = 0; comp < 6; ++comp) {
        const PetscInt i = 6 * node + comp;
        out.emplace_back(i, i, scale);
        for (int j = 0; j < 6; ++j)
          if (s.T[node][6 * comp + j] != 0) out.emplace_back(i, 6 * s.master[node] + j, -scale * s.T[node][6 * comp + j]);
      }
    }
  return out;
}

void AddPenaltyLinks(const ShellPatch &p, double penalty, double radius, Triplets &t)
{
  const PetscInt nmesh = (PetscInt)p.mesh.x.size();
  for (size_t k = 0; k < p.joint_nodes.size(); ++k) {
    const auto    &jn = p.joint_nodes[k];
    const PetscInt m  = nmesh + (PetscInt)k;
    for (int s : jn.footprint) {
      const std::array<double, 3> d       = {p.mesh.x[s][0] - jn.x[0], p.mesh.x[s][1] - jn.x[1], p.mesh.x[s][2] - jn.x[2]};
      const auto                  L       = RigidLinkPenalty(d, penalty, penalty * radius * radius);
      const PetscInt              node[2] = {s, m};
      for (int a = 0; a < 2; ++a)
        for (int i = 0; i < 6; ++i)
          for (int b = 0; b < 2; ++b)
            for (int j = 0; j < 6; ++j) t.emplace_back(6 * node[a] + i, 6 * node[b] + j, L[12 * (6 * a + i) + 6 * b + j]);
    }
  }
}

Triplets PatchTriplets(const ShellPatch &p, CouplingType type, double penalty, double radius, bool constraint_rows)
{
  Triplets t = ShellTriplets(p);
  if (type == CouplingType::Exact) t = EliminateSlaves(p, ExactSlaves(p), t, constraint_rows);
  if (type == CouplingType::Penalty) AddPenaltyLinks(p, penalty, radius, t);
  return t;
}

PatchOperator Compress(PetscInt n, Triplets &t)
{
  std::sort(t.begin(), t.end(), [](const auto &l, const auto &r) { return std::tie(std::get<0>(l), std::get<1>(l)) < std::tie(std::get<0>(r), std::get<1>(r)); });
  PatchOperator op;
  op.n = n;
  op.rowptr.assign(op.n + 1, 0);
  for (size_t i = 0; i < t.size();) {
    const PetscInt r = std::get<0>(t[i]), c = std::get<1>(t[i]);
    double         v = 0;
    for (; i < t.size() && std::get<0>(t[i]) == r && std::get<1>(t[i]) == c; ++i) v += std::get<2>(t[i]);
    op.cols.push_back(c);
    op.vals.push_back(v);
    op.rowptr[r + 1]++;
  }
  for (PetscInt r = 0; r < op.n; ++r) op.rowptr[r + 1] += op.rowptr[r];
  return op;
}

PatchOperator CompressRows(PetscInt n, const Triplets &t, const std::vector<PetscInt> &row)
{
  std::vector<PetscInt> start(n + 1, 0);
  for (const auto &[r, c, v] : t)
    if (row[r] >= 0 && row[c] >= 0) start[row[r] + 1]++;
  for (PetscInt i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<std::pair<PetscInt, PetscScalar>> byrow(start[n]);
  std::vector<PetscInt>                         next(start.begin(), start.end() - 1);
  for (const auto &[r, c, v] : t)
    if (row[r] >= 0 && row[c] >= 0) byrow[next[row[r]]++] = {row[c], v};
  PatchOperator k;
  k.n = n;
  k.rowptr.assign(n + 1, 0);
  std::vector<PetscInt>                         pos(n, -1);
  std::vector<std::pair<PetscInt, PetscScalar>> entries;
  for (PetscInt i = 0; i < n; ++i) {
    entries.clear();
    for (PetscInt e = start[i]; e < start[i + 1]; ++e) {
      const auto &[c, v] = byrow[e];
      if (pos[c] < 0) {
        pos[c] = (PetscInt)entries.size();
        entries.emplace_back(c, v);
      } else entries[pos[c]].second += v;
    }
    for (const auto &e : entries) pos[e.first] = -1;
    std::sort(entries.begin(), entries.end(), [](const auto &x, const auto &y) { return x.first < y.first; });
    for (const auto &e : entries) {
      k.cols.push_back(e.first);
      k.vals.push_back(e.second);
    }
    k.rowptr[i + 1] = (PetscInt)k.cols.size();
  }
  return k;
}

PatchOperator BuildShellOperator(const ShellPatch &p, CouplingType type, double penalty, double radius)
{
  Triplets t = PatchTriplets(p, type, penalty, radius, true);
  return Compress(6 * p.nnodes(), t);
}

} // namespace boltnet
