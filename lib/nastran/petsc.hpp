// The PETSc-facing side of the Nastran reader: a collective read (on every rank, or on rank 0
// alone) whose reader errors (file, line, field) become PETSc errors with the same message, and a
// viewer of the deck's summary.
#pragma once

#include "nastran/deck.hpp"

#include <petscviewer.h>

namespace boltnet {

/* NastranReadDeck - Reads a Nastran deck (nastran::ReadDeck) on every rank of comm. Collective.

   A reader error on any rank (the first such rank's message: file, line, card and field) is raised
   on every rank as a PETSc error (PETSC_ERR_USER_INPUT), so that no rank goes on alone. */
PetscErrorCode NastranReadDeck(MPI_Comm comm, const char path[], const nastran::ReadOptions &options, nastran::Deck *deck);

/* NastranReadDeckOnRank0 - The same, rank 0 alone reading the deck: the other ranks' deck is empty.
   Collective. The model the driver makes of it is rank 0's too, the other ranks receiving only
   what they lay out (io/nastran.cpp, patch/layout_steps.hpp). */
PetscErrorCode NastranReadDeckOnRank0(MPI_Comm comm, const char path[], const nastran::ReadOptions &options, nastran::Deck *deck);

/* NastranDeckView - Prints the deck's summary (nastran::Summary, docs/nastran.md) to an ASCII
   viewer (rank 0 of the viewer's communicator). */
PetscErrorCode NastranDeckView(const nastran::Deck &deck, PetscViewer viewer);

} // namespace boltnet
