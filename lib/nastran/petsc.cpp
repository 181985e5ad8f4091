// The PETSc-facing wrapper of the Nastran reader (petsc.hpp).
#include "nastran/petsc.hpp"

#include "nastran/report.hpp"

#include <climits>
#include <string>

namespace boltnet {

namespace {
// Reads the deck on every rank (everyone) or on rank 0 alone, the others' left empty; the first
// failing rank's message is raised on every rank.
PetscErrorCode ReadDeckOn(MPI_Comm comm, const char path[], const nastran::ReadOptions &options, bool everyone, nastran::Deck *deck)
{
  std::string message;
  PetscMPIInt rank, first, failed;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  *deck = nastran::Deck{};
  if (everyone || rank == 0) {
    try {
      *deck = nastran::ReadDeck(path, options);
    } catch (const nastran::Error &e) {
      message = e.what();
    } catch (const std::exception &e) {
      message = std::string("Reading the Nastran deck '") + path + "': " + e.what();
    }
  }
  failed = message.empty() ? INT_MAX : rank;
  PetscCallMPI(MPI_Allreduce(&failed, &first, 1, MPI_INT, MPI_MIN, comm));
  if (first == INT_MAX) {
    if (!everyone && rank == 0) PetscCall(PetscInfo(nullptr, "Read the Nastran deck '%s' on this rank alone\n", path));
    PetscFunctionReturn(0);
  }
  PetscMPIInt length = static_cast<PetscMPIInt>(message.size());
  PetscCallMPI(MPI_Bcast(&length, 1, MPI_INT, first, comm));
  message.resize(length);
  PetscCallMPI(MPI_Bcast(message.data(), length, MPI_CHAR, first, comm));
  SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s", message.c_str());
}
} // namespace

PetscErrorCode NastranReadDeck(MPI_Comm comm, const char path[], const nastran::ReadOptions &options, nastran::Deck *deck)
{
  return ReadDeckOn(comm, path, options, true, deck);
}

PetscErrorCode NastranReadDeckOnRank0(MPI_Comm comm, const char path[], const nastran::ReadOptions &options, nastran::Deck *deck)
{
  return ReadDeckOn(comm, path, options, false, deck);
}

PetscErrorCode NastranDeckView(const nastran::Deck &deck, PetscViewer viewer)
{
  PetscBool ascii;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(viewer), PETSCVIEWERASCII, &ascii));
  PetscCheck(ascii, PetscObjectComm(reinterpret_cast<PetscObject>(viewer)), PETSC_ERR_SUP, "The Nastran deck summary needs an ASCII viewer");
  std::string text;
  try {
    text = nastran::Summary(deck);
  } catch (const std::exception &e) {
    SETERRQ(PetscObjectComm(reinterpret_cast<PetscObject>(viewer)), PETSC_ERR_USER_INPUT, "%s", e.what());
  }
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s", text.c_str()));
  PetscFunctionReturn(0);
}

} // namespace boltnet
