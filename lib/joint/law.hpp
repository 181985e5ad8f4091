// Joint laws of the bolted-joint macroelement (paper sect. 2, made precise in docs/joint-laws.md).
//
// Every law is a pure function
//   (parameters, committed history, local jump) -> (local force, local tangent, trial history)
// Nothing here touches PETSc or global state: residual and Jacobian evaluations call evaluate(),
// and only the end of a converged load step copies the trial history into the committed one.
#pragma once

#include <array>
#include <string>

namespace boltnet {

// Which constitutive law an edge carries. Values are stored in plain structs copied by DMNetwork.
enum class Law : int { Spring = 0, Contact = 1, Friction = 2 };

// State of a joint after an evaluation. Written to joints.csv by name (stateName()).
enum class State : int { Linear = 0, Open = 1, Contact = 2, Stick = 3, Slide = 4 };

// Which tangent a law returns: the paper's state-switched one or the consistent (algorithmic) one.
enum class Tangent : int { Paper = 0, Consistent = 1 };

// Parameters of one joint type; a plain struct (no pointers): DMNetwork copies it as raw bytes.
// Local frame: component 0 is the bolt axis n, components 1, 2 the joint plane (t1, t2), 3..5 rotations.
// Units: force N, length mm, stiffness N/mm, rotational stiffness N mm/rad.
struct Params {
  Law    law = Law::Spring;
  double kn  = 0;  // axial stiffness along n
  double kt  = 0;  // in-plane stiffness: spring kt; contact k (before contact); friction ke (stick)
  double kr  = 0;  // rotational stiffness (high: rigid rotation)
  double kc  = 0;  // contact: k' (after contact); friction: bearing stiffness after the clearance closes
  double kg  = 0;  // friction: regularisation stiffness while sliding (kg = 0 is pure Coulomb)
  double gap = 0;  // j: radius of the clearance circle in the joint plane
  double mu  = 0;  // friction coefficient
  double nf  = 1;  // number of friction interfaces (1 single lap, 2 double lap)
  double pretension = 0;     // Pc, bolt clamp force
  double clamp_coupling = 0; // phi: G = mu nf max(0, Pc - phi F_n); 0 reproduces the paper (G constant)
  double offset[2] = {0, 0}; // initial position of the bolt in the hole (t1, t2): centre of the clearance circle
  // Spring only: a full stiffness, used as is when `full` is set (kn, kt, kr are then not used):
  // K (6 x 6, row major, the local frame above) maps the jump to the force, F = K du, with every
  // coupling between the axes kept (a Nastran CBUSH whose element axes are not the joint frame,
  // docs/nastran.md). Symmetric, its diagonal >= 0 (validate()).
  int    full = 0;
  double K[36] = {};
};

// Committed (or trial) history of one joint: the slip of the friction slider in the joint plane.
struct History {
  double slip[2] = {0, 0};
  int    state   = 0; // State as int
};

using Vec6 = std::array<double, 6>;
using Mat6 = std::array<double, 36>; // row major

struct Response {
  Vec6    force{};   // local force on node B (node A gets the opposite)
  Mat6    tangent{}; // d force / d jump, local frame
  History trial;     // history if this point were accepted
  State   state = State::Linear;
  bool    bearing = false; // friction: the slip has closed the clearance (bolt bears on the hole)
};

// Sliding stiffness in the tangent of the frictional law for kg = 0 (pure Coulomb), as a fraction of
// ke: the Jacobian only, the force uses kg = 0 itself; any kg > 0 is its own tangent (docs/joint-laws.md).
constexpr double kSlideFloor = 1e-3;

// The stiffness (2x2, row major, joint plane) that the consistent tangent of the frictional law adds
// to dh/dw when kg = 0, at a sliding point with this trial slip: kSlideFloor ke I inside the
// clearance, kSlideFloor ke (I - m m^T) in bearing (m the radial direction), zero for kg > 0.
std::array<double, 4> slideFloorOf(const Params &p, const History &trial, bool bearing);

// Friction threshold G = mu nf max(0, Pc - phi F_n) for the given normal force.
double frictionThreshold(const Params &p, double normal_force);

// Evaluate the law at the local jump du = (du_n, du_t1, du_t2, dth_n, dth_t1, dth_t2).
// frozen: keep the joint in the linear state it has with its committed history (friction: stick
// with the committed slip; contact: the clearance open), without the state test: an affine spring
// whose force and tangent are, bit for bit, the law's wherever the law is in that state
// (utilization() < 1). Used for joints that stay stuck (docs/solver.md, "Linear where it can be").
Response evaluate(const Params &p, const History &committed, const Vec6 &jump, Tangent tangent, bool frozen = false);

// How close the joint is, at this jump with this committed history, to leaving its linear state:
// friction |ke (du_t - w)| / G (stick while <= 1), contact |du_t - offset| / gap (open while <= 1),
// spring 0 (always linear). Infinity where the linear state has no room (G = 0 away from rest;
// gap = 0 always: the contact law then bears at every jump, at rest too).
double utilization(const Params &p, const History &committed, const Vec6 &jump);

// Check the parameters; returns an empty string when valid, else a message naming the parameter.
std::string validate(const Params &p);

const char *stateName(State s);
const char *lawName(Law l);
// Parse "spring" | "contact" | "friction"; returns false when unknown.
bool parseLaw(const std::string &name, Law *law);

} // namespace boltnet
