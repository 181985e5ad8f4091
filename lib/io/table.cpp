// CSV tables of a scene: io/table.hpp.
#include "io/table.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>
#include <stdexcept>

namespace boltnet {
namespace {

std::string Trim(const std::string &s)
{
  const size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

[[noreturn]] void Fail(const Table &t, size_t row, const std::string &col, const std::string &what)
{
  throw std::runtime_error(t.path + " line " + std::to_string(t.lines[row]) + ", column '" + col + "': " + what);
}

// Printable form of a cell for a message: control bytes shown as '?', long cells cut.
std::string Shown(const std::string &v)
{
  std::string s;
  for (char c : v.substr(0, 40)) s += (unsigned char)c < 0x20 || c == 0x7f ? '?' : c;
  return v.size() > 40 ? s + "..." : s;
}

} // namespace

bool Table::Has(const std::string &col) const
{
  for (const std::string &h : header)
    if (h == col) return true;
  return false;
}

Table ParseTable(const std::string &path, const std::string &text, const std::vector<std::string> &required)
{
  Table t;
  t.path = path;
  // A UTF-8 byte-order mark would otherwise become part of the first column's name.
  const size_t       start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  std::istringstream in(text.substr(start));
  std::string        line;
  int                lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    line = Trim(line);
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream        ls(line);
    std::string              cell;
    while (std::getline(ls, cell, ',')) cells.push_back(Trim(cell));
    if (line.back() == ',') cells.push_back("");
    if (t.header.empty()) {
      std::set<std::string> seen;
      for (const std::string &h : cells) {
        if (h.empty()) throw std::runtime_error(path + " line " + std::to_string(lineno) + ": the header has an empty column name");
        if (!seen.insert(h).second) throw std::runtime_error(path + " line " + std::to_string(lineno) + ": column '" + Shown(h) + "' appears twice in the header");
      }
      t.header = cells;
      continue;
    }
    if (cells.size() != t.header.size())
      throw std::runtime_error(path + " line " + std::to_string(lineno) + ": " + std::to_string(cells.size()) + " values for " + std::to_string(t.header.size()) + " columns");
    t.rows.push_back(std::move(cells));
    t.lines.push_back(lineno);
  }
  if (t.header.empty()) throw std::runtime_error(path + ": empty table (a header line is needed)");
  for (const std::string &c : required)
    if (!t.Has(c)) throw std::runtime_error(path + ": missing column '" + c + "'");
  return t;
}

const std::string &TableCell(const Table &t, size_t row, const std::string &col)
{
  if (row >= t.rows.size()) throw std::out_of_range(t.path + ": no row " + std::to_string(row));
  for (size_t k = 0; k < t.header.size(); ++k)
    if (t.header[k] == col) return t.rows[row][k];
  throw std::runtime_error(t.path + ": missing column '" + col + "'");
}

double TableReal(const Table &t, size_t row, const std::string &col)
{
  const std::string &v   = TableCell(t, row, col);
  char              *end = nullptr;
  errno                  = 0;
  const double x         = std::strtod(v.c_str(), &end);
  if (v.empty() || !end || *end != '\0' || errno != 0 || !std::isfinite(x)) Fail(t, row, col, "'" + Shown(v) + "' is not a number");
  return x;
}

bool ParseInt64(const std::string &s, std::int64_t *v)
{
  const size_t digits = s.find_first_not_of("+-") == std::string::npos ? s.size() : s.find_first_not_of("+-");
  if (s.empty() || digits > 1 || digits == s.size() || s.find_first_not_of("0123456789", digits) != std::string::npos) return false;
  char *end = nullptr;
  errno     = 0;
  const long long x = std::strtoll(s.c_str(), &end, 10);
  if (errno != 0 || *end != '\0') return false;
  *v = x;
  return true;
}

std::int64_t TableInt(const Table &t, size_t row, const std::string &col, std::int64_t lo, std::int64_t hi)
{
  const std::string &v = TableCell(t, row, col);
  std::int64_t       x = 0;
  const std::string   range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!ParseInt64(v, &x)) {
    // Digits that do not fit 64 bits are out of range too, not "not a number".
    const size_t d = v.find_first_not_of("+-");
    if (d != std::string::npos && d <= 1 && v.find_first_not_of("0123456789", d) == std::string::npos) Fail(t, row, col, "'" + Shown(v) + "' is out of range: it must lie in " + range);
    Fail(t, row, col, "'" + Shown(v) + "' is not a whole number");
  }
  if (x < lo || x > hi) Fail(t, row, col, std::to_string(x) + " is out of range: it must lie in " + range);
  return x;
}

} // namespace boltnet
