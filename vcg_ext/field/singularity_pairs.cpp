#include "field/singularity_pairs.h"

#include "field/field_analysis.h"

#include <algorithm>
#include <cstdlib>

namespace fcql {

namespace {

constexpr double kTurnStep = 5.0 * 3.14159265358979323846 / 180.0;  ///< 5 degrees
constexpr int kMaxSteps = 9;  ///< up to 45 degrees either way: a cross repeats every 90

/// The turns (in steps of kTurnStep) of the two crosses on a pair's edge, tried in this order:
/// one cross alone, the least turn first (the first face before the second, counter-clockwise
/// before clockwise), then both together, the least in all first.
const std::vector<std::pair<int, int>>& turns() {
  static const std::vector<std::pair<int, int>> all = [] {
    std::vector<std::pair<int, int>> t, both;
    for (int step = 1; step <= kMaxSteps; ++step)
      for (int sign : {1, -1}) t.emplace_back(sign * step, 0), t.emplace_back(0, sign * step);
    for (int i = -kMaxSteps; i <= kMaxSteps; ++i)
      for (int j = -kMaxSteps; j <= kMaxSteps; ++j)
        if (i != 0 && j != 0) both.emplace_back(i, j);
    std::stable_sort(both.begin(), both.end(), [](const auto& x, const auto& y) {
      return std::abs(x.first) + std::abs(x.second) < std::abs(y.first) + std::abs(y.second);
    });
    t.insert(t.end(), both.begin(), both.end());
    return t;
  }();
  return all;
}

}  // namespace

int cancelAdjacentSingularityPairs(const SurfaceMesh& mesh, CrossField& field, const std::vector<char>& fixedFace) {
  std::vector<int> q = computeVertexIndices(mesh, field);
  auto isFixed = [&](int f) { return !fixedFace.empty() && fixedFace[f] != 0; };
  int cancelled = 0;
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int i = 0; i < 3; ++i) {
      const int g = mesh.adjacentFace(f, i);
      if (g < f) continue;  // a border edge, or seen from g
      const int a = mesh.vertex(f, i), b = mesh.vertex(f, (i + 1) % 3);
      if (mesh.isBorderVertex(a) || mesh.isBorderVertex(b) || q[a] * q[b] >= 0) continue;
      // The vertices whose index a change of f's or g's cross can move.
      std::vector<int> around;
      for (int h : {f, g})
        for (int c = 0; c < 3; ++c)
          if (std::find(around.begin(), around.end(), mesh.vertex(h, c)) == around.end()) around.push_back(mesh.vertex(h, c));
      auto irregular = [&] {
        int sum = 0;
        for (int v : around) sum += std::abs(q[v]);
        return sum;
      };
      // A quarter off each end at a time (a ±1/2 pair takes two), while some turn does it.
      while (q[a] * q[b] < 0) {
        const int before = irregular(), qa = std::abs(q[a]), qb = std::abs(q[b]);
        std::vector<int> savedQ;
        for (int v : around) savedQ.push_back(q[v]);
        bool done = false;
        for (const auto& turn : turns()) {
          if ((turn.first != 0 && isFixed(f)) || (turn.second != 0 && isFixed(g))) continue;
          const Vec3 fromF = field.u[f], fromG = field.u[g];
          field.u[f] = rotateInPlane(fromF, mesh.faceNormal(f), turn.first * kTurnStep);
          field.u[g] = rotateInPlane(fromG, mesh.faceNormal(g), turn.second * kTurnStep);
          for (int v : around) q[v] = vertexIndexQuarters(mesh, field, v);
          // A quarter less at both ends, and the count around down by just that.
          if (std::abs(q[a]) == qa - 1 && std::abs(q[b]) == qb - 1 && irregular() == before - 2) {
            done = true;
            ++cancelled;
            break;
          }
          field.u[f] = fromF, field.u[g] = fromG;
          for (std::size_t k = 0; k < around.size(); ++k) q[around[k]] = savedQ[k];
        }
        if (!done) break;
      }
    }
  return cancelled;
}

}  // namespace fcql
