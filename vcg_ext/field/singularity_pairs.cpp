#include "field/singularity_pairs.h"

#include "field/field_analysis.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace fcql {

namespace {
constexpr double kTurnStep = 5.0 * 3.14159265358979323846 / 180.0;  ///< 5 degrees
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
      if (mesh.isBorderVertex(a) || mesh.isBorderVertex(b) || q[a] * q[b] != -1) continue;
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
      const int before = irregular();
      // The smallest turn of one of the two crosses that does it, in steps of 5 degrees.
      bool done = false;
      for (int step = 1; step <= 17 && !done; ++step)
        for (int sign : {1, -1})
          for (int h : {f, g}) {
            if (done || isFixed(h)) continue;
            const Vec3 saved = field.u[h];
            const double t = sign * step * kTurnStep;
            field.u[h] = saved * std::cos(t) + mesh.faceNormal(h).cross(saved) * std::sin(t);
            int savedQ[3];
            for (int c = 0; c < 3; ++c) {
              const int v = mesh.vertex(h, c);
              savedQ[c] = q[v];
              q[v] = vertexIndexQuarters(mesh, field, v);
            }
            // Both ends regular, and the count around down by exactly the pair.
            if (q[a] == 0 && q[b] == 0 && irregular() == before - 2) {
              done = true;
              ++cancelled;
            } else {
              field.u[h] = saved;
              for (int c = 0; c < 3; ++c) q[mesh.vertex(h, c)] = savedQ[c];
            }
          }
    }
  return cancelled;
}

}  // namespace fcql
