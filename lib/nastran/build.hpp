// The state of one ReadDeck while it runs: the deck being filled, the bulk data cards (kept until
// the references are checked, so that an error can name the field), and what only the resolution
// step can finish (GRDSET defaults, SPC1 and PLOAD4 THRU ranges). Internal to lib/nastran.
#pragma once

#include "nastran/fields.hpp"

#include <array>
#include <string>
#include <vector>

namespace boltnet::nastran {

struct Build {
  ReadOptions       options;
  Deck              deck;
  std::vector<Card> cards;

  struct GrdSet {
    bool   given = false;
    int    cp = 0, cd = 0;
    DofSet ps = 0;
  } grdset;
  std::vector<std::array<bool, 3>> grid_blank; // per grid: CP, CD, PS were blank (GRDSET applies)

  struct Spc1 {
    int                             sid = 0;
    DofSet                          dofs = 0;
    std::vector<int>                grids;  // listed one by one: must exist
    std::vector<std::array<int, 2>> ranges; // G1 THRU G2: grids that do not exist are skipped
    Source                          src;
  };
  std::vector<Spc1> spc1;

  struct Pload4 {
    Pressure proto;    // everything but the element
    int      eid1 = 0, eid2 = 0; // eid2 > eid1 for the THRU form
  };
  std::vector<Pload4> pload4;

  CardFields Fields(const Source &s) const { return CardFields(cards[s.card], deck.files); }
  void       Note(const Source &s, const std::string &what) { deck.notes.push_back(deck.Where(s) + ": " + what); }
  void       Unused(const std::string &name, const Source &s, const std::string &detail = "")
  {
    auto &u = deck.unused[name];
    if (u.count++ == 0) u.first = s;
    if (!detail.empty()) u.details.insert(detail);
  }
};

// Parses bulk data card number `index` of b.cards into b.deck (or counts it as unused).
void ParseBulkCard(Build &b, int index);
// The parsers of cards.cpp and connect.cpp: false if the name is not theirs.
bool ParseModelCard(const CardFields &c, Build &b, const Source &src);
bool ParseConnectionOrLoadCard(const CardFields &c, Build &b, const Source &src);
// Checks references and ids and resolves coordinates, element axes and ranges (resolve.cpp).
void Resolve(Build &b);

// Fails if any field from k on holds data (the card has more than it should).
void ExpectEnd(const CardFields &c, int k);

} // namespace boltnet::nastran
