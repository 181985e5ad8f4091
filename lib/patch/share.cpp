// What the ranks tell each other while the layout is made (layout_steps.hpp): which rank lays out
// each shell part, each holder's joints (sent by rank 0), and the records every rank needs of what
// the holders laid out.
#include "patch/layout_steps.hpp"
#include "core/hash.hpp"
#include "patch/pack.hpp"

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstring>
#include <new>
#include <numeric>
#include <type_traits>

namespace boltnet {

// Which rank lays out each shell part (-1: a rigid part, which every rank lays out): the largest
// first, each to the rank with the fewest nodes so far (longest processing time first), the lowest
// rank among equals, so that every rank computes the same assignment.
std::vector<PetscMPIInt> AssignParts(const Model &m, PetscMPIInt size)
{
  std::vector<PetscMPIInt> holder(m.parts.size(), -1);
  std::vector<std::pair<std::size_t, PetscInt>> bysize;
  for (const auto &[pos, sp] : m.shells) bysize.push_back({sp.read || sp.on_rank0 ? (std::size_t)sp.size : sp.mesh.x.size(), pos});
  std::stable_sort(bysize.begin(), bysize.end(), [](const auto &a, const auto &b) { return a.first > b.first; });
  std::vector<std::size_t> load(size, 0);
  for (const auto &[n, pos] : bysize) {
    const PetscMPIInt r = (PetscMPIInt)(std::min_element(load.begin(), load.end()) - load.begin());
    holder[pos]         = r;
    load[r] += n;
  }
  return holder;
}

// Rank 0 holds the model's joints (the scene's fastener table is read there alone, io/scene.cpp; a
// linking code may give them on every rank, and the other ranks' copies are dropped here). Each
// rank receives the joints that attach to the shell parts it holds (`holder`, AssignParts) with
// their positions in the model (`index`); rank 0 keeps the whole list in `all`, to lay out the
// network's graph. Every rank learns the number of joints.
PetscErrorCode ShareJoints(MPI_Comm comm, const std::vector<PetscMPIInt> &holder, Model &m, std::vector<JointDesc> *all, std::vector<PetscInt> *index, PetscInt *njoint)
{
  static_assert(std::is_trivially_copyable<JointDesc>::value, "joint descriptions travel as bytes");
  struct Sent {
    PetscInt  index;
    JointDesc d;
  };
  PetscMPIInt rank, size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<std::vector<Sent>> to(rank == 0 ? size : 0);
  std::vector<int>               counts(size, 0), displs(size, 0);
  std::vector<Sent>              packed;
  if (rank == 0) {
    *all = std::move(m.joints);
    for (size_t ji = 0; ji < all->size(); ++ji) {
      const JointDesc &d = (*all)[ji];
      const PetscMPIInt ra = holder[m.Find(d.part_a)], rb = holder[m.Find(d.part_b)];
      if (ra >= 0) to[ra].push_back(Sent{(PetscInt)ji, d});
      if (rb >= 0 && rb != ra) to[rb].push_back(Sent{(PetscInt)ji, d});
    }
    size_t end  = 0; // bytes packed so far: one MPI message, counted in int bytes, carries them all
    bool   fits = true;
    for (PetscMPIInt r = 0; r < size && fits; ++r) {
      const size_t bytes = to[r].size() * sizeof(Sent);
      fits               = end + bytes <= (size_t)INT_MAX;
      if (!fits) break;
      counts[r] = (int)bytes;
      displs[r] = (int)end;
      end += bytes;
      packed.insert(packed.end(), to[r].begin(), to[r].end());
    }
    std::vector<std::vector<Sent>>().swap(to);
    *njoint = fits ? (PetscInt)all->size() : -1;
  } else std::vector<JointDesc>().swap(m.joints);
  PetscCallMPI(MPI_Bcast(njoint, 1, MPIU_INT, 0, comm));
  PetscCheck(*njoint >= 0, comm, PETSC_ERR_SUP, "The model's joints are more than one message can carry to the ranks (%d bytes)", INT_MAX);
  int mine = 0;
  PetscCallMPI(MPI_Scatter(counts.data(), 1, MPI_INT, &mine, 1, MPI_INT, 0, comm));
  std::vector<Sent> got(mine / sizeof(Sent));
  PetscCallMPI(MPI_Scatterv(packed.data(), counts.data(), displs.data(), MPI_BYTE, got.data(), mine, MPI_BYTE, 0, comm));
  m.joints.clear();
  index->clear();
  for (const Sent &s : got) {
    m.joints.push_back(s.d);
    index->push_back(s.index);
  }
  std::int64_t sides = 0;
  for (const JointDesc &d : m.joints) sides += (holder[m.Find(d.part_a)] == rank) + (holder[m.Find(d.part_b)] == rank);
  PetscCall(PetscInfo(nullptr, "Attaching %zu of %" PetscInt_FMT " joints (%lld joint sides) on this rank's shell parts\n", m.joints.size(), *njoint, (long long)sides));
  PetscFunctionReturn(0);
}

namespace {

// Bytes in pieces of at most 1 GiB: one MPI message counts them in int.
constexpr std::size_t kPiece = std::size_t(1) << 30;

} // namespace

// Each part is a short exchange between rank 0 and the part's holder: its length (-1: rank 0 could
// not pack it), the holder's answer (1: ready to take it), then the bytes. Neither side leaves the
// loop on a failure (out of memory): it keeps its first error, skips the part's bytes, and goes on,
// so that every exchange is completed and the error is raised after it (by Collective, on every
// rank).
PetscErrorCode SendRank0Meshes(MPI_Comm comm, const std::vector<PetscMPIInt> &holder, Model &m)
{
  PetscMPIInt    rank;
  std::int64_t   parts = 0, bytes = 0;
  char           failed[256] = ""; // the first failure on this rank (no allocation after a bad_alloc)
  PetscErrorCode code        = PETSC_ERR_MEM;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  // The C++ work of an exchange (packing, allocating, unpacking): false if it threw.
  auto attempt = [&](PetscInt id, const char *what, auto &&work) {
    try {
      work();
      return true;
    } catch (const std::exception &e) {
      const bool memory = dynamic_cast<const std::bad_alloc *>(&e) != nullptr;
      if (!failed[0]) {
        std::snprintf(failed, sizeof failed, "Shell patch %lld: %s its mesh: %s", (long long)id, what, memory ? "out of memory" : e.what());
        code = memory ? PETSC_ERR_MEM : PETSC_ERR_PLIB;
      }
      return false;
    }
  };
  for (auto &[pos, sp] : m.shells) {
    const PetscMPIInt h = holder[pos];
    const PetscInt    id = m.parts[pos].id;
    if (!sp.on_rank0 || h == 0 || (rank != 0 && rank != h)) continue;
    std::vector<char> b;
    std::int64_t      len   = -1;
    int               ready = 0;
    if (rank == 0) {
      if (attempt(id, "rank 0 could not pack", [&] {
            PackWriter w(b);
            Pack(w, sp.mesh);
          }))
        len = (std::int64_t)b.size();
      sp.mesh = ShellMesh{}; // its memory released
      PetscCallMPI(MPI_Send(&len, 1, MPI_INT64_T, h, 0, comm));
      if (len >= 0) PetscCallMPI(MPI_Recv(&ready, 1, MPI_INT, h, 0, comm, MPI_STATUS_IGNORE));
      for (std::size_t at = 0; ready && at < b.size(); at += kPiece) PetscCallMPI(MPI_Send(b.data() + at, (PetscMPIInt)std::min(kPiece, b.size() - at), MPI_BYTE, h, 0, comm));
    } else {
      PetscCallMPI(MPI_Recv(&len, 1, MPI_INT64_T, 0, 0, comm, MPI_STATUS_IGNORE));
      if (len < 0) continue; // rank 0 keeps the error
      ready = attempt(id, "this rank could not take", [&] { b.resize((std::size_t)len); }) ? 1 : 0;
      PetscCallMPI(MPI_Send(&ready, 1, MPI_INT, 0, 0, comm));
      for (std::size_t at = 0; ready && at < b.size(); at += kPiece) PetscCallMPI(MPI_Recv(b.data() + at, (PetscMPIInt)std::min(kPiece, b.size() - at), MPI_BYTE, 0, 0, comm, MPI_STATUS_IGNORE));
      if (ready) attempt(id, "this rank could not unpack", [&] {
          PackReader r(b.data(), b.size());
          Unpack(r, sp.mesh);
        });
    }
    parts += ready;
    bytes += ready ? len : 0;
  }
  PetscCheck(!failed[0], PETSC_COMM_SELF, code, "%s", failed);
  if (parts && rank == 0) PetscCall(PetscInfo(nullptr, "Sent %lld shell part meshes (%lld bytes) to the ranks that lay them out\n", (long long)parts, (long long)bytes));
  if (parts && rank != 0) PetscCall(PetscInfo(nullptr, "Received %lld shell part meshes (%lld bytes) from rank 0\n", (long long)parts, (long long)bytes));
  PetscFunctionReturn(0);
}

// What the holders of the parts found, given to every rank: each patch's record (the nodes its
// vertex carries, all its nodes, whether condensed), each seam's ends, a stub (part, section,
// condensed) for every shell patch held elsewhere, the fingerprint. Each joint's attachment on shell
// parts goes to rank 0 alone, which lays out the network's graph (network/build.cpp) with `all`, its
// components of every joint (their shell sides still to be filled): the other ranks drop the
// components of their parts' joints here and receive their own from DMNetworkDistribute. Each value
// has one writer (the holder of its part), so sums gather them.
PetscErrorCode ShareLayout(MPI_Comm comm, const std::map<PetscInt, ShellPatch> &stubs, std::vector<JointComp> &&all, Layout *L)
{
  PetscFunctionBeginUser;
  const PetscInt np = (PetscInt)L->patches.size(), ns = (PetscInt)L->seams.size(), nj = L->njoints;
  constexpr int  kP = 6; // id, kind, nodes carried, all nodes, condensed, joint nodes
  std::vector<PetscInt>      pi(kP * np, 0), si(3 * ns, 0), ji(6 * nj, 0);
  std::vector<PetscReal>     px(3 * np, 0), jx(12 * nj, 0); // per joint side: d, attachment point
  std::vector<std::uint64_t> digest(np, 0);
  for (const auto &[pos, sp] : L->shells) {
    PetscInt *q = &pi[kP * pos];
    q[0] = sp.id, q[1] = static_cast<PetscInt>(PatchKind::Shell), q[2] = (PetscInt)sp.carried.size();
    q[3] = sp.nnodes(), q[4] = sp.condensed, q[5] = (PetscInt)sp.joint_nodes.size();
    for (int k = 0; k < 3; ++k) px[3 * pos + k] = sp.mesh.x[0][k];
    Hasher h;
    h.Add(sp.part_node);
    h.Add(sp.carried);
    digest[pos] = h.h;
  }
  for (PetscInt s = 0; s < ns; ++s) {
    const Seam &sm = L->seams[s];
    if (sm.part < 0) continue; // held elsewhere
    si[3 * s] = sm.part, si[3 * s + 1] = sm.va, si[3 * s + 2] = sm.vb;
  }
  for (const JointComp &c : L->joints) // this rank's parts' joints, at their place in the model
    for (int side = 0; side < 2; ++side) {
      const PetscInt j = c.index, v = side ? c.vb : c.va;
      if (v < 0 || !L->shells.count(v)) continue; // held elsewhere, or a rigid part's (known to all)
      PetscInt *q = &ji[6 * j + 3 * side];
      q[0] = v + 1, q[1] = side ? c.pnode_b : c.pnode_a, q[2] = side ? c.node_b : c.node_a;
      const std::array<double, 3> at = ShellAttachmentPoint(L->shells.at(v), c, q[1]);
      for (int k = 0; k < 3; ++k) {
        jx[12 * j + 6 * side + k]     = side ? c.db[k] : c.da[k];
        jx[12 * j + 6 * side + 3 + k] = at[k];
      }
    }
  std::vector<JointComp>().swap(L->joints); // rank 0's are `all`; the others' come from the network
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, pi.data(), (PetscMPIInt)pi.size(), MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, px.data(), (PetscMPIInt)px.size(), MPIU_REAL, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, digest.data(), (PetscMPIInt)digest.size(), MPI_UINT64_T, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, si.data(), (PetscMPIInt)si.size(), MPIU_INT, MPI_SUM, comm));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Reduce(rank == 0 ? MPI_IN_PLACE : ji.data(), ji.data(), (PetscMPIInt)ji.size(), MPIU_INT, MPI_SUM, 0, comm));
  PetscCallMPI(MPI_Reduce(rank == 0 ? MPI_IN_PLACE : jx.data(), jx.data(), (PetscMPIInt)jx.size(), MPIU_REAL, MPI_SUM, 0, comm));

  L->nodes.assign(np, 1);
  L->ncondensed = L->njoint_nodes = 0;
  for (PetscInt pos = 0; pos < np; ++pos) {
    if (L->holder[pos] < 0) continue; // a rigid patch: laid out everywhere
    const PetscInt *q = &pi[kP * pos];
    L->patches[pos]   = PatchComp{q[0], pos, q[1], q[2], {px[3 * pos], px[3 * pos + 1], px[3 * pos + 2]}};
    L->nodes[pos]     = q[3];
    L->ncondensed += q[4];
    L->njoint_nodes += q[5];
    if (L->shells.count(pos)) continue;
    ShellPatch stub  = stubs.at(L->part_of[pos]);
    stub.condensed   = q[4] != 0;
    L->shells[pos]   = std::move(stub);
  }
  for (PetscInt s = 0; s < ns; ++s) {
    Seam &sm = L->seams[s];
    if (sm.part >= 0) continue;
    sm.part = si[3 * s], sm.va = si[3 * s + 1], sm.vb = si[3 * s + 2];
    const ShellPatch &stub = stubs.at(L->part_of[sm.va]);
    sm.material = stub.material, sm.drill = stub.drill;
  }
  PetscInt unattached = -1; // the first joint not attached on both sides (rank 0's count)
  if (rank == 0) {
    L->joints = std::move(all);
    { // the output tables' rows: the joints by increasing id (CheckModel refused an id given twice)
      std::vector<PetscInt> order(L->joints.size());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](PetscInt l, PetscInt r) { return L->joints[l].id < L->joints[r].id; });
      for (size_t r = 0; r < order.size(); ++r) L->joints[order[r]].row = (PetscInt)r;
    }
    for (PetscInt j = 0; j < nj; ++j)
      for (int side = 0; side < 2; ++side) {
        const PetscInt *q = &ji[6 * j + 3 * side];
        if (q[0] == 0) continue;
        JointComp &c = L->joints[j];
        (side ? c.vb : c.va)           = q[0] - 1;
        (side ? c.pnode_b : c.pnode_a) = q[1];
        (side ? c.node_b : c.node_a)   = q[2];
        for (int k = 0; k < 3; ++k) {
          (side ? c.db : c.da)[k] = jx[12 * j + 6 * side + k];
          (side ? c.pb : c.pa)[k] = jx[12 * j + 6 * side + 3 + k];
        }
      }
    for (JointComp &c : L->joints) // the sides on rigid patches, laid out everywhere
      for (int side = 0; side < 2; ++side) {
        const PetscInt v = side ? c.vb : c.va;
        if (v < 0 || L->holder[v] >= 0) continue;
        for (int k = 0; k < 3; ++k) (side ? c.pb : c.pa)[k] = L->patches[v].x[k] + (side ? c.db : c.da)[k];
      }
    for (const JointComp &c : L->joints)
      if (unattached < 0 && (c.va < 0 || c.vb < 0)) unattached = c.id;
  }
  PetscCallMPI(MPI_Bcast(&unattached, 1, MPIU_INT, 0, comm));
  PetscCheck(unattached < 0, comm, PETSC_ERR_PLIB, "Joint %" PetscInt_FMT " was not attached on every side", unattached);

  // The fingerprint (rank 0's, given to all): the patches in order with the nodes they carry, the
  // joints with their patches.
  char hex[64] = {0};
  if (rank == 0) {
    Hasher h;
    h.Add((std::uint64_t)np);
    for (PetscInt p = 0; p < np; ++p) {
      h.Add(L->patches[p].id);
      h.Add(L->patches[p].kind);
      h.Add(L->patches[p].nnodes);
      h.Add(digest[p]);
    }
    h.Add((std::uint64_t)nj);
    for (const JointComp &c : L->joints) {
      h.Add(c.id);
      h.Add(c.va);
      h.Add(c.vb);
    }
    std::strncpy(hex, h.Hex().c_str(), sizeof hex - 1);
  }
  PetscCallMPI(MPI_Bcast(hex, (PetscMPIInt)sizeof hex, MPI_CHAR, 0, comm));
  L->fingerprint = hex;
  PetscFunctionReturn(0);
}

} // namespace boltnet
