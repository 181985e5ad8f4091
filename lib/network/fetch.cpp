// The whole patches and seams a rank needs, sent by the ranks that laid them out (patch/layout.hpp):
// after DMNetworkDistribute a rank owns vertices and edges whose parts another rank may hold.
#include "core/guard.hpp"
#include "network/internal.hpp"
#include "patch/pack.hpp"

#include <climits>
#include <set>

namespace boltnet {
namespace {

// What a rank asks of a holder: a patch (by position), a seam (by index) or a cut part's whole mesh
// (by the position of its first patch).
enum Item : PetscInt { kPatch = 0, kSeam = 1, kCutPart = 2 };

// MPI counts are int: a message of more than 2 GB would need splitting, and is refused instead.
PetscErrorCode CheckCount(MPI_Comm comm, std::size_t n)
{
  PetscFunctionBeginUser;
  PetscCheck(n <= (std::size_t)INT_MAX, comm, PETSC_ERR_SUP, "The layout a rank sends another is %zu bytes, more than an MPI message of int count can carry; run on more ranks", n);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode AssemblyFetchLayout(BoltnetAssembly a)
{
  Layout             &L = a->layout;
  const PetscMPIInt   size = a->size, rank = a->rank;
  std::set<PetscInt>  patches, seams, cuts;
  PetscFunctionBeginUser;
  // What this rank needs: the shell patches and the seams it owns; with keep_layout, everything (the
  // gathering writer reads every patch's mesh on rank 0). A joint needs nothing of its patches'
  // meshes past the layout: its component carries its attachment nodes and points.
  for (const OwnedPatch &op : a->patches.owned)
    if (op.shell) patches.insert(op.index);
  for (PetscInt e : a->net.sedges) {
    SeamComp sc;
    PetscCall(NetworkComponent(a->net.dm, e, nullptr, &sc, sizeof sc));
    seams.insert(sc.index);
  }
  if (a->opt.keep_layout) {
    for (size_t p = 0; p < L.patches.size(); ++p)
      if (L.holder[p] >= 0) patches.insert((PetscInt)p);
    for (size_t s = 0; s < L.seams.size(); ++s) seams.insert((PetscInt)s);
    for (size_t p = 0; p < L.patches.size(); ++p) // a cut part: its first patch stands for it
      if (L.holder[p] >= 0 && (p == 0 || L.part_of[p - 1] != L.part_of[p]) && p + 1 < L.patches.size() && L.part_of[p + 1] == L.part_of[p]) cuts.insert((PetscInt)p);
  }
  std::vector<std::vector<PetscInt>> ask(size);
  for (PetscInt p : patches)
    if (L.holder[p] != rank) ask[L.holder[p]].insert(ask[L.holder[p]].end(), {kPatch, p});
  for (PetscInt s : seams) {
    const PetscMPIInt h = L.holder[L.seams[s].va];
    if (h != rank) ask[h].insert(ask[h].end(), {kSeam, s});
  }
  for (PetscInt p : cuts)
    if (L.holder[p] != rank) ask[L.holder[p]].insert(ask[L.holder[p]].end(), {kCutPart, p});

  // The requests, then the answers, each in one all-to-all exchange.
  std::vector<int> nask(size), ngot(size), askoff(size + 1, 0), gotoff(size + 1, 0);
  std::vector<PetscInt> asked;
  for (PetscMPIInt r = 0; r < size; ++r) {
    nask[r]       = (int)ask[r].size();
    askoff[r + 1] = askoff[r] + nask[r];
    asked.insert(asked.end(), ask[r].begin(), ask[r].end());
  }
  PetscCallMPI(MPI_Alltoall(nask.data(), 1, MPI_INT, ngot.data(), 1, MPI_INT, a->comm));
  for (PetscMPIInt r = 0; r < size; ++r) gotoff[r + 1] = gotoff[r] + ngot[r];
  std::vector<PetscInt> wanted(gotoff[size]);
  PetscCallMPI(MPI_Alltoallv(asked.data(), nask.data(), askoff.data(), MPIU_INT, wanted.data(), ngot.data(), gotoff.data(), MPIU_INT, a->comm));

  std::vector<char> out;
  std::vector<int>  nout(size), outoff(size + 1, 0), nin(size), inoff(size + 1, 0);
  PetscCall(Collective(a->comm, "sending the layout", [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PackWriter w(out);
    for (PetscMPIInt r = 0; r < size; ++r) {
      const std::size_t start = out.size();
      for (int i = gotoff[r]; i < gotoff[r + 1]; i += 2) {
        const PetscInt what = wanted[i], k = wanted[i + 1];
        if (what == kPatch) Pack(w, L.shells.at(k));
        else if (what == kSeam) Pack(w, L.seams.at(k));
        else Pack(w, L.cut_parts.at(L.patches.at(k).id));
      }
      PetscCall(CheckCount(PETSC_COMM_SELF, out.size()));
      nout[r]       = (int)(out.size() - start);
      outoff[r + 1] = (int)out.size();
    }
    PetscFunctionReturn(0);
  }));
  PetscCallMPI(MPI_Alltoall(nout.data(), 1, MPI_INT, nin.data(), 1, MPI_INT, a->comm));
  std::size_t total = 0;
  for (PetscMPIInt r = 0; r < size; ++r) total += (std::size_t)nin[r];
  PetscCall(CheckCount(a->comm, total));
  for (PetscMPIInt r = 0; r < size; ++r) inoff[r + 1] = inoff[r] + nin[r];
  std::vector<char> in(total);
  PetscCallMPI(MPI_Alltoallv(out.data(), nout.data(), outoff.data(), MPI_CHAR, in.data(), nin.data(), inoff.data(), MPI_CHAR, a->comm));
  std::vector<char>().swap(out);

  PetscCall(Collective(a->comm, "receiving the layout", [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PackReader rd(in.data(), in.size());
    for (PetscInt i = 0; i < (PetscInt)asked.size(); i += 2) {
      const PetscInt what = asked[i], k = asked[i + 1];
      if (what == kPatch) Unpack(rd, L.shells[k]);
      else if (what == kSeam) Unpack(rd, L.seams[k]);
      else Unpack(rd, L.cut_parts[L.patches[k].id]);
    }
    PetscCheck(rd.Done(), PETSC_COMM_SELF, PETSC_ERR_PLIB, "The layout received has bytes left over");
    PetscFunctionReturn(0);
  }));
  PetscFunctionReturn(0);
}

} // namespace boltnet
