#include "mesh/border_tangents.h"

#include "util/math_constants.h"

#include <algorithm>
#include <cmath>

namespace fcql {

namespace {

constexpr double kJaggedDeg = 15;        ///< an edge this far off the border's mean direction takes the mean
constexpr double kBorderCornerDeg = 45;  ///< a turn over rc above this is a corner of the border
constexpr double kCornerEdges = 3;       ///< rc is at least this many of the loop's mean edges
constexpr double kLoopReaches = 12;      ///< a loop is at least this many reaches long, or the reach shrinks
constexpr double kCornerShare = 6;       ///< rc is at most the loop's length over this

/// The tangents of one loop's zigzag edges into `out`.
void loopTangents(const SurfaceMesh& mesh, const std::vector<StarCorner>& loop, double reach,
                  std::unordered_map<int, Vec3>& out) {
  const int m = int(loop.size());
  if (m < 3) return;
  std::vector<Vec3> along, start;
  std::vector<double> length;
  double total = 0;
  for (const StarCorner& e : loop) {
    along.push_back(mesh.edgeVector(e.face, e.corner));
    length.push_back(along.back().norm());
    start.push_back(mesh.position(mesh.vertex(e.face, e.corner)));
    total += length.back();
  }
  const double r = std::min(reach, total / kLoopReaches);
  if (!(r > 0)) return;
  const auto at = [m](int k) { return ((k % m) + m) % m; };
  // Corners (vertex k starts edge k): the turn of the chords over rc, a maximum within rc.
  const double rc = std::min(std::max(r, kCornerEdges * total / m), total / kCornerShare);
  std::vector<double> turn(static_cast<std::size_t>(m), 0.0);
  std::vector<int> backAt(static_cast<std::size_t>(m)), aheadAt(static_cast<std::size_t>(m));
  for (int k = 0; k < m; ++k) {
    int back = k, ahead = k;
    double lb = 0, la = 0;
    for (int steps = 0; lb < rc && steps < m / 2; ++steps) back = at(back - 1), lb += length[std::size_t(back)];
    for (int steps = 0; la < rc && steps < m / 2; ++steps) la += length[std::size_t(ahead)], ahead = at(ahead + 1);
    backAt[std::size_t(k)] = back, aheadAt[std::size_t(k)] = ahead;
    const Vec3 in = start[std::size_t(k)] - start[std::size_t(back)], out = start[std::size_t(ahead)] - start[std::size_t(k)];
    if (in.norm() > 0 && out.norm() > 0)
      turn[std::size_t(k)] = std::acos(std::clamp(in.normalized().dot(out.normalized()), -1.0, 1.0));
  }
  std::vector<char> corner(static_cast<std::size_t>(m), 0);
  for (int k = 0; k < m; ++k) {
    const double t = turn[std::size_t(k)];
    if (!(t > kBorderCornerDeg * kPi / 180)) continue;
    bool largest = true;  // ties go to the first vertex of the run
    for (int j = at(k + 1); largest && j != aheadAt[std::size_t(k)] && j != k; j = at(j + 1)) largest = turn[std::size_t(j)] <= t;
    for (int j = at(k - 1); largest && j != at(backAt[std::size_t(k)] - 1) && j != k; j = at(j - 1)) largest = turn[std::size_t(j)] < t;
    corner[std::size_t(k)] = largest;
  }
  const double cosJagged = std::cos(kJaggedDeg * kPi / 180);
  for (int k = 0; k < m; ++k) {
    // Only edges shorter than half a quad (`reach`, not shrunk) are detail to smooth over: a
    // border edge as long as a quad is the border's shape, which the quads follow (the
    // camelhead's border has notches of such edges; their tips are patch corners).
    if (!(length[std::size_t(k)] > 0) || !(length[std::size_t(k)] < reach / 2)) continue;
    const double half = length[std::size_t(k)] / 2;
    if (!(r > half)) continue;  // the window lies inside the edge
    double w = r, reached = half;
    for (int j = k; reached < w; reached += length[std::size_t(j)]) {  // back across vertex j
      if (corner[std::size_t(j)]) w = reached;
      else if ((j = at(j - 1)) == k) break;
    }
    reached = half;
    for (int j = at(k + 1); reached < w && j != k; reached += length[std::size_t(j)], j = at(j + 1))  // ahead across vertex j
      if (corner[std::size_t(j)]) w = reached;
    Vec3 sum = along[std::size_t(k)];
    for (int side : {-1, 1}) {
      double left = w - half;
      for (int j = at(k + side); left > 0 && j != k; left -= length[std::size_t(j)], j = at(j + side))
        if (length[std::size_t(j)] > 0)
          sum += along[std::size_t(j)] / length[std::size_t(j)] * std::min(left, length[std::size_t(j)]);
    }
    if (!(sum.norm() > 0)) continue;
    const Vec3 mean = sum.normalized();
    if ((along[std::size_t(k)] / length[std::size_t(k)]).dot(mean) < cosJagged)
      out[mesh.edgeId(loop[std::size_t(k)].face, loop[std::size_t(k)].corner)] = mean;
  }
}

}  // namespace

std::unordered_map<int, Vec3> zigzagBorderTangents(const SurfaceMesh& mesh, double reach) {
  std::unordered_map<int, Vec3> out;
  if (!(reach > 0)) return out;
  for (const auto& loop : mesh.borderLoops()) loopTangents(mesh, loop, reach, out);
  return out;
}

}  // namespace fcql
