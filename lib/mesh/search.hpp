// A uniform grid over the nodes of a mesh, so that a fastener finds the nodes near it in time
// proportional to their number, not to the size of the part (a wing skin has hundreds of thousands
// of nodes and thousands of fasteners). Pure C++.
#pragma once

#include "mesh/mesh.hpp"

#include <array>
#include <unordered_map>
#include <vector>

namespace boltnet {

class NodeGrid {
public:
  // cell: the grid spacing (mm); about the radius of the queries is best.
  NodeGrid(const std::vector<std::array<double, 3>> &x, double cell);
  // Every node within the ball of radius r about p (3D distance), in increasing node order.
  std::vector<int> Ball(const std::array<double, 3> &p, double r) const;

private:
  using Key = std::array<long long, 3>;
  struct KeyHash {
    size_t operator()(const Key &k) const { return (size_t)(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL); }
  };
  Key CellOf(const std::array<double, 3> &p) const;
  const std::vector<std::array<double, 3>> &x_;
  double                                    h_;
  std::unordered_map<Key, std::vector<int>, KeyHash> cells_;
};

// The elements that touch each node (node -> element numbers, increasing).
std::vector<std::vector<int>> NodeElements(const ShellMesh &m);

// The footprint searches of mesh.hpp on one part, through a NodeGrid, and restricted to the sheet
// of the part nearest the fastener point along its axis: only nodes within `reach` of the point
// along the axis count, and of those only the ones within `radius` (the footprint radius) of the
// nearest. On a closed part (a fuselage barrel) the far side projects onto the footprint too; the
// brute-force functions of mesh.hpp would take it, these do not (docs/coupling.md).
class FootprintFinder {
public:
  FootprintFinder(const ShellMesh &m, double reach);
  std::vector<int> Footprint(const std::array<double, 3> &p, const std::array<double, 3> &axis, double radius) const;
  int              ContainingElement(const std::array<double, 3> &p, const std::array<double, 3> &axis) const;
  std::vector<int> CouplingFootprint(const std::array<double, 3> &p, const std::array<double, 3> &axis, double radius) const;
  int              NearestNode(const std::array<double, 3> &p, const std::array<double, 3> &axis) const;

private:
  // Nodes within in-plane distance r of p and within the reach along the axis, nearest sheet only.
  std::vector<int> Near(const std::array<double, 3> &p, const double n[3], double r, double sheet) const;
  const ShellMesh               &m_;
  double                        reach_, hmax_ = 0;
  NodeGrid                      grid_;
  std::vector<std::vector<int>> touching_;
};

} // namespace boltnet
