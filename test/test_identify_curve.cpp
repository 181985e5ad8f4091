// The frictional macroelement's parameters (ke, G, kg, j, kc) fitted to a load-slip
// curve (lib/identify/curve.*). Requirements checked here:
//  - the forward model is boltnet's law (boltnet::evaluate) and its parameter sensitivities are exact;
//  - known parameters are recovered from curves boltnet generates: exactly (1e-8 relative) without
//    noise, monotonic and cyclic; within 3 standard errors with Gaussian noise (sigma = 1% of G), and
//    the standard errors agree with the scatter of the estimates over repeated noisy curves;
//  - a curve that cannot identify a parameter is rejected naming it (never slides; never bears);
//  - the CSV reader (item 5): empty curve, rows out of time order, malformed rows, named in the message.
#include "identify/curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace boltnet;
using namespace boltnet::identify;

namespace {

// fig3c's joint (share/scenes/fig3c.yaml): ke 1.5e5 N/mm, G 3000 N, kg 5000 N/mm, j 0.05 mm, kc 4e4 N/mm.
const Theta truth = {1.5e5, 3000, 5000, 0.05, 4e4};

// Slip path through the given turning points, `per` rows per segment, from rest (0 excluded).
std::vector<double> path(std::initializer_list<double> points, int per)
{
  std::vector<double> u;
  double              prev = 0;
  for (double p : points) {
    for (int i = 1; i <= per; ++i) u.push_back(prev + (p - prev) * i / per);
    prev = p;
  }
  return u;
}

Curve synthetic(const Theta &t, const std::vector<double> &slip)
{
  Curve c;
  c.name = "synthetic";
  c.slip = slip;
  c.load = simulate(t, slip);
  return c;
}

} // namespace

// The forward model is the law itself: along a monotonic path it gives docs/joint-laws.md's closed
// form (stick F = ke u; slide F = G + kg (u - G/ke); contact F = G + kg j + kc (u - G/ke - j)).
TEST(IdentifyCurve, ForwardModelIsTheLaw)
{
  const std::vector<double> u = path({0.2}, 400);
  const std::vector<double> F = simulate(truth, u);
  const double ke = truth[KE], g = truth[G], kg = truth[KG], j = truth[J], kc = truth[KC];
  for (size_t i = 0; i < u.size(); ++i) {
    const double x   = u[i];
    const double ref = x < g / ke ? ke * x : (x - g / ke < j ? g + kg * (x - g / ke) : g + kg * j + kc * (x - g / ke - j));
    EXPECT_NEAR(F[i], ref, 1e-9 * g) << "u = " << x;
  }
}

// The sensitivities d F_i / d theta_k against central differences, on a cyclic path (rows near a
// change of state are skipped: there the force is not differentiable in the parameters).
TEST(IdentifyCurve, JacobianMatchesFiniteDifferences)
{
  const std::vector<double> u = path({0.2, -0.2, 0.15}, 97);
  std::vector<double>       jac;
  std::vector<State>        st;
  simulate(truth, u, &jac, &st);
  for (int k = 0; k < NPARAM; ++k) {
    const double h  = 1e-6 * truth[k];
    Theta        tp = truth, tm = truth;
    tp[k] += h;
    tm[k] -= h;
    std::vector<State>        sp, sm;
    const std::vector<double> Fp = simulate(tp, u, nullptr, &sp), Fm = simulate(tm, u, nullptr, &sm);
    int                       checked = 0;
    for (size_t i = 0; i < u.size(); ++i) {
      if (sp[i] != st[i] || sm[i] != st[i]) continue;
      const double fd = (Fp[i] - Fm[i]) / (2 * h);
      EXPECT_NEAR(jac[i * NPARAM + k], fd, 1e-5 * (std::fabs(fd) + 1e-3 * truth[G] / truth[k])) << paramName(k) << " row " << i;
      ++checked;
    }
    EXPECT_GT(checked, 250);
  }
}

// Noise-free curves: the fit recovers the parameters to 1e-8 relative, monotonic and cyclic.
TEST(IdentifyCurve, ExactRecoveryMonotonic)
{
  FitResult r;
  ASSERT_EQ(fitFriction(synthetic(truth, path({0.2}, 200)), &r), "");
  for (int k = 0; k < NPARAM; ++k) EXPECT_NEAR(r.theta[k], truth[k], 1e-8 * truth[k]) << paramName(k);
  EXPECT_LT(r.rms, 1e-8 * truth[G]);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.warning, "");
}

TEST(IdentifyCurve, ExactRecoveryCyclic)
{
  // fig3c's load path in slip: up to bearing, down to reverse bearing, back, then a smaller cycle.
  FitResult r;
  ASSERT_EQ(fitFriction(synthetic(truth, path({0.15, -0.15, 0.12, -0.05, 0.1}, 120)), &r), "");
  for (int k = 0; k < NPARAM; ++k) EXPECT_NEAR(r.theta[k], truth[k], 1e-8 * truth[k]) << paramName(k);
  EXPECT_GT(r.n_stick, 0);
  EXPECT_GT(r.n_slide, 0);
  EXPECT_GT(r.n_bearing, 0);
  // A pure Coulomb slider (kg = 0) and a stiffer bearing are recovered too.
  const Theta other = {2e5, 1500, 0, 0.02, 1.2e5};
  ASSERT_EQ(fitFriction(synthetic(other, path({0.08, -0.08, 0.08}, 150)), &r), "");
  for (int k = 0; k < NPARAM; ++k) EXPECT_NEAR(r.theta[k], other[k], 1e-8 * std::max(other[k], 1.0)) << paramName(k);
}

// Noisy curves: Gaussian noise sigma = 1% of G on the load (std::mt19937, fixed seeds). Each
// parameter lies within 3 standard errors of the truth; the noise estimate is close to 1% of G; and
// over 40 noisy curves the scatter of each estimate matches the mean standard error within a
// factor 1.5 (the standard errors are sensible, not merely large).
TEST(IdentifyCurve, NoisyRecoveryWithinStandardErrors)
{
  const std::vector<double> u     = path({0.15, -0.15, 0.15}, 150);
  const Curve               clean = synthetic(truth, u);
  const double              sigma = 0.01 * truth[G];
  const int                 runs  = 40;
  Theta                     mean{}, m2{}, se{};
  for (int seed = 0; seed < runs; ++seed) {
    std::mt19937                     rng(1234 + seed);
    std::normal_distribution<double> noise(0.0, sigma);
    Curve                            c = clean;
    for (double &f : c.load) f += noise(rng);
    FitResult r;
    ASSERT_EQ(fitFriction(c, &r), "") << "seed " << seed;
    if (seed == 0) {
      for (int k = 0; k < NPARAM; ++k) {
        EXPECT_NEAR(r.theta[k], truth[k], 3 * r.stderr_[k]) << paramName(k);
        EXPECT_GT(r.stderr_[k], 0) << paramName(k);
        EXPECT_LT(r.stderr_[k], 0.05 * truth[k]) << paramName(k); // 1% noise: a few % at most
      }
      EXPECT_NEAR(r.sigma, sigma, 0.15 * sigma);
    }
    for (int k = 0; k < NPARAM; ++k) {
      mean[k] += r.theta[k] / runs;
      m2[k] += r.theta[k] * r.theta[k] / runs;
      se[k] += r.stderr_[k] / runs;
    }
  }
  for (int k = 0; k < NPARAM; ++k) {
    const double scatter = std::sqrt(std::max(m2[k] - mean[k] * mean[k], 0.0) * runs / (runs - 1));
    EXPECT_GT(scatter, se[k] / 1.5) << paramName(k);
    EXPECT_LT(scatter, se[k] * 1.5) << paramName(k);
    EXPECT_NEAR(mean[k], truth[k], 3 * se[k]) << paramName(k); // no bias beyond the noise
  }
}

// Identifiability: a curve that never slides cannot give G, kg, j, kc; one that slides but never
// bears cannot give j and kc. Noise does not fool the model selection.
TEST(IdentifyCurve, NotIdentifiableNamed)
{
  FitResult r;
  Curve     stick = synthetic(truth, path({0.015, -0.015, 0.015}, 60)); // G/ke = 0.02: never slides
  std::string m = fitFriction(stick, &r);
  EXPECT_NE(m.find("G, kg, j and kc are not identifiable: the curve never slides"), std::string::npos) << m;
  Curve slide = synthetic(truth, path({0.05, -0.05, 0.05}, 60)); // slip 0.03 < j: never bears
  m           = fitFriction(slide, &r);
  EXPECT_NE(m.find("j and kc are not identifiable: the curve never reaches bearing"), std::string::npos) << m;
  std::mt19937                     rng(7);
  std::normal_distribution<double> noise(0.0, 0.01 * truth[G]);
  for (double &f : stick.load) f += noise(rng);
  for (double &f : slide.load) f += noise(rng);
  EXPECT_NE(fitFriction(stick, &r).find("never slides"), std::string::npos);
  EXPECT_NE(fitFriction(slide, &r).find("never reaches bearing"), std::string::npos);
  Curve few = synthetic(truth, path({0.2}, 6));
  EXPECT_NE(fitFriction(few, &r).find("6 points: at least 10 are needed"), std::string::npos);
}

// The CSV reader: header load,slip (any order, optional increasing time), bad rows named.
TEST(IdentifyCurve, ParseCsv)
{
  Curve c;
  EXPECT_EQ(parseCurve("# a comment\ntime, slip, load\n0, 0, 0\n1, 0.01, 1500\r\n2, 0.02, 3000\n", "t.csv", &c), "");
  ASSERT_EQ(c.load.size(), 3u);
  EXPECT_EQ(c.load[2], 3000);
  EXPECT_EQ(c.slip[1], 0.01);
  EXPECT_NE(parseCurve("", "e.csv", &c).find("curve 'e.csv' is empty"), std::string::npos);
  EXPECT_NE(parseCurve("load,slip\n", "h.csv", &c).find("curve 'h.csv' has a header but no data rows"), std::string::npos);
  EXPECT_NE(parseCurve("force,slip\n1,2\n", "x.csv", &c).find("must name the columns 'load' and 'slip'"), std::string::npos);
  EXPECT_NE(parseCurve("load,slip\n1,abc\n", "x.csv", &c).find("line 2, column 'slip': 'abc' is not a finite number"), std::string::npos);
  EXPECT_NE(parseCurve("load,slip\n1\n", "x.csv", &c).find("line 2: 1 values for 2 columns"), std::string::npos);
  const std::string m = parseCurve("time,load,slip\n0,0,0\n2,1,0.1\n1,2,0.2\n", "n.csv", &c);
  EXPECT_NE(m.find("curve 'n.csv' line 4: time 1 does not come after the previous row's time 2"), std::string::npos) << m;
  EXPECT_NE(readCurve("/no/such/curve.csv", &c).find("Cannot read the curve file '/no/such/curve.csv'"), std::string::npos);
}

// The shipped test curves (test/data/identify/) read and fit: cyclic.csv was generated by this
// model with fig3c's parameters and noise sigma = 30 N (1% of G); stick-only.csv never slides.
TEST(IdentifyCurve, ShippedCurves)
{
  Curve c;
  ASSERT_EQ(readCurve(BOLTNET_IDENTIFY_DATA "/cyclic.csv", &c), "");
  FitResult r;
  ASSERT_EQ(fitFriction(c, &r), "");
  for (int k = 0; k < NPARAM; ++k) EXPECT_NEAR(r.theta[k], truth[k], 3 * r.stderr_[k]) << paramName(k);
  ASSERT_EQ(readCurve(BOLTNET_IDENTIFY_DATA "/stick-only.csv", &c), "");
  EXPECT_NE(fitFriction(c, &r).find("never slides"), std::string::npos);
  EXPECT_NE(readCurve(BOLTNET_IDENTIFY_DATA "/empty.csv", &c).find("has a header but no data rows"), std::string::npos);
  EXPECT_NE(readCurve(BOLTNET_IDENTIFY_DATA "/out-of-order.csv", &c).find("does not come after the previous row's time"), std::string::npos);
}
