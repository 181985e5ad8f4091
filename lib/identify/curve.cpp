// Test-curve identification of the frictional macroelement: see curve.hpp and docs/identify.md.
#include "identify/curve.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace boltnet {
namespace identify {
namespace {

std::string trim(const std::string &s)
{
  size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

std::vector<std::string> split(const std::string &line)
{
  std::vector<std::string> out;
  std::string              cell;
  std::istringstream       in(line);
  while (std::getline(in, cell, ',')) out.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

// Solve the small dense system A x = b (n <= 5) by Gaussian elimination with partial pivoting;
// false when singular.
bool solve(int n, std::vector<double> A, std::vector<double> b, std::vector<double> *x)
{
  for (int c = 0; c < n; ++c) {
    int p = c;
    for (int r = c + 1; r < n; ++r)
      if (std::fabs(A[r * n + c]) > std::fabs(A[p * n + c])) p = r;
    if (!(std::fabs(A[p * n + c]) > 0)) return false;
    if (p != c) {
      for (int k = 0; k < n; ++k) std::swap(A[c * n + k], A[p * n + k]);
      std::swap(b[c], b[p]);
    }
    for (int r = c + 1; r < n; ++r) {
      const double f = A[r * n + c] / A[c * n + c];
      for (int k = c; k < n; ++k) A[r * n + k] -= f * A[c * n + k];
      b[r] -= f * b[c];
    }
  }
  x->assign(n, 0);
  for (int r = n - 1; r >= 0; --r) {
    double v = b[r];
    for (int k = r + 1; k < n; ++k) v -= A[r * n + k] * (*x)[k];
    (*x)[r] = v / A[r * n + r];
  }
  return true;
}

// Linear least squares F ~ sum_k c_k phi_k(u) over the backbone; returns the RSS (inf if singular).
template <class Basis>
double linearFit(const std::vector<double> &u, const std::vector<double> &F, int m, Basis phi, std::vector<double> *c)
{
  std::vector<double> A(m * m, 0), b(m, 0), row(m);
  for (size_t i = 0; i < u.size(); ++i) {
    phi(u[i], row.data());
    for (int a = 0; a < m; ++a) {
      b[a] += row[a] * F[i];
      for (int k = 0; k < m; ++k) A[a * m + k] += row[a] * row[k];
    }
  }
  if (!solve(m, A, b, c)) return std::numeric_limits<double>::infinity();
  double rss = 0;
  for (size_t i = 0; i < u.size(); ++i) {
    phi(u[i], row.data());
    double f = 0;
    for (int a = 0; a < m; ++a) f += (*c)[a] * row[a];
    rss += (f - F[i]) * (f - F[i]);
  }
  return rss;
}

// Continuous piecewise-linear fit through the origin of the backbone (u > 0, F): 1, 2 or 3
// segments (stick; stick + slide; stick + slide + bearing), breakpoints on the data, the number of
// segments chosen by the Bayesian information criterion n ln(RSS/n) + p ln n (p = 1, 3, 5).
struct Segmented {
  int    m = 1;
  double ke = 0, kg = 0, kc = 0, b1 = 0, b2 = 0;
};

Segmented segmentedFit(const std::vector<double> &u, const std::vector<double> &F)
{
  const int n = static_cast<int>(u.size());
  double    sumF2 = 0;
  for (double f : F) sumF2 += f * f;
  const double floor = 1e-28 * sumF2 + std::numeric_limits<double>::min();
  auto bic = [&](double rss, int p) { return n * std::log(std::max(rss, floor) / n) + p * std::log(static_cast<double>(n)); };

  Segmented best;
  std::vector<double> c;
  double rss1 = linearFit(u, F, 1, [](double x, double *r) { r[0] = x; }, &c);
  best.ke       = c.empty() ? 0 : c[0];
  double bbest  = bic(rss1, 1);

  // Candidate breakpoints: the data's slips (at most 80 of them), each segment keeping >= 2 points.
  std::vector<double> sorted(u);
  std::sort(sorted.begin(), sorted.end());
  std::vector<double> cand;
  const int           lo = 2, hi = n - 2; // indices into sorted: >= 2 points on each side
  if (hi > lo) {
    const int step = std::max(1, (hi - lo) / 80);
    for (int i = lo; i < hi; i += step) cand.push_back(sorted[i]);
  }
  auto countIn = [&](double a, double b) { // points with a < u <= b
    return static_cast<int>(std::upper_bound(sorted.begin(), sorted.end(), b) - std::upper_bound(sorted.begin(), sorted.end(), a));
  };
  for (double b1 : cand) {
    double r2 = linearFit(u, F, 2, [b1](double x, double *r) { r[0] = std::min(x, b1); r[1] = std::max(x - b1, 0.0); }, &c);
    if (bic(r2, 3) < bbest && c[0] > 0) {
      bbest = bic(r2, 3);
      best  = {2, c[0], c[1], 0, b1, 0};
    }
  }
  for (double b1 : cand)
    for (double b2 : cand) {
      if (!(b2 > b1) || countIn(b1, b2) < 2) continue;
      double r3 = linearFit(u, F, 3, [b1, b2](double x, double *r) { r[0] = std::min(x, b1); r[1] = std::min(std::max(x - b1, 0.0), b2 - b1); r[2] = std::max(x - b2, 0.0); }, &c);
      if (bic(r3, 5) < bbest && c[0] > 0) {
        bbest = bic(r3, 5);
        best  = {3, c[0], c[1], c[2], b1, b2};
      }
    }
  return best;
}

// The backbone on one side (sign s): the origin and every row that goes beyond all earlier slips
// on that side, mirrored to positive values.
void backbone(const Curve &c, double s, std::vector<double> *u, std::vector<double> *F)
{
  u->assign(1, 0.0);
  F->assign(1, 0.0);
  double top = 0;
  for (size_t i = 0; i < c.slip.size(); ++i)
    if (s * c.slip[i] > top) {
      top = s * c.slip[i];
      u->push_back(top);
      F->push_back(s * c.load[i]);
    }
}

std::string fmt(double v)
{
  std::ostringstream o;
  o.precision(6);
  o << v;
  return o.str();
}

} // namespace

const char *paramName(int k)
{
  static const char *names[NPARAM] = {"ke", "G", "kg", "j", "kc"};
  return (k >= 0 && k < NPARAM) ? names[k] : "?";
}

std::string parseCurve(const std::string &text, const std::string &name, Curve *c)
{
  c->load.clear();
  c->slip.clear();
  c->name = name;
  std::istringstream in(text);
  std::string        line;
  int                lineno = 0, iload = -1, islip = -1, itime = -1;
  size_t             ncol = 0;
  bool               header = false;
  double             tprev = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    std::vector<std::string> cells = split(t);
    if (!header) {
      header = true;
      ncol   = cells.size();
      for (size_t k = 0; k < cells.size(); ++k) {
        std::string h = cells[k];
        std::transform(h.begin(), h.end(), h.begin(), [](unsigned char ch) { return std::tolower(ch); });
        if (h == "load") iload = static_cast<int>(k);
        if (h == "slip") islip = static_cast<int>(k);
        if (h == "time") itime = static_cast<int>(k);
      }
      if (iload < 0 || islip < 0)
        return "curve '" + name + "' line " + std::to_string(lineno) + ": the header must name the columns 'load' and 'slip' (found '" + t + "')";
      continue;
    }
    if (cells.size() != ncol)
      return "curve '" + name + "' line " + std::to_string(lineno) + ": " + std::to_string(cells.size()) + " values for " + std::to_string(ncol) + " columns";
    double v[3] = {0, 0, 0};
    const int idx[3] = {iload, islip, itime};
    const char *col[3] = {"load", "slip", "time"};
    for (int k = 0; k < 3; ++k) {
      if (idx[k] < 0) continue;
      const std::string &s = cells[idx[k]];
      char              *end = nullptr;
      errno                  = 0;
      v[k]                   = std::strtod(s.c_str(), &end);
      if (s.empty() || !end || *end != '\0' || errno != 0 || !std::isfinite(v[k]))
        return "curve '" + name + "' line " + std::to_string(lineno) + ", column '" + col[k] + "': '" + s + "' is not a finite number";
    }
    if (itime >= 0) {
      if (!c->load.empty() && !(v[2] > tprev))
        return "curve '" + name + "' line " + std::to_string(lineno) + ": time " + fmt(v[2]) + " does not come after the previous row's time " + fmt(tprev) +
               ": the rows must be in time order (the time column must increase strictly)";
      tprev = v[2];
    }
    c->load.push_back(v[0]);
    c->slip.push_back(v[1]);
  }
  if (!header) return "curve '" + name + "' is empty: it needs a header 'load,slip' and one row per point";
  if (c->load.empty()) return "curve '" + name + "' has a header but no data rows";
  return "";
}

std::string readCurve(const std::string &path, Curve *c)
{
  std::ifstream f(path, std::ios::binary);
  if (!f) return "Cannot read the curve file '" + path + "'";
  std::ostringstream s;
  s << f.rdbuf();
  return parseCurve(s.str(), path, c);
}

Params frictionParams(const Theta &t)
{
  Params p;
  p.law        = Law::Friction;
  p.kt         = t[KE];
  p.kg         = t[KG];
  p.kc         = t[KC];
  p.gap        = t[J];
  p.mu         = 1;
  p.nf         = 1;
  p.pretension = t[G];
  return p;
}

std::vector<double> simulate(const Theta &t, const std::vector<double> &slip, std::vector<double> *jac, std::vector<State> *states, std::vector<char> *bearing)
{
  const Params        p = frictionParams(t);
  const size_t        n = slip.size();
  std::vector<double> F(n);
  if (jac) jac->assign(n * NPARAM, 0.0);
  if (states) states->assign(n, State::Stick);
  if (bearing) bearing->assign(n, 0);
  History h;
  double  dw[NPARAM] = {0, 0, 0, 0, 0}; // d slip / d theta
  const double ke = t[KE], Gv = t[G], kg = t[KG], j = t[J], kc = t[KC];
  for (size_t i = 0; i < n; ++i) {
    const double   u  = slip[i];
    const Vec6     du = {0, u, 0, 0, 0, 0};
    const Response r  = evaluate(p, h, du, Tangent::Consistent);
    F[i]              = r.force[1];
    const bool slid   = r.state != State::Stick;
    if (states) (*states)[i] = r.state;
    if (bearing) (*bearing)[i] = r.bearing;
    if (jac) {
      // Sensitivities of the incremental law along the same states. Slide: w = u - G s/ke,
      // F = G s + h(w); stick: w frozen, F = ke (u - w) + h(w); h(w) = kg w + (kc - kg) <|w| - j>+ sign(w).
      const double s = (u - h.slip[0]) >= 0 ? 1.0 : -1.0; // direction of the slide
      if (slid) {
        for (double &x : dw) x = 0;
        dw[KE] = Gv * s / (ke * ke);
        dw[G]  = -s / ke;
      }
      const double w  = r.trial.slip[0];
      const double z  = std::fabs(w) - j;
      const bool   on = z > 0;
      const double sw = w >= 0 ? 1.0 : -1.0;
      const double hp = kg + (on ? kc - kg : 0.0);
      double       dF[NPARAM];
      for (int k = 0; k < NPARAM; ++k) dF[k] = hp * dw[k];
      dF[KG] += w - (on ? z * sw : 0.0);
      dF[KC] += on ? z * sw : 0.0;
      dF[J] += on ? -(kc - kg) * sw : 0.0;
      if (slid) dF[G] += s;
      else {
        dF[KE] += u - w;
        for (int k = 0; k < NPARAM; ++k) dF[k] -= ke * dw[k];
      }
      for (int k = 0; k < NPARAM; ++k) (*jac)[i * NPARAM + k] = dF[k];
    }
    h = r.trial;
  }
  return F;
}

namespace {

// Normal matrix A = J^T J and gradient g = J^T r.
void normal(const std::vector<double> &jac, const std::vector<double> &res, std::vector<double> *A, std::vector<double> *g)
{
  A->assign(NPARAM * NPARAM, 0.0);
  g->assign(NPARAM, 0.0);
  const size_t n = res.size();
  for (size_t i = 0; i < n; ++i) {
    const double *row = &jac[i * NPARAM];
    for (int a = 0; a < NPARAM; ++a) {
      (*g)[a] += row[a] * res[i];
      for (int b = 0; b < NPARAM; ++b) (*A)[a * NPARAM + b] += row[a] * row[b];
    }
  }
}

double cost(const Curve &c, const Theta &t, std::vector<double> *res, std::vector<double> *jac)
{
  const std::vector<double> F = simulate(t, c.slip, jac);
  res->resize(F.size());
  double s = 0;
  for (size_t i = 0; i < F.size(); ++i) {
    (*res)[i] = F[i] - c.load[i];
    s += (*res)[i] * (*res)[i];
  }
  return s;
}

// Keep the parameters admissible: ke > 0; G, kg, j, kc >= 0.
Theta project(const Theta &t, const Theta &prev)
{
  Theta q = t;
  if (!(q[KE] > 0)) q[KE] = 0.5 * prev[KE];
  if (!(q[G] > 0)) q[G] = 0.5 * prev[G];
  if (!(q[J] >= 0)) q[J] = 0.5 * prev[J];
  if (!(q[KG] >= 0)) q[KG] = 0;
  if (!(q[KC] >= 0)) q[KC] = 0;
  return q;
}

std::string neverSlides(double ke)
{
  return "G, kg, j and kc are not identifiable: the curve never slides (its backbone is one straight line, "
         "the stick slope ke = " + fmt(ke) + "); load the joint beyond its friction threshold G";
}

std::string neverBears(double G)
{
  return "j and kc are not identifiable: the curve never reaches bearing (it sticks, then slides above G = " + fmt(G) +
         " but never shows the stiffer slope of the bolt bearing on its hole); load it beyond the clearance";
}

} // namespace

std::string fitFriction(const Curve &c, FitResult *r)
{
  *r      = FitResult();
  r->n    = static_cast<int>(c.load.size());
  if (c.load.size() != c.slip.size()) return "curve '" + c.name + "': load and slip have different lengths";
  if (r->n < 2 * NPARAM)
    return "curve '" + c.name + "' has " + std::to_string(r->n) + " points: at least " + std::to_string(2 * NPARAM) + " are needed to fit the " +
           std::to_string(NPARAM) + " parameters ke, G, kg, j, kc";

  // 1. Initial guess: piecewise-linear fit of the backbone on each side; the side that shows more
  //    regimes (ties: the side the curve first moves to).
  double first = 0;
  for (double u : c.slip)
    if (u != 0) {
      first = u > 0 ? 1 : -1;
      break;
    }
  if (first == 0) return "curve '" + c.name + "': the slip is zero on every row, nothing can be identified";
  Segmented seg;
  for (double s : {first, -first}) {
    std::vector<double> u, F;
    backbone(c, s, &u, &F);
    if (u.size() < 5) continue;
    const Segmented t = segmentedFit(u, F);
    if (t.m > seg.m || seg.ke == 0) seg = t;
  }
  if (!(seg.ke > 0)) return "curve '" + c.name + "': the load does not rise with the slip; it is not a load-slip curve of a joint";
  if (seg.m == 1) return "curve '" + c.name + "': " + neverSlides(seg.ke);
  if (seg.m == 2) return "curve '" + c.name + "': " + neverBears(seg.ke * seg.b1);
  Theta t  = {seg.ke, seg.ke * seg.b1, std::max(seg.kg, 0.0), seg.b2 - seg.b1, std::max(seg.kc, 0.0)};
  r->guess = t;

  // 2. Levenberg-Marquardt with Marquardt's scaling: (A + lambda diag(A)) delta = -g.
  std::vector<double> res, jac, A, g, delta;
  double              f = cost(c, t, &res, &jac), lambda = 1e-3;
  for (r->iterations = 0; r->iterations < 500; ++r->iterations) {
    normal(jac, res, &A, &g);
    double dmax = 0;
    for (int k = 0; k < NPARAM; ++k) dmax = std::max(dmax, A[k * NPARAM + k]);
    bool accepted = false, small = false;
    while (lambda < 1e20) {
      std::vector<double> M = A, rhs(NPARAM);
      for (int k = 0; k < NPARAM; ++k) {
        M[k * NPARAM + k] += lambda * std::max(A[k * NPARAM + k], 1e-30 * dmax);
        rhs[k] = -g[k];
      }
      if (!solve(NPARAM, M, rhs, &delta)) {
        lambda *= 10;
        continue;
      }
      Theta trial;
      small = true;
      for (int k = 0; k < NPARAM; ++k) {
        trial[k] = t[k] + delta[k];
        if (std::fabs(delta[k]) > 1e-13 * (std::fabs(t[k]) + 1e-300)) small = false;
      }
      trial = project(trial, t);
      std::vector<double> res2, jac2;
      const double        f2 = cost(c, trial, &res2, &jac2);
      if (f2 <= f) {
        t = trial;
        f = f2;
        res.swap(res2);
        jac.swap(jac2);
        lambda = std::max(lambda / 5, 1e-15);
        accepted = true;
        break;
      }
      if (small) break;
      lambda *= 5;
    }
    if (!accepted || small || f == 0) {
      r->converged = true;
      break;
    }
  }

  // 3. Results, states, identifiability, standard errors.
  r->theta = t;
  r->rss   = f;
  r->rms   = std::sqrt(f / r->n);
  r->sigma = std::sqrt(f / (r->n - NPARAM));
  std::vector<State> states;
  std::vector<char>  bear;
  simulate(t, c.slip, nullptr, &states, &bear);
  for (size_t i = 0; i < states.size(); ++i) {
    if (states[i] == State::Stick) ++r->n_stick;
    else if (bear[i]) ++r->n_bearing;
    else ++r->n_slide;
  }
  if (r->n_slide + r->n_bearing == 0) return "curve '" + c.name + "': " + neverSlides(t[KE]);
  if (r->n_bearing == 0) return "curve '" + c.name + "': " + neverBears(t[G]);

  // Covariance s^2 (J^T J)^-1 through the column-scaled normal matrix; a (near) dependent column
  // means the curve does not determine that parameter.
  normal(jac, res, &A, &g);
  Theta scale;
  for (int k = 0; k < NPARAM; ++k) scale[k] = std::sqrt(A[k * NPARAM + k]);
  std::string undetermined;
  for (int k = 0; k < NPARAM; ++k)
    if (!(scale[k] > 0)) undetermined += std::string(undetermined.empty() ? "" : ", ") + paramName(k);
  std::vector<double> S(NPARAM * NPARAM);
  if (undetermined.empty()) {
    for (int a = 0; a < NPARAM; ++a)
      for (int b = 0; b < NPARAM; ++b) S[a * NPARAM + b] = A[a * NPARAM + b] / (scale[a] * scale[b]);
    // Cholesky with a pivot test names the first dependent parameter.
    std::vector<double> L(NPARAM * NPARAM, 0.0);
    for (int k = 0; k < NPARAM && undetermined.empty(); ++k) {
      double d = S[k * NPARAM + k];
      for (int m = 0; m < k; ++m) d -= L[k * NPARAM + m] * L[k * NPARAM + m];
      if (!(d > 1e-12)) {
        undetermined = paramName(k);
        break;
      }
      L[k * NPARAM + k] = std::sqrt(d);
      for (int i = k + 1; i < NPARAM; ++i) {
        double v = S[i * NPARAM + k];
        for (int m = 0; m < k; ++m) v -= L[i * NPARAM + m] * L[k * NPARAM + m];
        L[i * NPARAM + k] = v / L[k * NPARAM + k];
      }
    }
  }
  if (!undetermined.empty())
    return "curve '" + c.name + "': " + undetermined +
           " not identifiable: the curve does not constrain it independently of the other parameters (singular normal matrix; "
           "e.g. no rows slide inside the clearance, or too few rows in bearing)";
  for (int k = 0; k < NPARAM; ++k) {
    std::vector<double> e(NPARAM, 0.0), x;
    e[k] = 1;
    solve(NPARAM, S, e, &x);
    r->stderr_[k] = r->sigma * std::sqrt(std::max(x[k], 0.0)) / scale[k];
  }
  std::ostringstream w;
  if (t[KG] > t[KE]) w << "kg = " << fmt(t[KG]) << " exceeds ke = " << fmt(t[KE]) << "; ";
  if (t[KC] > t[KE]) w << "kc = " << fmt(t[KC]) << " exceeds ke = " << fmt(t[KE]) << " (boltnet's frictional law requires kc <= kt, docs/joint-laws.md); ";
  if (t[KC] < t[KG]) w << "kc = " << fmt(t[KC]) << " is below kg = " << fmt(t[KG]) << "; ";
  if (!r->converged) w << "Levenberg-Marquardt stopped after " << r->iterations << " iterations without converging; ";
  r->warning = w.str();
  return "";
}

} // namespace identify
} // namespace boltnet
