// Helpers shared by the unit tests.
#pragma once

#include <gtest/gtest.h>

#include "field/cross_field.h"
#include "field/field_io.h"
#include "mesh/closest_point_index.h"
#include "mesh/mesh_io.h"
#include "mesh/quad_mesh.h"
#include "mesh/surface_mesh.h"
#include "util/math_constants.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <string>

namespace fcql::test {

/// An n×n grid of unit quads on the plane z = 0, counter-clockwise about +z.
inline QuadMesh planarGrid(int n) {
  QuadMesh grid;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) grid.positions.push_back(Vec3(i, j, 0));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      grid.quads.push_back({(n + 1) * j + i, (n + 1) * j + i + 1, (n + 1) * (j + 1) + i + 1, (n + 1) * (j + 1) + i});
  return grid;
}

/// The largest distance from the triangles T over P to `other`, sampled on a barycentric grid
/// of each triangle at most `spacing` apart (inside and along the edges): a dense reference
/// for the distance measure, a lower bound on the true one-way distance.
inline double sampledOneWayDistance(const std::vector<Vec3>& P, const std::vector<std::array<int, 3>>& T,
                                    const ClosestPointIndex& other, double spacing) {
  double worst = 0;
  for (const auto& t : T) {
    const Vec3 &a = P[t[0]], &b = P[t[1]], &c = P[t[2]];
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const int n = std::max(1, int(std::ceil(longest / spacing)));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j)
        worst = std::max(worst, other.closest(a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n)).distance);
  }
  return worst;
}

/// Gaussian noise of standard deviation `sigma` on every vertex (mt19937 and Box–Muller, the
/// same numbers with any standard library).
inline SurfaceMesh withNoise(const SurfaceMesh& m, double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  auto uniform = [&] { return (double(rng()) + 0.5) / 4294967296.0; };
  std::vector<Vec3> p = m.positions();
  for (Vec3& x : p)
    for (int k = 0; k < 3; ++k) {
      const double u1 = uniform(), u2 = uniform();  // in this order on every compiler
      const double g = std::sqrt(-2 * std::log(u1)) * std::cos(2 * kPi * u2);
      x[k] += sigma * g;
    }
  return SurfaceMesh(p, m.faces());
}

/// Absolute path of a file in ../shared/data/meshes, or "" if the shared folder is absent.
inline std::string sharedMesh(const std::string& name) {
  std::string path = std::string(FCQL_SHARED_DIR) + "/data/meshes/" + name;
  std::ifstream probe(path);
  return probe ? path : std::string();
}

// A cube [-1,1]^3 with sharp edges, each side an n×n grid of split squares, welded, outward.
inline SurfaceMesh sharpCube(int n) {
  std::vector<Vec3> p;
  std::vector<std::array<int, 3>> faces;
  std::map<std::array<long, 3>, int> index;
  auto vertexAt = [&](const Vec3& x) {
    std::array<long, 3> key = {std::lround(x.x() * 1e6), std::lround(x.y() * 1e6), std::lround(x.z() * 1e6)};
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    p.push_back(x);
    return index[key] = int(p.size()) - 1;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = -1; side <= 1; side += 2) {
      Vec3 normal = Vec3::Zero();
      normal[axis] = side;
      Vec3 a = Vec3::Zero(), b = Vec3::Zero();
      a[(axis + 1) % 3] = 1;
      b[(axis + 2) % 3] = 1;
      if (side < 0) std::swap(a, b);  // keep (a, b, normal) right-handed
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          auto at = [&](int ii, int jj) {
            return vertexAt(normal + a * (-1 + 2.0 * ii / n) + b * (-1 + 2.0 * jj / n));
          };
          int v00 = at(i, j), v10 = at(i + 1, j), v11 = at(i + 1, j + 1), v01 = at(i, j + 1);
          faces.push_back({v00, v10, v11});
          faces.push_back({v00, v11, v01});
        }
    }
  return SurfaceMesh(p, faces);
}

// Per face, the coordinate axis of lowest index that lies in the face plane.
inline CrossField axisField(const SurfaceMesh& m) {
  std::vector<Vec3> u(m.numFaces());
  for (int f = 0; f < m.numFaces(); ++f) {
    const Vec3& n = m.faceNormal(f);
    u[f] = std::abs(n.x()) < 0.5 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  }
  return CrossField::fromVectors(m, u);
}

}  // namespace fcql::test

/// Skips the current test with a message when a shared mesh is missing.
#define FCQL_REQUIRE_SHARED(var, name)                                                   \
  std::string var = fcql::test::sharedMesh(name);                                        \
  if (var.empty()) GTEST_SKIP() << "../shared/data/meshes/" << name << " is absent: skipped"

// The shared mesh NAME.obj as `mesh` and the field it ships, NAME.ffield, as `field`; the
// test is skipped if ../shared is absent.
#define FCQL_REQUIRE_SHARED_WITH_FIELD(mesh, field, name)                                \
  FCQL_REQUIRE_SHARED(mesh##File, std::string(name) + ".obj");                          \
  fcql::SurfaceMesh mesh = fcql::loadMesh(mesh##File);                                   \
  fcql::CrossField field = fcql::loadField(mesh, fcql::test::sharedMesh(std::string(name) + ".ffield"))
