#include "network/patch.hpp"
#include "coupling/rigid.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <tuple>

namespace boltnet {

const char *const kCouplingTypeNames[3] = {"penalty", "exact", "node"};

namespace {
using Triplets = std::vector<std::tuple<PetscInt, PetscInt, double>>;

// Exact elimination: rewrite the shell triplets t (K) as those of A (patch.hpp).
Triplets EliminateSlaves(const ShellPatch &p, const Triplets &t)
{
  const PetscInt nmesh = (PetscInt)p.mesh.x.size();
  // Per slave dof: the master node and the 6 coefficients of u_s = sum_j T[j] u_m[j].
  struct Slave {
    PetscInt master = -1;
    double   T[6]   = {0, 0, 0, 0, 0, 0};
  };
  std::vector<Slave> slave(6 * (size_t)nmesh);
  for (size_t k = 0; k < p.joint_nodes.size(); ++k) {
    const auto &jn = p.joint_nodes[k];
    for (int s : jn.footprint) {
      if (slave[6 * s].master >= 0) throw std::logic_error("a footprint node is the slave of two joint nodes");
      const std::array<double, 3> d = {p.mesh.x[s][0] - jn.x[0], p.mesh.x[s][1] - jn.x[1], p.mesh.x[s][2] - jn.x[2]};
      const auto                  G = RigidLinkConstraint(d); // g = u_s - [I, -[d]x ...] u_m: T = -G_m
      for (int i = 0; i < 6; ++i) {
        Slave &sl = slave[6 * s + i];
        sl.master = nmesh + (PetscInt)k;
        for (int j = 0; j < 6; ++j) sl.T[j] = -G[12 * i + 6 + j];
      }
    }
  }
  // The scale of the constraint rows: the mean translational diagonal of K.
  double diag = 0;
  int    ndiag = 0;
  for (const auto &[r, c, v] : t)
    if (r == c && r % 6 < 3) diag += v, ndiag++;
  const double scale = ndiag ? diag / ndiag : 1.0;

  Triplets out;
  out.reserve(t.size() * 2);
  auto expand = [&](PetscInt i, auto &&f) { // dof i of u as a combination of the dof of v
    if (i < 6 * nmesh && slave[i].master >= 0) {
      for (int j = 0; j < 6; ++j)
        if (slave[i].T[j] != 0) f(6 * slave[i].master + j, slave[i].T[j]);
    } else f(i, 1.0);
  };
  for (const auto &[r, c, v] : t)
    expand(r, [&](PetscInt R, double a) { expand(c, [&](PetscInt C, double b) { out.emplace_back(R, C, a * b * v); }); });
  for (PetscInt i = 0; i < 6 * nmesh; ++i) {
    if (slave[i].master < 0) continue;
    out.emplace_back(i, i, scale);
    for (int j = 0; j < 6; ++j)
      if (slave[i].T[j] != 0) out.emplace_back(i, 6 * slave[i].master + j, -scale * slave[i].T[j]);
  }
  return out;
}
} // namespace

PatchOperator BuildShellOperator(const ShellPatch &p, CouplingType type, double penalty, double radius)
{
  // Collect (row, col, value) triplets, then compress; the patch is small enough for a sort.
  Triplets t;
  t.reserve(p.mesh.quads.size() * 576 + p.joint_nodes.size() * 144 * 8);
  shell::ElementMatrix K;
  for (const auto &q : p.mesh.quads) {
    shell::Nodes X;
    for (int k = 0; k < 4; ++k) X[k] = p.mesh.x[q[k]];
    shell::ElementStiffness(X, p.material, p.drill, K);
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 6; ++i)
        for (int b = 0; b < 4; ++b)
          for (int j = 0; j < 6; ++j) t.emplace_back(6 * q[a] + i, 6 * q[b] + j, K[24 * (6 * a + i) + 6 * b + j]);
  }
  const PetscInt nmesh = (PetscInt)p.mesh.x.size();
  if (type == CouplingType::Exact) t = EliminateSlaves(p, t);
  for (size_t k = 0; type == CouplingType::Penalty && k < p.joint_nodes.size(); ++k) {
    const auto    &jn = p.joint_nodes[k];
    const PetscInt m  = nmesh + (PetscInt)k;
    for (int s : jn.footprint) {
      const std::array<double, 3> d = {p.mesh.x[s][0] - jn.x[0], p.mesh.x[s][1] - jn.x[1], p.mesh.x[s][2] - jn.x[2]};
      const auto                  L = RigidLinkPenalty(d, penalty, penalty * radius * radius);
      const PetscInt              node[2] = {s, m};
      for (int a = 0; a < 2; ++a)
        for (int i = 0; i < 6; ++i)
          for (int b = 0; b < 2; ++b)
            for (int j = 0; j < 6; ++j) t.emplace_back(6 * node[a] + i, 6 * node[b] + j, L[12 * (6 * a + i) + 6 * b + j]);
    }
  }
  std::sort(t.begin(), t.end(), [](const auto &l, const auto &r) { return std::tie(std::get<0>(l), std::get<1>(l)) < std::tie(std::get<0>(r), std::get<1>(r)); });
  PatchOperator op;
  op.n = 6 * p.nnodes();
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

} // namespace boltnet
