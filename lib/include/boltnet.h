/* boltnet: bolted-joint macroelements on a PETSc DMNetwork.

   The public, C-callable API. Another PETSc code builds an assembly (patches, joints, boundary
   conditions), solves a load path and reads the joint forces and states:

     BoltnetInitializePackage();
     BoltnetAssemblyCreate(PETSC_COMM_WORLD, &a);
     BoltnetAssemblyAddRigidPatch(a, 0, x0);              -- every rank passes the same description
     BoltnetAssemblyAddRigidPatch(a, 1, x1);
     BoltnetJointParamsSetDefault(BOLTNET_LAW_FRICTION, &p); p.kt = ...;
     BoltnetAssemblyAddJoint(a, 0, 0, 1, &p, normal, t1);
     BoltnetAssemblyAddBC(a, 0, -1, BOLTNET_BC_FIXED, 0);  -- dof -1: all six dof of the patch
     BoltnetAssemblyAddBC(a, 1, 0, BOLTNET_BC_FORCE, 1.0); -- value times the load factor
     BoltnetAssemblySetFromOptions(a);                     -- -joint_tangent, -load_*, SNES options
     BoltnetAssemblySetUp(a);                              -- builds and distributes the DMNetwork
     BoltnetAssemblySolveLoadPath(a, n, factors, steps_per_segment);
     BoltnetAssemblyGetJointResult(a, 0, force, jump, &state);
     BoltnetAssemblyDestroy(&a);

   Units are the caller's; the shipped scenes use N, mm, MPa. Dof order per node: ux uy uz rx ry rz.

   Patches and boundary conditions are described alike on every rank. The joints are rank 0's: the
   set-up sends each rank those that attach to the shell parts it lays out, so the other ranks may
   pass the same joints (they are dropped) or none (a fastener table read on rank 0 alone, as the
   scene reader does). Either way rank 0's list is the model's.

   Errors (docs/architecture.md, "Errors"): every function checks its arguments before it allocates
   (a NULL pointer, a negative id, a count out of range: a PETSc error naming the function and the
   argument) and returns a C++ exception inside boltnet as a PETSc error (PETSC_ERR_MEM for
   std::bad_alloc), never std::terminate. A refused call leaves the assembly unchanged. */
#ifndef BOLTNET_H
#define BOLTNET_H

#include <petscsnes.h>
#include <petscdmnetwork.h>

#if defined(__cplusplus)
extern "C" {
#endif

typedef struct _p_BoltnetAssembly *BoltnetAssembly;

typedef enum { BOLTNET_LAW_SPRING = 0, BOLTNET_LAW_CONTACT = 1, BOLTNET_LAW_FRICTION = 2 } BoltnetLaw;
typedef enum {
  BOLTNET_STATE_LINEAR  = 0,
  BOLTNET_STATE_OPEN    = 1,
  BOLTNET_STATE_CONTACT = 2,
  BOLTNET_STATE_STICK   = 3,
  BOLTNET_STATE_SLIDE   = 4
} BoltnetJointState;
/* BOLTNET_BC_PRESSURE: a pressure (force per unit area, per unit load factor) on the elements of a
   shell patch, positive along each element's normal (right-handed about its node order), applied
   as consistent nodal forces; dof must be -1. On a node set it loads the elements whose nodes all
   lie in the set. */
typedef enum { BOLTNET_BC_FIXED = 0, BOLTNET_BC_DISPLACEMENT = 1, BOLTNET_BC_FORCE = 2, BOLTNET_BC_PRESSURE = 3 } BoltnetBCKind;

/* Macroelement parameters (see docs/joint-laws.md). kt is the in-plane stiffness: the spring's,
   the contact law's k before contact, the frictional law's stick stiffness ke. kc is k' (contact law)
   or the bearing stiffness (frictional law). G = mu nf max(0, pretension - clamp_coupling F_n). */
typedef struct {
  BoltnetLaw law;
  PetscReal  kn, kt, kr, kc, kg, gap, mu, nf, pretension, clamp_coupling, offset[2];
} BoltnetJointParams;

PETSC_EXTERN PetscErrorCode BoltnetInitializePackage(void);
PETSC_EXTERN PetscErrorCode BoltnetFinalizePackage(void);
PETSC_EXTERN PetscErrorCode BoltnetJointParamsSetDefault(BoltnetLaw, BoltnetJointParams *);
PETSC_EXTERN const char    *BoltnetJointStateName(BoltnetJointState);

PETSC_EXTERN PetscErrorCode BoltnetAssemblyCreate(MPI_Comm, BoltnetAssembly *);
PETSC_EXTERN PetscErrorCode BoltnetAssemblyDestroy(BoltnetAssembly *);
PETSC_EXTERN PetscErrorCode BoltnetAssemblySetOptionsPrefix(BoltnetAssembly, const char[]);
PETSC_EXTERN PetscErrorCode BoltnetAssemblyAddRigidPatch(BoltnetAssembly, PetscInt id, const PetscReal x[3]);
PETSC_EXTERN PetscErrorCode BoltnetAssemblyAddJoint(BoltnetAssembly, PetscInt id, PetscInt patch_a, PetscInt patch_b, const BoltnetJointParams *, const PetscReal normal[3], const PetscReal t1[3]);
PETSC_EXTERN PetscErrorCode BoltnetAssemblyAddBC(BoltnetAssembly, PetscInt patch, PetscInt dof, BoltnetBCKind, PetscReal value);
/* Shell patches: a quadrilateral mesh (nnodes coordinates xyz[3*i+k], nquads
   counter-clockwise quads[4*e+k], node numbers from 0) of an isotropic shell (E, nu, thickness t).
   Joints attach to a shell patch at their position, through the nodes of their footprint
   (-coupling_radius) tied rigidly to a joint node: eliminated exactly (-coupling_type exact, the
   default), by penalty links (penalty, -coupling_penalty), or to the nearest node (node);
   docs/coupling.md. */
PETSC_EXTERN PetscErrorCode BoltnetAssemblyAddShellPatch(BoltnetAssembly, PetscInt id, PetscInt nnodes, const PetscReal xyz[], PetscInt nquads, const PetscInt quads[], PetscReal E, PetscReal nu, PetscReal t);
/* A shell patch of triangles, quadrilaterals or both (a mixed mesh): nelems elements of four entries
   each, elems[4*e+k], the nodes counter-clockwise about the intended normal; a triangle gives three
   nodes and -1 as its fourth entry. Otherwise as BoltnetAssemblyAddShellPatch, which is this
   function with quadrilaterals only. A node number out of range or named twice in an element is an
   error naming the patch and the element. On a curved mesh the elements around a node share the
   mean of their normals as director (-shell_directors, docs/shell.md). */
PETSC_EXTERN PetscErrorCode BoltnetAssemblyAddShellPatchElements(BoltnetAssembly, PetscInt id, PetscInt nnodes, const PetscReal xyz[], PetscInt nelems, const PetscInt elems[], PetscReal E, PetscReal nu, PetscReal t);
PETSC_EXTERN PetscErrorCode BoltnetAssemblyAddNodeSet(BoltnetAssembly, PetscInt patch, const char name[], PetscInt n, const PetscInt nodes[]);
/* A boundary condition on a node set of a shell patch (NULL or "": all its nodes); a force value is
   the total on the set, shared equally by its nodes; a pressure loads the elements whose nodes all
   lie in the set (NULL or "": every element of the patch). */
PETSC_EXTERN PetscErrorCode BoltnetAssemblyAddBCOnSet(BoltnetAssembly, PetscInt patch, const char set[], PetscInt dof, BoltnetBCKind, PetscReal value);
/* A joint with a position (needed where it joins a shell patch). */
PETSC_EXTERN PetscErrorCode BoltnetAssemblyAddJointAt(BoltnetAssembly, PetscInt id, PetscInt patch_a, PetscInt patch_b, const BoltnetJointParams *, const PetscReal normal[3], const PetscReal t1[3], const PetscReal x[3]);
PETSC_EXTERN PetscErrorCode BoltnetAssemblySetFromOptions(BoltnetAssembly);
PETSC_EXTERN PetscErrorCode BoltnetAssemblySetUp(BoltnetAssembly);
PETSC_EXTERN PetscErrorCode BoltnetAssemblyGetDM(BoltnetAssembly, DM *);
PETSC_EXTERN PetscErrorCode BoltnetAssemblyGetSNES(BoltnetAssembly, SNES *);
/* Solve through the piecewise-linear load path factors[0..n-1] (starting from the current state),
   steps_per_segment equal steps per segment, with automatic cut-back. Returns an error when a step
   cannot be completed within the cut-back bound. */
PETSC_EXTERN PetscErrorCode BoltnetAssemblySolveLoadPath(BoltnetAssembly, PetscInt n, const PetscReal factors[], PetscInt steps_per_segment);
/* Collective: every rank receives the result of joint `id` at the last converged step
   (force on node B and jump, both in the joint's local frame n, t1, t2, and its state). */
PETSC_EXTERN PetscErrorCode BoltnetAssemblyGetJointResult(BoltnetAssembly, PetscInt id, PetscReal force[6], PetscReal jump[6], BoltnetJointState *);
/* Collective: displacement of a patch node (6 dof) at the last converged step. */
PETSC_EXTERN PetscErrorCode BoltnetAssemblyGetPatchDisplacement(BoltnetAssembly, PetscInt patch, PetscReal u[6]);
PETSC_EXTERN PetscErrorCode BoltnetAssemblyGetLoadFactor(BoltnetAssembly, PetscReal *);

/* Element results at the last converged step (docs/output.md, "Stresses and section forces"): the
   stress resultants of element `element` of shell patch `part` (numbers as the caller gave them),
   at its centroid, in its element frame (x along its first natural axis, z its normal by the
   counter-clockwise node order) or in the material frame (x along the material reference direction,
   global X by default, projected on the element). N (Nxx Nyy Nxy, force per length), M (Mxx Myy
   Mxy, moment per length), Q (Qxz Qyz); the strains of the top (z = +t/2) and bottom faces (eps_xx
   eps_yy gamma_xy); for a homogeneous section (one material through the thickness) their stresses
   (sigma_xx sigma_yy tau_xy) and von Mises stress; a laminate has NaN stresses (its ply stresses
   are not computed). axes: the frame's x, y, z as rows (global). Collective. */
typedef enum { BOLTNET_FRAME_ELEMENT = 0, BOLTNET_FRAME_MATERIAL = 1 } BoltnetFrame;
typedef struct {
  PetscReal axes[9];
  PetscReal N[3], M[3], Q[2];
  PetscReal strain_top[3], strain_bottom[3];
  PetscBool homogeneous;
  PetscReal stress_top[3], stress_bottom[3], von_mises_top, von_mises_bottom;
} BoltnetElementResult;
PETSC_EXTERN PetscErrorCode BoltnetAssemblyGetElementResult(BoltnetAssembly, PetscInt part, PetscInt element, BoltnetFrame, BoltnetElementResult *);

/* The boltnet line search (-snes_linesearch_type boltnet) and the joint-state SNES monitor. */
#define SNESLINESEARCHBOLTNET "boltnet"
/* Joint-state callback a line search can use: the number of joints whose state at x differs from
   their state at the reference point (summed over ranks). */
typedef PetscErrorCode (*BoltnetStateChangeFn)(SNES, Vec ref, Vec x, PetscInt *nchanged, void *ctx);
PETSC_EXTERN PetscErrorCode SNESLineSearchBoltnetSetStateChangeFunction(SNESLineSearch, BoltnetStateChangeFn, void *);

/* A PETSc program that loads the line search as a plugin (-dll_append libboltnet_snes.so) and does not
   link boltnet gives it its states by composing them on its SNES, at any time before SNESSolve()
   (docs/petsc-plugin.md has the complete recipe and an example, test/foreign_switch.c):

   - a state-change count, the BoltnetStateChangeFn above (ctx is the SNES's application context,
     SNESSetApplicationContext()):
       PetscObjectComposeFunction((PetscObject)snes, "SNESLineSearchBoltnetStateChange_C", fn);
   - or switch indicators: fn(snes, x, s, ctx) fills s with the values s_i(x) whose signs define the
     states (s_i > 0 against s_i <= 0: a gap, a yield function, ...; ctx as above), and a Vec with
     the layout of s (the line search duplicates it):
       PetscObjectComposeFunction((PetscObject)snes, "SNESLineSearchBoltnetSwitches_C", fn);
       PetscObjectCompose((PetscObject)snes, "SNESLineSearchBoltnetSwitches", (PetscObject)s);
     A state change is an indicator that changes sign; the count is summed over ranks.

   SNESLineSearchBoltnetSetStateChangeFunction() takes precedence over both (without boltnet.h: the
   method "SNESLineSearchBoltnetSetStateChangeFunction_C" that PetscObjectQueryFunction finds on the
   line search once it has its type); the count takes precedence over the switches. Composing NULL
   removes them. -snes_view says which one the line search uses. */
#define SNESLINESEARCHBOLTNET_STATECHANGE  "SNESLineSearchBoltnetStateChange_C"
#define SNESLINESEARCHBOLTNET_SWITCHES_FN  "SNESLineSearchBoltnetSwitches_C"
#define SNESLINESEARCHBOLTNET_SWITCHES_VEC "SNESLineSearchBoltnetSwitches"
typedef PetscErrorCode (*BoltnetSwitchFn)(SNES, Vec x, Vec s, void *ctx);

#if defined(__cplusplus)
}
#endif
#endif
