// SNESLINESEARCHBOLTNET: a backtracking line search that knows about joint states.
//
// The joint laws are piecewise smooth: the residual has kinks where a joint changes state, and the
// state-switched tangent is exact only on the side of the kink where it was computed. A full Newton
// step that crosses kinks can overshoot and, on the way back, cross them again: the iterates chatter
// between states and Newton never converges (docs/solver.md shows such a case). This line search
//   0. with joint states attached, a watchdog: takes the full (damped) step even when ||F|| grows,
//      for up to `watchdog` iterations in a row without progress against the last reference point
//      (a point whose ||F|| the iterates have not beaten since). When many joints leave stick in
//      the same step, full Newton steps raise ||F|| before they converge; a monotone search rejects
//      them and advances one state change per iteration. When the iterates chatter between states
//      instead, the watchdog runs out and steps 1-3 take over from where they are. Once an iterate
//      has beaten the solve's starting point, the watchdog also tries the half step and takes it
//      where it is the better: full steps that overshoot to the far side of the solution, each a
//      little below the last reference point, would otherwise keep the watchdog going for tens of
//      iterations (plate grids of 10 x 9 plates and more, docs/solver.md);
//   1. tries the full (damped) step and accepts it on sufficient decrease of ||F|| (as PETSc's bt);
//   2. otherwise, if a joint-state function was attached (boltnet's assembly does it), bisects the
//      step for the first point where a joint changes state and tries just past it: up to that point
//      the model is smooth, so the step is safe, and the next Jacobian sees the new state;
//   3. otherwise backtracks with the quadratic model of bt.
// Before 0, a plateau: when the full step leaves ||F|| unchanged (to round-off) and no joint changes
// state on it, the iterate sits on a flat stretch of the residual (a pure Coulomb joint sliding
// across its clearance under a prescribed force: F = G whatever the slip). No decrease can be
// measured there, and the Newton step (set by the tangent's floor, not by the residual) may end
// short of the plateau's end. The step is doubled until a joint changes state, then bisected to
// the first change and taken just past it, where the next Jacobian sees the new state (bearing).
// Without a state function it is steps 1 and 3: a safeguarded Armijo backtracking that keeps the
// contract of bt (pre/post-check, maxstep, Inf/NaN and domain errors cut the step, failure reported
// as a line-search reason).
//
// Where the state function comes from (StateSource below), first match wins:
//   a. SNESLineSearchBoltnetSetStateChangeFunction() (boltnet's assembly), or the method it calls,
//      "SNESLineSearchBoltnetSetStateChangeFunction_C", found with PetscObjectQueryFunction;
//   b. a BoltnetStateChangeFn composed on the SNES as "SNESLineSearchBoltnetStateChange_C";
//   c. a BoltnetSwitchFn composed on the SNES as "SNESLineSearchBoltnetSwitches_C" with a Vec of the
//      switches' layout composed as "SNESLineSearchBoltnetSwitches": a state change is a switch
//      indicator that changes sign (s > 0 against s <= 0).
// b and c let a PETSc program that loads the plugin with -dll_append, and so cannot link boltnet,
// give it its states (docs/petsc-plugin.md). They are looked up at every application, so they work
// whenever they are composed and whatever the order of SNESSetFromOptions and SNESLineSearchSetType.
#include "boltnet.h"
#include "core/compat.h"
#include "core/check.hpp"
#include "core/guard.hpp"

#include <petsc/private/linesearchimpl.h>
#include <petsc/private/snesimpl.h>

#include <cmath>

namespace {

struct LineSearchBoltnet {
  PetscReal            alpha     = 1e-4; // sufficient decrease parameter
  PetscInt             bisections = 12;  // resolution of the search for the first state change: 2^-n
  PetscInt             watchdog  = 3;     // full steps allowed in a row without progress
  PetscInt             extensions = 30;  // doublings of a step that stays on a plateau (2^30 ~ 1e9)
  PetscReal            growth    = 1e3;   // ... while ||F|| stays below growth * reference
  PetscInt             watch     = 0;     // steps taken since the reference point
  PetscReal            ref       = 0;     // ||F|| at the reference point
  PetscBool            beaten    = PETSC_FALSE; // an iterate of this solve has beaten its starting point
  BoltnetStateChangeFn statefn   = nullptr; // set by SNESLineSearchBoltnetSetStateChangeFunction()
  void                *statectx  = nullptr;
  Vec                  sref = nullptr, strial = nullptr; // switch indicators at X and at the trial point
  PetscInt             kinkSteps = 0;     // statistics, shown by -snes_linesearch_view
  PetscInt             backtracks = 0;
  PetscInt             relaxed    = 0;    // full steps taken by the watchdog
  PetscInt             extended   = 0;    // plateau steps lengthened to the next state change
  PetscBool            halve      = PETSC_TRUE; // the watchdog tries the half step too, and takes the better
  PetscInt             halved     = 0;    // watchdog steps where the half step was the better
};

// ||F|| unchanged by a step, to round-off: the residual is flat along it.
bool Flat(PetscReal gnorm, PetscReal fnorm) { return std::isfinite(gnorm) && std::abs(gnorm - fnorm) <= 1e-10 * fnorm; }

// Where this application's state function comes from (see the top of the file).
enum class StateKind { None, Set, Composed, Switches };
const char *StateKindName(StateKind k)
{
  switch (k) {
  case StateKind::Set: return "attached (SNESLineSearchBoltnetSetStateChangeFunction)";
  case StateKind::Composed: return "attached (SNESLineSearchBoltnetStateChange_C composed on the SNES)";
  case StateKind::Switches: return "attached (switch indicators SNESLineSearchBoltnetSwitches_C composed on the SNES)";
  default: return "not attached (plain backtracking)";
  }
}

struct StateSource {
  StateKind            kind = StateKind::None;
  BoltnetStateChangeFn fn   = nullptr;
  BoltnetSwitchFn      sw   = nullptr;
  void                *ctx  = nullptr;
  Vec                  layout = nullptr; // composed with the switch function
  PetscBool            haveRef = PETSC_FALSE; // switches at X computed (X does not change during an application)
};

PetscErrorCode GetStateSource(LineSearchBoltnet *bn, SNES snes, StateSource *src)
{
  PetscFunctionBeginUser;
  *src = StateSource();
  if (bn->statefn) {
    src->kind = StateKind::Set;
    src->fn   = bn->statefn;
    src->ctx  = bn->statectx;
    PetscFunctionReturn(0);
  }
  if (!snes) PetscFunctionReturn(0);
  PetscCall(PetscObjectQueryFunction((PetscObject)snes, SNESLINESEARCHBOLTNET_STATECHANGE, &src->fn));
  if (!src->fn) PetscCall(PetscObjectQueryFunction((PetscObject)snes, SNESLINESEARCHBOLTNET_SWITCHES_FN, &src->sw));
  if (!src->fn && !src->sw) PetscFunctionReturn(0);
  PetscCall(SNESGetApplicationContext(snes, &src->ctx));
  if (src->fn) {
    src->kind = StateKind::Composed;
    PetscFunctionReturn(0);
  }
  PetscObject obj;
  PetscCall(PetscObjectQuery((PetscObject)snes, SNESLINESEARCHBOLTNET_SWITCHES_VEC, &obj));
  PetscCheck(obj, PetscObjectComm((PetscObject)snes), PETSC_ERR_ARG_WRONGSTATE, "A switch function is composed on the SNES as \"%s\" but no Vec of the switches' layout as \"%s\" (docs/petsc-plugin.md)", SNESLINESEARCHBOLTNET_SWITCHES_FN, SNESLINESEARCHBOLTNET_SWITCHES_VEC);
  PetscCheck(obj->classid == VEC_CLASSID, PetscObjectComm((PetscObject)snes), PETSC_ERR_ARG_WRONG, "The object composed on the SNES as \"%s\" is a %s, not a Vec", SNESLINESEARCHBOLTNET_SWITCHES_VEC, obj->class_name);
  src->kind   = StateKind::Switches;
  src->layout = (Vec)obj;
  PetscFunctionReturn(0);
}

// The work vectors of the switch indicators follow the composed layout Vec (it may be replaced).
PetscErrorCode SwitchVectors(LineSearchBoltnet *bn, Vec layout)
{
  PetscBool same = PETSC_FALSE;
  PetscFunctionBeginUser;
  if (bn->sref) {
    PetscInt n0, n1, N0, N1;
    PetscCall(VecGetLocalSize(bn->sref, &n0));
    PetscCall(VecGetLocalSize(layout, &n1));
    PetscCall(VecGetSize(bn->sref, &N0));
    PetscCall(VecGetSize(layout, &N1));
    same = (n0 == n1 && N0 == N1) ? PETSC_TRUE : PETSC_FALSE;
    // Local sizes may change on some ranks only: every rank must take the same branch below.
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &same, 1, MPIU_BOOL, MPI_LAND, PetscObjectComm((PetscObject)layout)));
  }
  if (same) PetscFunctionReturn(0);
  PetscCall(VecDestroy(&bn->sref));
  PetscCall(VecDestroy(&bn->strial));
  PetscCall(VecDuplicate(layout, &bn->sref));
  PetscCall(VecDuplicate(layout, &bn->strial));
  PetscFunctionReturn(0);
}

// The number of states that differ between X and W (summed over ranks), from the state source.
PetscErrorCode CountStateChanges(LineSearchBoltnet *bn, StateSource *src, SNES snes, Vec X, Vec W, PetscInt *n)
{
  PetscFunctionBeginUser;
  *n = 0;
  if (src->fn) {
    PetscCall((*src->fn)(snes, X, W, n, src->ctx));
    PetscFunctionReturn(0);
  }
  if (!src->haveRef) {
    PetscCall(SwitchVectors(bn, src->layout));
    PetscCall((*src->sw)(snes, X, bn->sref, src->ctx));
    src->haveRef = PETSC_TRUE;
  }
  PetscCall((*src->sw)(snes, W, bn->strial, src->ctx));
  const PetscScalar *a, *b;
  PetscInt           m, local = 0;
  PetscCall(VecGetLocalSize(bn->sref, &m));
  PetscCall(VecGetArrayRead(bn->sref, &a));
  PetscCall(VecGetArrayRead(bn->strial, &b));
  for (PetscInt i = 0; i < m; ++i) local += ((PetscRealPart(a[i]) > 0) != (PetscRealPart(b[i]) > 0));
  PetscCall(VecRestoreArrayRead(bn->sref, &a));
  PetscCall(VecRestoreArrayRead(bn->strial, &b));
  PetscCall(MPIU_Allreduce(&local, n, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)bn->sref)));
  PetscFunctionReturn(0);
}

// F at W = X - lambda Y; returns gnorm = inf when F could not be evaluated there.
PetscErrorCode TryStep(SNESLineSearch ls, SNES snes, Vec X, Vec Y, PetscReal lambda, Vec W, Vec G, PetscReal *gnorm)
{
  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(W, -lambda, Y, X));
  if (ls->ops->viproject) PetscCall((*ls->ops->viproject)(snes, W));
  PetscCall((*ls->ops->snesfunc)(snes, W, G));
  if (snes->domainerror) {
    snes->domainerror = PETSC_FALSE;
    *gnorm            = PETSC_INFINITY;
    PetscFunctionReturn(0);
  }
  PetscCall(VecNorm(G, NORM_2, gnorm));
  if (PetscIsInfOrNanReal(*gnorm)) *gnorm = PETSC_INFINITY;
  PetscFunctionReturn(0);
}

PetscErrorCode SNESLineSearchApplyImpl(SNESLineSearch ls)
{
  auto     *bn = static_cast<LineSearchBoltnet *>(ls->data);
  SNES      snes;
  Vec       X, F, Y, W, G;
  PetscReal fnorm, xnorm, ynorm, gnorm, lambda, minlambda, maxstep;
  PetscInt  maxits;
  PetscBool changed_y = PETSC_FALSE, changed_w = PETSC_FALSE, accepted = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(SNESLineSearchGetSNES(ls, &snes));
  PetscCall(SNESLineSearchGetVecs(ls, &X, &F, &Y, &W, &G));
  PetscCall(SNESLineSearchGetNorms(ls, &xnorm, &fnorm, &ynorm));
  PetscCall(SNESLineSearchGetLambda(ls, &lambda));
  PetscCall(SNESLineSearchGetTolerances(ls, &minlambda, &maxstep, nullptr, nullptr, nullptr, &maxits));
  PetscCall(SNESLineSearchSetReason(ls, SNES_LINESEARCH_SUCCEEDED));

  PetscCall(SNESLineSearchPreCheck(ls, X, Y, &changed_y));
  PetscCall(VecNorm(Y, NORM_2, &ynorm));
  if (ynorm == 0.0) { // nothing to do: keep X and F
    PetscCall(SNESLineSearchSetNorms(ls, xnorm, fnorm, ynorm));
    PetscFunctionReturn(0);
  }
  if (ynorm > maxstep) { // step limit, as bt
    PetscCall(VecScale(Y, maxstep / ynorm));
    ynorm = maxstep;
  }
  lambda = ls->damping;

  if (snes->iter == 0) { // a new solve: the starting point is the reference
    bn->watch  = 0;
    bn->ref    = fnorm;
    bn->beaten = PETSC_FALSE;
  }
  StateSource src;
  PetscCall(GetStateSource(bn, snes, &src));
  const PetscBool states = src.kind != StateKind::None ? PETSC_TRUE : PETSC_FALSE;
  const PetscReal f2     = fnorm * fnorm;
  PetscBool       kinks  = states;
  PetscReal       best = PETSC_INFINITY, bestlambda = 0; // the best point tried, for an inexact Jacobian
  for (PetscInt it = 0; it < maxits && lambda >= minlambda; ++it) {
    PetscCall(TryStep(ls, snes, X, Y, lambda, W, G, &gnorm));
    if (gnorm < best) {
      best       = gnorm;
      bestlambda = lambda;
    }
    if (gnorm * gnorm <= (1.0 - 2.0 * bn->alpha * lambda) * f2) {
      accepted = PETSC_TRUE;
      break;
    }
    if (it == 0 && states && Flat(gnorm, fnorm)) { // a plateau: lengthen the step to the next state change
      PetscInt n;
      PetscCall(CountStateChanges(bn, &src, snes, X, W, &n));
      PetscReal lo = lambda, hi = lambda, g = gnorm;
      for (PetscInt k = 0; n == 0 && Flat(g, fnorm) && k < bn->extensions && 2 * hi * ynorm <= maxstep; ++k) {
        lo = hi;
        hi *= 2;
        PetscCall(TryStep(ls, snes, X, Y, hi, W, G, &g));
        PetscCall(CountStateChanges(bn, &src, snes, X, W, &n));
      }
      if (n > 0 && hi > lambda) { // the first state change lies in (lo, hi]: just past it
        for (PetscInt k = 0; k < bn->bisections; ++k) {
          const PetscReal mid = 0.5 * (lo + hi);
          PetscCall(VecWAXPY(W, -mid, Y, X));
          PetscCall(CountStateChanges(bn, &src, snes, X, W, &n));
          if (n > 0) hi = mid;
          else lo = mid;
        }
        PetscCall(TryStep(ls, snes, X, Y, hi, W, G, &g));
        if (std::isfinite(g) && g <= bn->growth * bn->ref) {
          if (ls->monitor) PetscCall(PetscViewerASCIIPrintf(ls->monitor, "    Line search: ||F|| flat along the step; lengthened to the first state change, lambda %g, ||F|| %g\n", (double)hi, (double)g));
          lambda   = hi;
          gnorm    = g;
          accepted = PETSC_TRUE;
          bn->extended++;
          break;
        }
      } else if (hi > lambda && g * g <= (1.0 - 2.0 * bn->alpha) * f2) { // the plateau ended without a state change
        lambda   = hi;
        gnorm    = g;
        accepted = PETSC_TRUE;
        bn->extended++;
        break;
      }
      PetscCall(TryStep(ls, snes, X, Y, lambda, W, G, &gnorm)); // back to the full step for what follows
    }
    if (it == 0 && states && bn->watch < bn->watchdog && std::isfinite(gnorm) && gnorm <= bn->growth * bn->ref) {
      if (bn->halve && bn->beaten) { // iterates that overshoot to the far side of the solution: the half step lands nearer
        PetscReal ghalf;
        PetscCall(TryStep(ls, snes, X, Y, 0.5 * lambda, W, G, &ghalf));
        if (std::isfinite(ghalf) && ghalf < gnorm) {
          if (ls->monitor) PetscCall(PetscViewerASCIIPrintf(ls->monitor, "    Line search: watchdog takes the half step, ||F|| %g -> %g (the full step: %g)\n", (double)fnorm, (double)ghalf, (double)gnorm));
          lambda   = 0.5 * lambda;
          gnorm    = ghalf;
          accepted = PETSC_TRUE;
          bn->halved++;
          break;
        }
        PetscCall(TryStep(ls, snes, X, Y, lambda, W, G, &gnorm)); // back to the full step
      }
      accepted = PETSC_TRUE; // the watchdog's full step
      bn->relaxed++;
      if (ls->monitor) PetscCall(PetscViewerASCIIPrintf(ls->monitor, "    Line search: watchdog takes the full step, ||F|| %g -> %g (%" PetscInt_FMT " of %" PetscInt_FMT " without progress)\n", (double)fnorm, (double)gnorm, bn->watch + 1, bn->watchdog));
      break;
    }
    if (kinks) { // look for the first state change on (0, lambda]
      kinks = PETSC_FALSE;
      PetscInt n;
      PetscCall(CountStateChanges(bn, &src, snes, X, W, &n));
      if (n > 0) {
        PetscReal lo = 0.0, hi = lambda;
        for (PetscInt k = 0; k < bn->bisections; ++k) {
          const PetscReal mid = 0.5 * (lo + hi);
          PetscCall(VecWAXPY(W, -mid, Y, X));
          PetscCall(CountStateChanges(bn, &src, snes, X, W, &n));
          if (n > 0) hi = mid;
          else lo = mid;
        }
        if (ls->monitor) PetscCall(PetscViewerASCIIPrintf(ls->monitor, "    Line search: first state change at lambda in (%g, %g]\n", (double)lo, (double)hi));
        bn->kinkSteps++;
        lambda = hi;
        continue; // try just past the first state change
      }
    }
    // Quadratic backtracking on phi(l) = ||F(X - l Y)||^2 / 2 with phi'(0) = -||F||^2 (Newton direction).
    bn->backtracks++;
    PetscReal next = 0.5 * lambda;
    if (std::isfinite(gnorm)) {
      const PetscReal denom = gnorm * gnorm - f2 + 2.0 * lambda * f2;
      if (denom > 0) next = lambda * lambda * f2 / denom;
    }
    lambda = PetscMax(0.1 * lambda, PetscMin(0.5 * lambda, next));
    if (ls->monitor) PetscCall(PetscViewerASCIIPrintf(ls->monitor, "    Line search: ||F|| %g -> %g, backtracking to lambda %g\n", (double)fnorm, (double)gnorm, (double)lambda));
  }
  if (!accepted && best < fnorm) {
    // With a Jacobian that is not the derivative (the paper's tangent) the direction need not be a
    // descent direction for ||F||: accept the best decrease found rather than stop.
    lambda = bestlambda;
    PetscCall(TryStep(ls, snes, X, Y, lambda, W, G, &gnorm));
    accepted = PETSC_TRUE;
    if (ls->monitor) PetscCall(PetscViewerASCIIPrintf(ls->monitor, "    Line search: no sufficient decrease; taking the best decrease, lambda %g, ||F|| %g\n", (double)lambda, (double)gnorm));
  }
  if (!accepted) {
    if (ls->monitor) PetscCall(PetscViewerASCIIPrintf(ls->monitor, "    Line search: no sufficient decrease of ||F|| down to lambda %g\n", (double)lambda));
    PetscCall(SNESLineSearchSetReason(ls, SNES_LINESEARCH_FAILED_REDUCT));
    PetscFunctionReturn(0);
  }
  // Progress against the reference point resets the watchdog; any other step uses it up.
  if (gnorm * gnorm <= (1.0 - 2.0 * bn->alpha) * bn->ref * bn->ref) {
    bn->watch  = 0;
    bn->ref    = gnorm;
    bn->beaten = PETSC_TRUE;
  } else bn->watch++;
  PetscCall(SNESLineSearchPostCheck(ls, X, Y, W, &changed_y, &changed_w));
  if (changed_w) {
    PetscCall((*ls->ops->snesfunc)(snes, W, G));
    PetscCall(VecNorm(G, NORM_2, &gnorm));
  }
  PetscCall(VecCopy(W, X));
  PetscCall(VecCopy(G, F));
  PetscCall(VecNorm(X, NORM_2, &xnorm));
  PetscCall(SNESLineSearchSetLambda(ls, lambda));
  PetscCall(SNESLineSearchSetNorms(ls, xnorm, gnorm, lambda * ynorm));
  PetscFunctionReturn(0);
}

// The line search's apply: it allocates nothing itself, but calls the application's state function,
// which may be C++ that throws; an exception must not travel on through SNES (C).
PetscErrorCode SNESLineSearchApply_Boltnet(SNESLineSearch ls)
{
  return boltnet::Guard("SNESLineSearchApply_Boltnet", [&] { return SNESLineSearchApplyImpl(ls); });
}

PetscErrorCode SNESLineSearchSetFromOptions_Boltnet(SNESLineSearch ls, PetscOptionItems *PetscOptionsObject)
{
  auto *bn = static_cast<LineSearchBoltnet *>(ls->data);
  PetscFunctionBeginUser;
  PetscOptionsHeadBegin(PetscOptionsObject, "SNESLineSearch boltnet options");
  PetscCall(PetscOptionsReal("-snes_linesearch_boltnet_alpha", "Sufficient decrease parameter of ||F||^2", "SNESLineSearchBoltnet", bn->alpha, &bn->alpha, nullptr));
  PetscCall(PetscOptionsInt("-snes_linesearch_boltnet_watchdog", "With a state function: full Newton steps allowed in a row without decreasing ||F|| below the last reference point (0: monotone search)", "SNESLineSearchBoltnet", bn->watchdog, &bn->watchdog, nullptr));
  PetscCall(PetscOptionsReal("-snes_linesearch_boltnet_growth", "The watchdog's full steps are taken while ||F|| stays below this multiple of the reference point's", "SNESLineSearchBoltnet", bn->growth, &bn->growth, nullptr));
  PetscCall(PetscOptionsInt("-snes_linesearch_boltnet_extensions", "With a state function: doublings of a step along which ||F|| stays flat, looking for the next state change (0: none)", "SNESLineSearchBoltnet", bn->extensions, &bn->extensions, nullptr));
  PetscCall(PetscOptionsBool("-snes_linesearch_boltnet_halve", "With a state function: where the watchdog would take a full step that does not decrease ||F||, try the half step too and take the better", "SNESLineSearchBoltnet", bn->halve, &bn->halve, nullptr));
  PetscCall(PetscOptionsInt("-snes_linesearch_boltnet_bisections", "With a state function: bisections that locate the first state change along the step (resolution 2^-n)", "SNESLineSearchBoltnet", bn->bisections, &bn->bisections, nullptr));
  PetscOptionsHeadEnd();
  PetscCheck(bn->alpha > 0 && bn->alpha < 0.5, PetscObjectComm((PetscObject)ls), PETSC_ERR_ARG_OUTOFRANGE, "-snes_linesearch_boltnet_alpha %g must lie in (0, 0.5)", (double)bn->alpha);
  PetscCheck(bn->watchdog >= 0, PetscObjectComm((PetscObject)ls), PETSC_ERR_ARG_OUTOFRANGE, "-snes_linesearch_boltnet_watchdog %" PetscInt_FMT " must be >= 0", bn->watchdog);
  PetscCheck(bn->growth >= 1, PetscObjectComm((PetscObject)ls), PETSC_ERR_ARG_OUTOFRANGE, "-snes_linesearch_boltnet_growth %g must be >= 1", (double)bn->growth);
  PetscCheck(bn->extensions >= 0 && bn->extensions <= 60, PetscObjectComm((PetscObject)ls), PETSC_ERR_ARG_OUTOFRANGE, "-snes_linesearch_boltnet_extensions %" PetscInt_FMT " must lie in [0, 60]", bn->extensions);
  PetscCheck(bn->bisections >= 1 && bn->bisections <= 50, PetscObjectComm((PetscObject)ls), PETSC_ERR_ARG_OUTOFRANGE, "-snes_linesearch_boltnet_bisections %" PetscInt_FMT " must lie in [1, 50]", bn->bisections);
  PetscFunctionReturn(0);
}

PetscErrorCode SNESLineSearchView_Boltnet(SNESLineSearch ls, PetscViewer viewer)
{
  auto     *bn = static_cast<LineSearchBoltnet *>(ls->data);
  PetscBool ascii;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (ascii) {
    SNES        snes = nullptr;
    StateSource src;
    PetscCall(SNESLineSearchGetSNES(ls, &snes));
    PetscCall(GetStateSource(bn, snes, &src));
    PetscCall(PetscViewerASCIIPrintf(viewer, "  boltnet: alpha %g, watchdog %" PetscInt_FMT " steps below %g x reference, %" PetscInt_FMT " bisections, state function %s\n", (double)bn->alpha, bn->watchdog, (double)bn->growth, bn->bisections, StateKindName(src.kind)));
    PetscCall(PetscViewerASCIIPrintf(viewer, "  boltnet: watchdog full steps %" PetscInt_FMT ", half steps %" PetscInt_FMT ", steps limited to a state change %" PetscInt_FMT ", plateau steps lengthened %" PetscInt_FMT ", quadratic backtracks %" PetscInt_FMT "\n", bn->relaxed, bn->halved, bn->kinkSteps, bn->extended, bn->backtracks));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode SNESLineSearchBoltnetSetStateChangeFunction_Boltnet(SNESLineSearch ls, BoltnetStateChangeFn fn, void *ctx)
{
  auto *bn = static_cast<LineSearchBoltnet *>(ls->data);
  PetscFunctionBeginUser;
  bn->statefn  = fn;
  bn->statectx = ctx;
  PetscFunctionReturn(0);
}

PetscErrorCode SNESLineSearchDestroy_Boltnet(SNESLineSearch ls)
{
  auto *bn = static_cast<LineSearchBoltnet *>(ls->data);
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&bn->sref));
  PetscCall(VecDestroy(&bn->strial));
  delete bn;
  ls->data = nullptr;
  PetscCall(PetscObjectComposeFunction((PetscObject)ls, "SNESLineSearchBoltnetSetStateChangeFunction_C", nullptr));
  PetscFunctionReturn(0);
}

} // namespace

/*@C
  SNESLineSearchBoltnetSetStateChangeFunction - gives the boltnet line search a function that counts
  the joints whose state differs between two points; a no-op for other line search types.

  Logically collective

  Input Parameters:
+ ls  - the line search
. fn  - the counting function (collective: returns the global count)
- ctx - its context
@*/
PetscErrorCode SNESLineSearchBoltnetSetStateChangeFunction(SNESLineSearch ls, BoltnetStateChangeFn fn, void *ctx)
{
  PetscFunctionBeginUser;
  // Explicit checks: PetscValidHeaderSpecific() does nothing in a PETSc built without debugging.
  BoltnetCheckPointer(ls, 1, "SNESLineSearch");
  PetscCheck(((PetscObject)ls)->classid == SNESLINESEARCH_CLASSID, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s: argument 1 is a %s, not a SNESLineSearch", __func__, ((PetscObject)ls)->class_name);
  PetscTryMethod(ls, "SNESLineSearchBoltnetSetStateChangeFunction_C", (SNESLineSearch, BoltnetStateChangeFn, void *), (ls, fn, ctx));
  PetscFunctionReturn(0);
}

extern "C" PetscErrorCode SNESLineSearchCreate_Boltnet(SNESLineSearch ls)
{
  PetscFunctionBeginUser;
  ls->ops->apply          = SNESLineSearchApply_Boltnet;
  ls->ops->destroy        = SNESLineSearchDestroy_Boltnet;
  ls->ops->setfromoptions = SNESLineSearchSetFromOptions_Boltnet;
  ls->ops->view           = SNESLineSearchView_Boltnet;
  ls->ops->reset          = nullptr;
  ls->ops->setup          = nullptr;
  PetscCall(boltnet::Guard("SNESLineSearchCreate_Boltnet", [&] {
    ls->data = new LineSearchBoltnet();
    return PetscErrorCode(0);
  }));
  ls->max_its             = 40;
  PetscCall(PetscObjectComposeFunction((PetscObject)ls, "SNESLineSearchBoltnetSetStateChangeFunction_C", SNESLineSearchBoltnetSetStateChangeFunction_Boltnet));
  PetscFunctionReturn(0);
}
