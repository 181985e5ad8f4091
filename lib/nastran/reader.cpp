// ReadDeck: the sections of a Nastran input file (executive control, case control, bulk data), the
// case control commands boltnet uses, then the bulk data cards and their resolution.
#include "nastran/build.hpp"

#include <cctype>
#include <fstream>
#include <sstream>

namespace boltnet::nastran {

std::string Deck::Where(const Source &s) const
{
  return (s.file >= 0 && s.file < static_cast<int>(files.size()) ? files[s.file] : std::string("?")) + ":" + std::to_string(s.line);
}

namespace {

enum class Section { Executive, CaseControl, Bulk };

std::string FirstWord(const std::string &s)
{
  const std::string u = Upper(Trim(s));
  size_t e = 0;
  while (e < u.size() && std::isalnum(static_cast<unsigned char>(u[e]))) ++e;
  return u.substr(0, e);
}

// A main file with CEND starts with executive control; without CEND but with BEGIN BULK, with case
// control; with neither, it is bulk data only (an INCLUDE file read on its own).
Section StartSection(const std::string &path)
{
  std::ifstream in(path);
  std::string line;
  bool begin_bulk = false;
  while (std::getline(in, line)) {
    const std::string s = Upper(Trim(StripComment(line)));
    if (FirstWord(s) == "CEND") return Section::Executive;
    if (FirstWord(s) == "BEGIN" && s.find("BULK") != std::string::npos) begin_bulk = true;
  }
  return begin_bulk ? Section::CaseControl : Section::Bulk;
}

class CaseControl {
public:
  explicit CaseControl(Build &b) : b_(b), d_(b.deck) {}

  // Returns true at BEGIN BULK.
  bool Add(const Line &l)
  {
    std::string s = Trim(StripComment(l.text));
    if (s.empty()) return false;
    if (!pending_.empty()) {
      s = pending_ + s;
      pending_.clear();
    }
    if (s.back() == ',') { // SET lists and the like continue after a trailing comma
      pending_ = s;
      return false;
    }
    const std::string key = FirstWord(s);
    const size_t eq = s.find('=');
    const std::string value = eq == std::string::npos ? "" : Trim(s.substr(eq + 1));
    const Source at{l.file, l.line, -1};
    const auto fail = [&](const std::string &what) { throw Error(d_.Where(at) + ": " + what, d_.files[l.file], l.line, key, 0); };
    const auto setid = [&](const std::string &name) {
      int v;
      if (!ParseInteger(value, v) || v <= 0) fail(name + " = " + value + ": expected a set id (a positive integer)");
      return v;
    };
    Subcase &target = in_subcase_ ? d_.subcases.back() : defaults_;
    if (key == "BEGIN") {
      if (FirstWord(Trim(s).substr(5)) == "BULK") return true;
      fail("'" + s + "': only BEGIN BULK is supported (no superelement or auxiliary model sections)");
    } else if (key == "SUBCOM" || key == "SUBCO" || key == "SYMCOM" || key == "SUBSEQ" || key == "SYMSEQ" || key == "REPCASE") {
      fail(key + ": subcase combinations and repeated subcases are not supported");
    } else if (Abbrev(key, "SUBCASE")) {
      int id;
      const std::string rest = Trim(eq == std::string::npos ? Trim(s).substr(key.size()) : value);
      if (!ParseInteger(rest, id) || id <= 0) fail("SUBCASE '" + rest + "': expected a positive subcase id");
      if (!d_.subcases.empty() && id <= d_.subcases.back().id)
        fail("SUBCASE " + std::to_string(id) + " after SUBCASE " + std::to_string(d_.subcases.back().id) + ": subcase ids must increase");
      Subcase sc = defaults_;
      sc.id = id;
      sc.src = at;
      d_.subcases.push_back(sc);
      in_subcase_ = true;
    } else if (key == "LOAD") {
      target.load = setid("LOAD");
      target.load_src = at;
    } else if (key == "SPC") {
      target.spc = setid("SPC");
      target.spc_src = at;
    } else if (Abbrev(key, "TITLE")) {
      target.title = value;
    } else if (Abbrev(key, "SUBTITLE")) {
      target.subtitle = value;
    } else if (Abbrev(key, "LABEL")) {
      target.label = value;
    } else {
      auto &u = d_.unused_case[key.empty() ? Trim(s) : key];
      if (u.count++ == 0) u.first = at;
    }
    return false;
  }

  void Finish(bool had_case_control)
  {
    if (d_.subcases.empty() && had_case_control) {
      defaults_.id = 1;
      d_.subcases.push_back(defaults_);
    }
  }

private:
  Build  &b_;
  Deck   &d_;
  Subcase defaults_;
  bool    in_subcase_ = false;
  std::string pending_;
  // Case control commands may be shortened to their first four letters.
  static bool Abbrev(const std::string &key, const std::string &name) { return key == name || (key.size() >= 4 && name.rfind(key, 0) == 0); }
};

} // namespace

Deck ReadDeck(const std::string &path, const ReadOptions &options)
{
  Build b;
  b.options = options;
  Deck &d = b.deck;
  Section section = StartSection(path);
  const bool had_case_control = section != Section::Bulk;
  LineReader lines(path, d.files);
  CardAssembler cards(d.files, b.cards);
  CaseControl cc(b);
  Line l;
  bool ended = false;
  int after = 0;
  Source end_at;
  while (lines.Next(l)) {
    if (ended) {
      if (!Trim(StripComment(l.text)).empty()) ++after;
      continue;
    }
    if (section == Section::Executive) {
      std::istringstream words(Upper(StripComment(l.text)));
      std::string w, sol;
      words >> w;
      if (w == "CEND") section = Section::CaseControl;
      else if (w == "SOL" && words >> sol) d.sol = sol;
    } else if (section == Section::CaseControl) {
      if (cc.Add(l)) section = Section::Bulk;
    } else {
      const std::string s = Upper(Trim(StripComment(l.text)));
      const std::string w = FirstWord(s);
      if (w == "ENDDATA" && l.text.find_first_not_of(" \t") == 0) {
        cards.Finish();
        ended = true;
        end_at = Source{l.file, l.line, -1};
      } else if (w == "BEGIN" && l.text.find_first_not_of(" \t") == 0) {
        if (s.find("BULK") == std::string::npos)
          throw Error(d.Where(Source{l.file, l.line, -1}) + ": '" + Trim(l.text) + "': only BEGIN BULK is supported (no superelement or auxiliary model sections)",
                      d.files[l.file], l.line, "BEGIN", 0);
      } else {
        cards.Add(l);
      }
    }
  }
  cards.Finish();
  if (section != Section::Bulk)
    throw Error(d.Where(Source{l.file, l.line, -1}) + ": the deck ends here, and it has CEND but no BEGIN BULK: there is no bulk data", d.files[l.file], l.line, "", 0);
  cc.Finish(had_case_control);
  if (after) d.notes.push_back(d.Where(end_at) + ": " + std::to_string(after) + " lines after ENDDATA are ignored (as Nastran does)");
  if (!d.sol.empty() && d.sol != "101" && d.sol != "SESTATIC")
    d.notes.push_back("SOL " + d.sol + " is not linear statics (101, SESTATIC): only the static model, constraints and loads are read");
  for (size_t i = 0; i < b.cards.size(); ++i) ParseBulkCard(b, static_cast<int>(i));
  Resolve(b);
  return std::move(b.deck);
}

} // namespace boltnet::nastran
