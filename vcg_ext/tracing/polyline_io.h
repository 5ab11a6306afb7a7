// Writing separatrices as OBJ polylines: `v` lines for the joints and one `l` line per path.
#pragma once

#include "tracing/traced_path.h"

#include <string>
#include <vector>

namespace fcql {

/// Text of an OBJ file with one `l` polyline per path (comment lines name each path).
std::string polylinesToObj(const std::vector<const TracedPath*>& paths, const std::vector<std::string>& comments = {});

}  // namespace fcql
