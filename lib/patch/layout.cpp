// The layout (layout.hpp): the model checked, then its steps in order (layout_steps.hpp): the
// parts assigned to their holders and the joints sent to them, each part read, its joints attached
// and it cut into patches, and the records shared.
#include "patch/layout_steps.hpp"
#include "core/guard.hpp"
#include "io/limits.hpp"
#include "mesh/mesh.hpp"

#include <cmath>
#include <functional>
#include <set>

namespace boltnet {
namespace {

// The model's ids, references and supports, on rank 0, which holds every joint (the other ranks hold
// the same parts and conditions; the meshes are read later, each by one rank).
PetscErrorCode CheckModel(MPI_Comm comm, const Model &m)
{
  PetscFunctionBeginUser;
  const PetscInt npart = (PetscInt)m.parts.size(), njoint = (PetscInt)m.joints.size();
  PetscCheck(npart > 0 && njoint > 0, comm, PETSC_ERR_USER_INPUT, "The assembly needs at least one patch and one joint (it has %" PetscInt_FMT " patches, %" PetscInt_FMT " joints)", npart, njoint);
  std::map<PetscInt, PetscInt> index;
  for (PetscInt i = 0; i < npart; ++i) {
    PetscCheck(!index.count(m.parts[i].id), comm, PETSC_ERR_USER_INPUT, "Patch id %" PetscInt_FMT " is given twice", m.parts[i].id);
    index[m.parts[i].id] = i;
  }
  std::set<PetscInt>    seen;
  std::vector<PetscInt> degree(npart, 0), group(npart);
  for (const JointDesc &j : m.joints) {
    PetscCheck(!seen.count(j.id), comm, PETSC_ERR_USER_INPUT, "Joint id %" PetscInt_FMT " is given twice", j.id);
    seen.insert(j.id);
    auto ia = index.find(j.part_a), ib = index.find(j.part_b);
    PetscCheck(ia != index.end(), comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " names patch %" PetscInt_FMT " which does not exist", j.id, j.part_a);
    PetscCheck(ib != index.end(), comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " names patch %" PetscInt_FMT " which does not exist", j.id, j.part_b);
    PetscCheck(ia->second != ib->second, comm, PETSC_ERR_USER_INPUT, "Joint %" PetscInt_FMT " joins patch %" PetscInt_FMT " to itself", j.id, j.part_a);
    degree[ia->second]++;
    degree[ib->second]++;
  }
  for (PetscInt i = 0; i < npart; ++i) PetscCheck(degree[i] > 0, comm, PETSC_ERR_USER_INPUT, "Patch %" PetscInt_FMT " is not joined to anything: every patch needs at least one joint", m.parts[i].id);
  for (const BCDesc &bc : m.bcs) PetscCheck(index.count(bc.patch), comm, PETSC_ERR_USER_INPUT, "A boundary condition names patch %" PetscInt_FMT " which does not exist", bc.patch);
  // Every group of parts joined by joints needs a prescribed displacement somewhere, else it can
  // move as a rigid body and the model is singular. Partial supports are not checked here: the
  // factorisations report what is left.
  for (PetscInt i = 0; i < npart; ++i) group[i] = i;
  std::function<PetscInt(PetscInt)> root = [&](PetscInt i) { return group[i] == i ? i : group[i] = root(group[i]); };
  for (const JointDesc &j : m.joints) group[root(index[j.part_a])] = root(index[j.part_b]);
  std::vector<char> supported(npart, 0);
  for (const BCDesc &bc : m.bcs)
    if (bc.kind != BOLTNET_BC_FORCE && bc.kind != BOLTNET_BC_PRESSURE) supported[root(index[bc.patch])] = 1;
  std::string free;
  for (PetscInt i = 0; i < npart; ++i)
    if (!supported[root(i)]) free += (free.empty() ? "" : ", ") + std::to_string(m.parts[i].id);
  PetscCheck(free.empty(), comm, PETSC_ERR_USER_INPUT, "Patch(es) %s and the joints between them have no fixed or prescribed dof: the model is singular (a rigid-body motion); fix or prescribe a dof of one of them", free.c_str());
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode LayoutCreate(MPI_Comm comm, Model &m, const LayoutOptions &o, Layout *L)
{
  PetscMPIInt rank, size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(Collective(comm, "checking the model", [&]() { return rank == 0 ? CheckModel(comm, m) : PetscErrorCode(0); }));
  const PetscInt                 npart  = (PetscInt)m.parts.size();
  const std::vector<PetscMPIInt> holder = AssignParts(m, size);
  // From here m.joints is this rank's share, `all` rank 0's whole list (model/model.hpp).
  std::vector<JointDesc> all;
  std::vector<PetscInt>  jindex; // each joint of the share: its position in the model
  PetscInt               njoint = 0;
  PetscCall(ShareJoints(comm, holder, m, &all, &jindex, &njoint));
  PetscCall(Collective(comm, "sending rank 0's meshes", [&] { return SendRank0Meshes(comm, holder, m); }));

  // The shell parts this rank lays out, read (ShellPart::read) and checked, as patches before any
  // cut; of the others, what a stub needs.
  std::map<PetscInt, ShellPatch> parts, stubs;
  std::vector<std::int64_t>      meshnodes(npart, 0);
  PetscCall(Collective(comm, "reading the parts", [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    for (auto &[pos, sp] : m.shells) {
      ShellPatch p;
      p.id       = m.parts[pos].id;
      p.material = sp.material;
      p.drill    = sp.drill;
      if (holder[pos] != rank) {
        stubs[pos] = std::move(p);
        continue;
      }
      if (sp.read) PetscCall(sp.read(&sp.mesh));
      PetscCheck(!sp.mesh.elems.empty(), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Shell patch %" PetscInt_FMT ": a mesh needs at least one element", p.id);
      for (const BCDesc &bc : m.bcs) {
        if (bc.patch != p.id || bc.set.empty()) continue;
        PetscCheck(sp.mesh.node_sets.count(bc.set), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Boundary condition on patch %" PetscInt_FMT ": it has no node set '%s'", p.id, bc.set.c_str());
        PetscCheck(bc.kind != BOLTNET_BC_PRESSURE || HasElementIn(sp.mesh, bc.set), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Pressure on patch %" PetscInt_FMT ", node set '%s': no element has all its nodes in the set, so the pressure would load nothing (a pressure loads the elements within a node set: name a surface's nodes, not a curve's)", p.id, bc.set.c_str());
      }
      meshnodes[pos] = (std::int64_t)sp.mesh.x.size();
      p.mesh         = std::move(sp.mesh);
      parts[pos]     = std::move(p);
    }
    PetscFunctionReturn(0);
  }));
  m.shells.clear();
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, meshnodes.data(), (PetscMPIInt)npart, MPI_INT64_T, MPI_SUM, comm));
  std::int64_t mesh_nodes = 0;
  for (std::int64_t n : meshnodes) mesh_nodes += n;
  PetscCheck(mesh_nodes <= limits::kMaxSceneNodes, comm, PETSC_ERR_USER_INPUT, "The shell parts have %lld nodes, more than the limit of %lld (docs/scenes.md, \"Limits\")", (long long)mesh_nodes, (long long)limits::kMaxSceneNodes);
  {
    std::int64_t mine = 0;
    for (const auto &[pos, p] : parts) mine += meshnodes[pos];
    PetscCall(PetscInfo(nullptr, "Read and laid out %zu of %zu shell parts (%lld of %lld mesh nodes) on this rank\n", parts.size(), parts.size() + stubs.size(), (long long)mine, (long long)mesh_nodes));
  }
  const long max_nodes = o.max_nodes >= 0 ? o.max_nodes : AutomaticPatchSize(mesh_nodes, size, o.condense != Condense::None);

  // Attach the joints and cut the parts, each part into a layout of its own with patch positions
  // from 0. Only the holder of a part knows it: errors are raised on every rank (Collective).
  std::vector<PetscInt>                               jnode;
  std::map<PetscInt, Layout>                          cuts;
  std::vector<NodeMap>                                nodemap(npart);
  std::vector<PetscInt>                               count(2 * npart, 0); // patches, seams of each part
  PetscCall(Collective(comm, "laying out the parts", [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    for (auto &[pos, p] : parts)
      if (o.directors) p.mesh.directors = NodalDirectors(p.mesh); // empty on a flat part
    PetscCall(AttachJoints(comm, m, o, parts, jnode));
    for (auto &[pos, p] : parts) {
      Layout &one = cuts[pos];
      CutShellPart(std::move(p), 0, max_nodes, &one, nodemap[pos]);
      count[2 * pos]     = (PetscInt)one.shells.size();
      count[2 * pos + 1] = (PetscInt)one.seams.size();
    }
    PetscFunctionReturn(0);
  }));
  parts.clear();
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, count.data(), (PetscMPIInt)count.size(), MPIU_INT, MPI_SUM, comm));

  // Every part's first patch and seam, the same on every rank.
  *L            = Layout{};
  L->nparts     = npart;
  L->mesh_nodes = (PetscInt)mesh_nodes;
  std::vector<PetscInt> first(npart), sfirst(npart);
  PetscInt              npatch = 0, nseam = 0;
  for (PetscInt i = 0; i < npart; ++i) {
    const bool shell = m.parts[i].kind == PatchKind::Shell;
    first[i]         = npatch;
    sfirst[i]        = nseam;
    npatch += shell ? count[2 * i] : 1;
    nseam += shell ? count[2 * i + 1] : 0;
    for (PetscInt s = first[i]; s < npatch; ++s) {
      L->part_of.push_back(i);
      L->holder.push_back(shell ? holder[i] : -1);
    }
  }
  L->patches.assign(npatch, PatchComp{});
  L->seams.resize(nseam);
  for (PetscInt i = 0; i < npart; ++i) {
    if (m.parts[i].kind == PatchKind::Shell) continue;
    L->patches[first[i]] = PatchComp{m.parts[i].id, first[i], static_cast<PetscInt>(PatchKind::Rigid), 1, {m.parts[i].x[0], m.parts[i].x[1], m.parts[i].x[2]}};
    nodemap[i]           = {{first[i], 0}};
  }
  for (auto &[pos, one] : cuts) { // this rank's parts, placed
    for (auto &[k, sp] : one.shells) L->shells[first[pos] + k] = std::move(sp);
    for (size_t s = 0; s < one.seams.size(); ++s) {
      Seam &sm = one.seams[s];
      sm.va += first[pos];
      sm.vb += first[pos];
      L->seams[sfirst[pos] + s] = std::move(sm);
    }
    for (auto &kv : one.cut_parts) L->cut_parts[kv.first] = std::move(kv.second);
    for (auto &nm : nodemap[pos]) nm.first += first[pos];
  }
  cuts.clear();
  // The components of this rank's parts' joints, attached on the sides it holds; rank 0 also makes
  // one of every joint, whose shell sides ShareLayout fills from the holders' attachments.
  for (size_t k = 0; k < m.joints.size(); ++k) L->joints.push_back(MakeJointComp(m, o, m.joints[k], jindex[k], nodemap, &jnode[2 * k], *L));
  std::vector<JointComp> full;
  for (size_t ji = 0; ji < all.size(); ++ji) full.push_back(MakeJointComp(m, o, all[ji], (PetscInt)ji, nodemap, nullptr, *L));
  std::vector<JointDesc>().swap(all);
  L->njoints = njoint;
  Carry(L, o);
  PetscCall(ShareLayout(comm, stubs, std::move(full), L));
  PetscFunctionReturn(0);
}

bool CondensePatchPays(PetscInt nb, PetscInt n, double ratio)
{
  return (double)nb <= ratio * std::sqrt((double)n);
}

std::vector<PetscInt> LayoutEdgeList(const Layout &L)
{
  std::vector<PetscInt> e;
  e.reserve(2 * (L.joints.size() + L.seams.size()));
  for (const JointComp &j : L.joints) e.insert(e.end(), {j.va, j.vb});
  for (const Seam &s : L.seams) e.insert(e.end(), {s.va, s.vb});
  return e;
}

} // namespace boltnet
