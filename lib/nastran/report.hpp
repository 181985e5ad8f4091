// A readable summary of a deck (docs/nastran.md, "The summary"): files, cards used and their
// counts, cards and case control commands not used, notes, the grids' bounding box, and per
// subcase the constraints and the load resultant. Pure C++.
#pragma once

#include "nastran/deck.hpp"

#include <string>

namespace boltnet::nastran {

struct Box {
  Vec3 lo{}, hi{};
  bool empty = true;
};
Box BoundingBox(const Deck &deck); // of the grids, basic system

std::string Summary(const Deck &deck);

} // namespace boltnet::nastran
