// Shell sections from PSHELL and PCOMP (docs/nastran.md, "What each card becomes"): the resultant
// stiffness A, B, D, H of lib/shell in the material axes. Pure C++; throws nastran::Error for a
// combination boltnet's shell element cannot represent.
#pragma once

#include "nastran/deck.hpp"
#include "shell/shell.hpp"

#include <string>
#include <vector>

namespace boltnet::nastran {

// The section of property `pid` (a PSHELL or PCOMP of the deck) at thickness `t` (PSHELL only;
// NaN: the property's T). Assumptions that change the model (MID3 blank, MAT8 G1Z/G2Z blank) are
// appended to notes.
shell::ShellMaterial SectionOf(const Deck &deck, int pid, double t, std::vector<std::string> &notes);

// The section about a reference plane moved by d along the normal (z_new = z_old - d), as a PCOMP
// Z0 or an element ZOFFS does: A' = A, B' = B - d A, D' = D - 2 d B + d^2 A.
shell::ShellMaterial Offset(const shell::ShellMaterial &m, double d);

} // namespace boltnet::nastran
