// Where the boltnet driver finds a scene (docs/install.md): -scene names a file (absolute, or
// relative to the current directory), or, when there is no such file and the name has no '/', a
// scene of the scenes directory that comes with the program: <bindir>/BOLTNET_SCENES_FROM_BINDIR,
// i.e. <prefix>/share/boltnet/scenes once installed (drivers/CMakeLists.txt sets the relative path;
// the build tree links build/share/boltnet/scenes to share/scenes). `-scene fig3c` and
// `-scene fig3c.yaml` both find <scenes>/fig3c.yaml. Rank 0 looks, as it reads the scene.
#pragma once
#include <petscsys.h>

#include <filesystem>
#include <string>
#include <system_error>

#ifndef BOLTNET_SCENES_FROM_BINDIR
#error "drivers/CMakeLists.txt defines BOLTNET_SCENES_FROM_BINDIR"
#endif

namespace boltnet {

// The scenes directory next to the running program ("" if /proc/self/exe cannot be read).
inline std::string InstalledScenesDir()
{
  std::error_code             ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  return (exe.parent_path() / BOLTNET_SCENES_FROM_BINDIR).lexically_normal().string();
}

// The file -scene `given` names, on every rank.
inline PetscErrorCode FindScene(MPI_Comm comm, const char given[], std::string *path)
{
  PetscMPIInt rank;
  char        found[PETSC_MAX_PATH_LEN] = "", dir[PETSC_MAX_PATH_LEN] = "";
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    std::error_code   ec;
    const std::string name(given), scenes = InstalledScenesDir();
    std::string       result = name; // a path: SceneInsertOptionsFile names it if it is missing
    if (!std::filesystem::exists(name, ec) && name.find('/') == std::string::npos) {
      result.clear();
      for (const std::string &candidate : {scenes + "/" + name, scenes + "/" + name + ".yaml"}) {
        if (!scenes.empty() && std::filesystem::is_regular_file(candidate, ec)) {
          result = candidate;
          break;
        }
      }
    }
    PetscCall(PetscStrncpy(found, result.c_str(), sizeof(found)));
    PetscCall(PetscStrncpy(dir, scenes.c_str(), sizeof(dir)));
  }
  PetscCallMPI(MPI_Bcast(found, sizeof(found), MPI_CHAR, 0, comm));
  PetscCallMPI(MPI_Bcast(dir, sizeof(dir), MPI_CHAR, 0, comm));
  PetscCheck(found[0], comm, PETSC_ERR_FILE_OPEN, "-scene %s: no such file here, and no scene %s or %s.yaml in %s (the scenes that come with boltnet)", given, given, given, dir[0] ? dir : "(the program's directory is unknown)");
  *path = found;
  PetscFunctionReturn(0);
}

} // namespace boltnet
