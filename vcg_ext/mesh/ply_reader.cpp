#include "mesh/ply_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace fcql {
namespace {

enum class Format { Ascii, BinaryLittle, BinaryBig };

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool typeFromName(const std::string& word, Type& type) {
  static const struct {
    const char* name;
    Type type;
  } kNames[] = {{"char", Type::Int8},     {"int8", Type::Int8},     {"uchar", Type::UInt8},    {"uint8", Type::UInt8},
                {"short", Type::Int16},   {"int16", Type::Int16},   {"ushort", Type::UInt16},  {"uint16", Type::UInt16},
                {"int", Type::Int32},     {"int32", Type::Int32},   {"uint", Type::UInt32},    {"uint32", Type::UInt32},
                {"float", Type::Float32}, {"float32", Type::Float32}, {"double", Type::Float64}, {"float64", Type::Float64}};
  for (const auto& n : kNames)
    if (word == n.name) {
      type = n.type;
      return true;
    }
  return false;
}

std::size_t sizeOf(Type t) {
  switch (t) {
    case Type::Int8: case Type::UInt8: return 1;
    case Type::Int16: case Type::UInt16: return 2;
    case Type::Int32: case Type::UInt32: case Type::Float32: return 4;
    case Type::Float64: return 8;
  }
  return 8;
}

bool isInteger(Type t) { return t != Type::Float32 && t != Type::Float64; }

struct Property {
  std::string name;
  Type type = Type::Float64;     ///< the value's type, or a list's item type
  bool list = false;
  Type countType = Type::UInt8;  ///< a list's count type (an integer type)
};

struct Element {
  std::string name;
  long long count = 0;
  int headerLine = 0;
  std::vector<Property> properties;

  int find(const std::string& property) const {
    for (std::size_t i = 0; i < properties.size(); ++i)
      if (properties[i].name == property) return int(i);
    return -1;
  }
  /// The fewest bytes one record can take: a list may be empty; an ASCII value is at least one
  /// character and one separator.
  std::size_t minRecordBytes(Format format) const {
    std::size_t bytes = 0;
    for (const Property& p : properties)
      bytes += format == Format::Ascii ? 2 : sizeOf(p.list ? p.countType : p.type);
    return bytes;
  }
};

std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

std::string plural(const std::string& element) {
  if (element == "vertex") return "vertices";
  if (element == "face") return "faces";
  return "'" + element + "' elements";
}

/// Reads the body, record by record, in one of the three formats.
class BodyReader {
public:
  BodyReader(const std::string& bytes, std::size_t start, int startLine, Format format, const std::string& name)
      : bytes_(bytes), at_(start), line_(startLine), format_(format), name_(name) {}

  [[noreturn]] void fail(const std::string& what) const {
    if (format_ == Format::Ascii) throw MeshError(name_ + ", line " + std::to_string(line_) + ": " + what);
    throw MeshError(name_ + ", byte " + std::to_string(at_) + ": " + what);
  }

  /// A value of type `t` as a double (integers are exact up to 2^53, which covers every type).
  double value(Type t, const char* what) {
    if (format_ == Format::Ascii) return asciiValue(t, what);
    return binaryValue(t, what);
  }

  /// Skips `count` values of type `t` (a list's items).
  void skip(Type t, long long count, const char* what) {
    if (count <= 0) return;
    if (format_ == Format::Ascii) {
      for (long long i = 0; i < count; ++i) asciiValue(t, what);
      return;
    }
    const std::size_t left = bytes_.size() - at_;
    if (static_cast<unsigned long long>(count) > left / sizeOf(t)) fail(std::string("the file ends inside ") + what);
    at_ += std::size_t(count) * sizeOf(t);
  }

  /// After the last element: only white space may follow in ASCII (binary files may be padded).
  void finish() {
    if (format_ != Format::Ascii) return;
    skipSpace();
    if (at_ < bytes_.size()) fail("unexpected data after the last element (the header declares fewer records)");
  }

private:
  void skipSpace() {
    while (at_ < bytes_.size()) {
      char c = bytes_[at_];
      if (c == '\n') {
        ++line_;
      } else if (c != ' ' && c != '\t' && c != '\r') {
        break;
      }
      ++at_;
    }
  }

  double asciiValue(Type t, const char* what) {
    skipSpace();
    if (at_ >= bytes_.size()) fail(std::string("the file ends inside ") + what);
    std::size_t start = at_;
    while (at_ < bytes_.size() && !std::strchr(" \t\r\n", bytes_[at_])) ++at_;
    std::string token = bytes_.substr(start, std::min<std::size_t>(at_ - start, 64));
    if (at_ - start > 64) fail(std::string("a value of ") + what + " is too long ('" + token + "...')");
    char* end = nullptr;
    if (isInteger(t)) {
      errno = 0;
      long long v = std::strtoll(token.c_str(), &end, 10);
      if (end == token.c_str() || *end != '\0' || errno == ERANGE)
        fail(std::string("'") + token + "' in " + what + " is not an integer");
      checkRange(t, double(v), token, what);
      return double(v);
    }
    double v = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0') fail(std::string("'") + token + "' in " + what + " is not a number");
    return v;
  }

  void checkRange(Type t, double v, const std::string& token, const char* what) const {
    double lo = 0, hi = 0;
    switch (t) {
      case Type::Int8: lo = -128, hi = 127; break;
      case Type::UInt8: lo = 0, hi = 255; break;
      case Type::Int16: lo = -32768, hi = 32767; break;
      case Type::UInt16: lo = 0, hi = 65535; break;
      case Type::Int32: lo = -2147483648.0, hi = 2147483647.0; break;
      case Type::UInt32: lo = 0, hi = 4294967295.0; break;
      default: return;
    }
    if (v < lo || v > hi) fail(std::string("'") + token + "' in " + what + " is out of range for its declared type");
  }

  double binaryValue(Type t, const char* what) {
    const std::size_t n = sizeOf(t);
    if (bytes_.size() - at_ < n) fail(std::string("the file ends inside ") + what);
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + at_, n);
    at_ += n;
    const bool little = format_ == Format::BinaryLittle;
    std::uint64_t bits = 0;
    for (std::size_t i = 0; i < n; ++i) bits |= std::uint64_t(raw[little ? i : n - 1 - i]) << (8 * i);
    switch (t) {
      case Type::Int8: return double(std::int8_t(bits));
      case Type::UInt8: return double(std::uint8_t(bits));
      case Type::Int16: return double(std::int16_t(bits));
      case Type::UInt16: return double(std::uint16_t(bits));
      case Type::Int32: return double(std::int32_t(bits));
      case Type::UInt32: return double(std::uint32_t(bits));
      case Type::Float32: {
        std::uint32_t b = std::uint32_t(bits);
        float f;
        std::memcpy(&f, &b, 4);
        return double(f);
      }
      case Type::Float64: {
        double d;
        std::memcpy(&d, &bits, 8);
        return d;
      }
    }
    return 0;
  }

  const std::string& bytes_;
  std::size_t at_;
  int line_;
  Format format_;
  const std::string& name_;
};

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  std::size_t bodyStart = 0;
  int bodyLine = 0;  ///< the line number of the body's first line (ASCII)
};

Header readHeader(const std::string& bytes, const std::string& name) {
  Header h;
  bool sawFormat = false;
  std::size_t at = 0;
  int line = 0;
  auto fail = [&](const std::string& what) -> MeshError {
    return MeshError(name + ", line " + std::to_string(line) + ": " + what);
  };
  for (;;) {
    std::size_t end = bytes.find('\n', at);
    if (end == std::string::npos) {
      if (line == 0) throw MeshError(name + ": not a PLY file (no line break in the first bytes)");
      throw MeshError(name + ": the PLY header has no end_header line");
    }
    ++line;
    std::string text = bytes.substr(at, end - at);
    at = end + 1;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (line == 1) {
      if (text != "ply") throw MeshError(name + ": not a PLY file (it does not start with the line 'ply')");
      continue;
    }
    std::vector<std::string> w = words(text);
    if (w.empty()) continue;  // a blank header line carries nothing
    const std::string& key = w[0];
    if (key == "comment" || key == "obj_info") continue;
    if (key == "format") {
      if (sawFormat) throw fail("a second format line");
      if (w.size() != 3) throw fail("the format line must be 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      if (w[1] == "ascii") h.format = Format::Ascii;
      else if (w[1] == "binary_little_endian") h.format = Format::BinaryLittle;
      else if (w[1] == "binary_big_endian") h.format = Format::BinaryBig;
      else throw fail("unknown PLY format '" + w[1] + "'");
      if (w[2] != "1.0" && w[2] != "1") throw fail("PLY version '" + w[2] + "' is not supported (1.0 only)");
      sawFormat = true;
    } else if (key == "element") {
      if (w.size() != 3) throw fail("an element line must be 'element NAME COUNT'");
      for (const Element& e : h.elements)
        if (e.name == w[1]) throw fail("element '" + w[1] + "' is declared twice");
      const std::string& count = w[2];
      if (count.empty() || count.size() > 10 || count.find_first_not_of("0123456789") != std::string::npos)
        throw fail("the count of element '" + w[1] + "' must be a non-negative integer, not '" + count + "'");
      Element e;
      e.name = w[1];
      e.count = std::strtoll(count.c_str(), nullptr, 10);
      if (e.count > std::numeric_limits<int>::max())
        throw fail("element '" + w[1] + "' declares " + count + " records, more than this reader can index");
      e.headerLine = line;
      h.elements.push_back(e);
    } else if (key == "property") {
      if (h.elements.empty()) throw fail("a property before any element");
      Property p;
      if (w.size() >= 2 && w[1] == "list") {
        if (w.size() != 5) throw fail("a list property must be 'property list COUNT_TYPE ITEM_TYPE NAME'");
        p.list = true;
        if (!typeFromName(w[2], p.countType)) throw fail("unknown PLY type '" + w[2] + "'");
        if (!isInteger(p.countType)) throw fail("a list's count type must be an integer type, not '" + w[2] + "'");
        if (!typeFromName(w[3], p.type)) throw fail("unknown PLY type '" + w[3] + "'");
        p.name = w[4];
      } else {
        if (w.size() != 3) throw fail("a property line must be 'property TYPE NAME'");
        if (!typeFromName(w[1], p.type)) throw fail("unknown PLY type '" + w[1] + "'");
        p.name = w[2];
      }
      Element& e = h.elements.back();
      if (e.find(p.name) >= 0) throw fail("property '" + p.name + "' of element '" + e.name + "' is declared twice");
      e.properties.push_back(p);
    } else if (key == "end_header") {
      if (w.size() != 1) throw fail("unexpected words after end_header");
      if (!sawFormat) throw fail("the header has no format line");
      h.bodyStart = at;
      h.bodyLine = line + 1;
      return h;
    } else {
      throw fail("unknown PLY header keyword '" + key + "'");
    }
  }
}

/// Every declared count against the bytes that follow the header, before anything is allocated.
void checkCounts(const Header& h, std::size_t bodyBytes, const std::string& name) {
  std::size_t left = bodyBytes;
  for (const Element& e : h.elements) {
    const std::size_t record = e.minRecordBytes(h.format);
    if (record == 0 || e.count == 0) continue;
    const std::size_t most = left / record;
    if (static_cast<unsigned long long>(e.count) > most)
      throw MeshError(name + ", line " + std::to_string(e.headerLine) + ": declares " + std::to_string(e.count) +
                      " " + plural(e.name) + " but the file holds at most " + std::to_string(most));
    left -= std::size_t(e.count) * record;
  }
}

}  // namespace

PlyPolygons parsePly(const std::string& bytes, const std::string& name, const std::vector<std::string>& faceProperties) {
  const Header h = readHeader(bytes, name);
  checkCounts(h, bytes.size() - h.bodyStart, name);
  const Element* vertex = nullptr;
  const Element* face = nullptr;
  for (const Element& e : h.elements) {
    if (e.name == "vertex") vertex = &e;
    if (e.name == "face") face = &e;
  }
  if (face == nullptr || face->count == 0) throw MeshError(name + ": the file holds no faces");
  if (vertex == nullptr) throw MeshError(name + ": the file has faces but no vertex element");
  int ix = vertex->find("x"), iy = vertex->find("y"), iz = vertex->find("z");
  for (int i : {ix, iy, iz})
    if (i < 0 || vertex->properties[i].list)
      throw MeshError(name + ", line " + std::to_string(vertex->headerLine) +
                      ": the vertex element needs scalar properties x, y and z");
  int indexList = face->find("vertex_indices");
  if (indexList < 0) indexList = face->find("vertex_index");
  if (indexList < 0 || !face->properties[indexList].list || !isInteger(face->properties[indexList].type))
    throw MeshError(name + ", line " + std::to_string(face->headerLine) +
                    ": the face element needs an integer list property vertex_indices");
  std::vector<int> kept(face->properties.size(), -1);  // property -> index into faceValues
  for (std::size_t k = 0; k < faceProperties.size(); ++k) {
    int p = face->find(faceProperties[k]);
    if (p < 0 || face->properties[p].list)
      throw MeshError(name + ", line " + std::to_string(face->headerLine) + ": the face element has no scalar property '" +
                      faceProperties[k] + "'");
    kept[p] = int(k);
  }
  PlyPolygons out;
  out.positions.reserve(std::size_t(vertex->count));
  out.faceStart.reserve(std::size_t(face->count) + 1);
  out.faceValues.assign(faceProperties.size(), {});
  for (auto& values : out.faceValues) values.reserve(std::size_t(face->count));
  const long long numVertices = vertex->count;

  BodyReader body(bytes, h.bodyStart, h.bodyLine, h.format, name);
  for (const Element& e : h.elements) {
    if (e.properties.empty()) continue;  // records of no bytes
    const bool isVertex = &e == vertex, isFace = &e == face;
    for (long long r = 0; r < e.count; ++r) {
      double xyz[3] = {0, 0, 0};
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const Property& p = e.properties[k];
        if (!p.list) {
          const double v = body.value(p.type, isVertex ? "the vertex records" : isFace ? "the face records" : "a record");
          if (isVertex) {
            if (int(k) == ix) xyz[0] = v;
            if (int(k) == iy) xyz[1] = v;
            if (int(k) == iz) xyz[2] = v;
          } else if (isFace && kept[k] >= 0) {
            if (!std::isfinite(v)) body.fail("face " + std::to_string(r) + " has a non-finite '" + p.name + "'");
            out.faceValues[kept[k]].push_back(v);
          }
          continue;
        }
        const double count = body.value(p.countType, "a list's count");
        if (count < 0) body.fail("a list of " + plural(e.name) + " record " + std::to_string(r) + " has a negative count");
        if (!(isFace && int(k) == indexList)) {
          body.skip(p.type, static_cast<long long>(count), "a list");
          continue;
        }
        if (count < 3)
          body.fail("face " + std::to_string(r) + " has " + std::to_string(static_cast<long long>(count)) +
                    " corners (a face needs at least 3)");
        for (long long c = 0; c < static_cast<long long>(count); ++c) {
          const double index = body.value(p.type, "the face records");
          if (index < 0 || index >= double(numVertices))
            body.fail("face " + std::to_string(r) + " refers to vertex " + std::to_string(static_cast<long long>(index)) +
                      ", out of range (the file declares " + std::to_string(numVertices) + " vertices)");
          out.corners.push_back(int(index));
        }
        if (out.corners.size() > std::size_t(std::numeric_limits<int>::max()))
          body.fail("more face corners than this reader can index");
        out.faceStart.push_back(int(out.corners.size()));
      }
      if (isVertex) {
        if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
          body.fail("vertex " + std::to_string(r) + " has a coordinate that is not finite");
        out.positions.emplace_back(xyz[0], xyz[1], xyz[2]);
      }
    }
  }
  body.finish();
  return out;
}

}  // namespace fcql
