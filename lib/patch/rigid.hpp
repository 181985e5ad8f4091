// Patch coupling: the footprint nodes of a fastener follow the rigid-body motion of the joint
// node (the patch centre). Pure C++; the network assembly adds these blocks to the patch.
#pragma once

#include <array>

namespace boltnet {

// Penalty link between a footprint node s and the master (joint) node m, at d = x_s - x_m:
// the constraint g = (u_s - u_m - theta_m x d, theta_s - theta_m) = 0 enforced by the energy
// (k/2) |g_u|^2 + (k_r/2) |g_theta|^2. Returns the 12 x 12 stiffness, row major, dof order
// [u_s, theta_s, u_m, theta_m]. It is symmetric, positive semi-definite, and does no work on a
// rigid motion of the pair.
std::array<double, 144> RigidLinkPenalty(const std::array<double, 3> &d, double k, double k_r);

// The same constraint as the 6 x 12 matrix G (g = G [u_s, theta_s, u_m, theta_m]), for exact
// elimination: u_s = u_m + theta_m x d, theta_s = theta_m.
std::array<double, 72> RigidLinkConstraint(const std::array<double, 3> &d);

} // namespace boltnet
