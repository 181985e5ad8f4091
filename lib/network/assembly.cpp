// DMNetwork assembly: patches are vertices, joints are edges (docs/architecture.md).
#include "network/assembly.hpp"
#include "network/gather.hpp"
#include "core/guard.hpp"
#include "mesh/cut.hpp"
#include "mesh/mesh.hpp"

#include <metis.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <map>
#include <set>
#include <tuple>

namespace boltnet {
namespace {

constexpr PetscInt kNodeDof = 6;

struct EdgeView {
  const JointComp *joint;
  PetscInt         va, vb; // vertex points
};

PetscErrorCode GetEdge(DM dm, PetscInt e, EdgeView *ev)
{
  PetscInt        key, nvar;
  void           *data;
  const PetscInt *cone;

  PetscFunctionBeginUser;
  PetscCall(DMNetworkGetComponent(dm, e, 0, &key, &data, &nvar));
  PetscCall(DMNetworkGetConnectedVertices(dm, e, &cone));
  ev->joint = static_cast<const JointComp *>(data);
  ev->va    = cone[0];
  ev->vb    = cone[1];
  PetscFunctionReturn(0);
}

// The edge and the local-vector offsets of its two attachment nodes.
PetscErrorCode GetEdgeLocal(DM dm, PetscInt e, EdgeView *ev, PetscInt *oa, PetscInt *ob)
{
  PetscFunctionBeginUser;
  PetscCall(GetEdge(dm, e, ev));
  PetscCall(DMNetworkGetLocalVecOffset(dm, ev->va, ALL_COMPONENTS, oa));
  PetscCall(DMNetworkGetLocalVecOffset(dm, ev->vb, ALL_COMPONENTS, ob));
  *oa += kNodeDof * ev->joint->node_a;
  *ob += kNodeDof * ev->joint->node_b;
  PetscFunctionReturn(0);
}

// Global rows of the 12 dof a joint couples: node a's six, then node b's (ghost vertices included).
PetscErrorCode GetEdgeGlobalRows(DM dm, const EdgeView &ev, PetscInt rows[12])
{
  PetscInt ga, gb;
  PetscFunctionBeginUser;
  PetscCall(DMNetworkGetGlobalVecOffset(dm, ev.va, ALL_COMPONENTS, &ga));
  PetscCall(DMNetworkGetGlobalVecOffset(dm, ev.vb, ALL_COMPONENTS, &gb));
  for (int i = 0; i < kNodeDof; ++i) {
    rows[i]            = ga + kNodeDof * ev.joint->node_a + i;
    rows[kNodeDof + i] = gb + kNodeDof * ev.joint->node_b + i;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode GetPatch(DM dm, PetscInt v, const PatchComp **patch)
{
  PetscInt key, nvar;
  void    *data;
  PetscFunctionBeginUser;
  PetscCall(DMNetworkGetComponent(dm, v, 0, &key, &data, &nvar));
  *patch = static_cast<const PatchComp *>(data);
  PetscFunctionReturn(0);
}

PetscErrorCode GetSeam(BoltnetAssembly a, PetscInt e, const Seam **seam)
{
  PetscInt key, nvar;
  void    *data;
  PetscFunctionBeginUser;
  PetscCall(DMNetworkGetComponent(a->dm, e, 0, &key, &data, &nvar));
  *seam = &a->seams.at(static_cast<const SeamComp *>(data)->index);
  PetscFunctionReturn(0);
}

// The 24 dof of each seam element: offsets of the seam's two vertices, global or local.
void SeamElementDofs(const Seam::Element &el, PetscInt oa, PetscInt ob, PetscInt dofs[24])
{
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < kNodeDof; ++i) dofs[kNodeDof * k + i] = (el.side[k] ? ob : oa) + kNodeDof * el.node[k] + i;
}

PetscErrorCode GetSeamOffsets(BoltnetAssembly a, PetscInt e, PetscBool global, PetscInt *oa, PetscInt *ob)
{
  const PetscInt *cone;
  PetscFunctionBeginUser;
  PetscCall(DMNetworkGetConnectedVertices(a->dm, e, &cone));
  if (global) {
    PetscCall(DMNetworkGetGlobalVecOffset(a->dm, cone[0], ALL_COMPONENTS, oa));
    PetscCall(DMNetworkGetGlobalVecOffset(a->dm, cone[1], ALL_COMPONENTS, ob));
  } else {
    PetscCall(DMNetworkGetLocalVecOffset(a->dm, cone[0], ALL_COMPONENTS, oa));
    PetscCall(DMNetworkGetLocalVecOffset(a->dm, cone[1], ALL_COMPONENTS, ob));
  }
  PetscFunctionReturn(0);
}

// Jump in the local frame: du = Q (u_b - u_a), Q = diag(R, R).
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

// Global force on node b: Q^T f.
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

// Global tangent Q^T K Q.
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

// The Jacobian's nonzero pattern, counted exactly with MATPREALLOCATOR: each joint couples the
// 6 dof of its node on patch a with those of its node on patch b (12 x 12), wherever the two
// vertices live; each owned patch contributes its own pattern (a rigid patch: its diagonal).
// DMNetwork's own user-block preallocation (DMNetworkHasJacobian + DMNetworkVertexSetMatrix) was
// tried first and, in PETSc 3.18.5, under-allocates couplings through edges owned by another rank
// ("new nonzero caused a malloc" inside DMCreateMatrix_Network on the chain scene at 2 ranks):
// docs/architecture.md.
PetscErrorCode CreateJacobian(BoltnetAssembly a)
{
  Mat      pre;
  PetscInt n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(a->X, &n));
  PetscCall(MatCreate(a->comm, &pre));
  PetscCall(MatSetType(pre, MATPREALLOCATOR));
  PetscCall(MatSetSizes(pre, n, n, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetUp(pre));
  PetscScalar zeros[576] = {0};
  for (PetscInt e : a->jedges) {
    EdgeView ev;
    PetscInt rows[12];
    PetscCall(GetEdge(a->dm, e, &ev));
    PetscCall(GetEdgeGlobalRows(a->dm, ev, rows));
    PetscCall(MatSetValues(pre, 12, rows, 12, rows, zeros, INSERT_VALUES));
  }
  for (PetscInt e : a->sedges) {
    const Seam *seam;
    PetscInt    ga, gb, rows[24];
    PetscCall(GetSeam(a, e, &seam));
    PetscCall(GetSeamOffsets(a, e, PETSC_TRUE, &ga, &gb));
    for (const Seam::Element &el : seam->elems) {
      SeamElementDofs(el, ga, gb, rows);
      PetscCall(MatSetValues(pre, 24, rows, 24, rows, zeros, INSERT_VALUES));
    }
  }
  for (PetscInt v = a->vStart; v < a->vEnd; ++v) {
    PetscBool ghost;
    PetscInt  goff;
    PetscCall(DMNetworkIsGhostVertex(a->dm, v, &ghost));
    if (ghost) continue;
    const PatchComp *p;
    PetscCall(GetPatch(a->dm, v, &p));
    PetscCall(DMNetworkGetGlobalVecOffset(a->dm, v, ALL_COMPONENTS, &goff));
    for (PetscInt i = 0; i < kNodeDof * p->nnodes; ++i) PetscCall(MatSetValue(pre, goff + i, goff + i, 0.0, INSERT_VALUES));
    auto op = a->ops.find(v);
    if (op == a->ops.end()) continue;
    std::vector<PetscInt> cols;
    std::vector<PetscScalar> z;
    for (PetscInt r = 0; r < op->second.n; ++r) {
      const PetscInt row = goff + r, b = op->second.rowptr[r], e = op->second.rowptr[r + 1];
      cols.resize(e - b);
      z.assign(e - b, 0.0);
      for (PetscInt k = b; k < e; ++k) cols[k - b] = goff + op->second.cols[k];
      PetscCall(MatSetValues(pre, 1, &row, e - b, cols.data(), z.data(), INSERT_VALUES));
    }
  }
  PetscCall(MatAssemblyBegin(pre, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(pre, MAT_FINAL_ASSEMBLY));
  PetscCall(MatCreate(a->comm, &a->J));
  PetscCall(MatSetType(a->J, MATAIJ));
  PetscCall(MatSetSizes(a->J, n, n, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatPreallocatorPreallocate(pre, PETSC_TRUE, a->J));
  PetscCall(MatDestroy(&pre));
  PetscFunctionReturn(0);
}

PetscErrorCode SetUpBoundaryRows(BoltnetAssembly a)
{
  PetscFunctionBeginUser;
  a->dirichlet_rows.clear();
  a->dirichlet_values.clear();
  a->force_rows.clear();
  a->force_values.clear();
  std::map<PetscInt, PetscReal> dir, frc; // global row -> value (later entries override / add)
  std::map<PetscInt, PetscInt>  frc_bc;   // global row -> the first force condition on it
  for (PetscInt v = a->vStart; v < a->vEnd; ++v) {
    PetscBool        ghost;
    const PatchComp *p;
    PetscInt         goff;
    PetscCall(DMNetworkIsGhostVertex(a->dm, v, &ghost));
    if (ghost) continue;
    PetscCall(GetPatch(a->dm, v, &p));
    PetscCall(DMNetworkGetGlobalVecOffset(a->dm, v, ALL_COMPONENTS, &goff));
    const bool        shell = p->kind == static_cast<PetscInt>(PatchKind::Shell);
    const ShellPatch *sp    = shell ? &a->shells.at(p->index) : nullptr;
    for (const BCDesc &bc : a->bcs) {
      if (bc.patch != p->id) continue;
      // The nodes in this patch: a rigid patch's node; a shell patch's share of the named set, or
      // all its mesh nodes. A force is the set's total over the whole part.
      std::vector<int> nodes = {0};
      PetscInt         total = 1;
      if (shell) {
        if (bc.set.empty()) {
          nodes.resize(sp->mesh.x.size());
          for (size_t n = 0; n < nodes.size(); ++n) nodes[n] = (int)n;
        } else {
          auto it = sp->mesh.node_sets.find(bc.set);
          nodes   = it == sp->mesh.node_sets.end() ? std::vector<int>{} : it->second; // checked when the BC was added
        }
        total = sp->part_set_size.at(bc.set);
      }
      for (int n : nodes)
        for (PetscInt d = 0; d < kNodeDof; ++d) {
          if (bc.dof >= 0 && d != bc.dof) continue;
          const PetscInt row = goff + kNodeDof * n + d;
          if (bc.kind == BOLTNET_BC_FORCE) {
            frc[row] += bc.value / (PetscReal)total;
            frc_bc.emplace(row, &bc - a->bcs.data());
          } else dir[row] = bc.kind == BOLTNET_BC_FIXED ? 0.0 : bc.value;
        }
    }
  }
  for (auto &kv : dir) {
    a->dirichlet_rows.push_back(kv.first);
    a->dirichlet_values.push_back(kv.second);
  }
  // A force on a prescribed dof would be absorbed by the support without a trace (a mistaken node
  // set gave a converged run with zero displacement): an error naming the condition.
  PetscInt bad = PETSC_MAX_INT, gbad;
  for (auto &kv : frc) {
    if (dir.count(kv.first)) bad = PetscMin(bad, frc_bc[kv.first]);
    a->force_rows.push_back(kv.first);
    a->force_values.push_back(kv.second);
  }
  PetscCall(MPIU_Allreduce(&bad, &gbad, 1, MPIU_INT, MPI_MIN, a->comm));
  PetscCheck(gbad == PETSC_MAX_INT, a->comm, PETSC_ERR_USER_INPUT, "The force on patch %" PetscInt_FMT " dof %s node set '%s' acts on dof that another boundary condition prescribes: the support would absorb it. Apply it to free dof (check the node set)",
             a->bcs[gbad].patch, a->bcs[gbad].dof < 0 ? "all" : std::array<const char *, 6>{"ux", "uy", "uz", "rx", "ry", "rz"}[a->bcs[gbad].dof], a->bcs[gbad].set.empty() ? "(all nodes)" : a->bcs[gbad].set.c_str());
  PetscFunctionReturn(0);
}

// Replace the parts by the patches they are cut into (lib/mesh/cut.hpp) and add the seams between
// them. jv holds the part position of each joint's two sides on entry, their patch position on
// return; the joints' attachment nodes are renumbered to their patch.
PetscErrorCode CutParts(BoltnetAssembly a, std::vector<PetscInt> &jv)
{
  PetscFunctionBeginUser;
  PetscInt maxn = a->patch_max_nodes;
  if (maxn < 0) { // automatic: about eight patches per rank, none smaller than 32 nodes
    PetscInt total = 0;
    for (const auto &kv : a->shells) total += (PetscInt)kv.second.mesh.x.size();
    maxn = a->size == 1 ? 0 : std::max<PetscInt>(32, (total + 8 * a->size - 1) / (8 * a->size));
  }
  const PetscInt                                        nparts = (PetscInt)a->patches.size();
  std::vector<PatchComp>                                patches;
  std::map<PetscInt, ShellPatch>                        shells;
  std::vector<std::vector<std::pair<PetscInt, int>>>    jnmap(nparts); // joint node k -> (patch, node)
  std::vector<std::vector<std::pair<PetscInt, int>>>    nodemap(nparts); // mesh node of a cut part -> (patch, node)
  std::vector<PetscInt>                                 first(nparts), nmesh(nparts, 0);
  for (PetscInt i = 0; i < nparts; ++i) {
    PatchComp p = a->patches[i];
    first[i]    = (PetscInt)patches.size();
    auto sh     = a->shells.find(i);
    if (sh == a->shells.end()) {
      p.index = first[i];
      patches.push_back(p);
      continue;
    }
    ShellPatch &part = sh->second;
    const int   n    = (int)part.mesh.x.size();
    nmesh[i]         = n;
    part.part_set_size[""] = n;
    for (const auto &kv : part.mesh.node_sets) part.part_set_size[kv.first] = (PetscInt)kv.second.size();
    // A footprint and every element touching it stay in one patch: no seam element may touch a
    // footprint node, since exact coupling eliminates those nodes inside the patch's operator.
    std::vector<std::vector<int>> touching(n), clusters;
    for (size_t e = 0; e < part.mesh.quads.size(); ++e)
      for (int v : part.mesh.quads[e]) touching[v].push_back((int)e);
    for (const auto &jn : part.joint_nodes) {
      std::set<int> c(jn.footprint.begin(), jn.footprint.end());
      for (int v : jn.footprint)
        for (int e : touching[v]) c.insert(part.mesh.quads[e].begin(), part.mesh.quads[e].end());
      clusters.emplace_back(c.begin(), c.end());
    }
    const PartCut cut = CutIntoStrips(part.mesh, clusters, maxn);
    if (cut.npatches == 1) {
      for (size_t k = 0; k < part.joint_nodes.size(); ++k) jnmap[i].push_back({first[i], n + (int)k});
      p.index = first[i];
      patches.push_back(p);
      shells[first[i]] = std::move(part);
      continue;
    }
    std::vector<ShellPatch> subs(cut.npatches);
    for (ShellPatch &sub : subs) {
      sub.id            = part.id;
      sub.material      = part.material;
      sub.drill         = part.drill;
      sub.part_set_size = part.part_set_size;
      for (const auto &kv : part.mesh.node_sets) sub.mesh.node_sets[kv.first]; // every set exists in every patch
    }
    std::vector<int> local(n);
    for (int v = 0; v < n; ++v) {
      ShellPatch &sub = subs[cut.patch[v]];
      local[v]        = (int)sub.mesh.x.size();
      sub.mesh.x.push_back(part.mesh.x[v]);
      sub.part_node.push_back(v);
      nodemap[i].push_back({first[i] + cut.patch[v], local[v]});
    }
    std::map<int, Seam> seams; // by lower strip
    for (const auto &q : part.mesh.quads) {
      int lo = cut.patch[q[0]];
      for (int k = 1; k < 4; ++k) lo = std::min(lo, cut.patch[q[k]]);
      bool one = true;
      for (int k = 0; k < 4; ++k) one = one && cut.patch[q[k]] == lo;
      if (one) {
        subs[lo].mesh.quads.push_back({local[q[0]], local[q[1]], local[q[2]], local[q[3]]});
        continue;
      }
      Seam &sm = seams[lo];
      Seam::Element el;
      for (int k = 0; k < 4; ++k) {
        el.X[k]    = part.mesh.x[q[k]];
        el.side[k] = cut.patch[q[k]] != lo;
        el.node[k] = local[q[k]];
      }
      sm.elems.push_back(el);
    }
    for (const auto &kv : part.mesh.node_sets)
      for (int v : kv.second) subs[cut.patch[v]].mesh.node_sets[kv.first].push_back(local[v]);
    for (auto jn : part.joint_nodes) { // the whole footprint is in one strip (CutIntoStrips)
      const int s = cut.patch[jn.footprint[0]];
      for (int &v : jn.footprint) v = local[v];
      jnmap[i].push_back({first[i] + s, (int)(subs[s].mesh.x.size() + subs[s].joint_nodes.size())});
      subs[s].joint_nodes.push_back(jn);
    }
    for (int s = 0; s < cut.npatches; ++s) {
      PatchComp q = p;
      q.index     = first[i] + s;
      q.nnodes    = subs[s].nnodes();
      for (int k = 0; k < 3; ++k) q.x[k] = subs[s].mesh.x[0][k];
      patches.push_back(q);
      shells[q.index] = std::move(subs[s]);
    }
    a->cut_parts[part.id] = part.mesh;
    for (auto &kv : seams) {
      Seam &sm    = kv.second;
      sm.part     = part.id;
      sm.va       = first[i] + kv.first;
      sm.vb       = first[i] + kv.first + 1;
      sm.material = part.material;
      sm.drill    = part.drill;
      a->seams.push_back(std::move(sm));
    }
  }
  for (size_t ji = 0; ji < a->joints.size(); ++ji)
    for (int side = 0; side < 2; ++side) {
      JointComp     &j    = a->joints[ji];
      PetscInt      &node = side ? j.node_b : j.node_a;
      PetscInt      &pos  = jv[2 * ji + side];
      const PetscInt part = pos;
      pos                 = first[part];
      if (!a->shells.count(part)) continue; // a rigid patch: its node 0
      if (node < nmesh[part]) {             // a mesh node (-coupling_type node)
        if (!nodemap[part].empty()) std::tie(pos, node) = nodemap[part][node];
      } else std::tie(pos, node) = jnmap[part][node - nmesh[part]];
    }
  a->patches = std::move(patches);
  a->shells  = std::move(shells);
  PetscFunctionReturn(0);
}

// Distribute the patches over the ranks by dof: METIS (vertex weight: the patch's dof; edge weight:
// the joints and seams between two patches) on rank 0, then each edge goes to the lower of its two
// vertices' ranks. PETSc gives a vertex shared by several ranks to the highest of them, so a patch
// joined to a patch of its own rank stays there; the achieved balance is measured after
// distribution (dof_imbalance). The plex's partitioner is set to a shell partitioner holding that
// edge partition; -petscpartitioner_type on the command line still overrides it.
PetscErrorCode SetPartition(BoltnetAssembly a, const std::vector<PetscInt> &edgelist)
{
  DM               plex;
  PetscPartitioner part;
  PetscFunctionBeginUser;
  if (a->size == 1 || !a->balance) PetscFunctionReturn(0);
  const PetscInt        ne = (PetscInt)edgelist.size() / 2;
  std::vector<PetscInt> sizes(a->size, 0), points;
  if (a->rank == 0) {
    idx_t                           nv = (idx_t)a->patches.size(), ncon = 1, nparts = a->size, objval;
    std::vector<std::map<idx_t, idx_t>> adj(nv);
    for (PetscInt e = 0; e < ne; ++e) {
      const idx_t u = (idx_t)edgelist[2 * e], v = (idx_t)edgelist[2 * e + 1];
      adj[u][v]++;
      adj[v][u]++;
    }
    std::vector<idx_t> xadj(1, 0), adjncy, adjwgt, vwgt(nv), vpart(nv, 0);
    for (idx_t u = 0; u < nv; ++u) {
      for (const auto &kv : adj[u]) {
        adjncy.push_back(kv.first);
        adjwgt.push_back(kv.second);
      }
      xadj.push_back((idx_t)adjncy.size());
      vwgt[u] = (idx_t)(kNodeDof * a->patches[u].nnodes);
    }
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_SEED]    = 1; // the same partition on every run
    options[METIS_OPTION_NUMBERING] = 0;
    int status = METIS_OK;
    if (nv > nparts) status = METIS_PartGraphKway(&nv, &ncon, xadj.data(), adjncy.data(), vwgt.data(), nullptr, adjwgt.data(), &nparts, nullptr, nullptr, options, &objval, vpart.data());
    else
      for (idx_t u = 0; u < nv; ++u) vpart[u] = u; // no more patches than ranks: one each
    PetscCheck(status == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "METIS failed to partition the network (status %d)", status);
    std::vector<std::vector<PetscInt>> byRank(a->size);
    for (PetscInt e = 0; e < ne; ++e) byRank[std::min(vpart[edgelist[2 * e]], vpart[edgelist[2 * e + 1]])].push_back(e);
    for (PetscMPIInt r = 0; r < a->size; ++r) {
      sizes[r] = (PetscInt)byRank[r].size();
      points.insert(points.end(), byRank[r].begin(), byRank[r].end());
    }
  }
  PetscCall(DMNetworkGetPlex(a->dm, &plex));
  PetscCall(DMPlexGetPartitioner(plex, &part));
  PetscCall(PetscPartitionerSetType(part, PETSCPARTITIONERSHELL));
  PetscCall(PetscPartitionerShellSetPartition(part, a->size, sizes.data(), points.data()));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode AssemblyBuildNetwork(BoltnetAssembly a)
{
  PetscFunctionBeginUser;
  const PetscInt npatch = (PetscInt)a->patches.size(), njoint = (PetscInt)a->joints.size();
  PetscCheck(npatch > 0 && njoint > 0, a->comm, PETSC_ERR_USER_INPUT, "The assembly needs at least one patch and one joint (it has %" PetscInt_FMT " patches, %" PetscInt_FMT " joints)", npatch, njoint);
  // Patch ids -> positions; every patch must be reached by a joint (DMNetwork vertices come from edges).
  std::map<PetscInt, PetscInt> index;
  for (PetscInt i = 0; i < npatch; ++i) {
    PetscCheck(!index.count(a->patches[i].id), a->comm, PETSC_ERR_USER_INPUT, "Patch id %" PetscInt_FMT " is given twice", a->patches[i].id);
    index[a->patches[i].id] = i;
  }
  std::vector<PetscInt> degree(npatch, 0), edgelist;
  {
    std::map<PetscInt, PetscInt> seen;
    for (const JointComp &j : a->joints) {
      PetscCheck(!seen.count(j.id), a->comm, PETSC_ERR_USER_INPUT, "Joint id %" PetscInt_FMT " is given twice", j.id);
      seen[j.id] = 1;
    }
  }
  for (JointComp &j : a->joints) {
    auto ia = index.find(j.patch_a), ib = index.find(j.patch_b);
    PetscCheck(ia != index.end(), a->comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " names patch %" PetscInt_FMT " which does not exist", j.id, j.patch_a);
    PetscCheck(ib != index.end(), a->comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " names patch %" PetscInt_FMT " which does not exist", j.id, j.patch_b);
    PetscCheck(ia->second != ib->second, a->comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " joins patch %" PetscInt_FMT " to itself", j.id, j.patch_a);
    edgelist.push_back(ia->second);
    edgelist.push_back(ib->second);
    degree[ia->second]++;
    degree[ib->second]++;
  }
  for (PetscInt i = 0; i < npatch; ++i)
    PetscCheck(degree[i] > 0, a->comm, PETSC_ERR_USER_INPUT, "Patch %" PetscInt_FMT " is not joined to anything: every patch needs at least one joint", a->patches[i].id);
  for (const BCDesc &bc : a->bcs)
    PetscCheck(index.count(bc.patch), a->comm, PETSC_ERR_USER_INPUT, "A boundary condition names patch %" PetscInt_FMT " which does not exist", bc.patch);
  // Every group of patches joined by joints needs a prescribed displacement somewhere, else it can
  // move as a rigid body and the model is singular (issue 3 item 8). Partial supports are not
  // checked here; MUMPS reports what is left as a failed factorisation.
  {
    std::vector<PetscInt> group(npatch);
    for (PetscInt i = 0; i < npatch; ++i) group[i] = i;
    std::function<PetscInt(PetscInt)> root = [&](PetscInt i) { return group[i] == i ? i : group[i] = root(group[i]); };
    for (size_t k = 0; k < edgelist.size(); k += 2) group[root(edgelist[k])] = root(edgelist[k + 1]);
    std::vector<char> supported(npatch, 0);
    for (const BCDesc &bc : a->bcs)
      if (bc.kind != BOLTNET_BC_FORCE) supported[root(index[bc.patch])] = 1;
    std::string free;
    for (PetscInt i = 0; i < npatch; ++i)
      if (!supported[root(i)]) free += (free.empty() ? "" : ", ") + std::to_string(a->patches[i].id);
    PetscCheck(free.empty(), a->comm, PETSC_ERR_USER_INPUT, "Patch(es) %s and the joints between them have no fixed or prescribed dof: the model is singular (a rigid-body motion); fix or prescribe a dof of one of them", free.c_str());
  }
  // Joints on shell patches attach to a joint node of their own, tied to the footprint nodes
  // (penalty, exact), or to the nearest mesh node (node). docs/coupling.md.
  std::map<PetscInt, std::vector<std::array<PetscInt, 2>>> jointOf;
  for (size_t ji = 0; ji < a->joints.size(); ++ji) {
    JointComp &j = a->joints[ji];
    for (int side = 0; side < 2; ++side) {
      const PetscInt pid  = side ? j.patch_b : j.patch_a;
      PetscInt      &node = side ? j.node_b : j.node_a;
      auto           sh   = a->shells.find(index[pid]);
      node                = 0;
      if (sh == a->shells.end()) continue;
      ShellPatch::JointNode jn;
      jn.x    = {j.x[0], j.x[1], j.x[2]};
      jn.axis = {j.R[0], j.R[1], j.R[2]};
      if (a->coupling_type == CouplingType::Node) {
        PetscCheck(ContainingElement(sh->second.mesh, jn.x, jn.axis) >= 0 || !Footprint(sh->second.mesh, jn.x, jn.axis, a->coupling_radius).empty(), a->comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " at (%g, %g, %g) mm: no element of patch %" PetscInt_FMT " contains it and no node lies within %g mm (-coupling_radius): the joint is outside the part", j.id, (double)j.x[0], (double)j.x[1], (double)j.x[2], pid, (double)a->coupling_radius);
        node = NearestNode(sh->second.mesh, jn.x, jn.axis);
        continue;
      }
      jn.footprint = CouplingFootprint(sh->second.mesh, jn.x, jn.axis, a->coupling_radius);
      PetscCheck(!jn.footprint.empty(), a->comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " at (%g, %g, %g) mm: no node of patch %" PetscInt_FMT " lies within the footprint radius %g mm (-coupling_radius): the joint is outside the part", j.id, (double)j.x[0], (double)j.x[1], (double)j.x[2], pid, (double)a->coupling_radius);
      node = sh->second.nnodes();
      sh->second.joint_nodes.push_back(jn);
      jointOf[sh->first].push_back({(PetscInt)ji, side});
    }
  }
  if (a->coupling_type == CouplingType::Exact)
    for (auto &[pidx, sp] : a->shells) {
      // A node in two footprints follows the nearer joint (the first one at equal distance); a
      // joint left with no node is an error naming both joints.
      const auto                   &jo = jointOf[pidx];
      std::map<int, size_t>         taken; // node -> joint node k
      for (size_t k = 0; k < sp.joint_nodes.size(); ++k)
        for (int nd : sp.joint_nodes[k].footprint) {
          auto dist = [&](size_t kk) {
            double r2 = 0;
            for (int c = 0; c < 3; ++c) r2 += (sp.mesh.x[nd][c] - sp.joint_nodes[kk].x[c]) * (sp.mesh.x[nd][c] - sp.joint_nodes[kk].x[c]);
            return r2;
          };
          auto it = taken.find(nd);
          if (it == taken.end()) taken[nd] = k;
          else if (dist(k) < dist(it->second) * (1 - 1e-12)) it->second = k;
        }
      std::vector<std::vector<int>> kept(sp.joint_nodes.size());
      for (auto &[nd, k] : taken) kept[k].push_back(nd);
      for (size_t k = 0; k < sp.joint_nodes.size(); ++k) {
        if (kept[k].empty()) {
          const int    nd    = sp.joint_nodes[k].footprint[0];
          const PetscInt other = a->joints[jo[taken[nd]][0]].id;
          SETERRQ(a->comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " on patch %" PetscInt_FMT ": every node of its footprint is nearer to joint %" PetscInt_FMT " (-coupling_type exact gives a shared node to the nearer joint): the two fasteners are too close for this mesh; refine the mesh or reduce -coupling_radius", a->joints[jo[k][0]].id, sp.id, other);
        }
        sp.joint_nodes[k].footprint = kept[k];
      }
      // A footprint node follows its joint node: it cannot also carry a boundary condition.
      for (const BCDesc &bc : a->bcs) {
        if (bc.patch != sp.id) continue;
        std::vector<int> nodes;
        if (bc.set.empty()) {
          nodes.resize(sp.mesh.x.size());
          for (size_t n = 0; n < nodes.size(); ++n) nodes[n] = (int)n;
        } else nodes = sp.mesh.node_sets.at(bc.set);
        for (int nd : nodes) {
          auto it = taken.find(nd);
          if (it == taken.end()) continue;
          SETERRQ(a->comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT ": node %d of patch %" PetscInt_FMT " at (%g, %g, %g) mm is in its footprint and also carries a boundary condition (%s): with -coupling_type exact a footprint node follows the joint node and cannot be fixed, prescribed or loaded; move the condition, reduce -coupling_radius, or use -coupling_type penalty", a->joints[jo[it->second][0]].id, nd, sp.id, sp.mesh.x[nd][0], sp.mesh.x[nd][1], sp.mesh.x[nd][2], bc.set.empty() ? "on the whole patch" : ("node set '" + bc.set + "'").c_str());
        }
      }
    }
  for (auto &kv : a->shells) a->patches[kv.first].nnodes = kv.second.nnodes();

  // Large parts become several patches joined by seams; the edges are the joints, then the seams.
  a->nparts = npatch;
  PetscCall(Guard(a->comm, [&] { return CutParts(a, edgelist); }));
  for (const Seam &sm : a->seams) {
    edgelist.push_back(sm.va);
    edgelist.push_back(sm.vb);
  }
  const PetscInt nseam = (PetscInt)a->seams.size();

  PetscCall(DMNetworkCreate(a->comm, &a->dm));
  PetscCall(DMNetworkSetNumSubNetworks(a->dm, PETSC_DECIDE, 1));
  PetscCall(DMNetworkRegisterComponent(a->dm, "patch", sizeof(PatchComp), &a->keyPatch));
  PetscCall(DMNetworkRegisterComponent(a->dm, "joint", sizeof(JointComp), &a->keyJoint));
  PetscCall(DMNetworkRegisterComponent(a->dm, "seam", sizeof(SeamComp), &a->keySeam));
  // Rank 0 lays out the whole network; DMNetworkDistribute spreads it.
  const PetscInt ne = a->rank == 0 ? njoint + nseam : 0;
  PetscCall(DMNetworkAddSubnetwork(a->dm, "assembly", ne, a->rank == 0 ? edgelist.data() : nullptr, nullptr));
  PetscCall(DMNetworkLayoutSetUp(a->dm));
  std::vector<SeamComp> seamcomps(nseam);
  if (a->rank == 0) {
    PetscInt        nv, nee;
    const PetscInt *vtx, *edges;
    PetscCall(DMNetworkGetSubnetwork(a->dm, 0, &nv, &nee, &vtx, &edges));
    for (PetscInt i = 0; i < njoint; ++i) {
      JointComp &j = a->joints[i];
      j.index      = i;
      PetscCall(DMNetworkAddComponent(a->dm, edges[i], a->keyJoint, &j, 0));
    }
    for (PetscInt i = 0; i < nseam; ++i) {
      seamcomps[i] = SeamComp{i, a->seams[i].part};
      PetscCall(DMNetworkAddComponent(a->dm, edges[njoint + i], a->keySeam, &seamcomps[i], 0));
    }
    for (PetscInt i = 0; i < nv; ++i) {
      PetscInt gidx;
      PetscCall(DMNetworkGetGlobalVertexIndex(a->dm, vtx[i], &gidx));
      PatchComp &p = a->patches[gidx];
      p.index      = gidx;
      PetscCall(DMNetworkAddComponent(a->dm, vtx[i], a->keyPatch, &p, kNodeDof * p.nnodes));
    }
  }
  PetscCall(DMNetworkFinalizeComponents(a->dm));
  PetscCall(SetPartition(a, edgelist));
  PetscCall(DMNetworkDistribute(&a->dm, 0));
  PetscCall(DMNetworkGetVertexRange(a->dm, &a->vStart, &a->vEnd));
  PetscCall(DMNetworkGetEdgeRange(a->dm, &a->eStart, &a->eEnd));
  a->jedges.clear();
  a->sedges.clear();
  for (PetscInt e = a->eStart; e < a->eEnd; ++e) {
    PetscInt key, nvar;
    void    *data;
    PetscCall(DMNetworkGetComponent(a->dm, e, 0, &key, &data, &nvar));
    (key == a->keySeam ? a->sedges : a->jedges).push_back(e);
  }
  a->committed.assign(a->jedges.size(), History{});
  PetscCall(Guard(a->comm, [&] {
    for (PetscInt e : a->sedges) {
      const Seam *seam;
      PetscCall(GetSeam(a, e, &seam));
      auto &Ks = a->seam_ops[e];
      Ks.resize(seam->elems.size());
      for (size_t k = 0; k < seam->elems.size(); ++k) shell::ElementStiffness(seam->elems[k].X, seam->material, seam->drill, Ks[k]);
    }
    return PetscErrorCode(0);
  }));
  for (PetscInt v = a->vStart; v < a->vEnd; ++v) {
    PetscBool        ghost;
    const PatchComp *p;
    PetscCall(DMNetworkIsGhostVertex(a->dm, v, &ghost));
    PetscCall(GetPatch(a->dm, v, &p));
    if (ghost || p->kind != static_cast<PetscInt>(PatchKind::Shell)) continue;
    const ShellPatch &sp = a->shells.at(p->index);
    PetscCall(Guard(a->comm, [&] {
      a->ops[v] = BuildShellOperator(sp, a->coupling_type, a->coupling_penalty * sp.material.A[0], a->coupling_radius);
      return PetscErrorCode(0);
    }));
  }

  PetscCall(DMCreateGlobalVector(a->dm, &a->X));
  PetscCall(VecGetSize(a->X, &a->ndof_global));
  {
    PetscInt nloc, nmax;
    PetscCall(VecGetLocalSize(a->X, &nloc));
    PetscCallMPI(MPI_Allreduce(&nloc, &nmax, 1, MPIU_INT, MPI_MAX, a->comm));
    a->dof_imbalance = a->ndof_global > 0 ? (PetscReal)nmax * a->size / (PetscReal)a->ndof_global : 1;
  }
  PetscCall(VecSet(a->X, 0.0));
  PetscCall(CreateJacobian(a));
  PetscCall(MatSetOption(a->J, MAT_KEEP_NONZERO_PATTERN, PETSC_TRUE));
  PetscCall(MatSetOption(a->J, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  PetscCall(SetUpBoundaryRows(a));
  PetscFunctionReturn(0);
}

namespace {
// The joints evaluated from the local (ghosted) vector x.
PetscErrorCode EvaluateJointsLocal(BoltnetAssembly a, const PetscScalar *x, std::vector<Response> &out, std::vector<Vec6> *jumps, bool full_law)
{
  PetscFunctionBeginUser;
  out.resize(a->jedges.size());
  if (jumps) jumps->resize(a->jedges.size());
  const bool any_frozen = !full_law && a->frozen.size() == a->jedges.size();
  for (size_t i = 0; i < a->jedges.size(); ++i) {
    EdgeView ev;
    PetscInt oa, ob;
    PetscCall(GetEdgeLocal(a->dm, a->jedges[i], &ev, &oa, &ob));
    const Vec6 du = LocalJump(ev.joint->R, x + oa, x + ob);
    out[i]        = evaluate(ev.joint->params, a->committed[i], du, a->tangent, any_frozen && a->frozen[i]);
    if (jumps) (*jumps)[i] = du;
  }
  PetscFunctionReturn(0);
}
} // namespace

// The ghosted local copy of X (collective: every rank must call it, whatever it owns).
static PetscErrorCode GetLocalX(BoltnetAssembly a, Vec X, Vec *Xl, const PetscScalar **x)
{
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(a->dm, Xl));
  PetscCall(DMGlobalToLocalBegin(a->dm, X, INSERT_VALUES, *Xl));
  PetscCall(DMGlobalToLocalEnd(a->dm, X, INSERT_VALUES, *Xl));
  PetscCall(VecGetArrayRead(*Xl, x));
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyEvaluateJoints(BoltnetAssembly a, Vec X, std::vector<Response> &out, std::vector<Vec6> *jumps, bool full_law)
{
  Vec                Xl;
  const PetscScalar *x;
  PetscFunctionBeginUser;
  PetscCall(GetLocalX(a, X, &Xl, &x));
  PetscCall(EvaluateJointsLocal(a, x, out, jumps, full_law));
  PetscCall(VecRestoreArrayRead(Xl, &x));
  PetscCall(DMRestoreLocalVector(a->dm, &Xl));
  PetscFunctionReturn(0);
}

static PetscErrorCode AssemblyFormFunctionImpl(SNES snes, Vec X, Vec F, void *ctx)
{
  BoltnetAssembly       a = static_cast<BoltnetAssembly>(ctx);
  Vec                   Xl, Fl;
  const PetscScalar    *x, *xl;
  PetscScalar          *f;
  std::vector<Response> resp;
  PetscFunctionBeginUser;
  // One ghost update of X, for the joints and the patches alike.
  PetscCall(GetLocalX(a, X, &Xl, &xl));
  PetscCall(EvaluateJointsLocal(a, xl, resp, nullptr, false));
  PetscCall(DMGetLocalVector(a->dm, &Fl));
  PetscCall(VecSet(Fl, 0.0));
  PetscCall(VecGetArray(Fl, &f));
  for (size_t k = 0; k < a->jedges.size(); ++k) {
    EdgeView ev;
    PetscInt oa, ob;
    PetscCall(GetEdgeLocal(a->dm, a->jedges[k], &ev, &oa, &ob));
    const Vec6 g = GlobalForce(ev.joint->R, resp[k].force);
    for (int i = 0; i < kNodeDof; ++i) {
      f[ob + i] += g[i];
      f[oa + i] -= g[i];
    }
  }
  for (const auto &[e, Ks] : a->seam_ops) { // the owned seams' elements: K u
    const Seam *seam;
    PetscInt    oa, ob, dofs[24];
    PetscCall(GetSeam(a, e, &seam));
    PetscCall(GetSeamOffsets(a, e, PETSC_FALSE, &oa, &ob));
    for (size_t k = 0; k < Ks.size(); ++k) {
      SeamElementDofs(seam->elems[k], oa, ob, dofs);
      for (int r = 0; r < 24; ++r) {
        PetscScalar sum = 0;
        for (int c = 0; c < 24; ++c) sum += Ks[k][24 * r + c] * xl[dofs[c]];
        f[dofs[r]] += sum;
      }
    }
  }
  for (const auto &[v, op] : a->ops) { // the owned shell patches' linear forces K u
    PetscInt o;
    PetscCall(DMNetworkGetLocalVecOffset(a->dm, v, ALL_COMPONENTS, &o));
    for (PetscInt r = 0; r < op.n; ++r) {
      PetscScalar sum = 0;
      for (PetscInt k = op.rowptr[r]; k < op.rowptr[r + 1]; ++k) sum += op.vals[k] * xl[o + op.cols[k]];
      f[o + r] += sum;
    }
  }
  PetscCall(VecRestoreArrayRead(Xl, &xl));
  PetscCall(DMRestoreLocalVector(a->dm, &Xl));
  PetscCall(VecRestoreArray(Fl, &f));
  PetscCall(VecSet(F, 0.0));
  PetscCall(DMLocalToGlobalBegin(a->dm, Fl, ADD_VALUES, F));
  PetscCall(DMLocalToGlobalEnd(a->dm, Fl, ADD_VALUES, F));
  PetscCall(DMRestoreLocalVector(a->dm, &Fl));

  // Applied forces, then the constrained rows: r = u - lambda * value.
  PetscInt rstart;
  PetscCall(VecGetOwnershipRange(F, &rstart, nullptr));
  PetscCall(VecGetArray(F, &f));
  PetscCall(VecGetArrayRead(X, &x));
  for (size_t i = 0; i < a->force_rows.size(); ++i) f[a->force_rows[i] - rstart] -= a->lambda_target * a->force_values[i];
  for (size_t i = 0; i < a->dirichlet_rows.size(); ++i) {
    const PetscInt r = a->dirichlet_rows[i] - rstart;
    f[r]             = x[r] - a->lambda_target * a->dirichlet_values[i];
  }
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscCall(VecRestoreArray(F, &f));
  PetscFunctionReturn(0);
}

static PetscErrorCode AssemblyFormJacobianImpl(SNES snes, Vec X, Mat J, Mat P, void *ctx)
{
  BoltnetAssembly       a = static_cast<BoltnetAssembly>(ctx);
  std::vector<Response> resp;
  PetscFunctionBeginUser;
  PetscCall(AssemblyEvaluateJoints(a, X, resp));
  // Linear where it can be: the patches and seams are linear, so when no joint's tangent differs
  // (bit for bit) from the one in J, J is already this Jacobian. Leaving it untouched keeps its
  // object state, and PCSetUp then keeps the factorisation too.
  if (a->stuck_linear && J == P && P == a->J && a->jac_valid) {
    PetscMPIInt changed = 0, any;
    for (size_t k = 0; k < resp.size() && !changed; ++k) changed = std::memcmp(resp[k].tangent.data(), a->jac_tangent[k].data(), sizeof(Mat6)) != 0;
    PetscCallMPI(MPIU_Allreduce(&changed, &any, 1, MPI_INT, MPI_LOR, a->comm));
    if (!any) {
      ++a->jac_reused;
      PetscFunctionReturn(0);
    }
  }
  PetscCall(MatZeroEntries(P));
  for (size_t k = 0; k < a->jedges.size(); ++k) {
    EdgeView    ev;
    PetscInt    rows[12];
    PetscScalar vals[144];
    PetscCall(GetEdge(a->dm, a->jedges[k], &ev));
    PetscCall(GetEdgeGlobalRows(a->dm, ev, rows));
    const Mat6 K = GlobalTangent(ev.joint->R, resp[k].tangent);
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) {
        const double sign = ((i < 6) == (j < 6)) ? 1.0 : -1.0;
        vals[12 * i + j]  = sign * K[6 * (i % 6) + (j % 6)];
      }
    PetscCall(MatSetValues(P, 12, rows, 12, rows, vals, ADD_VALUES));
  }
  for (const auto &[e, Ks] : a->seam_ops) { // the seams' elements
    const Seam *seam;
    PetscInt    ga, gb, dofs[24];
    PetscCall(GetSeam(a, e, &seam));
    PetscCall(GetSeamOffsets(a, e, PETSC_TRUE, &ga, &gb));
    for (size_t k = 0; k < Ks.size(); ++k) {
      SeamElementDofs(seam->elems[k], ga, gb, dofs);
      PetscCall(MatSetValues(P, 24, dofs, 24, dofs, Ks[k].data(), ADD_VALUES));
    }
  }
  for (const auto &[v, op] : a->ops) { // the shell patches' stiffness
    PetscInt              goff;
    std::vector<PetscInt> cols;
    PetscCall(DMNetworkGetGlobalVecOffset(a->dm, v, ALL_COMPONENTS, &goff));
    for (PetscInt r = 0; r < op.n; ++r) {
      const PetscInt row = goff + r, b = op.rowptr[r], e = op.rowptr[r + 1];
      cols.resize(e - b);
      for (PetscInt k = b; k < e; ++k) cols[k - b] = goff + op.cols[k];
      PetscCall(MatSetValues(P, 1, &row, e - b, cols.data(), op.vals.data() + b, ADD_VALUES));
    }
  }
  PetscCall(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatZeroRows(P, (PetscInt)a->dirichlet_rows.size(), a->dirichlet_rows.data(), 1.0, nullptr, nullptr));
  PetscCall(MatNorm(P, NORM_INFINITY, &a->jnorm)); // the scale of round-off in K u (solver/stepper.cpp)
  ++a->jac_assembled;
  a->jac_valid = (P == a->J) ? PETSC_TRUE : PETSC_FALSE;
  a->jac_tangent.resize(resp.size());
  for (size_t k = 0; k < resp.size(); ++k) a->jac_tangent[k] = resp[k].tangent;
  if (J != P) {
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode AssemblyCountStateChangesImpl(SNES snes, Vec ref, Vec X, PetscInt *nchanged, void *ctx)
{
  BoltnetAssembly       a = static_cast<BoltnetAssembly>(ctx);
  std::vector<Response> r0, r1;
  PetscFunctionBeginUser;
  PetscCall(AssemblyEvaluateJoints(a, ref, r0));
  PetscCall(AssemblyEvaluateJoints(a, X, r1));
  PetscInt n = 0;
  for (size_t i = 0; i < r0.size(); ++i) n += (r0[i].state != r1[i].state) ? 1 : 0;
  PetscCall(MPIU_Allreduce(&n, nchanged, 1, MPIU_INT, MPI_SUM, a->comm));
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyStateCounts(BoltnetAssembly a, Vec X, PetscInt counts[5])
{
  std::vector<Response> r;
  PetscInt              loc[5] = {0, 0, 0, 0, 0};
  PetscFunctionBeginUser;
  PetscCall(AssemblyEvaluateJoints(a, X, r));
  for (const Response &x : r) loc[static_cast<int>(x.state)]++;
  PetscCall(MPIU_Allreduce(loc, counts, 5, MPIU_INT, MPI_SUM, a->comm));
  PetscFunctionReturn(0);
}

// The utilization (law.hpp) of every local joint at the given jumps, with its committed history.
static PetscErrorCode UtilizationAt(BoltnetAssembly a, const std::vector<Vec6> &jumps, std::vector<PetscReal> &util)
{
  PetscFunctionBeginUser;
  util.resize(a->jedges.size());
  for (size_t i = 0; i < a->jedges.size(); ++i) {
    EdgeView ev;
    PetscCall(GetEdge(a->dm, a->jedges[i], &ev));
    util[i] = utilization(ev.joint->params, a->committed[i], jumps[i]);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyCommit(BoltnetAssembly a, Vec X)
{
  PetscFunctionBeginUser;
  PetscCall(AssemblyEvaluateJoints(a, X, a->accepted, &a->accepted_jump, true));
  for (size_t i = 0; i < a->accepted.size(); ++i) a->committed[i] = a->accepted[i].trial;
  // Utilization with the new history, for the next step's choice of frozen joints.
  a->util_before = a->util_now;
  PetscCall(UtilizationAt(a, a->accepted_jump, a->util_now));
  if (!a->util_ready) a->util_before = a->util_now;
  a->util_ready = PETSC_TRUE;
  a->frozen.clear();
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyFreezeStuck(BoltnetAssembly a, PetscReal increment)
{
  PetscFunctionBeginUser;
  a->frozen.clear();
  if (!a->stuck_linear) PetscFunctionReturn(0);
  if (!a->util_ready) { // before the first step: at the initial state (collective: every rank)
    std::vector<Response> r;
    std::vector<Vec6>     du;
    PetscCall(AssemblyEvaluateJoints(a, a->X, r, &du, true));
    PetscCall(UtilizationAt(a, du, a->util_now));
    a->util_before = a->util_now;
    a->util_ready  = PETSC_TRUE;
  }
  // Predicted utilization at the end of the step: the last step's change, scaled to this increment.
  // Before the first converged step nothing is known of how the joints load: none is frozen (an
  // elastic predictor there releases most of them again, at the cost of Newton iterations).
  if (a->last_increment == 0) PetscFunctionReturn(0);
  const PetscReal ratio = std::abs(increment / a->last_increment);
  PetscInt        loc[2] = {0, (PetscInt)a->jedges.size()}, glob[2];
  a->frozen.assign(a->jedges.size(), 0);
  for (size_t i = 0; i < a->jedges.size(); ++i) {
    const PetscReal pred = a->util_now[i] + std::abs(a->util_now[i] - a->util_before[i]) * ratio;
    a->frozen[i]         = pred < a->stuck_margin;
    loc[0] += a->frozen[i];
  }
  PetscCall(MPIU_Allreduce(loc, glob, 2, MPIU_INT, MPI_SUM, a->comm));
  a->frozen_joint_steps += glob[0];
  a->joint_steps += glob[1];
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyReleaseUnstuck(BoltnetAssembly a, Vec X, PetscInt *nreleased)
{
  std::vector<Response> full;
  std::vector<Vec6>     du;
  PetscInt              n = 0;
  PetscFunctionBeginUser;
  PetscCall(AssemblyEvaluateJoints(a, X, full, &du, true)); // one ghost update; the frozen states below are local
  for (size_t i = 0; i < a->frozen.size(); ++i) {
    if (!a->frozen[i]) continue;
    EdgeView ev;
    PetscCall(GetEdge(a->dm, a->jedges[i], &ev));
    if (full[i].state != evaluate(ev.joint->params, a->committed[i], du[i], a->tangent, true).state) {
      a->frozen[i] = 0;
      ++n;
    }
  }
  PetscCall(MPIU_Allreduce(&n, nreleased, 1, MPIU_INT, MPI_SUM, a->comm));
  a->released += *nreleased;
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyGatherRecords(BoltnetAssembly a, std::vector<JointRecord> &records)
{
  std::vector<JointRecord> mine;
  PetscFunctionBeginUser;
  if (a->accepted.size() != a->jedges.size()) PetscCall(AssemblyEvaluateJoints(a, a->X, a->accepted, &a->accepted_jump, true)); // before the first step
  for (size_t k = 0; k < a->jedges.size(); ++k) {
    EdgeView ev;
    PetscCall(GetEdge(a->dm, a->jedges[k], &ev));
    const Response &re = a->accepted[k];
    const Vec6     &du = a->accepted_jump[k];
    JointRecord     rec{};
    rec.joint   = ev.joint->id;
    rec.state   = static_cast<PetscInt>(re.state);
    rec.bearing = re.bearing ? 1 : 0;
    for (int i = 0; i < 6; ++i) {
      rec.jump[i]  = du[i];
      rec.force[i] = re.force[i];
    }
    rec.slip[0] = re.trial.slip[0];
    rec.slip[1] = re.trial.slip[1];
    mine.push_back(rec);
  }

  PetscCall(GatherToZero(a->comm, mine, records));
  std::sort(records.begin(), records.end(), [](const JointRecord &l, const JointRecord &r) { return l.joint < r.joint; });
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyApplyDirichlet(BoltnetAssembly a, Vec X, PetscReal lambda)
{
  PetscScalar *x;
  PetscInt     rstart;
  PetscFunctionBeginUser;
  PetscCall(VecGetOwnershipRange(X, &rstart, nullptr));
  PetscCall(VecGetArray(X, &x));
  for (size_t i = 0; i < a->dirichlet_rows.size(); ++i) x[a->dirichlet_rows[i] - rstart] = lambda * a->dirichlet_values[i];
  PetscCall(VecRestoreArray(X, &x));
  PetscFunctionReturn(0);
}


PetscErrorCode AssemblyFormFunction(SNES snes, Vec X, Vec F, void *ctx)
{
  return Guard(PetscObjectComm((PetscObject)snes), [&] { return AssemblyFormFunctionImpl(snes, X, F, ctx); });
}

PetscErrorCode AssemblyFormJacobian(SNES snes, Vec X, Mat J, Mat P, void *ctx)
{
  return Guard(PetscObjectComm((PetscObject)snes), [&] { return AssemblyFormJacobianImpl(snes, X, J, P, ctx); });
}

PetscErrorCode AssemblyCountStateChanges(SNES snes, Vec ref, Vec X, PetscInt *nchanged, void *ctx)
{
  return Guard(PetscObjectComm((PetscObject)snes), [&] { return AssemblyCountStateChangesImpl(snes, ref, X, nchanged, ctx); });
}

} // namespace boltnet
