// The field writer before the parallel one (io/fields.cpp), kept to measure against
// (-output_fields_gather, docs/output.md): rank 0 writes what network/fields_gather.cpp gathers.
#include "io/io.hpp"
#include "io/xdmf.hpp"

#include <petscviewerhdf5.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace boltnet {
namespace {

const char *kH5 = "fields.h5";

PetscErrorCode WriteVec(PetscViewer v, const char name[], PetscInt bs, const std::vector<double> &data)
{
  Vec x;
  PetscFunctionBeginUser;
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, (PetscInt)data.size(), &x));
  PetscCall(VecSetBlockSize(x, bs));
  PetscScalar *a;
  PetscCall(VecGetArray(x, &a));
  for (size_t i = 0; i < data.size(); ++i) a[i] = data[i];
  PetscCall(VecRestoreArray(x, &a));
  PetscCall(PetscObjectSetName((PetscObject)x, name));
  PetscCall(VecView(x, v));
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(0);
}

PetscErrorCode WriteIS(PetscViewer v, const char name[], PetscInt bs, const std::vector<PetscInt> &data)
{
  IS is;
  PetscFunctionBeginUser;
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)data.size(), data.data(), PETSC_COPY_VALUES, &is));
  PetscCall(ISSetBlockSize(is, bs));
  PetscCall(PetscObjectSetName((PetscObject)is, name));
  PetscCall(ISView(is, v));
  PetscCall(ISDestroy(&is));
  PetscFunctionReturn(0);
}

std::string StepGroup(PetscInt step)
{
  char s[32];
  std::snprintf(s, sizeof(s), "/steps/%06d", (int)step);
  return s;
}

// One DataItem naming a dataset of fields.h5 with its exact dimensions: VecView writes (n) for
// block size 1 and (n, bs) otherwise; ISView always writes (n, bs).
std::string Item(const std::string &path, PetscInt n, PetscInt bs, bool integer)
{
  std::ostringstream o;
  o << "<DataItem Dimensions=\"" << n;
  if (bs > 1 || integer) o << " " << bs;
  o << "\" NumberType=\"" << (integer ? "Int" : "Float") << "\" Precision=\"" << (integer ? sizeof(PetscInt) : sizeof(PetscReal)) << "\" Format=\"HDF\">" << kH5 << ":" << path << "</DataItem>";
  return o.str();
}

std::string Attribute(const char name[], const char type[], const char center[], const std::string &item)
{
  return std::string("      <Attribute Name=\"") + name + "\" AttributeType=\"" + type + "\" Center=\"" + center + "\">\n        " + item + "\n      </Attribute>\n";
}

// fields.xdmf for the steps written so far, through a temporary file and a rename: the file on disk
// always describes whole steps of fields.h5.
PetscErrorCode WriteXdmf(const FieldsFile &ff)
{
  PetscFunctionBeginUser;
  std::ostringstream o;
  o.precision(17);
  o << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n <Domain>\n"
    << "  <Grid Name=\"" << xdmf::Escape(ff.scene) << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto &[step, load] : ff.steps) {
    const std::string g = StepGroup(step);
    o << "   <Grid Name=\"step " << step << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
      << "    <Time Value=\"" << step << "\"/>\n"
      << "    <Information Name=\"load\" Value=\"" << load << "\"/>\n";
    if (ff.nnodes > 0) {
      o << "    <Grid Name=\"shells\" GridType=\"Uniform\">\n"
        << "      <Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"" << ff.nquads << "\">\n        " << Item("/shells/quads", ff.nquads, 4, true) << "\n      </Topology>\n"
        << "      <Geometry GeometryType=\"XYZ\">\n        " << Item("/shells/coordinates", ff.nnodes, 3, false) << "\n      </Geometry>\n"
        << Attribute("part", "Scalar", "Cell", Item("/shells/part", ff.nquads, 1, true))
        << Attribute("displacement", "Vector", "Node", Item(g + "/shells/displacement", ff.nnodes, 3, false))
        << Attribute("rotation", "Vector", "Node", Item(g + "/shells/rotation", ff.nnodes, 3, false))
        << "    </Grid>\n";
    }
    o << "    <Grid Name=\"joints\" GridType=\"Uniform\">\n"
      << "      <Topology TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\"" << ff.njoints << "\">\n        " << Item("/joints/lines", ff.njoints, 2, true) << "\n      </Topology>\n"
      << "      <Geometry GeometryType=\"XYZ\">\n        " << Item("/joints/coordinates", 2 * ff.njoints, 3, false) << "\n      </Geometry>\n"
      << Attribute("joint", "Scalar", "Cell", Item("/joints/id", ff.njoints, 1, true))
      << Attribute("displacement", "Vector", "Node", Item(g + "/joints/displacement", 2 * ff.njoints, 3, false))
      << Attribute("state", "Scalar", "Cell", Item(g + "/joints/state", ff.njoints, 1, true))
      << Attribute("in_plane_force", "Scalar", "Cell", Item(g + "/joints/in_plane_force", ff.njoints, 1, false))
      << "    </Grid>\n"
      << "   </Grid>\n";
  }
  o << "  </Grid>\n </Domain>\n</Xdmf>\n";
  const std::string why = WriteFileWhole(ff.dir + "/fields.xdmf", o.str());
  PetscCheck(why.empty(), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "%s", why.c_str());
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode FieldsWriteStepGather(FieldsFile *ff, const StepInfo &info, const std::vector<PartField> &parts, const std::vector<JointLine> &lines)
{
  PetscFunctionBeginUser;
  // Geometry and topology once, with the first step. The file stays open and is flushed after each
  // step, so that a run that stops leaves every step before it readable. Measured on fig3a (20
  // steps, 1 rank): reopening the file per step cost 0.1 s a step, the flush costs 0.05 s (PETSc
  // opens HDF5 files through MPI-IO, whose sync waits), writing without flushing 0.005 s.
  const bool first = ff->steps.empty();
  if (!ff->viewer) {
    // HDF5 prints its own error stack (a dozen lines) before PETSc's viewer reports the failure with
    // the file's name: the caller's message is the one shown (docs/output.md).
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    PetscCall(PetscViewerHDF5Open(PETSC_COMM_SELF, (ff->dir + "/" + kH5).c_str(), FILE_MODE_WRITE, &ff->viewer));
  }
  PetscViewer v = ff->viewer;
  if (first) {
    std::vector<double>   x, jx;
    std::vector<PetscInt> quads, part, jl, jid;
    for (const PartField &p : parts) {
      const PetscInt base = (PetscInt)(x.size() / 3);
      for (const auto &c : p.x) x.insert(x.end(), c.begin(), c.end());
      for (const auto &q : p.elems) {
        for (int k = 0; k < 4; ++k) quads.push_back(base + q[k]); // quadrilaterals only (OutputOpen)
        part.push_back(p.id);
      }
    }
    for (size_t i = 0; i < lines.size(); ++i) {
      jx.insert(jx.end(), lines[i].xa.begin(), lines[i].xa.end());
      jx.insert(jx.end(), lines[i].xb.begin(), lines[i].xb.end());
      jl.push_back(2 * (PetscInt)i);
      jl.push_back(2 * (PetscInt)i + 1);
      jid.push_back(lines[i].id);
    }
    ff->nnodes  = (PetscInt)(x.size() / 3);
    ff->nquads  = (PetscInt)part.size();
    ff->njoints = (PetscInt)lines.size();
    if (ff->nnodes > 0) {
      PetscCall(PetscViewerHDF5PushGroup(v, "/shells"));
      PetscCall(WriteVec(v, "coordinates", 3, x));
      PetscCall(WriteIS(v, "quads", 4, quads));
      PetscCall(WriteIS(v, "part", 1, part));
      PetscCall(PetscViewerHDF5PopGroup(v));
    }
    PetscCall(PetscViewerHDF5PushGroup(v, "/joints"));
    PetscCall(WriteVec(v, "coordinates", 3, jx));
    PetscCall(WriteIS(v, "lines", 2, jl));
    PetscCall(WriteIS(v, "id", 1, jid));
    PetscCall(PetscViewerHDF5PopGroup(v));
  }
  PetscCheck((PetscInt)lines.size() == ff->njoints, PETSC_COMM_SELF, PETSC_ERR_PLIB, "The number of joints changed between steps");
  const std::string g = StepGroup(info.step);
  if (ff->nnodes > 0) {
    std::vector<double> u, r;
    for (const PartField &p : parts)
      for (size_t n = 0; n < p.x.size(); ++n) {
        u.insert(u.end(), p.dof.begin() + 6 * n, p.dof.begin() + 6 * n + 3);
        r.insert(r.end(), p.dof.begin() + 6 * n + 3, p.dof.begin() + 6 * n + 6);
      }
    PetscCheck((PetscInt)u.size() == 3 * ff->nnodes, PETSC_COMM_SELF, PETSC_ERR_PLIB, "The number of shell nodes changed between steps");
    PetscCall(PetscViewerHDF5PushGroup(v, (g + "/shells").c_str()));
    PetscCall(WriteVec(v, "displacement", 3, u));
    PetscCall(WriteVec(v, "rotation", 3, r));
    PetscCall(PetscViewerHDF5PopGroup(v));
  }
  {
    std::vector<double>   u, f;
    std::vector<PetscInt> s;
    for (const JointLine &l : lines) {
      u.insert(u.end(), l.ua.begin(), l.ua.begin() + 3);
      u.insert(u.end(), l.ub.begin(), l.ub.begin() + 3);
      s.push_back(l.state);
      f.push_back(std::hypot(l.force[1], l.force[2]));
    }
    PetscCall(PetscViewerHDF5PushGroup(v, (g + "/joints").c_str()));
    PetscCall(WriteVec(v, "displacement", 3, u));
    PetscCall(WriteIS(v, "state", 1, s));
    PetscCall(WriteVec(v, "in_plane_force", 1, f));
    PetscCall(PetscViewerHDF5PopGroup(v));
  }
  PetscCall(PetscViewerHDF5WriteAttribute(v, g.c_str(), "load", PETSC_REAL, &info.load));
  PetscCall(PetscViewerHDF5WriteAttribute(v, g.c_str(), "step", PETSC_INT, &info.step));
  PetscCall(PetscViewerFlush(v));
  ff->steps.emplace_back(info.step, info.load);
  PetscCall(WriteXdmf(*ff));
  PetscFunctionReturn(0);
}

} // namespace boltnet
