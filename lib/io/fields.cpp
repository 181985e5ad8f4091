// Field output (docs/output.md): fields.h5 written in parallel through PETSc's HDF5 viewer, each
// rank its own rows of every dataset (network/fields.hpp puts them in the file's numbering), and
// fields.xdmf (shells) and joints.xdmf (joint lines), XDMF 3, written by rank 0. HDF5 itself is
// called once, to silence its error printing.
#include "io/io.hpp"
#include "io/xdmf.hpp"
#include "network/gather.hpp"

#include <petscviewerhdf5.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <sstream>

namespace boltnet {
namespace {

const char *kH5 = "fields.h5";

PetscErrorCode View(Vec v, const char name[], PetscViewer viewer)
{
  PetscFunctionBeginUser;
  PetscCall(PetscObjectSetName((PetscObject)v, name));
  PetscCall(VecView(v, viewer));
  PetscFunctionReturn(0);
}

// bs values per owned item of s, written as dataset `name` in natural order.
PetscErrorCode WriteReals(MPI_Comm comm, PetscViewer viewer, FieldSpace &s, PetscInt bs, const std::vector<double> &owned, const char name[])
{
  Vec v;
  PetscFunctionBeginUser;
  PetscCall(FieldSpaceNatural(comm, s, bs, owned, &v));
  PetscCall(View(v, name, viewer));
  PetscFunctionReturn(0);
}

// The same as rows of `view_bs` values (a joint's two endpoints: bs 6 viewed as two rows of 3).
PetscErrorCode WriteRealsAs(MPI_Comm comm, PetscViewer viewer, FieldSpace &s, PetscInt bs, PetscInt view_bs, const std::vector<double> &owned, const char name[])
{
  Vec                v, w;
  const PetscScalar *p;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(FieldSpaceNatural(comm, s, bs, owned, &v));
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetArrayRead(v, &p));
  PetscCall(VecCreateMPIWithArray(comm, view_bs, n, PETSC_DETERMINE, p, &w));
  PetscCall(View(w, name, viewer));
  PetscCall(VecDestroy(&w));
  PetscCall(VecRestoreArrayRead(v, &p));
  PetscFunctionReturn(0);
}

// Integers (PetscInt) in natural order: moved as reals (exact below 2^53), written by ISView.
PetscErrorCode WriteInts(MPI_Comm comm, PetscViewer viewer, FieldSpace &s, PetscInt bs, const std::vector<PetscInt> &owned, const char name[])
{
  Vec                v;
  IS                 is;
  const PetscScalar *p;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(FieldSpaceNatural(comm, s, bs, std::vector<double>(owned.begin(), owned.end()), &v));
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetArrayRead(v, &p));
  std::vector<PetscInt> ints(p, p + n);
  PetscCall(VecRestoreArrayRead(v, &p));
  PetscCall(ISCreateGeneral(comm, n, ints.data(), PETSC_COPY_VALUES, &is));
  PetscCall(ISSetBlockSize(is, bs));
  PetscCall(PetscObjectSetName((PetscObject)is, name));
  PetscCall(ISView(is, viewer));
  PetscCall(ISDestroy(&is));
  PetscFunctionReturn(0);
}

std::string StepGroup(PetscInt step)
{
  char s[32];
  std::snprintf(s, sizeof(s), "/steps/%06d", (int)step);
  return s;
}

// Geometry, topology and the numbering: written once, with the first step.
PetscErrorCode WriteMesh(BoltnetAssembly a, FieldsFile *ff, const StepFields &f)
{
  MPI_Comm    comm = a->comm;
  FieldMap   &m    = ff->map;
  PetscViewer v    = ff->viewer;
  PetscFunctionBeginUser;
  if (m.nodes.nglobal > 0) {
    std::vector<double>   x, normal, eaxis, maxis;
    std::vector<PetscInt> part, pnode, cells, type, epart, elem;
    for (size_t i = 0; i < m.node_src.size(); ++i) {
      const auto &[o, l]   = m.node_src[i];
      const ShellPatch &sp = a->layout.shells.at(a->patches.owned[o].index);
      x.insert(x.end(), sp.mesh.x[l].begin(), sp.mesh.x[l].end());
      part.push_back(sp.id);
      pnode.push_back(m.nodes.natural[i] - m.node_off.at(sp.id));
    }
    for (const FieldElement &e : m.elements) {
      for (int k = 0; k < 4; ++k) cells.push_back(k < e.nn ? e.node[k] : -1);
      type.push_back(e.type);
      epart.push_back(e.part);
      elem.push_back(e.elem);
      const shell::ElementFrame fr = shell::MakeElementFrame(e.X);
      shell::SectionResults     s{};
      s.e1 = fr.e1, s.e2 = fr.e2;
      const double phi = shell::MaterialAngle(s, FieldElementMaterial(a, e));
      for (int c = 0; c < 3; ++c) {
        normal.push_back(fr.e3[c]);
        eaxis.push_back(fr.e1[c]);
        maxis.push_back(std::cos(phi) * fr.e1[c] + std::sin(phi) * fr.e2[c]);
      }
    }
    PetscCall(PetscViewerHDF5PushGroup(v, "/shells"));
    PetscCall(WriteReals(comm, v, m.nodes, 3, x, "coordinates"));
    PetscCall(WriteInts(comm, v, m.nodes, 1, part, "node_part"));
    PetscCall(WriteInts(comm, v, m.nodes, 1, pnode, "node"));
    PetscCall(WriteInts(comm, v, m.elems, 4, cells, "cells"));
    PetscCall(WriteInts(comm, v, m.elems, 1, type, "cell_type"));
    PetscCall(WriteInts(comm, v, m.elems, 1, epart, "part"));
    PetscCall(WriteInts(comm, v, m.elems, 1, elem, "element"));
    PetscCall(WriteReals(comm, v, m.elems, 3, normal, "normal"));
    PetscCall(WriteReals(comm, v, m.elems, 3, eaxis, "element_axis"));
    PetscCall(WriteReals(comm, v, m.elems, 3, maxis, "material_axis"));
    PetscCall(PetscViewerHDF5PopGroup(v));
  }
  std::vector<double>   jx;
  std::vector<PetscInt> id;
  for (const JointLine &l : f.lines) {
    jx.insert(jx.end(), l.xa.begin(), l.xa.end());
    jx.insert(jx.end(), l.xb.begin(), l.xb.end());
    id.push_back(l.id);
  }
  // The lines of the natural rows this rank writes: joint i runs from point 2i to point 2i + 1.
  std::vector<PetscInt> lines;
  for (PetscInt i = m.joints.start; i < m.joints.start + m.joints.nlocal; ++i) lines.insert(lines.end(), {2 * i, 2 * i + 1});
  IS is;
  PetscCall(PetscViewerHDF5PushGroup(v, "/joints"));
  PetscCall(WriteRealsAs(comm, v, m.joints, 6, 3, jx, "coordinates"));
  PetscCall(ISCreateGeneral(comm, (PetscInt)lines.size(), lines.data(), PETSC_COPY_VALUES, &is));
  PetscCall(ISSetBlockSize(is, 2));
  PetscCall(PetscObjectSetName((PetscObject)is, "lines"));
  PetscCall(ISView(is, v));
  PetscCall(ISDestroy(&is));
  PetscCall(WriteInts(comm, v, m.joints, 1, id, "id"));
  PetscCall(PetscViewerHDF5PopGroup(v));
  PetscFunctionReturn(0);
}

// The element results of a step: resultants in the material and in the element frame, surface
// strains and stresses in the material frame, von Mises and principal stresses.
PetscErrorCode WriteResults(BoltnetAssembly a, FieldsFile *ff, const StepFields &f)
{
  MPI_Comm    comm = a->comm;
  FieldMap   &m    = ff->map;
  PetscViewer v    = ff->viewer;
  PetscFunctionBeginUser;
  std::vector<double> N, M, Q, Ne, Me, Qe, et, eb, st, sb, vt, vb, pt, pb;
  for (size_t k = 0; k < f.results.size(); ++k) {
    const shell::SectionResults &e = f.results[k];
    const shell::SectionResults  r = shell::Rotated(e, shell::MaterialAngle(e, FieldElementMaterial(a, m.elements[k])));
    N.insert(N.end(), r.N.begin(), r.N.end());
    M.insert(M.end(), r.M.begin(), r.M.end());
    Q.insert(Q.end(), r.Q.begin(), r.Q.end());
    Ne.insert(Ne.end(), e.N.begin(), e.N.end());
    Me.insert(Me.end(), e.M.begin(), e.M.end());
    Qe.insert(Qe.end(), e.Q.begin(), e.Q.end());
    et.insert(et.end(), r.strain_top.begin(), r.strain_top.end());
    eb.insert(eb.end(), r.strain_bottom.begin(), r.strain_bottom.end());
    st.insert(st.end(), r.stress_top.begin(), r.stress_top.end());
    sb.insert(sb.end(), r.stress_bottom.begin(), r.stress_bottom.end());
    vt.push_back(shell::VonMises(r.stress_top));
    vb.push_back(shell::VonMises(r.stress_bottom));
    const auto p = shell::Principal(r.stress_top), q = shell::Principal(r.stress_bottom);
    pt.insert(pt.end(), p.begin(), p.end());
    pb.insert(pb.end(), q.begin(), q.end());
  }
  PetscCall(WriteReals(comm, v, m.elems, 3, N, "N"));
  PetscCall(WriteReals(comm, v, m.elems, 3, M, "M"));
  PetscCall(WriteReals(comm, v, m.elems, 2, Q, "Q"));
  PetscCall(WriteReals(comm, v, m.elems, 3, Ne, "N_element"));
  PetscCall(WriteReals(comm, v, m.elems, 3, Me, "M_element"));
  PetscCall(WriteReals(comm, v, m.elems, 2, Qe, "Q_element"));
  PetscCall(WriteReals(comm, v, m.elems, 3, et, "strain_top"));
  PetscCall(WriteReals(comm, v, m.elems, 3, eb, "strain_bottom"));
  PetscCall(WriteReals(comm, v, m.elems, 3, st, "stress_top"));
  PetscCall(WriteReals(comm, v, m.elems, 3, sb, "stress_bottom"));
  PetscCall(WriteReals(comm, v, m.elems, 1, vt, "von_mises_top"));
  PetscCall(WriteReals(comm, v, m.elems, 1, vb, "von_mises_bottom"));
  PetscCall(WriteReals(comm, v, m.elems, 2, pt, "principal_top"));
  PetscCall(WriteReals(comm, v, m.elems, 2, pb, "principal_bottom"));
  PetscFunctionReturn(0);
}

PetscErrorCode WriteJoints(BoltnetAssembly a, FieldsFile *ff, const StepFields &f)
{
  MPI_Comm    comm = a->comm;
  FieldMap   &m    = ff->map;
  PetscViewer v    = ff->viewer;
  PetscFunctionBeginUser;
  std::vector<double>   u, fip, force, jump, table;
  std::vector<PetscInt> state;
  for (const JointLine &l : f.lines) {
    u.insert(u.end(), l.ua.begin(), l.ua.begin() + 3);
    u.insert(u.end(), l.ub.begin(), l.ub.begin() + 3);
    state.push_back(l.state);
    fip.push_back(std::hypot(l.force[1], l.force[2]));
    force.insert(force.end(), l.force.begin(), l.force.begin() + 3);
    jump.insert(jump.end(), l.jump.begin(), l.jump.begin() + 3);
    // The columns of joints.csv after step and load (the group's attributes); the state as its code.
    table.insert(table.end(), {(double)l.id, (double)l.state, l.jump[0], l.jump[1], l.jump[2], l.force[0], l.force[1], l.force[2], (double)l.bearing, l.slip[0], l.slip[1]});
  }
  PetscCall(WriteRealsAs(comm, v, m.joints, 6, 3, u, "displacement"));
  PetscCall(WriteInts(comm, v, m.joints, 1, state, "state"));
  PetscCall(WriteReals(comm, v, m.joints, 1, fip, "in_plane_force"));
  PetscCall(WriteReals(comm, v, m.joints, 3, force, "force"));
  PetscCall(WriteReals(comm, v, m.joints, 3, jump, "jump"));
  if (ff->opt.joints_hdf5) PetscCall(WriteReals(comm, v, m.joints, 11, table, "table"));
  PetscFunctionReturn(0);
}

// The XML of one temporal collection: a uniform grid per step written so far.
std::string Temporal(const FieldsFile &ff, const std::string &name, const std::string &mesh, const std::function<std::string(const std::string &)> &attributes)
{
  std::ostringstream o;
  o.precision(17);
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
    << "  <Grid Name=\"" << xdmf::Escape(ff.scene + " " + name) << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto &[step, load] : ff.steps) {
    o << "   <Grid Name=\"step " << step << "\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << step << "\"/>\n"
      << "    <Information Name=\"load\" Value=\"" << load << "\"/>\n"
      << mesh << attributes(StepGroup(step)) << "   </Grid>\n";
  }
  o << "  </Grid>\n </Domain>\n</Xdmf>\n";
  return o.str();
}

// fields.xdmf (shells) and joints.xdmf for the steps written so far, each through a temporary file
// and a rename: the files on disk always describe whole steps of fields.h5.
PetscErrorCode WriteXdmf(const FieldsFile &ff)
{
  using xdmf::Attribute;
  using xdmf::Item;
  PetscFunctionBeginUser;
  const FieldMap &m = ff.map;
  const PetscInt  N = m.nodes.nglobal, E = m.elems.nglobal, J = m.joints.nglobal;
  if (N > 0) {
    // All quadrilaterals today; a mesh with triangles writes the XDMF "Mixed" topology instead (a
    // flat list of type code and nodes per cell, from /shells/cell_type and /shells/cells).
    const std::string mesh = "    <Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"" + std::to_string(E) + "\">\n      " + Item(kH5, "/shells/cells", E, 4, true) + "\n    </Topology>\n" +
                             "    <Geometry GeometryType=\"XYZ\">\n      " + Item(kH5, "/shells/coordinates", N, 3, false) + "\n    </Geometry>\n" +
                             Attribute("part", "Scalar", "Cell", Item(kH5, "/shells/part", E, 1, true)) + Attribute("element", "Scalar", "Cell", Item(kH5, "/shells/element", E, 1, true)) +
                             Attribute("node_part", "Scalar", "Node", Item(kH5, "/shells/node_part", N, 1, true)) + Attribute("node", "Scalar", "Node", Item(kH5, "/shells/node", N, 1, true)) +
                             Attribute("normal", "Vector", "Cell", Item(kH5, "/shells/normal", E, 3, false)) + Attribute("material_axis", "Vector", "Cell", Item(kH5, "/shells/material_axis", E, 3, false));
    const bool        results = ff.opt.results;
    const std::string text    = Temporal(ff, "shells", mesh, [&](const std::string &g) {
      std::string s = Attribute("displacement", "Vector", "Node", Item(kH5, g + "/shells/displacement", N, 3, false)) + Attribute("rotation", "Vector", "Node", Item(kH5, g + "/shells/rotation", N, 3, false));
      if (!results) return s;
      for (const char *name : {"N", "M", "N_element", "M_element", "strain_top", "strain_bottom", "stress_top", "stress_bottom"}) s += Attribute(name, "Vector", "Cell", Item(kH5, g + "/shells/" + name, E, 3, false));
      for (const char *name : {"Q", "Q_element", "principal_top", "principal_bottom"}) s += Attribute(name, "Matrix", "Cell", Item(kH5, g + "/shells/" + name, E, 2, false));
      for (const char *name : {"von_mises_top", "von_mises_bottom"}) s += Attribute(name, "Scalar", "Cell", Item(kH5, g + "/shells/" + name, E, 1, false));
      return s;
    });
    const std::string why = WriteFileWhole(ff.dir + "/fields.xdmf", text);
    PetscCheck(why.empty(), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "%s", why.c_str());
  }
  const std::string mesh = "    <Topology TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\"" + std::to_string(J) + "\">\n      " + Item(kH5, "/joints/lines", J, 2, true) + "\n    </Topology>\n" +
                           "    <Geometry GeometryType=\"XYZ\">\n      " + Item(kH5, "/joints/coordinates", 2 * J, 3, false) + "\n    </Geometry>\n" + Attribute("joint", "Scalar", "Cell", Item(kH5, "/joints/id", J, 1, true));
  const std::string text = Temporal(ff, "joints", mesh, [&](const std::string &g) {
    return Attribute("displacement", "Vector", "Node", Item(kH5, g + "/joints/displacement", 2 * J, 3, false)) + Attribute("state", "Scalar", "Cell", Item(kH5, g + "/joints/state", J, 1, true)) +
           Attribute("in_plane_force", "Scalar", "Cell", Item(kH5, g + "/joints/in_plane_force", J, 1, false)) + Attribute("force", "Vector", "Cell", Item(kH5, g + "/joints/force", J, 3, false)) +
           Attribute("jump", "Vector", "Cell", Item(kH5, g + "/joints/jump", J, 3, false));
  });
  const std::string why  = WriteFileWhole(ff.dir + "/joints.xdmf", text);
  PetscCheck(why.empty(), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "%s", why.c_str());
  PetscFunctionReturn(0);
}

// The bypass rows of every rank gathered to rank 0 (small, like joints.csv's records). Collective.
PetscErrorCode GatherBypass(BoltnetAssembly a, FieldsFile *ff, const StepFields &f, std::vector<BypassRow> &all)
{
  std::vector<BypassRow> mine;
  PetscFunctionBeginUser;
  if (ff->map.bypass_width == 0) PetscCall(FieldMapBypassRegions(a, ff->map, ff->opt.bypass_width > 0 ? ff->opt.bypass_width : 6 * a->opt.coupling_radius));
  PetscCall(AssemblyBypass(a, ff->map, f, mine));
  PetscCall(GatherToZero(a->comm, mine, all));
  PetscFunctionReturn(0);
}

// bypass.csv (rank 0), by joint and side.
PetscErrorCode WriteBypass(FieldsFile *ff, const StepInfo &info, std::vector<BypassRow> &all)
{
  PetscFunctionBeginUser;
  std::sort(all.begin(), all.end(), [](const BypassRow &l, const BypassRow &r) { return l.joint != r.joint ? l.joint < r.joint : l.side < r.side; });
  const std::string path = ff->dir + "/bypass.csv";
  if (!ff->bypass) {
    ff->bypass = std::fopen(path.c_str(), "w");
    PetscCheck(ff->bypass, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write %s: %s", path.c_str(), std::strerror(errno));
    std::fprintf(ff->bypass, "step,load,joint,sheet,part,bearing,dx,dy,dz,n_avg,width,bypass_flux,bypass_load,elements\n");
  }
  errno = 0;
  bool ok = true;
  for (const BypassRow &b : all)
    ok = ok && std::fprintf(ff->bypass, "%" PetscInt_FMT ",%.17g,%" PetscInt_FMT ",%s,%" PetscInt_FMT ",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%" PetscInt_FMT "\n", info.step, (double)info.load, b.joint, b.side ? "b" : "a", b.part, b.bearing, b.d[0], b.d[1], b.d[2], b.n_avg, b.width, b.flux, b.load, b.elements) >= 0;
  PetscCheck(ok && std::fflush(ff->bypass) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write %s: %s", path.c_str(), std::strerror(errno));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode FieldsOptionsFromCommandLine(PetscOptionItems *PetscOptionsObject, FieldsOptions *o)
{
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsBool("-output_fields", "Write fields.h5, fields.xdmf and joints.xdmf per converged step (shell displacement/rotation and element results, joint lines with state); scenes with no shell patch (rigid only) have no fields", "", o->fields, &o->fields, nullptr));
  PetscCall(PetscOptionsBool("-output_stresses", "With the fields, the element resultants N, M, Q, surface strains and stresses of every step", "", o->results, &o->results, nullptr));
  PetscCall(PetscOptionsBool("-output_joints_hdf5", "With the fields, the joints.csv table of every step also as the dataset /steps/NNNNNN/joints/table of fields.h5", "", o->joints_hdf5, &o->joints_hdf5, nullptr));
  PetscCall(PetscOptionsReal("-output_bypass_width", "Width w (mm) of the strip whose force balance gives the bypass load in bypass.csv; 0: 6 -coupling_radius", "", o->bypass_width, &o->bypass_width, nullptr));
  PetscCheck(o->bypass_width >= 0, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-output_bypass_width %g: a width must be positive (or 0 for the default)", (double)o->bypass_width);
  PetscCall(PetscOptionsBool("-output_fields_gather", "Write the fields from rank 0 after gathering them (the former writer, kept to measure against; displacements only)", "", o->gather, &o->gather, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldsWriteStep(BoltnetAssembly a, FieldsFile *ff, const StepInfo &info)
{
  PetscFunctionBeginUser;
  if (!ff->mapped) {
    PetscCall(FieldMapCreate(a, &ff->map));
    ff->mapped = true;
  }
  StepFields f;
  PetscCall(AssemblyStepFields(a, ff->map, ff->opt.results, &f));
  // The file stays open and is flushed after each step, so that a run that stops leaves every step
  // before it readable (docs/output.md, "When it is written").
  const bool first = ff->steps.empty();
  if (!ff->viewer) {
    // HDF5 prints its own error stack (a dozen lines) before PETSc's viewer reports the failure with
    // the file's name: the caller's message is the one shown (docs/output.md).
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    PetscCall(PetscViewerHDF5Open(a->comm, (ff->dir + "/" + kH5).c_str(), FILE_MODE_WRITE, &ff->viewer));
  }
  PetscViewer v = ff->viewer;
  if (first) PetscCall(WriteMesh(a, ff, f));
  const std::string g = StepGroup(info.step);
  if (ff->map.nodes.nglobal > 0) {
    PetscCall(PetscViewerHDF5PushGroup(v, (g + "/shells").c_str()));
    PetscCall(WriteReals(a->comm, v, ff->map.nodes, 3, f.u, "displacement"));
    PetscCall(WriteReals(a->comm, v, ff->map.nodes, 3, f.r, "rotation"));
    if (ff->opt.results) PetscCall(WriteResults(a, ff, f));
    PetscCall(PetscViewerHDF5PopGroup(v));
  }
  PetscCall(PetscViewerHDF5PushGroup(v, (g + "/joints").c_str()));
  PetscCall(WriteJoints(a, ff, f));
  PetscCall(PetscViewerHDF5PopGroup(v));
  PetscCall(PetscViewerHDF5WriteAttribute(v, g.c_str(), "load", PETSC_REAL, &info.load));
  PetscCall(PetscViewerHDF5WriteAttribute(v, g.c_str(), "step", PETSC_INT, &info.step));
  PetscCall(PetscViewerFlush(v));
  ff->steps.emplace_back(info.step, info.load);
  // Everything collective is done before rank 0 writes its files alone: an error there must not
  // leave the other ranks waiting in a collective call (OutputStep shares it).
  std::vector<BypassRow> bypass;
  const bool             withBypass = ff->opt.results && ff->map.nodes.nglobal > 0;
  if (withBypass) PetscCall(GatherBypass(a, ff, f, bypass));
  if (a->rank == 0) PetscCall(WriteXdmf(*ff));
  if (a->rank == 0 && withBypass) PetscCall(WriteBypass(ff, info, bypass));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldsClose(FieldsFile *ff)
{
  PetscFunctionBeginUser;
  PetscCall(PetscViewerDestroy(&ff->viewer));
  if (ff->mapped) PetscCall(FieldMapDestroy(&ff->map));
  if (ff->bypass) {
    const bool closed = std::fclose(ff->bypass) == 0;
    ff->bypass        = nullptr;
    PetscCheck(closed, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write %s/bypass.csv: %s", ff->dir.c_str(), std::strerror(errno));
  }
  ff->mapped = false;
  PetscFunctionReturn(0);
}

} // namespace boltnet
