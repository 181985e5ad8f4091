// CSV tables of a scene (patches, joints, boundary conditions): parsing and typed cells. Pure C++
// (no PETSc, no MPI), so that unit tests and the fuzz target call it directly; every error is a
// std::runtime_error whose message names the file, the line and the column.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace boltnet {

struct Table {
  std::string                           path;
  std::vector<std::string>              header;
  std::vector<std::vector<std::string>> rows;
  std::vector<int>                      lines; // line number of each row, for messages
  bool Has(const std::string &col) const;
};

// A header line, then rows; blank lines and lines starting with '#' are skipped, a UTF-8
// byte-order mark before the header is dropped (spreadsheets write one). Errors: no header, an
// empty or duplicated column name, a row with another number of cells, a missing required column.
Table ParseTable(const std::string &path, const std::string &text, const std::vector<std::string> &required);

// The cell of row `row` (0-based) in column `col`.
const std::string &TableCell(const Table &t, size_t row, const std::string &col);
// A finite real number.
double TableReal(const Table &t, size_t row, const std::string &col);
// A whole number in [lo, hi], read as 64-bit: a value out of range is refused, never truncated.
std::int64_t TableInt(const Table &t, size_t row, const std::string &col, std::int64_t lo, std::int64_t hi);

// A whole decimal number (optional sign, digits only) into *v; false if s is not one or does not fit
// 64 bits. Shared with the option checks (io/scene.cpp).
bool ParseInt64(const std::string &s, std::int64_t *v);

} // namespace boltnet
