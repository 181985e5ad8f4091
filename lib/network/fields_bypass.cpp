// The bypass load beside each fastener (network/fields.hpp, docs/output.md "Bypass"): the force
// balance of bearing-bypass analysis on a strip of width w through the fastener, in the direction of
// the fastener's in-plane load d on the sheet,
//   P_incoming = P_bypass + P_bearing,  with the element-averaged running load
//   n_avg = (n_incoming + n_bypass) / 2  =>  n_bypass = sign(n_avg) (|n_avg| - P_bearing / (2 w)),
// n_avg the area-weighted mean of d.N.d over the elements of the sheet whose centroid lies within
// w / 2 of the fastener axis (the footprint's rigid elements left out). P_bypass = n_bypass w.
// Elements and joints may sit on different ranks: each rank owns its joints only (network/build.cpp),
// so it sends each joint side to the ranks whose elements of that part come near it (NearbySides);
// each rank adds its elements' sums into a Vec laid out by joint, scattered to the joints' owners.
#include "core/guard.hpp"
#include "network/fields.hpp"
#include "network/internal.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace boltnet {
namespace {

constexpr int kSums = 8; // area * N (xx yy zz xy yz xz, global), area, element count

// A joint side on a shell part: its part, slot, fastener position and axis. Plain data: it travels
// between ranks as bytes.
struct Side {
  PetscInt               part, slot, pos, node; // pos: the patch (layout position), node: the joint node there
  std::array<double, 3> x, n;
};

double Dot(const std::array<double, 3> &a, const std::array<double, 3> &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

std::array<double, 3> Centroid(const FieldElement &e)
{
  std::array<double, 3> c{0, 0, 0};
  for (int i = 0; i < e.nn; ++i)
    for (int d = 0; d < 3; ++d) c[d] += e.geom.X[i][d] / e.nn;
  return c;
}

// Collective: the sides of every joint whose region may hold a centroid of this rank's elements.
// Each rank's box around its elements' centroids, by part, is gathered (a few per rank); each rank
// sends each side of its own joints to the ranks whose box of that part, grown by the largest
// distance of a region's centroid from its fastener (margin), holds the fastener.
PetscErrorCode NearbySides(BoltnetAssembly a, const FieldMap &m, double margin, std::vector<Side> *sides)
{
  constexpr int kBox = 7; // part, low corner, high corner
  MPI_Comm      comm = a->comm;
  PetscFunctionBeginUser;
  std::map<PetscInt, std::array<double, 6>> box;
  for (const FieldElement &e : m.elements) {
    const std::array<double, 3> c = Centroid(e);
    auto [it, fresh]              = box.try_emplace(e.part, std::array<double, 6>{c[0], c[1], c[2], c[0], c[1], c[2]});
    for (int d = 0; d < 3 && !fresh; ++d) it->second[d] = std::min(it->second[d], c[d]), it->second[3 + d] = std::max(it->second[3 + d], c[d]);
  }
  std::vector<double> mine;
  for (const auto &[part, b] : box) {
    mine.push_back((double)part);
    mine.insert(mine.end(), b.begin(), b.end());
  }
  std::vector<PetscMPIInt> count(a->size), displ(a->size + 1, 0);
  const PetscMPIInt        n = (PetscMPIInt)mine.size();
  PetscCallMPI(MPI_Allgather(&n, 1, MPI_INT, count.data(), 1, MPI_INT, comm));
  for (PetscMPIInt r = 0; r < a->size; ++r) displ[r + 1] = displ[r] + count[r];
  std::vector<double> all(displ[a->size]);
  PetscCallMPI(MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), count.data(), displ.data(), MPI_DOUBLE, comm));
  std::multimap<PetscInt, std::pair<PetscMPIInt, const double *>> boxes; // by part: (rank, corners)
  for (PetscMPIInt r = 0; r < a->size; ++r)
    for (PetscMPIInt i = displ[r]; i < displ[r + 1]; i += kBox) boxes.insert({(PetscInt)all[i], {r, &all[i + 1]}});

  std::vector<std::vector<Side>> out(a->size);
  for (const JointComp &j : a->joints.comp)
    for (int s = 0; s < 2; ++s) {
      const PetscInt pos = s ? j.vb : j.va;
      if (!a->layout.shells.count(pos)) continue;
      const Side sd{s ? j.patch_b : j.patch_a, 2 * j.index + s, pos, s ? j.pnode_b : j.pnode_a, {j.x[0], j.x[1], j.x[2]}, {j.R[0], j.R[1], j.R[2]}};
      auto [lo, hi] = boxes.equal_range(sd.part);
      for (auto it = lo; it != hi; ++it) {
        const double *b    = it->second.second;
        bool          near = true;
        for (int d = 0; d < 3; ++d) near = near && sd.x[d] >= b[d] - margin && sd.x[d] <= b[3 + d] + margin;
        if (near) out[it->second.first].push_back(sd);
      }
    }
  std::vector<PetscMPIInt> scount(a->size), sdispl(a->size + 1, 0), rcount(a->size), rdispl(a->size + 1, 0);
  std::vector<Side>        send;
  for (PetscMPIInt r = 0; r < a->size; ++r) {
    scount[r] = (PetscMPIInt)(out[r].size() * sizeof(Side));
    send.insert(send.end(), out[r].begin(), out[r].end());
  }
  PetscCallMPI(MPI_Alltoall(scount.data(), 1, MPI_INT, rcount.data(), 1, MPI_INT, comm));
  for (PetscMPIInt r = 0; r < a->size; ++r) sdispl[r + 1] = sdispl[r] + scount[r], rdispl[r + 1] = rdispl[r] + rcount[r];
  sides->resize(rdispl[a->size] / sizeof(Side));
  PetscCallMPI(MPI_Alltoallv(send.data(), scount.data(), sdispl.data(), MPI_BYTE, sides->data(), rcount.data(), rdispl.data(), MPI_BYTE, comm));
  PetscFunctionReturn(0);
}

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
  std::vector<Side> near;
  // A region's centroid is within reach along the axis and width / 2 across it: within this of x.
  PetscCall(NearbySides(a, m, 1.000001 * std::sqrt(reach * reach + width * width / 4), &near));
  std::map<PetscInt, std::unordered_map<Key, std::vector<Side>, decltype(hash)>> sides;
  for (const Side &sd : near) sides.try_emplace(sd.part, 16, hash).first->second[key(sd.x)].push_back(sd);
  for (size_t k = 0; k < m.elements.size(); ++k) {
    const FieldElement &e  = m.elements[k];
    const PetscInt      pos = a->patches.owned[e.owned].index;
    auto                it  = sides.find(e.part);
    if (it == sides.end()) continue;
    const std::array<double, 3> c  = Centroid(e);
    const Key                   k0 = key(c);
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
