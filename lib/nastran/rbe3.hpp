// RBE3 as a load distribution (docs/nastran.md, "RBE3"). Pure C++; throws nastran::Error naming the
// card.
//
// Nastran's RBE3 (Quick Reference Guide, RBE3) makes the components REFC of REFGRID the weighted
// least-squares average of the components Ci of the grids Gi,j: with v = (u, theta) the rigid motion
// of REFGRID and s_k = (d_k, r_k x d_k) for independent component k (direction d_k, grid offset
// r_k = x_k - x_ref, weight w_k), v solves A v = sum w_k s_k u_k, A = sum w_k s_k s_k^T. It adds no
// stiffness. By virtual work a load P = (F, M) on REFGRID acts on the independent components as
// f_k = w_k s_k . A^-1 P, which keeps the resultant and its moment: sum f_k s_k = P.
//
// boltnet uses an RBE3 this way only: REFGRID must be connected to nothing but the RBE3 (Rbe3ByRefgrid
// checks that) and the loads on it are moved to the independent grids here.
#pragma once

#include "nastran/deck.hpp"
#include "nastran/expand.hpp"

#include <map>
#include <string>
#include <vector>

namespace boltnet::nastran {

// What boltnet supports of the card itself: translational independent components (Ci within 123,
// any subset, per group, in each grid's displacement system), no UM, REFGRID not among its own
// independent grids, and independent components that can carry every component REFC (Nastran's
// remark: the Ci at the Gi,j must react the rigid-body motion of REFC; collinear grids with
// translations only cannot carry a moment about their line). Throws naming the card and its place.
void CheckRbe3(const Deck &deck, const Rbe3 &rbe3);

// The forces at the independent grids (basic system, one entry per grid, sorted by grid index) that
// stand for `force` and `moment` (basic) on REFGRID. A load component that REFC does not contain
// (in REFGRID's displacement system) is refused: Nastran leaves it on REFGRID, which boltnet does
// not model. `subcase` only names the subcase in that message.
std::vector<NodalLoad> DistributeRbe3(const Deck &deck, const Rbe3 &rbe3, const Vec3 &force, const Vec3 &moment, int subcase);

// Every RBE3 of the deck checked (CheckRbe3) and keyed by its REFGRID's grid index, once its REFGRID
// is known to be connected to nothing else: no shell (on_shell, per grid index), no CBUSH, no RBE2,
// no other RBE3 (as REFGRID or independent grid), and in `subcase` no SPC or GRID PS on a REFC
// component (Nastran refuses a constraint on a dependent component). Throws naming both cards.
std::map<int, const Rbe3 *> Rbe3ByRefgrid(const Deck &deck, const std::vector<bool> &on_shell, const std::vector<Constraint> &spc, const Subcase &subcase);

// Replaces the loads on REFGRIDs in `nodal` (sorted by grid index, as ExpandLoad gives them) by
// their RBE3's forces at the independent grids, summed per grid; notes each load moved.
void MoveRbe3Loads(const Deck &deck, const std::map<int, const Rbe3 *> &by_refgrid, int subcase, std::vector<NodalLoad> &nodal, std::vector<std::string> &notes);

} // namespace boltnet::nastran
