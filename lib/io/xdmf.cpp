// XDMF 3 pieces (xdmf.hpp).
#include "io/xdmf.hpp"

#include <sstream>

namespace boltnet::xdmf {
namespace {

// The length of the valid UTF-8 sequence at s[i] (0: not valid), without overlong forms,
// surrogates or code points above U+10FFFF.
size_t Utf8Length(const std::string &s, size_t i)
{
  const unsigned char c = (unsigned char)s[i];
  size_t              n;
  unsigned            cp;
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) n = 2, cp = c & 0x1F;
  else if (c >= 0xE0 && c <= 0xEF) n = 3, cp = c & 0x0F;
  else if (c >= 0xF0 && c <= 0xF4) n = 4, cp = c & 0x07;
  else return 0;
  if (i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k) {
    const unsigned char d = (unsigned char)s[i + k];
    if ((d & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (d & 0x3F);
  }
  if ((n == 3 && (cp < 0x800 || (cp >= 0xD800 && cp <= 0xDFFF))) || (n == 4 && (cp < 0x10000 || cp > 0x10FFFF))) return 0;
  if (cp == 0xFFFE || cp == 0xFFFF) return 0; // not XML characters
  return n;
}

} // namespace

std::string Escape(const std::string &s)
{
  std::string o;
  for (size_t i = 0; i < s.size();) {
    const unsigned char c = (unsigned char)s[i];
    const size_t        n = Utf8Length(s, i);
    if (n == 0 || (c < 0x20 && c != '\t' && c != '\n' && c != '\r')) {
      o += '?';
      i += n ? n : 1;
      continue;
    }
    switch (c) {
    case '&': o += "&amp;"; break;
    case '<': o += "&lt;"; break;
    case '>': o += "&gt;"; break;
    case '"': o += "&quot;"; break;
    case '\'': o += "&apos;"; break;
    case '\t': o += "&#9;"; break; // attribute values normalise raw whitespace
    case '\n': o += "&#10;"; break;
    case '\r': o += "&#13;"; break;
    default: o.append(s, i, n);
    }
    i += n;
  }
  return o;
}

std::string Item(const std::string &file, const std::string &path, PetscInt n, PetscInt bs, bool integer)
{
  std::ostringstream o;
  o << "<DataItem Dimensions=\"" << n;
  if (bs > 1 || integer) o << " " << bs;
  o << "\" DataType=\"" << (integer ? "Int" : "Float") << "\" Precision=\"" << (integer ? sizeof(PetscInt) : sizeof(PetscReal)) << "\" Format=\"HDF\">" << Escape(file) << ":" << Escape(path) << "</DataItem>";
  return o.str();
}

std::string Attribute(const std::string &name, const char type[], const char center[], const std::string &item)
{
  return "      <Attribute Name=\"" + Escape(name) + "\" AttributeType=\"" + type + "\" Center=\"" + center + "\">\n        " + item + "\n      </Attribute>\n";
}

} // namespace boltnet::xdmf
