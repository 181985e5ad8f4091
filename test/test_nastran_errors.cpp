// Requirement 3 of the Nastran reader (docs/nastran.md, "Errors"): a malformed deck stops with an
// Error naming the file, the line, the card and the field. Each case writes a small deck (the text
// is in the test) and checks where the reader points and what it says.
#include "nastran/deck.hpp"
#include "nastran/expand.hpp"
#include "nastran/section.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <string>

using namespace boltnet::nastran;

namespace {

const std::string kData = BOLTNET_NASTRAN_DATA;

std::string Write(const std::string &name, const std::string &text)
{
  const std::string path = testing::TempDir() + "nastran-" + name + ".bdf";
  std::ofstream(path) << text;
  return path;
}

// Reads the deck and expects an Error at `line` of it, on `card`, field `field`, whose message
// matches `pattern` (and starts with "<file>:<line>: ").
void ExpectError(const std::string &name, const std::string &text, int line, const std::string &card, int field, const std::string &pattern)
{
  const std::string path = Write(name, text);
  try {
    ReadDeck(path);
    ADD_FAILURE() << name << ": no error";
  } catch (const Error &e) {
    const std::string what = e.what();
    EXPECT_EQ(e.file, path) << what;
    EXPECT_EQ(e.line, line) << what;
    EXPECT_EQ(e.card, card) << what;
    EXPECT_EQ(e.field, field) << what;
    EXPECT_EQ(what.rfind(path + ":" + std::to_string(line) + ": ", 0), 0u) << what;
    EXPECT_TRUE(std::regex_search(what, std::regex(pattern))) << what << "\n  does not match: " << pattern;
  }
}

// One small-field line: each field padded to 8 columns (the 10th, a continuation marker, too).
std::string S(std::initializer_list<const char *> fields)
{
  std::string line;
  for (const char *f : fields) line += (std::string(f) + "        ").substr(0, std::max<size_t>(8, std::string(f).size()));
  return line + "\n";
}

const std::string kPlate = "GRID    1               0.      0.      0.\n"
                           "GRID    2               1.      0.      0.\n"
                           "GRID    3               1.      1.      0.\n"
                           "GRID    4               0.      1.      0.\n"
                           "MAT1    1       7.+4            .3\n"
                           "PSHELL  1       1       .1      1               1\n";

} // namespace

// Requirement 3: a bad number names its field (and says why: an integer where a real is required, ...).
TEST(Errors, BadNumbers)
{
  ExpectError("bad-real", "BEGIN BULK\nGRID    1               1.2.3   0.      0.\n", 2, "GRID", 4,
              R"(GRID 1, field 4 \(X1\): '1.2.3' is not a real number)");
  ExpectError("int-for-real", "BEGIN BULK\nMAT1    1       70000           .3\n", 2, "MAT1", 3,
              R"(MAT1 1, field 3 \(E\): '70000' is an integer where Nastran requires a real \(write 70000.\))");
  ExpectError("real-for-int", "BEGIN BULK\nGRID    1.                      0.      0.      0.\n", 2, "GRID", 2, R"(field 2 \(ID\): '1.' is not an integer \(it is a real\))");
  ExpectError("no-point", "BEGIN BULK\nGRID    1               1+3     0.      0.\n", 2, "GRID", 4, R"('1\+3' is not a real number)");
  ExpectError("bad-dofs", "BEGIN BULK\n" + kPlate + "SPC1    1       1237    1\n", 8, "SPC1", 3, R"(field 3 \(C\): '1237' is not a set of components)");
  ExpectError("repeated-dof", "BEGIN BULK\n" + kPlate + "SPC1    1       1231    1\n", 8, "SPC1", 3, R"(repeats component 1)");
}

// Requirement 3: field numbers as they stand on the line, in large and free field and on continuations.
TEST(Errors, FieldNumbersInEachFormat)
{
  // Large field: X3 on the continuation line is its field 2; free field: the position in the list.
  ExpectError("large", "BEGIN BULK\nGRID*                  1                              0.              0.*\n*             1.x\n", 3, "GRID", 2,
              R"(GRID 1, field 2 \(X3\): '1.x' is not a real number)");
  ExpectError("free", "BEGIN BULK\nGRID,1,,0.,0.,zero\n", 2, "GRID", 6, R"(GRID 1, field 6 \(X3\): 'zero')");
  ExpectError("continuation", "BEGIN BULK\n" + kPlate + S({"CQUAD4", "7", "1", "1", "2", "3", "4", "", "", "+C"}) + S({"+C", "", "", "2", ".1"}), 9, "CQUAD4", 4,
              R"(CQUAD4 7, field 4 \(TFLAG\): must be 0 \(thicknesses\) or 1)");
}

// Requirement 3: a missing required field.
TEST(Errors, MissingRequiredFields)
{
  ExpectError("blank-grid", "BEGIN BULK\n" + kPlate + "CQUAD4  7       1       1       2       3\n", 8, "CQUAD4", 7, R"(field 7 \(G4\): blank: an integer is required)");
  ExpectError("free-blank", "BEGIN BULK\nPLOAD4,1,2\n", 2, "PLOAD4", 4, R"(PLOAD4 1, field 4 \(P1\): blank: a real is required)");
  ExpectError("blank-middle", "BEGIN BULK\n" + kPlate + "CQUAD4  7       1       1               3       4\n", 8, "CQUAD4", 5, R"(field 5 \(G2\): blank: an integer is required)");
  ExpectError("mat1-no-modulus", "BEGIN BULK\nMAT1    1                       .3\n", 2, "MAT1", 3, R"(E and G are both blank)");
  ExpectError("pcomp-no-ply", "BEGIN BULK\nPCOMP   1\n", 2, "PCOMP", 2, R"(field 2 of continuation 1 \(MID1\): a PCOMP needs at least one ply)");
  ExpectError("rbe3-weight", "BEGIN BULK\n" + kPlate + "RBE3    5               1       123     1       123     2       3\n", 8, "RBE3", 6,
              R"(RBE3 5, field 6 \(WT1\): '1' is not a weight \(a real)");
}

// Requirement 3: references to undefined grids, properties, materials, coordinate systems and sets.
TEST(Errors, UndefinedReferences)
{
  ExpectError("undefined-grid", "BEGIN BULK\n" + kPlate + "CQUAD4  7       1       1       2       3       99\n", 8, "CQUAD4", 7, R"(field 7 \(G4\): grid 99 is not defined)");
  ExpectError("undefined-property", "BEGIN BULK\n" + kPlate + "CQUAD4  7       8       1       2       3       4\n", 8, "CQUAD4", 3,
              R"(field 3 \(PID\): property 8 is not a PSHELL or PCOMP)");
  ExpectError("undefined-material", "BEGIN BULK\nPSHELL  1       2       .1      2\n", 2, "PSHELL", 3, R"(field 3 \(MID1\): material 2 is not a MAT1 or MAT8)");
  ExpectError("undefined-coord", "BEGIN BULK\nGRID    1       9       0.      0.      0.\n", 2, "GRID", 3,
              R"(field 3 \(CP\): coordinate system 9 is not defined)");
  ExpectError("undefined-spc-grid", "BEGIN BULK\n" + kPlate + "SPC1    1       123     1       7       2\n", 8, "SPC1", 5, R"(field 5 \(G\): grid 7 is not defined)");
  ExpectError("empty-thru", "BEGIN BULK\n" + kPlate + "SPC1    1       123     10      THRU    20\n", 8, "SPC1", 4, R"(no grid of the range 10 THRU 20 exists)");
  ExpectError("pload4-not-shell", "BEGIN BULK\n" + kPlate + "PLOAD4  1       12      1.\n", 8, "PLOAD4", 3, R"(element 12 is not a CQUAD4 or CTRIA3)");
  ExpectError("load-set", "BEGIN BULK\n" + kPlate + "FORCE   2       1       0       1.      1.      0.      0.\nLOAD    1       1.      1.      2       1.      3\n", 9,
              "LOAD", 7, R"(field 7 \(L2\): no FORCE, MOMENT or PLOAD4 set 3)");
  ExpectError("spcadd-of-spcadd", "BEGIN BULK\n" + kPlate + "SPC1    1       1       1\nSPCADD  2       1\nSPCADD  3       2\n", 10, "SPCADD", 3,
              R"(an SPCADD cannot include another SPCADD \(2\))");
  ExpectError("bush-property", "BEGIN BULK\n" + kPlate + "CBUSH   9       1       1       2       0.      0.      1.\n", 8, "CBUSH", 3,
              R"(field 3 \(PID\): property 1 is not a PBUSH)");
}

// Requirements 2 and 3: cycles and degenerate systems, undefined directions, bush axes that Nastran refuses.
TEST(Errors, CoordinateSystems)
{
  ExpectError("coord-cycle",
              "BEGIN BULK\nCORD2R  1       2       0.      0.      0.      0.      0.      1.\n        1.      0.      0.\n"
              "CORD2R  2       1       0.      0.      0.      0.      0.      1.\n        1.      0.      0.\n",
              2, "CORD2R", 3, R"(field 3 \(RID\): coordinate systems 1 -> 2 -> 1 reference each other in a cycle)");
  ExpectError("coord-collinear", "BEGIN BULK\nCORD2R  1       0       0.      0.      0.      0.      0.      1.\n        0.      0.      2.\n", 3, "CORD2R", 2,
              R"(field 2 \(C1\): C lies on the line through A and B)");
  ExpectError("cd-on-axis",
              "BEGIN BULK\nCORD2C  1       0       0.      0.      0.      0.      0.      1.\n        1.      0.      0.\nGRID    1               0.      0.      5.      1\n", 4,
              "GRID", 7, R"(field 7 \(CD\): the grid's displacement directions are undefined: the point lies on the axis of cylindrical system 1)");
  ExpectError("bush-coincident", "BEGIN BULK\n" + kPlate + "GRID    5               1.      1.      0.\nPBUSH   2       K       1.\nCBUSH   9       2       3       5       0.      0.      1.\n", 10,
              "CBUSH", 9, R"(GA and GB coincide \(closer than 1e-4\): the element axes need CID)");
  ExpectError("bush-parallel", "BEGIN BULK\n" + kPlate + "PBUSH   2       K       1.\nCBUSH   9       2       1       2       2.      0.      0.\n", 9, "CBUSH", 6,
              R"(the orientation vector is parallel to the line from GA to GB)");
}

// Requirement 3: duplicate ids name the first definition.
TEST(Errors, DuplicateIds)
{
  ExpectError("dup-grid", "BEGIN BULK\n" + kPlate + "GRID    2               5.      0.      0.\n", 8, "GRID", 2, R"(duplicate id: GRID 2 is already defined at .*dup-grid.bdf:3)");
  ExpectError("dup-element", "BEGIN BULK\n" + kPlate + "CQUAD4  7       1       1       2       3       4\nPBUSH   2       K       1.\nCBUSH   7       2       1       2       0.      0.      1.\n",
              10, "CBUSH", 2, R"(duplicate id: CQUAD4 7 is already defined at .*:8)");
  ExpectError("dup-property", "BEGIN BULK\n" + kPlate + "PBUSH   1       K       1.\n", 8, "PBUSH", 2, R"(duplicate id: PSHELL 1 is already defined)");
}

// Requirements 1 and 3: malformed lines and continuations.
TEST(Errors, LinesAndContinuations)
{
  ExpectError("marker", "BEGIN BULK\n" + S({"CORD2R", "1", "0", "0.", "0.", "0.", "0.", "0.", "1.", "+A"}) + S({"+B", "1.", "0.", "0."}), 3, "CORD2R", 1,
              R"(CORD2R, field 1: continuation marker '\+B' does not match '\+A')");
  ExpectError("orphan", "BEGIN BULK\n        1.      0.      0.\n", 2, "", 1, R"(continuation line with no card before it)");
  ExpectError("column-81", "BEGIN BULK\n" + S({"GRID", "1", "", "0.", "0.", "0.", "", "", "", "", "extra"}), 2, "GRID", 0,
              R"(text beyond column 80 of a small- or large-field line: 'extra')");
  ExpectError("free-too-long", "BEGIN BULK\nGRID,1,,0.,0.,0.,,,,,7\n", 2, "GRID", 11, R"(a free-field line holds at most 10 fields)");
  ExpectError("card-name", "BEGIN BULK\nGRID 1 0 0. 0. 0.\n", 2, "", 1, R"(field 1: 'GRID 1 0' is not a card name)");
  ExpectError("extra-data", "BEGIN BULK\nGRID    1               0.      0.      0.\n        7\n", 3, "GRID", 2,
              R"(GRID 1, field 2 \(after the last field of GRID\): unexpected data '7')");
}

// Requirements 1 and 3: case control and INCLUDE errors name the line.
TEST(Errors, CaseControlAndInclude)
{
  ExpectError("case-load", "SOL 101\nCEND\nSUBCASE 1\n  LOAD = 5\nBEGIN BULK\n" + kPlate, 4, "LOAD", 0,
              R"(LOAD = 5 \(subcase 1\): no LOAD, FORCE, MOMENT or PLOAD4 set 5 in the bulk data)");
  ExpectError("case-spc", "SOL 101\nCEND\nSPC = 5\nBEGIN BULK\n" + kPlate, 3, "SPC", 0, R"(SPC = 5 \(subcase 1\): no SPCADD, SPC or SPC1 set 5)");
  ExpectError("case-order", "CEND\nSUBCASE 2\nSUBCASE 1\nBEGIN BULK\n", 3, "SUBCASE", 0, R"(SUBCASE 1 after SUBCASE 2: subcase ids must increase)");
  ExpectError("case-subcom", "CEND\nSUBCASE 1\nSUBCOM 2\nBEGIN BULK\n", 3, "SUBCOM", 0, R"(SUBCOM: subcase combinations and repeated subcases are not supported)");
  ExpectError("case-set", "CEND\nLOAD = ALL\nBEGIN BULK\n", 2, "LOAD", 0, R"(LOAD = ALL: expected a set id)");
  ExpectError("no-bulk", "SOL 101\nCEND\nLOAD = 1\n", 3, "", 0, R"(the deck ends here, and it has CEND but no BEGIN BULK)");
  ExpectError("include-text", "BEGIN BULK\nINCLUDE 'a.bdf' b.bdf\n", 2, "INCLUDE", 0, R"(INCLUDE: unexpected text after the file name: 'b.bdf')");
  ExpectError("include-open", "BEGIN BULK\nINCLUDE 'a.bdf\n", 2, "INCLUDE", 0, R"(INCLUDE: the quoted file name is not closed)");
  for (const auto &[file, line, pattern] :
       {std::tuple<std::string, int, std::string>{"include/missing.bdf", 2, "INCLUDE: cannot read the file '.*include/no-such-file.bdf'"},
        {"include/cycle-a.bdf", 2, "INCLUDE cycle: '.*include/cycle-a.bdf' is already being read"}}) {
    try {
      ReadDeck(kData + "/" + file);
      ADD_FAILURE() << file;
    } catch (const Error &e) {
      EXPECT_EQ(e.line, line) << e.what();
      EXPECT_TRUE(std::regex_search(e.what(), std::regex(pattern))) << e.what();
    }
  }
  try {
    ReadDeck(kData + "/no-such-deck.bdf");
    ADD_FAILURE();
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find("Cannot read the Nastran deck"), std::string::npos);
  }
}

// Sections boltnet cannot represent, and conflicting constraints, name the card.
TEST(Errors, UnsupportedSectionsAndConflicts)
{
  // A membrane-only PSHELL reads, but it is not a section boltnet's shell can use.
  const Deck d = ReadDeck(Write("membrane", "BEGIN BULK\n" + kPlate + "PSHELL  2       1       .1\n"));
  std::vector<std::string> notes;
  try {
    SectionOf(d, 2, NAN, notes);
    ADD_FAILURE();
  } catch (const Error &e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex(R"(membrane.bdf:8: PSHELL 2: MID2 is blank \(membrane only\))"))) << e.what();
  }
  // MID3 blank: noted (Nastran has no transverse shear flexibility then).
  SectionOf(ReadDeck(Write("kirchhoff", "BEGIN BULK\n" + kPlate.substr(0, kPlate.rfind("PSHELL")) + "PSHELL  1       1       .1      1\n")), 1, NAN, notes);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("MID3 is blank"), std::string::npos);
  // One component enforced to two values by two SPC sets of one SPCADD.
  const Deck c = ReadDeck(Write("conflict", "BEGIN BULK\n" + kPlate + "SPC     1       1       3       .1\nSPC     2       1       3       .2\nSPCADD  3       1       2\n"));
  try {
    ExpandSpc(c, 3);
    ADD_FAILURE();
  } catch (const Error &e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex(R"(conflict.bdf:9: SPC: grid 1 component 3 is enforced to 0.2 here and to 0.1 at .*conflict.bdf:8)"))) << e.what();
  }
}
