// MUMPS's out-of-core files (ICNTL(22) = 1: factors kept on disk, docs/solver.md) outlive a run
// that is stopped: MUMPS deletes them when its instance is destroyed, which a signal (a job
// scheduler's SIGTERM at its time limit, a kill, timeout(1)) or an MPI_Abort never reaches, and one
// killed medium junction left 16 GB in /tmp. So each driver process names its files itself: unless
// the user chose a prefix, it sets MUMPS_OOC_PREFIX to "boltnet<host>_<pid>" (MUMPS then names its
// files <dir>/boltnet<host>_<pid>_mumps_...: MUMPS's users' guide, "Out-of-core facility"; <host> a
// hash of the host name, since a scratch directory may be shared by the processes of several
// nodes), and removes those files when a signal stops it and when it stops on an error. SIGKILL
// cannot be caught: its files stay.
//
// A signal handler takes no context, so the description lives in static storage (one per process,
// OocFilesOfProcess), set before any factorisation and kept until the handlers are restored; the
// removal uses only async-signal-safe system calls on a directory opened beforehand.
#pragma once
#include <petscsys.h>

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace boltnet {

struct OocFiles {
  int    dir = -1;     // the directory MUMPS writes them in, opened at set-up (-1: nothing to remove)
  char   prefix[96]{}; // the names' start, "boltnet<host>_<pid>_mumps_"
  size_t len = 0;
  static constexpr int kStops[3] = {SIGTERM, SIGINT, SIGXCPU};
  bool             caught[3]{}; // our handler installed, the former action saved
  struct sigaction former[3]{};
};

inline OocFiles &OocFilesOfProcess()
{
  static OocFiles files;
  return files;
}

// Before any factorisation: MUMPS_OOC_PREFIX for this process, unless the user has set it (then
// nothing is removed: the files may be the user's). The directory is -mat_mumps_ooc_tmpdir if
// given (PETSc passes it to MUMPS), else MUMPS_OOC_TMPDIR, else /tmp; an empty MUMPS_OOC_TMPDIR,
// which MUMPS takes as it is, is left alone.
inline void OocFilesSetUp(const char *option_dir)
{
  OocFiles   &f   = OocFilesOfProcess();
  const char *env = std::getenv("MUMPS_OOC_TMPDIR");
  const char *dir = option_dir && option_dir[0] ? option_dir : env ? env : "/tmp";
  if (std::getenv("MUMPS_OOC_PREFIX") || !dir[0]) return;
  char host[256] = "";
  (void)gethostname(host, sizeof host - 1);
  std::uint32_t h = 2166136261u; // FNV-1a
  for (const char *c = host; *c; ++c) h = (h ^ (unsigned char)*c) * 16777619u;
  char mine[64];
  std::snprintf(mine, sizeof mine, "boltnet%08x_%lld", (unsigned)h, (long long)getpid());
  if (setenv("MUMPS_OOC_PREFIX", mine, 0) != 0) return;
  const int n = std::snprintf(f.prefix, sizeof f.prefix, "%s_mumps_", mine);
  f.len       = n > 0 && (size_t)n < sizeof f.prefix ? (size_t)n : 0;
  f.dir       = f.len ? open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC) : -1;
}

// Removes this process's out-of-core files: getdents64 and unlinkat on the directory opened at
// set-up, safe in a signal handler. Scans again after a pass that removed something (removing
// entries while reading a directory may hide others), at most a few times.
inline void OocFilesRemove()
{
  const OocFiles &f = OocFilesOfProcess();
  if (f.dir < 0 || !f.len) return;
  alignas(8) char buf[8192];
  for (int pass = 0; pass < 8; ++pass) {
    bool removed = false;
    if (lseek(f.dir, 0, SEEK_SET) < 0) return;
    for (ssize_t n; (n = getdents64(f.dir, buf, sizeof buf)) > 0;)
      for (ssize_t at = 0; at < n;) {
        const struct dirent64 *e = reinterpret_cast<const struct dirent64 *>(buf + at);
        at += e->d_reclen;
        size_t k = 0;
        while (k < f.len && e->d_name[k] == f.prefix[k]) ++k;
        if (k == f.len && unlinkat(f.dir, e->d_name, 0) == 0) removed = true;
      }
    if (!removed) return;
  }
}

// PETSc's signal handler with the files removed first: for the signals PETSc catches (SIGSEGV,
// SIGBUS, SIGFPE, SIGHUP, SIGQUIT, ...; PetscPushSignalHandler).
inline PetscErrorCode OocFilesSignalHandler(int sig, void *)
{
  OocFilesRemove();
  return PetscSignalHandlerDefault(sig, nullptr);
}

// PETSc leaves SIGTERM alone under Open MPI (which stops its ranks with it) and does not catch
// SIGINT or SIGXCPU either: those are how a job is stopped (a scheduler's time limit, timeout(1),
// Ctrl-C through mpirun). This handler removes the files and lets the signal do what it did (the
// default action, raised again once the handler returns).
extern "C" inline void OocFilesOnStop(int sig)
{
  OocFilesRemove();
  signal(sig, SIG_DFL);
  raise(sig);
}

// Catches SIGTERM, SIGINT and SIGXCPU where nothing else does (their action is still the default).
inline void OocFilesCatchStops()
{
  OocFiles &f = OocFilesOfProcess();
  if (f.dir < 0) return;
  struct sigaction sa {};
  sa.sa_handler = OocFilesOnStop;
  sigemptyset(&sa.sa_mask);
  for (int i = 0; i < 3; ++i)
    if (sigaction(OocFiles::kStops[i], nullptr, &f.former[i]) == 0 && f.former[i].sa_handler == SIG_DFL) f.caught[i] = sigaction(OocFiles::kStops[i], &sa, nullptr) == 0;
}

// The actions as they were and the directory closed: at the driver's end, on every path.
inline void OocFilesRelease()
{
  OocFiles &f = OocFilesOfProcess();
  for (int i = 0; i < 3; ++i)
    if (f.caught[i]) (void)sigaction(OocFiles::kStops[i], &f.former[i], nullptr), f.caught[i] = false;
  if (f.dir >= 0) (void)close(f.dir);
  f.dir = -1;
  f.len = 0;
}

} // namespace boltnet
