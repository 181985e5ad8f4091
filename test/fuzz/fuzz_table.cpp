// Fuzz target: the CSV tables of a scene (io/table.hpp). Any input either parses or is refused with
// a std::runtime_error; nothing else may escape (std::bad_alloc, std::length_error, a crash, undefined
// behaviour). Built by scripts/fuzz with libFuzzer and by test/fuzz/replay.cpp for the regressions.
#include "io/limits.hpp"
#include "io/table.hpp"

#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, size_t size)
{
  using namespace boltnet;
  const std::string text(reinterpret_cast<const char *>(data), size);
  Table             t;
  try {
    t = ParseTable("fuzz.csv", text, {"id"});
  } catch (const std::runtime_error &) {
    return 0;
  }
  // What the scene reader relies on: every row has a cell per column, a line number per row.
  if (t.lines.size() != t.rows.size()) std::abort();
  for (size_t r = 0; r < t.rows.size(); ++r) {
    if (t.rows[r].size() != t.header.size()) std::abort();
    if (r >= 4) continue; // typed reads of the first rows: enough for coverage, and each refusal throws
    for (const std::string &c : t.header) {
      try {
        const std::int64_t i = TableInt(t, r, c, 0, limits::kMaxId);
        if (i < 0 || i > limits::kMaxId) std::abort();
      } catch (const std::runtime_error &) {
      }
      try {
        (void)TableReal(t, r, c);
      } catch (const std::runtime_error &) {
      }
    }
  }
  return 0;
}
