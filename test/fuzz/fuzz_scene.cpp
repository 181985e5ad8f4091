// Fuzz target: a scene file as boltnet reads it (io/scene.cpp): the libyaml scan with its limits
// (io/scene_yaml.cpp), then PETSc's YAML options reader into a fresh options database, then the
// section check on the options it set. A refused input is a std::runtime_error or a PETSc error;
// nothing may crash, leak outside PETSc, or run away in time or memory.
#include "io/scene_yaml.hpp"

#include <petscsys.h>

#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
  // PETSc's own signal handler would hide the fuzzer's; errors are returned, not printed.
  setenv("PETSC_OPTIONS", "-no_signal_handler", 1);
  if (PetscInitializeNoArguments()) std::abort();
  if (PetscPushErrorHandler(PetscReturnErrorHandler, nullptr)) std::abort();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, size_t size)
{
  const std::string             text(reinterpret_cast<const char *>(data), size);
  std::vector<boltnet::YamlKey> keys;
  try {
    keys = boltnet::ScanSceneYaml("fuzz.yaml", text);
  } catch (const std::runtime_error &) {
    return 0;
  }
  PetscOptions opts;
  if (PetscOptionsCreate(&opts)) std::abort();
  if (!PetscOptionsInsertStringYAML(opts, text.c_str())) {
    PetscInt n;
    char   **names, **values;
    if (PetscOptionsLeftGet(opts, &n, &names, &values)) std::abort();
    const std::vector<std::string> set(names, names + n);
    (void)boltnet::CheckSceneSections("fuzz.yaml", keys, set);
    if (PetscOptionsLeftRestore(opts, &n, &names, &values)) std::abort();
  }
  if (PetscOptionsDestroy(&opts)) std::abort();
  return 0;
}
