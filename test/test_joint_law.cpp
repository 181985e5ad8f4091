// Unit tests of the joint laws (lib/joint/law.hpp, law.cpp).
//
// Every expected value is an independent reference: a closed form written here from the model
// (docs/mission.md "The macroelement", docs/benchmarks.md "The macroelement") or a central finite
// difference of evaluate(). The laws are driven as a load stepper drives them: each step evaluates
// with the committed history, then commits Response::trial.
//
// Most load paths use dyadic parameters (ke = 1024, G = 128, j = 1/4, steps of 1/64 mm): every
// breakpoint then falls on a step boundary and every value is exact in binary floating point, so
// closed forms hold to 1e-12 relative and trapezoidal energy integrals are exact.
#include "joint/law.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <set>
#include <string>
#include <vector>

using namespace boltnet;

namespace {

constexpr double kClosed = 1e-12; // relative tolerance against closed forms
constexpr double kFD     = 1e-6;  // relative tolerance against central finite differences
const double     kPi     = std::acos(-1.0);

Vec6 jumpOf(double n, double t1, double t2, double rn = 0, double r1 = 0, double r2 = 0)
{
  return {n, t1, t2, rn, r1, r2};
}

// |got - want| <= rel * max(|want|, scale); scale sets the size of "zero" for entries that vanish.
::testing::AssertionResult Near(double got, double want, double rel, double scale = 0.0)
{
  const double tol = rel * std::max(std::abs(want), scale);
  if (std::abs(got - want) <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "got " << got << ", want " << want << " (diff " << got - want << ", tol " << tol
                                       << ")";
}

double K(const Mat6 &m, int i, int j) { return m[6 * i + j]; }

// ---------------------------------------------------------------------------------------------
// Parameter sets.

Params springParams()
{
  Params p;
  p.law = Law::Spring;
  p.kn  = 4000;
  p.kt  = 1500;
  p.kr  = 2e6;
  return p;
}

Params contactParams()
{
  Params p;
  p.law = Law::Contact;
  p.kn  = 5000;
  p.kt  = 300;  // k, before contact
  p.kc  = 3000; // k', after contact
  p.kr  = 1e6;
  p.gap = 0.15;
  return p;
}

// Dyadic friction joint: ke = 1024, kc = 512, kg = 64, j = 1/4, G = mu nf Pc = 0.25 * 2 * 256 = 128,
// so G/ke = 1/8: stick up to du = 1/8, slide up to du = 3/8, bearing beyond.
Params dyadicFriction()
{
  Params p;
  p.law        = Law::Friction;
  p.kn         = 4096;
  p.kt         = 1024;
  p.kr         = 1048576;
  p.kc         = 512;
  p.kg         = 64;
  p.gap        = 0.25;
  p.mu         = 0.25;
  p.nf         = 2;
  p.pretension = 256;
  return p;
}

// Friction threshold written from the model, independently of frictionThreshold().
double thresholdOf(const Params &p, double du_n)
{
  return p.mu * p.nf * std::max(0.0, p.pretension - p.clamp_coupling * p.kn * du_n);
}

// Slip resistance h(w) of the friction law in 1D with zero offset: kg w + (kc - kg) <|w| - j>+ sign(w).
double slipResistance1D(const Params &p, double w)
{
  const double over = std::max(0.0, std::abs(w) - p.gap);
  return p.kg * w + (p.kc - p.kg) * over * (w >= 0 ? 1.0 : -1.0);
}

// Paper sect. 2.2, 1D monotonic response from a fresh history (the brief's trilinear form).
double frictionMonotonic(const Params &p, double G, double du)
{
  const double ke = p.kt;
  if (ke * du <= G) return ke * du;
  const double w = du - G / ke;
  if (w <= p.gap) return G + p.kg * w;
  return G + p.kg * p.gap + p.kc * (w - p.gap);
}

// ---------------------------------------------------------------------------------------------
// Load stepping.

// Drives one joint as a load stepper would: evaluate with the committed history, then commit.
struct Driver {
  Params  p;
  History committed{};
  Tangent tangent = Tangent::Paper;

  Response step(const Vec6 &du)
  {
    Response r = evaluate(p, committed, du, tangent);
    committed  = r.trial;
    return r;
  }
};

struct Point {
  Vec6     du;
  Response r;
};

// Moves the jump linearly from `from` to `to` in `steps` equal increments, committing each step.
// Returns the points after each step (the start point is not evaluated).
std::vector<Point> ramp(Driver &d, const Vec6 &from, const Vec6 &to, int steps)
{
  std::vector<Point> out;
  for (int k = 1; k <= steps; ++k) {
    Vec6 du;
    for (int i = 0; i < 6; ++i) du[i] = from[i] + (to[i] - from[i]) * k / steps;
    out.push_back({du, d.step(du)});
  }
  return out;
}

// Trapezoidal integral of F . d(du) over consecutive points (in-plane and normal components).
double trapezoidWork(const std::vector<Point> &pts)
{
  double W = 0;
  for (size_t k = 1; k < pts.size(); ++k)
    for (int i = 0; i < 3; ++i) W += 0.5 * (pts[k - 1].r.force[i] + pts[k].r.force[i]) * (pts[k].du[i] - pts[k - 1].du[i]);
  return W;
}

void append(std::vector<Point> &a, const std::vector<Point> &b) { a.insert(a.end(), b.begin(), b.end()); }

// ---------------------------------------------------------------------------------------------
// Finite differences.

// Central finite difference of evaluate() over all 6 jump components, committed history fixed.
// *same_state reports whether every perturbed evaluation stayed in the state of the centre point.
// extra_k adds extra_k d(slip)/d(du) to the in-plane rows: the tangent of a law whose slip
// resistance is stiffer by extra_k, which is what the Jacobian's floor on kg is (kSlideFloor).
Mat6 fdTangent(const Params &p, const History &h, const Vec6 &du, double step, bool *same_state, std::array<double, 4> extra_k = {0, 0, 0, 0})
{
  const Response c = evaluate(p, h, du, Tangent::Consistent);
  Mat6           m{};
  *same_state = true;
  for (int j = 0; j < 6; ++j) {
    Vec6 up = du, dn = du;
    up[j] += step;
    dn[j] -= step;
    const Response ru = evaluate(p, h, up, Tangent::Consistent);
    const Response rd = evaluate(p, h, dn, Tangent::Consistent);
    if (ru.state != c.state || rd.state != c.state || ru.bearing != c.bearing || rd.bearing != c.bearing) *same_state = false;
    for (int i = 0; i < 6; ++i) m[6 * i + j] = (ru.force[i] - rd.force[i]) / (2 * step);
    for (int i = 0; i < 2; ++i)
      for (int k = 0; k < 2; ++k) m[6 * (1 + i) + j] += extra_k[2 * i + k] * (ru.trial.slip[k] - rd.trial.slip[k]) / (2 * step);
  }
  return m;
}

// Checks the Consistent tangent against the finite difference, entry by entry, relative to the
// in-plane stiffness scale kt (entries that vanish are compared against that scale).
void expectTangentMatchesFD(const Params &p, const History &h, const Vec6 &du, const char *what)
{
  const double step = 1e-6; // mm: jumps are O(0.01..1) mm; truncation O(step^2), rounding O(eps F / step)
  bool         same = false;
  // Pure Coulomb (kg = 0) while sliding: the tangent is that of a slip resistance stiffer by the
  // floor (kSlideFloor ke inside the clearance, across the radius in bearing); kg > 0: its own.
  const Response c     = evaluate(p, h, du, Tangent::Consistent);
  const bool     slips = p.law == Law::Friction && c.state != State::Stick;
  const Mat6     fd    = fdTangent(p, h, du, step, &same, slips ? slideFloorOf(p, c.trial, c.bearing) : std::array<double, 4>{0, 0, 0, 0});
  if (slips && p.kg == 0 && !c.bearing) {
    EXPECT_EQ(slideFloorOf(p, c.trial, c.bearing)[0], kSlideFloor * p.kt);
  }
  ASSERT_TRUE(same) << what << ": sample point too close to a state switch";
  const Mat6 an = evaluate(p, h, du, Tangent::Consistent).tangent;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      EXPECT_TRUE(Near(K(an, i, j), K(fd, i, j), kFD, p.kt)) << what << ": entry (" << i << "," << j << ")";
}

// The Paper tangent is diag(kn, k, k, kr, kr, kr) with the in-plane k switched by state.
void expectPaperTangent(const Params &p, const Mat6 &m, double k_in_plane, const char *what)
{
  const double diag[6] = {p.kn, k_in_plane, k_in_plane, p.kr, p.kr, p.kr};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) EXPECT_EQ(K(m, i, j), i == j ? diag[i] : 0.0) << what << ": entry (" << i << "," << j << ")";
}

// Random sample points for the friction law in a required state, with the expected trial slip.
struct FrictionSample {
  History h;
  Vec6    du;
  double  w[2]; // expected trial slip
};

FrictionSample frictionSample(std::mt19937 &rng, const Params &p, State target)
{
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const double                           ke = p.kt, j = p.gap, c0 = p.offset[0], c1 = p.offset[1];
  FrictionSample                         s{};
  // Normal jump: keeps Pc - phi F_n within [0.3, 1.5] Pc, away from the kink of max(0, .).
  double du_n = 0.02 * (2 * U(rng) - 1);
  if (p.clamp_coupling > 0) du_n = (1.0 - (0.3 + 1.2 * U(rng))) * p.pretension / (p.clamp_coupling * p.kn);
  const double G = thresholdOf(p, du_n);
  auto polar = [&](double rmin, double rmax, double *x, double *y) {
    const double r = rmin + (rmax - rmin) * U(rng), a = 2 * kPi * U(rng);
    *x = r * std::cos(a);
    *y = r * std::sin(a);
  };
  double e0, e1; // random unit vector
  polar(1, 1, &e0, &e1);
  if (target == State::Stick) {
    double w0, w1, f0, f1;
    polar(0, 1.5 * j, &w0, &w1); // committed slip, possibly in bearing
    polar(0, 0.9 * G, &f0, &f1); // trial force inside the Coulomb disk
    s.h.slip[0] = c0 + w0;
    s.h.slip[1] = c1 + w1;
    s.w[0]      = s.h.slip[0];
    s.w[1]      = s.h.slip[1];
    s.du        = jumpOf(du_n, s.h.slip[0] + f0 / ke, s.h.slip[1] + f1 / ke, 1e-3 * U(rng), -2e-3 * U(rng), 5e-4);
    return s;
  }
  // Slide / Contact: pick the new slip w (inside or outside the clearance circle), a sliding
  // direction n and a committed slip behind it: w_n = w - sl n, du_t = w + G n / ke.
  double w0, w1;
  if (target == State::Slide) polar(0, 0.9 * j, &w0, &w1);
  else polar(1.1 * j, 2.0 * j, &w0, &w1);
  s.w[0]          = c0 + w0;
  s.w[1]          = c1 + w1;
  const double sl = 0.05 + 0.3 * U(rng);
  s.h.slip[0]     = s.w[0] - sl * e0;
  s.h.slip[1]     = s.w[1] - sl * e1;
  s.du            = jumpOf(du_n, s.w[0] + G * e0 / ke, s.w[1] + G * e1 / ke, -1e-3 * U(rng), 2e-3 * U(rng), -5e-4);
  return s;
}

// Friction parameter variants used by the tangent checks: paper defaults, then offset + coupling.
std::vector<Params> frictionVariants()
{
  Params a;
  a.law        = Law::Friction;
  a.kn         = 5000;
  a.kt         = 2000;
  a.kr         = 1e6;
  a.kc         = 1500;
  a.kg         = 100;
  a.gap        = 0.2;
  a.mu         = 0.3;
  a.nf         = 2;
  a.pretension = 1000; // G = 600, G/ke = 0.3
  Params b     = a;
  b.offset[0]      = 0.05;
  b.offset[1]      = -0.08;
  b.clamp_coupling = 0.4;
  Params c         = b; // pure Coulomb sliding, bearing as stiff as sticking
  c.kg             = 0;
  c.kc             = c.kt;
  Params d         = b; // near-Coulomb: kg far below kSlideFloor ke is its own tangent
  d.kg             = 1e-6 * d.kt;
  return {a, b, c, d};
}

} // namespace

// =============================================================================================
// 1. Closed forms, monotonic loading.

// Spring law: f = diag(kn, kt, kt, kr, kr, kr) du, state Linear, both tangents equal the diagonal.
TEST(SpringLaw, LinearInAllComponents)
{
  const Params p  = springParams();
  const Vec6   du = jumpOf(0.01, -0.3, 0.7, 1e-3, -2e-3, 3e-3);
  for (Tangent t : {Tangent::Paper, Tangent::Consistent}) {
    const Response r       = evaluate(p, History{}, du, t);
    const double   diag[6] = {p.kn, p.kt, p.kt, p.kr, p.kr, p.kr};
    for (int i = 0; i < 6; ++i) EXPECT_TRUE(Near(r.force[i], diag[i] * du[i], kClosed)) << "component " << i;
    EXPECT_EQ(r.state, State::Linear);
    EXPECT_FALSE(r.bearing);
    expectPaperTangent(p, r.tangent, p.kt, "spring");
  }
}

// A spring with a full stiffness (Params::full): a bush with diagonal stiffness k in element axes
// a_i (rows of Q, a rotation of the joint frame) has K = Q^T diag(k) Q in the joint frame. The
// reference force is computed the other way round, without K: rotate the jump into the element
// axes, scale by k, rotate back. Requirement: a full 6 x 6 stiffness used as is (no averaging, no
// dropped couplings): force = K jump, tangent = K (both tangents), symmetric, state linear.
Params fullSpring(const double k[6], const double Q[9])
{
  Params p;
  p.law  = Law::Spring;
  p.full = 1;
  p.kn = p.kt = p.kr = 12345; // ignored when full
  for (int b = 0; b < 2; ++b)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double s = 0;
        for (int m = 0; m < 3; ++m) s += Q[3 * m + i] * k[3 * b + m] * Q[3 * m + j];
        p.K[6 * (3 * b + i) + 3 * b + j] = s;
      }
  return p;
}

TEST(SpringLaw, FullStiffnessOfARotatedBush)
{
  // Element axes: x along n, y and z turned 45 degrees about n in the joint plane (the wing box's
  // bolts), then a general rotation (30, 50, 70 degrees about three axes).
  const double c = std::sqrt(0.5);
  const double Q45[9] = {1, 0, 0, 0, c, c, 0, -c, c};
  double       Qg[9];
  {
    const double a = 0.5236, b = 0.8727, g = 1.2217;
    const double Rx[9] = {1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a)};
    const double Ry[9] = {std::cos(b), 0, std::sin(b), 0, 1, 0, -std::sin(b), 0, std::cos(b)};
    const double Rz[9] = {std::cos(g), -std::sin(g), 0, std::sin(g), std::cos(g), 0, 0, 0, 1};
    double       T[9]  = {};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int m = 0; m < 3; ++m) T[3 * i + j] += Rx[3 * i + m] * Ry[3 * m + j];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        Qg[3 * i + j] = 0;
        for (int m = 0; m < 3; ++m) Qg[3 * i + j] += T[3 * i + m] * Rz[3 * m + j];
      }
  }
  const double k[6] = {1e9, 1e9, 100, 1e7, 2e7, 3e7};
  const Vec6   du   = jumpOf(1e-4, -3e-3, 7e-3, 1e-3, -2e-3, 3e-3);
  for (const double *Q : {Q45, static_cast<const double *>(Qg)}) {
    const Params p = fullSpring(k, Q);
    EXPECT_EQ(validate(p), "");
    Vec6 want{};
    for (int b = 0; b < 2; ++b) {
      double e[3] = {};
      for (int m = 0; m < 3; ++m)
        for (int j = 0; j < 3; ++j) e[m] += Q[3 * m + j] * du[3 * b + j];
      for (int i = 0; i < 3; ++i)
        for (int m = 0; m < 3; ++m) want[3 * b + i] += Q[3 * m + i] * k[3 * b + m] * e[m];
    }
    for (Tangent t : {Tangent::Paper, Tangent::Consistent})
      for (bool frozen : {false, true}) {
        const Response r = evaluate(p, History{}, du, t, frozen);
        for (int i = 0; i < 6; ++i) EXPECT_TRUE(Near(r.force[i], want[i], kClosed, 1e9 * 1e-4)) << "component " << i;
        for (int i = 0; i < 36; ++i) EXPECT_EQ(r.tangent[i], p.K[i]);
        for (int i = 0; i < 6; ++i)
          for (int j = 0; j < 6; ++j) EXPECT_NEAR(r.tangent[6 * i + j], r.tangent[6 * j + i], 1e-15 * 1e9); // round-off of Q^T k Q
        EXPECT_EQ(r.state, State::Linear);
      }
    EXPECT_EQ(utilization(p, History{}, du), 0.0);
  }
  // The 45-degree bush along t1 alone: force (k2 + k3)/2 du along t1 and (k2 - k3)/2 du along t2
  // (hand-worked from a_y = (t1 + t2)/sqrt2, a_z = (t2 - t1)/sqrt2), not k2 nor k3.
  const Response r = evaluate(fullSpring(k, Q45), History{}, jumpOf(0, 1e-3, 0), Tangent::Consistent);
  EXPECT_TRUE(Near(r.force[1], 0.5 * (1e9 + 100) * 1e-3, kClosed));
  EXPECT_TRUE(Near(r.force[2], 0.5 * (1e9 - 100) * 1e-3, kClosed));
  EXPECT_TRUE(Near(r.force[0], 0, kClosed, 1e6));
}

// validate() refuses a full stiffness that is not symmetric, has a negative diagonal term or a
// non-finite term, or belongs to a law other than the spring, naming the term.
TEST(Validate, RejectsABadFullStiffness)
{
  const double k[6] = {10, 20, 40, 1, 2, 6}, I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  Params       p    = fullSpring(k, I);
  p.K[6 * 1 + 2]    = 3;
  EXPECT_NE(validate(p).find("K[1][2] = 3 and K[2][1] = 0 differ"), std::string::npos) << validate(p);
  p              = fullSpring(k, I);
  p.K[6 * 4 + 4] = -2;
  EXPECT_NE(validate(p).find("K[4][4] = -2 must be >= 0"), std::string::npos) << validate(p);
  p    = fullSpring(k, I);
  p.K[0] = std::nan("");
  EXPECT_NE(validate(p).find("not a finite number"), std::string::npos) << validate(p);
  p     = fullSpring(k, I);
  p.law = Law::Friction;
  EXPECT_NE(validate(p).find("the friction law has its own"), std::string::npos) << validate(p);
}

// Contact law (paper 2.1), c = 0: F_t = k du_t for r <= j, (k j + k'(r - j)) du_t / r beyond; along a 2D direction.
TEST(ContactLaw, ClosedFormBothBranches2D)
{
  const Params p = contactParams();
  const double e[2] = {std::cos(2.2), std::sin(2.2)};
  Driver       d{p};
  const double rmax = 3 * p.gap;
  int          open = 0, contact = 0;
  for (const Point &pt : ramp(d, jumpOf(-0.004, 0, 0, 1e-3), jumpOf(-0.004, rmax * e[0], rmax * e[1], 1e-3), 97)) {
    const double r = std::hypot(pt.du[1], pt.du[2]);
    const double s = r <= p.gap ? p.kt : (p.kt * p.gap + p.kc * (r - p.gap)) / r; // secant stiffness
    EXPECT_TRUE(Near(pt.r.force[1], s * pt.du[1], kClosed, p.kt * r)) << "r = " << r;
    EXPECT_TRUE(Near(pt.r.force[2], s * pt.du[2], kClosed, p.kt * r)) << "r = " << r;
    EXPECT_TRUE(Near(pt.r.force[0], p.kn * pt.du[0], kClosed));
    EXPECT_TRUE(Near(pt.r.force[3], p.kr * pt.du[3], kClosed));
    EXPECT_EQ(pt.r.state, r > p.gap ? State::Contact : State::Open) << "r = " << r;
    EXPECT_EQ(pt.r.bearing, r > p.gap) << "r = " << r;
    (r > p.gap ? contact : open)++;
  }
  EXPECT_GT(open, 10);
  EXPECT_GT(contact, 10);
}

// Contact law with an offset c: the clearance circle is centred on c, so contact starts at du = c +- j along t1.
TEST(ContactLaw, OffsetShiftsClearanceCircle)
{
  Params p    = contactParams();
  p.offset[0] = 0.05; // |c| < j = 0.15: contact at du1 = 0.2 (forward) and du1 = -0.1 (backward)
  for (double du1 : {0.19, 0.21, 0.35, -0.09, -0.11, -0.3, 0.0}) {
    const Response r    = evaluate(p, History{}, jumpOf(0, du1, 0), Tangent::Paper);
    const double   d    = du1 - p.offset[0];
    const double   over = std::max(0.0, std::abs(d) - p.gap);
    const double   want = p.kt * du1 + (p.kc - p.kt) * over * (d > 0 ? 1 : -1);
    EXPECT_TRUE(Near(r.force[1], want, kClosed, p.kt * 0.1)) << "du1 = " << du1;
    EXPECT_EQ(r.force[2], 0.0);
    EXPECT_EQ(r.state, over > 0 ? State::Contact : State::Open) << "du1 = " << du1;
  }
}

// Friction law 1D monotonic: trilinear stick / slide / contact with exact breakpoints G/ke and G/ke + j and their states.
TEST(FrictionLaw, MonotonicTrilinearAndBreakpoints)
{
  const Params p  = dyadicFriction();
  const double ke = p.kt, G = thresholdOf(p, 0), j = p.gap;
  ASSERT_EQ(G, 128.0);
  const double du_n = 1.0 / 256, th[3] = {1.0 / 512, -1.0 / 1024, 1.0 / 2048}; // carried along, phi = 0
  Driver       d{p};
  for (const Point &pt : ramp(d, jumpOf(du_n, 0, 0, th[0], th[1], th[2]), jumpOf(du_n, 1, 0, th[0], th[1], th[2]), 64)) {
    const double du = pt.du[1];
    const State  want = du <= G / ke ? State::Stick : (du <= G / ke + j ? State::Slide : State::Contact);
    EXPECT_TRUE(Near(pt.r.force[1], frictionMonotonic(p, G, du), kClosed, G)) << "du = " << du;
    EXPECT_EQ(pt.r.force[2], 0.0);
    EXPECT_TRUE(Near(pt.r.force[0], p.kn * du_n, kClosed));
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(Near(pt.r.force[3 + i], p.kr * th[i], kClosed));
    EXPECT_EQ(pt.r.state, want) << "du = " << du;
    EXPECT_EQ(pt.r.trial.state, static_cast<int>(want));
    EXPECT_EQ(pt.r.bearing, du > G / ke + j) << "du = " << du;
    EXPECT_TRUE(Near(pt.r.trial.slip[0], std::max(0.0, du - G / ke), kClosed, 1e-3)) << "du = " << du;
    EXPECT_EQ(pt.r.trial.slip[1], 0.0);
  }
  // The breakpoints themselves (exact in binary): du = G/ke is the last Stick point, F = G;
  // du = G/ke + j the last Slide point, F = G + kg j; one step beyond each, the next state.
  auto at = [&](double du) { // response of the step (of 1/64) that arrives at du
    Driver dd{p};
    return ramp(dd, jumpOf(0, 0, 0), jumpOf(0, du, 0), static_cast<int>(du * 64)).back().r;
  };
  const Response b1 = at(G / ke), b1p = at(G / ke + 1.0 / 64), b2 = at(G / ke + j), b2p = at(G / ke + j + 1.0 / 64);
  EXPECT_EQ(b1.state, State::Stick);
  EXPECT_EQ(b1.force[1], G);
  EXPECT_EQ(b1p.state, State::Slide);
  EXPECT_EQ(b2.state, State::Slide);
  EXPECT_EQ(b2.force[1], G + p.kg * j);
  EXPECT_FALSE(b2.bearing);
  EXPECT_EQ(b2p.state, State::Contact);
  EXPECT_TRUE(b2p.bearing);
  EXPECT_EQ(b2p.force[1], G + p.kg * j + p.kc / 64);
}

// Friction law 2D radial monotonic loading (isotropic Coulomb): F = F_1D(s) e and slip = <s - G/ke>+ e along direction e.
TEST(FrictionLaw, MonotonicRadial2D)
{
  const Params p  = dyadicFriction();
  const double ke = p.kt, G = thresholdOf(p, 0);
  for (double angle : {0.4, 2.0, -2.7}) {
    const double e[2] = {std::cos(angle), std::sin(angle)};
    Driver       d{p};
    for (const Point &pt : ramp(d, jumpOf(0, 0, 0), jumpOf(0, e[0], e[1]), 100)) {
      const double s = std::hypot(pt.du[1], pt.du[2]);
      const double F = frictionMonotonic(p, G, s), w = std::max(0.0, s - G / ke);
      for (int i = 0; i < 2; ++i) {
        EXPECT_TRUE(Near(pt.r.force[1 + i], F * e[i], kClosed, G)) << "angle " << angle << " s " << s;
        EXPECT_TRUE(Near(pt.r.trial.slip[i], w * e[i], kClosed, 1.0)) << "angle " << angle << " s " << s;
      }
      EXPECT_EQ(pt.r.state, s < G / ke ? State::Stick : (w < p.gap ? State::Slide : State::Contact)) << "s " << s;
    }
  }
}

// Friction law with offset c: bearing starts when the slip leaves the circle |w - c| = j, at du = G/ke + c + j forward and -(G/ke) + c - j backward.
TEST(FrictionLaw, OffsetMovesBearingOnset)
{
  Params p    = dyadicFriction();
  p.offset[0] = 1.0 / 16;
  const double ke = p.kt, G = thresholdOf(p, 0), j = p.gap, c = p.offset[0];
  for (double sign : {+1.0, -1.0}) {
    Driver d{p};
    for (const Point &pt : ramp(d, jumpOf(0, 0, 0), jumpOf(0, sign, 0), 64)) {
      const double du   = pt.du[1];
      const double w    = std::abs(du) <= G / ke ? 0.0 : du - sign * G / ke;
      const double over = std::max(0.0, std::abs(w - c) - j);
      const double Ff   = std::abs(du) <= G / ke ? ke * du : sign * G;
      const double want = Ff + p.kg * w + (p.kc - p.kg) * over * sign;
      EXPECT_TRUE(Near(pt.r.force[1], want, kClosed, G)) << "du = " << du;
      const bool bearing = sign > 0 ? du > G / ke + c + j : du < -G / ke + c - j;
      EXPECT_EQ(pt.r.bearing, bearing) << "du = " << du;
      EXPECT_EQ(pt.r.state, std::abs(du) <= G / ke ? State::Stick : (bearing ? State::Contact : State::Slide)) << "du = " << du;
    }
  }
}

// =============================================================================================
// 2-4. Benchmarks of docs/benchmarks.md.

// Single bolt, kg = 0, force-controlled reading: stick u = F/ke, slide F = G, bearing u = j + G/ke + (F - G)/kc.
TEST(FrictionBenchmark, SingleBoltForceDisplacement)
{
  Params p = dyadicFriction();
  p.kg     = 0;
  const double ke = p.kt, G = thresholdOf(p, 0), j = p.gap, kc = p.kc;
  Driver       d{p};
  int          n[3] = {0, 0, 0};
  for (const Point &pt : ramp(d, jumpOf(0, 0, 0), jumpOf(0, 1, 0), 64)) {
    const double u = pt.du[1], F = pt.r.force[1];
    switch (pt.r.state) {
    case State::Stick: EXPECT_TRUE(Near(u, F / ke, kClosed)) << "u = " << u; ++n[0]; break;
    case State::Slide: EXPECT_TRUE(Near(F, G, kClosed)) << "u = " << u; ++n[1]; break;
    case State::Contact: EXPECT_TRUE(Near(u, j + G / ke + (F - G) / kc, kClosed)) << "u = " << u; ++n[2]; break;
    default: ADD_FAILURE() << "unexpected state " << stateName(pt.r.state);
    }
  }
  EXPECT_EQ(n[0], 8);  // u in (0, 1/8]
  EXPECT_EQ(n[1], 16); // u in (1/8, 3/8]
  EXPECT_EQ(n[2], 40); // u in (3/8, 1]
}

// Unloading from bearing: elastic (slope ke) until the force has dropped by exactly 2G, then reverse slip (slip decreasing).
// While the reverse slip keeps |w| > j the bolt still bears on the hole (h(w) > 0), so the state is Contact by the law's
// definition (slipping and |w - c| > j); it becomes Slide, F = -G + kg w, once the slip re-enters the clearance.
TEST(FrictionBenchmark, UnloadingFromBearing)
{
  for (double kg : {0.0, 64.0}) {
    Params p = dyadicFriction();
    p.kg     = kg;
    const double ke = p.kt, G = thresholdOf(p, 0), j = p.gap, umax = 1;
    Driver       d{p};
    const Point  top = ramp(d, jumpOf(0, 0, 0), jumpOf(0, umax, 0), 64).back();
    const double wmax = umax - G / ke, Fmax = G + slipResistance1D(p, wmax);
    ASSERT_EQ(top.r.state, State::Contact);
    ASSERT_TRUE(Near(top.r.force[1], Fmax, kClosed));

    const double ustart = umax - 2 * G / ke; // reverse slip starts here, F = Fmax - 2G
    double       prev_slip = d.committed.slip[0];
    bool         seen_contact_back = false, seen_slide_back = false, hit_start = false;
    for (const Point &pt : ramp(d, jumpOf(0, umax, 0), jumpOf(0, -umax, 0), 128)) {
      const double u = pt.du[1], F = pt.r.force[1];
      if (u >= ustart) { // elastic unloading with the slip frozen
        EXPECT_EQ(pt.r.state, State::Stick) << "kg " << kg << " u " << u;
        EXPECT_TRUE(Near(F, Fmax - ke * (umax - u), kClosed, G)) << "kg " << kg << " u " << u;
        EXPECT_EQ(pt.r.trial.slip[0], wmax);
        if (u == ustart) {
          hit_start = true;
          EXPECT_TRUE(Near(F, Fmax - 2 * G, kClosed)) << "kg " << kg;
        }
      } else { // reverse slip: w = u + G/ke, F = -G + h(w)
        const double w = u + G / ke;
        EXPECT_TRUE(Near(pt.r.trial.slip[0], w, kClosed, 1.0)) << "kg " << kg << " u " << u;
        EXPECT_LT(pt.r.trial.slip[0], prev_slip) << "slip must decrease, u " << u;
        EXPECT_TRUE(Near(F, -G + slipResistance1D(p, w), kClosed, G)) << "kg " << kg << " u " << u;
        const State want = std::abs(w) > j ? State::Contact : State::Slide;
        EXPECT_EQ(pt.r.state, want) << "kg " << kg << " u " << u;
        if (want == State::Contact && w > 0) seen_contact_back = true;
        if (want == State::Slide) seen_slide_back = true;
      }
      prev_slip = pt.r.trial.slip[0];
    }
    EXPECT_TRUE(hit_start);         // the onset lies on the step grid (u = 3/4)
    EXPECT_TRUE(seen_contact_back); // slipping back while the bolt still bears (|w| > j)
    EXPECT_TRUE(seen_slide_back);   // then sliding back across the clearance, force -G + kg w
  }
}

// Jenkins loop (kg = 0, gap not reached, +-A, breakpoints on step boundaries): dissipation per cycle = 4 G (A - G/ke), to 1e-12.
TEST(FrictionBenchmark, JenkinsLoopEnergyAlignedSteps)
{
  Params p = dyadicFriction();
  p.kg     = 0;
  p.kc     = 0;
  p.gap    = 1e6;
  const double ke = p.kt, G = thresholdOf(p, 0), A = 0.5; // kinks at +-A and +-(A - 2G/ke) = +-1/4: on the 1/64 grid
  Driver       d{p};
  ramp(d, jumpOf(0, 0, 0), jumpOf(0, A, 0), 32);
  for (int cycle = 0; cycle < 3; ++cycle) {
    std::vector<Point> loop{{jumpOf(0, A, 0), evaluate(p, d.committed, jumpOf(0, A, 0), Tangent::Paper)}};
    append(loop, ramp(d, jumpOf(0, A, 0), jumpOf(0, -A, 0), 64));
    append(loop, ramp(d, jumpOf(0, -A, 0), jumpOf(0, A, 0), 64));
    EXPECT_EQ(loop.front().r.force[1], loop.back().r.force[1]); // closed, stabilized loop
    EXPECT_TRUE(Near(trapezoidWork(loop), 4 * G * (A - G / ke), kClosed)) << "cycle " << cycle;
  }
}

// Jenkins loop with steps not aligned to the breakpoints, along a 2D direction: 4 G (A - G/ke) to 1e-6 relative.
// Trapezoid error bound: a slope change ke inside a step of length h costs at most ke h^2 / 8, two per
// cycle: ke h^2 / 4 = 1000 * (0.37/4000)^2 / 4 = 2e-6, against W = 120 (relative 2e-8).
TEST(FrictionBenchmark, JenkinsLoopEnergyUnalignedSteps2D)
{
  Params p;
  p.law        = Law::Friction;
  p.kn         = 3000;
  p.kt         = 1000;
  p.kr         = 1e6;
  p.gap        = 1e6;
  p.mu         = 0.3;
  p.pretension = 400; // G = 120, G/ke = 0.12
  const double ke = p.kt, G = thresholdOf(p, 0), A = 0.37, e[2] = {std::cos(1.1), std::sin(1.1)};
  const int    N = 8000; // steps per half cycle
  Driver       d{p};
  const Vec6   plus = jumpOf(0, A * e[0], A * e[1]), minus = jumpOf(0, -A * e[0], -A * e[1]);
  ramp(d, jumpOf(0, 0, 0), plus, N / 2);
  ramp(d, plus, minus, N);
  ramp(d, minus, plus, N);
  std::vector<Point> loop{{plus, evaluate(p, d.committed, plus, Tangent::Paper)}};
  append(loop, ramp(d, plus, minus, N));
  append(loop, ramp(d, minus, plus, N));
  EXPECT_TRUE(Near(trapezoidWork(loop), 4 * G * (A - G / ke), kFD));
}

// Isotropic Coulomb in 2D: du stepped around a circle of radius R (kg = 0, gap not reached, N steps of angle d) drags the
// slip, in the steady state, around a circle of radius rho_d with |F| = G; dissipation per turn W_d (closed forms below).
// Steady state of the return mapping: w_k = rho e^{i(th_k - b)}; |du_k+1 - w_k+1| = g = G/ke and w_k+1 - w_k parallel to
// du_k+1 - w_k+1 give R e^{ib} - rho = g e^{i(pi - d)/2}, so rho_d = sqrt(R^2 - g^2 cos^2(d/2)) - g sin(d/2)
// (-> sqrt(R^2 - g^2) as d -> 0); the trapezoid over one turn gives W_d = N G rho_d sin(d) cos(d/2) (-> 2 pi G rho).
TEST(FrictionBenchmark, CircularPathDissipation2D)
{
  Params p;
  p.law        = Law::Friction;
  p.kn         = 3000;
  p.kt         = 1000;
  p.kr         = 1e6;
  p.gap        = 1e6;
  p.mu         = 0.3;
  p.pretension = 400; // G = 120, g = G/ke = 0.12
  const double G = thresholdOf(p, 0), g = G / p.kt, R = 0.5;
  for (int N : {360, 5000}) {
    const double d     = 2 * kPi / N;
    const double rho_d = std::sqrt(R * R - g * g * std::cos(d / 2) * std::cos(d / 2)) - g * std::sin(d / 2);
    const double W_d   = N * G * rho_d * std::sin(d) * std::cos(d / 2);
    Driver       dr{p};
    ramp(dr, jumpOf(0, 0, 0), jumpOf(0, R, 0), 100);
    auto circle = [&](int k) { return jumpOf(0, R * std::cos(k * d), R * std::sin(k * d)); };
    for (int k = 1; k <= 4 * N; ++k) dr.step(circle(k)); // four turns to reach the steady state
    std::vector<Point> turn{{circle(0), evaluate(p, dr.committed, circle(0), Tangent::Paper)}};
    for (int k = 1; k <= N; ++k) turn.push_back({circle(k), dr.step(circle(k))});
    EXPECT_TRUE(Near(trapezoidWork(turn), W_d, kClosed)) << "N = " << N;
    // Sanity of the closed form: first-order convergence to the continuous 2 pi G sqrt(R^2 - g^2).
    EXPECT_TRUE(Near(W_d, 2 * kPi * G * std::sqrt(R * R - g * g), g * d / rho_d)) << "continuous limit, N = " << N;
    for (size_t k = 1; k < turn.size(); ++k) { // turn[0] re-evaluates the committed point: no increment, Stick
      const Point &pt = turn[k];
      EXPECT_EQ(pt.r.state, State::Slide);
      EXPECT_TRUE(Near(std::hypot(pt.r.force[1], pt.r.force[2]), G, kClosed));
      EXPECT_TRUE(Near(std::hypot(pt.r.trial.slip[0], pt.r.trial.slip[1]), rho_d, kClosed)) << "N = " << N;
    }
  }
}

// =============================================================================================
// 5. Energy.

// kg < kc <= ke, closed cycle into bearing on both sides: W = 2 G (dw - dh/ke) > 0 (dw, dh ranges of slip and h(w)).
// Derivation: F = Ff + h(w), du = Ff/ke + w, so the loop integral of F d(du) = loop integral of Ff (1 - h'(w)/ke) dw
// (the exact differentials Ff dFf and h dw close), and Ff = +-G with the sign of dw while slipping.
TEST(FrictionEnergy, BearingCycleDissipatesPositiveEnergy)
{
  for (double kc : {512.0, 1024.0}) { // kc < ke and kc = ke
    Params p = dyadicFriction();
    p.kc     = kc;
    const double ke = p.kt, G = thresholdOf(p, 0), A = 1; // bearing on both sides: A - G/ke = 7/8 > j = 1/4
    Driver       d{p};
    ramp(d, jumpOf(0, 0, 0), jumpOf(0, A, 0), 64);
    ramp(d, jumpOf(0, A, 0), jumpOf(0, -A, 0), 128);
    ramp(d, jumpOf(0, -A, 0), jumpOf(0, A, 0), 128);
    std::vector<Point> loop{{jumpOf(0, A, 0), evaluate(p, d.committed, jumpOf(0, A, 0), Tangent::Paper)}};
    append(loop, ramp(d, jumpOf(0, A, 0), jumpOf(0, -A, 0), 128));
    append(loop, ramp(d, jumpOf(0, -A, 0), jumpOf(0, A, 0), 128));
    EXPECT_EQ(loop.front().r.force[1], loop.back().r.force[1]);
    const double wmax = A - G / ke, wmin = -wmax;
    const double dw = wmax - wmin, dh = slipResistance1D(p, wmax) - slipResistance1D(p, wmin);
    const double W = 2 * G * (dw - dh / ke);
    EXPECT_GT(W, 0.0);
    EXPECT_TRUE(Near(trapezoidWork(loop), W, kClosed)) << "kc = " << kc;
    bool bearing_pos = false, bearing_neg = false;
    for (const Point &pt : loop) {
      bearing_pos |= pt.r.bearing && pt.r.trial.slip[0] > 0;
      bearing_neg |= pt.r.bearing && pt.r.trial.slip[0] < 0;
    }
    EXPECT_TRUE(bearing_pos && bearing_neg);
  }
}

// =============================================================================================
// 6. Tangents.

// Spring and contact laws: Consistent tangent = central FD of the force over all 6 jump components (2D, offset).
TEST(ConsistentTangent, SpringAndContactMatchFiniteDifferences)
{
  std::mt19937                           rng(12345);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  {
    const Params p = springParams();
    for (int k = 0; k < 20; ++k)
      expectTangentMatchesFD(p, History{}, jumpOf(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5, 1e-3 * U(rng), 0, -1e-3), "spring");
  }
  for (double c0 : {0.0, 0.03}) {
    Params p    = contactParams();
    p.offset[0] = c0;
    p.offset[1] = -c0;
    for (State target : {State::Open, State::Contact})
      for (int k = 0; k < 200; ++k) {
        const double r  = target == State::Open ? 0.9 * p.gap * U(rng) : p.gap * (1.1 + 2 * U(rng));
        const double a  = 2 * kPi * U(rng);
        const Vec6   du = jumpOf(0.01 * (U(rng) - 0.5), p.offset[0] + r * std::cos(a), p.offset[1] + r * std::sin(a), 1e-3, 0, 0);
        ASSERT_EQ(evaluate(p, History{}, du, Tangent::Consistent).state, target);
        expectTangentMatchesFD(p, History{}, du, stateName(target));
      }
  }
}

// Friction law: Consistent tangent = central FD over all 6 jump components, random points in Stick/Slide/Contact,
// 2D directions, offset and clamp coupling (where dF_t/ddu_n is nonzero); states and trial slip as designed.
TEST(ConsistentTangent, FrictionMatchesFiniteDifferences)
{
  std::mt19937 rng(2024);
  for (const Params &p : frictionVariants()) {
    for (State target : {State::Stick, State::Slide, State::Contact}) {
      double coupling_column = 0; // largest |dF_t/ddu_n| seen, to make sure the phi column is exercised
      for (int k = 0; k < 200; ++k) {
        const FrictionSample s = frictionSample(rng, p, target);
        const Response       r = evaluate(p, s.h, s.du, Tangent::Consistent);
        ASSERT_EQ(r.state, target) << "phi " << p.clamp_coupling;
        EXPECT_TRUE(Near(r.trial.slip[0], s.w[0], kClosed, 1.0));
        EXPECT_TRUE(Near(r.trial.slip[1], s.w[1], kClosed, 1.0));
        expectTangentMatchesFD(p, s.h, s.du, stateName(target));
        coupling_column = std::max({coupling_column, std::abs(K(r.tangent, 1, 0)), std::abs(K(r.tangent, 2, 0))});
      }
      if (p.clamp_coupling > 0 && target != State::Stick) EXPECT_GT(coupling_column, 0.1 * p.mu * p.nf * p.clamp_coupling * p.kn);
      else EXPECT_EQ(coupling_column, 0.0) << "no dF_t/ddu_n when stuck or phi = 0";
    }
  }
}

// Paper tangent: diag(kn, k, k, kr, kr, kr) with k = ke/kg/kc (friction), k/k' (contact); same force and trial as Consistent.
TEST(PaperTangent, SwitchedDefinitionInEveryState)
{
  std::mt19937 rng(77);
  for (const Params &p : frictionVariants())
    for (State target : {State::Stick, State::Slide, State::Contact})
      for (int k = 0; k < 50; ++k) {
        const FrictionSample s  = frictionSample(rng, p, target);
        const Response       rp = evaluate(p, s.h, s.du, Tangent::Paper);
        const Response       rc = evaluate(p, s.h, s.du, Tangent::Consistent);
        ASSERT_EQ(rp.state, target);
        expectPaperTangent(p, rp.tangent, target == State::Stick ? p.kt : (target == State::Slide ? (p.kg > 0 ? p.kg : kSlideFloor * p.kt) : p.kc), stateName(target));
        EXPECT_EQ(rp.force, rc.force);
        EXPECT_EQ(rp.trial.slip[0], rc.trial.slip[0]);
        EXPECT_EQ(rp.trial.slip[1], rc.trial.slip[1]);
      }
  const Params p = contactParams();
  for (double r : {0.5 * p.gap, 2 * p.gap}) {
    const Response rp = evaluate(p, History{}, jumpOf(0.01, r * 0.6, -r * 0.8), Tangent::Paper);
    expectPaperTangent(p, rp.tangent, r > p.gap ? p.kc : p.kt, stateName(rp.state));
  }
}

// 1D monotonic (friction and contact): Paper and Consistent tangents coincide in every entry that the 1D response
// involves, and along any 2D loading direction e (K e); only the transverse stiffness e_perp^T K e_perp differs.
TEST(ConsistentTangent, CoincidesWithPaperIn1DMonotonic)
{
  for (const Params &p : {dyadicFriction(), contactParams()}) {
    Driver dp{p}, dc{p, History{}, Tangent::Consistent};
    for (int k = 1; k <= 64; ++k) {
      const Vec6     du = jumpOf(1.0 / 512, k / 64.0, 0, 1e-4, 0, 0);
      const Response rp = dp.step(du), rc = dc.step(du);
      ASSERT_EQ(rp.state, rc.state);
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
          if (!(i == 2 && j == 2)) {
            EXPECT_TRUE(Near(K(rc.tangent, i, j), K(rp.tangent, i, j), kClosed, p.kt)) << "du " << du[1] << " (" << i << "," << j << ")";
          }
    }
  }
  const Params p = dyadicFriction();
  const double e[2] = {std::cos(0.9), std::sin(0.9)};
  Driver       dp{p}, dc{p, History{}, Tangent::Consistent};
  for (int k = 1; k <= 100; ++k) {
    const Vec6     du = jumpOf(0, e[0] * k / 100.0, e[1] * k / 100.0);
    const Response rp = dp.step(du), rc = dc.step(du);
    for (int i = 0; i < 2; ++i) {
      const double Kp_e = K(rp.tangent, 1 + i, 1) * e[0] + K(rp.tangent, 1 + i, 2) * e[1];
      const double Kc_e = K(rc.tangent, 1 + i, 1) * e[0] + K(rc.tangent, 1 + i, 2) * e[1];
      EXPECT_TRUE(Near(Kc_e, Kp_e, kClosed, p.kt)) << "s " << k / 100.0;
    }
  }
}

// =============================================================================================
// 7. Path dependence and history.

// After sliding, returning the jump to zero leaves a residual slip and a nonzero force (closed forms for both returns).
TEST(PathDependence, ResidualSlipAfterReturnToZero)
{
  const Params p  = dyadicFriction();
  const double ke = p.kt, G = thresholdOf(p, 0);
  { // small excursion: slip w = 1/16, stuck on the way back: F(0) = -ke w + kg w
    Driver d{p};
    ramp(d, jumpOf(0, 0, 0), jumpOf(0, 3.0 / 16, 0), 12);
    const Response r = ramp(d, jumpOf(0, 3.0 / 16, 0), jumpOf(0, 0, 0), 12).back().r;
    const double   w = 3.0 / 16 - G / ke;
    EXPECT_EQ(r.state, State::Stick);
    EXPECT_EQ(r.trial.slip[0], w);
    EXPECT_TRUE(Near(r.force[1], -ke * w + p.kg * w, kClosed));
    EXPECT_NE(r.force[1], 0.0);
  }
  { // larger excursion: slides back, ends with slip G/ke and F(0) = -G + kg G/ke
    Driver d{p};
    ramp(d, jumpOf(0, 0, 0), jumpOf(0, 5.0 / 16, 0), 20);
    const Response r = ramp(d, jumpOf(0, 5.0 / 16, 0), jumpOf(0, 0, 0), 20).back().r;
    EXPECT_EQ(r.state, State::Slide);
    EXPECT_TRUE(Near(r.trial.slip[0], G / ke, kClosed));
    EXPECT_TRUE(Near(r.force[1], -G + p.kg * G / ke, kClosed));
  }
}

// evaluate() never modifies the committed history: same committed input and jump give the same response, even after
// evaluations at other jumps (as between Newton iterations).
TEST(PathDependence, EvaluateIsPureInTheCommittedHistory)
{
  std::mt19937 rng(99);
  const Params p = frictionVariants()[1];
  for (State target : {State::Stick, State::Slide, State::Contact})
    for (int k = 0; k < 20; ++k) {
      const FrictionSample s     = frictionSample(rng, p, target);
      const FrictionSample other = frictionSample(rng, p, State::Contact);
      const History        copy  = s.h;
      const Response       r1    = evaluate(p, s.h, s.du, Tangent::Consistent);
      evaluate(p, s.h, other.du, Tangent::Consistent);
      evaluate(p, other.h, other.du, Tangent::Paper);
      const Response r2 = evaluate(p, s.h, s.du, Tangent::Consistent);
      EXPECT_EQ(std::memcmp(&copy, &s.h, sizeof(History)), 0);
      EXPECT_EQ(r1.force, r2.force);
      EXPECT_EQ(r1.tangent, r2.tangent);
      EXPECT_EQ(r1.state, r2.state);
      EXPECT_EQ(r1.bearing, r2.bearing);
      EXPECT_EQ(r1.trial.slip[0], r2.trial.slip[0]);
      EXPECT_EQ(r1.trial.slip[1], r2.trial.slip[1]);
      EXPECT_EQ(r1.trial.state, r2.trial.state);
    }
}

// =============================================================================================
// 7b. Frozen joints (-joint_stuck_linear): the linear state of the committed history, no state test.

// Where the law sticks (or the clearance is open), the frozen evaluation is the law, bit for bit;
// utilization() < 1 there (the law's own test, written from the model: |ke (du - w)| < G).
TEST(FrozenJoint, IdenticalToTheLawWhereItSticks)
{
  std::mt19937 rng(7);
  for (const Params &p : frictionVariants())
    for (int k = 0; k < 50; ++k) {
      const FrictionSample s = frictionSample(rng, p, State::Stick);
      for (Tangent t : {Tangent::Consistent, Tangent::Paper}) {
        const Response law = evaluate(p, s.h, s.du, t), frozen = evaluate(p, s.h, s.du, t, true);
        ASSERT_EQ(law.state, State::Stick);
        EXPECT_EQ(frozen.state, State::Stick);
        EXPECT_EQ(law.force, frozen.force);
        EXPECT_EQ(law.tangent, frozen.tangent);
        EXPECT_EQ(law.trial.slip[0], frozen.trial.slip[0]);
        EXPECT_EQ(law.trial.slip[1], frozen.trial.slip[1]);
      }
      const double G = thresholdOf(p, s.du[0]);
      const double a = p.kt * std::hypot(s.du[1] - s.h.slip[0], s.du[2] - s.h.slip[1]);
      EXPECT_TRUE(Near(utilization(p, s.h, s.du), a / G, kClosed));
      EXPECT_LT(utilization(p, s.h, s.du), 1.0);
    }
  const Params c = contactParams();
  const Vec6   du = jumpOf(0.01, 0.06, -0.08, 0, 0, 0); // |du_t| = 0.1 < gap 0.15
  const Response law = evaluate(c, History{}, du, Tangent::Consistent), frozen = evaluate(c, History{}, du, Tangent::Consistent, true);
  EXPECT_EQ(law.state, State::Open);
  EXPECT_EQ(law.force, frozen.force);
  EXPECT_EQ(law.tangent, frozen.tangent);
  EXPECT_TRUE(Near(utilization(c, History{}, du), 0.1 / 0.15, kClosed));
}

// Beyond the threshold the frozen joint is the affine stick spring of its committed slip (closed
// form: F = ke (du - w) + h(w) in 1D), while the law slides; utilization() > 1 says so.
TEST(FrozenJoint, AffineStickSpringBeyondTheThreshold)
{
  const Params  p = dyadicFriction(); // G/ke = 1/8
  const History fresh{};
  for (double du : {0.25, 0.5, -1.0}) {
    const Vec6     j      = jumpOf(0, du, 0);
    const Response frozen = evaluate(p, fresh, j, Tangent::Consistent, true);
    const Response law    = evaluate(p, fresh, j, Tangent::Consistent);
    EXPECT_EQ(frozen.state, State::Stick);
    EXPECT_NE(law.state, State::Stick);
    EXPECT_TRUE(Near(frozen.force[1], p.kt * du, kClosed));
    EXPECT_TRUE(Near(K(frozen.tangent, 1, 1), p.kt, kClosed));
    EXPECT_TRUE(Near(utilization(p, fresh, j), std::abs(du) * p.kt / 128.0, kClosed));
    EXPECT_GT(utilization(p, fresh, j), 1.0);
  }
  // A committed slip in bearing (w = 3/8 > j): the frozen spring keeps h(w) = kg j + kc (w - j).
  History h;
  h.slip[0]         = 0.375;
  const Vec6     j  = jumpOf(0, 0.375 + 0.0625, 0);
  const Response fr = evaluate(p, h, j, Tangent::Consistent, true);
  EXPECT_TRUE(Near(fr.force[1], p.kt * 0.0625 + slipResistance1D(p, 0.375), kClosed));
  EXPECT_TRUE(Near(utilization(p, h, j), 0.5, kClosed));
  // Contact law beyond the clearance: frozen stays open (k du), the law bears.
  const Params   c  = contactParams();
  const Vec6     jc = jumpOf(0, 0.3, 0);
  EXPECT_TRUE(Near(evaluate(c, History{}, jc, Tangent::Consistent, true).force[1], c.kt * 0.3, kClosed));
  EXPECT_EQ(evaluate(c, History{}, jc, Tangent::Consistent).state, State::Contact);
  EXPECT_TRUE(Near(utilization(c, History{}, jc), 2.0, kClosed));
  // Springs have no state: utilization 0. No room (G = 0, gap = 0): infinite unless at rest.
  EXPECT_EQ(utilization(springParams(), History{}, jc), 0.0);
  Params g0 = p;
  g0.pretension = 0;
  EXPECT_TRUE(std::isinf(utilization(g0, History{}, jumpOf(0, 1e-9, 0))));
  EXPECT_EQ(utilization(g0, History{}, jumpOf(0, 0, 0)), 0.0);
  // A contact joint without clearance bears at every jump, at rest too: never an open spring.
  Params c0 = contactParams();
  c0.gap    = 0;
  EXPECT_TRUE(std::isinf(utilization(c0, History{}, jumpOf(0, 0, 0))));
}

// Pure Coulomb (kg = 0): the force stays on the plateau G (the law), while the tangent along the
// slip is the floor kSlideFloor ke (Jacobian only), in both tangents; kg above the floor is kept.
TEST(FrictionLaw, PureCoulombTangentFloor)
{
  Params p = dyadicFriction(); // G = 128, ke = 1024, j = 1/4
  p.kg     = 0;
  for (double du : {0.25, -0.3}) { // slip 1/8 and -0.175: sliding, inside the clearance
    const Vec6     j = jumpOf(0, du, 0);
    const Response c = evaluate(p, History{}, j, Tangent::Consistent), q = evaluate(p, History{}, j, Tangent::Paper);
    EXPECT_EQ(c.state, State::Slide);
    EXPECT_TRUE(Near(c.force[1], du > 0 ? 128.0 : -128.0, kClosed));
    EXPECT_TRUE(Near(K(c.tangent, 1, 1), kSlideFloor * p.kt, kClosed));
    EXPECT_TRUE(Near(K(q.tangent, 1, 1), kSlideFloor * p.kt, kClosed));
  }
  // In bearing (1D, slip 3/8 > j) the radial stiffness is kc: no floor along x, Newton is exact there.
  const Response b = evaluate(p, History{}, jumpOf(0, 0.5, 0), Tangent::Consistent);
  EXPECT_EQ(b.state, State::Contact);
  EXPECT_TRUE(Near(K(b.tangent, 1, 1), p.kc, kClosed));
  // Across the slip (t2): G ke/a + (kc (r - j)/r + floor)(1 - G/a), a = ke du = 512, r = 3/8.
  EXPECT_TRUE(Near(K(b.tangent, 2, 2), 128.0 * p.kt / 512.0 + (p.kc * (0.375 - 0.25) / 0.375 + kSlideFloor * p.kt) * (1 - 128.0 / 512.0), kClosed));
  const Params   d = dyadicFriction(); // kg = 64 > kSlideFloor ke: its own tangent
  const Response r = evaluate(d, History{}, jumpOf(0, 0.25, 0), Tangent::Consistent);
  EXPECT_TRUE(Near(K(r.tangent, 1, 1), d.kg, kClosed));
}

// 0 < kg < kSlideFloor ke: the tangent along the slip is kg itself in both tangents, and equals the
// finite difference of the force (a stiffer floor made each Newton step kg / floor of the way to
// the slide's solution (T - G)/kg + G/ke, and a slide with no bearing in reach did not converge).
TEST(FrictionLaw, NearCoulombKeepsItsOwnTangent)
{
  Params p = dyadicFriction(); // G = 128, ke = 1024, j = 1/4
  p.kg     = 1e-6 * p.kt;
  for (double du : {0.25, -0.3}) {
    const Vec6     j = jumpOf(0, du, 0);
    const Response c = evaluate(p, History{}, j, Tangent::Consistent), q = evaluate(p, History{}, j, Tangent::Paper);
    EXPECT_EQ(c.state, State::Slide);
    EXPECT_EQ(K(c.tangent, 1, 1), p.kg);
    EXPECT_EQ(K(q.tangent, 1, 1), p.kg);
    bool       same = false;
    const Mat6 fd   = fdTangent(p, History{}, j, 1e-6, &same);
    ASSERT_TRUE(same);
    EXPECT_TRUE(Near(K(fd, 1, 1), p.kg, 1e-3)); // the FD of the force itself (rounding ~3e-8), no floor added
  }
}

// Contact law without clearance (gap = 0): F_t = kc du_t for every jump, at du_t = 0 too, state
// contact; the tangent there is kc I (it was kt, zero for kt = 0: a singular Jacobian at rest), and
// matches the central finite difference through du_t = 0 (offset 0: the circle is a point).
TEST(ContactLaw, NoClearanceIsLinearThroughZero)
{
  Params p = contactParams();
  p.gap    = 0;
  p.kt     = 0;
  for (double d : {0.0, 1e-9, -0.2}) {
    const Vec6 j = jumpOf(0, d, 0.5 * d);
    for (Tangent t : {Tangent::Consistent, Tangent::Paper}) {
      const Response r = evaluate(p, History{}, j, t);
      EXPECT_EQ(r.state, State::Contact);
      EXPECT_TRUE(r.bearing);
      EXPECT_TRUE(Near(r.force[1], p.kc * d, kClosed, p.kc));
      EXPECT_TRUE(Near(r.force[2], p.kc * 0.5 * d, kClosed, p.kc));
      EXPECT_TRUE(Near(K(r.tangent, 1, 1), p.kc, kClosed));
      EXPECT_TRUE(Near(K(r.tangent, 2, 2), p.kc, kClosed));
      EXPECT_TRUE(Near(K(r.tangent, 1, 2), 0.0, kClosed, p.kc));
    }
  }
  bool       same = false;
  const Mat6 fd   = fdTangent(p, History{}, jumpOf(0, 0, 0), 1e-6, &same);
  ASSERT_TRUE(same);
  EXPECT_TRUE(Near(K(fd, 1, 1), p.kc, kFD, p.kc));
  EXPECT_TRUE(Near(K(fd, 2, 2), p.kc, kFD, p.kc));
}

// =============================================================================================
// 8. Clamp-force coupling.

// frictionThreshold: G = mu nf max(0, Pc - phi F_n), including compression (F_n < 0) and G = 0 beyond F_n = Pc/phi.
TEST(ClampCoupling, ThresholdFormula)
{
  Params p         = dyadicFriction();
  p.clamp_coupling = 0.5; // Pc/phi = 512
  for (double Fn : {-300.0, 0.0, 100.0, 511.0, 512.0, 513.0, 4000.0}) {
    const double want = p.mu * p.nf * std::max(0.0, p.pretension - 0.5 * Fn);
    EXPECT_TRUE(Near(frictionThreshold(p, Fn), want, kClosed)) << "Fn = " << Fn;
  }
  EXPECT_EQ(frictionThreshold(p, 513.0), 0.0);
  EXPECT_GT(frictionThreshold(p, -300.0), p.mu * p.nf * p.pretension);
}

// With phi > 0 the sliding plateau and the stick limit follow G(du_n) = mu nf max(0, Pc - phi kn du_n).
TEST(ClampCoupling, SlidingPlateauFollowsNormalJump)
{
  Params p         = dyadicFriction();
  p.kg             = 0;
  p.gap            = 1e6;
  p.clamp_coupling = 0.5;
  for (double du_n : {-1.0 / 32, 0.0, 1.0 / 64, 3.0 / 64}) { // kn du_n = -128, 0, 64, 192 < Pc/phi = 512
    const double G = p.mu * p.nf * (p.pretension - p.clamp_coupling * p.kn * du_n);
    Driver       d{p};
    for (const Point &pt : ramp(d, jumpOf(du_n, 0, 0), jumpOf(du_n, 1, 0), 64)) {
      const double u = pt.du[1];
      EXPECT_TRUE(Near(pt.r.force[1], std::min(p.kt * u, G), kClosed, G)) << "du_n " << du_n << " u " << u;
      EXPECT_EQ(pt.r.state, p.kt * u <= G ? State::Stick : State::Slide) << "du_n " << du_n << " u " << u;
      EXPECT_TRUE(Near(pt.r.force[0], p.kn * du_n, kClosed));
    }
  }
}

// With phi > 0 and F_n > Pc/phi the joint has no friction: any tangential jump slides, F_t = h(du_t).
TEST(ClampCoupling, ZeroThresholdBeyondPcOverPhi)
{
  Params p         = dyadicFriction();
  p.clamp_coupling = 0.5;
  const double du_n = 0.25; // kn du_n = 1024 > Pc/phi = 512
  for (double u : {0.1, 0.5, -0.7}) {
    const Response r = evaluate(p, History{}, jumpOf(du_n, u, 0), Tangent::Paper);
    EXPECT_EQ(r.state, std::abs(u) > p.gap ? State::Contact : State::Slide) << "u " << u;
    EXPECT_TRUE(Near(r.trial.slip[0], u, kClosed));
    EXPECT_TRUE(Near(r.force[1], slipResistance1D(p, u), kClosed)) << "u " << u;
  }
  // Exactly no tangential jump: nothing to slide, the joint stays stuck with zero force.
  const Response r0 = evaluate(p, History{}, jumpOf(du_n, 0, 0), Tangent::Paper);
  EXPECT_EQ(r0.force[1], 0.0);
  EXPECT_EQ(r0.force[2], 0.0);
}

// Defaults (phi = 0, offset = 0) reproduce the paper: G = mu nf Pc whatever du_n, contact circle centred on zero.
TEST(ClampCoupling, DefaultsReproducePaper)
{
  const Params defaults;
  EXPECT_EQ(defaults.clamp_coupling, 0.0);
  EXPECT_EQ(defaults.offset[0], 0.0);
  EXPECT_EQ(defaults.offset[1], 0.0);
  EXPECT_EQ(defaults.nf, 1.0);
  Params p = dyadicFriction(); // phi and offset left at their defaults
  p.kg     = 0;
  p.gap    = 1e6;
  const double G = p.mu * p.nf * p.pretension;
  for (double du_n : {-0.2, 0.0, 0.3}) {
    EXPECT_EQ(frictionThreshold(p, p.kn * du_n), G);
    const Response r = evaluate(p, History{}, jumpOf(du_n, 0.7, 0), Tangent::Paper);
    EXPECT_TRUE(Near(r.force[1], G, kClosed)) << "du_n " << du_n;
  }
  Params c = contactParams(); // contact onset at r = j in every direction
  for (double a : {0.0, 1.0, 2.5, 4.0}) {
    const double inside = 0.999 * c.gap, outside = 1.001 * c.gap;
    EXPECT_EQ(evaluate(c, History{}, jumpOf(0, inside * std::cos(a), inside * std::sin(a)), Tangent::Paper).state, State::Open);
    EXPECT_EQ(evaluate(c, History{}, jumpOf(0, outside * std::cos(a), outside * std::sin(a)), Tangent::Paper).state, State::Contact);
  }
}

// =============================================================================================
// 9. validate(), names.

// validate() is empty for valid parameter sets of each law (contact may have k' > k; friction kg <= kc <= kt).
TEST(Validate, AcceptsValidParameters)
{
  EXPECT_EQ(validate(springParams()), "");
  EXPECT_EQ(validate(contactParams()), "");
  EXPECT_EQ(validate(dyadicFriction()), "");
  for (const Params &p : frictionVariants()) EXPECT_EQ(validate(p), "");
  Params onCircle    = dyadicFriction();
  onCircle.offset[0] = onCircle.gap; // bolt touching the hole: still inside the clearance
  EXPECT_EQ(validate(onCircle), "");
}

// validate() names the offending parameter: negative stiffness/gap/..., kc > kt and kg > kt (friction), offset outside, nf < 1.
TEST(Validate, RejectsInvalidParametersNamingThem)
{
  auto expectNames = [](const Params &p, const std::string &name) {
    const std::string msg = validate(p);
    EXPECT_FALSE(msg.empty()) << name;
    EXPECT_NE(msg.find(name), std::string::npos) << "message '" << msg << "' does not name " << name;
  };
  struct Field {
    const char *name;
    double Params::*member;
  };
  const Field fields[] = {{"kn", &Params::kn},   {"kt", &Params::kt}, {"kr", &Params::kr},
                          {"kc", &Params::kc},   {"kg", &Params::kg}, {"gap", &Params::gap},
                          {"mu", &Params::mu},   {"pretension", &Params::pretension},
                          {"clamp_coupling", &Params::clamp_coupling}};
  for (const Params &base : {springParams(), contactParams(), dyadicFriction()})
    for (const Field &f : fields) {
      Params p   = base;
      p.*f.member = -1;
      expectNames(p, f.name);
      p.*f.member = std::nan("");
      expectNames(p, f.name);
    }
  Params p = dyadicFriction();
  p.kc     = p.kt * 2; // bearing stiffer than sticking
  expectNames(p, "kc");
  p    = dyadicFriction();
  p.kg = p.kt * 2; // sliding stiffer than sticking (kc raised too, so only kg > kt is wrong besides kc > kt)
  p.kc = p.kt * 2;
  expectNames(p, "kg");
  p           = dyadicFriction();
  p.offset[0] = 0.6 * p.gap;
  p.offset[1] = 0.9 * p.gap; // |c| = 1.08 j
  expectNames(p, "offset");
  Params c    = contactParams();
  c.offset[1] = -2 * c.gap;
  expectNames(c, "offset");
  for (double nf : {0.0, 0.5, -2.0}) {
    p    = dyadicFriction();
    p.nf = nf;
    expectNames(p, "nf");
  }
}

// parseLaw(lawName(l)) == l for every law, unknown names are rejected; stateName gives the documented distinct names.
TEST(Names, ParseLawAndStateNameRoundTrip)
{
  for (Law l : {Law::Spring, Law::Contact, Law::Friction}) {
    Law back = l == Law::Spring ? Law::Friction : Law::Spring;
    ASSERT_TRUE(parseLaw(lawName(l), &back)) << lawName(l);
    EXPECT_EQ(back, l);
  }
  EXPECT_STREQ(lawName(Law::Spring), "spring");
  EXPECT_STREQ(lawName(Law::Contact), "contact");
  EXPECT_STREQ(lawName(Law::Friction), "friction");
  Law untouched = Law::Contact;
  EXPECT_FALSE(parseLaw("coulomb", &untouched));
  EXPECT_FALSE(parseLaw("", &untouched));
  EXPECT_FALSE(parseLaw("Friction", &untouched));
  EXPECT_EQ(untouched, Law::Contact);

  const std::pair<State, const char *> names[] = {
      {State::Linear, "linear"}, {State::Open, "open"}, {State::Contact, "contact"}, {State::Stick, "stick"}, {State::Slide, "slide"}};
  std::set<std::string> seen;
  for (const auto &[s, name] : names) {
    EXPECT_STREQ(stateName(s), name);
    seen.insert(stateName(s));
  }
  EXPECT_EQ(seen.size(), 5u);
}
