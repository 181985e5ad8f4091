// What a checkpoint belongs to (io/checkpoint.hpp): the scene, the options that can change results,
// hashes of the model and of the network's layout.
#include "core/guard.hpp"
#include "io/checkpoint.hpp"
#include "core/hash.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <cstring>
#include <sstream>

namespace boltnet {
namespace {

// Options that only choose what is printed, written or checked, never a result: they may differ
// between a run and its restart. Every other option, PETSc's included, must be the same; an option
// missing here only makes a restart refuse, naming it.
bool PrintOnly(const std::string &name)
{
  static const char *const exact[] = {"scene", "output_dir", "output_fields", "output_stresses_cache", "restart", "checkpoint_every", "checkpoint_file", "options_left", "help", "version", "joint_monitor", "history", "fp_trap", "no_signal_handler", "check_pointer_intensity", "checkstack", "objects_dump", "skip_petscrc", "error_output_stdout", "on_error_abort", "on_error_attach_debugger", "start_in_debugger", "stop_for_debugger", "debugger_ranks"};
  for (const char *e : exact)
    if (name == e) return true;
  static const char *const prefixes[] = {"malloc", "log", "info", "memory_", "options_", "viewer_", "draw"};
  for (const char *p : prefixes)
    if (name.rfind(p, 0) == 0) return true;
  // SNES, KSP and line search monitors and views (-snes_monitor, -ksp_converged_reason, -snes_view, ...).
  for (const char *s : {"monitor", "converged_reason", "_view"})
    if (name.find(s) != std::string::npos) return true;
  return false;
}

// The numbers of a value ("6000,-6000,0", "1e4"), or false when it is not a list of numbers.
bool Numbers(const std::string &v, std::vector<double> *x)
{
  std::string s = v;
  std::replace(s.begin(), s.end(), ',', ' ');
  std::istringstream in(s);
  std::string        tok;
  while (in >> tok) {
    char  *end;
    double d = std::strtod(tok.c_str(), &end);
    if (*end) return false;
    x->push_back(d);
  }
  return !x->empty();
}

bool SameValue(const std::string &a, const std::string &b)
{
  std::vector<double> x, y;
  if (Numbers(a, &x) && Numbers(b, &y)) return x == y;
  return a == b;
}

std::map<std::string, std::string> ParseLines(const std::string &text)
{
  std::map<std::string, std::string> m;
  std::istringstream                 in(text);
  std::string                        line;
  while (std::getline(in, line)) {
    const size_t sp = line.find(' ');
    m[line.substr(0, sp)] = sp == std::string::npos ? "" : line.substr(sp + 1);
  }
  return m;
}

void AddParams(Hasher &h, const Params &p)
{
  h.Add(static_cast<int>(p.law));
  for (double v : {p.kn, p.kt, p.kr, p.kc, p.kg, p.gap, p.mu, p.nf, p.pretension, p.clamp_coupling, p.offset[0], p.offset[1]}) h.Add(v);
  if (p.full) { // only then: the identities of runs without a full stiffness stay as they were
    h.Add(p.full);
    for (double v : p.K) h.Add(v);
  }
}

void AddMesh(Hasher &h, const ShellMesh &m)
{
  h.Add(m.x);
  h.Add(m.elems); // quadrilaterals and triangles (a triangle's fourth node is -1)
  for (const auto &[name, nodes] : m.node_sets) {
    h.Add(name);
    h.Add(nodes);
  }
}

} // namespace

std::vector<std::pair<std::string, std::string>> ResultOptions(const std::string &all)
{
  std::vector<std::pair<std::string, std::string>> o;
  for (auto &nv : OptionsSplit(all))
    if (!PrintOnly(nv.first)) o.push_back(std::move(nv));
  std::sort(o.begin(), o.end());
  return o;
}

std::string OptionsDifference(const std::string &now, const std::string &saved)
{
  const auto         a = ParseLines(now), b = ParseLines(saved);
  std::ostringstream d;
  auto               note = [&](const std::string &name, const std::string &mine, const std::string &theirs) {
    d << (d.tellp() > 0 ? ", " : "") << "-" << name << " " << mine << " (checkpoint: " << theirs << ")";
  };
  for (const auto &[name, value] : a) {
    const auto it = b.find(name);
    if (it == b.end()) note(name, value.empty() ? "given" : value, "not given");
    else if (!SameValue(value, it->second)) note(name, value, it->second);
  }
  for (const auto &[name, value] : b)
    if (!a.count(name)) note(name, "not given", value.empty() ? "given" : value);
  return d.str();
}

PetscErrorCode CheckpointIdentify(BoltnetAssembly a, const std::string &scene, CheckpointIdentity *id)
{
  char *all = nullptr;
  PetscFunctionBeginUser;
  PetscCheck(!a->net.dm, a->comm, PETSC_ERR_ORDER, "CheckpointIdentify() must come before BoltnetAssemblySetUp()");
  PetscCall(PetscOptionsGetAll(nullptr, &all)); // marks nothing used (-options_left)
  PetscCall(Guard(a->comm, [&] {
    id->scene = scene;
    std::ostringstream o;
    for (const auto &[name, value] : ResultOptions(all ? all : "")) o << name << " " << value << "\n";
    id->options = o.str();
    const Model &m = a->model;
    Hasher       parts, joints, bcs;
    for (size_t i = 0; i < m.parts.size(); ++i) {
      parts.Add(m.parts[i].id);
      parts.Add(m.parts[i].kind);
      parts.Add(m.parts[i].x);
      const auto sh = m.shells.find((PetscInt)i);
      if (sh == m.shells.end()) continue;
      const ShellPart &s = sh->second;
      AddMesh(parts, s.mesh);
      for (const auto *M : {&s.material.A, &s.material.B, &s.material.D}) parts.Add(*M);
      parts.Add(s.material.H);
      parts.Add(s.material.thickness);
      parts.Add(s.material.direction);
      parts.Add(s.drill);
    }
    for (const JointDesc &j : m.joints) {
      joints.Add(j.id);
      joints.Add(j.part_a);
      joints.Add(j.part_b);
      joints.Add(j.x);
      joints.Add(j.R);
      AddParams(joints, j.params);
      joints.Add(j.positioned);
      joints.Add(j.lever);
      if (j.lever) joints.Add(j.at_a), joints.Add(j.at_b);
      if (j.footprint[0]) joints.Add(std::string(j.footprint.data()));
    }
    for (const BCDesc &b : m.bcs) {
      bcs.Add(b.patch);
      bcs.Add(b.set);
      bcs.Add(b.dof);
      bcs.Add(b.kind);
      bcs.Add(b.value);
    }
    id->parts  = parts.Hex();
    id->joints = joints.Hex();
    id->bcs    = bcs.Hex();
    return PetscErrorCode(0);
  }));
  // The joints are rank 0's (a scene's fastener table is read there alone: io/scene.cpp), and so
  // are the meshes of parts given to rank 0 alone (ShellPart::on_rank0): rank 0's hashes count.
  for (std::string *h : {&id->joints, &id->parts}) {
    char hex[64] = {0};
    std::strncpy(hex, h->c_str(), sizeof hex - 1);
    PetscCallMPI(MPI_Bcast(hex, (PetscMPIInt)sizeof hex, MPI_CHAR, 0, a->comm));
    *h = hex;
  }
  PetscCall(PetscFree(all));
  PetscFunctionReturn(0);
}

} // namespace boltnet
