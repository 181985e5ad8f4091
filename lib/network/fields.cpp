// The assembly's results where they live (network/fields.hpp): the natural numbering of nodes,
// elements and joints, the owned-to-natural scatters, and each converged step's displacements,
// element results and joint lines on the rank that owns them.
#include "network/fields.hpp"
#include "core/guard.hpp"
#include "core/log.hpp"
#include "network/internal.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace boltnet {
namespace {

constexpr int kXdmfQuadrilateral = 5, kXdmfTriangle = 4; // XDMF cell type codes

// The elements a patch writes, each element of a part exactly once over its patches: the patch's
// whole elements, and of the elements it shares with other patches (ShellPatch::SharedElement, one
// copy in every patch holding one of its nodes) those whose node 0 it holds: exactly one patch holds
// any node. f(element number in the part, the patch's node numbers (-1: another patch's, or past a
// triangle's third), the part's node numbers (-1 past a triangle's third), the geometry and
// directors the stiffness uses). This is the only code that enumerates output elements.
template <class F>
void ElementsOf(const ShellPatch &sp, F &&f)
{
  const auto partNode = [&](int l) { return sp.part_node.empty() ? l : sp.part_node[l]; };
  for (size_t e = 0; e < sp.mesh.elems.size(); ++e) {
    const MeshElement &q  = sp.mesh.elems[e];
    const int          nn = ElementNodes(q);
    std::array<int, 4> pn{-1, -1, -1, -1};
    for (int k = 0; k < nn; ++k) pn[k] = partNode(q[k]);
    f(sp.part_elem.empty() ? (int)e : sp.part_elem[e], q, pn, GeometryOf(sp.mesh, q));
  }
  for (const auto &el : sp.shared)
    if (el.node[0] >= 0) f(el.elem, el.node, el.part_node, el.geom);
}

PetscErrorCode CreateVec(MPI_Comm comm, PetscInt n, PetscInt N, PetscInt bs, Vec *v)
{
  PetscFunctionBeginUser;
  PetscCall(VecCreate(comm, v));
  PetscCall(VecSetSizes(*v, bs * n, bs * N));
  PetscCall(VecSetBlockSize(*v, bs));
  PetscCall(VecSetType(*v, VECSTANDARD));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode FieldSpaceSetUp(MPI_Comm comm, FieldSpace &s)
{
  PetscFunctionBeginUser;
  s.nlocal = (PetscInt)s.natural.size();
  s.start  = 0;
  PetscCallMPI(MPI_Exscan(&s.nlocal, &s.start, 1, MPIU_INT, MPI_SUM, comm));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) s.start = 0; // MPI_Exscan leaves rank 0's result undefined
  PetscCall(MPIU_Allreduce(&s.nlocal, &s.nglobal, 1, MPIU_INT, MPI_SUM, comm));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldSpaceDestroy(FieldSpace &s)
{
  PetscFunctionBeginUser;
  for (auto &kv : s.scatter) PetscCall(VecScatterDestroy(&kv.second));
  for (auto &kv : s.vecs)
    for (Vec &v : kv.second) PetscCall(VecDestroy(&v));
  s = FieldSpace{};
  PetscFunctionReturn(0);
}

PetscErrorCode FieldSpaceRelease(FieldSpace &s, PetscInt bs)
{
  PetscFunctionBeginUser;
  auto sc = s.scatter.find(bs);
  if (sc != s.scatter.end()) {
    PetscCall(VecScatterDestroy(&sc->second));
    s.scatter.erase(sc);
  }
  auto v = s.vecs.find(bs);
  if (v != s.vecs.end()) {
    for (Vec &x : v->second) PetscCall(VecDestroy(&x));
    s.vecs.erase(v);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FieldMapCreate(BoltnetAssembly a, FieldMap *m)
{
  MPI_Comm comm = a->comm;
  PetscFunctionBeginUser;
  std::set<PetscInt> ids;
  for (const PatchComp &p : a->layout.patches)
    if (p.kind == static_cast<PetscInt>(PatchKind::Shell)) ids.insert(p.id);
  m->part_ids.assign(ids.begin(), ids.end());
  const size_t np = m->part_ids.size();
  auto         where = [&](PetscInt id) { return (size_t)(std::lower_bound(m->part_ids.begin(), m->part_ids.end(), id) - m->part_ids.begin()); };
  // Part-wise counts of what this rank holds, summed over ranks: the offsets of the natural numbering.
  std::vector<PetscInt> count(2 * np, 0), total(2 * np, 0);
  for (const OwnedPatch &op : a->patches.owned) {
    if (!op.shell) continue;
    const ShellPatch &sp = a->layout.shells.at(op.index);
    count[2 * where(sp.id)] += (PetscInt)sp.mesh.x.size();
    ElementsOf(sp, [&](int, const std::array<int, 4> &, const std::array<int, 4> &, const ElementGeometry &) { count[2 * where(sp.id) + 1]++; });
  }
  PetscCall(MPIU_Allreduce(count.data(), total.data(), (PetscMPIInt)(2 * np), MPIU_INT, MPI_SUM, comm));
  PetscInt noff = 0, eoff = 0;
  for (size_t i = 0; i < np; ++i) {
    m->node_off[m->part_ids[i]] = noff;
    m->elem_off[m->part_ids[i]] = eoff;
    noff += total[2 * i];
    eoff += total[2 * i + 1];
  }
  std::set<PetscInt> ghosts;
  for (size_t i = 0; i < a->patches.owned.size(); ++i) {
    const OwnedPatch &op = a->patches.owned[i];
    if (!op.shell) continue;
    const ShellPatch &sp = a->layout.shells.at(op.index);
    const PetscInt    n0 = m->node_off.at(sp.id), e0 = m->elem_off.at(sp.id);
    for (size_t l = 0; l < sp.mesh.x.size(); ++l) {
      m->nodes.natural.push_back(n0 + (sp.part_node.empty() ? (PetscInt)l : sp.part_node[l]));
      m->node_src.push_back({(PetscInt)i, (PetscInt)l});
    }
    ElementsOf(sp, [&](int elem, const std::array<int, 4> &local, const std::array<int, 4> &pn, const ElementGeometry &g) {
      FieldElement fe{sp.id, elem, (PetscInt)i, g.n == 4 ? kXdmfQuadrilateral : kXdmfTriangle, g.n, {-1, -1, -1, -1}, local, g};
      for (int k = 0; k < g.n; ++k) {
        fe.node[k] = n0 + pn[k];
        if (local[k] < 0) ghosts.insert(fe.node[k]);
      }
      m->elems.natural.push_back(e0 + elem);
      m->elements.push_back(fe);
    });
  }
  for (size_t k = 0; k < a->joints.size(); ++k) m->joints.natural.push_back(a->joints.comp[k].index);
  PetscCall(FieldSpaceSetUp(comm, m->nodes));
  PetscCall(FieldSpaceSetUp(comm, m->elems));
  PetscCall(FieldSpaceSetUp(comm, m->joints));
  PetscInt tri = 0;
  for (const FieldElement &e : m->elements) tri += e.nn == 3;
  PetscCall(MPIU_Allreduce(&tri, &m->ntriangles, 1, MPIU_INT, MPI_SUM, comm));
  PetscCheck(m->nodes.nglobal == noff && m->elems.nglobal == eoff && m->joints.nglobal == a->layout.njoints, comm, PETSC_ERR_PLIB, "The output numbering does not cover the model once");
  // The other patches' nodes of the shared elements this rank writes, from the natural vectors.
  m->ghosts.assign(ghosts.begin(), ghosts.end());
  for (size_t g = 0; g < m->ghosts.size(); ++g) m->ghost_index[m->ghosts[g]] = (PetscInt)g;
  {
    const PetscInt ng = (PetscInt)m->ghosts.size();
    Vec            nat;
    IS             from, to;
    PetscCall(CreateVec(comm, m->nodes.nlocal, m->nodes.nglobal, 6, &nat));
    PetscCall(VecCreateSeq(PETSC_COMM_SELF, 6 * ng, &m->ghost_dof));
    PetscCall(ISCreateBlock(PETSC_COMM_SELF, 6, ng, m->ghosts.data(), PETSC_COPY_VALUES, &from));
    PetscCall(ISCreateStride(PETSC_COMM_SELF, 6 * ng, 0, 1, &to));
    PetscCall(VecScatterCreate(nat, from, m->ghost_dof, to, &m->ghost_scatter));
    PetscCall(ISDestroy(&from));
    PetscCall(ISDestroy(&to));
    PetscCall(VecDestroy(&nat));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FieldMapDestroy(FieldMap *m)
{
  PetscFunctionBeginUser;
  for (FieldSpace *s : {&m->nodes, &m->elems, &m->joints}) PetscCall(FieldSpaceDestroy(*s));
  PetscCall(VecScatterDestroy(&m->ghost_scatter));
  PetscCall(VecDestroy(&m->ghost_dof));
  PetscCall(VecScatterDestroy(&m->bypass_scatter));
  PetscCall(VecDestroy(&m->bypass_sums));
  PetscCall(VecDestroy(&m->bypass_local));
  PetscCall(VecScatterDestroy(&m->bypass_force_scatter));
  PetscCall(VecDestroy(&m->bypass_force));
  PetscCall(VecDestroy(&m->bypass_force_local));
  PetscCall(VecDestroy(&m->bypass_reach));
  PetscCall(VecDestroy(&m->bypass_reach_local));
  *m = FieldMap{};
  PetscFunctionReturn(0);
}

PetscErrorCode FieldSpaceNatural(MPI_Comm comm, FieldSpace &s, PetscInt bs, const std::vector<double> &owned, Vec *natural)
{
  PetscFunctionBeginUser;
  PetscCheck((PetscInt)owned.size() == bs * s.nlocal, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%zu values for %" PetscInt_FMT " items of block size %" PetscInt_FMT, owned.size(), s.nlocal, bs);
  auto &v = s.vecs[bs];
  if (!v[0]) PetscCall(CreateVec(comm, s.nlocal, s.nglobal, bs, &v[0]));
  if (!v[1]) PetscCall(CreateVec(comm, s.nlocal, s.nglobal, bs, &v[1]));
  if (!s.scatter[bs]) {
    IS from, to;
    PetscCall(ISCreateStride(PETSC_COMM_SELF, bs * s.nlocal, bs * s.start, 1, &from));
    PetscCall(ISCreateBlock(PETSC_COMM_SELF, bs, s.nlocal, s.natural.data(), PETSC_COPY_VALUES, &to));
    PetscCall(VecScatterCreate(v[0], from, v[1], to, &s.scatter[bs]));
    PetscCall(ISDestroy(&from));
    PetscCall(ISDestroy(&to));
  }
  PetscScalar *p;
  PetscCall(VecGetArray(v[0], &p));
  std::copy(owned.begin(), owned.end(), p);
  PetscCall(VecRestoreArray(v[0], &p));
  PetscCall(VecScatterBegin(s.scatter[bs], v[0], v[1], INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(s.scatter[bs], v[0], v[1], INSERT_VALUES, SCATTER_FORWARD));
  *natural = v[1];
  PetscFunctionReturn(0);
}

PetscErrorCode FieldSpaceColumns(FieldSpace &s, Vec packed, PetscInt K, PetscInt first, PetscInt bs, Vec *out)
{
  PetscFunctionBeginUser;
  if (K == bs) {
    *out = packed;
    PetscFunctionReturn(0);
  }
  Vec &v = s.vecs[bs][1];
  if (!v) { // the first time for this block size: every rank gets here in the same order
    MPI_Comm comm;
    PetscCall(PetscObjectGetComm((PetscObject)packed, &comm));
    PetscCall(CreateVec(comm, s.nlocal, s.nglobal, bs, &v));
  }
  const PetscScalar *p;
  PetscScalar       *q;
  PetscCall(VecGetArrayRead(packed, &p));
  PetscCall(VecGetArray(v, &q));
  for (PetscInt i = 0; i < s.nlocal; ++i)
    for (PetscInt c = 0; c < bs; ++c) q[bs * i + c] = p[K * i + first + c];
  PetscCall(VecRestoreArray(v, &q));
  PetscCall(VecRestoreArrayRead(packed, &p));
  *out = v;
  PetscFunctionReturn(0);
}

namespace {

// A triangle's nodes and directors in the shell element's types.
std::pair<shell::TriNodes, shell::TriDirectors> TriangleOf(const ElementGeometry &g)
{
  shell::TriNodes     X;
  shell::TriDirectors V;
  std::copy(g.X.begin(), g.X.begin() + 3, X.begin());
  std::copy(g.V.begin(), g.V.begin() + 3, V.begin());
  return {X, V};
}

shell::ElementOptions OptionsOf(double drill)
{
  shell::ElementOptions o;
  o.drill = drill; // the options of the patch operator (ElementMatrixOf, patch/operator.cpp)
  return o;
}

} // namespace

shell::SectionResults ElementResultsOf(const ElementGeometry &g, const shell::ShellMaterial &mat, double drill, const shell::ElementVector &u,
                                       const shell::CondensedModes *kept)
{
  const shell::ElementOptions o = OptionsOf(drill);
  if (g.n == 4) return shell::ElementResults(g.X, g.directors ? &g.V : nullptr, mat, o, u, kept);
  const auto       [X, V] = TriangleOf(g);
  shell::TriVector ut;
  std::copy(u.begin(), u.begin() + 18, ut.begin());
  return shell::ElementResults(X, g.directors ? &V : nullptr, mat, o, ut, kept);
}

shell::CondensedModes CondensedModesOf(const ElementGeometry &g, const shell::ShellMaterial &mat, double drill)
{
  const shell::ElementOptions o = OptionsOf(drill);
  if (g.n == 4) return shell::ElementCondensedModes(g.X, g.directors ? &g.V : nullptr, mat, o);
  const auto [X, V] = TriangleOf(g);
  return shell::ElementCondensedModes(X, g.directors ? &V : nullptr, mat, o);
}

std::array<shell::Vec3, 3> ElementAxesOf(const ElementGeometry &g)
{
  if (g.n == 4) {
    const shell::ElementFrame f = shell::MakeElementFrame(g.X);
    return {f.e1, f.e2, f.e3};
  }
  const shell::TriFrame f = shell::MakeElementFrame(shell::TriNodes{g.X[0], g.X[1], g.X[2]});
  return {f.e1, f.e2, f.e3};
}

double ElementArea(const ElementGeometry &g)
{
  // Half the cross product of the diagonals (a flat quadrilateral) or of two sides (a triangle).
  std::array<double, 3> d1, d2;
  for (int c = 0; c < 3; ++c) {
    d1[c] = g.X[2][c] - g.X[0][c];
    d2[c] = g.n == 4 ? g.X[3][c] - g.X[1][c] : g.X[1][c] - g.X[0][c];
  }
  return 0.5 * std::sqrt(std::pow(d1[1] * d2[2] - d1[2] * d2[1], 2) + std::pow(d1[2] * d2[0] - d1[0] * d2[2], 2) + std::pow(d1[0] * d2[1] - d1[1] * d2[0], 2));
}

const shell::ShellMaterial &FieldElementMaterial(BoltnetAssembly a, const FieldElement &e)
{
  return a->layout.shells.at(a->patches.owned[e.owned].index).material;
}

PetscErrorCode AssemblyStepFields(BoltnetAssembly a, FieldMap &m, bool results, bool keep_modes, StepFields *f)
{
  Vec                Xl;
  const PetscScalar *x;
  PetscFunctionBeginUser;
  f->dof.clear();
  f->dof_natural = nullptr;
  f->results.clear();
  f->lines.clear();
  // Before the first step the joints have no accepted response yet (as AssemblyGatherRecords).
  JointSet &js      = a->joints;
  PetscInt  missing = js.accepted.size() != js.size(), any;
  PetscCall(MPIU_Allreduce(&missing, &any, 1, MPIU_INT, MPI_MAX, a->comm));
  if (any) PetscCall(AssemblyEvaluateJoints(a, a->X, js.accepted, &js.accepted_jump, true));
  PetscCall(GetLocalX(a, a->X, &Xl, &x));
  std::map<PetscInt, std::vector<double>> disp; // by position in the owned patches
  for (size_t i = 0; i < a->patches.owned.size(); ++i)
    if (a->patches.owned[i].shell) PetscCall(AssemblyPatchDisplacement(a, a->patches.owned[i], x, a->lambda, disp[(PetscInt)i]));
  f->dof.reserve(6 * m.node_src.size());
  for (const auto &[i, l] : m.node_src) f->dof.insert(f->dof.end(), disp[i].data() + 6 * l, disp[i].data() + 6 * l + 6);
  for (size_t k = 0; k < js.size(); ++k) {
    const JointComp &j  = js.comp[k];
    const Response  &re = js.accepted[k];
    JointLine        l{};
    l.id      = j.id;
    l.state   = static_cast<PetscInt>(re.state);
    l.bearing = re.bearing ? 1 : 0;
    l.xa      = {j.pa[0], j.pa[1], j.pa[2]};
    l.xb      = {j.pb[0], j.pb[1], j.pb[2]};
    std::copy(x + js.oa[k], x + js.oa[k] + 6, l.ua.begin());
    std::copy(x + js.ob[k], x + js.ob[k] + 6, l.ub.begin());
    std::copy(j.R, j.R + 9, l.R.begin());
    for (int i = 0; i < 6; ++i) {
      l.jump[i]  = js.accepted_jump[k][i];
      l.force[i] = re.force[i];
    }
    l.slip = {re.trial.slip[0], re.trial.slip[1]};
    f->lines.push_back(l);
  }
  PetscCall(RestoreLocalX(a, &Xl, &x));
  if (!results) PetscFunctionReturn(0);
  // The other patches' nodes of the shared elements: through the natural vectors.
  PetscCall(FieldSpaceNatural(a->comm, m.nodes, 6, f->dof, &f->dof_natural)); // the writer's too
  PetscCall(VecScatterBegin(m.ghost_scatter, f->dof_natural, m.ghost_dof, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(m.ghost_scatter, f->dof_natural, m.ghost_dof, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar *gd;
  PetscCall(VecGetArrayRead(m.ghost_dof, &gd));
  PetscCall(PetscLogEventBegin(Events().element_results, 0, 0, 0, 0));
  PetscCall(Collective(a->comm, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    // The elements do not change between steps: their condensed modes, most of the results' work,
    // are computed once when they are to be kept.
    if (keep_modes && m.modes.size() != m.elements.size()) {
      m.modes.clear();
      m.modes.reserve(m.elements.size());
      for (const FieldElement &e : m.elements) {
        const ShellPatch &sp = a->layout.shells.at(a->patches.owned[e.owned].index);
        m.modes.push_back(CondensedModesOf(e.geom, sp.material, sp.drill));
      }
    }
    f->results.reserve(m.elements.size());
    for (size_t i = 0; i < m.elements.size(); ++i) {
      const FieldElement  &e = m.elements[i];
      const double        *d = disp[e.owned].data();
      shell::ElementVector ue{};
      for (int k = 0; k < e.nn; ++k) {
        const PetscInt g = e.local[k] < 0 ? m.ghost_index.at(e.node[k]) : -1;
        for (int c = 0; c < 6; ++c) ue[6 * k + c] = g < 0 ? d[6 * e.local[k] + c] : gd[6 * g + c];
      }
      const ShellPatch &sp = a->layout.shells.at(a->patches.owned[e.owned].index);
      f->results.push_back(ElementResultsOf(e.geom, sp.material, sp.drill, ue, keep_modes ? &m.modes[i] : nullptr));
    }
    PetscFunctionReturn(0);
  }));
  PetscCall(PetscLogEventEnd(Events().element_results, 0, 0, 0, 0));
  PetscCall(VecRestoreArrayRead(m.ghost_dof, &gd));
  PetscFunctionReturn(0);
}

} // namespace boltnet

using namespace boltnet;

// Collective. The owner of the element (the rank whose patch writes it, ElementsOf) broadcasts its
// nodes' numbers in the part, coordinates and section; every rank adds the dof of those nodes that
// its own patches hold; every rank then evaluates the element. Costs a pass over the part's
// patches on this rank: for a whole model's results read fields.h5.
PetscErrorCode BoltnetAssemblyGetElementResult(BoltnetAssembly a, PetscInt part, PetscInt element, BoltnetFrame frame, BoltnetElementResult *out)
{
  struct Owned {
    std::array<int, 4>   pn;
    ElementGeometry      geom;
    shell::ShellMaterial material;
    double               drill;
  } el{};
  PetscFunctionBeginUser;
  PetscCheck(a->net.dm, a->comm, PETSC_ERR_ORDER, "Call BoltnetAssemblySetUp() first");
  PetscCheck(frame == BOLTNET_FRAME_ELEMENT || frame == BOLTNET_FRAME_MATERIAL, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "Unknown frame %d (BOLTNET_FRAME_ELEMENT or BOLTNET_FRAME_MATERIAL)", (int)frame);
  PetscMPIInt found = -1, owner;
  bool        shellPart = false;
  for (const OwnedPatch &op : a->patches.owned) {
    if (!op.shell || a->layout.patches[op.index].id != part) continue;
    const ShellPatch &sp = a->layout.shells.at(op.index);
    ElementsOf(sp, [&](int elem, const std::array<int, 4> &, const std::array<int, 4> &pn, const ElementGeometry &g) {
      if (elem != element) return;
      el     = Owned{pn, g, sp.material, sp.drill};
      found  = a->rank;
    });
  }
  for (const PatchComp &p : a->layout.patches) shellPart = shellPart || (p.id == part && p.kind == static_cast<PetscInt>(PatchKind::Shell));
  PetscCheck(shellPart, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "No shell patch with id %" PetscInt_FMT, part);
  PetscCallMPI(MPI_Allreduce(&found, &owner, 1, MPI_INT, MPI_MAX, a->comm));
  PetscCheck(owner >= 0, a->comm, PETSC_ERR_ARG_OUTOFRANGE, "Shell patch %" PetscInt_FMT " has no element %" PetscInt_FMT, part, element);
  PetscCallMPI(MPI_Bcast(&el, sizeof el, MPI_BYTE, owner, a->comm));
  PetscReal          loc[28] = {0}, glob[28];
  Vec                Xl;
  const PetscScalar *x;
  PetscCall(GetLocalX(a, a->X, &Xl, &x));
  PetscCall(Collective(a->comm, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    for (const OwnedPatch &op : a->patches.owned) {
      if (!op.shell || a->layout.patches[op.index].id != part) continue;
      const ShellPatch   &sp = a->layout.shells.at(op.index);
      std::vector<double> u;
      for (int k = 0; k < el.geom.n; ++k) {
        int l = el.pn[k];
        if (!sp.part_node.empty()) l = (int)(std::find(sp.part_node.begin(), sp.part_node.end(), el.pn[k]) - sp.part_node.begin());
        if (l < 0 || l >= (int)sp.mesh.x.size()) continue;
        if (u.empty()) PetscCall(AssemblyPatchDisplacement(a, op, x, a->lambda, u));
        for (int c = 0; c < 6; ++c) loc[6 * k + c] = u[6 * l + c];
        loc[24 + k] += 1;
      }
    }
    PetscFunctionReturn(0);
  }));
  PetscCall(RestoreLocalX(a, &Xl, &x));
  PetscCall(MPIU_Allreduce(loc, glob, 28, MPIU_REAL, MPIU_SUM, a->comm));
  for (int k = 0; k < el.geom.n; ++k) PetscCheck(glob[24 + k] == 1, a->comm, PETSC_ERR_PLIB, "Node %d of element %" PetscInt_FMT " of patch %" PetscInt_FMT " is held %g times", el.pn[k], element, part, (double)glob[24 + k]);
  shell::SectionResults r;
  PetscCall(Guard(a->comm, [&] {
    shell::ElementVector ue;
    std::copy(glob, glob + 24, ue.begin());
    r = ElementResultsOf(el.geom, el.material, el.drill, ue);
    if (frame == BOLTNET_FRAME_MATERIAL) r = shell::Rotated(r, shell::MaterialAngle(r, el.material));
    return PetscErrorCode(0);
  }));
  for (int c = 0; c < 3; ++c) {
    out->axes[c] = r.e1[c], out->axes[3 + c] = r.e2[c], out->axes[6 + c] = r.e3[c];
    out->N[c] = r.N[c], out->M[c] = r.M[c];
    out->strain_top[c] = r.strain_top[c], out->strain_bottom[c] = r.strain_bottom[c];
    out->stress_top[c] = r.stress_top[c], out->stress_bottom[c] = r.stress_bottom[c];
  }
  out->Q[0] = r.Q[0], out->Q[1] = r.Q[1];
  out->homogeneous      = r.homogeneous ? PETSC_TRUE : PETSC_FALSE;
  out->von_mises_top    = shell::VonMises(r.stress_top);
  out->von_mises_bottom = shell::VonMises(r.stress_bottom);
  PetscFunctionReturn(0);
}
