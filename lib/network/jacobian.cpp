// The Jacobian of the network: its exact nonzero pattern, its near-null space, and its assembly.
#include "core/guard.hpp"
#include "core/log.hpp"
#include "network/internal.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

namespace boltnet {
namespace {

// Where a block of the Jacobian goes, in global dof: the assembled AIJ matrix (MatSetValues), or
// one rank's subdomain matrix of the MATIS (LocalInserter below).
using Inserter = std::function<PetscErrorCode(PetscInt, const PetscInt *, PetscInt, const PetscInt *, const PetscScalar *, InsertMode)>;

Inserter MatInserter(Mat M)
{
  return [M](PetscInt m, const PetscInt *r, PetscInt n, const PetscInt *c, const PetscScalar *v, InsertMode mode) { return MatSetValues(M, m, r, n, c, v, mode); };
}

// Seam element blocks: the rows of the nodes on each side (global dof), -1 elsewhere.
void SideRows(const Seam::Element &el, PetscInt ga, PetscInt gb, PetscInt rows[2][24], PetscInt idx[2][24], int n[2])
{
  n[0] = n[1] = 0;
  for (int k = 0; k < 4; ++k) {
    const int s = el.side[k];
    if (s < 0) continue;
    for (int i = 0; i < 6; ++i) {
      rows[s][n[s]] = (s ? gb : ga) + 6 * el.node[k] + i;
      idx[s][n[s]]  = 6 * k + i;
      n[s]++;
    }
  }
}

// The global offsets of the two vertices of seam edge e, and its seam.
PetscErrorCode SeamOf(BoltnetAssembly a, PetscInt e, const Seam **seam, PetscInt *oa, PetscInt *ob)
{
  SeamComp        sc;
  const PetscInt *cone;
  PetscFunctionBeginUser;
  PetscCall(NetworkComponent(a->net.dm, e, nullptr, &sc, sizeof sc));
  *seam = &a->layout.seams.at(sc.index);
  PetscCall(DMNetworkGetConnectedVertices(a->net.dm, e, &cone));
  PetscCall(DMNetworkGetGlobalVecOffset(a->net.dm, cone[0], ALL_COMPONENTS, oa));
  PetscCall(DMNetworkGetGlobalVecOffset(a->net.dm, cone[1], ALL_COMPONENTS, ob));
  PetscFunctionReturn(0);
}

// Add the blocks between the two sides of every element of an owned seam: (side 0 rows, side 1
// columns) and (side 1 rows, side 0 columns). The blocks within one side belong to the patches.
PetscErrorCode AddSeamBlocks(BoltnetAssembly a, const Inserter &M, bool values)
{
  PetscFunctionBeginUser;
  std::vector<PetscScalar> blk(24 * 24, 0.0);
  for (PetscInt e : a->net.sedges) {
    const Seam *seam = nullptr;
    PetscInt    ga, gb;
    PetscCall(SeamOf(a, e, &seam, &ga, &gb));
    const auto *Ks = values ? &a->patches.seam_ops.at(e) : nullptr;
    for (size_t k = 0; k < seam->elems.size(); ++k) {
      PetscInt rows[2][24], idx[2][24];
      int      n[2];
      SideRows(seam->elems[k], ga, gb, rows, idx, n);
      for (int s = 0; s < 2; ++s) {
        const int t = 1 - s;
        for (int i = 0; i < n[s]; ++i)
          for (int j = 0; j < n[t]; ++j) blk[(size_t)i * n[t] + j] = values ? (*Ks)[k][24 * idx[s][i] + idx[t][j]] : 0.0;
        PetscCall(M(n[s], rows[s], n[t], rows[t], blk.data(), values ? ADD_VALUES : INSERT_VALUES));
      }
    }
  }
  PetscFunctionReturn(0);
}

// Add the owned patches' operators (values false: zeros, for the pattern).
PetscErrorCode AddPatchBlocks(BoltnetAssembly a, const Inserter &M, bool values)
{
  PetscFunctionBeginUser;
  std::vector<PetscInt>    cols;
  std::vector<PetscScalar> z;
  for (const OwnedPatch &op : a->patches.owned) {
    if (!op.shell) continue;
    if (a->layout.shells.at(op.index).condensed) {
      const PetscInt nb = op.cond.nb;
      cols.resize(nb);
      for (PetscInt i = 0; i < nb; ++i) cols[i] = op.goff + i;
      if (!values) z.assign((size_t)nb * nb, 0.0);
      PetscCall(M(nb, cols.data(), nb, cols.data(), values ? op.cond.S.data() : z.data(), values ? ADD_VALUES : INSERT_VALUES));
      continue;
    }
    for (PetscInt r = 0; r < op.op.n; ++r) {
      const PetscInt row = op.goff + r, b = op.op.rowptr[r], e = op.op.rowptr[r + 1];
      cols.resize(e - b);
      for (PetscInt k = b; k < e; ++k) cols[k - b] = op.goff + op.op.cols[k];
      if (!values) z.assign(e - b, 0.0);
      PetscCall(M(1, &row, e - b, cols.data(), values ? op.op.vals.data() + b : z.data(), values ? ADD_VALUES : INSERT_VALUES));
    }
  }
  PetscFunctionReturn(0);
}

// The coordinates of every node an owned vertex carries (for the rigid-body modes).
void CarriedCoordinates(BoltnetAssembly a, std::vector<std::array<double, 3>> &x)
{
  x.clear();
  for (const OwnedPatch &op : a->patches.owned) {
    if (!op.shell) {
      const PatchComp &p = a->layout.patches[op.index];
      x.push_back({p.x[0], p.x[1], p.x[2]});
      continue;
    }
    const ShellPatch &sp    = a->layout.shells.at(op.index);
    const int         nmesh = (int)sp.mesh.x.size();
    for (int n : sp.carried) x.push_back(n < nmesh ? sp.mesh.x[n] : sp.joint_nodes[n - nmesh].x);
  }
}

// The six rigid-body modes (three translations, three rotations u = theta x (x - c), with the
// rotation dof set) of the nodes at x, 6 dof each in that order on this rank, orthonormalised, as
// a near-null space: what GAMG needs for 6-dof shell nodes (MatNullSpaceCreateRigidBody handles
// only block sizes 1-3; docs/architecture.md).
PetscErrorCode CreateRigidBodyModes(MPI_Comm comm, const std::vector<std::array<double, 3>> &x, MatNullSpace *nsp)
{
  Vec modes[6];
  PetscFunctionBeginUser;
  double c[3] = {0, 0, 0}, cg[3];
  double nloc = (double)x.size(), ng;
  for (const auto &p : x)
    for (int k = 0; k < 3; ++k) c[k] += p[k];
  PetscCallMPI(MPI_Allreduce(c, cg, 3, MPI_DOUBLE, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(&nloc, &ng, 1, MPI_DOUBLE, MPI_SUM, comm));
  for (int k = 0; k < 3; ++k) cg[k] /= ng > 0 ? ng : 1;
  for (int m = 0; m < 6; ++m) {
    PetscScalar *v;
    PetscCall(VecCreateMPI(comm, 6 * (PetscInt)x.size(), PETSC_DETERMINE, &modes[m]));
    PetscCall(VecSetBlockSize(modes[m], 6));
    PetscCall(VecGetArray(modes[m], &v));
    for (size_t n = 0; n < x.size(); ++n) {
      PetscScalar *u = v + 6 * n;
      for (int i = 0; i < 6; ++i) u[i] = 0;
      if (m < 3) u[m] = 1;
      else {
        const int    k    = m - 3;
        const double d[3] = {x[n][0] - cg[0], x[n][1] - cg[1], x[n][2] - cg[2]};
        const double e[3] = {k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0};
        u[0]              = e[1] * d[2] - e[2] * d[1];
        u[1]              = e[2] * d[0] - e[0] * d[2];
        u[2]              = e[0] * d[1] - e[1] * d[0];
        u[3 + k]          = 1;
      }
    }
    PetscCall(VecRestoreArray(modes[m], &v));
    for (int q = 0; q < m; ++q) { // modified Gram-Schmidt
      PetscScalar dot;
      PetscCall(VecDot(modes[m], modes[q], &dot));
      PetscCall(VecAXPY(modes[m], -dot, modes[q]));
    }
    PetscCall(VecNormalize(modes[m], nullptr));
  }
  PetscCall(MatNullSpaceCreate(comm, PETSC_FALSE, 6, modes, nsp));
  for (int m = 0; m < 6; ++m) PetscCall(VecDestroy(&modes[m]));
  PetscFunctionReturn(0);
}

// The rigid-body modes of every node the network carries as the Jacobian's near-null space.
PetscErrorCode SetRigidBodyModes(BoltnetAssembly a)
{
  std::vector<std::array<double, 3>> x;
  MatNullSpace                       nsp;
  PetscFunctionBeginUser;
  CarriedCoordinates(a, x);
  PetscCall(CreateRigidBodyModes(a->comm, x, &nsp));
  PetscCall(MatSetNearNullSpace(a->J, nsp));
  if (a->isolve.P) PetscCall(MatSetNearNullSpace(a->isolve.P, nsp));
  PetscCall(MatNullSpaceDestroy(&nsp));
  PetscFunctionReturn(0);
}

// This rank's subdomain of the MATIS (-interface_matis): the global nodes (6 dof each) that its
// joints, seams, patches and owned rows touch, sorted; global dof g is its local dof
// 6 * (position of g / 6) + g % 6. Blocks go into its local matrix in global dof.
Inserter LocalInserter(const std::vector<PetscInt> &nodes, Mat loc)
{
  return [&nodes, loc](PetscInt m, const PetscInt *r, PetscInt n, const PetscInt *c, const PetscScalar *v, InsertMode mode) -> PetscErrorCode {
    PetscFunctionBeginUser;
    auto local = [&nodes](PetscInt g) -> PetscInt {
      const auto it = std::lower_bound(nodes.begin(), nodes.end(), g / 6);
      return it != nodes.end() && *it == g / 6 ? 6 * (PetscInt)(it - nodes.begin()) + g % 6 : -1;
    };
    std::vector<PetscInt> lr(m), lc(n);
    for (PetscInt i = 0; i < m; ++i) PetscCheck((lr[i] = local(r[i])) >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "dof %" PetscInt_FMT " is not in this rank's subdomain", r[i]);
    for (PetscInt j = 0; j < n; ++j) PetscCheck((lc[j] = local(c[j])) >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "dof %" PetscInt_FMT " is not in this rank's subdomain", c[j]);
    PetscCall(MatSetValues(loc, m, lr.data(), n, lc.data(), v, mode));
    PetscFunctionReturn(0);
  };
}

// The rank's blocks of the linear part, and zeros where its joints and the diagonal go: the
// diagonal of its owned rows and of every node of its subdomain (nodes, once they are known),
// since MatZeroRows puts a Dirichlet row's diagonal into every subdomain that holds its dof.
PetscErrorCode AddSubdomainBlocks(BoltnetAssembly a, const Inserter &ins, bool values, InsertMode zeros_mode, const std::vector<PetscInt> &nodes)
{
  PetscScalar zeros[144] = {0};
  PetscInt    rstart, rend;
  PetscFunctionBeginUser;
  PetscCall(VecGetOwnershipRange(a->X, &rstart, &rend));
  for (const auto &rows : a->joints.rows) PetscCall(ins(12, rows.data(), 12, rows.data(), zeros, zeros_mode));
  for (PetscInt i = rstart; i < rend; ++i) PetscCall(ins(1, &i, 1, &i, zeros, zeros_mode));
  for (PetscInt node : nodes)
    for (PetscInt i = 6 * node; i < 6 * node + 6; ++i) PetscCall(ins(1, &i, 1, &i, zeros, zeros_mode));
  PetscCall(AddSeamBlocks(a, ins, values));
  PetscCall(AddPatchBlocks(a, ins, values));
  PetscFunctionReturn(0);
}

// The linear part of J as a MATIS (MatCreateIS), for PCBDDC (docs/solver.md, "BDDC"): one
// subdomain per rank, whose local matrix is the sum of the rank's own contributions, its patches
// (their condensed S or their whole operator), its seams' blocks and, at each Jacobian, its joints'
// blocks. Summed over the ranks that is J, entry for entry; unlike a MATIS converted from the AIJ J
// (MatConvert, which gives each rank its rows, not a subdomain's Neumann matrix), it is the
// unassembled operator BDDC's subdomain solves need.
PetscErrorCode CreateSubdomainMatrix(BoltnetAssembly a)
{
  std::vector<PetscInt> &nodes = a->isolve.subdomain_nodes;
  PetscInt               n;
  Mat                    pre, loc;
  ISLocalToGlobalMapping l2g;
  PetscFunctionBeginUser;
  nodes.clear();
  const Inserter collect = [&nodes](PetscInt m, const PetscInt *r, PetscInt k, const PetscInt *c, const PetscScalar *, InsertMode) -> PetscErrorCode {
    for (PetscInt i = 0; i < m; ++i) nodes.push_back(r[i] / 6);
    for (PetscInt j = 0; j < k; ++j) nodes.push_back(c[j] / 6);
    return PetscErrorCode(0);
  };
  PetscCall(AddSubdomainBlocks(a, collect, false, INSERT_VALUES, {}));
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  const PetscInt nl = 6 * (PetscInt)nodes.size();
  PetscCall(MatCreate(PETSC_COMM_SELF, &pre));
  PetscCall(MatSetType(pre, MATPREALLOCATOR));
  PetscCall(MatSetSizes(pre, nl, nl, nl, nl));
  PetscCall(MatSetBlockSize(pre, 6));
  PetscCall(MatSetUp(pre));
  PetscCall(AddSubdomainBlocks(a, LocalInserter(nodes, pre), false, INSERT_VALUES, nodes));
  PetscCall(MatAssemblyBegin(pre, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(pre, MAT_FINAL_ASSEMBLY));
  PetscCall(MatCreate(PETSC_COMM_SELF, &loc));
  PetscCall(MatSetType(loc, MATSEQAIJ));
  PetscCall(MatSetSizes(loc, nl, nl, nl, nl));
  PetscCall(MatSetBlockSize(loc, 6));
  PetscCall(MatPreallocatorPreallocate(pre, PETSC_TRUE, loc));
  PetscCall(MatDestroy(&pre));
  PetscCall(MatSetOption(loc, MAT_KEEP_NONZERO_PATTERN, PETSC_TRUE));
  PetscCall(MatSetOption(loc, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  PetscCall(AddSubdomainBlocks(a, LocalInserter(nodes, loc), true, ADD_VALUES, nodes));
  PetscCall(MatAssemblyBegin(loc, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(loc, MAT_FINAL_ASSEMBLY));
  PetscCall(VecGetLocalSize(a->X, &n));
  PetscCall(ISLocalToGlobalMappingCreate(a->comm, 6, (PetscInt)nodes.size(), nodes.data(), PETSC_COPY_VALUES, &l2g));
  PetscCall(MatCreateIS(a->comm, 6, n, n, PETSC_DETERMINE, PETSC_DETERMINE, l2g, l2g, &a->isolve.P));
  PetscCall(ISLocalToGlobalMappingDestroy(&l2g));
  PetscCall(MatISSetLocalMat(a->isolve.P, loc));
  PetscCall(MatDestroy(&loc));
  PetscCall(MatAssemblyBegin(a->isolve.P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(a->isolve.P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatDuplicate(a->isolve.P, MAT_COPY_VALUES, &a->isolve.Pbase));
  PetscFunctionReturn(0);
}

} // namespace

// The rows of exact coupling's slaves and the rest (the masters), for PCFIELDSPLIT on a Jacobian
// kept whole. A slave row holds c (u_s - T u_m) and the master rows hold T^T K T with no slave
// column (patch/patch.hpp), so J is block lower triangular in (masters, slaves): a multiplicative
// split solves it exactly given a solver of the master block, which is the symmetric stiffness
// with the footprints eliminated. The master split gets the rigid-body modes of its own nodes as
// near-null space (composed on its IS, which PCFIELDSPLIT gives its submatrix).
PetscErrorCode AssemblySetSlaveSplit(BoltnetAssembly a, PC pc)
{
  std::vector<std::array<double, 3>> x;
  std::vector<char>                  slave;
  PetscFunctionBeginUser;
  CarriedCoordinates(a, x);
  for (const OwnedPatch &op : a->patches.owned) {
    if (!op.shell) {
      slave.push_back(0);
      continue;
    }
    const ShellPatch &sp = a->layout.shells.at(op.index);
    std::vector<char> in_footprint(sp.mesh.x.size(), 0);
    if (!sp.condensed && a->opt.coupling_type == CouplingType::Exact)
      for (const auto &jn : sp.joint_nodes)
        for (int n : jn.footprint) in_footprint[n] = 1;
    for (int n : sp.carried) slave.push_back(n < (int)in_footprint.size() && in_footprint[n] ? 1 : 0);
  }
  PetscInt rstart, n;
  PetscCall(VecGetOwnershipRange(a->X, &rstart, nullptr));
  PetscCall(VecGetLocalSize(a->X, &n));
  PetscCheck((PetscInt)slave.size() * 6 == n, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%zu carried nodes for %" PetscInt_FMT " owned dof", slave.size(), n);
  std::vector<PetscInt> im, is;
  std::vector<size_t>   mnode;
  for (size_t k = 0; k < slave.size(); ++k) {
    auto &v = slave[k] ? is : im;
    for (int i = 0; i < 6; ++i) v.push_back(rstart + 6 * (PetscInt)k + i);
    if (!slave[k]) mnode.push_back(k);
  }
  PetscInt nslave = (PetscInt)is.size(), nslave_global;
  PetscCallMPI(MPI_Allreduce(&nslave, &nslave_global, 1, MPIU_INT, MPI_SUM, a->comm));
  // Node or penalty coupling, rigid patches alone, or every patch condensed: no slave rows, and
  // PCFIELDSPLIT's own splits of a DMNetwork fail with a message about the DM's set-up.
  PetscCheck(nslave_global, a->comm, PETSC_ERR_USER_INPUT, "-pc_type fieldsplit: this model has no slave rows to split off (-interface_slave_split needs shell patches kept whole, -patch_condense false, with -coupling_type exact); use -pc_type gamg, or PCFIELDSPLIT's own splits: -interface_slave_split false -pc_fieldsplit_dm_splits false -pc_fieldsplit_block_size 6");
  IS ism, iss;
  PetscCall(ISCreateGeneral(a->comm, (PetscInt)im.size(), im.data(), PETSC_COPY_VALUES, &ism));
  PetscCall(ISCreateGeneral(a->comm, (PetscInt)is.size(), is.data(), PETSC_COPY_VALUES, &iss));
  PetscCall(ISSetBlockSize(ism, 6));
  PetscCall(ISSetBlockSize(iss, 6));
  if (a->opt.near_null_space) {
    std::vector<std::array<double, 3>> xm;
    MatNullSpace                       nsp;
    xm.reserve(mnode.size());
    for (size_t k : mnode) xm.push_back(x[k]);
    PetscCall(CreateRigidBodyModes(a->comm, xm, &nsp));
    PetscCall(PetscObjectCompose((PetscObject)ism, "nearnullspace", (PetscObject)nsp));
    PetscCall(MatNullSpaceDestroy(&nsp));
  }
  PetscCall(PCFieldSplitSetIS(pc, "m", ism));
  PetscCall(PCFieldSplitSetIS(pc, "s", iss));
  PetscCall(ISDestroy(&ism));
  PetscCall(ISDestroy(&iss));
  PetscFunctionReturn(0);
}

// The Jacobian's nonzero pattern, counted exactly with MATPREALLOCATOR: each joint couples the 6
// dof of its node on patch a with those of its node on patch b (12 x 12), wherever the two
// vertices live; each owned patch contributes its own pattern (condensed: a dense block on its
// ports; a rigid patch: its diagonal), each seam its blocks between its two patches.
// DMNetwork's own user-block preallocation (DMNetworkHasJacobian + DMNetworkVertexSetMatrix) was
// tried first and, in PETSc 3.18.5, under-allocates couplings through edges owned by another rank
// ("new nonzero caused a malloc" inside DMCreateMatrix_Network on the chain scene at 2 ranks):
// docs/architecture.md.
PetscErrorCode AssemblyCreateJacobian(BoltnetAssembly a)
{
  Mat      pre;
  PetscInt n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(a->X, &n));
  PetscCall(MatCreate(a->comm, &pre));
  PetscCall(MatSetType(pre, MATPREALLOCATOR));
  PetscCall(MatSetSizes(pre, n, n, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetBlockSize(pre, 6));
  PetscCall(MatSetUp(pre));
  PetscScalar zeros[144] = {0};
  for (const auto &rows : a->joints.rows) PetscCall(MatSetValues(pre, 12, rows.data(), 12, rows.data(), zeros, INSERT_VALUES));
  PetscCall(AddSeamBlocks(a, MatInserter(pre), false));
  PetscInt rstart;
  PetscCall(VecGetOwnershipRange(a->X, &rstart, nullptr));
  for (PetscInt i = rstart; i < rstart + n; ++i) PetscCall(MatSetValue(pre, i, i, 0.0, INSERT_VALUES));
  PetscCall(AddPatchBlocks(a, MatInserter(pre), false));
  PetscCall(MatAssemblyBegin(pre, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(pre, MAT_FINAL_ASSEMBLY));
  PetscCall(MatCreate(a->comm, &a->J));
  PetscCall(MatSetType(a->J, MATAIJ));
  PetscCall(MatSetSizes(a->J, n, n, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetBlockSize(a->J, 6));
  PetscCall(MatPreallocatorPreallocate(pre, PETSC_TRUE, a->J));
  PetscCall(MatDestroy(&pre));
  PetscCall(MatSetOption(a->J, MAT_KEEP_NONZERO_PATTERN, PETSC_TRUE));
  PetscCall(MatSetOption(a->J, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  // The linear part, once: every patch and seam block, and zeros where the joints and the diagonal
  // go (so that the assembly keeps their places). Each Jacobian starts as a copy of it.
  for (const auto &rows : a->joints.rows) PetscCall(MatSetValues(a->J, 12, rows.data(), 12, rows.data(), zeros, ADD_VALUES));
  for (PetscInt i = rstart; i < rstart + n; ++i) PetscCall(MatSetValue(a->J, i, i, 0.0, ADD_VALUES));
  PetscCall(AddSeamBlocks(a, MatInserter(a->J), true));
  PetscCall(AddPatchBlocks(a, MatInserter(a->J), true));
  PetscCall(MatAssemblyBegin(a->J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(a->J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatDuplicate(a->J, MAT_COPY_VALUES, &a->Jbase));
  if (a->opt.matis) PetscCall(CreateSubdomainMatrix(a));
  // Jbase now holds the patch operators, the condensed S and the seam blocks: the residual
  // multiplies by it, so their own copies go (on a 5M-dof model a whole copy of the global matrix).
  for (OwnedPatch &op : a->patches.owned) {
    op.op = PatchOperator{};
    std::vector<double>().swap(op.cond.S);
  }
  a->patches.seam_ops.clear();
  if (a->opt.near_null_space) PetscCall(SetRigidBodyModes(a));
  PetscFunctionReturn(0);
}

// The lagged interface solve: keep the PC's factorisation of an earlier J while the Krylov solves
// it preconditions converge quickly; refactor when the last solve took more than
// -interface_refactor_its iterations or failed, and before the first solve. Joints that change
// state change J by a few rows: the preconditioned operator is then the identity plus a low-rank
// term, and Krylov converges in about that rank's iterations (docs/solver.md, "The interface
// solve"). The choice goes through SNES's lag of the preconditioner, which SNESComputeJacobian
// turns into KSPSetReusePreconditioner() after this function returns: -2 factors once, then -1
// keeps that factorisation until the next -2.
PetscErrorCode AssemblyLaggedFactorisation(BoltnetAssembly a)
{
  KSP                ksp;
  KSPConvergedReason reason;
  PetscInt           its;
  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(a->snes, &ksp));
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  PetscCall(KSPGetIterationNumber(ksp, &its));
  if (!a->isolve.factors_valid || reason < 0 || its > a->isolve.refactor_its) {
    PetscCall(SNESSetLagPreconditioner(a->snes, -2));
    a->isolve.factors_valid = PETSC_TRUE;
    ++a->isolve.factorisations;
  } else PetscCall(SNESSetLagPreconditioner(a->snes, -1));
  PetscFunctionReturn(0);
}

// A joint's state as the Jacobian sees it: stick, slide, contact, and whether it bears in its
// clearance (jointset.hpp's jac_state).
static char StateCode(const Response &r)
{
  return (char)((int)r.state + (r.bearing ? 8 : 0));
}

static PetscErrorCode AssemblyFormJacobianImpl(SNES snes, Vec X, Mat J, Mat P, void *ctx)
{
  BoltnetAssembly       a = static_cast<BoltnetAssembly>(ctx);
  JointSet             &js = a->joints;
  std::vector<Response> resp;
  PetscFunctionBeginUser;
  PetscCall(AssemblyEvaluateJoints(a, X, resp));
  PetscCall(PetscLogEventBegin(Events().jacobian, 0, 0, 0, 0));
  // How fast the solve converges: the residual against the last iteration's (modified Newton, below).
  PetscInt  it;
  PetscReal fnorm;
  PetscCall(SNESGetIterationNumber(snes, &it));
  PetscCall(SNESGetFunctionNorm(snes, &fnorm));
  const PetscReal ratio = it > 0 && it == a->isolve.keep_it + 1 && a->isolve.keep_fnorm > 0 ? fnorm / a->isolve.keep_fnorm : PETSC_MAX_REAL;
  const bool      fast  = a->isolve.keep_ratio > 0 && ratio <= a->isolve.keep_ratio;
  a->isolve.keep_it = it, a->isolve.keep_fnorm = fnorm;
  // Linear where it can be: the patches and seams are linear, so when no joint's tangent differs
  // (bit for bit) from the one in J, J is already this Jacobian. Leaving it untouched keeps its
  // object state, and PCSetUp then keeps the factorisation too.
  if (a->isolve.lagged && !a->isolve.lagged_ksp) PetscCall(AssemblyUseLaggedKSP(a)); // chosen by MUMPS's first analysis
  const bool own_pc = P == J || (a->isolve.P && P == a->isolve.P); // the preconditioner is built from J (or its MATIS)
  if (a->opt.stuck_linear && J == a->J && own_pc && js.jac_valid) {
    // Counted over all joints, for -info: how far the Jacobian is from the last one (a low-rank
    // update of a kept factorisation pays only when few joints change: docs/performance.md).
    PetscInt changed[2] = {0, (PetscInt)resp.size()}, total[2];
    for (size_t k = 0; k < resp.size(); ++k) changed[0] += std::memcmp(resp[k].tangent.data(), js.jac_tangent[k].data(), sizeof(Mat6)) != 0;
    PetscCallMPI(MPIU_Allreduce(changed, total, 2, MPIU_INT, MPI_SUM, a->comm));
    PetscCall(PetscInfo(snes, "%" PetscInt_FMT " of the %" PetscInt_FMT " joints' tangents differ from the last Jacobian's\n", total[0], total[1]));
    if (!total[0]) {
      ++js.jac_reused;
      // J is this iterate's Jacobian to the bit: it holds these states as much as the ones it was
      // assembled at. Recorded, so that a run restarted here (which assembles J afresh) keeps the
      // same factorisations below as the run that was not interrupted.
      js.jac_state.resize(resp.size());
      for (size_t k = 0; k < resp.size(); ++k) js.jac_state[k] = StateCode(resp[k]);
      if (a->isolve.lagged) PetscCall(AssemblyLaggedFactorisation(a));
      PetscCall(PetscLogEventEnd(Events().jacobian, 0, 0, 0, 0));
      PetscFunctionReturn(0);
    }
  }
  // Modified Newton: keep J and its factorisation from an earlier iterate of this solve while the
  // last iteration reduced the residual by keep_ratio and no joint changed state since J was
  // assembled. Only the bearing joints' contact directions (and sliding joints' tangents) have moved:
  // the step with the old factors then contracts about as fast as the factorisation saved is dear.
  if (fast && !a->isolve.lagged && J == a->J && own_pc && js.jac_valid && js.jac_state.size() == resp.size()) {
    PetscInt changed = 0, total;
    for (size_t k = 0; k < resp.size(); ++k) changed += js.jac_state[k] != StateCode(resp[k]);
    PetscCallMPI(MPIU_Allreduce(&changed, &total, 1, MPIU_INT, MPI_SUM, a->comm));
    if (!total) {
      ++a->isolve.kept;
      PetscCall(PetscInfo(snes, "Jacobian and factorisation kept at iteration %" PetscInt_FMT " (residual %g of the last)\n", it, (double)ratio));
      PetscCall(PetscLogEventEnd(Events().jacobian, 0, 0, 0, 0));
      PetscFunctionReturn(0);
    }
  }
  // J = the linear part (Jbase) + the joints. In the lagged interface solve the PC may keep the
  // factorisation of an earlier J: the Krylov solve on this J is preconditioned by it.
  // With -interface_matis, P is J's MATIS: a->J is assembled as always, and P from its linear
  // part (Pbase) and the same joint blocks, in this rank's subdomain.
  const bool matis = a->isolve.P && P == a->isolve.P;
  Mat        M     = matis ? a->J : P, Ploc = nullptr;
  PetscCall(MatCopy(a->Jbase, M, SAME_NONZERO_PATTERN));
  if (matis) {
    Mat Bloc;
    PetscCall(MatISGetLocalMat(a->isolve.Pbase, &Bloc));
    PetscCall(MatISGetLocalMat(P, &Ploc));
    PetscCall(MatCopy(Bloc, Ploc, SAME_NONZERO_PATTERN));
    PetscCall(MatISRestoreLocalMat(a->isolve.Pbase, &Bloc));
  }
  const Inserter subdomain = matis ? LocalInserter(a->isolve.subdomain_nodes, Ploc) : Inserter();
  for (size_t k = 0; k < js.size(); ++k) {
    PetscScalar vals[144];
    // In the joint plane (t1, t2), entries at round-off of the block's largest are zeros that the
    // law computed from a jump with a round-off component (a contact direction a hair off its
    // axis): kept, a direction with no stiffness (a mechanism) gets a row of round-off that
    // MUMPS's scaling blows up to an ordinary pivot, and the mechanism is no longer a null pivot.
    Mat6   T    = resp[k].tangent;
    double tmax = 0;
    for (int a = 1; a < 3; ++a)
      for (int b = 1; b < 3; ++b) tmax = std::max(tmax, std::fabs(T[6 * a + b]));
    for (int a = 1; a < 3; ++a)
      for (int b = 1; b < 3; ++b)
        if (std::fabs(T[6 * a + b]) <= 1e-13 * tmax) T[6 * a + b] = 0;
    const Mat6 K = GlobalTangent(js.comp[k].R, T);
    // In the dof of the two nodes: Ta^T K Ta, -Ta^T K Tb; -Tb^T K Ta, Tb^T K Tb (jointset.hpp).
    const Mat6 Ta = AttachmentMap(js.comp[k].da), Tb = AttachmentMap(js.comp[k].db);
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) {
        const Mat6  &Ti = i < 6 ? Ta : Tb, &Tj = j < 6 ? Ta : Tb;
        const double sign = ((i < 6) == (j < 6)) ? 1.0 : -1.0;
        double       v    = 0;
        for (int p = 0; p < 6; ++p)
          for (int q = 0; q < 6; ++q) v += Ti[6 * p + (i % 6)] * K[6 * p + q] * Tj[6 * q + (j % 6)];
        vals[12 * i + j] = sign * v;
      }
    PetscCall(MatSetValues(M, 12, js.rows[k].data(), 12, js.rows[k].data(), vals, ADD_VALUES));
    if (matis) PetscCall(subdomain(12, js.rows[k].data(), 12, js.rows[k].data(), vals, ADD_VALUES));
  }
  PetscCall(MatAssemblyBegin(M, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(M, MAT_FINAL_ASSEMBLY));
  PetscCall(MatZeroRows(M, (PetscInt)a->bc.dirichlet_rows.size(), a->bc.dirichlet_rows.data(), 1.0, nullptr, nullptr));
  if (matis) {
    PetscCall(MatISRestoreLocalMat(P, &Ploc));
    PetscCall(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY));
    PetscCall(MatZeroRows(P, (PetscInt)a->bc.dirichlet_rows.size(), a->bc.dirichlet_rows.data(), 1.0, nullptr, nullptr));
  }
  PetscCall(MatNorm(M, NORM_INFINITY, &a->checks.jnorm)); // the scale of round-off in K u (solver/stepper.cpp)
  if (a->checks.Jlast != M) { // the round-off test's |J| |x| is computed from M itself (solver/roundoff.hpp)
    PetscCall(PetscObjectReference((PetscObject)M));
    PetscCall(MatDestroy(&a->checks.Jlast));
    a->checks.Jlast = M;
  }
  ++js.jac_assembled;
  js.jac_valid = (M == a->J) ? PETSC_TRUE : PETSC_FALSE;
  js.jac_tangent.resize(resp.size());
  js.jac_state.resize(resp.size());
  for (size_t k = 0; k < resp.size(); ++k) {
    js.jac_tangent[k] = resp[k].tangent;
    js.jac_state[k]   = StateCode(resp[k]);
  }
  if (a->isolve.lagged) PetscCall(AssemblyLaggedFactorisation(a));
  else if (J != M) { // a J of SNES's own (-snes_mf_operator: matrix-free) is assembled here
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  }
  PetscCall(PetscLogEventEnd(Events().jacobian, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode AssemblyFormJacobian(SNES snes, Vec X, Mat J, Mat P, void *ctx)
{
  return Guard("AssemblyFormJacobian (SNES Jacobian)", [&] { return AssemblyFormJacobianImpl(snes, X, J, P, ctx); });
}

} // namespace boltnet
