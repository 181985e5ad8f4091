// Hashes: FNV-1a over bytes, to identify a model, a layout (patch/layout.hpp) or an option list
// (io/checkpoint.hpp), and an order-free checksum of indexed values, to find a damaged checkpoint.
// Neither is a cryptographic hash: they guard against mistakes and damage, not against forgery.
#pragma once
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace boltnet {

// FNV-1a, 64 bits (Fowler, Noll, Vo), fed field by field (never a struct with padding whole).
struct Hasher {
  std::uint64_t h = 14695981039346656037ull;
  void Bytes(const void *p, std::size_t n)
  {
    const unsigned char *c = static_cast<const unsigned char *>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 1099511628211ull;
  }
  template <class T> void Add(const T &v)
  {
    static_assert(std::is_arithmetic<T>::value || std::is_enum<T>::value, "hash fields one by one");
    Bytes(&v, sizeof v);
  }
  template <class T, std::size_t N> void Add(const std::array<T, N> &v)
  {
    for (const T &x : v) Add(x);
  }
  template <class T> void Add(const std::vector<T> &v)
  {
    Add((std::uint64_t)v.size());
    for (const T &x : v) Add(x);
  }
  void Add(const std::string &s)
  {
    Add((std::uint64_t)s.size());
    Bytes(s.data(), s.size());
  }
  std::string Hex() const
  {
    char s[17];
    std::snprintf(s, sizeof s, "%016llx", (unsigned long long)h);
    return s;
  }
};

// SplitMix64's finaliser (Steele, Lea, Flood 2014): a bijective mix of 64 bits.
inline std::uint64_t Mix64(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// The checksum term of value v at position i of array `tag`: summed (mod 2^64) over all entries, in any
// order and over any split between ranks, it changes with any entry's bits or position.
inline std::uint64_t ChecksumTerm(std::uint64_t tag, std::uint64_t i, double v)
{
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  return Mix64(Mix64((tag << 48) ^ i) ^ bits);
}

} // namespace boltnet
