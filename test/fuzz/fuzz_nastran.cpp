// Fuzz target: the Nastran bulk data reader (lib/nastran, docs/nastran.md). Any input either gives a
// deck or is refused with a nastran::Error naming where; another exception, a crash or a hang is a
// bug. The reader takes a path (INCLUDE is relative to the including file), so each input is written
// to a file of its own directory: an INCLUDE finds only that file (a cycle, refused) or nothing.
// A deck that is read must be consistent: every shell's nodes index existing grids.
#include "nastran/deck.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace {
std::string g_path; // the input's file, in a private directory made once per process
}

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
  char dir[] = "/tmp/boltnet-fuzz-nastran-XXXXXX";
  if (!mkdtemp(dir)) std::abort();
  g_path = std::string(dir) + "/fuzz.bdf";
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, size_t size)
{
  if (g_path.empty()) LLVMFuzzerInitialize(nullptr, nullptr);
  std::FILE *f = std::fopen(g_path.c_str(), "wb");
  if (!f) std::abort();
  if (size && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);
  boltnet::nastran::Deck deck;
  try {
    deck = boltnet::nastran::ReadDeck(g_path);
  } catch (const boltnet::nastran::Error &) {
    return 0;
  }
  for (const auto &s : deck.shells)
    for (int k = 0; k < s.Nodes(); ++k)
      if (s.node[k] < 0 || (size_t)s.node[k] >= deck.grids.size()) std::abort();
  return 0;
}
