// Joint laws: see law.hpp and docs/joint-laws.md for the formulas.
#include "joint/law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace boltnet {
namespace {

using Mat2 = std::array<double, 4>; // row major 2x2

// Bearing term of the in-plane force: k <|d| - j>+ d/|d| and its derivative with respect to d.
struct Bearing {
  std::array<double, 2> force{0, 0};
  Mat2                  dforce{0, 0, 0, 0};
  bool                  active = false;
};

Bearing bearing(double k, double j, double d0, double d1)
{
  Bearing b;
  if (j == 0.0) {
    // No clearance: the bolt bears for every d, and the term is the linear k d, also at d = 0, where
    // the formula below has no direction d/|d|. (Treating d = 0 as "not bearing" gave the contact
    // law the tangent k = kt there, zero when kt = 0, while its force is kc du for every du.)
    b.active = true;
    b.force  = {k * d0, k * d1};
    b.dforce = {k, 0, 0, k};
    return b;
  }
  const double r = std::hypot(d0, d1);
  if (!(r > j)) return b;
  const double m[2] = {d0 / r, d1 / r};
  const double s    = (r - j) / r; // secant factor, in (0, 1]
  b.active          = true;
  b.force           = {k * (r - j) * m[0], k * (r - j) * m[1]};
  for (int a = 0; a < 2; ++a)
    for (int c = 0; c < 2; ++c) b.dforce[2 * a + c] = k * (m[a] * m[c] + s * ((a == c) - m[a] * m[c]));
  return b;
}

// The stiffness the consistent tangent adds to dh/dw for pure Coulomb (kg = 0) where h has none:
// kSlideFloor ke in the whole plane inside the clearance; in bearing only across the radius
// (sliding around the hole), since the radial kc is there. Zero for kg > 0. Public as slideFloorOf().
Mat2 slideFloor(const Params &p, const Bearing &b, const double w[2])
{
  const double f = kSlideFloor * p.kt;
  if (p.kg > 0) return {0, 0, 0, 0};
  if (!b.active) return {f, 0, 0, f};
  const double d0 = w[0] - p.offset[0], d1 = w[1] - p.offset[1], r = std::hypot(d0, d1);
  if (r == 0) return {0, 0, 0, 0}; // gap = 0 at the centre: h = kc w is isotropic, kc I
  const double m[2] = {d0 / r, d1 / r};
  return {f * (1 - m[0] * m[0]), -f * m[0] * m[1], -f * m[1] * m[0], f * (1 - m[1] * m[1])};
}

void setInPlane(Mat6 &K, const Mat2 &T)
{
  K[6 * 1 + 1] = T[0];
  K[6 * 1 + 2] = T[1];
  K[6 * 2 + 1] = T[2];
  K[6 * 2 + 2] = T[3];
}

void linearParts(const Params &p, const Vec6 &du, Response &r)
{
  r.force[0]   = p.kn * du[0];
  r.tangent[0] = p.kn;
  for (int i = 3; i < 6; ++i) {
    r.force[i]           = p.kr * du[i];
    r.tangent[6 * i + i] = p.kr;
  }
}

void evaluateSpring(const Params &p, const Vec6 &du, Response &r)
{
  r.state = State::Linear;
  if (p.full) { // F = K du, tangent K: replaces the diagonal parts linearParts() set
    for (int i = 0; i < 6; ++i) {
      double f = 0;
      for (int k = 0; k < 6; ++k) f += p.K[6 * i + k] * du[k];
      r.force[i] = f;
    }
    std::copy(p.K, p.K + 36, r.tangent.begin());
    return;
  }
  r.force[1] = p.kt * du[1];
  r.force[2] = p.kt * du[2];
  setInPlane(r.tangent, {p.kt, 0, 0, p.kt});
}

// Paper sect. 2.1: F_t = k du_t for r <= j and (k j + k' (r - j)) du_t / r beyond, written as
// k du_t + (k' - k) <r - j>+ d / r with d = du_t - offset (the offset moves the clearance circle).
void evaluateContact(const Params &p, const Vec6 &du, Tangent tangent, bool frozen, Response &r)
{
  const Bearing b = frozen ? Bearing{} : bearing(p.kc - p.kt, p.gap, du[1] - p.offset[0], du[2] - p.offset[1]);
  r.force[1]      = p.kt * du[1] + b.force[0];
  r.force[2]      = p.kt * du[2] + b.force[1];
  r.state         = b.active ? State::Contact : State::Open;
  r.bearing       = b.active;
  if (tangent == Tangent::Paper) {
    const double k = b.active ? p.kc : p.kt;
    setInPlane(r.tangent, {k, 0, 0, k});
  } else {
    setInPlane(r.tangent, {p.kt + b.dforce[0], b.dforce[1], b.dforce[2], p.kt + b.dforce[3]});
  }
}

// Paper sect. 2.2 as an incremental law: Jenkins element (ke, G) on the slip w, plus the slip
// resistance h(w) = kg w + (kc - kg) <|w - c| - j>+ m. Monotonic loading gives the paper's
// F = ke du, G + kg (du - G/ke), G + kg j + kc (du - G/ke - j) exactly (docs/joint-laws.md).
void evaluateFriction(const Params &p, const History &h, const Vec6 &du, Tangent tangent, bool frozen, Response &r)
{
  const double ke = p.kt;
  const double Fn = p.kn * du[0];
  const double G  = frictionThreshold(p, Fn);
  const double dG = (p.mu * p.nf * (p.pretension - p.clamp_coupling * Fn) > 0) ? -p.mu * p.nf * p.clamp_coupling * p.kn : 0.0;

  const double Ftr[2] = {ke * (du[1] - h.slip[0]), ke * (du[2] - h.slip[1])};
  const double a      = std::hypot(Ftr[0], Ftr[1]);
  const bool   slide  = !frozen && a > G * (1.0 + 1e-10) && a > 0.0;

  double w[2] = {h.slip[0], h.slip[1]};
  double Ff[2] = {Ftr[0], Ftr[1]};
  double n[2]  = {0, 0};
  if (slide) {
    n[0]  = Ftr[0] / a;
    n[1]  = Ftr[1] / a;
    Ff[0] = G * n[0];
    Ff[1] = G * n[1];
    w[0]  = du[1] - G * n[0] / ke;
    w[1]  = du[2] - G * n[1] / ke;
  }
  const Bearing b = bearing(p.kc - p.kg, p.gap, w[0] - p.offset[0], w[1] - p.offset[1]);
  r.force[1]      = Ff[0] + p.kg * w[0] + b.force[0];
  r.force[2]      = Ff[1] + p.kg * w[1] + b.force[1];
  r.trial.slip[0] = w[0];
  r.trial.slip[1] = w[1];
  r.bearing       = b.active;
  r.state         = !slide ? State::Stick : (b.active ? State::Contact : State::Slide);
  r.trial.state   = static_cast<int>(r.state);

  // The Jacobian only: pure Coulomb (kg = 0) has no stiffness along the slip, and the tangent would be
  // singular while the bolt slides across its clearance under a prescribed force; it takes
  // kSlideFloor ke there. The force keeps kg = 0: converged solutions do not change, only the Newton
  // steps toward them (the line search lengthens a step that stays on the flat plateau,
  // docs/solver.md). Any kg > 0 is its own tangent: a stiffer floor would shorten every Newton step
  // by kg / floor, and a slide with no bearing in reach would converge only linearly.
  const double kg_t  = p.kg > 0 ? p.kg : kSlideFloor * ke;
  const Mat2   floor = slideFloor(p, b, w);
  if (tangent == Tangent::Paper) {
    const double k = r.state == State::Stick ? ke : (r.state == State::Slide ? kg_t : p.kc);
    setInPlane(r.tangent, {k, 0, 0, k});
    return;
  }
  if (!slide) { // h(w) is frozen while stuck
    setInPlane(r.tangent, {ke, 0, 0, ke});
    return;
  }
  // Consistent tangent: dF/ddu_t = G ke/a P + Hw (I - G/a P), P = I - n n^T, Hw = dh/dw.
  const Mat2 P  = {1 - n[0] * n[0], -n[0] * n[1], -n[1] * n[0], 1 - n[1] * n[1]};
  const Mat2 Hw = {p.kg + floor[0] + b.dforce[0], floor[1] + b.dforce[1], floor[2] + b.dforce[2], p.kg + floor[3] + b.dforce[3]};
  Mat2       T{};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      double v = G * ke / a * P[2 * i + j];
      for (int k = 0; k < 2; ++k) v += Hw[2 * i + k] * ((k == j) - G / a * P[2 * k + j]);
      T[2 * i + j] = v;
    }
  setInPlane(r.tangent, T);
  // Clamp-force coupling: dF_t/ddu_n = (n - Hw n / ke) dG/ddu_n.
  for (int i = 0; i < 2; ++i) r.tangent[6 * (1 + i) + 0] = (n[i] - (Hw[2 * i] * n[0] + Hw[2 * i + 1] * n[1]) / ke) * dG;
}

} // namespace

std::array<double, 4> slideFloorOf(const Params &p, const History &trial, bool bearing_active)
{
  Bearing b;
  b.active = bearing_active;
  return slideFloor(p, b, trial.slip);
}

double frictionThreshold(const Params &p, double normal_force)
{
  return p.mu * p.nf * std::max(0.0, p.pretension - p.clamp_coupling * normal_force);
}

Response evaluate(const Params &p, const History &committed, const Vec6 &jump, Tangent tangent, bool frozen)
{
  Response r;
  r.trial = committed;
  linearParts(p, jump, r);
  switch (p.law) {
  case Law::Spring: evaluateSpring(p, jump, r); break;
  case Law::Contact: evaluateContact(p, jump, tangent, frozen, r); break;
  case Law::Friction: evaluateFriction(p, committed, jump, tangent, frozen, r); break;
  }
  r.trial.state = static_cast<int>(r.state);
  return r;
}

double utilization(const Params &p, const History &h, const Vec6 &du)
{
  const double inf = std::numeric_limits<double>::infinity();
  switch (p.law) {
  case Law::Spring: return 0.0;
  case Law::Contact: {
    // gap = 0: the bolt bears at every jump (F = kc du), the open spring kt du is the law nowhere.
    const double r = std::hypot(du[1] - p.offset[0], du[2] - p.offset[1]);
    return p.gap > 0 ? r / p.gap : inf;
  }
  case Law::Friction: {
    const double a = p.kt * std::hypot(du[1] - h.slip[0], du[2] - h.slip[1]);
    const double G = frictionThreshold(p, p.kn * du[0]);
    return G > 0 ? a / G : (a > 0 ? inf : 0.0);
  }
  }
  return inf;
}

std::string validate(const Params &p)
{
  std::ostringstream msg;
  auto nonneg = [&](const char *name, double v) {
    if (!(v >= 0) || !std::isfinite(v)) msg << name << " = " << v << " must be a finite number >= 0; ";
  };
  nonneg("kn", p.kn);
  nonneg("kt", p.kt);
  nonneg("kr", p.kr);
  nonneg("kc", p.kc);
  nonneg("kg", p.kg);
  nonneg("gap", p.gap);
  nonneg("mu", p.mu);
  nonneg("pretension", p.pretension);
  nonneg("clamp_coupling", p.clamp_coupling);
  if (!msg.str().empty()) return msg.str();
  if (p.full) {
    if (p.law != Law::Spring) return std::string("a full stiffness matrix K is a spring's: the ") + lawName(p.law) + " law has its own (kn, kt, kr, ...); ";
    double scale = 0;
    for (double v : p.K) scale = std::isfinite(v) ? std::max(scale, std::fabs(v)) : HUGE_VAL;
    if (!std::isfinite(scale)) return "the full stiffness K has a term that is not a finite number; ";
    for (int i = 0; i < 6; ++i) {
      if (p.K[7 * i] < 0) msg << "K[" << i << "][" << i << "] = " << p.K[7 * i] << " must be >= 0; ";
      for (int k = i + 1; k < 6; ++k)
        if (std::fabs(p.K[6 * i + k] - p.K[6 * k + i]) > 1e-12 * scale)
          msg << "K[" << i << "][" << k << "] = " << p.K[6 * i + k] << " and K[" << k << "][" << i << "] = " << p.K[6 * k + i] << " differ: a spring's stiffness is symmetric; ";
    }
    return msg.str();
  }
  if (!std::isfinite(p.offset[0]) || !std::isfinite(p.offset[1])) msg << "offset must be finite; ";
  if (!(p.nf >= 1) || !std::isfinite(p.nf) || p.nf != std::floor(p.nf)) msg << "nf = " << p.nf << " must be a whole number >= 1 (friction interfaces); ";
  if (p.law != Law::Spring && std::hypot(p.offset[0], p.offset[1]) > p.gap)
    msg << "offset (" << p.offset[0] << ", " << p.offset[1] << ") puts the bolt outside its clearance circle of radius gap = " << p.gap << "; ";
  if (p.law == Law::Friction) {
    if (!(p.kt > 0)) msg << "kt (the stick stiffness ke) = " << p.kt << " must be > 0; ";
    else {
      if (p.kg > p.kt) msg << "kg = " << p.kg << " must not exceed kt = " << p.kt << " (sliding is softer than sticking); ";
      if (p.kc > p.kt)
        msg << "kc = " << p.kc << " must not exceed kt = " << p.kt
            << ": with bearing stiffer than sticking the law would create energy over a load cycle (docs/joint-laws.md); ";
    }
    if (p.kc < p.kg) msg << "kc = " << p.kc << " must be >= kg = " << p.kg << " (bearing is stiffer than sliding); ";
  }
  return msg.str();
}

const char *stateName(State s)
{
  switch (s) {
  case State::Linear: return "linear";
  case State::Open: return "open";
  case State::Contact: return "contact";
  case State::Stick: return "stick";
  case State::Slide: return "slide";
  }
  return "unknown";
}

const char *lawName(Law l)
{
  switch (l) {
  case Law::Spring: return "spring";
  case Law::Contact: return "contact";
  case Law::Friction: return "friction";
  }
  return "unknown";
}

bool parseLaw(const std::string &name, Law *law)
{
  if (name == "spring") *law = Law::Spring;
  else if (name == "contact") *law = Law::Contact;
  else if (name == "friction") *law = Law::Friction;
  else return false;
  return true;
}

} // namespace boltnet
