// An HDF5 identifier closed when it goes out of scope (RAII for the HDF5 C API calls that PETSc's
// viewer does not cover: joints.h5's tables, fields.h5 rebuilt on a restart).
#pragma once

#include <hdf5.h>

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

} // namespace boltnet
