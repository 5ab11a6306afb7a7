#include "mesh/surface_mesh.h"

#include "util/union_find.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace fcql {
namespace {

std::string faceName(int f) { return "face " + std::to_string(f); }

/// The pipeline squares lengths and multiplies areas, so a mesh whose size is far from 1 in
/// its units underflows or overflows double precision (at 1e-100 every face would look
/// degenerate, at 1e300 the field would not be finite). Sizes within [kMinExtent, kMaxExtent]
/// are safe; others are refused with a message that says so and what to do.
constexpr double kMinExtent = 1e-20, kMaxExtent = 1e20;

void checkCoordinateRange(const std::vector<Vec3>& positions, const std::vector<std::array<int, 3>>& faces) {
  Vec3 lo = positions[faces[0][0]], hi = lo;
  for (const auto& t : faces)
    for (int v : t) lo = lo.cwiseMin(positions[v]), hi = hi.cwiseMax(positions[v]);
  const double extent = (hi - lo).cwiseAbs().maxCoeff();  // no squares: exact for any finite input
  const double largest = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  if (extent >= kMinExtent && largest <= kMaxExtent) return;
  auto number = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", x);
    return std::string(text);
  };
  throw MeshError("the coordinates are out of the supported range: the mesh spans " + number(extent) + " units" +
                  (largest > kMaxExtent ? " and reaches out to " + number(largest) : std::string()) +
                  "; scale it to a size between " + number(kMinExtent) + " and " + number(kMaxExtent) + " units");
}

}  // namespace

SurfaceMesh::SurfaceMesh(std::vector<Vec3> positions, std::vector<std::array<int, 3>> faces)
    : positions_(std::move(positions)), faces_(std::move(faces)) {
  const int nv = numVertices();
  const int nf = numFaces();
  if (nf == 0) throw MeshError("the mesh has no faces");
  for (int v = 0; v < nv; ++v)
    if (!positions_[v].allFinite())
      throw MeshError("vertex " + std::to_string(v) + " has a non-finite coordinate");
  for (int f = 0; f < nf; ++f) {
    for (int c = 0; c < 3; ++c)
      if (faces_[f][c] < 0 || faces_[f][c] >= nv)
        throw MeshError(faceName(f) + " refers to vertex " + std::to_string(faces_[f][c]) +
                        ", out of range (the mesh has " + std::to_string(nv) + " vertices)");
    if (faces_[f][0] == faces_[f][1] || faces_[f][1] == faces_[f][2] || faces_[f][0] == faces_[f][2])
      throw MeshError(faceName(f) + " uses the same vertex twice (degenerate face)");
  }
  checkCoordinateRange(positions_, faces_);

  // Geometry per face; a face whose area is negligible against its longest edge is degenerate.
  normals_.resize(nf);
  frameX_.resize(nf);
  areas_.resize(nf);
  double edgeLengthSum = 0;
  for (int f = 0; f < nf; ++f) {
    const Vec3& p0 = positions_[faces_[f][0]];
    const Vec3& p1 = positions_[faces_[f][1]];
    const Vec3& p2 = positions_[faces_[f][2]];
    Vec3 cross = (p1 - p0).cross(p2 - p0);
    double longest = std::max({(p1 - p0).norm(), (p2 - p1).norm(), (p0 - p2).norm()});
    double area2 = cross.norm();
    if (!(longest > 0) || !(area2 > 1e-10 * longest * longest))
      throw MeshError(faceName(f) + " is degenerate (zero area: its corners are collinear or coincide)");
    normals_[f] = cross / area2;
    areas_[f] = 0.5 * area2;
    frameX_[f] = (p1 - p0).normalized();
    edgeLengthSum += (p1 - p0).norm() + (p2 - p1).norm() + (p0 - p2).norm();
  }

  // Half-edges grouped by their origin vertex (a counting sort, in face order): half-edge
  // h = 3f + i runs from corner i to corner i+1 of face f. Each vertex's group is also its
  // list of corners, and the half-edges of an edge are found in the groups of its two ends,
  // without a hash table (a 1M-face mesh: 2.9M half-edges).
  std::vector<int> outStart(nv + 1, 0);
  for (int f = 0; f < nf; ++f)
    for (int i = 0; i < 3; ++i) ++outStart[faces_[f][i] + 1];
  for (int v = 0; v < nv; ++v) outStart[v + 1] += outStart[v];
  std::vector<int> outgoing(std::size_t(nf) * 3);
  {
    std::vector<int> fill(outStart.begin(), outStart.end() - 1);
    for (int f = 0; f < nf; ++f)
      for (int i = 0; i < 3; ++i) outgoing[fill[faces_[f][i]]++] = f * 3 + i;
  }
  auto target = [&](int h) { return faces_[h / 3][(h % 3 + 1) % 3]; };
  // The half-edge a -> b, the first in face order, or -1.
  auto findHalfEdge = [&](int a, int b) {
    for (int k = outStart[a]; k < outStart[a + 1]; ++k)
      if (target(outgoing[k]) == b) return outgoing[k];
    return -1;
  };
  for (int f = 0; f < nf; ++f)
    for (int i = 0; i < 3; ++i) {
      int a = faces_[f][i], b = faces_[f][(i + 1) % 3];
      const int first = findHalfEdge(a, b);
      if (first == f * 3 + i) continue;
      // Either three or more faces share the edge, or two faces run it the same way.
      int uses = 0;
      for (int g = 0; g < nf && uses < 3; ++g)
        for (int j = 0; j < 3; ++j) {
          int c = faces_[g][j], d = faces_[g][(j + 1) % 3];
          if ((c == a && d == b) || (c == b && d == a)) ++uses;
        }
      if (uses > 2)
        throw MeshError("non-manifold edge: the edge between vertices " + std::to_string(a) +
                        " and " + std::to_string(b) + " is shared by more than two faces");
      {
        std::array<int, 3> x = faces_[first / 3], y = faces_[f];
        std::sort(x.begin(), x.end());
        std::sort(y.begin(), y.end());
        if (x == y)
          throw MeshError("faces " + std::to_string(first / 3) + " and " + std::to_string(f) +
                          " are the same triangle (a duplicated face)");
      }
      throw MeshError("inconsistent orientation: faces " + std::to_string(first / 3) + " and " +
                      std::to_string(f) + " traverse the edge between vertices " + std::to_string(a) +
                      " and " + std::to_string(b) + " in the same direction (flipped face or "
                      "non-orientable surface)");
    }
  adjFace_.assign(nf, {-1, -1, -1});
  adjEdge_.assign(nf, {-1, -1, -1});
  edgeId_.assign(nf, {-1, -1, -1});
  numEdges_ = 0;
  for (int f = 0; f < nf; ++f)
    for (int i = 0; i < 3; ++i) {
      if (edgeId_[f][i] >= 0) continue;
      int a = faces_[f][i], b = faces_[f][(i + 1) % 3];
      const int twin = findHalfEdge(b, a);
      edgeId_[f][i] = numEdges_;
      if (twin >= 0) {
        int g = twin / 3, j = twin % 3;
        adjFace_[f][i] = g;
        adjEdge_[f][i] = j;
        adjFace_[g][j] = f;
        adjEdge_[g][j] = i;
        edgeId_[g][j] = numEdges_;
      }
      ++numEdges_;
    }
  meanEdgeLength_ = edgeLengthSum / (3.0 * nf);

  // Stars: corners of each vertex (its outgoing half-edges, in face order), then ordered
  // counter-clockwise by walking across the edge that enters the vertex (edge (c+2)%3 of the
  // current face).
  stars_.assign(nv, {});
  borderVertex_.assign(nv, 0);
  numUsedVertices_ = 0;
  for (int v = 0; v < nv; ++v) {
    const int begin = outStart[v], count = outStart[v + 1] - begin;
    if (count == 0) continue;
    ++numUsedVertices_;
    // A border vertex's fan starts at the corner whose outgoing edge (edge c) is on the border.
    int start = 0, borderStarts = 0;
    for (int k = 0; k < count; ++k) {
      const int h = outgoing[begin + k];
      if (adjFace_[h / 3][h % 3] < 0) {
        if (borderStarts == 0) start = k;
        ++borderStarts;
      }
    }
    if (borderStarts > 1)
      throw MeshError("non-manifold vertex " + std::to_string(v) +
                      ": its faces form several fans touching only at the vertex");
    borderVertex_[v] = borderStarts == 1;
    std::vector<StarCorner> fan;
    fan.reserve(count);
    StarCorner cur{outgoing[begin + start] / 3, outgoing[begin + start] % 3};
    for (int step = 0; step <= count; ++step) {
      fan.push_back(cur);
      int entering = (cur.corner + 2) % 3;
      int g = adjFace_[cur.face][entering];
      if (g < 0) break;  // reached the border
      int j = adjEdge_[cur.face][entering];
      StarCorner next{g, j};  // in g, edge j runs v -> other, so v is corner j
      if (next.face == fan.front().face) break;  // closed the loop
      cur = next;
    }
    if (int(fan.size()) != count)
      throw MeshError("non-manifold vertex " + std::to_string(v) +
                      ": its faces form several fans touching only at the vertex");
    stars_[v] = std::move(fan);
  }
  std::vector<int>().swap(outgoing);

  // Components, border loops, genus.
  UnionFind uf(nf);
  for (int f = 0; f < nf; ++f)
    for (int i = 0; i < 3; ++i)
      if (adjFace_[f][i] >= 0) uf.unite(f, adjFace_[f][i]);
  // componentOf[root] numbers the components in the order of their first face.
  std::vector<int> componentOf(nf, -1);
  numComponents_ = 0;
  for (int f = 0; f < nf; ++f)
    if (componentOf[uf.find(f)] < 0) componentOf[uf.find(f)] = numComponents_++;
  std::vector<long> compV(numComponents_, 0), compE(numComponents_, 0), compF(numComponents_, 0),
      compLoops(numComponents_, 0);
  for (int f = 0; f < nf; ++f) {
    int c = componentOf[uf.find(f)];
    compF[c] += 1;
    for (int i = 0; i < 3; ++i)
      if (adjFace_[f][i] < 0 || f < adjFace_[f][i]) compE[c] += 1;
  }
  for (int v = 0; v < nv; ++v)
    if (!stars_[v].empty()) compV[componentOf[uf.find(stars_[v][0].face)]] += 1;
  // Border loops: follow border half-edges; each border vertex has exactly one outgoing one.
  std::vector<int> nextBorder(nv, -1);
  std::vector<int> borderFaceOf(nv, -1);
  for (int f = 0; f < nf; ++f)
    for (int i = 0; i < 3; ++i)
      if (adjFace_[f][i] < 0) {
        nextBorder[faces_[f][i]] = faces_[f][(i + 1) % 3];
        borderFaceOf[faces_[f][i]] = f;
      }
  std::vector<char> visited(nv, 0);
  numBorderLoops_ = 0;
  for (int v = 0; v < nv; ++v) {
    if (nextBorder[v] < 0 || visited[v]) continue;
    ++numBorderLoops_;
    compLoops[componentOf[uf.find(borderFaceOf[v])]] += 1;
    for (int w = v; w >= 0 && !visited[w]; w = nextBorder[w]) visited[w] = 1;
  }
  genus_ = 0;
  for (int c = 0; c < numComponents_; ++c) {
    long chi = compV[c] - compE[c] + compF[c];
    genus_ += int((2 - chi - compLoops[c]) / 2);
  }
}

int SurfaceMesh::eulerCharacteristic() const { return numUsedVertices_ - numEdges_ + numFaces(); }

Vec3 SurfaceMesh::faceCentroid(int f) const {
  return (positions_[faces_[f][0]] + positions_[faces_[f][1]] + positions_[faces_[f][2]]) / 3.0;
}

double SurfaceMesh::cornerAngle(int f, int c) const {
  const Vec3& p = positions_[faces_[f][c]];
  Vec3 a = positions_[faces_[f][(c + 1) % 3]] - p;
  Vec3 b = positions_[faces_[f][(c + 2) % 3]] - p;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

double SurfaceMesh::boundingBoxDiagonal() const {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int v = 0; v < numVertices(); ++v)
    if (!stars_[v].empty()) {
      lo = lo.cwiseMin(positions_[v]);
      hi = hi.cwiseMax(positions_[v]);
    }
  return (hi - lo).norm();
}

}  // namespace fcql
