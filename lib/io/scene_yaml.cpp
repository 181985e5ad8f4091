// The scene file before PETSc reads it: io/scene_yaml.hpp.
#include "io/scene_yaml.hpp"
#include "io/limits.hpp"

#include <yaml.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <stdexcept>

namespace boltnet {
namespace {

// boltnet's sections: the option prefixes its drivers and library read (io/scene.cpp,
// network/api.cpp, solver/loadpath.cpp, drivers/boltnet.cpp).
const char *const kBoltnetSections[] = {"scene", "nastran", "material", "joint", "coupling", "load", "patch", "output"};
// PETSc's: the first words of the options that `boltnet -scene ... -help` lists (PETSc 3.18: the
// solver objects' and the run-time options read by PetscInitialize), plus the prefixes of the
// objects and sub-solvers PETSc creates from options (vec, is, sf, petscpartitioner, sub, mg,
// fieldsplit, redundant, npc).
const char *const kPetscSections[] = {"snes", "ksp", "pc", "mat", "vec", "dm", "is", "sf", "petscsection", "section", "global", "petscpartitioner",
                                      "sub", "mg", "fieldsplit", "redundant", "npc", "all", "log", "malloc", "memory", "options", "info", "help",
                                      "version", "debugger", "start", "stop", "on", "fp", "no", "not", "shared", "tmp", "display", "petsc",
                                      "mpi", "device", "default", "root", "get"};

struct Parser {
  yaml_parser_t p;
  Parser() { yaml_parser_initialize(&p); }
  ~Parser() { yaml_parser_delete(&p); }
};
struct Event {
  yaml_event_t e;
  ~Event() { yaml_event_delete(&e); }
};

// 1-based line of a byte offset (reader errors give an offset, not a mark).
int LineOf(const std::string &text, size_t offset)
{
  return 1 + (int)std::count(text.begin(), text.begin() + (std::ptrdiff_t)std::min(offset, text.size()), '\n');
}

} // namespace

std::vector<YamlKey> ScanSceneYaml(const std::string &path, const std::string &text)
{
  // Nodes once aliases are expanded: PETSc's reader walks an alias's target again at every use,
  // so a few nested aliases could otherwise make it set billions of options.
  constexpr std::int64_t kMaxNodes = 100000;
  Parser                 parser;
  std::vector<YamlKey>   keys;
  auto fail = [&](int line, int col, const std::string &what) -> void {
    throw std::runtime_error(path + " line " + std::to_string(line) + (col > 0 ? ", column " + std::to_string(col) : std::string()) + ": " + what);
  };
  yaml_parser_set_input_string(&parser.p, reinterpret_cast<const unsigned char *>(text.data()), text.size());

  struct Level {
    bool         mapping;
    bool         expect_key; // in a mapping: the next node is a key
    std::string  anchor;
    std::int64_t start; // nodes seen when the level opened (for an anchored node's size)
    std::string  key;   // a sequence: the key it is the value of
    int          line = 0, col = 0, items = 0; // a sequence: where it starts, its items so far
  };
  std::string last_key; // the last key read, at any depth
  std::vector<Level>                  stack;
  std::map<std::string, std::int64_t> anchors; // anchor -> nodes it expands to
  std::int64_t                        nodes = 0;
  bool                                done  = false;
  while (!done) {
    Event ev;
    if (!yaml_parser_parse(&parser.p, &ev.e)) {
      const yaml_parser_t &p = parser.p;
      std::string          what = p.problem ? p.problem : "YAML syntax error";
      if (p.context) what += std::string(" (") + p.context + " at line " + std::to_string(p.context_mark.line + 1) + ")";
      if (p.error == YAML_READER_ERROR) fail(LineOf(text, p.problem_offset), 0, what + " (byte " + std::to_string(p.problem_offset) + ")");
      fail((int)p.problem_mark.line + 1, (int)p.problem_mark.column + 1, what);
    }
    const int line = (int)ev.e.start_mark.line + 1, col = (int)ev.e.start_mark.column + 1;
    const yaml_event_type_t type = ev.e.type;
    if (type == YAML_STREAM_END_EVENT) done = true;
    if (type != YAML_SCALAR_EVENT && type != YAML_ALIAS_EVENT && type != YAML_MAPPING_START_EVENT && type != YAML_SEQUENCE_START_EVENT && type != YAML_MAPPING_END_EVENT && type != YAML_SEQUENCE_END_EVENT) continue;

    const bool closing = type == YAML_MAPPING_END_EVENT || type == YAML_SEQUENCE_END_EVENT;
    if (closing) {
      const Level l = stack.back();
      // PETSc's reader sets no option for an empty list: `cases: []` would silently be no list.
      if (!l.mapping && l.items == 0) fail(l.line, l.col, "'" + l.key + "' is an empty list, which sets no option: give its items, or leave the key out");
      stack.pop_back();
      if (!l.anchor.empty()) anchors[l.anchor] = nodes - l.start;
      if (!stack.empty() && stack.back().mapping) stack.back().expect_key = !stack.back().expect_key;
      continue;
    }
    // A node: a document's root, a key, a value or a sequence item.
    const bool is_key = !stack.empty() && stack.back().mapping && stack.back().expect_key;
    if (!stack.empty() && !stack.back().mapping) ++stack.back().items;
    if (is_key && type == YAML_SCALAR_EVENT) last_key.assign(reinterpret_cast<const char *>(ev.e.data.scalar.value), ev.e.data.scalar.length);
    if (stack.empty()) {
      const bool empty_scalar = type == YAML_SCALAR_EVENT && ev.e.data.scalar.length == 0;
      if (type != YAML_MAPPING_START_EVENT && !empty_scalar) fail(line, col, "a scene is a map of sections (name: value), not a single value or a list");
    }
    if (is_key && type != YAML_SCALAR_EVENT && type != YAML_ALIAS_EVENT) fail(line, col, "a key must be a plain name, not a map or a list");
    if (type == YAML_ALIAS_EVENT) {
      const std::string a = reinterpret_cast<const char *>(ev.e.data.alias.anchor);
      if (!anchors.count(a)) fail(line, col, "alias *" + a + " names no complete anchor before it");
      nodes += anchors[a];
    } else ++nodes;
    if (nodes > kMaxNodes) fail(line, col, "more than " + std::to_string(kMaxNodes) + " values once aliases are expanded");
    if (is_key && stack.size() == 1 && type == YAML_SCALAR_EVENT) keys.push_back({std::string(reinterpret_cast<const char *>(ev.e.data.scalar.value), ev.e.data.scalar.length), line});

    const unsigned char *anchor = type == YAML_SCALAR_EVENT ? ev.e.data.scalar.anchor : type == YAML_MAPPING_START_EVENT ? ev.e.data.mapping_start.anchor : type == YAML_SEQUENCE_START_EVENT ? ev.e.data.sequence_start.anchor : nullptr;
    if (type == YAML_MAPPING_START_EVENT || type == YAML_SEQUENCE_START_EVENT) {
      if ((int)stack.size() >= limits::kMaxYamlDepth) fail(line, col, "nested deeper than " + std::to_string(limits::kMaxYamlDepth) + " levels");
      stack.push_back({type == YAML_MAPPING_START_EVENT, true, anchor ? reinterpret_cast<const char *>(anchor) : "", nodes, last_key, line, col, 0});
      continue;
    }
    if (anchor) anchors[reinterpret_cast<const char *>(anchor)] = 1;
    if (!stack.empty() && stack.back().mapping) stack.back().expect_key = !stack.back().expect_key;
  }
  return keys;
}

std::string SectionOf(const std::string &option)
{
  return option.substr(0, option.find('_'));
}

bool IsSceneSection(const std::string &section)
{
  for (const char *s : kBoltnetSections)
    if (section == s) return true;
  for (const char *s : kPetscSections)
    if (section == s) return true;
  return false;
}

std::string SceneSectionList()
{
  std::string s;
  for (const char *b : kBoltnetSections) s += (s.empty() ? "" : ", ") + std::string(b);
  return s;
}

std::string CheckSceneSections(const std::string &path, const std::vector<YamlKey> &keys, const std::vector<std::string> &options)
{
  std::map<std::string, std::vector<std::string>> unknown; // section -> options
  for (const std::string &o : options)
    if (!IsSceneSection(SectionOf(o))) unknown[SectionOf(o)].push_back("-" + o);
  if (unknown.empty()) return "";
  std::string msg;
  for (const auto &[section, opts] : unknown) {
    int line = 0;
    for (const YamlKey &k : keys)
      if (line == 0 && SectionOf(k.name) == section) line = k.line;
    std::string list;
    for (size_t i = 0; i < opts.size() && i < 4; ++i) list += (i ? ", " : "") + opts[i];
    if (opts.size() > 4) list += ", ...";
    msg += (msg.empty() ? "" : "; ") + path + (line ? " line " + std::to_string(line) : std::string()) + ": unknown section '" + section + "' (" + list + ")";
  }
  return msg + ". A scene's sections are " + SceneSectionList() + " and the prefixes of PETSc's options (snes, ksp, pc, mat, log, ...): misspelled?";
}

} // namespace boltnet
