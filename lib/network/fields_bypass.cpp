// The bypass load beside each fastener (network/fields.hpp, docs/output.md "Bypass"): the force
// balance of bearing-bypass analysis on a strip of width w through the fastener, in the direction of
// the fastener's in-plane load d on the sheet,
//   P_incoming = P_bypass + P_bearing,  with the element-averaged running load
//   n_avg = (n_incoming + n_bypass) / 2  =>  n_bypass = sign(n_avg) (|n_avg| - P_bearing / (2 w)),
// n_avg the area-weighted mean of d.N.d over the elements of the sheet whose centroid lies within
// w / 2 of the fastener axis (the footprint's rigid elements left out). P_bypass = n_bypass w.
// Elements and joints may sit on different ranks: each rank adds its elements' sums into a Vec laid
// out by joint, scattered to the ranks that own the joints.
#include "core/guard.hpp"
#include "network/fields.hpp"
#include "network/internal.hpp"

#include <cmath>
#include <unordered_map>

namespace boltnet {
namespace {

constexpr int kSums = 8; // area * N (xx yy zz xy yz xz, global), area, element count

// A joint side on a shell part: its slot, fastener position and axis.
struct Side {
  PetscInt               slot, pos, node; // pos: the patch (layout position), node: the joint node there
  std::array<double, 3> x, n;
};

double Dot(const std::array<double, 3> &a, const std::array<double, 3> &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

} // namespace

PetscErrorCode FieldMapBypassRegions(BoltnetAssembly a, FieldMap &m, double width)
{
  MPI_Comm comm = a->comm;
  PetscFunctionBeginUser;
  m.bypass_width     = width;
  const double reach = a->opt.coupling_reach > 0 ? a->opt.coupling_reach : 4 * a->opt.coupling_radius;
  const double h     = std::max(width / 2, reach); // bucket size: a region spans its neighbours only
  // The joint sides of each shell part, bucketed by position.
  using Key = std::array<long long, 3>;
  auto key  = [h](const std::array<double, 3> &x) { return Key{(long long)std::floor(x[0] / h), (long long)std::floor(x[1] / h), (long long)std::floor(x[2] / h)}; };
  auto hash = [](const Key &k) { return std::hash<long long>()(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL); };
  std::map<PetscInt, std::unordered_map<Key, std::vector<Side>, decltype(hash)>> sides;
  for (const JointComp &j : a->layout.joints)
    for (int s = 0; s < 2; ++s) {
      const PetscInt pos = s ? j.vb : j.va;
      if (!a->layout.shells.count(pos)) continue;
      Side sd{2 * j.index + s, pos, s ? j.pnode_b : j.pnode_a, {j.x[0], j.x[1], j.x[2]}, {j.R[0], j.R[1], j.R[2]}};
      auto &b = sides.try_emplace(s ? j.patch_b : j.patch_a, 16, hash).first->second;
      b[key(sd.x)].push_back(sd);
    }
  for (size_t k = 0; k < m.elements.size(); ++k) {
    const FieldElement &e  = m.elements[k];
    const PetscInt      pos = a->patches.owned[e.owned].index;
    auto                it  = sides.find(e.part);
    if (it == sides.end()) continue;
    std::array<double, 3> c{0, 0, 0};
    for (int i = 0; i < e.nn; ++i)
      for (int d = 0; d < 3; ++d) c[d] += e.geom.X[i][d] / e.nn;
    const Key k0 = key(c);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          auto b = it->second.find(Key{k0[0] + dx, k0[1] + dy, k0[2] + dz});
          if (b == it->second.end()) continue;
          for (const Side &sd : b->second) {
            const std::array<double, 3> v = {c[0] - sd.x[0], c[1] - sd.x[1], c[2] - sd.x[2]};
            const double                ax = Dot(v, sd.n), r2 = Dot(v, v) - ax * ax;
            if (std::fabs(ax) > reach || r2 > width * width / 4) continue;
            // The footprint's own elements move rigidly with the fastener (exact coupling): no load there.
            const ShellPatch &sp = a->layout.shells.at(sd.pos);
            if (pos == sd.pos && sd.node >= (PetscInt)sp.mesh.x.size()) {
              const auto &fp    = sp.joint_nodes[sd.node - sp.mesh.x.size()].footprint;
              bool        rigid = true;
              for (int i = 0; i < e.nn; ++i) rigid = rigid && e.local[i] >= 0 && std::binary_search(fp.begin(), fp.end(), e.local[i]);
              if (rigid) continue;
            }
            m.bypass_members.push_back({(PetscInt)k, sd.slot});
          }
        }
  }
  // Sums laid out like the joints' natural rows (2 sides x kSums per joint); each rank reads its joints'.
  const PetscInt nj = (PetscInt)a->joints.size();
  PetscCall(VecCreateMPI(comm, 2 * kSums * m.joints.nlocal, 2 * kSums * m.joints.nglobal, &m.bypass_sums));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, 2 * kSums * nj, &m.bypass_local));
  std::vector<PetscInt> idx;
  for (PetscInt k = 0; k < nj; ++k) idx.push_back(a->joints.comp[k].index);
  IS from, to;
  PetscCall(ISCreateBlock(PETSC_COMM_SELF, 2 * kSums, nj, idx.data(), PETSC_COPY_VALUES, &from));
  PetscCall(ISCreateStride(PETSC_COMM_SELF, 2 * kSums * nj, 0, 1, &to));
  PetscCall(VecScatterCreate(m.bypass_sums, from, m.bypass_local, to, &m.bypass_scatter));
  PetscCall(ISDestroy(&from));
  PetscCall(ISDestroy(&to));
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyBypass(BoltnetAssembly a, FieldMap &m, const StepFields &f, std::vector<BypassRow> &rows)
{
  PetscFunctionBeginUser;
  rows.clear();
  PetscCall(VecSet(m.bypass_sums, 0.0));
  for (const auto &[k, slot] : m.bypass_members) {
    const shell::SectionResults &r = f.results[k];
    const FieldElement          &e = m.elements[k];
    const double                 area = ElementArea(e.geom);
    // N in global components: Nxx e1 e1 + Nyy e2 e2 + Nxy (e1 e2 + e2 e1).
    auto         T    = [&](int i, int j) { return r.N[0] * r.e1[i] * r.e1[j] + r.N[1] * r.e2[i] * r.e2[j] + r.N[2] * (r.e1[i] * r.e2[j] + r.e2[i] * r.e1[j]); };
    PetscScalar  v[kSums] = {area * T(0, 0), area * T(1, 1), area * T(2, 2), area * T(0, 1), area * T(1, 2), area * T(0, 2), area, 1};
    PetscInt     idx[kSums];
    for (int c = 0; c < kSums; ++c) idx[c] = kSums * slot + c;
    PetscCall(VecSetValues(m.bypass_sums, kSums, idx, v, ADD_VALUES));
  }
  PetscCall(VecAssemblyBegin(m.bypass_sums));
  PetscCall(VecAssemblyEnd(m.bypass_sums));
  PetscCall(VecScatterBegin(m.bypass_scatter, m.bypass_sums, m.bypass_local, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(m.bypass_scatter, m.bypass_sums, m.bypass_local, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar *s;
  PetscCall(VecGetArrayRead(m.bypass_local, &s));
  const double w = m.bypass_width;
  for (size_t k = 0; k < a->joints.size(); ++k) {
    const JointComp &j = a->joints.comp[k];
    const Response  &re = a->joints.accepted[k];
    for (int side = 0; side < 2; ++side) {
      if (!a->layout.shells.count(side ? j.vb : j.va)) continue;
      const PetscScalar *q = s + (2 * k + side) * kSums;
      BypassRow          b{j.id, side, side ? j.patch_b : j.patch_a, (PetscInt)q[7], 0, {0, 0, 0}, NAN, w, NAN, NAN};
      // The fastener's in-plane force on this sheet: +f on patch b's node, -f on patch a's.
      const double sign = side ? 1 : -1, f1 = sign * re.force[1], f2 = sign * re.force[2];
      b.bearing         = std::hypot(f1, f2);
      for (int c = 0; c < 3; ++c) b.d[c] = b.bearing > 0 ? (f1 * j.R[3 + c] + f2 * j.R[6 + c]) / b.bearing : j.R[3 + c];
      if (q[6] > 0) {
        const double N[3][3] = {{q[0], q[3], q[5]}, {q[3], q[1], q[4]}, {q[5], q[4], q[2]}};
        double       ndd     = 0;
        for (int i = 0; i < 3; ++i)
          for (int l = 0; l < 3; ++l) ndd += b.d[i] * N[i][l] * b.d[l];
        b.n_avg = ndd / q[6];
        b.flux  = std::copysign(std::fabs(b.n_avg) - b.bearing / (2 * w), b.n_avg);
        b.load  = b.flux * w;
      }
      rows.push_back(b);
    }
  }
  PetscCall(VecRestoreArrayRead(m.bypass_local, &s));
  PetscFunctionReturn(0);
}

} // namespace boltnet
