// Scenes: a PETSc YAML options file (every parameter is an option) plus CSV tables for the
// structured lists (patches, joints, boundary conditions) that options cannot hold.
#include "io/io.hpp"
#include "io/cases.hpp"
#include "io/limits.hpp"
#include "io/scene_yaml.hpp"
#include "io/input.hpp"
#include "io/table.hpp"
#include "core/errors.hpp"
#include "core/bcast.hpp"
#include "core/guard.hpp"
#include "mesh/gmsh.hpp"
#include "identify/coupon.hpp"
#include "identify/options.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace boltnet {
namespace {

PetscErrorCode ParseTable(MPI_Comm comm, const std::string &path, const std::string &text, const std::vector<std::string> &required, Table *t)
{
  return Input(comm, "reading the scene", [&] { *t = boltnet::ParseTable(path, text, required); });
}

PetscErrorCode Cell(MPI_Comm comm, const Table &t, size_t row, const std::string &col, std::string *v)
{
  return Input(comm, "reading the scene", [&] { *v = TableCell(t, row, col); });
}

PetscErrorCode RealCell(MPI_Comm comm, const Table &t, size_t row, const std::string &col, PetscReal *x)
{
  return Input(comm, "reading the scene", [&] { *x = TableReal(t, row, col); });
}

// A whole number in [lo, hi] (at most limits::kMaxId: PetscInt is 32-bit here).
PetscErrorCode IntCell(MPI_Comm comm, const Table &t, size_t row, const std::string &col, std::int64_t lo, std::int64_t hi, PetscInt *i)
{
  return Input(comm, "reading the scene", [&] { *i = static_cast<PetscInt>(TableInt(t, row, col, lo, hi)); });
}

// An id of a patch or a joint: 0 .. 2^31 - 1.
PetscErrorCode IdCell(MPI_Comm comm, const Table &t, size_t row, const std::string &col, PetscInt *i)
{
  return IntCell(comm, t, row, col, 0, limits::kMaxId, i);
}

// Options PETSc reads only while or after it solves (viewers and reasons printed at the end of a
// solve, the factorisation package's options at the first factorisation, the logs at
// PetscFinalize): an option check before the solve cannot count them as unused.
// Measured on fig3a with PETSc 3.18: -snes_view, -ksp_view, -dm_view, -snes_converged_reason,
// -ksp_converged_reason, -snes_test_jacobian and -mat_mumps_icntl_14 are unused before SNESSolve;
// so are the options of BDDC's subdomain and coarse solvers (-pc_bddc_dirichlet_, -pc_bddc_neumann_,
// -pc_bddc_coarse_), which PCSetUp_BDDC creates, and those of the solvers that PCSetUp creates for
// PCFIELDSPLIT's splits (-fieldsplit_), for multigrid's levels (-mg_levels_, -mg_coarse_) and for
// block Jacobi's blocks (-sub_).
bool ReadDuringSolve(const std::string &name)
{
  auto ends   = [&](const std::string &s) { return name.size() >= s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0; };
  auto starts = [&](const std::string &s) { return name.rfind(s, 0) == 0; };
  if (ends("_view") || name.find("_view_") != std::string::npos || ends("_converged_reason")) return true;
  for (const char *p : {"snes_test_", "ksp_test_", "mat_mumps_", "mat_superlu", "mat_umfpack_", "mat_cholmod_", "mat_klu_", "mat_strumpack_", "log_", "pc_bddc_dirichlet_", "pc_bddc_neumann_", "pc_bddc_coarse_", "fieldsplit_", "mg_levels_", "mg_coarse_", "sub_"})
    if (starts(p)) return true;
  return false;
}

bool HasColumn(const Table &t, const std::string &col)
{
  return t.Has(col);
}

std::string Resolve(const Scene &s, const std::string &option, const std::string &path)
{
  if (path.empty() || path[0] == '/' || !s.from_file.count(option) || s.dir.empty()) return path;
  return s.dir + "/" + path;
}

// The macroelement's parameters as options, inside the joint type's options block.
PetscErrorCode JointParamsOptions(PetscOptionItems *PetscOptionsObject, BoltnetJointParams *p)
{
  const char *laws[] = {"spring", "contact", "friction"};
  PetscInt    law    = 0;
  PetscBool   set;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsEList("-law", "Macroelement law", "", laws, 3, laws[law], &law, &set));
  p->law = static_cast<BoltnetLaw>(law);
  PetscCall(PetscOptionsReal("-kn", "Axial stiffness along the bolt (N/mm)", "", p->kn, &p->kn, nullptr));
  PetscCall(PetscOptionsReal("-kt", "In-plane stiffness (N/mm): spring kt, contact k before contact, friction ke while sticking", "", p->kt, &p->kt, nullptr));
  PetscCall(PetscOptionsReal("-kr", "Rotational stiffness (N mm/rad), high for a rigid rotation", "", p->kr, &p->kr, nullptr));
  PetscCall(PetscOptionsReal("-kc", "Stiffness after the clearance closes (N/mm): contact k', friction bearing kc", "", p->kc, &p->kc, nullptr));
  PetscCall(PetscOptionsReal("-kg", "Friction: regularisation stiffness while sliding (N/mm); 0 is pure Coulomb", "", p->kg, &p->kg, nullptr));
  PetscCall(PetscOptionsReal("-gap", "Clearance j between bolt and hole, radius in the joint plane (mm)", "", p->gap, &p->gap, nullptr));
  PetscCall(PetscOptionsReal("-mu", "Friction coefficient", "", p->mu, &p->mu, nullptr));
  PetscCall(PetscOptionsReal("-nf", "Friction interfaces: 1 single lap, 2 double lap", "", p->nf, &p->nf, nullptr));
  PetscCall(PetscOptionsReal("-pretension", "Bolt clamp force Pc (N); G = mu nf Pc", "", p->pretension, &p->pretension, nullptr));
  PetscCall(PetscOptionsReal("-clamp_coupling", "phi in G = mu nf max(0, Pc - phi F_n); 0 is the paper's constant G", "", p->clamp_coupling, &p->clamp_coupling, nullptr));
  PetscCall(PetscOptionsReal("-offset_t1", "Initial bolt offset in the hole along t1 (mm)", "", p->offset[0], &p->offset[0], nullptr));
  PetscCall(PetscOptionsReal("-offset_t2", "Initial bolt offset in the hole along t2 (mm)", "", p->offset[1], &p->offset[1], nullptr));
  PetscFunctionReturn(0);
}

// Options of one joint type, prefix joint_<type>_; -help lists them with defaults and units.
// The shell correction of a joint type identified from its geometry (docs/identify.md, "Stiffness
// already in the shells"): the coupon meshed like the patches around its first joint, with their
// sections and the scene's coupling; corrects q's kc and kt and records the coupon in j.
PetscErrorCode ShellCorrection(MPI_Comm comm, BoltnetAssembly a, const std::string &type, const identify::FastenerOptions &o, const identify::ShellCorrectionOptions &sc, const FirstJoint &fj, Params *q, std::ostringstream &j)
{
  identify::CouponSpec   spec;
  identify::CouponResult res;
  PetscFunctionBeginUser;
  // The coupling the scene will use (read again by BoltnetAssemblySetFromOptions later).
  PetscInt  ct = static_cast<PetscInt>(a->opt.coupling_type);
  PetscReal radius = a->opt.coupling_radius, penalty = a->opt.coupling_penalty;
  PetscCall(PetscOptionsGetEList(nullptr, a->prefix.c_str(), "-coupling_type", kCouplingTypeNames, 3, &ct, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, a->prefix.c_str(), "-coupling_radius", &radius, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, a->prefix.c_str(), "-coupling_penalty", &penalty, nullptr));
  PetscCheck(o.g.n == 1, comm, PETSC_ERR_USER_INPUT, "Joint type '%s': the shell correction's coupon is a single lap of two sheets; it needs -joint_%s_fastener_shear_planes 1 (got %d)", type.c_str(), type.c_str(), o.g.n);
  const PetscInt ids[2] = {fj.patch_a, fj.patch_b};
  for (int i = 0; i < 2; ++i) {
    const PetscInt   pos = a->model.Find(ids[i]);
    const ShellPart *sp  = a->model.shells.count(pos) ? &a->model.shells.at(pos) : nullptr;
    PetscCheck(sp, comm, PETSC_ERR_USER_INPUT, "Joint type '%s': the shell correction (-joint_%s_fastener_shell_correction) needs shell patches, but joint %" PetscInt_FMT " attaches to patch %" PetscInt_FMT ", which is not one", type.c_str(), type.c_str(), fj.id, ids[i]);
    // The coupon lies in its x-y plane, pulled along x = the joint's t1 (y = n x t1): a laminate's
    // reference direction goes with it.
    spec.sheet[i] = sp->material;
    {
      const PetscReal *n = fj.n, *t = fj.t1, *dir = sp->material.direction.data();
      const PetscReal  nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), dn = (t[0] * n[0] + t[1] * n[1] + t[2] * n[2]) / (nn * nn);
      PetscReal        e1[3] = {t[0] - dn * n[0], t[1] - dn * n[1], t[2] - dn * n[2]}, e2[3];
      const PetscReal  en = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
      for (PetscReal &c : e1) c /= en;
      e2[0] = (n[1] * e1[2] - n[2] * e1[1]) / nn, e2[1] = (n[2] * e1[0] - n[0] * e1[2]) / nn, e2[2] = (n[0] * e1[1] - n[1] * e1[0]) / nn;
      spec.sheet[i].direction = {dir[0] * e1[0] + dir[1] * e1[1] + dir[2] * e1[2], dir[0] * e2[0] + dir[1] * e2[1] + dir[2] * e2[2], 0.0};
    }
    if (sc.h > 0) spec.hx[i] = spec.hy[i] = sc.h;
    else if (sp->on_rank0) { // measured where the mesh is
      PetscMPIInt rank;
      double      h[2] = {0, 0};
      PetscCallMPI(MPI_Comm_rank(comm, &rank));
      PetscCall(Collective(comm, "measuring the elements", [&] { return rank ? PetscErrorCode(0) : identify::FootprintElementSize(PETSC_COMM_SELF, sp->mesh, fj.x, fj.n, fj.t1, radius, &h[0], &h[1]); }));
      PetscCallMPI(MPI_Bcast(h, 2, MPI_DOUBLE, 0, comm));
      spec.hx[i] = h[0], spec.hy[i] = h[1];
    } else {
      // A part read later (ShellPart::read) is read here for the measurement and not kept.
      ShellMesh read;
      if (sp->read) PetscCall(Collective(comm, "reading a mesh", [&] { return sp->read(&read); }));
      PetscCall(identify::FootprintElementSize(comm, sp->read ? read : sp->mesh, fj.x, fj.n, fj.t1, radius, &spec.hx[i], &spec.hy[i]));
    }
  }
  spec.d        = o.g.d;
  spec.width    = sc.width;
  spec.coupling = static_cast<CouplingType>(ct);
  spec.radius   = radius;
  spec.penalty  = penalty;
  spec.kspring  = sc.spring * q->kc;
  PetscCall(identify::CouponCompliance(spec, &res));
  const double kc0 = q->kc, kt0 = q->kt;
  char         what[256];
  PetscCall(PetscSNPrintf(what, sizeof(what), "Joint type '%s' (shell correction at its joint %" PetscInt_FMT ", elements %.3g x %.3g and %.3g x %.3g mm, %s coupling)", type.c_str(), fj.id, spec.hx[0], spec.hy[0], spec.hx[1], spec.hy[1], kCouplingTypeNames[ct]));
  PetscCall(identify::ApplyShellCorrection(comm, what, res.Cc, q));
  j << ", \"shell_correction\": {\"C_c\": " << res.Cc << ", \"kc_formula\": " << kc0 << ", \"kt_formula\": " << kt0 << ", \"h\": [[" << spec.hx[0] << ", " << spec.hy[0] << "], [" << spec.hx[1] << ", " << spec.hy[1] << "]]"
    << ", \"coupling\": \"" << kCouplingTypeNames[ct] << "\", \"radius\": " << radius << ", \"coupon\": {\"width\": " << res.width << ", \"length\": " << res.length << ", \"edge\": " << res.edge << ", \"C_b\": " << res.Cb << ", \"spring\": " << spec.kspring << "}}";
  PetscCall(PetscInfo(nullptr, "joint type %s: shell correction C_c %g (elements %g x %g, %g x %g): kc %g -> %g\n", type.c_str(), res.Cc, spec.hx[0], spec.hy[0], spec.hx[1], spec.hy[1], kc0, q->kc));
  PetscFunctionReturn(0);
}

PetscErrorCode JointTypeFromOptions(MPI_Comm comm, BoltnetAssembly a, const std::string &type, const FirstJoint &fj, BoltnetJointParams *p, Scene *scene)
{
  const std::string prefix = "joint_" + type + "_";
  const std::string title  = "Joint type '" + type + "' (units: N, mm, N/mm, N mm/rad)";
  PetscFunctionBeginUser;
  PetscCall(BoltnetJointParamsSetDefault(BOLTNET_LAW_SPRING, p));
  // Parameters given, or identified from the fastener's geometry at start-up.
  const char *sources[] = {"parameters", "geometry"};
  PetscInt    source    = 0;
  PetscOptionsBegin(comm, prefix.c_str(), title.c_str(), "boltnet");
  PetscCall(PetscOptionsEList("-from", "Where the macroelement's parameters come from: the options below, or the fastener geometry (-joint_<type>_fastener_*, docs/identify.md)", "", sources, 2, sources[0], &source, nullptr));
  if (source == 0) PetscCall(JointParamsOptions(PetscOptionsObject, p));
  PetscOptionsEnd();
  if (source == 1) {
    identify::FastenerOptions o;
    Params                    q;
    const std::string         fprefix = prefix + "fastener_";
    const std::string         ftitle  = "Joint type '" + type + "': fastener geometry (units: N, mm, MPa, N mm)";
    PetscCall(identify::FastenerFromOptions(comm, fprefix.c_str(), ftitle.c_str(), &o));
    PetscCall(identify::FastenerMacroelement(comm, fprefix.c_str(), o, &q));
    identify::ShellCorrectionOptions sc;
    const std::string                stitle = "Joint type '" + type + "': shell correction of the formula's stiffness";
    std::ostringstream               jc;
    jc.precision(17);
    PetscCall(identify::ShellCorrectionFromOptions(comm, fprefix.c_str(), stitle.c_str(), PETSC_FALSE, &sc));
    PetscBool help;
    PetscCall(PetscOptionsHasHelp(nullptr, &help));
    if (sc.on && !help) PetscCall(ShellCorrection(comm, a, type, o, sc, fj, &q, jc));
    p->law = BOLTNET_LAW_FRICTION;
    p->kn = q.kn, p->kt = q.kt, p->kr = q.kr, p->kc = q.kc, p->kg = q.kg, p->gap = q.gap, p->mu = q.mu, p->nf = q.nf;
    p->pretension = q.pretension, p->clamp_coupling = q.clamp_coupling, p->offset[0] = q.offset[0], p->offset[1] = q.offset[1];
    std::ostringstream j;
    j.precision(17);
    j << (scene->identified.empty() ? "" : ", ") << "\"" << type << "\": {\"formula\": \"" << identify::formulaName(o.formula) << "\", \"kn\": " << q.kn << ", \"kt\": " << q.kt << ", \"kc\": " << q.kc
      << ", \"kg\": " << q.kg << ", \"kr\": " << q.kr << ", \"gap\": " << q.gap << ", \"mu\": " << q.mu << ", \"nf\": " << q.nf << ", \"pretension\": " << q.pretension << ", \"G\": " << frictionThreshold(q, 0.0) << jc.str() << "}";
    scene->identified += j.str();
    PetscCall(PetscInfo(nullptr, "joint type %s identified from its geometry: kc %g gap %g pretension %g\n", type.c_str(), q.kc, q.gap, q.pretension));
    PetscFunctionReturn(0);
  }
  Params q;
  q.law = static_cast<Law>(p->law);
  q.kn = p->kn, q.kt = p->kt, q.kr = p->kr, q.kc = p->kc, q.kg = p->kg, q.gap = p->gap, q.mu = p->mu, q.nf = p->nf;
  q.pretension = p->pretension, q.clamp_coupling = p->clamp_coupling, q.offset[0] = p->offset[0], q.offset[1] = p->offset[1];
  const std::string bad = validate(q);
  PetscCheck(bad.empty(), comm, PETSC_ERR_USER_INPUT, "Joint type '%s' (options -%s*): %s", type.c_str(), prefix.c_str(), bad.c_str());
  PetscFunctionReturn(0);
}

// A shell section from options: isotropic (-material_<name>_E, _nu, _t) or a laminate given ply by
// ply (-material_<name>_layup angles from the bottom, -material_<name>_ply_t, and the ply moduli
// -material_<name>_E1, _E2, _nu12, _G12, _G13, _G23), by classical lamination theory.
PetscErrorCode MaterialFromOptions(MPI_Comm comm, const std::string &name, shell::ShellMaterial *mat)
{
  const char       *kinds[] = {"isotropic", "laminate"};
  PetscInt          kind    = 0, nply = 256;
  PetscReal         E = 0, nu = 0.3, t = 0, angles[256], tply = 0, E1 = 0, E2 = 0, nu12 = 0.3, G12 = 0, G13 = 0, G23 = 0;
  PetscBool         hasLayup = PETSC_FALSE;
  const std::string prefix = "material_" + name + "_";
  const std::string title  = "Material '" + name + "' (shell section; units: MPa, mm, degrees)";
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, prefix.c_str(), title.c_str(), "boltnet");
  PetscCall(PetscOptionsEList("-type", "Section: isotropic, or a laminate given ply by ply", "", kinds, 2, kinds[0], &kind, nullptr));
  if (kind == 0) {
    PetscCall(PetscOptionsReal("-E", "Young's modulus (MPa)", "", E, &E, nullptr));
    PetscCall(PetscOptionsReal("-nu", "Poisson's ratio", "", nu, &nu, nullptr));
    PetscCall(PetscOptionsReal("-t", "Shell thickness (mm)", "", t, &t, nullptr));
  } else {
    PetscCall(PetscOptionsRealArray("-layup", "Ply angles from the bottom ply up (degrees, comma separated)", "", angles, &nply, &hasLayup));
    PetscCall(PetscOptionsReal("-ply_t", "Ply thickness (mm)", "", tply, &tply, nullptr));
    PetscCall(PetscOptionsReal("-E1", "Ply modulus along the fibres (MPa)", "", E1, &E1, nullptr));
    PetscCall(PetscOptionsReal("-E2", "Ply modulus across the fibres (MPa)", "", E2, &E2, nullptr));
    PetscCall(PetscOptionsReal("-nu12", "Ply major Poisson's ratio", "", nu12, &nu12, nullptr));
    PetscCall(PetscOptionsReal("-G12", "Ply in-plane shear modulus (MPa)", "", G12, &G12, nullptr));
    PetscCall(PetscOptionsReal("-G13", "Ply transverse shear modulus 13 (MPa)", "", G13, &G13, nullptr));
    PetscCall(PetscOptionsReal("-G23", "Ply transverse shear modulus 23 (MPa)", "", G23, &G23, nullptr));
  }
  PetscOptionsEnd();
  if (kind == 0) {
    PetscCheck(E > 0, comm, PETSC_ERR_USER_INPUT, "Material '%s': -%sE = %g must be > 0", name.c_str(), prefix.c_str(), (double)E);
    PetscCheck(t > 0, comm, PETSC_ERR_USER_INPUT, "Material '%s': -%st = %g must be > 0", name.c_str(), prefix.c_str(), (double)t);
    PetscCheck(nu > -1 && nu < 0.5, comm, PETSC_ERR_USER_INPUT, "Material '%s': -%snu = %g must lie in (-1, 0.5)", name.c_str(), prefix.c_str(), (double)nu);
  } else PetscCheck(hasLayup && nply > 0, comm, PETSC_ERR_USER_INPUT, "Material '%s' is a laminate with no plies: give -%slayup (ply angles, e.g. 0,45,-45,90)", name.c_str(), prefix.c_str());
  std::vector<shell::Ply> plies;
  for (PetscInt i = 0; kind == 1 && i < nply; ++i) plies.push_back(shell::Ply{angles[i], tply, E1, E2, nu12, G12, G13, G23});
  PetscCall(Guard(comm, [&] {
    try {
      *mat = kind == 0 ? shell::IsotropicMaterial(E, nu, t) : shell::LaminateMaterial(plies);
    } catch (const std::invalid_argument &e) {
      throw std::invalid_argument("Material '" + name + "' (options -" + prefix + "*): " + e.what());
    }
    return PetscErrorCode(0);
  }));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode SceneJointTypes(MPI_Comm comm, BoltnetAssembly a, std::vector<std::pair<std::string, FirstJoint>> *firsts, std::vector<BoltnetJointParams> *types, Scene *scene)
{
  static_assert(std::is_trivially_copyable<FirstJoint>::value, "a first joint travels as bytes");
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  std::vector<FirstJoint> first;
  for (const auto &[type, f] : *firsts) first.push_back(f);
  PetscCall(BcastVector(comm, &first));
  if (rank) firsts->resize(first.size());
  for (size_t k = 0; k < first.size(); ++k) {
    PetscCall(BcastString(comm, &(*firsts)[k].first));
    (*firsts)[k].second = first[k];
  }
  types->assign(firsts->size(), BoltnetJointParams{});
  for (size_t k = 0; k < firsts->size(); ++k) PetscCall(Guard(comm, [&] { return JointTypeFromOptions(comm, a, (*firsts)[k].first, (*firsts)[k].second, &(*types)[k], scene); }));
  PetscFunctionReturn(0);
}

namespace {

// A row of the fastener table, checked; type is its position in the list of joint types.
struct FastenerRow {
  PetscInt  id, pa, pb;
  PetscReal n[3], t[3], pos[3];
  bool      positioned;
  size_t    type;
  std::string footprint; // a node set named as the footprint (column `footprint`; empty: found)
  int         line;      // in the table, for messages
  // This joint's own clearance and clamp force (columns `gap`, mm, and `pretension`, N), in place
  // of its type's; an empty cell or no column: the type's.
  bool      has_gap = false, has_pretension = false;
  PetscReal gap = 0, pretension = 0;
};

// An optional cell of a number >= 0: no column or an empty cell leave *given false.
PetscErrorCode OptionalCell(MPI_Comm comm, const Table &t, size_t row, const std::string &col, const char *what, PetscReal *x, bool *given)
{
  std::string text;
  PetscFunctionBeginUser;
  *given = false;
  if (!HasColumn(t, col)) PetscFunctionReturn(0);
  PetscCall(Cell(comm, t, row, col, &text));
  if (text.find_first_not_of(" \t") == std::string::npos) PetscFunctionReturn(0);
  PetscCall(RealCell(comm, t, row, col, x));
  PetscCheck(std::isfinite(*x) && *x >= 0, comm, PETSC_ERR_USER_INPUT, "%s line %d, column '%s': %g must be a finite number >= 0 (%s)", t.path.c_str(), t.lines[row], col.c_str(), (double)*x, what);
  *given = true;
  PetscFunctionReturn(0);
}

// The rows of the fastener table, and its joint types with the first joint of each, in the order of
// first use.
PetscErrorCode FastenerRows(MPI_Comm comm, const Table &joints, std::vector<FastenerRow> *rows, std::vector<std::pair<std::string, FirstJoint>> *firsts)
{
  std::map<std::string, size_t> seen;
  PetscFunctionBeginUser;
  for (size_t r = 0; r < joints.rows.size(); ++r) {
    std::string type;
    PetscCall(Cell(comm, joints, r, "type", &type));
    PetscCheck(!type.empty() && type.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789") == std::string::npos, comm, PETSC_ERR_USER_INPUT, "%s line %d: joint type '%s' must be lower-case letters and digits (it names the options -joint_<type>_*)", joints.path.c_str(), joints.lines[r], type.c_str());
    FastenerRow f{};
    PetscCall(IdCell(comm, joints, r, "id", &f.id));
    PetscCall(IdCell(comm, joints, r, "patch_a", &f.pa));
    PetscCall(IdCell(comm, joints, r, "patch_b", &f.pb));
    const char *nc[] = {"nx", "ny", "nz"}, *tc[] = {"t1x", "t1y", "t1z"}, *xc[] = {"x", "y", "z"};
    f.positioned = HasColumn(joints, "x");
    for (int k = 0; k < 3; ++k) {
      PetscCall(RealCell(comm, joints, r, nc[k], &f.n[k]));
      PetscCall(RealCell(comm, joints, r, tc[k], &f.t[k]));
    }
    for (int k = 0; k < 3 && f.positioned; ++k) PetscCall(RealCell(comm, joints, r, xc[k], &f.pos[k]));
    if (HasColumn(joints, "footprint")) PetscCall(Cell(comm, joints, r, "footprint", &f.footprint));
    PetscCheck(f.footprint.empty() || f.positioned, comm, PETSC_ERR_USER_INPUT, "%s line %d: a joint with a footprint set needs its position (columns x, y, z): the set's nodes follow the joint node there", joints.path.c_str(), joints.lines[r]);
    f.line = joints.lines[r];
    PetscCall(OptionalCell(comm, joints, r, "gap", "mm: this joint's clearance, in place of its type's gap", &f.gap, &f.has_gap));
    PetscCall(OptionalCell(comm, joints, r, "pretension", "N: this joint's clamp force, in place of its type's pretension", &f.pretension, &f.has_pretension));
    auto it = seen.find(type);
    if (it == seen.end()) {
      it = seen.emplace(type, firsts->size()).first;
      firsts->push_back({type, FirstJoint{f.id, f.pa, f.pb, {f.n[0], f.n[1], f.n[2]}, {f.t[0], f.t[1], f.t[2]}, {f.pos[0], f.pos[1], f.pos[2]}}});
    }
    f.type = it->second;
    rows->push_back(f);
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode ReadFileCollective(MPI_Comm comm, const std::string &path, const char what[], std::string *text, bool broadcast)
{
  PetscMPIInt rank;
  long long   len = -1; // -1: cannot be read; -2: larger than limits::kMaxInputBytes; -3: no memory
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) { // what fails here is told to every rank through len, so that none waits alone
    try {
      std::ifstream in(path, std::ios::binary);
      if (in) {
        // Read in pieces and stop past the limit: a huge file, or a device that never ends, is
        // refused before it is held in memory.
        std::string buf(1 << 20, '\0');
        text->clear();
        while (in && (long long)text->size() <= limits::kMaxInputBytes) {
          in.read(&buf[0], (std::streamsize)buf.size());
          text->append(buf, 0, (size_t)in.gcount());
        }
        len = in.bad() ? -1 : (long long)text->size() > limits::kMaxInputBytes ? -2 : (long long)text->size();
      }
    } catch (const std::bad_alloc &) {
      len = -3;
    } catch (const std::exception &) {
      len = -1;
    }
  }
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_LONG_LONG, 0, comm));
  PetscCheck(len != -3, comm, PETSC_ERR_MEM, "Out of memory while reading the %s file '%s'", what, path.c_str());
  PetscCheck(len != -2, comm, PETSC_ERR_USER_INPUT, "The %s file '%s' is larger than %lld bytes (docs/scenes.md, \"Limits\")", what, path.c_str(), (long long)limits::kMaxInputBytes);
  PetscCheck(len >= 0, comm, PETSC_ERR_FILE_OPEN, "Cannot read the %s file '%s'", what, path.c_str());
  if (!broadcast) PetscFunctionReturn(0); // the other ranks' text stays empty
  int held = 1; // every rank can hold the text: agreed before the broadcast, so that none waits in it
  try {
    text->resize((size_t)len);
  } catch (const std::bad_alloc &) {
    held = 0;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &held, 1, MPI_INT, MPI_MIN, comm));
  PetscCheck(held, comm, PETSC_ERR_MEM, "Out of memory while reading the %s file '%s'", what, path.c_str());
  PetscCallMPI(MPI_Bcast(text->data(), (PetscMPIInt)len, MPI_CHAR, 0, comm));
  PetscFunctionReturn(0);
}

static PetscErrorCode SceneInsertOptionsFileImpl(MPI_Comm comm, const char file[], Scene *scene)
{
  PetscOptions opts;
  PetscInt     n;
  char       **names, **values;
  std::string  text;
  PetscFunctionBeginUser;
  PetscCall(ReadFileCollective(comm, file, "scene", &text)); // a clear message for a missing file
  scene->file            = file;
  const size_t slash     = scene->file.find_last_of('/');
  scene->dir             = slash == std::string::npos ? "." : scene->file.substr(0, slash);
  std::string base       = slash == std::string::npos ? scene->file : scene->file.substr(slash + 1);
  scene->name            = base.substr(0, base.find('.'));
  // Syntax and shape first, with lines and columns (PETSc's reader names neither file nor line).
  std::vector<YamlKey> keys;
  PetscCall(Input(comm, "reading the scene", [&] { keys = ScanSceneYaml(file, text); }));
  PetscCall(PetscOptionsCreate(&opts));
  {
    ErrorLog       log;
    PetscErrorCode ierr;
    PetscCall(PetscPushErrorHandler(CaptureErrorHandler, &log));
    ierr = PetscOptionsInsertStringYAML(opts, text.c_str());
    PetscCall(PetscPopErrorHandler());
    if (ierr) PetscCall(PetscOptionsDestroy(&opts));
    PetscCheck(!ierr, comm, PETSC_ERR_USER_INPUT, "Scene file %s: %s", file, ErrorText(log).c_str());
  }
  PetscCall(PetscOptionsLeftGet(opts, &n, &names, &values)); // all of them: none was used yet
  {
    // A misspelled section (lod: for load:) would otherwise set options that nothing reads.
    std::vector<std::string> set(names, names + n);
    std::string              bad;
    PetscCall(Input(comm, "reading the scene", [&] { bad = CheckSceneSections(file, keys, set); }));
    if (!bad.empty()) {
      PetscCall(PetscOptionsLeftRestore(opts, &n, &names, &values));
      PetscCall(PetscOptionsDestroy(&opts));
    }
    PetscCheck(bad.empty(), comm, PETSC_ERR_USER_INPUT, "%s", bad.c_str());
  }
  for (PetscInt i = 0; i < n; ++i) {
    const std::string name = std::string("-") + names[i];
    PetscBool         given;
    PetscCall(PetscOptionsHasName(nullptr, nullptr, name.c_str(), &given));
    if (given) continue; // the command line overrides the scene
    PetscCall(PetscOptionsSetValue(nullptr, name.c_str(), values[i]));
    scene->from_file.insert(names[i]);
  }
  PetscCall(PetscOptionsLeftRestore(opts, &n, &names, &values));
  PetscCall(PetscOptionsDestroy(&opts));
  PetscFunctionReturn(0);
}

static PetscErrorCode SceneDescribeAssemblyImpl(MPI_Comm comm, Scene *scene, BoltnetAssembly a)
{
  char        name[PETSC_MAX_PATH_LEN], fp[PETSC_MAX_PATH_LEN] = "", fj[PETSC_MAX_PATH_LEN] = "", fb[PETSC_MAX_PATH_LEN] = "";
  std::string text;
  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(name, scene->name.c_str(), sizeof(name)));
  PetscOptionsBegin(comm, nullptr, "boltnet scene", "boltnet");
  PetscCall(PetscOptionsString("-scene_name", "Scene name (results go to results/<name>/ by default)", "", name, name, sizeof(name), nullptr));
  PetscCall(PetscOptionsString("-scene_patches", "CSV table of patches: id,kind,x,y,z[,lx,ly,nx,ny,elements,mesh,part,material] (kind rigid, plate or gmsh; elements quad, tri or mixed)", "", fp, fp, sizeof(fp), nullptr));
  PetscCall(PetscOptionsString("-scene_joints", "CSV fastener table: id,patch_a,patch_b,type,nx,ny,nz,t1x,t1y,t1z[,x,y,z,footprint,gap,pretension] (n bolt axis, t1 first in-plane direction, x position; footprint: a node set that follows the joint rigidly instead of -coupling_radius's; gap, pretension: this joint's, in place of its type's)", "", fj, fj, sizeof(fj), nullptr));
  PetscCall(PetscOptionsString("-scene_bcs", "CSV boundary conditions: patch,dof,kind,value[,set,load] (dof ux..rz or all; kind fixed, displacement, force or pressure; value per unit load factor, mm, N or MPa; set: a shell patch's node set (a pressure loads the elements within it); load: the load it belongs to, for -load_cases)", "", fb, fb, sizeof(fb), nullptr));
  PetscOptionsEnd();
  scene->name = name;
  scene->bc_loads.clear();
  PetscCheck(fp[0] && fj[0] && fb[0], comm, PETSC_ERR_USER_INPUT, "The scene must name its tables: -scene_patches, -scene_joints and -scene_bcs (missing: %s%s%s)", fp[0] ? "" : "-scene_patches ", fj[0] ? "" : "-scene_joints ", fb[0] ? "" : "-scene_bcs");

  Table patches, joints, bcs;
  std::string path = Resolve(*scene, "scene_patches", fp);
  PetscCall(ReadFileCollective(comm, path, "patch table (-scene_patches)", &text));
  PetscCall(ParseTable(comm, path, text, {"id", "kind", "x", "y", "z"}, &patches));
  // The fastener table is read and parsed by rank 0 alone, which holds the model's joints until the
  // layout sends each rank those of the parts it holds (patch/share.cpp); the other ranks learn its
  // joint types only (below). Its errors are raised on every rank (Collective).
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  path = Resolve(*scene, "scene_joints", fj);
  PetscCall(ReadFileCollective(comm, path, "fastener table (-scene_joints)", &text, false));
  PetscCall(Collective(comm, "reading the scene", [&] { return rank == 0 ? ParseTable(comm, path, text, {"id", "patch_a", "patch_b", "type", "nx", "ny", "nz", "t1x", "t1y", "t1z"}, &joints) : PetscErrorCode(0); }));
  std::string().swap(text);
  path = Resolve(*scene, "scene_bcs", fb);
  PetscCall(ReadFileCollective(comm, path, "boundary condition table (-scene_bcs)", &text));
  PetscCall(ParseTable(comm, path, text, {"patch", "dof", "kind", "value"}, &bcs));

  std::int64_t scene_nodes = 0; // shell nodes of the patches read so far
  for (size_t r = 0; r < patches.rows.size(); ++r) {
    PetscInt    id;
    PetscReal   x[3];
    std::string kind;
    PetscCall(IdCell(comm, patches, r, "id", &id));
    PetscCall(Cell(comm, patches, r, "kind", &kind));
    PetscCheck(kind == "rigid" || kind == "plate" || kind == "gmsh", comm, PETSC_ERR_USER_INPUT, "%s line %d: patch kind '%s' is not known (rigid, plate, gmsh)", patches.path.c_str(), patches.lines[r], kind.c_str());
    PetscCall(RealCell(comm, patches, r, "x", &x[0]));
    PetscCall(RealCell(comm, patches, r, "y", &x[1]));
    PetscCall(RealCell(comm, patches, r, "z", &x[2]));
    if (kind == "rigid") {
      PetscCall(BoltnetAssemblyAddRigidPatch(a, id, x));
      continue;
    }
    // Shell patches: a generated plate (corner x, y, z; lx, ly; nx by ny elements) or a Gmsh part.
    // The mesh is read only by the rank that lays the part out (patch/layout.hpp): here the row is
    // checked, and read() keeps what it needs to make the mesh and to name this line in its errors.
    std::string          matname;
    shell::ShellMaterial mat;
    PetscCall(Cell(comm, patches, r, "material", &matname));
    PetscCheck(!matname.empty(), comm, PETSC_ERR_USER_INPUT, "%s line %d: a %s patch needs a material", patches.path.c_str(), patches.lines[r], kind.c_str());
    PetscCall(MaterialFromOptions(comm, matname, &mat));
    if (kind == "plate") {
      PetscReal lx, ly;
      PetscInt  nx, ny;
      PetscCall(RealCell(comm, patches, r, "lx", &lx));
      PetscCall(RealCell(comm, patches, r, "ly", &ly));
      // Element counts are checked before the mesh is allocated (io/limits.hpp).
      PetscCall(IntCell(comm, patches, r, "nx", 1, limits::kMaxPlateElements, &nx));
      PetscCall(IntCell(comm, patches, r, "ny", 1, limits::kMaxPlateElements, &ny));
      PetscCheck(lx > 0 && ly > 0, comm, PETSC_ERR_USER_INPUT, "%s line %d: a plate needs lx, ly > 0", patches.path.c_str(), patches.lines[r]);
      PetscCheck((std::int64_t)nx * ny <= limits::kMaxPlateElements, comm, PETSC_ERR_USER_INPUT, "%s line %d: a plate of %" PetscInt_FMT " x %" PetscInt_FMT " elements is larger than the limit of %lld elements (docs/scenes.md, \"Limits\")", patches.path.c_str(), patches.lines[r], nx, ny, (long long)limits::kMaxPlateElements);
      scene_nodes += (std::int64_t)(nx + 1) * (ny + 1);
      PetscCheck(scene_nodes <= limits::kMaxSceneNodes, comm, PETSC_ERR_USER_INPUT, "%s line %d: the shell patches so far have %lld nodes, more than the limit of %lld (docs/scenes.md, \"Limits\")", patches.path.c_str(), patches.lines[r], (long long)scene_nodes, (long long)limits::kMaxSceneNodes);
      // Optional column elements: quad (default), tri (each cell split in two) or mixed.
      std::string   elements;
      PlateElements pe = PlateElements::Quads;
      if (HasColumn(patches, "elements")) PetscCall(Cell(comm, patches, r, "elements", &elements));
      PetscCheck(elements.empty() || elements == "quad" || elements == "tri" || elements == "mixed", comm, PETSC_ERR_USER_INPUT, "%s line %d, column 'elements': '%s' is not quad, tri or mixed", patches.path.c_str(), patches.lines[r], elements.c_str());
      if (elements == "tri") pe = PlateElements::Triangles;
      if (elements == "mixed") pe = PlateElements::Mixed;
      const std::array<double, 3> at = {x[0], x[1], x[2]};
      PetscCall(AssemblyAddShellRead(a, id, (std::int64_t)(nx + 1) * (ny + 1), [at, lx, ly, nx, ny, pe](ShellMesh *mesh) -> PetscErrorCode {
        *mesh = RectanglePlate(at[0], at[1], lx, ly, (int)nx, (int)ny, at[2], pe);
        return PetscErrorCode(0);
      }, mat));
    } else {
      std::string file, part;
      PetscCall(Cell(comm, patches, r, "mesh", &file));
      PetscCall(Cell(comm, patches, r, "part", &part));
      // A relative mesh path is relative to the patches table that names it.
      const std::string tdir = std::filesystem::path(patches.path).parent_path().string();
      if (!file.empty() && file[0] != '/' && !tdir.empty()) file = tdir + "/" + file;
      std::error_code      ec;
      const std::uintmax_t bytes = std::filesystem::file_size(file, ec);
      PetscCheck(!ec && std::ifstream(file).good(), comm, PETSC_ERR_USER_INPUT, "%s line %d: Cannot read the mesh file '%s'", patches.path.c_str(), patches.lines[r], file.c_str());
      const std::array<double, 3> at    = {x[0], x[1], x[2]};
      const std::string           where = patches.path + " line " + std::to_string(patches.lines[r]);
      // Weighed by the nodes its file declares (all its parts'), or by its bytes if it declares none
      // or is larger than a mesh file may be (its reader then refuses it: docs/scenes.md, "Limits").
      const long long declared = (long long)bytes <= limits::kMaxInputBytes ? GmshNodeCount(file) : -1;
      PetscCall(AssemblyAddShellRead(a, id, declared >= 0 ? (std::int64_t)declared : (std::int64_t)(bytes / 100), [at, file, part, where](ShellMesh *mesh) -> PetscErrorCode {
        std::map<std::string, ShellMesh> parts;
        std::string                      why;
        PetscFunctionBeginUser;
        try {
          parts = ReadGmsh(file);
        } catch (const std::exception &e) {
          why = e.what();
        }
        PetscCheck(why.empty(), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: %s", where.c_str(), why.c_str());
        PetscCheck(parts.count(part), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: mesh '%s' has no part (physical surface) '%s'", where.c_str(), file.c_str(), part.c_str());
        *mesh = std::move(parts[part]);
        PetscCheck((std::int64_t)mesh->x.size() <= limits::kMaxSceneNodes, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: part '%s' has %zu nodes, more than the limit of %lld (docs/scenes.md, \"Limits\")", where.c_str(), part.c_str(), mesh->x.size(), (long long)limits::kMaxSceneNodes);
        for (auto &xn : mesh->x)
          for (int k = 0; k < 3; ++k) xn[k] += at[k]; // x, y, z: where the part is placed
        PetscFunctionReturn(0);
      }, mat));
    }
  }
  // The fastener table's rows, on rank 0; every joint type with its first joint, in the order of
  // first use, on every rank: each rank reads the type's options (-options_left counts them on every
  // rank), and identifying a type from its geometry may mesh a coupon like the patches around it.
  // Every row is checked before any type's options are: a table with a bad cell and a bad type
  // option reports the cell.
  std::vector<FastenerRow>                        rows;
  std::vector<std::pair<std::string, FirstJoint>> firsts;
  PetscCall(Collective(comm, "reading the scene", [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (rank == 0) PetscCall(FastenerRows(comm, joints, &rows, &firsts));
    PetscFunctionReturn(0);
  }));
  std::vector<BoltnetJointParams> types;
  PetscCall(SceneJointTypes(comm, a, &firsts, &types, scene));
  PetscCall(Collective(comm, "reading the scene", [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    for (const FastenerRow &f : rows) {
      // A joint's own gap and pretension in place of its type's (docs/scenes.md, "Per-joint
      // parameters"); the law's checks (an offset inside the gap) then see the joint's values.
      BoltnetJointParams p = types[f.type];
      const char        *type = firsts[f.type].first.c_str();
      PetscCheck(!f.has_gap || p.law != BOLTNET_LAW_SPRING, comm, PETSC_ERR_USER_INPUT, "%s line %d, column 'gap': joint %" PetscInt_FMT "'s type '%s' is a linear spring, which has no gap", joints.path.c_str(), f.line, f.id, type);
      PetscCheck(!f.has_pretension || p.law == BOLTNET_LAW_FRICTION, comm, PETSC_ERR_USER_INPUT, "%s line %d, column 'pretension': joint %" PetscInt_FMT "'s type '%s' is not of the frictional law, the only one with a pretension", joints.path.c_str(), f.line, f.id, type);
      if (f.has_gap) p.gap = f.gap;
      if (f.has_pretension) p.pretension = f.pretension;
      PetscCall(BoltnetAssemblyAddJointAt(a, f.id, f.pa, f.pb, &p, f.n, f.t, f.positioned ? f.pos : nullptr));
      if (!f.footprint.empty()) PetscCall(AssemblySetJointFootprint(a, f.id, f.footprint.c_str()));
    }
    PetscFunctionReturn(0);
  }));
  if (rank == 0) PetscCall(PetscInfo(nullptr, "Read the fastener table's %zu rows on this rank\n", rows.size()));
  std::vector<FastenerRow>().swap(rows);
  const std::map<std::string, PetscInt> dofs = {{"ux", 0}, {"uy", 1}, {"uz", 2}, {"rx", 3}, {"ry", 4}, {"rz", 5}, {"all", -1}};
  const std::map<std::string, BoltnetBCKind> kinds = {{"fixed", BOLTNET_BC_FIXED}, {"displacement", BOLTNET_BC_DISPLACEMENT}, {"force", BOLTNET_BC_FORCE}, {"pressure", BOLTNET_BC_PRESSURE}};
  for (size_t r = 0; r < bcs.rows.size(); ++r) {
    PetscInt    patch;
    PetscReal   value;
    std::string dof, kind;
    PetscCall(IdCell(comm, bcs, r, "patch", &patch));
    PetscCall(Cell(comm, bcs, r, "dof", &dof));
    PetscCall(Cell(comm, bcs, r, "kind", &kind));
    PetscCall(RealCell(comm, bcs, r, "value", &value));
    PetscCheck(dofs.count(dof), comm, PETSC_ERR_USER_INPUT, "%s line %d: dof '%s' is not one of ux uy uz rx ry rz all", bcs.path.c_str(), bcs.lines[r], dof.c_str());
    PetscCheck(kinds.count(kind), comm, PETSC_ERR_USER_INPUT, "%s line %d: kind '%s' is not one of fixed displacement force pressure", bcs.path.c_str(), bcs.lines[r], kind.c_str());
    PetscCheck(!(kind == "force" && dof == "all"), comm, PETSC_ERR_USER_INPUT, "%s line %d: a force needs one dof, not 'all'", bcs.path.c_str(), bcs.lines[r]);
    PetscCheck(!(kind == "pressure" && dof != "all"), comm, PETSC_ERR_USER_INPUT, "%s line %d: a pressure acts along the elements' normals: its dof is 'all', not '%s'", bcs.path.c_str(), bcs.lines[r], dof.c_str());
    std::string set, load;
    if (HasColumn(bcs, "set")) PetscCall(Cell(comm, bcs, r, "set", &set));
    if (HasColumn(bcs, "load")) PetscCall(Cell(comm, bcs, r, "load", &load));
    PetscCheck(load.find_first_not_of(kLoadNameChars) == std::string::npos, comm, PETSC_ERR_USER_INPUT, "%s line %d, column 'load': '%s' is not a load name (lower-case letters, digits, '_' and '-'; empty: a condition of every load case)", bcs.path.c_str(), bcs.lines[r], load.c_str());
    PetscCall(BoltnetAssemblyAddBCOnSet(a, patch, set.c_str(), dofs.at(dof), kinds.at(kind), value));
    scene->bc_loads.push_back(load);
  }
  scene->bcs_path = bcs.path;
  PetscFunctionReturn(0);
}

// The public entry points: a C++ exception (std::bad_alloc from a table far larger than memory)
// becomes a PETSc error rather than ending the run (core/guard.hpp).
PetscErrorCode SceneInsertOptionsFile(MPI_Comm comm, const char file[], Scene *scene)
{
  return Guard(comm, [&] { return SceneInsertOptionsFileImpl(comm, file, scene); });
}

PetscErrorCode SceneDescribeAssembly(MPI_Comm comm, Scene *scene, BoltnetAssembly a)
{
  return Guard(comm, [&] { return SceneDescribeAssemblyImpl(comm, scene, a); });
}

PetscErrorCode UnusedOptionsAsError(MPI_Comm comm, const char program[], PetscBool before_solve, int *exitcode)
{
  PetscInt    n;
  char      **names, **values;
  std::string left;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsLeftGet(nullptr, &n, &names, &values));
  for (PetscInt i = 0; i < n; ++i)
    if (!before_solve || !ReadDuringSolve(names[i])) left += std::string(" -") + names[i];
  PetscCall(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  if (!left.empty()) {
    PetscCall(PetscPrintf(comm, "%s: ERROR: option(s) given but never used:%s%s\n", program, left.c_str(), before_solve ? " (-options_left; checked before the solve, nothing was written)" : ""));
    *exitcode = 2;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode SceneCheckUnusedOptions(MPI_Comm comm)
{
  PetscInt    n;
  char      **names, **values;
  std::string bad;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsLeftGet(nullptr, &n, &names, &values));
  for (PetscInt i = 0; i < n; ++i) {
    const std::string s = names[i];
    if (s.rfind("scene_", 0) == 0 || s.rfind("nastran_", 0) == 0 || s.rfind("joint_", 0) == 0 || s.rfind("load_", 0) == 0 || s.rfind("material_", 0) == 0 || s.rfind("coupling_", 0) == 0 || s == "output_dir") bad += " -" + s;
  }
  PetscCall(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  PetscCheck(bad.empty(), comm, PETSC_ERR_USER_INPUT, "Unknown boltnet option(s):%s (misspelled, or a joint type that no joint of the fastener table uses?); -help lists the options", bad.c_str());
  PetscFunctionReturn(0);
}

} // namespace boltnet

namespace boltnet {

std::vector<std::pair<std::string, std::string>> OptionsSplit(const std::string &all)
{
  std::vector<std::pair<std::string, std::string>> o;
  std::istringstream                               in(all);
  std::string                                      tok;
  while (in >> tok) {
    // A token starting with '-' and a letter is a name; anything else is the value of the name before.
    if (tok.size() > 1 && tok[0] == '-' && std::isalpha((unsigned char)tok[1])) o.emplace_back(tok.substr(1), "");
    else if (!o.empty()) o.back().second += (o.back().second.empty() ? "" : " ") + tok;
  }
  return o;
}

PetscErrorCode SceneCheckOptionValues(MPI_Comm comm)
{
  // boltnet's integer options. PETSc reads an integer option with strtol and casts it to a 32-bit
  // PetscInt, so 99999999999 would silently become 1215752191: checked here, as 64-bit, first.
  const char *const ints[] = {"load_steps", "load_max_cuts", "patch_max_nodes", "snes_linesearch_boltnet_watchdog", "snes_linesearch_boltnet_bisections"};
  char             *all    = nullptr;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(nullptr, &all)); // does not mark anything used (-options_left)
  std::string bad;
  PetscCall(Guard(comm, [&] {
    for (const auto &[name, value] : OptionsSplit(all ? all : ""))
      for (const char *i : ints) {
        std::int64_t v;
        if (name != i) continue;
        if (!ParseInt64(value, &v)) bad = "-" + name + " " + value + ": not a whole number";
        else if (v < -limits::kMaxId || v > limits::kMaxId) bad = "-" + name + " " + value + ": out of range (at most " + std::to_string(limits::kMaxId) + ")";
      }
    return PetscErrorCode(0);
  }));
  PetscCall(PetscFree(all));
  PetscCheck(bad.empty(), comm, PETSC_ERR_USER_INPUT, "%s", bad.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode OptionsWithValue(const std::string &value, std::string *names)
{
  char *all = nullptr;
  PetscFunctionBeginUser;
  names->clear();
  PetscCall(PetscOptionsGetAll(nullptr, &all));
  PetscCall(Guard(PETSC_COMM_SELF, [&] {
    for (const auto &[name, v] : OptionsSplit(all ? all : ""))
      if (v == value) *names += (names->empty() ? "-" : ", -") + name;
    return PetscErrorCode(0);
  }));
  PetscCall(PetscFree(all));
  PetscFunctionReturn(0);
}

} // namespace boltnet
