static const char help[] = "nastran-summary: read a Nastran deck and print what boltnet makes of it.\n\
\n\
Counts of the cards used, the cards and case control commands not used (counted, never dropped),\n\
the reader's notes, the grids' bounding box, and per subcase the constraints and the load\n\
resultant. A malformed deck stops with a message naming the file, the line and the field.\n\
  nastran-summary -nastran_deck model.bdf [-nastran_allow_missing_properties]\n\
  mpiexec -n 2 nastran-summary -nastran_deck model.bdf   (every rank reads; rank 0 prints)\n\
Supported cards and formats: docs/nastran.md.\n\n";

#include "io/io.hpp"
#include "nastran/petsc.hpp"

#include <boltnet.h>
#include <petscsys.h>

using namespace boltnet;

namespace {

PetscErrorCode Run(int *exitcode)
{
  MPI_Comm  comm = PETSC_COMM_WORLD;
  char      path[PETSC_MAX_PATH_LEN] = "";
  PetscBool given = PETSC_FALSE, optionsLeft = PETSC_FALSE, help = PETSC_FALSE, missing = PETSC_FALSE;
  nastran::ReadOptions read;
  PetscFunctionBeginUser;
  PetscCall(BoltnetInitializePackage());
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-options_left", &optionsLeft, nullptr));
  PetscOptionsBegin(comm, "nastran_", "nastran-summary", "boltnet");
  PetscCall(PetscOptionsString("-deck", "Nastran input file (.bdf, .dat, .nas): executive and case control optional", "", path, path, sizeof(path), &given));
  PetscCall(PetscOptionsBool("-allow_missing_properties", "Keep shells whose PID is not a PSHELL or PCOMP (a mesh whose properties come from elsewhere), with a note", "", missing, &missing, nullptr));
  read.allow_missing_properties = missing;
  PetscOptionsEnd();
  PetscCall(PetscOptionsHasHelp(nullptr, &help));
  if (help) PetscFunctionReturn(0);
  PetscCheck(given, comm, PETSC_ERR_USER_INPUT, "No deck: give -nastran_deck <file>");
  nastran::Deck deck;
  PetscCall(NastranReadDeck(comm, path, read, &deck));
  PetscCall(NastranDeckView(deck, PETSC_VIEWER_STDOUT_(comm)));
  if (optionsLeft) PetscCall(UnusedOptionsAsError(comm, "nastran-summary", PETSC_FALSE, exitcode));
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv)
{
  int exitcode = 0;
  PetscCall(PetscInitialize(&argc, &argv, nullptr, help));
  PetscCall(Run(&exitcode));
  PetscCall(PetscFinalize());
  return exitcode;
}
