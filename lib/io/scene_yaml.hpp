// The scene file before PETSc reads it: YAML syntax errors with their line and column, the shape
// PETSc's YAML options reader accepts, bounded nesting and alias expansion, and the top-level
// sections. Pure C++ over libyaml (no PETSc, no MPI), so that the fuzz target calls it directly.
#pragma once
#include <string>
#include <vector>

namespace boltnet {

struct YamlKey {
  std::string name;
  int         line; // 1-based
};

// Scans the whole text (every document of the stream). Throws std::runtime_error naming
// "<path> line L, column C" for a syntax error, a document that is not a map, a key that is not a
// plain scalar, nesting deeper than limits::kMaxYamlDepth, an unknown alias, more nodes than
// limits allow once aliases are expanded, or an empty list (PETSc's reader would set no option). Returns the top-level keys with their lines.
std::vector<YamlKey> ScanSceneYaml(const std::string &path, const std::string &text);

// The section an option belongs to: its name up to the first '_' ("load" for "load_steps").
std::string SectionOf(const std::string &option);

// Sections a scene may set: boltnet's own (scene, material, joint, coupling, load, patch, output)
// and the prefixes of the PETSc options this program reads (snes, ksp, pc, mat, ..., log, malloc,
// options, ...). true if `section` is one of them.
bool IsSceneSection(const std::string &section);
// Comma-separated list of boltnet's own sections, for messages.
std::string SceneSectionList();

// Options (names without '-') set by the scene file at `path`, whose top-level keys are `keys`:
// returns "" if every option belongs to a known section, else a message naming the unknown
// section(s), the line of its key when there is one, and the options it would have set.
std::string CheckSceneSections(const std::string &path, const std::vector<YamlKey> &keys, const std::vector<std::string> &options);

} // namespace boltnet
