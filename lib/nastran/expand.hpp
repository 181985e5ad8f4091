// A subcase's constraints and loads, expanded from the deck's sets (SPCADD, SPC, SPC1, GRID PS;
// LOAD, FORCE, MOMENT, PLOAD4) into per-grid and per-element lists, the form a boltnet scene needs.
// Pure C++; throws nastran::Error.
#pragma once

#include "nastran/deck.hpp"

#include <array>
#include <vector>

namespace boltnet::nastran {

// Constrained components of one grid, in the grid's displacement system (Grid::cd_axes), with the
// enforced values (0 unless an SPC gives one).
struct Constraint {
  int                   node = -1; // index into Deck::grids
  DofSet                dofs = 0;
  std::array<double, 6> value{};
};

// SPC set `sid` (an SPCADD or an SPC/SPC1 set; 0: none) plus every grid's permanent constraints
// (GRID PS), merged per grid and sorted by grid index. A component given two different enforced
// values throws.
std::vector<Constraint> ExpandSpc(const Deck &deck, int sid);

struct NodalLoad {
  int  node = -1;
  Vec3 force{}, moment{}; // basic system
};
struct ShellPressure {
  int                   shell = -1; // index into Deck::shells
  std::array<double, 4> p{};        // scaled corner pressures
  bool                  has_direction = false;
  Vec3                  direction{}; // unit, basic (when has_direction)
};
struct StaticLoad {
  std::vector<NodalLoad>     nodal;     // FORCE and MOMENT summed per grid, sorted by grid index
  std::vector<ShellPressure> pressures; // PLOAD4, one per card and element
};

// Load set `sid` (a LOAD combination: S * sum Si Li, or a FORCE/MOMENT/PLOAD4 set; 0: none).
StaticLoad ExpandLoad(const Deck &deck, int sid);

// Total force and moment about the basic origin of a load (pressures integrated exactly over the
// bilinear quadrilateral and the linear triangle).
struct Resultant {
  Vec3 force{}, moment{};
};
Resultant LoadResultant(const Deck &deck, const StaticLoad &load);

} // namespace boltnet::nastran
