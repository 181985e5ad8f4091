// The scene parsers on their own (requirement: every bad input caught before it is narrowed or
// allocated, with a message naming file, line and column): io/table.hpp, io/scene_yaml.hpp and the
// Gmsh parser. References are the inputs' own definitions: the value written in the text, the line
// it is on, the limit in io/limits.hpp.
#include "io/limits.hpp"
#include "io/scene_yaml.hpp"
#include "io/table.hpp"
#include "mesh/gmsh.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>
#include <string>

using namespace boltnet;

namespace {

// The message of the std::runtime_error that f throws ("" if none).
template <class F>
std::string Error(F &&f)
{
  try {
    f();
  } catch (const std::runtime_error &e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST(Table, HeaderRowsCommentsAndBom)
{
  const Table t = ParseTable("t.csv", "\xEF\xBB\xBFid,kind\n# comment\n\n 3 , rigid \n", {"id", "kind"});
  ASSERT_EQ(t.header.size(), 2u);
  EXPECT_EQ(t.header[0], "id"); // the byte-order mark is not part of the name
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_EQ(t.lines[0], 4);
  EXPECT_EQ(TableInt(t, 0, "id", 0, limits::kMaxId), 3);
  EXPECT_EQ(TableCell(t, 0, "kind"), "rigid");
}

TEST(Table, BadTables)
{
  EXPECT_EQ(Error([] { ParseTable("t.csv", "id,x,x\n1,2,3\n", {}); }), "t.csv line 1: column 'x' appears twice in the header");
  EXPECT_EQ(Error([] { ParseTable("t.csv", "id,,x\n", {}); }), "t.csv line 1: the header has an empty column name");
  EXPECT_EQ(Error([] { ParseTable("t.csv", "id,x\n1\n", {}); }), "t.csv line 2: 1 values for 2 columns");
  EXPECT_EQ(Error([] { ParseTable("t.csv", "# only a comment\n", {}); }), "t.csv: empty table (a header line is needed)");
  EXPECT_EQ(Error([] { ParseTable("t.csv", "id,x\n", {"kind"}); }), "t.csv: missing column 'kind'");
}

TEST(Table, IntegersAre64BitAndRangeChecked)
{
  const Table t = ParseTable("t.csv", "n\n99999999999\n-2147483649\n99999999999999999999\n1e3\n+7\n", {});
  EXPECT_EQ(Error([&] { TableInt(t, 0, "n", 0, limits::kMaxId); }), "t.csv line 2, column 'n': 99999999999 is out of range: it must lie in [0, 2147483647]");
  EXPECT_EQ(Error([&] { TableInt(t, 1, "n", 1, 1000000); }), "t.csv line 3, column 'n': -2147483649 is out of range: it must lie in [1, 1000000]");
  EXPECT_EQ(Error([&] { TableInt(t, 2, "n", 0, limits::kMaxId); }), "t.csv line 4, column 'n': '99999999999999999999' is out of range: it must lie in [0, 2147483647]");
  EXPECT_EQ(Error([&] { TableInt(t, 3, "n", 0, limits::kMaxId); }), "t.csv line 5, column 'n': '1e3' is not a whole number");
  EXPECT_EQ(TableInt(t, 4, "n", 0, 10), 7);
}

TEST(Table, Reals)
{
  const Table t = ParseTable("t.csv", "x\n2.5e3\nnan\n1e400\n", {});
  EXPECT_EQ(TableReal(t, 0, "x"), 2500.0);
  EXPECT_EQ(Error([&] { TableReal(t, 1, "x"); }), "t.csv line 3, column 'x': 'nan' is not a number");
  EXPECT_EQ(Error([&] { TableReal(t, 2, "x"); }), "t.csv line 4, column 'x': '1e400' is not a number");
}

TEST(SceneYaml, KeysAndSections)
{
  const std::string text = "scene:\n  name: a\nlod:\n  steps: 3\nload_max: 2\n";
  const auto        keys = ScanSceneYaml("s.yaml", text);
  ASSERT_EQ(keys.size(), 3u);
  EXPECT_EQ(keys[1].name, "lod");
  EXPECT_EQ(keys[1].line, 3);
  EXPECT_EQ(CheckSceneSections("s.yaml", keys, {"scene_name", "load_max", "snes_rtol", "mat_mumps_icntl_14", "log_view"}), "");
  const std::string m = CheckSceneSections("s.yaml", keys, {"scene_name", "lod_steps"});
  EXPECT_EQ(m.rfind("s.yaml line 3: unknown section 'lod' (-lod_steps)", 0), 0u) << m;
  // A top-level key that is itself an option ("lod_steps: 3") belongs to the section "lod".
  EXPECT_NE(CheckSceneSections("s.yaml", ScanSceneYaml("s.yaml", "lod_steps: 3\n"), {"lod_steps"}).find("s.yaml line 1: unknown section 'lod'"), std::string::npos);
}

TEST(SceneYaml, SyntaxAndShape)
{
  EXPECT_EQ(Error([] { ScanSceneYaml("s.yaml", "load:\n  table: [1, 2\n  steps: 4\n"); }), "s.yaml line 3, column 8: did not find expected ',' or ']' (while parsing a flow sequence at line 2)");
  EXPECT_EQ(Error([] { ScanSceneYaml("s.yaml", "- a\n- b\n"); }), "s.yaml line 1, column 1: a scene is a map of sections (name: value), not a single value or a list");
  EXPECT_EQ(Error([] { ScanSceneYaml("s.yaml", "? [a, b]\n: 1\n"); }), "s.yaml line 1, column 3: a key must be a plain name, not a map or a list");
  EXPECT_EQ(Error([] { ScanSceneYaml("s.yaml", "a: *nothing\n"); }), "s.yaml line 1, column 4: alias *nothing names no complete anchor before it");
  EXPECT_NE(Error([] { ScanSceneYaml("s.yaml", std::string("a: b\0c\n", 7)); }).find("s.yaml line 1: control characters are not allowed"), std::string::npos);
  EXPECT_EQ(Error([] { ScanSceneYaml("s.yaml", ""); }), ""); // an empty scene file sets nothing
  // PETSc's reader sets no option for an empty list: `cases: []` would be no list at all (load cases,
  // docs/scenes.md); a list with items is fine.
  EXPECT_EQ(Error([] { ScanSceneYaml("s.yaml", "load:\n  cases: []\n"); }), "s.yaml line 2, column 10: 'cases' is an empty list, which sets no option: give its items, or leave the key out");
  EXPECT_EQ(Error([] { ScanSceneYaml("s.yaml", "load:\n  cases: [a, b]\n  table: [1, -1]\n"); }), "");
}

TEST(SceneYaml, NestingAndAliasesAreBounded)
{
  std::string deep = "a: ";
  for (int i = 0; i < 30; ++i) deep += "[";
  EXPECT_EQ(Error([&] { ScanSceneYaml("s.yaml", deep); }), "s.yaml line 1, column " + std::to_string(4 + limits::kMaxYamlDepth - 1) + ": nested deeper than " + std::to_string(limits::kMaxYamlDepth) + " levels");
  // Each level doubles the last: 2^20 values from 21 lines.
  std::string laughs = "l0: &l0 [x, x]\n";
  for (int i = 1; i <= 20; ++i) laughs += "l" + std::to_string(i) + ": &l" + std::to_string(i) + " [*l" + std::to_string(i - 1) + ", *l" + std::to_string(i - 1) + "]\n";
  EXPECT_NE(Error([&] { ScanSceneYaml("s.yaml", laughs); }).find("values once aliases are expanded"), std::string::npos);
}

TEST(GmshText, CountsAreCheckedNotAllocated)
{
  const std::string head = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  // A node block announcing 10^18 nodes ends at the end of the file, not in an allocation.
  EXPECT_EQ(Error([&] { ParseGmsh("m.msh", head + "$Nodes\n1 1 1 1\n2 1 0 1000000000000000000\n1\n"); }), "Mesh file 'm.msh' line 7: unexpected end of file");
  EXPECT_EQ(Error([&] { ParseGmsh("m.msh", head + "$Nodes\n-1 1 1 1\n"); }), "Mesh file 'm.msh' line 5: the number of node blocks is negative");
  EXPECT_EQ(Error([&] { ParseGmsh("m.msh", head + "$Entities\n0 0 1 0\n1 0 0 0 1 1 0 1 -2147483648 0\n"); }), "Mesh file 'm.msh' line 6: physical tag out of range");
  EXPECT_EQ(Error([&] { ParseGmsh("m.msh", head + "$Elements\n1 1 1 1\n2 1 3 1\n1 1 2 2 3\n"); }), "Mesh file 'm.msh' line 7: a quadrangle names the same node twice");
}

// The nodes a Gmsh file declares, read from its $Nodes header alone (what a part is weighed by before
// one rank reads it): on the two-part test mesh, the nodes the full reader finds in its two parts
// (they share none); -1 for a missing file and for a file without $Nodes; CRLF line ends read alike.
TEST(GmshText, DeclaredNodeCount)
{
  const std::string mesh = std::string(BOLTNET_TEST_DATA) + "/two-parts.msh";
  size_t            parsed = 0;
  for (const auto &[name, part] : ReadGmsh(mesh)) parsed += part.x.size();
  EXPECT_EQ(GmshNodeCount(mesh), (long long)parsed);
  EXPECT_EQ(GmshNodeCount(std::string(BOLTNET_TEST_DATA) + "/no-such-mesh.msh"), -1);
  const std::string dir = ::testing::TempDir();
  auto              write = [&](const std::string &name, const std::string &text) {
    std::ofstream(dir + name, std::ios::binary) << text;
    return dir + name;
  };
  EXPECT_EQ(GmshNodeCount(write("no-nodes.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Elements\n0 0 0 0\n$EndElements\n")), -1);
  EXPECT_EQ(GmshNodeCount(write("crlf.msh", "$MeshFormat\r\n4.1 0 8\r\n$EndMeshFormat\r\n$Nodes\r\n2 7 1 7\r\n")), 7);
}
