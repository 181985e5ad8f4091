// Package initialisation: registers boltnet's PETSc types once per PetscInitialize.
#include "boltnet.h"
#include "core/check.hpp"
#include "core/compat.h"
#include "core/log.hpp"
#include "joint/law.hpp"

extern "C" PetscErrorCode SNESLineSearchCreate_Boltnet(SNESLineSearch);

namespace {
PetscBool          packageInitialized = PETSC_FALSE; // reset by the finalizer registered with PETSc
boltnet::LogEvents events;                            // registered with the package, like PETSc's own
} // namespace

const boltnet::LogEvents &boltnet::Events()
{
  return events;
}

/*@C
  BoltnetFinalizePackage - called by PetscFinalize(); resets the package so that a later
  PetscInitialize() registers the types again.
@*/
PetscErrorCode BoltnetFinalizePackage(void)
{
  PetscFunctionBeginUser;
  packageInitialized = PETSC_FALSE;
  PetscFunctionReturn(0);
}

/*@C
  BoltnetInitializePackage - registers the boltnet line search (SNESLINESEARCHBOLTNET). Idempotent;
  call it after PetscInitialize() and before SNESSetFromOptions(). The plugin calls it from
  PetscDLLibraryRegister_boltnet_snes().
@*/
PetscErrorCode BoltnetInitializePackage(void)
{
  PetscFunctionBeginUser;
  if (packageInitialized) PetscFunctionReturn(0);
  packageInitialized = PETSC_TRUE;
  PetscCall(SNESInitializePackage());
  PetscCall(SNESLineSearchRegister(SNESLINESEARCHBOLTNET, SNESLineSearchCreate_Boltnet));
  PetscCall(PetscClassIdRegister("boltnet", &events.classid));
  PetscCall(PetscLogEventRegister("BoltnetLayout", events.classid, &events.layout));
  PetscCall(PetscLogEventRegister("BoltnetNetwork", events.classid, &events.network));
  PetscCall(PetscLogEventRegister("BoltnetCondense", events.classid, &events.condense));
  PetscCall(PetscLogEventRegister("BoltnetPatchMatrix", events.classid, &events.patch_matrix));
  PetscCall(PetscLogEventRegister("BoltnetSchur", events.classid, &events.schur));
  PetscCall(PetscLogEventRegister("BoltnetResidual", events.classid, &events.residual));
  PetscCall(PetscLogEventRegister("BoltnetJacobian", events.classid, &events.jacobian));
  PetscCall(PetscLogEventRegister("BoltnetJoints", events.classid, &events.joints));
  PetscCall(PetscLogEventRegister("BoltnetInterfaceSolve", events.classid, &events.interface_solve));
  PetscCall(PetscLogEventRegister("BoltnetRecover", events.classid, &events.recover));
  PetscCall(PetscLogEventRegister("BoltnetOutput", events.classid, &events.output));
  PetscCall(PetscLogEventRegister("BoltnetElementResults", events.classid, &events.element_results));
  PetscCall(PetscLogEventRegister("BoltnetJointOutput", events.classid, &events.joint_output));
  PetscCall(PetscLogEventRegister("BoltnetJointGather", events.classid, &events.joint_gather));
  PetscCall(PetscLogStageRegister("Boltnet Set-up", &events.setup_stage));
  PetscCall(PetscLogStageRegister("Boltnet Condense", &events.condense_stage));
  PetscCall(PetscLogStageRegister("Boltnet Solve", &events.solve_stage));
  PetscCall(PetscLogStageRegister("Boltnet Output", &events.output_stage));
  PetscCall(PetscRegisterFinalize(BoltnetFinalizePackage));
  PetscFunctionReturn(0);
}

PetscErrorCode BoltnetJointParamsSetDefault(BoltnetLaw law, BoltnetJointParams *p)
{
  PetscFunctionBeginUser;
  BoltnetCheckPointer(p, 2, "BoltnetJointParams *");
  PetscCheck(law >= BOLTNET_LAW_SPRING && law <= BOLTNET_LAW_FRICTION, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s: argument 1 (law) = %d is not a BoltnetLaw", __func__, (int)law);
  const boltnet::Params d; // the library's defaults (plain numbers: nothing here throws)
  p->law            = law;
  p->kn             = d.kn;
  p->kt             = d.kt;
  p->kr             = d.kr;
  p->kc             = d.kc;
  p->kg             = d.kg;
  p->gap            = d.gap;
  p->mu             = d.mu;
  p->nf             = d.nf;
  p->pretension     = d.pretension;
  p->clamp_coupling = d.clamp_coupling;
  p->offset[0]      = d.offset[0];
  p->offset[1]      = d.offset[1];
  PetscFunctionReturn(0);
}

// "unknown" for a value that is no BoltnetJointState (never NULL, never an error).
const char *BoltnetJointStateName(BoltnetJointState s)
{
  return boltnet::stateName(static_cast<boltnet::State>(s));
}
