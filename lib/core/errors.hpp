// PETSc error messages collected instead of printed: a handler for PetscPushErrorHandler() that
// keeps each error's first message (PETSc calls it again at every level of the traceback), so that a
// caller can name the cause in one line (the driver) or add the file it was reading (io/scene.cpp).
#pragma once
#include <petscsys.h>

#include <string>
#include <vector>

namespace boltnet {

struct ErrorLog {
  std::vector<std::string> messages; // one per error raised (PETSC_ERROR_INITIAL), oldest first
};

// For PetscPushErrorHandler(CaptureErrorHandler, &log): prints nothing, returns the error code.
inline PetscErrorCode CaptureErrorHandler(MPI_Comm, int, const char *, const char *, PetscErrorCode n, PetscErrorType p, const char *mess, void *ctx)
{
  if (p != PETSC_ERROR_INITIAL || !ctx) return n;
  try {
    std::string m = mess ? mess : "";
    while (!m.empty() && (m.back() == '\n' || m.back() == ' ')) m.pop_back();
    if (m.empty()) {
      const char *text = nullptr;
      PetscErrorMessage(n, &text, nullptr);
      m = text ? text : "PETSc error " + std::to_string((int)n);
    }
    static_cast<ErrorLog *>(ctx)->messages.push_back(m);
  } catch (...) { // out of memory while recording it: the error code still goes up
  }
  return n;
}

// One line for the errors recorded: the last one raised (the outermost context), followed by the
// first (the cause) when it is another message that the last does not already contain.
inline std::string ErrorText(const ErrorLog &log)
{
  if (log.messages.empty()) return "";
  const std::string &last = log.messages.back(), &first = log.messages.front();
  if (log.messages.size() == 1 || last.find(first) != std::string::npos) return last;
  return last + ": " + first;
}

} // namespace boltnet
