// ExtendShortHDF5 (io/h5id.hpp). The superblock's layout is the HDF5 File Format Specification's
// (section II.A, "Disk Format: Level 0A - Format Signature and Superblock", versions 0 to 3): the
// signature at byte 0, 512, 1024, 2048, ... (after a user block), then the version, the size of
// offsets, and the base address and the end-of-file address, the latter relative to the former.
#include "io/h5id.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace boltnet {
namespace {

std::uint64_t LittleEndian(const unsigned char *p, int n)
{
  std::uint64_t v = 0;
  for (int i = n - 1; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

} // namespace

std::string ExtendShortHDF5(const std::string &path)
{
  static const unsigned char signature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
  std::error_code            ec;
  const std::uintmax_t       size = std::filesystem::file_size(path, ec);
  if (ec) return ""; // not there: opening it says so
  std::ifstream in(path, std::ios::binary);
  for (std::uintmax_t at = 0; at < size; at = at ? 2 * at : 512) {
    std::array<unsigned char, 64> b{};
    in.clear();
    in.seekg((std::streamoff)at);
    in.read(reinterpret_cast<char *>(b.data()), b.size());
    const std::streamsize got = in.gcount();
    if (got < 16 || std::memcmp(b.data(), signature, sizeof signature)) continue;
    // Versions 0 and 1: the size of offsets at byte 13, the base address at 24 (28 in version 1);
    // versions 2 and 3: at 9 and 12. The end-of-file address follows the base and one more address.
    const int version = b[8];
    if (version > 3) return ""; // a format this code does not know: HDF5 says what it makes of it
    const int offsets = version <= 1 ? b[13] : b[9], base_at = version == 0 ? 24 : version == 1 ? 28 : 12;
    if ((offsets != 2 && offsets != 4 && offsets != 8) || base_at + 3 * offsets > got) return "";
    const std::uintmax_t end = LittleEndian(&b[base_at], offsets) + LittleEndian(&b[base_at + 2 * offsets], offsets);
    if (end <= size) return "";
    // A kill leaves unwritten what HDF5 was writing then, a small part of the file; a superblock that
    // asks for much more than the file holds was damaged otherwise, and is not followed.
    if (end > 2 * size + (std::uintmax_t{64} << 20))
      return "its superblock records an end of file at byte " + std::to_string(end) + ", far beyond its " + std::to_string(size) + " bytes: not a file that a kill cut short";
    in.close();
    std::filesystem::resize_file(path, end, ec);
    if (ec) return "it is " + std::to_string(end - size) + " bytes shorter than its superblock records, and extending it failed: " + ec.message();
    return "";
  }
  return "";
}

} // namespace boltnet
