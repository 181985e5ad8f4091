// The bypass load beside each fastener (network/fields.hpp, docs/output.md "Bypass"): the force
// balance of bearing-bypass analysis (Crews and Naik, Composite Structures 6, 1986) on a strip of
// width w through the fastener, along the direction d in which the sheet bears on the fastener with
// the in-plane force P (the fastener pushes the sheet with -P d).
// The running load d.N.d is averaged over two bands of the strip, one on each side of the fastener:
// the elements of the sheet whose centroid lies within w / 2 of the line through the fastener along
// d and beyond the footprint's extent along d (a section through the footprint, where the
// coupling's forces act, does not carry its force in the elements' N), and that begin within L of
// the fastener. Between the
// footprint and the next fastener no load enters the strip, so each band's mean is its section's
// force per width: n_+ ahead of the fastener (along d), n_- behind it, and a free body gives
//   (n_+ - n_-) w = P.
// The band with the smaller |n| is the bypass (the load that passes the hole), the other the
// incoming load; a band with no element is taken from the balance. P_bypass = n_bypass w.
// Elements and joints may sit on different ranks: each rank owns its joints only (network/build.cpp),
// so it sends each joint side to the ranks whose elements of that part come near it (NearbySides);
// each step, the fastener forces go from the joints' ranks to the elements' (a VecScatter), each rank
// adds its elements' band sums into a Vec laid out by joint, and that Vec is scattered back.
#include "core/guard.hpp"
#include "network/fields.hpp"
#include "network/internal.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace boltnet {
namespace {

constexpr int kSums = 6; // per band (ahead, behind): area * d.N.d, area, element count

// A joint side on a shell part: its part, slot, fastener position and axis. Plain data: it travels
// between ranks as bytes.
struct Side {
  PetscInt               part, slot, pos, node; // pos: the patch (layout position), node: the joint node there
  std::array<double, 3> x, n, t1, t2;          // the fastener's position and axes (JointComp::R)
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
      const Side sd{s ? j.patch_b : j.patch_a, 2 * j.index + s, pos, s ? j.pnode_b : j.pnode_a, {j.x[0], j.x[1], j.x[2]}, {j.R[0], j.R[1], j.R[2]}, {j.R[3], j.R[4], j.R[5]}, {j.R[6], j.R[7], j.R[8]}};
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

// The farthest a point set reaches along (d0, d1) in the joint's plane (0 for none: the fastener).
double Extent(const std::vector<std::array<double, 2>> &pts, double d0, double d1)
{
  double e = 0;
  for (const auto &p : pts) e = std::max(e, p[0] * d0 + p[1] * d1);
  return e;
}

// A point's coordinates in a joint side's plane: along t1 and t2 from the fastener at x.
template <class Point>
std::array<double, 2> InPlane(const Point &X, const std::array<double, 3> &x, const std::array<double, 3> &t1, const std::array<double, 3> &t2)
{
  const std::array<double, 3> u = {X[0] - x[0], X[1] - x[1], X[2] - x[2]};
  return {Dot(u, t1), Dot(u, t2)};
}

} // namespace

PetscErrorCode FieldMapBypassRegions(BoltnetAssembly a, FieldMap &m, double width, double length)
{
  MPI_Comm comm = a->comm;
  PetscFunctionBeginUser;
  m.bypass_width     = width;
  m.bypass_length    = length;
  const double reach = a->opt.coupling_reach > 0 ? a->opt.coupling_reach : 4 * a->opt.coupling_radius;
  // A band holds centroids within w / 2 across d and elements that begin within L along it, so its
  // elements' centroids lie within span of the fastener in the plane, rho being the largest distance
  // of an element's node from its centroid (over all ranks: the margin of NearbySides).
  double rho = 0;
  for (const FieldElement &e : m.elements) {
    const std::array<double, 3> c = Centroid(e);
    for (int i = 0; i < e.nn; ++i) {
      const std::array<double, 3> v = {e.geom.X[i][0] - c[0], e.geom.X[i][1] - c[1], e.geom.X[i][2] - c[2]};
      rho                           = std::max(rho, std::sqrt(Dot(v, v)));
    }
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &rho, 1, MPI_DOUBLE, MPI_MAX, comm));
  const double span = 1.000001 * (std::hypot(width / 2, length) + rho);
  const double h    = std::max(span, reach); // bucket size: a band spans its neighbours only
  // The joint sides of each shell part, bucketed by position.
  using Key = std::array<long long, 3>;
  auto key  = [h](const std::array<double, 3> &x) { return Key{(long long)std::floor(x[0] / h), (long long)std::floor(x[1] / h), (long long)std::floor(x[2] / h)}; };
  auto hash = [](const Key &k) { return std::hash<long long>()(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL); };
  std::vector<Side> near;
  PetscCall(NearbySides(a, m, std::hypot(reach, span), &near));
  std::map<PetscInt, std::unordered_map<Key, std::vector<Side>, decltype(hash)>> sides;
  for (const Side &sd : near) sides.try_emplace(sd.part, 16, hash).first->second[key(sd.x)].push_back(sd);
  std::map<PetscInt, size_t> where;  // slot -> position in m.bypass_sides
  PetscInt                   across = 0; // candidates in another patch than their fastener's
  for (size_t k = 0; k < m.elements.size(); ++k) {
    const FieldElement &e   = m.elements[k];
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
            if (std::fabs(ax) > reach || r2 > span * span) continue;
            // The footprint's own elements move rigidly with the fastener (exact coupling): no load there.
            const ShellPatch *sp = pos == sd.pos ? &a->layout.shells.at(sd.pos) : nullptr;
            const bool        fp = sp && sd.node >= (PetscInt)sp->mesh.x.size();
            if (fp) {
              const auto &nodes = sp->joint_nodes[sd.node - sp->mesh.x.size()].footprint;
              bool        rigid = true;
              for (int i = 0; i < e.nn; ++i) rigid = rigid && e.local[i] >= 0 && std::binary_search(nodes.begin(), nodes.end(), e.local[i]);
              if (rigid) continue;
            }
            auto [at, fresh] = where.try_emplace(sd.slot, m.bypass_sides.size());
            if (fresh) m.bypass_sides.push_back({sd.slot, sd.t1, sd.t2, {}});
            FieldMap::BypassSide &bs = m.bypass_sides[at->second];
            // The footprint's nodes, where its extent along d is known: on the ranks holding its patch.
            if (fp && bs.footprint.empty())
              for (PetscInt i : sp->joint_nodes[sd.node - sp->mesh.x.size()].footprint) bs.footprint.push_back(InPlane(sp->mesh.x[i], sd.x, sd.t1, sd.t2));
            FieldMap::BypassMember mb{(PetscInt)k, (PetscInt)at->second, e.nn, {}};
            for (int i = 0; i < e.nn; ++i) mb.p[i] = InPlane(e.geom.X[i], sd.x, sd.t1, sd.t2);
            m.bypass_members.push_back(mb);
            across += pos != sd.pos;
          }
        }
  }
  PetscCall(PetscInfo(nullptr, "Bypass bands: %zu candidate elements for %zu joint sides, %" PetscInt_FMT " of them in another patch than their fastener's\n", m.bypass_members.size(), m.bypass_sides.size(), across));
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
  // Each sheet's in-plane force on the fastener (f_t1, f_t2: 2 per slot, 4 per joint, natural order),
  // scattered to the ranks whose elements may lie in the side's bands.
  const PetscInt nb = (PetscInt)m.bypass_sides.size();
  PetscCall(VecCreateMPI(comm, 4 * m.joints.nlocal, 4 * m.joints.nglobal, &m.bypass_force));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, 2 * nb, &m.bypass_force_local));
  idx.clear();
  for (const auto &bs : m.bypass_sides) idx.push_back(bs.slot);
  PetscCall(ISCreateBlock(PETSC_COMM_SELF, 2, nb, idx.data(), PETSC_COPY_VALUES, &from));
  PetscCall(ISCreateStride(PETSC_COMM_SELF, 2 * nb, 0, 1, &to));
  PetscCall(VecScatterCreate(m.bypass_force, from, m.bypass_force_local, to, &m.bypass_force_scatter));
  PetscCall(ISDestroy(&from));
  PetscCall(ISDestroy(&to));
  // The footprint's reach along d ahead and behind, laid out the same: a footprint lies in one patch,
  // and the ranks whose elements of another patch (across a seam) lie in its bands learn it from the
  // rank holding it, so that the bands do not depend on how parts are cut between ranks.
  PetscCall(VecDuplicate(m.bypass_force, &m.bypass_reach));
  PetscCall(VecDuplicate(m.bypass_force_local, &m.bypass_reach_local));
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyBypass(BoltnetAssembly a, FieldMap &m, const StepFields &f, std::vector<BypassRow> &rows)
{
  PetscFunctionBeginUser;
  rows.clear();
  // The in-plane force of each sheet on the fastener: +f on patch b's node, -f on patch a's.
  auto force = [&](size_t k, int side) {
    const Response &re   = a->joints.accepted[k];
    const double    sign = side ? 1 : -1;
    return std::array<double, 2>{sign * re.force[1], sign * re.force[2]};
  };
  // A force below a millionth of the largest bearing load so far is taken as none (d = t1): its
  // direction would be round-off, which differs with the number of ranks.
  double peak = 0;
  for (size_t k = 0; k < a->joints.size(); ++k) {
    const std::array<double, 2> fs = force(k, 0);
    peak                           = std::max(peak, std::hypot(fs[0], fs[1]));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &peak, 1, MPI_DOUBLE, MPI_MAX, a->comm));
  m.bypass_peak     = std::max(m.bypass_peak, peak);
  const double none = 1e-6 * m.bypass_peak;
  for (size_t k = 0; k < a->joints.size(); ++k) {
    const JointComp &j = a->joints.comp[k];
    for (int side = 0; side < 2; ++side) {
      const std::array<double, 2> fs  = force(k, side);
      const PetscInt              i[2] = {2 * (2 * j.index + side), 2 * (2 * j.index + side) + 1};
      PetscCall(VecSetValues(m.bypass_force, 2, i, fs.data(), INSERT_VALUES));
    }
  }
  PetscCall(VecAssemblyBegin(m.bypass_force));
  PetscCall(VecAssemblyEnd(m.bypass_force));
  PetscCall(VecScatterBegin(m.bypass_force_scatter, m.bypass_force, m.bypass_force_local, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(m.bypass_force_scatter, m.bypass_force, m.bypass_force_local, INSERT_VALUES, SCATTER_FORWARD));
  // Each side's d in its joint's plane: the sheet's force on the fastener, t1 when there is none.
  const size_t        nb = m.bypass_sides.size();
  std::vector<double> dir(2 * nb);
  {
    const PetscScalar *fl;
    PetscCall(VecGetArrayRead(m.bypass_force_local, &fl));
    for (size_t i = 0; i < nb; ++i) {
      const double P = std::hypot(fl[2 * i], fl[2 * i + 1]);
      dir[2 * i]     = P > none ? fl[2 * i] / P : 1;
      dir[2 * i + 1] = P > none ? fl[2 * i + 1] / P : 0;
    }
    PetscCall(VecRestoreArrayRead(m.bypass_force_local, &fl));
  }
  // The footprint's reach ahead and behind along d, from the rank that holds the footprint.
  PetscCall(VecSet(m.bypass_reach, 0.0));
  for (size_t i = 0; i < nb; ++i) {
    const FieldMap::BypassSide &bs = m.bypass_sides[i];
    if (bs.footprint.empty()) continue;
    const PetscScalar v[2]   = {Extent(bs.footprint, dir[2 * i], dir[2 * i + 1]), Extent(bs.footprint, -dir[2 * i], -dir[2 * i + 1])};
    const PetscInt    idx[2] = {2 * bs.slot, 2 * bs.slot + 1};
    PetscCall(VecSetValues(m.bypass_reach, 2, idx, v, INSERT_VALUES));
  }
  PetscCall(VecAssemblyBegin(m.bypass_reach));
  PetscCall(VecAssemblyEnd(m.bypass_reach));
  PetscCall(VecScatterBegin(m.bypass_force_scatter, m.bypass_reach, m.bypass_reach_local, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(m.bypass_force_scatter, m.bypass_reach, m.bypass_reach_local, INSERT_VALUES, SCATTER_FORWARD));

  // Each element in a band adds its area-weighted d.N.d to its band: ahead (0) or behind (1).
  const double w = m.bypass_width, L = m.bypass_length, tol = 1e-9 * (w + L);
  PetscCall(VecSet(m.bypass_sums, 0.0));
  const PetscScalar *reach;
  PetscCall(VecGetArrayRead(m.bypass_reach_local, &reach));
  for (const FieldMap::BypassMember &mb : m.bypass_members) {
    const FieldMap::BypassSide &bs = m.bypass_sides[mb.side];
    const double                d0 = dir[2 * mb.side], d1 = dir[2 * mb.side + 1];
    double                      amin = INFINITY, amax = -INFINITY, along = 0, across = 0; // along, across: the centroid's
    for (int i = 0; i < mb.nn; ++i) {
      const double t = mb.p[i][0] * d0 + mb.p[i][1] * d1; // the node along d
      amin = std::min(amin, t), amax = std::max(amax, t);
      along += t / mb.nn;
      across += (-mb.p[i][0] * d1 + mb.p[i][1] * d0) / mb.nn;
    }
    // Every bound is taken with a tolerance: on a structured mesh centroids and nodes fall exactly on
    // w / 2, L and the footprint's reach, and a round-off tilt of d must not move them in or out
    // (the bands would then depend on the number of ranks).
    if (std::fabs(across) > w / 2 + tol) continue;
    int band;
    if (along >= reach[2 * mb.side] - tol && amin <= L + tol) band = 0;
    else if (along <= -reach[2 * mb.side + 1] + tol && -amax <= L + tol) band = 1;
    else continue;
    const shell::SectionResults &r    = f.results[mb.elem];
    const double                 area = ElementArea(m.elements[mb.elem].geom);
    std::array<double, 3>        d;
    for (int c = 0; c < 3; ++c) d[c] = d0 * bs.t1[c] + d1 * bs.t2[c];
    const double e1 = d[0] * r.e1[0] + d[1] * r.e1[1] + d[2] * r.e1[2], e2 = d[0] * r.e2[0] + d[1] * r.e2[1] + d[2] * r.e2[2];
    const PetscScalar v[3] = {area * (r.N[0] * e1 * e1 + r.N[1] * e2 * e2 + 2 * r.N[2] * e1 * e2), area, 1};
    PetscInt          idx[3];
    for (int c = 0; c < 3; ++c) idx[c] = kSums * bs.slot + 3 * band + c;
    PetscCall(VecSetValues(m.bypass_sums, 3, idx, v, ADD_VALUES));
  }
  PetscCall(VecRestoreArrayRead(m.bypass_reach_local, &reach));
  PetscCall(VecAssemblyBegin(m.bypass_sums));
  PetscCall(VecAssemblyEnd(m.bypass_sums));
  PetscCall(VecScatterBegin(m.bypass_scatter, m.bypass_sums, m.bypass_local, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(m.bypass_scatter, m.bypass_sums, m.bypass_local, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar *s;
  PetscCall(VecGetArrayRead(m.bypass_local, &s));
  for (size_t k = 0; k < a->joints.size(); ++k) {
    const JointComp &j = a->joints.comp[k];
    for (int side = 0; side < 2; ++side) {
      if (!a->layout.shells.count(side ? j.vb : j.va)) continue;
      const PetscScalar          *q  = s + (2 * k + side) * kSums;
      const std::array<double, 2> fs = force(k, side);
      BypassRow                   b{j.id, side, side ? j.patch_b : j.patch_a, (PetscInt)(q[2] + q[5]), std::hypot(fs[0], fs[1]), {0, 0, 0}, w, L, NAN, NAN, NAN, NAN};
      for (int c = 0; c < 3; ++c) b.d[c] = b.bearing > none ? (fs[0] * j.R[3 + c] + fs[1] * j.R[6 + c]) / b.bearing : j.R[3 + c];
      double ahead = q[1] > 0 ? q[0] / q[1] : NAN, behind = q[4] > 0 ? q[3] / q[4] : NAN;
      if (!std::isnan(ahead) || !std::isnan(behind)) {
        if (!std::isnan(ahead) && !std::isnan(behind)) b.balance = (ahead - behind) * w - b.bearing;
        if (std::isnan(ahead)) ahead = behind + b.bearing / w;
        if (std::isnan(behind)) behind = ahead - b.bearing / w;
        const bool by_ahead = std::fabs(ahead) <= std::fabs(behind);
        b.flux              = by_ahead ? ahead : behind;
        b.n_in              = by_ahead ? behind : ahead;
        b.load              = b.flux * w;
      }
      rows.push_back(b);
    }
  }
  PetscCall(VecRestoreArrayRead(m.bypass_local, &s));
  PetscFunctionReturn(0);
}

} // namespace boltnet
