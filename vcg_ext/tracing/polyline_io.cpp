#include "tracing/polyline_io.h"

#include <iomanip>
#include <sstream>

namespace fcql {

std::string polylinesToObj(const std::vector<const TracedPath*>& paths, const std::vector<std::string>& comments) {
  std::ostringstream out;
  out << std::setprecision(10);
  out << "# field-coherent separatrices: " << paths.size() << " polylines\n";
  for (const TracedPath* p : paths)
    for (const PathPoint& q : p->points) out << "v " << q.position.x() << ' ' << q.position.y() << ' ' << q.position.z() << '\n';
  long next = 1;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    if (i < comments.size() && !comments[i].empty()) out << "# " << comments[i] << '\n';
    out << 'l';
    for (std::size_t k = 0; k < paths[i]->points.size(); ++k) out << ' ' << next++;
    out << '\n';
  }
  return out.str();
}

}  // namespace fcql
