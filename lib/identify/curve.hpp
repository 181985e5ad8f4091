// The frictional macroelement's parameters from a test curve: a load-slip curve
// (monotonic or cyclic) is fitted by nonlinear least squares (Levenberg-Marquardt on the five
// parameters ke, G, kg, j, kc), with standard errors and the residual; a curve that cannot identify
// a parameter is rejected with a message naming it. docs/identify.md has the details.
//
// The forward model is boltnet's own law (boltnet::evaluate, lib/joint/law.cpp) driven along the
// curve's slip history, one committed step per row. Pure C++: no PETSc, no global state.
#pragma once

#include "joint/law.hpp"

#include <array>
#include <string>
#include <vector>

namespace boltnet {
namespace identify {

// A test curve: rows in time order. Slip is the joint's in-plane jump (the macroelement's du_t),
// load the force it carries.
struct Curve {
  std::vector<double> load, slip;
  std::string         name; // where it came from, for messages
};

// Parse CSV text: a header naming the columns `load` and `slip` (any order, other columns ignored
// except `time`), then one row per point. Blank lines and lines starting with '#' are skipped.
// If a `time` column is present it must increase strictly from row to row (the rows are the
// history, in order); without it, the row order is the time order. Returns "" or a message
// naming the file, the line and the column.
std::string parseCurve(const std::string &text, const std::string &name, Curve *c);
// Read and parse a file; "" or a message (a missing file included).
std::string readCurve(const std::string &path, Curve *c);

// The five fitted parameters, in this order.
enum Param : int { KE = 0, G = 1, KG = 2, J = 3, KC = 4, NPARAM = 5 };
using Theta = std::array<double, NPARAM>;
const char *paramName(int k); // "ke", "G", "kg", "j", "kc"

// The joint parameters of a 1D frictional macroelement with these values (G = mu nf Pc with
// mu = nf = 1, Pc = G; no offset).
Params frictionParams(const Theta &t);

// Drive boltnet::evaluate along the slip history from rest; the force at each row.
// If jac is given it receives d force_i / d theta_k (row major, n x 5), exact (the sensitivities
// of the incremental law, with the states evaluate() chose). If states is given, it receives the
// state of each row (State::Stick, Slide or Contact) and bearing flags in *bearing.
std::vector<double> simulate(const Theta &t, const std::vector<double> &slip, std::vector<double> *jac = nullptr,
                             std::vector<State> *states = nullptr, std::vector<char> *bearing = nullptr);

struct FitResult {
  Theta       theta{};       // fitted ke, G, kg, j, kc
  Theta       stderr_{};     // standard errors: sqrt(diag(s^2 (J^T J)^-1)), s^2 = RSS / (n - 5)
  Theta       guess{};       // the initial guess (breakpoints of the backbone curve)
  double      rss = 0;       // residual sum of squares
  double      rms = 0;       // sqrt(RSS / n)
  double      sigma = 0;     // s = sqrt(RSS / (n - 5)), the noise estimate
  int         n = 0;         // points
  int         iterations = 0;
  bool        converged = false;
  int         n_stick = 0, n_slide = 0, n_bearing = 0; // rows in each state with the fitted parameters
  std::string warning;       // e.g. the fitted parameters break kg <= kc <= ke
};

// Fit; returns "" or a message saying why the curve cannot be fitted (too few points, or which
// parameters it cannot identify and why).
std::string fitFriction(const Curve &c, FitResult *r);

} // namespace identify
} // namespace boltnet
