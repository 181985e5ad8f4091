// XDMF 3 pieces (docs/output.md): XML text that stays valid for any string the user gives (a scene
// name), and the DataItems that name datasets of an HDF5 file with their exact dimensions.
#pragma once

#include <petscsys.h>

#include <string>

namespace boltnet::xdmf {

// s as XML character data or an attribute value: & < > " ' escaped; the characters XML 1.0 cannot
// hold at all (control characters other than tab, newline and carriage return, and bytes that are
// not UTF-8) replaced by '?'.
std::string Escape(const std::string &s);

// A DataItem naming dataset `path` of HDF5 file `file` with n rows of bs values. PETSc's VecView
// writes (n) for block size 1 and (n, bs) otherwise; ISView always writes (n, bs).
std::string Item(const std::string &file, const std::string &path, PetscInt n, PetscInt bs, bool integer);

// An Attribute element (type Scalar, Vector, Matrix; center Node or Cell) around one DataItem.
std::string Attribute(const std::string &name, const char type[], const char center[], const std::string &item);

} // namespace boltnet::xdmf
