#include "layout/layout_io.h"

#include "tracing/polyline_io.h"

#include <cmath>
#include <sstream>

namespace fcql {

std::array<unsigned char, 3> patchColour(int i) {
  // Golden-ratio hues at two saturations: neighbours in id get distant colours.
  double h = std::fmod(0.618033988749895 * i, 1.0) * 6.0;
  double s = (i % 2) ? 0.55 : 0.8, v = (i % 3 == 0) ? 0.95 : 0.8;
  double c = v * s, x = c * (1 - std::abs(std::fmod(h, 2.0) - 1)), m = v - c;
  double r = 0, g = 0, b = 0;
  switch (int(h)) {
    case 0: r = c, g = x; break;
    case 1: r = x, g = c; break;
    case 2: g = c, b = x; break;
    case 3: g = x, b = c; break;
    case 4: r = x, b = c; break;
    default: r = c, b = x;
  }
  auto byte = [](double t) { return static_cast<unsigned char>(std::lround(255 * t)); };
  return {byte(r + m), byte(g + m), byte(b + m)};
}

std::string patchLayoutToPly(const PatchLayout& layout) {
  std::ostringstream out;
  out.precision(9);
  out << "ply\nformat ascii 1.0\ncomment field-coherent quad layout: " << layout.numPatches() << " patches\n"
      << "element vertex " << layout.positions.size() << "\n"
      << "property float x\nproperty float y\nproperty float z\nproperty uchar corner\n"
      << "element face " << layout.triangles.size() << "\n"
      << "property list uchar int vertex_indices\nproperty int patch\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  for (std::size_t v = 0; v < layout.positions.size(); ++v) {
    const Vec3& p = layout.positions[v];
    out << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << int(layout.corner[v]) << '\n';
  }
  for (std::size_t t = 0; t < layout.triangles.size(); ++t) {
    const auto& tri = layout.triangles[t];
    auto c = patchColour(layout.patch[t]);
    out << "3 " << tri[0] << ' ' << tri[1] << ' ' << tri[2] << ' ' << layout.patch[t] << ' ' << int(c[0]) << ' '
        << int(c[1]) << ' ' << int(c[2]) << '\n';
  }
  return out.str();
}

std::string separatricesToObj(const Layout& layout) {
  std::vector<const TracedPath*> paths;
  std::vector<std::string> comments;
  for (std::size_t i = 0; i < layout.separatrices.size(); ++i) {
    const auto& s = layout.separatrices[i];
    paths.push_back(&s.path);
    const char* kind = s.kind == LayoutSeparatrix::Full ? "separatrix" : (s.kind == LayoutSeparatrix::TJunction ? "t-junction" : "to border");
    comments.push_back(std::to_string(i) + ": " + kind + " from port " + std::to_string(s.portA) +
                       (s.portB >= 0 ? " to port " + std::to_string(s.portB) : std::string()));
  }
  return polylinesToObj(paths, comments);
}

}  // namespace fcql
