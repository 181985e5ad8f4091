// An HDF5 identifier closed when it goes out of scope (RAII for the HDF5 C API calls that PETSc's
// viewer does not cover: joints.h5's tables, fields.h5 rebuilt on a restart).
#pragma once

#include <hdf5.h>
#include <string>

namespace boltnet {

struct H5Id {
  hid_t id;
  herr_t (*close)(hid_t);
  H5Id(hid_t i, herr_t (*c)(hid_t)) : id(i), close(c) {}
  H5Id(const H5Id &)            = delete;
  H5Id &operator=(const H5Id &) = delete;
  ~H5Id()
  {
    if (id >= 0) close(id);
  }
  operator hid_t() const { return id; }
};

// A file that a kill left shorter than the end of file its HDF5 superblock records: HDF5 had
// allocated space for what it was writing (a step's fields, a row of joints.h5) and recorded it
// before the data reached the disk, and it then refuses the whole file ("truncated file"). The file
// is extended with zeros to that end, so that HDF5 opens it again and the restart can remove what
// was being written. A file that is not short, not there or not HDF5 is left as it is. "" or why not.
std::string ExtendShortHDF5(const std::string &path);

} // namespace boltnet
