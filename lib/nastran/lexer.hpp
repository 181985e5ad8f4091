// The text layer of the Nastran reader: lines of the deck with INCLUDE expanded, and bulk data lines
// assembled into cards (small, large and free field; continuations). Internal to lib/nastran.
#pragma once

#include "nastran/deck.hpp"

#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace boltnet::nastran {

// One field of a card: its text (trimmed, as written) and where it was read: the file, the line and
// the field number on that line (1-based: 1 is the name or continuation field).
struct Field {
  std::string text;
  int         file = -1, line = 0, column = 0;
};

// A bulk data card: name (upper case, without the large-field '*') and its data fields in logical
// order: eight per small-field line, four per large-field line (two large lines make one small
// line). Fields past the last line are absent (Size()).
struct Card {
  std::string        name;
  Field              head;  // the name field as written
  std::vector<Field> data;
  int                last_line = 0, last_file = -1;
};

// A physical line of the deck.
struct Line {
  std::string text;
  int         file = -1, line = 0;
};

// Reads lines from the main file and the files it INCLUDEs (relative to the including file,
// quoted or not, a quoted name continued over several lines), in order. Records every file read in
// files. Throws Error for a file that cannot be read or an INCLUDE cycle.
class LineReader {
public:
  LineReader(const std::string &path, std::vector<std::string> &files);
  ~LineReader();
  bool Next(Line &line);

private:
  struct Open;
  std::vector<std::unique_ptr<Open>> stack_;
  std::vector<std::string>          &files_;
  void Push(const std::string &path, const Line *from);
  bool Raw(Line &line);
};

// Assembles bulk data lines into cards. Feed every bulk data line (comments included) to Add; each
// completed card is appended to cards. Throws Error for a malformed line.
class CardAssembler {
public:
  CardAssembler(const std::vector<std::string> &files, std::vector<Card> &cards) : files_(files), cards_(cards) {}
  void Add(const Line &line);
  void Finish();

private:
  const std::vector<std::string> &files_;
  std::vector<Card>              &cards_;
  Card                            card_;
  bool                            open_ = false;
  std::string                     marker_; // continuation marker of the card's last line
  [[noreturn]] void Fail(const Line &line, const std::string &card, int column, const std::string &what) const;
};

// Strips a '$' comment (outside quotes) and trailing blanks and carriage returns.
std::string StripComment(const std::string &s);
std::string Upper(std::string s);
std::string Trim(const std::string &s);

} // namespace boltnet::nastran
