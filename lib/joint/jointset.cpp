#include "joint/jointset.hpp"

namespace boltnet {

Vec6 AttachmentDof(const PetscReal d[3], const PetscScalar *u)
{
  Vec6 a;
  for (int i = 0; i < 6; ++i) a[i] = u[i];
  a[0] += u[4] * d[2] - u[5] * d[1];
  a[1] += u[5] * d[0] - u[3] * d[2];
  a[2] += u[3] * d[1] - u[4] * d[0];
  return a;
}

Mat6 AttachmentMap(const PetscReal d[3])
{
  Mat6 T{};
  for (int i = 0; i < 6; ++i) T[6 * i + i] = 1;
  // theta x d = -[d]x theta
  T[6 * 0 + 4] = d[2], T[6 * 0 + 5] = -d[1];
  T[6 * 1 + 3] = -d[2], T[6 * 1 + 5] = d[0];
  T[6 * 2 + 3] = d[1], T[6 * 2 + 4] = -d[0];
  return T;
}

Vec6 NodeLoad(const PetscReal d[3], const Vec6 &f)
{
  Vec6 g = f;
  g[3] += d[1] * f[2] - d[2] * f[1];
  g[4] += d[2] * f[0] - d[0] * f[2];
  g[5] += d[0] * f[1] - d[1] * f[0];
  return g;
}

Vec6 LocalJump(const PetscReal R[9], const PetscScalar *ua, const PetscScalar *ub)
{
  Vec6 du{};
  for (int blk = 0; blk < 2; ++blk)
    for (int i = 0; i < 3; ++i) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += R[3 * i + k] * (ub[3 * blk + k] - ua[3 * blk + k]);
      du[3 * blk + i] = s;
    }
  return du;
}

Vec6 GlobalForce(const PetscReal R[9], const Vec6 &f)
{
  Vec6 g{};
  for (int blk = 0; blk < 2; ++blk)
    for (int k = 0; k < 3; ++k) {
      double s = 0;
      for (int i = 0; i < 3; ++i) s += R[3 * i + k] * f[3 * blk + i];
      g[3 * blk + k] = s;
    }
  return g;
}

Mat6 GlobalTangent(const PetscReal R[9], const Mat6 &K)
{
  double Q[36] = {0};
  for (int blk = 0; blk < 2; ++blk)
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) Q[6 * (3 * blk + i) + 3 * blk + k] = R[3 * i + k];
  Mat6 KQ{}, G{};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      double s = 0;
      for (int k = 0; k < 6; ++k) s += K[6 * i + k] * Q[6 * k + j];
      KQ[6 * i + j] = s;
    }
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      double s = 0;
      for (int k = 0; k < 6; ++k) s += Q[6 * k + i] * KQ[6 * k + j];
      G[6 * i + j] = s;
    }
  return G;
}

void EvaluateJoints(const JointSet &js, const PetscScalar *x, Tangent tangent, bool full_law, std::vector<Response> &out, std::vector<Vec6> *jumps)
{
  out.resize(js.size());
  if (jumps) jumps->resize(js.size());
  const bool any_frozen = !full_law && js.frozen.size() == js.size();
  for (size_t i = 0; i < js.size(); ++i) {
    const Vec6 ua = AttachmentDof(js.comp[i].da, x + js.oa[i]), ub = AttachmentDof(js.comp[i].db, x + js.ob[i]);
    const Vec6 du = LocalJump(js.comp[i].R, ua.data(), ub.data());
    out[i]        = evaluate(js.comp[i].params, js.committed[i], du, tangent, any_frozen && js.frozen[i]);
    if (jumps) (*jumps)[i] = du;
  }
}

} // namespace boltnet
