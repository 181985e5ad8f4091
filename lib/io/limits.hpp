// The limits a scene is checked against before anything is allocated from it (docs/scenes.md,
// "Limits"). Pure C++: the fuzz targets and unit tests use them without PETSc.
#pragma once
#include <cstdint>

namespace boltnet {
namespace limits {

// Ids of patches and joints, and every other count a table gives, end up in a PetscInt, which is
// 32-bit in the PETSc that boltnet is built with: they are read as 64-bit integers and refused
// above 2^31 - 1 rather than truncated.
constexpr std::int64_t kMaxId = 2147483647;
// A generated plate (kind plate): at most 10^6 elements. 1000 x 1000 elements are 6 million dof,
// whose assembled matrix alone takes about 4 GB (54 nonzeros a row); more does not fit the
// machines boltnet runs on, and an id past this is almost always a typo.
constexpr std::int64_t kMaxPlateElements = 1000000;
// All shell nodes of a scene: 6 dof each must fit a 32-bit PetscInt with room for the rigid
// patches and joints (6 x 2e7 = 1.2e8 dof, far below 2^31).
constexpr std::int64_t kMaxSceneNodes = 20000000;
// Load steps of a whole load path (-load_steps times the segments of -load_table): each converged
// step writes a row per joint; 10^6 steps is far past any quasi-static path.
constexpr std::int64_t kMaxLoadSteps = 1000000;
// A scene file, table or mesh read into memory: 1 GiB (MPI broadcasts at most 2^31 - 1 bytes).
constexpr std::int64_t kMaxInputBytes = std::int64_t(1) << 30;
// Nesting of a YAML scene (maps and sequences): PETSc's reader recurses and its option-prefix stack
// holds 25 levels; a scene needs 4.
constexpr int kMaxYamlDepth = 20;

} // namespace limits
} // namespace boltnet
