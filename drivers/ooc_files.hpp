// MUMPS's out-of-core files (ICNTL(22) = 1: factors kept on disk, docs/solver.md) outlive a run
// that is stopped: MUMPS deletes them when its instance is destroyed, which a signal (a job
// scheduler's SIGTERM at its time limit, a kill, timeout(1)) or an MPI_Abort never reaches, and one
// killed medium junction left 16 GB in /tmp. So each driver process names its files itself: unless
// the user chose a prefix, it sets MUMPS_OOC_PREFIX to "boltnet<pid>" (MUMPS then names its files
// <dir>/boltnet<pid>_mumps_..., in MUMPS_OOC_TMPDIR or /tmp: MUMPS's users' guide, "Out-of-core
// facility"), and removes those files when a signal stops it (before PETSc's default handler ends
// the job) and when it stops on an error. SIGKILL cannot be caught: its files stay.
#pragma once
#include <petscsys.h>

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <string>

namespace boltnet {

struct OocFiles {
  std::string dir;    // where MUMPS writes them: MUMPS_OOC_TMPDIR, else /tmp
  std::string prefix; // the file names' start, "boltnet<pid>_mumps_"; empty: the user's own prefix
};

// Sets MUMPS_OOC_PREFIX for this process unless the user has (then nothing is removed: the files
// may be the user's), before any factorisation.
inline OocFiles OocFilesSetUp()
{
  OocFiles    f;
  const char *dir = std::getenv("MUMPS_OOC_TMPDIR");
  f.dir           = dir && dir[0] ? dir : "/tmp";
  if (!std::getenv("MUMPS_OOC_PREFIX")) {
    const std::string mine = "boltnet" + std::to_string((long long)getpid());
    if (setenv("MUMPS_OOC_PREFIX", mine.c_str(), 0) == 0) f.prefix = mine + "_mumps_";
  }
  return f;
}

// Removes this process's out-of-core files. Called from a signal handler too, as the process ends:
// readdir and unlinkat on the names as they are, no copies (opendir allocates, which POSIX does
// not count as async-signal-safe; PETSc's own handler, which runs next, does more).
inline void OocFilesRemove(const OocFiles &f)
{
  if (f.prefix.empty()) return;
  DIR *d = opendir(f.dir.c_str());
  if (!d) return;
  const int fd = dirfd(d);
  for (struct dirent *e = readdir(d); e; e = readdir(d))
    if (std::strncmp(e->d_name, f.prefix.c_str(), f.prefix.size()) == 0) (void)unlinkat(fd, e->d_name, 0);
  closedir(d);
}

// PETSc's signal handler with the files removed first (PetscPushSignalHandler's ctx: the OocFiles):
// for the signals PETSc catches (SIGSEGV, SIGBUS, SIGFPE, SIGHUP, SIGQUIT, ...).
inline PetscErrorCode OocFilesSignalHandler(int sig, void *ctx)
{
  OocFilesRemove(*static_cast<const OocFiles *>(ctx));
  return PetscSignalHandlerDefault(sig, nullptr);
}

// PETSc leaves SIGTERM alone under Open MPI (which stops its ranks with it) and does not catch
// SIGINT or SIGXCPU either: those are how a job is stopped (a scheduler's time limit, timeout(1),
// Ctrl-C through mpirun). A handler of our own removes the files and then lets the signal do what
// it did (default action, raised again). Such a handler takes no context: the files' description
// is reached through this one pointer, set once by OocFilesCatchStops.
inline const OocFiles *&OocFilesOfStops()
{
  static const OocFiles *files = nullptr;
  return files;
}

extern "C" inline void OocFilesOnStop(int sig)
{
  if (const OocFiles *f = OocFilesOfStops()) OocFilesRemove(*f);
  signal(sig, SIG_DFL);
  raise(sig);
}

// Catches SIGTERM, SIGINT and SIGXCPU where nothing else does (their action is still the default).
inline void OocFilesCatchStops(const OocFiles &f)
{
  if (f.prefix.empty()) return;
  OocFilesOfStops() = &f;
  struct sigaction sa {};
  sa.sa_handler = OocFilesOnStop;
  sigemptyset(&sa.sa_mask);
  for (int s : {SIGTERM, SIGINT, SIGXCPU}) {
    struct sigaction old {};
    if (sigaction(s, nullptr, &old) == 0 && old.sa_handler == SIG_DFL) (void)sigaction(s, &sa, nullptr);
  }
}

} // namespace boltnet
