#include "field/field_io.h"

#include "mesh/input_file.h"
#include "util/number_text.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace fcql {
namespace {

/// The least share of a field vector's length that must lie in its face's plane: sin 30°, i.e.
/// the vector is at most 60° out of the plane. A field written for the mesh lies in the plane up
/// to rounding (or a few degrees, if computed on a slightly different surface); a vector nearer
/// the normal gives its face a direction that rounding alone decides.
constexpr double kMinTangentialShare = 0.5;

std::string readWholeFile(const std::string& path) {
  std::string bytes, error;
  if (!readRegularFile(path, bytes, error)) throw FieldError(error + " (the field file)");
  return bytes;
}

// Splits text into lines and lines into whitespace-separated tokens, skipping blank lines and
// (for .ffield) lines starting with '#'. Keeps the 1-based line number for messages.
struct Line {
  int number;
  std::vector<std::string> tokens;
};

std::vector<Line> tokenize(const std::string& text, bool skipComments) {
  std::vector<Line> lines;
  std::istringstream in(text);
  std::string raw;
  int number = 0;
  while (std::getline(in, raw)) {
    ++number;
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    std::istringstream ls(raw);
    Line line{number, {}};
    std::string tok;
    while (ls >> tok) line.tokens.push_back(tok);
    if (line.tokens.empty()) continue;
    if (skipComments && line.tokens[0][0] == '#') continue;
    lines.push_back(std::move(line));
  }
  return lines;
}

double parseNumber(const std::string& token, const std::string& name, int line) {
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  double value = std::strtod(begin, &end);
  if (end == begin || *end != '\0')
    throw FieldError(name + ", line " + std::to_string(line) + ": '" + token + "' is not a number");
  if (!std::isfinite(value))
    throw FieldError(name + ", line " + std::to_string(line) + ": '" + token + "' is not a finite number");
  return value;
}

long parseCount(const Line& line, const std::string& name, const std::string& what) {
  if (line.tokens.size() != 1)
    throw FieldError(name + ", line " + std::to_string(line.number) + ": expected " + what);
  const std::string& tok = line.tokens[0];
  char* end = nullptr;
  long value = std::strtol(tok.c_str(), &end, 10);
  if (end == tok.c_str() || *end != '\0' || value < 0)
    throw FieldError(name + ", line " + std::to_string(line.number) + ": expected " + what + ", found '" + tok + "'");
  return value;
}

void checkFaceCount(long count, const SurfaceMesh& mesh, const std::string& name) {
  if (count != mesh.numFaces())
    throw FieldError(name + ": the field has " + std::to_string(count) + " faces but the mesh has " +
                     std::to_string(mesh.numFaces()));
}

// The vector's part in the face's plane, normalised. A vector more than 60° out of the plane
// gives no reliable direction in the face: it is rejected, as a zero vector is. Components are scaled first so that huge ones (1e300) do not
// overflow.
Vec3 faceVector(const SurfaceMesh& mesh, const Vec3& w, int f, const std::string& name, int line) {
  const double largest = w.cwiseAbs().maxCoeff();
  auto fail = [&](const std::string& what) {
    return FieldError(name + ", line " + std::to_string(line) + ": the vector of face " + std::to_string(f) + " " + what);
  };
  if (!(largest > 0)) throw fail("is zero");
  const Vec3 unit = w / largest;
  const Vec3& n = mesh.faceNormal(f);
  const Vec3 t = unit - n * n.dot(unit);
  if (!(t.norm() > kMinTangentialShare * unit.norm()))
    throw fail("is more than 60 degrees out of the face's plane (nearly along its normal), so it gives no direction in the face");
  return t.normalized();
}

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw FieldError(path + ": cannot write the field file");
  out << text;
  out.flush();
  if (!out) throw FieldError(path + ": error while writing the field file");
}

std::string extensionOf(const std::string& path) {
  auto dot = path.find_last_of('.');
  return dot == std::string::npos ? "" : path.substr(dot + 1);
}

}  // namespace

CrossField parseFField(const SurfaceMesh& mesh, const std::string& text, const std::string& name) {
  std::vector<Line> lines = tokenize(text, true);
  if (lines.empty()) throw FieldError(name + ": the field file is empty");
  std::size_t at = 0;
  if (lines[at].tokens.size() == 2 && lines[at].tokens[0] == "target" && lines[at].tokens[1] == "frame") ++at;
  if (at >= lines.size()) throw FieldError(name + ": truncated field file: the face count is missing");
  long count = parseCount(lines[at], name, "the number of faces");
  checkFaceCount(count, mesh, name);
  ++at;
  // Optional header line "k1 k2 k1v_x k1v_y k1v_z k2v_x k2v_y k2v_z".
  if (at < lines.size() && !lines[at].tokens.empty() && lines[at].tokens[0] == "k1") ++at;
  CrossField field;
  field.u.resize(mesh.numFaces());
  for (int f = 0; f < mesh.numFaces(); ++f, ++at) {
    if (at >= lines.size())
      throw FieldError(name + ": truncated field file: " + std::to_string(f) + " of " +
                       std::to_string(mesh.numFaces()) + " faces present");
    const Line& line = lines[at];
    if (line.tokens.size() != 8)
      throw FieldError(name + ", line " + std::to_string(line.number) + ": expected 8 numbers (k1 k2 d1 d2), found " +
                       std::to_string(line.tokens.size()) + " values");
    double v[8];
    for (int i = 0; i < 8; ++i) v[i] = parseNumber(line.tokens[i], name, line.number);
    // vcglib reads the first triple into PD2 and the second into PD1; for a cross field they are
    // interchangeable up to a quarter turn, so the first direction is used as u.
    Vec3 d1(v[2], v[3], v[4]);
    if (d1.norm() == 0) d1 = Vec3(v[5], v[6], v[7]);
    field.u[f] = faceVector(mesh, d1, f, name, line.number);
  }
  if (at < lines.size())
    throw FieldError(name + ", line " + std::to_string(lines[at].number) +
                     ": unexpected data after the last face (the field has more faces than the mesh)");
  return field;
}

CrossField parseRosy(const SurfaceMesh& mesh, const std::string& text, const std::string& name) {
  std::vector<Line> lines = tokenize(text, true);
  if (lines.empty()) throw FieldError(name + ": the field file is empty");
  long count = parseCount(lines[0], name, "the number of faces");
  checkFaceCount(count, mesh, name);
  if (lines.size() < 2) throw FieldError(name + ": truncated field file: the symmetry (4) is missing");
  long symmetry = parseCount(lines[1], name, "the symmetry order");
  if (symmetry != 4)
    throw FieldError(name + ", line " + std::to_string(lines[1].number) + ": a " + std::to_string(symmetry) +
                     "-RoSy field is not a cross field (expected 4)");
  CrossField field;
  field.u.resize(mesh.numFaces());
  std::size_t at = 2;
  for (int f = 0; f < mesh.numFaces(); ++f, ++at) {
    if (at >= lines.size())
      throw FieldError(name + ": truncated field file: " + std::to_string(f) + " of " +
                       std::to_string(mesh.numFaces()) + " faces present");
    const Line& line = lines[at];
    if (line.tokens.size() != 3)
      throw FieldError(name + ", line " + std::to_string(line.number) + ": expected 3 numbers, found " +
                       std::to_string(line.tokens.size()) + " values");
    Vec3 w(parseNumber(line.tokens[0], name, line.number), parseNumber(line.tokens[1], name, line.number),
           parseNumber(line.tokens[2], name, line.number));
    field.u[f] = faceVector(mesh, w, f, name, line.number);
  }
  if (at < lines.size())
    throw FieldError(name + ", line " + std::to_string(lines[at].number) +
                     ": unexpected data after the last face (the field has more faces than the mesh)");
  return field;
}

CrossField loadFFieldFile(const SurfaceMesh& mesh, const std::string& path) {
  return parseFField(mesh, readWholeFile(path), path);
}

CrossField loadRosyFile(const SurfaceMesh& mesh, const std::string& path) {
  return parseRosy(mesh, readWholeFile(path), path);
}

CrossField loadField(const SurfaceMesh& mesh, const std::string& path) {
  std::string ext = extensionOf(path);
  if (ext == "ffield") return loadFFieldFile(mesh, path);
  if (ext == "rosy") return loadRosyFile(mesh, path);
  throw FieldError(path + ": unknown field format '." + ext + "' (use .ffield or .rosy)");
}

void saveFField(const SurfaceMesh& mesh, const CrossField& field, const std::string& path) {
  if (field.numFaces() != mesh.numFaces()) throw FieldError("the field does not match the mesh");
  std::string out = "# frame generated with VCG\ntarget frame\n" + std::to_string(mesh.numFaces()) + "\n";
  out += "k1 k2 k1v_x k1v_y k1v_z k2v_x k2v_y k2v_z\n";
  for (int f = 0; f < mesh.numFaces(); ++f) {
    Vec3 d1 = field.u[f], d2 = field.direction(mesh, f, 1);
    out += "1 1";
    for (const Vec3* d : {&d1, &d2})
      for (int c = 0; c < 3; ++c) {
        out += ' ';
        appendNumber(out, (*d)[c], 9);
      }
    out += '\n';
  }
  writeFile(path, out);
}

void saveRosy(const SurfaceMesh& mesh, const CrossField& field, const std::string& path) {
  if (field.numFaces() != mesh.numFaces()) throw FieldError("the field does not match the mesh");
  std::string out = std::to_string(mesh.numFaces()) + "\n4\n";
  for (int f = 0; f < mesh.numFaces(); ++f) {
    for (int c = 0; c < 3; ++c) {
      if (c > 0) out += ' ';
      appendNumber(out, field.u[f][c], 9);
    }
    out += '\n';
  }
  writeFile(path, out);
}

}  // namespace fcql
