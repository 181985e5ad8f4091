static const char help[] = "test_capi_errors: bad arguments and out-of-memory at the entry points of boltnet.h.\n\
\n\
Requirement: every entry point of the C API refuses a NULL pointer, a negative count, an id or a\n\
count out of range with a PETSc error whose message names the function and the argument, before it\n\
allocates anything; a C++ exception inside the library (std::bad_alloc) comes back as a PETSc error\n\
(PETSC_ERR_MEM, naming the function), never as std::terminate; and an assembly that refused a call\n\
still works.\n\
\n\
The errors are collected by an error handler that prints nothing, so that each check sees the code\n\
and the first message of its error. Out of memory is real: the address space of the process is\n\
limited (setrlimit RLIMIT_AS) to a few MB above what it uses, and BoltnetAssemblySolveLoadPath()\n\
gets a load path of 10^6 factors, which passes its checks (at most 10^6 load steps) and needs 8 MB.\n\
After the refused calls the assembly (a spring joint of stiffness kt between a clamped and a loaded\n\
rigid patch) is solved and its jump checked against the closed form u = F / kt.\n\
Prints a PASS line unless a check fails (then a PETSc error naming it, exit code 1).\n\
\n\
  mpiexec -n 2 build/bin/test_capi_errors -options_left -malloc_debug -malloc_dump\n\n";

#include <boltnet.h>
#include <math.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

/* The first message of the last error raised (PETSC_ERROR_INITIAL), kept in a static buffer: the
   handler allocates nothing, as it also runs out of memory. */
static char lastMessage[4096];

static PetscErrorCode Collect(MPI_Comm comm, int line, const char *fun, const char *file, PetscErrorCode n, PetscErrorType p, const char *mess, void *ctx)
{
  (void)comm, (void)line, (void)fun, (void)file, (void)ctx;
  if (p == PETSC_ERROR_INITIAL) {
    strncpy(lastMessage, mess ? mess : "", sizeof(lastMessage) - 1);
    lastMessage[sizeof(lastMessage) - 1] = 0;
  }
  return n;
}

static PetscInt nchecked = 0;

/* The call must fail with `code` and its message contain `what` and `arg` (NULL: not checked). */
static PetscErrorCode Expect(PetscErrorCode ierr, const char *call, PetscErrorCode code, const char *what, const char *arg)
{
  PetscFunctionBeginUser;
  PetscCheck(ierr == code, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s returned %d, expected %d (message: %s)", call, (int)ierr, (int)code, lastMessage);
  PetscCheck(!what || strstr(lastMessage, what), PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: the message \"%s\" does not name %s", call, lastMessage, what);
  PetscCheck(!arg || strstr(lastMessage, arg), PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: the message \"%s\" does not name the argument %s", call, lastMessage, arg);
  lastMessage[0] = 0;
  ++nchecked;
  PetscFunctionReturn(0);
}

/* EXPECT(call, code, function name, argument): runs call under the collecting handler. */
#define EXPECT(call, code, what, arg) \
  do { \
    PetscErrorCode ierr_; \
    lastMessage[0] = 0; \
    PetscCall(PetscPushErrorHandler(Collect, NULL)); \
    ierr_ = (call); \
    PetscCall(PetscPopErrorHandler()); \
    PetscCall(Expect(ierr_, #call, code, what, arg)); \
  } while (0)

static const PetscReal x0[3] = {0, 0, 0}, nz[3] = {0, 0, 1}, ex[3] = {1, 0, 0};
static const PetscReal kt = 2.0e4, F = 500.0; /* N/mm, N */

/* Bad arguments to the description calls of an assembly not yet set up. */
static PetscErrorCode TestDescription(BoltnetAssembly a)
{
  BoltnetJointParams p;
  const PetscReal    xyz[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const PetscInt     quad[4] = {0, 1, 2, 3}, nodes[2] = {0, 1};

  PetscFunctionBeginUser;
  PetscCall(BoltnetJointParamsSetDefault(BOLTNET_LAW_SPRING, &p));
  EXPECT(BoltnetJointParamsSetDefault(BOLTNET_LAW_SPRING, NULL), PETSC_ERR_ARG_NULL, "BoltnetJointParamsSetDefault", "argument 2");
  EXPECT(BoltnetJointParamsSetDefault((BoltnetLaw)7, &p), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetJointParamsSetDefault", "argument 1 (law)");
  PetscCheck(BoltnetJointStateName((BoltnetJointState)99) && !strcmp(BoltnetJointStateName((BoltnetJointState)99), "unknown"), PETSC_COMM_SELF, PETSC_ERR_PLIB, "BoltnetJointStateName(99) is not \"unknown\"");

  EXPECT(BoltnetAssemblyCreate(PETSC_COMM_WORLD, NULL), PETSC_ERR_ARG_NULL, "BoltnetAssemblyCreate", "argument 2");
  EXPECT(BoltnetAssemblySetOptionsPrefix(NULL, "x_"), PETSC_ERR_ARG_NULL, "BoltnetAssemblySetOptionsPrefix", "argument 1 (BoltnetAssembly)");
  EXPECT(BoltnetAssemblyAddRigidPatch(NULL, 0, x0), PETSC_ERR_ARG_NULL, "BoltnetAssemblyAddRigidPatch", "argument 1 (BoltnetAssembly)");
  EXPECT(BoltnetAssemblyAddRigidPatch(a, -1, x0), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblyAddRigidPatch", "argument 2 (id) = -1");

  EXPECT(BoltnetAssemblyAddJoint(NULL, 0, 0, 1, &p, nz, ex), PETSC_ERR_ARG_NULL, "BoltnetAssemblyAddJoint", "argument 1 (BoltnetAssembly)");
  EXPECT(BoltnetAssemblyAddJoint(a, 0, 0, 1, NULL, nz, ex), PETSC_ERR_ARG_NULL, "BoltnetAssemblyAddJoint", "argument 5 (BoltnetJointParams)");
  EXPECT(BoltnetAssemblyAddJoint(a, -2, 0, 1, &p, nz, ex), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblyAddJointAt", "argument 2 (id) = -2");
  EXPECT(BoltnetAssemblyAddJointAt(a, 0, -1, 1, &p, nz, ex, x0), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblyAddJointAt", "argument 3 (patch_a) = -1");
  EXPECT(BoltnetAssemblyAddJointAt(a, 0, 0, -5, &p, nz, ex, x0), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblyAddJointAt", "argument 4 (patch_b) = -5");
  EXPECT(BoltnetAssemblyAddJointAt(a, 0, 0, 1, NULL, nz, ex, x0), PETSC_ERR_ARG_NULL, "BoltnetAssemblyAddJointAt", "argument 5 (BoltnetJointParams)");

  EXPECT(BoltnetAssemblyAddBC(NULL, 0, -1, BOLTNET_BC_FIXED, 0), PETSC_ERR_ARG_NULL, "BoltnetAssemblyAddBC", "argument 1 (BoltnetAssembly)");
  EXPECT(BoltnetAssemblyAddBC(a, -1, -1, BOLTNET_BC_FIXED, 0), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblyAddBC", "argument 2 (patch) = -1");
  EXPECT(BoltnetAssemblyAddBCOnSet(NULL, 0, "edge", -1, BOLTNET_BC_FIXED, 0), PETSC_ERR_ARG_NULL, "BoltnetAssemblyAddBCOnSet", "argument 1 (BoltnetAssembly)");
  EXPECT(BoltnetAssemblyAddBCOnSet(a, -3, "edge", -1, BOLTNET_BC_FIXED, 0), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblyAddBCOnSet", "argument 2 (patch) = -3");

  EXPECT(BoltnetAssemblyAddShellPatch(NULL, 5, 4, xyz, 1, quad, 7e4, 0.3, 2), PETSC_ERR_ARG_NULL, "BoltnetAssemblyAddShellPatch", "argument 1 (BoltnetAssembly)");
  EXPECT(BoltnetAssemblyAddShellPatch(a, -1, 4, xyz, 1, quad, 7e4, 0.3, 2), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblyAddShellPatch", "argument 2 (id) = -1");
  EXPECT(BoltnetAssemblyAddShellPatch(a, 5, -4, xyz, 1, quad, 7e4, 0.3, 2), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblyAddShellPatch", "argument 3 (nnodes) = -4");
  EXPECT(BoltnetAssemblyAddShellPatch(a, 5, 2000000000, xyz, 1, quad, 7e4, 0.3, 2), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblyAddShellPatch", "argument 3 (nnodes) = 2000000000");
  EXPECT(BoltnetAssemblyAddShellPatch(a, 5, 4, NULL, 1, quad, 7e4, 0.3, 2), PETSC_ERR_ARG_NULL, "BoltnetAssemblyAddShellPatch", "argument 4 (xyz)");
  EXPECT(BoltnetAssemblyAddShellPatch(a, 5, 4, xyz, -1, quad, 7e4, 0.3, 2), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblyAddShellPatch", "argument 5 (nquads) = -1");
  EXPECT(BoltnetAssemblyAddShellPatch(a, 5, 4, xyz, 1, NULL, 7e4, 0.3, 2), PETSC_ERR_ARG_NULL, "BoltnetAssemblyAddShellPatch", "argument 6 (quads)");
  EXPECT(BoltnetAssemblyAddShellPatch(a, 5, 4, xyz, 1, quad, -7e4, 0.3, 2), PETSC_ERR_USER_INPUT, "Shell patch 5", "Young's modulus");
  EXPECT(BoltnetAssemblyAddShellPatchElements(NULL, 5, 4, xyz, 1, quad, 7e4, 0.3, 2), PETSC_ERR_ARG_NULL, "BoltnetAssemblyAddShellPatchElements", "argument 1 (BoltnetAssembly)");
  EXPECT(BoltnetAssemblyAddShellPatchElements(a, 5, 4, xyz, 1000000000, quad, 7e4, 0.3, 2), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblyAddShellPatchElements", "argument 5 (nelems) = 1000000000");
  EXPECT(BoltnetAssemblyAddShellPatchElements(a, 5, 4, xyz, 1, NULL, 7e4, 0.3, 2), PETSC_ERR_ARG_NULL, "BoltnetAssemblyAddShellPatchElements", "argument 6 (elems)");

  EXPECT(BoltnetAssemblyAddNodeSet(NULL, 0, "edge", 2, nodes), PETSC_ERR_ARG_NULL, "BoltnetAssemblyAddNodeSet", "argument 1 (BoltnetAssembly)");
  EXPECT(BoltnetAssemblyAddNodeSet(a, -1, "edge", 2, nodes), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblyAddNodeSet", "argument 2 (patch) = -1");
  EXPECT(BoltnetAssemblyAddNodeSet(a, 0, NULL, 2, nodes), PETSC_ERR_ARG_NULL, "BoltnetAssemblyAddNodeSet", "argument 3 (name)");
  EXPECT(BoltnetAssemblyAddNodeSet(a, 0, "edge", -2, nodes), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblyAddNodeSet", "argument 4 (n) = -2");
  EXPECT(BoltnetAssemblyAddNodeSet(a, 0, "edge", 2, NULL), PETSC_ERR_ARG_NULL, "BoltnetAssemblyAddNodeSet", "argument 5 (nodes)");

  /* A refused node set leaves no set behind: a boundary condition on it is then refused as on a set
     that was never given (on a second assembly, so that this one stays the two rigid patches). */
  {
    BoltnetAssembly b;
    const PetscInt  bad[2] = {0, 99};
    PetscCall(BoltnetAssemblyCreate(PETSC_COMM_WORLD, &b));
    PetscCall(BoltnetAssemblyAddShellPatch(b, 5, 4, xyz, 1, quad, 7e4, 0.3, 2));
    EXPECT(BoltnetAssemblyAddNodeSet(b, 5, "edge", 2, bad), PETSC_ERR_USER_INPUT, "Node set 'edge' of patch 5", "node 99 does not exist");
    EXPECT(BoltnetAssemblyAddBCOnSet(b, 5, "edge", -1, BOLTNET_BC_FIXED, 0), PETSC_ERR_USER_INPUT, "patch 5", "no node set 'edge'");
    PetscCall(BoltnetAssemblyAddNodeSet(b, 5, "edge", 2, nodes));
    PetscCall(BoltnetAssemblyAddBCOnSet(b, 5, "edge", -1, BOLTNET_BC_FIXED, 0));
    /* A pressure acts along the elements' normals (dof -1 only), on a shell patch only. */
    EXPECT(BoltnetAssemblyAddBCOnSet(b, 5, NULL, 2, BOLTNET_BC_PRESSURE, 0.1), PETSC_ERR_USER_INPUT, "Pressure on patch 5", "its dof is -1 (all), not 2");
    PetscCall(BoltnetAssemblyAddRigidPatch(b, 6, x0));
    EXPECT(BoltnetAssemblyAddBC(b, 6, -1, BOLTNET_BC_PRESSURE, 0.1), PETSC_ERR_USER_INPUT, "Pressure on patch 6", "it is not a shell patch");
    PetscCall(BoltnetAssemblyAddBCOnSet(b, 5, NULL, -1, BOLTNET_BC_PRESSURE, 0.1));
    PetscCall(BoltnetAssemblyDestroy(&b));
  }

  EXPECT(BoltnetAssemblySetFromOptions(NULL), PETSC_ERR_ARG_NULL, "BoltnetAssemblySetFromOptions", "argument 1 (BoltnetAssembly)");
  EXPECT(BoltnetAssemblySetUp(NULL), PETSC_ERR_ARG_NULL, "BoltnetAssemblySetUp", "argument 1 (BoltnetAssembly)");
  /* Results before set-up: refused, naming the order. */
  EXPECT(BoltnetAssemblyGetJointResult(a, 0, NULL, NULL, NULL), PETSC_ERR_ORDER, "BoltnetAssemblyGetJointResult", "BoltnetAssemblySetUp()");
  EXPECT(BoltnetAssemblySolveLoadPath(a, 1, &F, 1), PETSC_ERR_ORDER, "BoltnetAssemblySolveLoadPath", "BoltnetAssemblySetUp()");
  PetscFunctionReturn(0);
}

/* Bad arguments to the solve and result calls of an assembly set up. */
static PetscErrorCode TestSolveAndResults(BoltnetAssembly a)
{
  DM                 dm;
  SNES               snes;
  PetscReal          lambda, u[6], factors[2] = {1, INFINITY};
  BoltnetJointParams p;

  PetscFunctionBeginUser;
  PetscCall(BoltnetJointParamsSetDefault(BOLTNET_LAW_SPRING, &p));
  EXPECT(BoltnetAssemblyAddRigidPatch(a, 7, x0), PETSC_ERR_ORDER, "BoltnetAssemblyAddRigidPatch", "already set up");
  EXPECT(BoltnetAssemblyGetDM(NULL, &dm), PETSC_ERR_ARG_NULL, "BoltnetAssemblyGetDM", "argument 1 (BoltnetAssembly)");
  EXPECT(BoltnetAssemblyGetDM(a, NULL), PETSC_ERR_ARG_NULL, "BoltnetAssemblyGetDM", "argument 2 (DM *)");
  EXPECT(BoltnetAssemblyGetSNES(NULL, &snes), PETSC_ERR_ARG_NULL, "BoltnetAssemblyGetSNES", "argument 1 (BoltnetAssembly)");
  EXPECT(BoltnetAssemblyGetSNES(a, NULL), PETSC_ERR_ARG_NULL, "BoltnetAssemblyGetSNES", "argument 2 (SNES *)");
  EXPECT(BoltnetAssemblyGetLoadFactor(NULL, &lambda), PETSC_ERR_ARG_NULL, "BoltnetAssemblyGetLoadFactor", "argument 1 (BoltnetAssembly)");
  EXPECT(BoltnetAssemblyGetLoadFactor(a, NULL), PETSC_ERR_ARG_NULL, "BoltnetAssemblyGetLoadFactor", "argument 2 (PetscReal *)");
  EXPECT(BoltnetAssemblyGetJointResult(NULL, 0, NULL, NULL, NULL), PETSC_ERR_ARG_NULL, "BoltnetAssemblyGetJointResult", "argument 1 (BoltnetAssembly)");
  EXPECT(BoltnetAssemblyGetJointResult(a, -1, NULL, NULL, NULL), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblyGetJointResult", "argument 2 (id) = -1");
  EXPECT(BoltnetAssemblyGetJointResult(a, 3, NULL, NULL, NULL), PETSC_ERR_ARG_OUTOFRANGE, "No joint with id 3", NULL);
  EXPECT(BoltnetAssemblyGetPatchDisplacement(NULL, 0, u), PETSC_ERR_ARG_NULL, "BoltnetAssemblyGetPatchDisplacement", "argument 1 (BoltnetAssembly)");
  EXPECT(BoltnetAssemblyGetPatchDisplacement(a, -1, u), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblyGetPatchDisplacement", "argument 2 (patch) = -1");
  EXPECT(BoltnetAssemblyGetPatchDisplacement(a, 0, NULL), PETSC_ERR_ARG_NULL, "BoltnetAssemblyGetPatchDisplacement", "argument 3 (u)");
  EXPECT(SNESLineSearchBoltnetSetStateChangeFunction(NULL, NULL, NULL), PETSC_ERR_ARG_NULL, "SNESLineSearchBoltnetSetStateChangeFunction", "argument 1 (SNESLineSearch)");
  PetscCall(BoltnetAssemblyGetSNES(a, &snes));
  EXPECT(SNESLineSearchBoltnetSetStateChangeFunction((SNESLineSearch)snes, NULL, NULL), PETSC_ERR_ARG_WRONG, "SNESLineSearchBoltnetSetStateChangeFunction", "argument 1 is a SNES");

  /* The load path: its counts bounded by 10^6 load steps before anything is allocated. */
  EXPECT(BoltnetAssemblySolveLoadPath(NULL, 1, factors, 1), PETSC_ERR_ARG_NULL, "BoltnetAssemblySolveLoadPath", "argument 1 (BoltnetAssembly)");
  EXPECT(BoltnetAssemblySolveLoadPath(a, -1, factors, 1), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblySolveLoadPath", "argument 2 (n, the number of load factors) = -1");
  EXPECT(BoltnetAssemblySolveLoadPath(a, 2000000, factors, 1), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblySolveLoadPath", "argument 2 (n, the number of load factors) = 2000000");
  EXPECT(BoltnetAssemblySolveLoadPath(a, 1, NULL, 1), PETSC_ERR_ARG_NULL, "BoltnetAssemblySolveLoadPath", "argument 3 (factors)");
  EXPECT(BoltnetAssemblySolveLoadPath(a, 2, factors, 1), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblySolveLoadPath", "factors[1] is not finite");
  EXPECT(BoltnetAssemblySolveLoadPath(a, 1, factors, 0), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblySolveLoadPath", "argument 4 (steps_per_segment) = 0");
  EXPECT(BoltnetAssemblySolveLoadPath(a, 1, factors, 2000000000), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblySolveLoadPath", "argument 4 (steps_per_segment) = 2000000000");
  factors[1] = -1; /* two segments of 600000 steps: 1.2 10^6 in all */
  EXPECT(BoltnetAssemblySolveLoadPath(a, 2, factors, 600000), PETSC_ERR_ARG_OUTOFRANGE, "BoltnetAssemblySolveLoadPath", "over 2 segments is more than the limit of 1000000 load steps");
  PetscCall(BoltnetAssemblyGetLoadFactor(a, &lambda));
  PetscCheck(lambda == 0, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "A refused load path moved the load factor to %g", (double)lambda);
  PetscFunctionReturn(0);
}

/* std::bad_alloc inside BoltnetAssemblySolveLoadPath(): a PETSc error, not std::terminate. */
static PetscErrorCode TestOutOfMemory(BoltnetAssembly a)
{
  const PetscInt n = 1000000; /* the most load factors the checks accept */
  PetscReal     *factors;
  struct rlimit  saved, low;
  long           pages = 0, rss;
  FILE          *statm;

  PetscFunctionBeginUser;
#if defined(__SANITIZE_ADDRESS__)
  /* AddressSanitizer reserves terabytes of address space: RLIMIT_AS cannot be lowered under it. */
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "test_capi_errors: out-of-memory check skipped under AddressSanitizer\n"));
  PetscFunctionReturn(0);
#endif
  PetscCall(PetscCalloc1(n, &factors)); /* all 0, the current load factor: no step to take */
  statm = fopen("/proc/self/statm", "r");
  PetscCheck(statm && fscanf(statm, "%ld %ld", &pages, &rss) == 2, PETSC_COMM_SELF, PETSC_ERR_SYS, "Cannot read /proc/self/statm");
  fclose(statm);
  PetscCheck(getrlimit(RLIMIT_AS, &saved) == 0, PETSC_COMM_SELF, PETSC_ERR_SYS, "getrlimit(RLIMIT_AS) failed");
  low          = saved;
  low.rlim_cur = (rlim_t)pages * (rlim_t)getpagesize() + (rlim_t)(2 << 20); /* 2 MB to spare: less than the 8 MB the path needs */
  PetscCheck(getpagesize() > 0 && setrlimit(RLIMIT_AS, &low) == 0, PETSC_COMM_SELF, PETSC_ERR_SYS, "setrlimit(RLIMIT_AS) failed");
  {
    PetscErrorCode ierr;
    lastMessage[0] = 0;
    ierr           = PetscPushErrorHandler(Collect, NULL);
    if (!ierr) ierr = BoltnetAssemblySolveLoadPath(a, n, factors, 1);
    (void)PetscPopErrorHandler();
    PetscCheck(setrlimit(RLIMIT_AS, &saved) == 0, PETSC_COMM_SELF, PETSC_ERR_SYS, "setrlimit(RLIMIT_AS) could not restore the limit");
    PetscCall(Expect(ierr, "BoltnetAssemblySolveLoadPath(a, 1000000, factors, 1) with 2 MB of address space to spare", PETSC_ERR_MEM, "BoltnetAssemblySolveLoadPath", "out of memory"));
  }
  /* With the memory back, the same request is accepted (and takes no step). */
  PetscCall(BoltnetAssemblySolveLoadPath(a, n, factors, 1));
  PetscCall(PetscFree(factors));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  BoltnetAssembly    a;
  BoltnetJointParams p;
  PetscReal          f[6], u[6], lambda;
  const PetscReal    one = 1.0, x1[3] = {10, 0, 0};
  BoltnetJointState  s;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(BoltnetAssemblyCreate(PETSC_COMM_WORLD, &a));
  PetscCall(TestDescription(a));
  /* The refused calls left nothing behind: the assembly is described and solved as usual. */
  PetscCall(BoltnetAssemblyAddRigidPatch(a, 0, x0));
  PetscCall(BoltnetAssemblyAddRigidPatch(a, 1, x1));
  PetscCall(BoltnetJointParamsSetDefault(BOLTNET_LAW_SPRING, &p));
  p.kn = 1e4; /* the spring's other stiffnesses: without them the patch 1 is a mechanism */
  p.kt = kt;
  p.kr = 1e7;
  PetscCall(BoltnetAssemblyAddJoint(a, 0, 0, 1, &p, nz, ex));
  PetscCall(BoltnetAssemblyAddBC(a, 0, -1, BOLTNET_BC_FIXED, 0));
  PetscCall(BoltnetAssemblyAddBC(a, 1, 0, BOLTNET_BC_FORCE, F));
  PetscCall(BoltnetAssemblySetFromOptions(a));
  PetscCall(BoltnetAssemblySetUp(a));
  PetscCall(TestSolveAndResults(a));
  PetscCall(TestOutOfMemory(a));
  PetscCall(BoltnetAssemblyGetLoadFactor(a, &lambda));
  PetscCheck(lambda == 0, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "The out-of-memory check moved the load factor to %g", (double)lambda);
  PetscCall(BoltnetAssemblySolveLoadPath(a, 1, &one, 2));
  PetscCall(BoltnetAssemblyGetJointResult(a, 0, f, u, &s));
  /* The spring's jump in t1 = x: u = F / kt (relative tolerance 1e-9). */
  PetscCheck(PetscAbsReal(u[1] - F / kt) <= 1e-9 * F / kt, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "After the refused calls the jump is %.15g, expected F / kt = %.15g", (double)u[1], (double)(F / kt));
  PetscCheck(PetscAbsReal(f[1] - F) <= 1e-9 * F, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "After the refused calls the joint force is %.15g, expected %.15g", (double)f[1], (double)F);
  PetscCall(BoltnetAssemblyDestroy(&a));
  PetscCall(BoltnetAssemblyDestroy(&a)); /* a destroyed (NULL) assembly: nothing to do, as PETSc's XxxDestroy() */
  PetscCall(BoltnetAssemblyDestroy(NULL));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "test_capi_errors: PASS (%" PetscInt_FMT " refused calls checked on each rank)\n", nchecked));
  PetscCall(PetscFinalize());
  return 0;
}
