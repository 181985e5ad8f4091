// Fuzz target: the Gmsh MSH 4.1 reader (mesh/gmsh.cpp). Any input either gives parts or is refused
// with a std::runtime_error; a part's triangles and quadrangles (three or four distinct nodes, a
// triangle's fourth -1) and node sets must name existing nodes.
#include "mesh/gmsh.hpp"

#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, size_t size)
{
  const std::string                         text(reinterpret_cast<const char *>(data), size);
  std::map<std::string, boltnet::ShellMesh> parts;
  try {
    parts = boltnet::ParseGmsh("fuzz.msh", text);
  } catch (const std::runtime_error &) {
    return 0;
  }
  for (const auto &[name, m] : parts) {
    if (m.elems.empty()) std::abort();
    for (const auto &q : m.elems) {
      const int nn = boltnet::ElementNodes(q);
      for (int k = 0; k < nn; ++k) {
        if (q[k] < 0 || (size_t)q[k] >= m.x.size()) std::abort();
        for (int j = 0; j < k; ++j)
          if (q[j] == q[k]) std::abort();
      }
    }
    for (const auto &[set, nodes] : m.node_sets)
      for (int n : nodes)
        if (n < 0 || (size_t)n >= m.x.size()) std::abort();
  }
  return 0;
}
