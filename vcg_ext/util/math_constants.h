// Mathematical constants of the library, defined once (C++14: the MeshLab plugin includes
// headers that use them).
#pragma once

namespace fcql {

/// π to double precision.
constexpr double kPi = 3.14159265358979323846;

}  // namespace fcql
