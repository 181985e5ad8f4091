// The drivers raise the soft stack limit of their process before any work starts, because MUMPS's
// parallel factorisation recurses on the main thread's stack to a depth that grows with the model
// (docs/performance.md, "Stack: MUMPS's message recursion").
//
// On more than one rank, a process that cannot send a contribution block because its send buffer
// is full (DMUMPS_MAPLIG, MUMPS 5.5) receives and treats the next message instead
// (DMUMPS_TRY_RECVTREAT -> DMUMPS_RECV_AND_TREAT -> DMUMPS_TRAITER_MESSAGE), and that message may
// be another DMUMPS_MAPLIG whose send buffer is full too: one recursion level per message, about
// 6.8 kB of stack each. A 1,030,344-dof plate grid on 2 ranks went about 1,000 levels deep (7 MB)
// and overflowed the usual 8 MB limit at 1,220. No MUMPS control bounds that depth.
//
// Linux checks RLIMIT_STACK when the main thread's stack grows, so raising the soft limit up to the
// hard one at run time is enough; threads already have their own stacks, set when they were created.
#pragma once
#include <sys/resource.h>

namespace boltnet {

// The soft stack limit the drivers ask for: far above the depth measured (docs/performance.md),
// and memory is used only as deep as the stack actually goes.
constexpr rlim_t kDriverStackBytes = rlim_t(1) << 30; // 1 GiB

// Below this the limit is reported as too small for large parallel solves.
constexpr rlim_t kDriverStackWarnBytes = rlim_t(64) << 20; // 64 MiB

struct StackLimit {
  rlim_t before = 0, after = 0; // soft limits (RLIM_INFINITY: unlimited)
  bool   raised = false;
};

// Raises the soft RLIMIT_STACK of this process to kDriverStackBytes, or to the hard limit if that
// is lower; a larger soft limit (or unlimited) is left as it is.
inline StackLimit RaiseStackLimit()
{
  StackLimit s;
  rlimit     r;
  if (getrlimit(RLIMIT_STACK, &r)) return s;
  s.before = s.after = r.rlim_cur;
  if (r.rlim_cur == RLIM_INFINITY || r.rlim_cur >= kDriverStackBytes) return s;
  rlim_t want = kDriverStackBytes;
  if (r.rlim_max != RLIM_INFINITY && r.rlim_max < want) want = r.rlim_max;
  if (want <= r.rlim_cur) return s;
  r.rlim_cur = want;
  if (setrlimit(RLIMIT_STACK, &r)) return s;
  s.after  = want;
  s.raised = true;
  return s;
}

inline bool StackLimitTooSmall(const StackLimit &s) { return s.after != RLIM_INFINITY && s.after < kDriverStackWarnBytes; }

} // namespace boltnet
