#include "partition/balance.hpp"

#include <metis.h>

#include <algorithm>
#include <map>

namespace boltnet {

PetscErrorCode SetPatchPartition(DM dm, const std::vector<PetscInt> &weights, const std::vector<PetscInt> &edgelist)
{
  DM               plex;
  PetscPartitioner part;
  PetscMPIInt      rank, size;
  MPI_Comm         comm;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)dm, &comm));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  const PetscInt        ne = (PetscInt)edgelist.size() / 2;
  std::vector<PetscInt> sizes(size, 0), points;
  int                   status = METIS_OK;
  if (rank == 0) {
    idx_t                               nv = (idx_t)weights.size(), ncon = 1, nparts = size, objval;
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
      vwgt[u] = (idx_t)weights[u];
    }
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_SEED]      = 1; // the same partition on every run
    options[METIS_OPTION_NUMBERING] = 0;
    if (nv > nparts) status = METIS_PartGraphKway(&nv, &ncon, xadj.data(), adjncy.data(), vwgt.data(), nullptr, adjwgt.data(), &nparts, nullptr, nullptr, options, &objval, vpart.data());
    else
      for (idx_t u = 0; u < nv; ++u) vpart[u] = u; // no more patches than ranks: one each
    std::vector<std::vector<PetscInt>> byRank(size);
    for (PetscInt e = 0; e < ne; ++e) byRank[std::min(vpart[edgelist[2 * e]], vpart[edgelist[2 * e + 1]])].push_back(e);
    for (PetscMPIInt r = 0; r < size; ++r) {
      sizes[r] = (PetscInt)byRank[r].size();
      points.insert(points.end(), byRank[r].begin(), byRank[r].end());
    }
  }
  PetscCallMPI(MPI_Bcast(&status, 1, MPI_INT, 0, comm));
  PetscCheck(status == METIS_OK, comm, PETSC_ERR_LIB, "METIS failed to partition the network (status %d)", status);
  PetscCall(DMNetworkGetPlex(dm, &plex));
  PetscCall(DMPlexGetPartitioner(plex, &part));
  PetscCall(PetscPartitionerSetType(part, PETSCPARTITIONERSHELL));
  PetscCall(PetscPartitionerShellSetPartition(part, size, sizes.data(), points.data()));
  PetscFunctionReturn(0);
}

} // namespace boltnet
