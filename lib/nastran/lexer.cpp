// Lines with INCLUDE expanded, and bulk data lines assembled into cards (docs/nastran.md, "Field
// formats"): small field (8 columns, 80 per line, tabs to the next multiple of 8), large field
// (16 columns, '*' after the name and on continuation lines), free field (commas), continuation
// lines that start with a blank field 1, '+' or '*' and follow their card.
#include "nastran/lexer.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace boltnet::nastran {

namespace fs = std::filesystem;

std::string Upper(std::string s)
{
  for (char &c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string Trim(const std::string &s)
{
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::string StripComment(const std::string &s)
{
  char quote = 0;
  size_t end = s.size();
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '$') {
      end = i;
      break;
    }
  }
  std::string r = s.substr(0, end);
  while (!r.empty() && (r.back() == ' ' || r.back() == '\r' || r.back() == '\n' || r.back() == '\t')) r.pop_back();
  return r;
}

// ---------------------------------------------------------------------------------------------
// LineReader

struct LineReader::Open {
  std::ifstream in;
  int           file = -1, line = 0;
  std::string   path, canonical;
};

LineReader::LineReader(const std::string &path, std::vector<std::string> &files) : files_(files) { Push(path, nullptr); }
LineReader::~LineReader() = default;

void LineReader::Push(const std::string &path, const Line *from)
{
  const std::string here = from ? files_[from->file] + ":" + std::to_string(from->line) + ": " : "";
  auto o = std::make_unique<Open>();
  o->path = path;
  std::error_code ec;
  if (fs::is_directory(path, ec) || (o->in.open(path), !o->in))
    throw Error(here + (from ? "INCLUDE: cannot read the file '" : "Cannot read the Nastran deck '") + path + "'",
                from ? files_[from->file] : path, from ? from->line : 0, from ? "INCLUDE" : "", 0);
  // Only a regular file ends: a device or a pipe (INCLUDE /dev/zero) would be read forever.
  if (!fs::is_regular_file(path, ec))
    throw Error(here + (from ? "INCLUDE: '" : "The Nastran deck '") + path + "' is not a regular file",
                from ? files_[from->file] : path, from ? from->line : 0, from ? "INCLUDE" : "", 0);
  o->canonical = fs::weakly_canonical(fs::path(path), ec).string();
  for (const auto &s : stack_)
    if (s->canonical == o->canonical)
      throw Error(here + "INCLUDE cycle: '" + path + "' is already being read (it includes itself through '" + files_[from->file] + "')",
                  files_[from->file], from->line, "INCLUDE", 0);
  o->file = static_cast<int>(files_.size());
  files_.push_back(path);
  stack_.push_back(std::move(o));
}

bool LineReader::Raw(Line &line)
{
  while (!stack_.empty()) {
    Open &o = *stack_.back();
    if (std::getline(o.in, line.text)) {
      line.file = o.file;
      line.line = ++o.line;
      if (!line.text.empty() && line.text.back() == '\r') line.text.pop_back();
      return true;
    }
    stack_.pop_back();
  }
  return false;
}

bool LineReader::Next(Line &line)
{
  while (Raw(line)) {
    const std::string head = Upper(line.text.substr(0, 8));
    const bool include = head.rfind("INCLUDE", 0) == 0 && (line.text.size() == 7 || line.text[7] == ' ' || line.text[7] == '\t' ||
                                                          line.text[7] == '\'' || line.text[7] == '"');
    if (!include) return true;
    const Line at = line;
    const auto fail = [&](const std::string &what) {
      throw Error(files_[at.file] + ":" + std::to_string(at.line) + ": INCLUDE: " + what, files_[at.file], at.line, "INCLUDE", 0);
    };
    std::string rest = line.text.substr(7), name;
    const size_t b = rest.find_first_not_of(" \t");
    if (b == std::string::npos || rest[b] == '$') fail("no file name");
    if (rest[b] == '\'' || rest[b] == '"') {
      // A quoted name may continue over several lines: the pieces are joined, each trimmed.
      const char q = rest[b];
      std::string piece = rest.substr(b + 1);
      for (;;) {
        const size_t e = piece.find(q);
        if (e != std::string::npos) {
          name += Trim(piece.substr(0, e));
          rest = piece.substr(e + 1);
          break;
        }
        name += Trim(piece);
        Line more;
        if (!Raw(more)) fail("the quoted file name is not closed before the end of the file");
        piece = more.text;
      }
    } else {
      const size_t e = rest.find_first_of(" \t$", b);
      name = rest.substr(b, e == std::string::npos ? std::string::npos : e - b);
      rest = e == std::string::npos ? "" : rest.substr(e);
    }
    if (!Trim(StripComment(rest)).empty()) fail("unexpected text after the file name: '" + Trim(StripComment(rest)) + "'");
    if (name.empty()) fail("empty file name");
    fs::path p(name);
    if (p.is_relative()) p = fs::path(files_[at.file]).parent_path() / p;
    Push(p.lexically_normal().string(), &at);
  }
  return false;
}

// ---------------------------------------------------------------------------------------------
// CardAssembler

void CardAssembler::Fail(const Line &line, const std::string &card, int column, const std::string &what) const
{
  throw Error(files_[line.file] + ":" + std::to_string(line.line) + ": " + (card.empty() ? "" : card + ", ") +
                (column ? "field " + std::to_string(column) + ": " : "") + what,
              files_[line.file], line.line, card, column);
}

namespace {

std::string ExpandTabs(const std::string &s)
{
  std::string r;
  for (char c : s) {
    if (c == '\t') {
      do r.push_back(' ');
      while (r.size() % 8);
    } else {
      r.push_back(c);
    }
  }
  return r;
}

std::string MarkerKey(const std::string &m)
{
  std::string k = Upper(Trim(m));
  if (!k.empty() && (k[0] == '+' || k[0] == '*')) k.erase(0, 1);
  return Trim(k);
}

bool IsCardName(const std::string &n)
{
  if (n.empty() || !std::isalpha(static_cast<unsigned char>(n[0]))) return false;
  return std::all_of(n.begin(), n.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)); });
}

} // namespace

void CardAssembler::Add(const Line &line)
{
  const std::string s = StripComment(line.text);
  if (Trim(s).empty()) return;
  const bool free = s.find(',') != std::string::npos;

  std::vector<std::string> pf; // physical fields: [0] name/continuation, then data, then the marker
  std::string first = free ? Trim(s.substr(0, s.find(','))) : Trim(ExpandTabs(s).substr(0, 8));
  const bool continuation = first.empty() || first[0] == '+' || first[0] == '*';
  const bool large = continuation ? (!first.empty() && first[0] == '*') : first.back() == '*';
  const int  n = large ? 4 : 8;
  // The card this line belongs to, for messages: the open card for a continuation, else its name.
  const std::string card = continuation ? (open_ ? card_.name : "") : Upper(large ? first.substr(0, first.size() - 1) : first);
  if (free) {
    size_t start = 0;
    for (;;) {
      const size_t c = s.find(',', start);
      pf.push_back(Trim(s.substr(start, c == std::string::npos ? std::string::npos : c - start)));
      if (c == std::string::npos) break;
      start = c + 1;
    }
  } else {
    const std::string x = ExpandTabs(s);
    if (x.size() > 80 && !Trim(x.substr(80)).empty())
      Fail(line, card, 0, "text beyond column 80 of a small- or large-field line: '" + Trim(x.substr(80)) + "' (Nastran ignores it; use free field for long lines)");
  }

  std::vector<std::string> data(n);
  std::string marker;
  if (free) {
    if (static_cast<int>(pf.size()) > n + 2)
      Fail(line, card, n + 3, "a free-field " + std::string(large ? "large-field " : "") + "line holds at most " + std::to_string(n + 2) +
                          " fields (name, " + std::to_string(n) + " data fields, continuation); this one has " + std::to_string(pf.size()));
    for (int i = 0; i < n && i + 1 < static_cast<int>(pf.size()); ++i) data[i] = pf[i + 1];
    if (static_cast<int>(pf.size()) == n + 2) marker = pf[n + 1];
  } else {
    const std::string x = ExpandTabs(s);
    const int w = large ? 16 : 8;
    for (int i = 0; i < n; ++i)
      if (8 + w * i < static_cast<int>(x.size())) data[i] = Trim(x.substr(8 + w * i, w));
    if (x.size() > 72) marker = Trim(x.substr(72, 8));
  }

  if (!continuation) {
    Finish();
    const std::string &name = card;
    if (!IsCardName(name))
      Fail(line, "", 1, "'" + first + "' is not a card name (a card starts with its name in field 1, a continuation line with a blank field 1, '+' or '*')");
    card_ = Card{};
    card_.name = name;
    card_.head = Field{first, line.file, line.line, 1};
    open_ = true;
  } else {
    if (!open_) Fail(line, "", 1, "continuation line with no card before it");
    const std::string want = MarkerKey(marker_), got = MarkerKey(first);
    if (!want.empty() && !got.empty() && want != got)
      Fail(line, card, 1, "continuation marker '" + first + "' does not match '" + marker_ + "' at the end of the previous line");
    // Two large-field lines make one small-field line: a small line after an odd number of large
    // lines starts a new group of eight.
    if (!large)
      while (card_.data.size() % 8) card_.data.push_back(Field{"", card_.last_file, card_.last_line, 0});
  }
  for (int i = 0; i < n; ++i) card_.data.push_back(Field{data[i], line.file, line.line, i + 2});
  marker_ = marker;
  card_.last_line = line.line;
  card_.last_file = line.file;
}

void CardAssembler::Finish()
{
  if (!open_) return;
  cards_.push_back(std::move(card_));
  card_ = Card{};
  open_ = false;
  marker_.clear();
}

} // namespace boltnet::nastran
