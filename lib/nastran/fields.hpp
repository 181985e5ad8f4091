// Nastran numbers and typed access to the fields of a card, each failure an Error naming the file,
// the line, the card and the field. Internal to lib/nastran.
#pragma once

#include "nastran/lexer.hpp"

#include <string>
#include <vector>

namespace boltnet::nastran {

// What a field holds: blank, an integer (optional sign, digits), a real (Nastran forms: 1.5,
// 1.5+3, 1.5-3, 1.5E3, 1.5D3, .5, -5., 1e-10), a word (a letter, then letters and digits), or
// nothing valid.
enum class Kind { Blank, Integer, Real, Word, Bad };
Kind ClassifyField(const std::string &text);
// Strict parsers: false unless the whole text is one number of that kind (and in range).
bool ParseInteger(const std::string &text, int &value);
bool ParseReal(const std::string &text, double &value);

// Data field index of field `field` (2..9) on logical line `line` (0: the card's first line), in
// the small-field numbering of the Nastran Quick Reference Guide.
constexpr int F(int line, int field) { return 8 * line + field - 2; }

class CardFields {
public:
  CardFields(const Card &card, const std::vector<std::string> &files) : c_(card), files_(files) {}
  const std::string &Name() const { return c_.name; }
  int                Size() const { return static_cast<int>(c_.data.size()); }
  bool               Blank(int k) const { return k >= Size() || c_.data[k].text.empty(); }
  Kind               KindOf(int k) const { return k >= Size() ? Kind::Blank : ClassifyField(c_.data[k].text); }
  const std::string &Text(int k) const;
  Source             Src(int card) const { return Source{c_.head.file, c_.head.line, card}; }

  int         Int(int k, const char *what) const;               // required integer
  int         IntOr(int k, const char *what, int def) const;    // integer or blank
  double      Real(int k, const char *what) const;              // required real
  double      RealOr(int k, const char *what, double def) const;
  std::string Word(int k, const char *what) const;              // upper case; "" if blank
  DofSet      Dofs(int k, const char *what, bool required) const; // "123456" (unique digits 1-6)
  // Integer fields that name things: ids > 0 (Id) and coordinate systems >= 0 (Cid).
  int Id(int k, const char *what) const;
  int IdOr(int k, const char *what, int def) const;
  int CidOr(int k, const char *what, int def) const;

  // An Error naming this card and field k (past the last line: the card's last line).
  [[noreturn]] void Fail(int k, const std::string &what, const std::string &problem) const;
  // An Error naming this card only.
  [[noreturn]] void FailCard(const std::string &problem) const;
  std::string       Title() const; // "GRID 7" (the card and its first field when that is an id)

private:
  const Card                     &c_;
  const std::vector<std::string> &files_;
};

} // namespace boltnet::nastran
