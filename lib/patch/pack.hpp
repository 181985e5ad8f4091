// Shell patches, seams and meshes as bytes: the layout of a part is made on the rank that holds the
// part (patch/layout.hpp), and each piece is then sent to the ranks that own it or attach a joint to
// it (network/build.cpp). Pure C++: the bytes are only ever read back by the same build of boltnet
// (no versioning, no byte-order conversion), within one MPI job.
#pragma once

#include "patch/patch.hpp"

#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace boltnet {

// Appends values to a byte buffer: plain values whole, vectors and strings by their length first.
class PackWriter {
public:
  explicit PackWriter(std::vector<char> &out) : out_(out) {}
  template <class T> void Put(const T &v)
  {
    static_assert(std::is_trivially_copyable<T>::value, "pack plain values only");
    const char *p = reinterpret_cast<const char *>(&v);
    out_.insert(out_.end(), p, p + sizeof v);
  }
  template <class T> void Put(const std::vector<T> &v)
  {
    static_assert(std::is_trivially_copyable<T>::value, "pack vectors of plain values only");
    Put((std::uint64_t)v.size());
    const char *p = reinterpret_cast<const char *>(v.data());
    out_.insert(out_.end(), p, p + v.size() * sizeof(T));
  }
  void Put(const std::string &s)
  {
    Put((std::uint64_t)s.size());
    out_.insert(out_.end(), s.begin(), s.end());
  }

private:
  std::vector<char> &out_;
};

// Reads back what a PackWriter wrote, in the same order; throws std::runtime_error if the buffer
// ends early (a programming error: both sides run the same code).
class PackReader {
public:
  PackReader(const char *p, std::size_t n) : p_(p), end_(p + n) {}
  template <class T> void Get(T &v)
  {
    static_assert(std::is_trivially_copyable<T>::value, "unpack plain values only");
    Take(&v, sizeof v);
  }
  template <class T> void Get(std::vector<T> &v)
  {
    std::uint64_t n;
    Get(n);
    if (n > (std::uint64_t)(end_ - p_) / (sizeof(T) ? sizeof(T) : 1)) throw std::runtime_error("a packed layout ends early");
    v.resize(n);
    Take(v.data(), n * sizeof(T));
  }
  void Get(std::string &s)
  {
    std::uint64_t n;
    Get(n);
    if (n > (std::uint64_t)(end_ - p_)) throw std::runtime_error("a packed layout ends early");
    s.assign(p_, p_ + n);
    p_ += n;
  }
  bool Done() const { return p_ == end_; }

private:
  void Take(void *dst, std::size_t n)
  {
    if (n > (std::size_t)(end_ - p_)) throw std::runtime_error("a packed layout ends early");
    if (n) std::memcpy(dst, p_, n);
    p_ += n;
  }
  const char *p_, *end_;
};

void Pack(PackWriter &w, const ShellMesh &m);
void Unpack(PackReader &r, ShellMesh &m);
// The whole patch; carried_index is rebuilt from carried on the way back.
void Pack(PackWriter &w, const ShellPatch &p);
void Unpack(PackReader &r, ShellPatch &p);
void Pack(PackWriter &w, const Seam &s);
void Unpack(PackReader &r, Seam &s);

} // namespace boltnet
