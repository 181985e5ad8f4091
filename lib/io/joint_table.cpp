// joints.h5 (io/joint_table.hpp, docs/output.md "The joint table"). PETSc's HDF5 viewer opens the
// file on the assembly's communicator (MPI-IO when HDF5 is parallel, as Debian's is); the datasets
// are HDF5's own: chunked, their step dimension unlimited, each step's rows written by every rank
// at its own offset in one collective H5Dwrite per dataset.
#include "io/h5id.hpp"
#include "io/joint_table.hpp"
#include "joint/law.hpp"

#include <petscviewerhdf5.h>

#include <algorithm>
#include <array>
#include <cstring>

namespace boltnet {
namespace {

// The joint's columns as they travel to their rows: state, bearing, jump (6), force (6), slip (2).
constexpr PetscInt kPacked = 16;
// Rows per chunk of the per-joint datasets: 16384 joints of 6 reals is 768 kB, one chunk per step
// for models up to that size.
constexpr hsize_t kChunkRows = 16384;
constexpr int     kStates    = 5; // State's codes 0..4 (joint/law.hpp)

struct Dataset {
  const char *name;
  hid_t       type;     // memory and file type
  int         width;    // values per joint and step; 0: one value per step (not per joint)
  const char *columns;  // attribute "columns"
  const char *units;    // attribute "units"
  const char *meaning;  // attribute "meaning"
};

// The datasets that grow by one step at a time, in the order JointTableWriteStep fills them.
std::array<Dataset, 7> StepDatasets()
{
  hid_t pint;
  PetscDataTypeToHDF5DataType(PETSC_INT, &pint);
  return {{{"step", pint, 0, "step", "1", "converged step number (joints.csv's step)"},
           {"load", H5T_NATIVE_DOUBLE, 0, "load", "1", "load factor of the step (joints.csv's load)"},
           {"state", H5T_NATIVE_INT, 1, "state", "1", "what the joint did during the step, as a code: state_names[code] is joints.csv's state"},
           {"bearing", H5T_NATIVE_INT, 1, "bearing", "1", "1 when the bolt touches its hole, else 0"},
           {"jump", H5T_NATIVE_DOUBLE, 6, "du_n du_t1 du_t2 dtheta_n dtheta_t1 dtheta_t2", "mm mm mm rad rad rad", "jump of node B over node A in the joint frame (n, t1, t2)"},
           {"force", H5T_NATIVE_DOUBLE, 6, "f_n f_t1 f_t2 m_n m_t1 m_t2", "N N N N*mm N*mm N*mm", "force and moment on node B in the joint frame (n, t1, t2)"},
           {"slip", H5T_NATIVE_DOUBLE, 2, "slip_t1 slip_t2", "mm mm", "accumulated slip in the joint frame (t1, t2)"}}};
}

herr_t StringAttribute(hid_t obj, const char *name, const std::string &value)
{
  H5Id type(H5Tcopy(H5T_C_S1), H5Tclose);
  if (type < 0 || H5Tset_size(type, std::max<size_t>(1, value.size())) < 0) return -1;
  H5Id space(H5Screate(H5S_SCALAR), H5Sclose);
  H5Id attr(space < 0 ? -1 : H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (attr < 0) return -1;
  std::string v = value.empty() ? std::string(1, '\0') : value;
  return H5Awrite(attr, type, v.data());
}

// A transfer property list for collective writes: every rank calls H5Dwrite, each with its own
// selection (perhaps none), and MPI-IO combines them.
hid_t CollectiveTransfer()
{
  const hid_t dxpl = H5Pcreate(H5P_DATASET_XFER);
#if defined(H5_HAVE_PARALLEL)
  if (dxpl >= 0 && H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_COLLECTIVE) < 0) {
    H5Pclose(dxpl);
    return -1;
  }
#endif
  return dxpl;
}

// This rank's n items of a dataset of shape dims (rank 1, 2 or 3), at `at` along the first
// dimension and, for 2 or 3 dimensions, rows [start, start + n) of the second: the hyperslab
// (at, start..start+n, all). With extend, the dataset is first extended to dims (collective).
herr_t WriteSlab(hid_t dset, hid_t type, int rank, const hsize_t *dims, bool extend, hsize_t at, hsize_t start, hsize_t n, const void *buf)
{
  if (extend && H5Dset_extent(dset, dims) < 0) return -1;
  H5Id fspace(H5Dget_space(dset), H5Sclose);
  if (fspace < 0) return -1;
  const hsize_t off[3] = {at, start, 0}, cnt[3] = {rank == 1 ? n : 1, n, rank == 3 ? dims[2] : 1};
  const hsize_t count  = rank == 1 ? n : n * cnt[2];
  const herr_t  sel    = n == 0 ? H5Sselect_none(fspace) : H5Sselect_hyperslab(fspace, H5S_SELECT_SET, off, nullptr, cnt, nullptr);
  H5Id          mspace(H5Screate_simple(1, &count, nullptr), H5Sclose);
  H5Id          dxpl(CollectiveTransfer(), H5Pclose);
  const char    none = 0; // HDF5 wants a buffer even for an empty selection
  if (sel < 0 || mspace < 0 || dxpl < 0) return -1;
  return H5Dwrite(dset, type, mspace, fspace, dxpl, n ? buf : &none);
}

// The rows of the joints this rank owns: the joints by increasing id (JointComp::row, numbered when
// the model was laid out, so that no rank needs the model's whole joint list here).
PetscErrorCode SetUpRows(BoltnetAssembly a, FieldSpace *rows)
{
  PetscFunctionBeginUser;
  rows->natural.clear();
  for (const JointComp &c : a->joints.comp) rows->natural.push_back(c.row);
  PetscCall(FieldSpaceSetUp(a->comm, *rows));
  PetscCheck(rows->nglobal == a->layout.njoints, a->comm, PETSC_ERR_PLIB, "The joint table's rows do not cover the model's joints once");
  PetscFunctionReturn(0);
}

// Collective: the ids of this rank's rows of the table, [start, start + nlocal), sent by the ranks
// that own the joints.
PetscErrorCode RowIds(BoltnetAssembly a, FieldSpace &rows, std::vector<PetscInt> *ids)
{
  std::vector<double> owned;
  Vec                 natural;
  const PetscScalar  *p;
  PetscFunctionBeginUser;
  for (const JointComp &c : a->joints.comp) owned.push_back((double)c.id); // an id is exact as a double
  PetscCall(FieldSpaceNatural(a->comm, rows, 1, owned, &natural));
  PetscCall(VecGetArrayRead(natural, &p));
  ids->assign(rows.nlocal, 0);
  for (PetscInt i = 0; i < rows.nlocal; ++i) (*ids)[i] = (PetscInt)PetscRealPart(p[i]);
  PetscCall(VecRestoreArrayRead(natural, &p));
  PetscCall(FieldSpaceRelease(rows, 1));
  PetscFunctionReturn(0);
}

// One rank's share of JointTableCheck: the table's shape, its steps, and its ids at this rank's rows.
std::string CheckRows(const std::string &path, PetscInt k, const FieldSpace &rows, const std::vector<PetscInt> &ids)
{
  hid_t pint;
  if (PetscDataTypeToHDF5DataType(PETSC_INT, &pint)) return "PETSc error";
  const hsize_t J = (hsize_t)rows.nglobal;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  H5Id file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  const std::string not_it = "Cannot restart: " + path + " is not the joint table of the run that wrote the checkpoint: ";
  if (file < 0) return "Cannot restart: there is no readable joint table " + path + " to continue (-output_dir must name the directory of the run that wrote the checkpoint, with the same -output_joints)";
  // The shape of a dataset, or an empty vector.
  const auto shape = [&](const char *name) {
    std::vector<hsize_t> dims;
    if (H5Lexists(file, name, H5P_DEFAULT) <= 0) return dims;
    H5Id dset(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose);
    H5Id space(dset < 0 ? -1 : H5Dget_space(dset), H5Sclose);
    const int n = space < 0 ? -1 : H5Sget_simple_extent_ndims(space);
    if (n <= 0) return dims;
    dims.resize((size_t)n);
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    return dims;
  };
  // n values of a one-dimensional dataset from offset off.
  const auto read = [&](const char *name, hsize_t off, size_t n, std::vector<PetscInt> &v) {
    v.assign(n, 0);
    H5Id dset(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose);
    H5Id fspace(dset < 0 ? -1 : H5Dget_space(dset), H5Sclose);
    const hsize_t cnt = n;
    H5Id mspace(H5Screate_simple(1, &cnt, nullptr), H5Sclose);
    return fspace >= 0 && mspace >= 0 && (n == 0 || H5Sselect_hyperslab(fspace, H5S_SELECT_SET, &off, nullptr, &cnt, nullptr) >= 0) && (n == 0 || H5Dread(dset, pint, mspace, fspace, H5P_DEFAULT, v.data()) >= 0);
  };
  std::vector<PetscInt> v;
  if (shape("joint") != std::vector<hsize_t>{J} || !read("joint", (hsize_t)rows.start, ids.size(), v) || v != ids) return not_it + "its joints are not the model's";
  for (const Dataset &d : StepDatasets()) {
    const std::vector<hsize_t> dims = shape(d.name);
    if (dims.empty() || dims[0] < (hsize_t)k || (d.width > 0 && dims[1] != J)) return not_it + "its dataset " + d.name + " does not hold " + std::to_string(k) + " steps of " + std::to_string(J) + " joints";
  }
  if (!read("step", 0, (size_t)k, v)) return not_it + "its steps cannot be read";
  for (PetscInt s = 0; s < k; ++s)
    if (v[(size_t)s] != s + 1) return not_it + "its row " + std::to_string(s) + " is step " + std::to_string(v[(size_t)s]) + ", not " + std::to_string(s + 1);
  return "";
}

} // namespace

PetscErrorCode JointOutputOptionsFromCommandLine(PetscOptionItems *PetscOptionsObject, JointOutputOptions *o)
{
  static const char *const modes[] = {"auto", "csv", "hdf5", "both", "JointOutput", "", nullptr};
  PetscEnum                m       = static_cast<PetscEnum>(o->mode);
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsEnum("-output_joints", "Joint results: csv (joints.csv, gathered to and written by rank 0), hdf5 (joints.h5, written in parallel by every rank), both, or auto: csv below -output_joints_auto_limit joints, hdf5 from it on", "", modes, m, &m, nullptr));
  o->mode = static_cast<JointOutput>(m);
  PetscCall(PetscOptionsInt("-output_joints_auto_limit", "With -output_joints auto, the number of joints from which joints.h5 replaces joints.csv", "", o->limit, &o->limit, nullptr));
  PetscCheck(o->limit >= 0, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-output_joints_auto_limit %" PetscInt_FMT ": a number of joints must be >= 0", o->limit);
  PetscFunctionReturn(0);
}

JointFiles JointFilesFor(const JointOutputOptions &o, size_t njoints)
{
  switch (o.mode) {
  case JointOutput::Csv:
    return {true, false};
  case JointOutput::Hdf5:
    return {false, true};
  case JointOutput::Both:
    return {true, true};
  default:
    return (PetscInt)njoints < o.limit ? JointFiles{true, false} : JointFiles{false, true};
  }
}

PetscErrorCode JointTableCreate(BoltnetAssembly a, const std::string &scene, const std::string &path, JointTable *t)
{
  hid_t                 file, pint;
  std::vector<PetscInt> ids; // of this rank's rows
  PetscFunctionBeginUser;
  t->path   = path;
  t->nsteps = 0;
  PetscCall(SetUpRows(a, &t->rows));
  PetscCall(RowIds(a, t->rows, &ids));
  const hsize_t J = (hsize_t)t->rows.nglobal;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // the caller's message names the file and the reason
  PetscCall(PetscViewerHDF5Open(a->comm, path.c_str(), FILE_MODE_WRITE, &t->viewer));
  PetscCall(PetscViewerHDF5GetFileId(t->viewer, &file));
  PetscCall(PetscDataTypeToHDF5DataType(PETSC_INT, &pint));
  bool ok = StringAttribute(file, "format", "boltnet joint table 1: joints.csv's quantities by step and joint (docs/output.md)") >= 0 && StringAttribute(file, "scene", scene) >= 0 &&
            StringAttribute(file, "frame", "joint frame (n, t1, t2) of each joint; force on node B, jump of B over A") >= 0;
  // joint (J): the ids in increasing order, each rank its rows.
  {
    const hsize_t dims[1] = {J};
    H5Id          space(H5Screate_simple(1, dims, nullptr), H5Sclose);
    H5Id          dset(space < 0 ? -1 : H5Dcreate2(file, "joint", pint, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
    ok = ok && dset >= 0 && StringAttribute(dset, "meaning", "user id of the joint of each row (increasing)") >= 0 &&
         WriteSlab(dset, pint, 1, dims, false, (hsize_t)t->rows.start, 0, (hsize_t)t->rows.nlocal, ids.data()) >= 0;
  }
  // state_names (5): the name of each state code, as joints.csv writes it.
  {
    const hsize_t dims[1] = {kStates};
    char          names[kStates][8]{};
    for (int s = 0; s < kStates; ++s) std::strncpy(names[s], stateName(static_cast<State>(s)), sizeof(names[s]) - 1);
    H5Id type(H5Tcopy(H5T_C_S1), H5Tclose);
    ok = ok && type >= 0 && H5Tset_size(type, sizeof(names[0])) >= 0;
    H5Id space(H5Screate_simple(1, dims, nullptr), H5Sclose);
    H5Id dset(!ok || space < 0 ? -1 : H5Dcreate2(file, "state_names", type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
    ok = ok && dset >= 0 && StringAttribute(dset, "meaning", "state_names[code] is the name of state code `code` (lib/joint/law.hpp)") >= 0 && WriteSlab(dset, type, 1, dims, false, 0, 0, a->rank == 0 ? kStates : 0, names) >= 0;
  }
  // The step datasets, empty: (0) or (0, J[, k]), the first dimension unlimited.
  for (const Dataset &d : StepDatasets()) {
    const int     rank     = d.width == 0 ? 1 : d.width == 1 ? 2 : 3;
    const hsize_t dims[3]  = {0, J, (hsize_t)d.width}, maxd[3] = {H5S_UNLIMITED, J ? J : H5S_UNLIMITED, (hsize_t)d.width}; // no joint: no fixed size 0
    const hsize_t chunk[3] = {(hsize_t)(rank == 1 ? 256 : 1), std::max<hsize_t>(1, std::min(J, kChunkRows)), (hsize_t)std::max(1, d.width)};
    H5Id          space(H5Screate_simple(rank, dims, maxd), H5Sclose);
    H5Id          dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    ok = ok && space >= 0 && dcpl >= 0 && H5Pset_chunk(dcpl, rank, chunk) >= 0;
    H5Id dset(!ok ? -1 : H5Dcreate2(file, d.name, d.type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose);
    ok = ok && dset >= 0 && StringAttribute(dset, "columns", d.columns) >= 0 && StringAttribute(dset, "units", d.units) >= 0 && StringAttribute(dset, "meaning", d.meaning) >= 0;
  }
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5 could not set up the datasets");
  PetscCall(PetscViewerFlush(t->viewer));
  PetscFunctionReturn(0);
}

PetscErrorCode JointTableCheck(BoltnetAssembly a, const std::string &path, PetscInt k, std::string *why)
{
  FieldSpace            rows;
  std::vector<PetscInt> ids;
  PetscFunctionBeginUser;
  PetscCall(SetUpRows(a, &rows));
  PetscCall(RowIds(a, rows, &ids));
  // A kill while a step's rows were written can leave the file shorter than its superblock says:
  // rank 0 extends it to that end (ExtendShortHDF5) before any rank opens it.
  std::string mine;
  if (a->rank == 0) mine = ExtendShortHDF5(path);
  if (!mine.empty()) mine = "Cannot restart: " + path + ": " + mine;
  PetscCallMPI(MPI_Barrier(a->comm));
  try {
    if (mine.empty()) mine = CheckRows(path, k, rows, ids);
  } catch (const std::exception &e) {
    mine = std::string("Cannot restart: ") + e.what();
  }
  PetscCall(FieldSpaceDestroy(rows));
  // The lowest complaining rank's reason, on every rank.
  PetscMPIInt first = mine.empty() ? a->size : a->rank, len;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, a->comm));
  why->clear();
  if (first == a->size) PetscFunctionReturn(0);
  len = (PetscMPIInt)mine.size();
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, first, a->comm));
  mine.resize((size_t)len);
  PetscCallMPI(MPI_Bcast(mine.data(), len, MPI_CHAR, first, a->comm));
  *why = mine;
  PetscFunctionReturn(0);
}

PetscErrorCode JointTableReopen(BoltnetAssembly a, const std::string &path, PetscInt k, JointTable *t)
{
  hid_t file;
  PetscFunctionBeginUser;
  t->path = path;
  PetscCall(SetUpRows(a, &t->rows));
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  PetscCall(PetscViewerHDF5Open(a->comm, path.c_str(), FILE_MODE_APPEND, &t->viewer));
  PetscCall(PetscViewerHDF5GetFileId(t->viewer, &file));
  // The steps after k (a killed run may have written some) are cut: every rank, as HDF5 changes a
  // file's structure in collective calls.
  for (const Dataset &d : StepDatasets()) {
    const hsize_t dims[3] = {(hsize_t)k, (hsize_t)t->rows.nglobal, (hsize_t)d.width};
    H5Id          dset(H5Dopen2(file, d.name, H5P_DEFAULT), H5Dclose);
    PetscCheck(dset >= 0 && H5Dset_extent(dset, dims) >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "HDF5 could not cut the dataset %s after step %" PetscInt_FMT, d.name, k);
  }
  PetscCall(PetscViewerFlush(t->viewer));
  t->nsteps = k;
  PetscFunctionReturn(0);
}

PetscErrorCode JointTableWriteStep(BoltnetAssembly a, JointTable *t, const StepInfo &info, const std::vector<JointRecord> &mine)
{
  std::vector<double> owned;
  Vec                 natural;
  hid_t               file;
  PetscFunctionBeginUser;
  owned.reserve(kPacked * mine.size());
  for (const JointRecord &r : mine) {
    owned.insert(owned.end(), {(double)r.state, (double)r.bearing}); // small integers: exact as reals
    owned.insert(owned.end(), r.jump, r.jump + 6);
    owned.insert(owned.end(), r.force, r.force + 6);
    owned.insert(owned.end(), r.slip, r.slip + 2);
  }
  // Each rank's joints to their rows: afterwards this rank holds rows [start, start + n).
  PetscCall(FieldSpaceNatural(a->comm, t->rows, kPacked, owned, &natural));
  const hsize_t      n = (hsize_t)t->rows.nlocal, J = (hsize_t)t->rows.nglobal, T = (hsize_t)t->nsteps;
  std::vector<int>   state(n), bearing(n);
  std::vector<double> jump(6 * n), force(6 * n), slip(2 * n);
  const PetscScalar *p;
  PetscCall(VecGetArrayRead(natural, &p));
  for (hsize_t i = 0; i < n; ++i) {
    const PetscScalar *row = p + kPacked * i;
    state[i]   = (int)row[0];
    bearing[i] = (int)row[1];
    std::copy(row + 2, row + 8, jump.begin() + 6 * i);
    std::copy(row + 8, row + 14, force.begin() + 6 * i);
    std::copy(row + 14, row + 16, slip.begin() + 2 * i);
  }
  PetscCall(VecRestoreArrayRead(natural, &p));
  const void *bufs[] = {&info.step, &info.load, state.data(), bearing.data(), jump.data(), force.data(), slip.data()};
  PetscCall(PetscViewerHDF5GetFileId(t->viewer, &file));
  int i = 0;
  for (const Dataset &d : StepDatasets()) {
    const int     rank    = d.width == 0 ? 1 : d.width == 1 ? 2 : 3;
    const hsize_t dims[3] = {T + 1, J, (hsize_t)d.width};
    H5Id          dset(H5Dopen2(file, d.name, H5P_DEFAULT), H5Dclose);
    // step and load: one value per step, written by rank 0.
    const herr_t e = dset < 0 ? -1 : rank == 1 ? WriteSlab(dset, d.type, 1, dims, true, T, 0, a->rank == 0 ? 1 : 0, bufs[i]) : WriteSlab(dset, d.type, rank, dims, true, T, (hsize_t)t->rows.start, n, bufs[i]);
    PetscCheck(e >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5 could not write the dataset %s", d.name);
    ++i;
  }
  // The step is on disk before the next is solved: a run that stops leaves whole steps.
  PetscCall(PetscViewerFlush(t->viewer));
  t->nsteps++;
  PetscFunctionReturn(0);
}

PetscErrorCode JointTableClose(JointTable *t)
{
  PetscFunctionBeginUser;
  PetscCall(PetscViewerDestroy(&t->viewer));
  PetscCall(FieldSpaceDestroy(t->rows));
  PetscFunctionReturn(0);
}

} // namespace boltnet
