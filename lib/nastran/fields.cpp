// Nastran numbers and typed field access (docs/nastran.md, "Numbers").
#include "nastran/fields.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

namespace boltnet::nastran {

namespace {

bool Digit(char c) { return c >= '0' && c <= '9'; }

// Splits a Nastran real into a form std::from_chars reads: "1.5+3" -> "1.5e+3", "1.5D3" -> "1.5e3".
// False unless the text is [sign] mantissa [exponent] with a mantissa of digits and at most one
// point, and has a point or an exponent letter (an integer is not a real).
bool NormaliseReal(const std::string &s, std::string &out)
{
  size_t i = 0;
  out.clear();
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) out.push_back(s[i++]);
  size_t digits = 0;
  bool point = false;
  for (; i < s.size(); ++i) {
    if (Digit(s[i])) {
      ++digits;
      out.push_back(s[i]);
    } else if (s[i] == '.' && !point) {
      point = true;
      out.push_back('.');
    } else {
      break;
    }
  }
  if (digits == 0) return false;
  bool letter = false;
  if (i < s.size()) {
    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(s[i])));
    if (c == 'E' || c == 'D') {
      letter = true;
      ++i;
    } else if (c != '+' && c != '-') {
      return false;
    }
    out.push_back('e');
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) out.push_back(s[i++]);
    size_t edigits = 0;
    for (; i < s.size() && Digit(s[i]); ++i, ++edigits) out.push_back(s[i]);
    if (edigits == 0 || i != s.size()) return false;
  }
  return point || letter;
}

} // namespace

bool ParseInteger(const std::string &s, int &value)
{
  if (s.empty()) return false;
  const char *b = s.data(), *e = s.data() + s.size();
  if (*b == '+' || *b == '-') {
    if (b + 1 == e || !Digit(b[1])) return false;
    if (*b == '+') ++b;
  } else if (!Digit(*b)) {
    return false;
  }
  long long v = 0;
  auto [p, ec] = std::from_chars(b, e, v);
  if (ec != std::errc() || p != e || v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) return false;
  value = static_cast<int>(v);
  return true;
}

bool ParseReal(const std::string &s, double &value)
{
  std::string n;
  if (!NormaliseReal(s, n)) return false;
  const char *b = n.data();
  if (*b == '+') ++b;
  double v = 0;
  auto [p, ec] = std::from_chars(b, n.data() + n.size(), v);
  if (ec != std::errc() || p != n.data() + n.size() || !std::isfinite(v)) return false;
  value = v;
  return true;
}

Kind ClassifyField(const std::string &t)
{
  if (t.empty()) return Kind::Blank;
  int i;
  double r;
  if (ParseInteger(t, i)) return Kind::Integer;
  if (ParseReal(t, r)) return Kind::Real;
  if (std::isalpha(static_cast<unsigned char>(t[0]))) {
    for (char c : t)
      if (!std::isalnum(static_cast<unsigned char>(c))) return Kind::Bad;
    return Kind::Word;
  }
  return Kind::Bad;
}

// ---------------------------------------------------------------------------------------------

const std::string &CardFields::Text(int k) const
{
  static const std::string blank;
  return k < Size() ? c_.data[k].text : blank;
}

std::string CardFields::Title() const
{
  int id;
  if (Size() > 0 && ParseInteger(c_.data[0].text, id)) return c_.name + " " + c_.data[0].text;
  return c_.name;
}

void CardFields::Fail(int k, const std::string &what, const std::string &problem) const
{
  if (k < Size() && c_.data[k].column > 0) {
    const Field &f = c_.data[k];
    throw Error(files_[f.file] + ":" + std::to_string(f.line) + ": " + Title() + ", field " + std::to_string(f.column) + " (" + what + "): " + problem,
                files_[f.file], f.line, c_.name, f.column);
  }
  const int line = k / 8, column = k % 8 + 2;
  const std::string where = line == 0 ? "of its first line" : "of continuation " + std::to_string(line);
  throw Error(files_[c_.last_file] + ":" + std::to_string(c_.last_line) + ": " + Title() + ", field " + std::to_string(column) + " " + where +
                " (" + what + "): " + problem,
              files_[c_.last_file], c_.last_line, c_.name, column);
}

void CardFields::FailCard(const std::string &problem) const
{
  throw Error(files_[c_.head.file] + ":" + std::to_string(c_.head.line) + ": " + Title() + ": " + problem, files_[c_.head.file], c_.head.line,
              c_.name, 0);
}

int CardFields::Int(int k, const char *what) const
{
  if (Blank(k)) Fail(k, what, k >= Size() ? "missing (the card ends before it): an integer is required" : "blank: an integer is required");
  int v;
  if (!ParseInteger(Text(k), v)) {
    const Kind kind = KindOf(k);
    Fail(k, what, "'" + Text(k) + "' is not an integer" + (kind == Kind::Real ? " (it is a real)" : ""));
  }
  return v;
}

int CardFields::IntOr(int k, const char *what, int def) const { return Blank(k) ? def : Int(k, what); }

double CardFields::Real(int k, const char *what) const
{
  if (Blank(k)) Fail(k, what, k >= Size() ? "missing (the card ends before it): a real is required" : "blank: a real is required");
  double v;
  if (!ParseReal(Text(k), v)) {
    int i;
    if (ParseInteger(Text(k), i)) Fail(k, what, "'" + Text(k) + "' is an integer where Nastran requires a real (write " + Text(k) + ".)");
    Fail(k, what, "'" + Text(k) + "' is not a real number (Nastran reals: 1.5, 1.5+3, 1.5-3, 1.5E3, 1.5D3, .5, -5.)");
  }
  return v;
}

double CardFields::RealOr(int k, const char *what, double def) const { return Blank(k) ? def : Real(k, what); }

std::string CardFields::Word(int k, const char *what) const
{
  if (Blank(k)) return "";
  if (KindOf(k) != Kind::Word) Fail(k, what, "'" + Text(k) + "' is not a word");
  return Upper(Text(k));
}

DofSet CardFields::Dofs(int k, const char *what, bool required) const
{
  if (Blank(k)) {
    if (required) Fail(k, what, k >= Size() ? "missing (the card ends before it): components (digits 1-6) are required" : "blank: components (digits 1-6) are required");
    return 0;
  }
  const std::string &t = Text(k);
  DofSet d = 0;
  for (char c : t) {
    if (c < '1' || c > '6') Fail(k, what, "'" + t + "' is not a set of components (unique digits 1 to 6)");
    const DofSet bit = 1u << (c - '1');
    if (d & bit) Fail(k, what, "'" + t + "' repeats component " + std::string(1, c));
    d |= bit;
  }
  return d;
}

int CardFields::Id(int k, const char *what) const
{
  const int v = Int(k, what);
  if (v <= 0) Fail(k, what, std::to_string(v) + " must be a positive id");
  return v;
}

int CardFields::IdOr(int k, const char *what, int def) const { return Blank(k) ? def : Id(k, what); }

int CardFields::CidOr(int k, const char *what, int def) const
{
  if (Blank(k)) return def;
  const int v = Int(k, what);
  if (v < 0) Fail(k, what, std::to_string(v) + " must be a coordinate system id >= 0");
  return v;
}

std::string DofString(DofSet dofs)
{
  std::string s;
  for (int i = 0; i < 6; ++i)
    if (dofs & (1u << i)) s.push_back(static_cast<char>('1' + i));
  return s;
}

} // namespace boltnet::nastran
