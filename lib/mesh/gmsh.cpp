#include "mesh/gmsh.hpp"
#include "io/limits.hpp"

#include <algorithm>
#include <climits>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace boltnet {
namespace {

class Reader {
public:
  Reader(const std::string &path, const std::string &text) : path_(path), in_(text) {}
  // Next non-empty line.
  std::string line()
  {
    std::string s;
    while (std::getline(in_, s)) {
      ++lineno_;
      if (!s.empty() && s.back() == '\r') s.pop_back();
      if (s.find_first_not_of(" \t") != std::string::npos) return s;
    }
    fail("unexpected end of file");
  }
  [[noreturn]] void fail(const std::string &what) const
  {
    throw std::runtime_error("Mesh file '" + path_ + "' line " + std::to_string(lineno_) + ": " + what);
  }
  template <class T>
  T get(std::istringstream &ss, const char *what)
  {
    T v;
    if (!(ss >> v)) fail(std::string("expected ") + what);
    return v;
  }
  // A count: never negative. The items it announces are read one line at a time, so a count larger
  // than the file ends at "unexpected end of file" instead of a huge allocation.
  long count(std::istringstream &ss, const char *what)
  {
    const long n = get<long>(ss, what);
    if (n < 0) fail(std::string(what) + " is negative");
    return n;
  }
  bool eof() { return !in_.good(); }
  std::string path_;

private:
  std::istringstream in_;
  int           lineno_ = 0;
};

// Gmsh's element types (its reference manual, "MSH file format"): the node count of the ones read
// here, -1 for the others.
int TypeNodes(int type) { return type == 1 ? 2 : type == 2 ? 3 : type == 3 ? 4 : type == 15 ? 1 : -1; }

// The name of a type boltnet does not read, for the message that refuses it.
std::string TypeName(int type)
{
  static const char *const names[] = {nullptr, nullptr, nullptr, nullptr, "4-node tetrahedra", "8-node hexahedra", "6-node prisms", "5-node pyramids", "3-node lines", "6-node triangles", "9-node quadrangles", "10-node tetrahedra", "27-node hexahedra", "18-node prisms", "14-node pyramids", nullptr, "8-node quadrangles", "20-node hexahedra", "15-node prisms", "13-node pyramids"};
  const std::string n = "element type " + std::to_string(type);
  return type >= 0 && type < (int)(sizeof names / sizeof names[0]) && names[type] ? n + " (" + names[type] + ")" : n;
}

} // namespace

std::map<std::string, ShellMesh> ReadGmsh(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("Cannot read the mesh file '" + path + "'");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw std::runtime_error("Cannot read the mesh file '" + path + "'");
  if ((long long)ss.tellp() > limits::kMaxInputBytes) throw std::runtime_error("Mesh file '" + path + "' is larger than " + std::to_string(limits::kMaxInputBytes) + " bytes (docs/scenes.md, \"Limits\")");
  return ParseGmsh(path, ss.str());
}

long long GmshNodeCount(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  std::string   line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line == "$Elements") break; // MSH 4.1 puts $Nodes first
    if (line != "$Nodes" || !std::getline(in, line)) continue;
    std::istringstream ss(line);
    long long          blocks, n;
    return (ss >> blocks >> n) && n >= 0 ? n : -1;
  }
  return -1;
}

std::map<std::string, ShellMesh> ParseGmsh(const std::string &path, const std::string &text)
{
  Reader                                    r(path, text);
  std::map<std::pair<int, int>, std::string> names;          // (dim, physical tag) -> name
  std::map<std::pair<int, int>, std::vector<int>> physOf;   // (dim, entity tag) -> physical tags
  std::map<long, std::array<double, 3>>     nodes;           // node tag -> coordinates
  std::map<std::string, std::vector<std::array<long, 4>>> partElems; // triangles end with -1
  std::map<std::string, std::set<long>>     groupNodes;      // every physical group -> node tags
  bool                                      format = false;

  std::string s;
  while (true) {
    try {
      s = r.line();
    } catch (const std::runtime_error &) {
      break; // end of file between sections
    }
    if (s == "$MeshFormat") {
      std::istringstream ss(r.line());
      const std::string  version = r.get<std::string>(ss, "a version");
      const int          binary  = r.get<int>(ss, "the file type");
      if (version.rfind("4.1", 0) != 0) r.fail("MSH version " + version + " is not supported: save as MSH 4.1 (Gmsh 4 default)");
      if (binary != 0) r.fail("binary MSH is not supported: save as ASCII");
      format = true;
    } else if (s == "$PhysicalNames") {
      std::istringstream ss(r.line());
      const long         n = r.count(ss, "the number of physical names");
      for (long i = 0; i < n; ++i) {
        std::istringstream ls(r.line());
        const int          dim = r.get<int>(ls, "a dimension"), tag = r.get<int>(ls, "a physical tag");
        std::string        rest;
        std::getline(ls, rest);
        const size_t a = rest.find('"'), b = rest.rfind('"');
        if (a == std::string::npos || b == a) r.fail("expected a quoted physical name");
        names[{dim, tag}] = rest.substr(a + 1, b - a - 1);
      }
    } else if (s == "$Entities") {
      std::istringstream ss(r.line());
      long               count[4];
      for (long &c : count) c = r.count(ss, "entity counts");
      for (int dim = 0; dim < 4; ++dim)
        for (long i = 0; i < count[dim]; ++i) {
          std::istringstream ls(r.line());
          const int          tag = r.get<int>(ls, "an entity tag");
          for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) r.get<double>(ls, "a bounding box");
          const long nphys = r.count(ls, "the number of physical tags");
          for (long k = 0; k < nphys; ++k) {
            const int ph = r.get<int>(ls, "a physical tag"); // its sign is the orientation
            if (ph == INT_MIN) r.fail("physical tag out of range");
            physOf[{dim, tag}].push_back(ph < 0 ? -ph : ph);
          }
        }
    } else if (s == "$Nodes") {
      if (!format) r.fail("$Nodes before $MeshFormat: not an MSH file");
      std::istringstream ss(r.line());
      const long         blocks = r.count(ss, "the number of node blocks");
      for (long b = 0; b < blocks; ++b) {
        std::istringstream hs(r.line());
        const int          dim = r.get<int>(hs, "an entity dimension"), tag = r.get<int>(hs, "an entity tag");
        const int          param = r.get<int>(hs, "the parametric flag");
        const long         n     = r.count(hs, "the number of nodes in the block");
        std::vector<long>  tags;
        for (long i = 0; i < n; ++i) {
          std::istringstream ls(r.line());
          tags.push_back(r.get<long>(ls, "a node tag"));
        }
        for (long i = 0; i < n; ++i) {
          std::istringstream ls(r.line());
          std::array<double, 3> x;
          for (double &c : x) c = r.get<double>(ls, "node coordinates");
          nodes[tags[i]] = x;
          (void)param;
        }
        for (int ph : physOf[{dim, tag}]) groupNodes[names.count({dim, ph}) ? names[{dim, ph}] : std::to_string(ph)].insert(tags.begin(), tags.end());
      }
    } else if (s == "$Elements") {
      if (!format) r.fail("$Elements before $MeshFormat: not an MSH file");
      std::istringstream ss(r.line());
      const long         blocks = r.count(ss, "the number of element blocks");
      for (long b = 0; b < blocks; ++b) {
        std::istringstream hs(r.line());
        const int          dim = r.get<int>(hs, "an entity dimension"), tag = r.get<int>(hs, "an entity tag");
        const int          type = r.get<int>(hs, "an element type");
        const long         n    = r.count(hs, "the number of elements in the block");
        const int          nn   = TypeNodes(type);
        if (nn < 0) r.fail(TypeName(type) + " is not supported: boltnet reads 3-node triangles (type 2) and 4-node quadrangles (type 3) in the parts, lines and points in the node sets (save a first-order mesh)");
        std::vector<std::string> groups;
        for (int ph : physOf[{dim, tag}]) groups.push_back(names.count({dim, ph}) ? names[{dim, ph}] : std::to_string(ph));
        for (long i = 0; i < n; ++i) {
          std::istringstream ls(r.line());
          r.get<long>(ls, "an element tag");
          std::array<long, 4> q = {-1, -1, -1, -1};
          for (int k = 0; k < nn; ++k) {
            q[k] = r.get<long>(ls, "element nodes");
            if (q[k] <= 0) r.fail("element node tag " + std::to_string(q[k]) + " is not positive"); // -1 marks a triangle's fourth
          }
          if (type == 2 || type == 3)
            for (int a = 0; a < nn; ++a)
              for (int b = a + 1; b < nn; ++b)
                if (q[a] == q[b]) r.fail(std::string(type == 2 ? "a triangle" : "a quadrangle") + " names the same node twice");
          for (const std::string &g : groups) {
            for (int k = 0; k < nn; ++k) groupNodes[g].insert(q[k]);
            if (dim != 2) continue;
            if (type != 2 && type != 3) r.fail("part '" + g + "' (a physical surface) holds " + TypeName(type) + ": a shell part is made of 3-node triangles and 4-node quadrangles");
            partElems[g].push_back(q);
          }
        }
      }
    }
  }
  if (!format) throw std::runtime_error("Mesh file '" + path + "' is not a Gmsh mesh (no $MeshFormat section)");
  if (partElems.empty()) throw std::runtime_error("Mesh file '" + path + "' has no physical surface of triangles or quadrangles: name each part with a physical surface group");

  std::map<std::string, ShellMesh> parts;
  for (auto &[name, elems] : partElems) {
    ShellMesh          &m = parts[name];
    std::map<long, int> local;
    for (auto &q : elems) {
      MeshElement e = {-1, -1, -1, -1};
      for (int k = 0; k < (q[3] < 0 ? 3 : 4); ++k) {
        auto it = local.find(q[k]);
        if (it == local.end()) {
          auto xn = nodes.find(q[k]);
          if (xn == nodes.end()) throw std::runtime_error("Mesh file '" + path + "': part '" + name + "' uses node " + std::to_string(q[k]) + " which is not in $Nodes");
          it = local.emplace(q[k], static_cast<int>(m.x.size())).first;
          m.x.push_back(xn->second);
        }
        e[k] = it->second;
      }
      m.elems.push_back(e);
    }
    for (auto &[g, tags] : groupNodes) {
      if (g == name) continue;
      std::vector<int> set;
      for (long t : tags) {
        auto it = local.find(t);
        if (it != local.end()) set.push_back(it->second);
      }
      if (!set.empty()) m.node_sets[g] = set;
    }
  }
  return parts;
}

} // namespace boltnet
