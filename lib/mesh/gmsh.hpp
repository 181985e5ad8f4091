// Reader of Gmsh meshes (MSH 4.1 ASCII, what Gmsh 4 writes by default): each physical surface group
// is a part (a ShellMesh of 3-node triangles and 4-node quadrangles); physical point, curve and surface groups become node sets of every part
// that holds their nodes.
#pragma once

#include "mesh/mesh.hpp"

#include <map>
#include <string>

namespace boltnet {

// Throws std::runtime_error with a message naming the file (and the line where it applies) for a
// missing file, a file that is not an MSH 4.1 ASCII mesh, an element type other than 3-node
// triangles and 4-node quadrangles in a part (or lines and points in a node set), naming the type.
std::map<std::string, ShellMesh> ReadGmsh(const std::string &path);
// The number of nodes the file declares (its $Nodes header), read without parsing the rest: what a
// part read later (model/model.hpp, ShellPart::read) weighs before it is read. -1 where the file
// cannot be read or declares none; the full read then says why.
long long GmshNodeCount(const std::string &path);
// The same from the file's text (path names it in messages): the pure parser, for tests and fuzzing.
// Counts are checked before use and nothing is allocated from a count, only from lines read.
std::map<std::string, ShellMesh> ParseGmsh(const std::string &path, const std::string &text);

} // namespace boltnet
