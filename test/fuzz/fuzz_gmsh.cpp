// Fuzz target: the Gmsh MSH 4.1 reader (mesh/gmsh.cpp). Any input either gives parts or is refused
// with a std::runtime_error; a part's quadrangles and node sets must name existing nodes.
#include "mesh/gmsh.hpp"

#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, size_t size)
{
  const std::string                     text(reinterpret_cast<const char *>(data), size);
  std::map<std::string, boltnet::QuadMesh> parts;
  try {
    parts = boltnet::ParseGmsh("fuzz.msh", text);
  } catch (const std::runtime_error &) {
    return 0;
  }
  for (const auto &[name, m] : parts) {
    if (m.quads.empty()) std::abort();
    for (const auto &q : m.quads)
      for (int n : q)
        if (n < 0 || (size_t)n >= m.x.size()) std::abort();
    for (const auto &[set, nodes] : m.node_sets)
      for (int n : nodes)
        if (n < 0 || (size_t)n >= m.x.size()) std::abort();
  }
  return 0;
}
