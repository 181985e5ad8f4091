#include "network/patch.hpp"
#include "coupling/rigid.hpp"

#include <algorithm>
#include <map>
#include <tuple>

namespace boltnet {

PatchOperator BuildShellOperator(const ShellPatch &p, double penalty, double radius)
{
  // Collect (row, col, value) triplets, then compress; the patch is small enough for a sort.
  std::vector<std::tuple<PetscInt, PetscInt, double>> t;
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
  for (size_t k = 0; k < p.joint_nodes.size(); ++k) {
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
