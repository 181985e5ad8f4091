#include "patch/rigid.hpp"

namespace boltnet {

std::array<double, 72> RigidLinkConstraint(const std::array<double, 3> &d)
{
  // g_u = u_s - u_m - theta_m x d = u_s - u_m + [d]_x theta_m, with [d]_x theta = d x theta.
  std::array<double, 72> G{};
  auto set = [&G](int r, int c, double v) { G[12 * r + c] = v; };
  for (int i = 0; i < 3; ++i) {
    set(i, i, 1.0);          // u_s
    set(i, 6 + i, -1.0);     // u_m
    set(3 + i, 3 + i, 1.0);  // theta_s
    set(3 + i, 9 + i, -1.0); // theta_m
  }
  // [d]_x = [[0, -d2, d1], [d2, 0, -d0], [-d1, d0, 0]] acting on theta_m (columns 9..11)
  set(0, 10, -d[2]);
  set(0, 11, d[1]);
  set(1, 9, d[2]);
  set(1, 11, -d[0]);
  set(2, 9, -d[1]);
  set(2, 10, d[0]);
  return G;
}

std::array<double, 144> RigidLinkPenalty(const std::array<double, 3> &d, double k, double k_r)
{
  const std::array<double, 72> G = RigidLinkConstraint(d);
  std::array<double, 144>      K{};
  for (int r = 0; r < 6; ++r) {
    const double w = r < 3 ? k : k_r;
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) K[12 * i + j] += w * G[12 * r + i] * G[12 * r + j];
  }
  return K;
}

} // namespace boltnet
