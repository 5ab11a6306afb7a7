#include "tracing/polyline_io.h"

#include "util/number_text.h"

namespace fcql {

std::string polylinesToObj(const std::vector<const TracedPath*>& paths, const std::vector<std::string>& comments) {
  std::string out = "# field-coherent separatrices: " + std::to_string(paths.size()) + " polylines\n";
  for (const TracedPath* p : paths)
    for (const PathPoint& q : p->points) {
      out += 'v';
      for (int c = 0; c < 3; ++c) {
        out += ' ';
        appendNumber(out, q.position[c], 10);
      }
      out += '\n';
    }
  long next = 1;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    if (i < comments.size() && !comments[i].empty()) out += "# " + comments[i] + '\n';
    out += 'l';
    for (std::size_t k = 0; k < paths[i]->points.size(); ++k) {
      out += ' ';
      appendNumber(out, next++);
    }
    out += '\n';
  }
  return out;
}

}  // namespace fcql
