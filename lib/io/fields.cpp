// Field output (docs/output.md): fields.h5 written in parallel through PETSc's HDF5 viewer, each
// rank its own rows of every dataset (network/fields.hpp puts them in the file's numbering), and
// fields.xdmf (shells) and joints.xdmf (joint lines), XDMF 3, written by rank 0. HDF5 itself is
// called to silence its error printing and to write the one-dimensional topology of a mesh with
// triangles (WriteMixedTopology).
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
#include <map>
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

// One dataset among several of a space written together: bs values per item, real or integer
// (PetscInt, moved as reals: exact below 2^53), or real rows of 6 written as two rows of 3 (a
// joint's two endpoints).
struct Column {
  const char *name;
  PetscInt    bs;
  enum Kind { Real, Int, Pairs } kind;
};

// The datasets `cols` of space s from `rows` (per owned item, the columns side by side), in one
// scatter to natural order (or from *given, already scattered), each then written by VecView or
// ISView: every rank its own rows. *given (if not null) is set to the natural Vec, borrowed from s.
PetscErrorCode WritePacked(MPI_Comm comm, PetscViewer viewer, FieldSpace &s, const std::vector<Column> &cols, const std::vector<double> &rows, Vec *given = nullptr)
{
  PetscInt K = 0, first = 0;
  Vec      natural = given ? *given : nullptr;
  PetscFunctionBeginUser;
  for (const Column &c : cols) K += c.bs;
  if (!natural) PetscCall(FieldSpaceNatural(comm, s, K, rows, &natural));
  if (given) *given = natural;
  for (const Column &c : cols) {
    Vec v;
    PetscCall(FieldSpaceColumns(s, natural, K, first, c.bs, &v));
    first += c.bs;
    if (c.kind == Column::Real) {
      PetscCall(View(v, c.name, viewer));
      continue;
    }
    const PetscScalar *p;
    const PetscInt     n = c.bs * s.nlocal;
    PetscCall(VecGetArrayRead(v, &p));
    if (c.kind == Column::Pairs) {
      Vec w;
      PetscCall(VecCreateMPIWithArray(comm, 3, n, PETSC_DETERMINE, p, &w));
      PetscCall(View(w, c.name, viewer));
      PetscCall(VecDestroy(&w));
    } else {
      std::vector<PetscInt> ints(p, p + n);
      IS                    is;
      PetscCall(ISCreateGeneral(comm, n, ints.data(), PETSC_COPY_VALUES, &is));
      PetscCall(ISSetBlockSize(is, c.bs));
      PetscCall(PetscObjectSetName((PetscObject)is, c.name));
      PetscCall(ISView(is, viewer));
      PetscCall(ISDestroy(&is));
    }
    PetscCall(VecRestoreArrayRead(v, &p));
  }
  PetscFunctionReturn(0);
}

std::string StepGroup(PetscInt step)
{
  char s[32];
  std::snprintf(s, sizeof(s), "/steps/%06d", (int)step);
  return s;
}

// A mesh with triangles: the XDMF "Mixed" topology /shells/topology, per cell (in natural order) its
// type code and its nodes, one flat list of 5 E - (number of triangles) integers. Each rank writes
// the cells of its natural rows, read from `natural` (K columns, cells in 0..3, the type code in 4),
// at the offset of the ranks before it. Written through HDF5 itself: XDMF readers (meshio among
// them) want a one-dimensional dataset, and ISView always writes two dimensions.
PetscErrorCode WriteMixedTopology(MPI_Comm comm, PetscViewer viewer, const FieldSpace &s, Vec natural, PetscInt K)
{
  const PetscScalar    *p;
  std::vector<PetscInt> mine;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(natural, &p));
  for (PetscInt i = 0; i < s.nlocal; ++i) {
    const PetscInt type = (PetscInt)p[K * i + 4];
    mine.push_back(type);
    for (int k = 0; k < (type == 4 ? 3 : 4); ++k) mine.push_back((PetscInt)p[K * i + k]);
  }
  PetscCall(VecRestoreArrayRead(natural, &p));
  unsigned long long n = mine.size(), start = 0, total = 0;
  PetscMPIInt        rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Exscan(&n, &start, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm));
  if (rank == 0) start = 0; // MPI_Exscan leaves rank 0's result undefined
  PetscCallMPI(MPI_Allreduce(&n, &total, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm));
  hid_t   file, type;
  hsize_t hn = n, hstart = start, htotal = total;
  PetscCall(PetscViewerHDF5GetFileId(viewer, &file));
  PetscCall(PetscDataTypeToHDF5DataType(PETSC_INT, &type));
  const char  *path   = "/shells/topology";
  const hid_t  fspace = H5Screate_simple(1, &htotal, nullptr);
  const hid_t  mspace = H5Screate_simple(1, &hn, nullptr);
  const hid_t  dset   = fspace < 0 ? -1 : H5Dcreate2(file, path, type, fspace, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t sel    = fspace < 0 ? -1 : hn > 0 ? H5Sselect_hyperslab(fspace, H5S_SELECT_SET, &hstart, nullptr, &hn, nullptr) : H5Sselect_none(fspace);
  const herr_t wrote  = dset < 0 || mspace < 0 || sel < 0 ? -1 : H5Dwrite(dset, type, mspace, fspace, H5P_DEFAULT, mine.data());
  const bool   closed = (dset < 0 || H5Dclose(dset) >= 0) & (mspace < 0 || H5Sclose(mspace) >= 0) & (fspace < 0 || H5Sclose(fspace) >= 0);
  PetscCheck(wrote >= 0 && closed, PETSC_COMM_SELF, PETSC_ERR_LIB, "HDF5 could not write %s", path);
  PetscFunctionReturn(0);
}

// Geometry, topology and the numbering: written once, with the first step.
PetscErrorCode WriteMesh(BoltnetAssembly a, FieldsFile *ff, const StepFields &f)
{
  MPI_Comm    comm = a->comm;
  FieldMap   &m    = ff->map;
  PetscViewer v    = ff->viewer;
  PetscFunctionBeginUser;
  if (m.nodes.nglobal > 0) {
    std::vector<double> nodes, elems;
    for (size_t i = 0; i < m.node_src.size(); ++i) {
      const auto &[o, l]   = m.node_src[i];
      const ShellPatch &sp = a->layout.shells.at(a->patches.owned[o].index);
      nodes.insert(nodes.end(), sp.mesh.x[l].begin(), sp.mesh.x[l].end());
      nodes.insert(nodes.end(), {(double)sp.id, (double)(m.nodes.natural[i] - m.node_off.at(sp.id))});
    }
    for (const FieldElement &e : m.elements) {
      for (int k = 0; k < 4; ++k) elems.push_back(k < e.nn ? (double)e.node[k] : -1.0);
      elems.insert(elems.end(), {(double)e.type, (double)e.part, (double)e.elem});
      const auto            fr = ElementAxesOf(e.geom); // e1, e2, e3
      shell::SectionResults s{};
      s.e1 = fr[0], s.e2 = fr[1];
      const double phi = shell::MaterialAngle(s, FieldElementMaterial(a, e));
      elems.insert(elems.end(), fr[2].begin(), fr[2].end());
      elems.insert(elems.end(), fr[0].begin(), fr[0].end());
      for (int c = 0; c < 3; ++c) elems.push_back(std::cos(phi) * fr[0][c] + std::sin(phi) * fr[1][c]);
    }
    PetscCall(PetscViewerHDF5PushGroup(v, "/shells"));
    PetscCall(WritePacked(comm, v, m.nodes, {{"coordinates", 3, Column::Real}, {"node_part", 1, Column::Int}, {"node", 1, Column::Int}}, nodes));
    Vec natural = nullptr; // the elements' columns side by side, in natural order
    PetscCall(WritePacked(comm, v, m.elems,
                          {{"cells", 4, Column::Int}, {"cell_type", 1, Column::Int}, {"part", 1, Column::Int}, {"element", 1, Column::Int}, {"normal", 3, Column::Real}, {"element_axis", 3, Column::Real}, {"material_axis", 3, Column::Real}}, elems, &natural));
    PetscCall(PetscViewerHDF5PopGroup(v));
    if (m.ntriangles > 0) PetscCall(WriteMixedTopology(comm, v, m.elems, natural, 16));
    // Written once: their packed Vecs (16 values an element, twice) are not kept for the run.
    // Block size 4 went with them; 3, 2 and 1 are the results' (WriteResults).
    PetscCall(FieldSpaceRelease(m.nodes, 5));
    PetscCall(FieldSpaceRelease(m.elems, 16));
    PetscCall(FieldSpaceRelease(m.elems, 4));
  }
  std::vector<double> joints;
  for (const JointLine &l : f.lines) {
    joints.insert(joints.end(), l.xa.begin(), l.xa.end());
    joints.insert(joints.end(), l.xb.begin(), l.xb.end());
    joints.push_back((double)l.id);
  }
  // The lines of the natural rows this rank writes: joint i runs from point 2i to point 2i + 1.
  std::vector<PetscInt> lines;
  for (PetscInt i = m.joints.start; i < m.joints.start + m.joints.nlocal; ++i) lines.insert(lines.end(), {2 * i, 2 * i + 1});
  IS is;
  PetscCall(PetscViewerHDF5PushGroup(v, "/joints"));
  PetscCall(WritePacked(comm, v, m.joints, {{"coordinates", 6, Column::Pairs}, {"id", 1, Column::Int}}, joints));
  PetscCall(ISCreateGeneral(comm, (PetscInt)lines.size(), lines.data(), PETSC_COPY_VALUES, &is));
  PetscCall(ISSetBlockSize(is, 2));
  PetscCall(PetscObjectSetName((PetscObject)is, "lines"));
  PetscCall(ISView(is, v));
  PetscCall(ISDestroy(&is));
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
  std::vector<double> rows;
  rows.reserve(34 * f.results.size());
  for (size_t k = 0; k < f.results.size(); ++k) {
    const shell::SectionResults &e = f.results[k];
    const shell::SectionResults  r = shell::Rotated(e, shell::MaterialAngle(e, FieldElementMaterial(a, m.elements[k])));
    const auto                   p = shell::Principal(r.stress_top), q = shell::Principal(r.stress_bottom);
    for (const auto *c : {&r.N, &r.M}) rows.insert(rows.end(), c->begin(), c->end());
    rows.insert(rows.end(), r.Q.begin(), r.Q.end());
    for (const auto *c : {&e.N, &e.M}) rows.insert(rows.end(), c->begin(), c->end());
    rows.insert(rows.end(), e.Q.begin(), e.Q.end());
    for (const auto *c : {&r.strain_top, &r.strain_bottom, &r.stress_top, &r.stress_bottom}) rows.insert(rows.end(), c->begin(), c->end());
    rows.insert(rows.end(), {shell::VonMises(r.stress_top), shell::VonMises(r.stress_bottom), p[0], p[1], q[0], q[1]});
  }
  // One dataset at a time: a scatter of the 34 columns together would keep two natural Vecs of 34
  // values an element for the whole run (FieldSpaceNatural keeps what it creates); these keep two
  // of 3, 2 and 1, shared by the datasets of each width (docs/output.md, "Cost").
  const std::vector<Column> cols = {{"N", 3, Column::Real},
                                    {"M", 3, Column::Real},
                                    {"Q", 2, Column::Real},
                                    {"N_element", 3, Column::Real},
                                    {"M_element", 3, Column::Real},
                                    {"Q_element", 2, Column::Real},
                                    {"strain_top", 3, Column::Real},
                                    {"strain_bottom", 3, Column::Real},
                                    {"stress_top", 3, Column::Real},
                                    {"stress_bottom", 3, Column::Real},
                                    {"von_mises_top", 1, Column::Real},
                                    {"von_mises_bottom", 1, Column::Real},
                                    {"principal_top", 2, Column::Real},
                                    {"principal_bottom", 2, Column::Real}};
  const size_t              K    = 34, n = f.results.size();
  std::vector<double>       one;
  size_t                    first = 0;
  for (const Column &c : cols) {
    one.resize((size_t)c.bs * n);
    for (size_t k = 0; k < n; ++k) std::copy_n(rows.data() + K * k + first, c.bs, one.data() + (size_t)c.bs * k);
    PetscCall(WritePacked(comm, v, m.elems, {c}, one));
    first += (size_t)c.bs;
  }
  PetscCheck(first == K, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%zu result columns written, %zu computed", first, K);
  PetscFunctionReturn(0);
}

PetscErrorCode WriteJoints(BoltnetAssembly a, FieldsFile *ff, const StepFields &f)
{
  MPI_Comm    comm = a->comm;
  FieldMap   &m    = ff->map;
  PetscViewer v    = ff->viewer;
  PetscFunctionBeginUser;
  std::vector<double> rows;
  for (const JointLine &l : f.lines) {
    rows.insert(rows.end(), l.ua.begin(), l.ua.begin() + 3);
    rows.insert(rows.end(), l.ub.begin(), l.ub.begin() + 3);
    rows.insert(rows.end(), {(double)l.state, std::hypot(l.force[1], l.force[2])});
    rows.insert(rows.end(), l.force.begin(), l.force.begin() + 3);
    rows.insert(rows.end(), l.jump.begin(), l.jump.begin() + 3);
  }
  PetscCall(WritePacked(comm, v, m.joints, {{"displacement", 6, Column::Pairs}, {"state", 1, Column::Int}, {"in_plane_force", 1, Column::Real}, {"force", 3, Column::Real}, {"jump", 3, Column::Real}}, rows));
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
    // Quadrilaterals only: /shells/cells. With triangles, the XDMF "Mixed" topology: a flat list of
    // type code and nodes per cell (/shells/topology, WriteMixedTopology).
    const PetscInt    L        = 5 * E - m.ntriangles;
    const std::string topology = m.ntriangles == 0 ? "    <Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"" + std::to_string(E) + "\">\n      " + Item(kH5, "/shells/cells", E, 4, true) + "\n    </Topology>\n"
                                                   : "    <Topology TopologyType=\"Mixed\" NumberOfElements=\"" + std::to_string(E) + "\">\n      <DataItem Dimensions=\"" + std::to_string(L) + "\" DataType=\"Int\" Precision=\"" + std::to_string(sizeof(PetscInt)) + "\" Format=\"HDF\">" + kH5 + ":/shells/topology</DataItem>\n    </Topology>\n";
    const std::string mesh = topology +
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

// The bypass rows of the joints this rank owns (JointSet order, a row per side on a shell part).
// Collective.
PetscErrorCode OwnedBypass(BoltnetAssembly a, FieldsFile *ff, const StepFields &f, std::vector<BypassRow> &mine)
{
  PetscFunctionBeginUser;
  if (ff->map.bypass_width == 0) {
    const double w = ff->opt.bypass_width > 0 ? ff->opt.bypass_width : 6 * a->opt.coupling_radius;
    PetscCall(FieldMapBypassRegions(a, ff->map, w, ff->opt.bypass_length > 0 ? ff->opt.bypass_length : w / 2));
  }
  PetscCall(AssemblyBypass(a, ff->map, f, mine));
  PetscFunctionReturn(0);
}

// The bypass of the step's joints into the joints group of fields.h5, every rank its own rows, in
// the joints' natural order: per joint and side (a, b) the bypass load, flux, incoming running load,
// the bands' balance, the bearing load and the elements averaged; NaN (0 elements) for a side on a
// rigid part.
// Collective.
PetscErrorCode WriteBypassFields(BoltnetAssembly a, FieldsFile *ff, const std::vector<BypassRow> &mine)
{
  PetscFunctionBeginUser;
  const size_t        nj = a->joints.size();
  std::vector<double> load(2 * nj, NAN), flux(2 * nj, NAN), nin(2 * nj, NAN), balance(2 * nj, NAN), bearing(2 * nj, NAN), elements(2 * nj, 0);
  std::map<PetscInt, size_t> at; // joint id -> position in JointSet order
  for (size_t k = 0; k < nj; ++k) at[a->joints.comp[k].id] = k;
  for (const BypassRow &b : mine) {
    const size_t i = 2 * at.at(b.joint) + (size_t)b.side;
    load[i]        = b.load;
    flux[i]        = b.flux;
    nin[i]         = b.n_in;
    balance[i]     = b.balance;
    bearing[i]     = b.bearing;
    elements[i]    = (double)b.elements;
  }
  std::vector<double> rows;
  rows.reserve(12 * nj);
  for (size_t k = 0; k < nj; ++k)
    for (const auto *col : {&load, &flux, &nin, &balance, &bearing, &elements}) rows.insert(rows.end(), {(*col)[2 * k], (*col)[2 * k + 1]});
  PetscCall(WritePacked(a->comm, ff->viewer, ff->map.joints,
                        {{"bypass_load", 2, Column::Real}, {"bypass_flux", 2, Column::Real}, {"bypass_n_incoming", 2, Column::Real}, {"bypass_balance", 2, Column::Real}, {"bypass_bearing", 2, Column::Real}, {"bypass_elements", 2, Column::Int}},
                        rows));
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
    std::fprintf(ff->bypass, "step,load,joint,sheet,part,bearing,dx,dy,dz,width,length,n_incoming,bypass_flux,bypass_load,balance,elements\n");
  }
  errno = 0;
  bool ok = true;
  for (const BypassRow &b : all)
    ok = ok && std::fprintf(ff->bypass, "%" PetscInt_FMT ",%.17g,%" PetscInt_FMT ",%s,%" PetscInt_FMT ",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%" PetscInt_FMT "\n", info.step, (double)info.load, b.joint, b.side ? "b" : "a", b.part, b.bearing, b.d[0], b.d[1], b.d[2], b.width, b.length, b.n_in, b.flux, b.load, b.balance, b.elements) >= 0;
  PetscCheck(ok && std::fflush(ff->bypass) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write %s: %s", path.c_str(), std::strerror(errno));
  PetscFunctionReturn(0);
}

} // namespace

std::string FieldsStepGroup(PetscInt step) { return StepGroup(step); }

PetscErrorCode FieldsOptionsFromCommandLine(PetscOptionItems *PetscOptionsObject, FieldsOptions *o)
{
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsBool("-output_fields", "Write fields.h5, fields.xdmf and joints.xdmf per converged step (shell displacement/rotation and element results, joint lines with state); scenes with no shell patch (rigid only) have no fields", "", o->fields, &o->fields, nullptr));
  PetscCall(PetscOptionsBool("-output_stresses", "With the fields, the element resultants N, M, Q, surface strains and stresses of every step", "", o->results, &o->results, nullptr));
  PetscCall(PetscOptionsBool("-output_stresses_cache", "Keep each element's condensed modes (776 bytes an element) from the second step on, so that later steps' element results do not integrate the elements again; false saves the memory", "", o->results_cache, &o->results_cache, nullptr));
  PetscCall(PetscOptionsReal("-output_bypass_width", "Width w (mm) of the strip whose force balance gives the bypass load (bypass.csv, fields.h5); 0: 6 -coupling_radius", "", o->bypass_width, &o->bypass_width, nullptr));
  PetscCheck(o->bypass_width >= 0, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-output_bypass_width %g: a width must be positive (or 0 for the default)", (double)o->bypass_width);
  PetscCall(PetscOptionsReal("-output_bypass_length", "Length L (mm) along the load of the bands on each side of a fastener whose running loads give the incoming and the bypass load: elements beyond the footprint that begin within L; keep it short of the next fastener (half a row spacing); 0: w / 2", "", o->bypass_length, &o->bypass_length, nullptr));
  PetscCheck(o->bypass_length >= 0, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-output_bypass_length %g: a length must be positive (or 0 for the default)", (double)o->bypass_length);
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
  // The elements' condensed modes are kept from the second step on (-output_stresses_cache).
  PetscCall(AssemblyStepFields(a, ff->map, ff->opt.results, ff->opt.results_cache && !ff->steps.empty(), &f));
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
    PetscCall(WritePacked(a->comm, v, ff->map.nodes, {{"displacement", 3, Column::Real}, {"rotation", 3, Column::Real}}, f.dof, &f.dof_natural));
    if (ff->opt.results) PetscCall(WriteResults(a, ff, f));
    PetscCall(PetscViewerHDF5PopGroup(v));
  }
  // Everything collective is done before rank 0 writes its files alone: an error there must not
  // leave the other ranks waiting in a collective call (OutputStep shares it).
  std::vector<BypassRow> bypass;
  const bool             withBypass = ff->opt.results && ff->map.nodes.nglobal > 0;
  if (withBypass) PetscCall(OwnedBypass(a, ff, f, bypass));
  PetscCall(PetscViewerHDF5PushGroup(v, (g + "/joints").c_str()));
  PetscCall(WriteJoints(a, ff, f));
  if (withBypass) PetscCall(WriteBypassFields(a, ff, bypass));
  PetscCall(PetscViewerHDF5PopGroup(v));
  if (withBypass) PetscCall(PetscViewerHDF5WriteAttribute(v, (g + "/joints").c_str(), "bypass_width", PETSC_REAL, &ff->map.bypass_width));
  if (withBypass) PetscCall(PetscViewerHDF5WriteAttribute(v, (g + "/joints").c_str(), "bypass_length", PETSC_REAL, &ff->map.bypass_length));
  PetscCall(PetscViewerHDF5WriteAttribute(v, g.c_str(), "load", PETSC_REAL, &info.load));
  PetscCall(PetscViewerHDF5WriteAttribute(v, g.c_str(), "step", PETSC_INT, &info.step));
  PetscCall(PetscViewerFlush(v));
  ff->steps.emplace_back(info.step, info.load);
  // bypass.csv, for models small enough for joints.csv: the rows gathered to rank 0.
  if (withBypass && ff->bypass_csv) {
    std::vector<BypassRow> all;
    PetscCall(GatherToZero(a->comm, bypass, all));
    bypass.swap(all);
  }
  if (a->rank == 0) PetscCall(WriteXdmf(*ff));
  if (a->rank == 0 && withBypass && ff->bypass_csv) PetscCall(WriteBypass(ff, info, bypass));
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
