// The joints a rank holds (the joint edges of the network it owns) and their history: what the
// solver evaluates at every residual, commits after a converged step, and freezes as linear
// springs where they stay stuck (docs/solver.md, "Linear where it can be").
#pragma once

#include "joint/law.hpp"
#include "patch/layout.hpp"

#include <array>
#include <vector>

namespace boltnet {

struct JointSet {
  // Per local joint, in edge order: an aligned copy of its component (the network's component
  // storage is only 4-byte aligned), its edge point, the local-vector offsets of its two attachment
  // nodes and the global rows of its 12 dof (node a's six, then node b's).
  std::vector<JointComp>                comp;
  std::vector<PetscInt>                 edge;
  std::vector<PetscInt>                 oa, ob;
  std::vector<std::array<PetscInt, 12>> rows;

  // History, owned by the edge's rank.
  std::vector<History> committed;
  // The joints at the last converged step, evaluated against the history before it (so that the
  // state says what the joint did during the step: a joint that slid reads 'slide', not 'stick').
  std::vector<Response> accepted;
  std::vector<Vec6>     accepted_jump;
  // Joint states at each Newton iterate of the current solve, for the monitor and for naming the
  // joints that kept changing state when a step fails.
  std::vector<std::vector<PetscInt>> state_trace;
  // Joints solved as linear springs in the current attempt (1: frozen; empty: none), their
  // utilization (law.hpp) at the last two converged steps, and the last step's load increment.
  std::vector<char>      frozen;
  std::vector<PetscReal> util_now, util_before;
  PetscReal              last_increment = 0;
  PetscBool              util_ready     = PETSC_FALSE; // util_now holds the last converged step's
  // The joint tangents assembled into J (valid only while jac_valid) and the bookkeeping.
  std::vector<Mat6> jac_tangent;
  std::vector<char> jac_state; // their states (State, plus 8 when bearing)
  PetscBool         jac_valid = PETSC_FALSE;
  PetscInt          jac_assembled = 0, jac_reused = 0;         // Jacobian evaluations assembled / kept
  PetscInt          frozen_joint_steps = 0, joint_steps = 0;   // summed over attempts: joints frozen / all
  PetscInt          released = 0;                              // frozen joints the full law sent out of stick

  size_t size() const { return comp.size(); }
};

// The dof of a joint's attachment point at offset d from its node (a rigid patch's node):
// u + theta x d, theta. T is that map as a 6 x 6 matrix (row major).
Vec6 AttachmentDof(const PetscReal d[3], const PetscScalar *u);
Mat6 AttachmentMap(const PetscReal d[3]);
// A force and moment f at the attachment point as the load on the node: T^T f = (f, m + d x f).
Vec6 NodeLoad(const PetscReal d[3], const Vec6 &f);
// Jump in the local frame: du = Q (u_b - u_a), Q = diag(R, R).
Vec6 LocalJump(const PetscReal R[9], const PetscScalar *ua, const PetscScalar *ub);
// Global force on node b: Q^T f.
Vec6 GlobalForce(const PetscReal R[9], const Vec6 &f);
// Global tangent Q^T K Q.
Mat6 GlobalTangent(const PetscReal R[9], const Mat6 &K);

// Every local joint evaluated at the local (ghosted) vector x against its committed history, as
// the solver sees it (frozen joints as linear springs) or with the full law everywhere. Pure.
void EvaluateJoints(const JointSet &js, const PetscScalar *x, Tangent tangent, bool full_law, std::vector<Response> &out, std::vector<Vec6> *jumps);

} // namespace boltnet
