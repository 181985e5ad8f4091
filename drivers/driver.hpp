// The drivers' main(): PETSc's errors are collected rather than printed as its traceback (about
// forty lines), and an error ends the program with one line naming the problem and exit code 1 on
// every rank (docs/scenes.md, "Errors").
#pragma once
#include "core/errors.hpp"
#include "io/io.hpp"
#include "ooc_files.hpp"
#include "stack.hpp"

#include <petscsys.h>

#include <cstdio>
#include <exception>
#include <new>
#include <string>

namespace boltnet {

// How long a rank that stopped on an error waits for the others to stop too (seconds). Checks of
// input are collective (every rank raises the same error at the same point) and the ranks then end
// cleanly; an error raised on some ranks only leaves the others waiting in a collective call, and
// only MPI_Abort can end them.
constexpr double kErrorAgreeSeconds = 10;

// The message of the error: the outermost context and the first cause (core/errors.hpp); PETSc's
// complaint about an option's value ("Input string abc has no numeric value") names the option(s)
// with that value.
inline std::string DescribeError(const ErrorLog &log)
{
  std::string msg = ErrorText(log);
  if (msg.empty()) msg = "unknown error";
  try {
    // PETSc 3.18's words for a value it cannot convert (PetscOptionsStringToInt, _ToReal, _ToBool).
    std::string  value;
    const size_t a = msg.find("Input string "), b = msg.find(" has no "), c = msg.find("Unknown logical value: ");
    if (a != std::string::npos && b != std::string::npos && b > a) value = msg.substr(a + 13, b - a - 13);
    else if (c != std::string::npos) value = msg.substr(c + 23);
    std::string names;
    if (!value.empty() && !OptionsWithValue(value, &names) && !names.empty()) msg = "option " + names + ": " + msg;
  } catch (...) {
  }
  return msg;
}

// One line on rank 0 and a clean PetscFinalize on every rank when every rank stopped on the error;
// the message of each rank that did and MPI_Abort otherwise (after kErrorAgreeSeconds).
inline int ExitOnError(const char *program, MPI_Comm agree, const ErrorLog &log, bool handler)
{
  const std::string msg = DescribeError(log);
  int               rank = 0, done = 0;
  MPI_Request       req;
  MPI_Comm_rank(agree, &rank);
  MPI_Ibarrier(agree, &req);
  const double t0 = MPI_Wtime();
  while (!done && MPI_Wtime() - t0 < kErrorAgreeSeconds) {
    MPI_Test(&req, &done, MPI_STATUS_IGNORE);
    if (!done) PetscSleep(0.01);
  }
  if (!done) {
    std::fprintf(stderr, "%s: error (rank %d): %s\n", program, rank, msg.c_str());
    std::fflush(stderr);
    OocFilesRemove(); // MPI_Abort ends the factorisations without MUMPS's own clean-up
    MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  }
  if (rank == 0) std::fprintf(stderr, "%s: error: %s\n", program, msg.c_str());
  // Nothing more to say: no list of options left unused by a run that stopped.
  PetscOptionsClearValue(nullptr, "-options_left");
  MPI_Comm_free(&agree);
  PetscPopErrorHandler();
  if (handler) PetscPopSignalHandler();
  PetscFinalize();
  OocFilesRemove(); // those of a factorisation that the error left undestroyed
  OocFilesRelease();
  return 1;
}

// main() of a driver whose work is run(&exitcode, &log): returns the exit code (exitcode, or 1 on
// an error, PETSc's or a C++ exception).
template <class Run>
int DriverMain(const char *program, int *argc, char ***argv, const char *help, Run run)
{
  int      exitcode = 0;
  bool     handler  = false; // boltnet's signal handlers installed (ooc_files.hpp)
  ErrorLog log;
  MPI_Comm agree = MPI_COMM_NULL;
  const StackLimit stack = RaiseStackLimit(); // before any work: MUMPS's recursion (stack.hpp)
  if (PetscInitialize(argc, argv, nullptr, help)) return 1;
  {
    auto mb = [](rlim_t b) { return b == RLIM_INFINITY ? std::string("unlimited") : std::to_string((unsigned long long)(b >> 20)) + " MB"; };
    if (PetscInfo(nullptr, "stack limit (soft): %s, now %s\n", mb(stack.before).c_str(), mb(stack.after).c_str())) return 1;
    if (StackLimitTooSmall(stack) &&
        PetscFPrintf(PETSC_COMM_WORLD, PETSC_STDERR, "%s: warning: the stack limit is %s and the hard limit (ulimit -H -s) keeps it there: MUMPS's parallel factorisation of a large model may overflow it (docs/performance.md, \"Stack\")\n", program, mb(stack.after).c_str()))
      return 1;
  }
  // MUMPS's out-of-core files named per process and removed when an error or a signal stops it
  // (ooc_files.hpp); -no_signal_handler leaves the signals to their defaults, as it does PETSc's.
  {
    char      dir[PETSC_MAX_PATH_LEN] = "";
    PetscBool nohandler = PETSC_FALSE;
    if (PetscOptionsGetString(nullptr, nullptr, "-mat_mumps_ooc_tmpdir", dir, sizeof dir, nullptr)) return 1;
    if (PetscOptionsGetBool(nullptr, nullptr, "-no_signal_handler", &nohandler, nullptr)) return 1;
    OocFilesSetUp(dir);
    handler = !nohandler;
  }
  if (handler && PetscPushSignalHandler(OocFilesSignalHandler, nullptr)) return 1;
  if (handler) OocFilesCatchStops();
  if (PetscPushErrorHandler(CaptureErrorHandler, &log) || MPI_Comm_dup(PETSC_COMM_WORLD, &agree)) return 1;
  PetscErrorCode ierr;
  try {
    ierr = run(&exitcode, &log);
  } catch (const std::bad_alloc &) {
    log.messages.push_back("Out of memory");
    ierr = PETSC_ERR_MEM;
  } catch (const std::exception &e) {
    log.messages.push_back(std::string("C++ exception: ") + e.what());
    ierr = PETSC_ERR_LIB;
  }
  if (ierr) return ExitOnError(program, agree, log, handler);
  MPI_Comm_free(&agree);
  PetscPopErrorHandler();
  if (handler && PetscPopSignalHandler()) return 1;
  const PetscErrorCode fin = PetscFinalize();
  OocFilesRelease();
  return fin ? 1 : exitcode;
}

} // namespace boltnet
