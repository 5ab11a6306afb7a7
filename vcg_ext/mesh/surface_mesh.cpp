#include "mesh/surface_mesh.h"

#include "mesh/border_tangents.h"
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

/// Step 1: at least one face, finite coordinates, indices in range, no face repeating a
/// vertex, a size double precision can work with.
void checkIndicesAndValues(const std::vector<Vec3>& positions, const std::vector<std::array<int, 3>>& faces) {
  const int nv = int(positions.size());
  const int nf = int(faces.size());
  if (nf == 0) throw MeshError("the mesh has no faces");
  for (int v = 0; v < nv; ++v)
    if (!positions[v].allFinite())
      throw MeshError("vertex " + std::to_string(v) + " has a non-finite coordinate");
  for (int f = 0; f < nf; ++f) {
    for (int c = 0; c < 3; ++c)
      if (faces[f][c] < 0 || faces[f][c] >= nv)
        throw MeshError(faceName(f) + " refers to vertex " + std::to_string(faces[f][c]) +
                        ", out of range (the mesh has " + std::to_string(nv) + " vertices)");
    if (faces[f][0] == faces[f][1] || faces[f][1] == faces[f][2] || faces[f][0] == faces[f][2])
      throw MeshError(faceName(f) + " uses the same vertex twice (degenerate face)");
  }
  checkCoordinateRange(positions, faces);
}

/// Step 2: geometry per face; a face whose area is negligible against its longest edge is
/// degenerate. Returns the sum of the faces' edge lengths.
double faceGeometry(const std::vector<Vec3>& positions, const std::vector<std::array<int, 3>>& faces,
                    std::vector<Vec3>& normals, std::vector<Vec3>& frameX, std::vector<double>& areas) {
  const int nf = int(faces.size());
  normals.resize(nf);
  frameX.resize(nf);
  areas.resize(nf);
  double edgeLengthSum = 0;
  for (int f = 0; f < nf; ++f) {
    const Vec3& p0 = positions[faces[f][0]];
    const Vec3& p1 = positions[faces[f][1]];
    const Vec3& p2 = positions[faces[f][2]];
    Vec3 cross = (p1 - p0).cross(p2 - p0);
    double longest = std::max({(p1 - p0).norm(), (p2 - p1).norm(), (p0 - p2).norm()});
    double area2 = cross.norm();
    if (!(longest > 0) || !(area2 > 1e-10 * longest * longest))
      throw MeshError(faceName(f) + " is degenerate (zero area: its corners are collinear or coincide)");
    normals[f] = cross / area2;
    areas[f] = 0.5 * area2;
    frameX[f] = (p1 - p0).normalized();
    edgeLengthSum += (p1 - p0).norm() + (p2 - p1).norm() + (p0 - p2).norm();
  }
  return edgeLengthSum;
}

/// Half-edges grouped by their origin vertex (a counting sort, in face order): half-edge
/// h = 3f + i runs from corner i to corner i+1 of face f. Each vertex's group is also its
/// list of corners, and the half-edges of an edge are found in the groups of its two ends,
/// without a hash table (a 1M-face mesh: 2.9M half-edges).
class HalfEdgesByOrigin {
public:
  HalfEdgesByOrigin(const std::vector<std::array<int, 3>>& faces, int nv) : faces_(faces), start_(nv + 1, 0) {
    const int nf = int(faces.size());
    for (int f = 0; f < nf; ++f)
      for (int i = 0; i < 3; ++i) ++start_[faces[f][i] + 1];
    for (int v = 0; v < nv; ++v) start_[v + 1] += start_[v];
    outgoing_.resize(std::size_t(nf) * 3);
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (int f = 0; f < nf; ++f)
      for (int i = 0; i < 3; ++i) outgoing_[fill[faces[f][i]]++] = f * 3 + i;
  }
  /// The half-edges leaving v are outgoing(begin(v)) .. outgoing(end(v) − 1).
  int begin(int v) const { return start_[v]; }
  int end(int v) const { return start_[v + 1]; }
  int outgoing(int k) const { return outgoing_[k]; }
  /// The half-edge a -> b, the first in face order, or -1.
  int find(int a, int b) const {
    for (int k = start_[a]; k < start_[a + 1]; ++k)
      if (target(outgoing_[k]) == b) return outgoing_[k];
    return -1;
  }

private:
  int target(int h) const { return faces_[h / 3][(h % 3 + 1) % 3]; }
  const std::vector<std::array<int, 3>>& faces_;
  std::vector<int> start_;
  std::vector<int> outgoing_;
};

/// Step 3: every half-edge is the first of its kind: no edge shared by more than two faces,
/// no duplicated face, no two faces running an edge the same way.
void checkEdgeManifold(const std::vector<std::array<int, 3>>& faces, const HalfEdgesByOrigin& halfEdges) {
  const int nf = int(faces.size());
  for (int f = 0; f < nf; ++f)
    for (int i = 0; i < 3; ++i) {
      int a = faces[f][i], b = faces[f][(i + 1) % 3];
      const int first = halfEdges.find(a, b);
      if (first == f * 3 + i) continue;
      // Either three or more faces share the edge, or two faces run it the same way.
      int uses = 0;
      for (int g = 0; g < nf && uses < 3; ++g)
        for (int j = 0; j < 3; ++j) {
          int c = faces[g][j], d = faces[g][(j + 1) % 3];
          if ((c == a && d == b) || (c == b && d == a)) ++uses;
        }
      if (uses > 2)
        throw MeshError("non-manifold edge: the edge between vertices " + std::to_string(a) +
                        " and " + std::to_string(b) + " is shared by more than two faces");
      {
        std::array<int, 3> x = faces[first / 3], y = faces[f];
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
}

/// Step 4: edge ids and the face across each edge (adjFace, adjEdge; −1 on the border).
/// Returns the number of edges.
int linkEdges(const std::vector<std::array<int, 3>>& faces, const HalfEdgesByOrigin& halfEdges,
              std::vector<std::array<int, 3>>& adjFace, std::vector<std::array<int, 3>>& adjEdge,
              std::vector<std::array<int, 3>>& edgeId) {
  const int nf = int(faces.size());
  adjFace.assign(nf, {-1, -1, -1});
  adjEdge.assign(nf, {-1, -1, -1});
  edgeId.assign(nf, {-1, -1, -1});
  int numEdges = 0;
  for (int f = 0; f < nf; ++f)
    for (int i = 0; i < 3; ++i) {
      if (edgeId[f][i] >= 0) continue;
      int a = faces[f][i], b = faces[f][(i + 1) % 3];
      const int twin = halfEdges.find(b, a);
      edgeId[f][i] = numEdges;
      if (twin >= 0) {
        int g = twin / 3, j = twin % 3;
        adjFace[f][i] = g;
        adjEdge[f][i] = j;
        adjFace[g][j] = f;
        adjEdge[g][j] = i;
        edgeId[g][j] = numEdges;
      }
      ++numEdges;
    }
  return numEdges;
}

/// Step 5: stars, the corners of each vertex (its outgoing half-edges, in face order), then
/// ordered counter-clockwise by walking across the edge that enters the vertex (edge (c+2)%3
/// of the current face); a vertex whose corners form more than one fan is non-manifold.
/// Returns the number of vertices with a non-empty star.
int buildStars(int nv, const HalfEdgesByOrigin& halfEdges, const std::vector<std::array<int, 3>>& adjFace,
               const std::vector<std::array<int, 3>>& adjEdge, std::vector<std::vector<StarCorner>>& stars,
               std::vector<char>& borderVertex) {
  stars.assign(nv, {});
  borderVertex.assign(nv, 0);
  int numUsedVertices = 0;
  for (int v = 0; v < nv; ++v) {
    const int begin = halfEdges.begin(v), count = halfEdges.end(v) - begin;
    if (count == 0) continue;
    ++numUsedVertices;
    // A border vertex's fan starts at the corner whose outgoing edge (edge c) is on the border.
    int start = 0, borderStarts = 0;
    for (int k = 0; k < count; ++k) {
      const int h = halfEdges.outgoing(begin + k);
      if (adjFace[h / 3][h % 3] < 0) {
        if (borderStarts == 0) start = k;
        ++borderStarts;
      }
    }
    if (borderStarts > 1)
      throw MeshError("non-manifold vertex " + std::to_string(v) +
                      ": its faces form several fans touching only at the vertex");
    borderVertex[v] = borderStarts == 1;
    std::vector<StarCorner> fan;
    fan.reserve(count);
    StarCorner cur{halfEdges.outgoing(begin + start) / 3, halfEdges.outgoing(begin + start) % 3};
    for (int step = 0; step <= count; ++step) {
      fan.push_back(cur);
      int entering = (cur.corner + 2) % 3;
      int g = adjFace[cur.face][entering];
      if (g < 0) break;  // reached the border
      int j = adjEdge[cur.face][entering];
      StarCorner next{g, j};  // in g, edge j runs v -> other, so v is corner j
      if (next.face == fan.front().face) break;  // closed the loop
      cur = next;
    }
    if (int(fan.size()) != count)
      throw MeshError("non-manifold vertex " + std::to_string(v) +
                      ": its faces form several fans touching only at the vertex");
    stars[v] = std::move(fan);
  }
  return numUsedVertices;
}

struct Topology {
  int numComponents = 0, genus = 0;
  std::vector<std::vector<StarCorner>> borderLoops;
};

/// Step 6: components, border loops, genus.
Topology topology(const std::vector<std::array<int, 3>>& faces, int nv, const std::vector<std::array<int, 3>>& adjFace,
                  const std::vector<std::vector<StarCorner>>& stars) {
  const int nf = int(faces.size());
  Topology result;
  UnionFind uf(nf);
  for (int f = 0; f < nf; ++f)
    for (int i = 0; i < 3; ++i)
      if (adjFace[f][i] >= 0) uf.unite(f, adjFace[f][i]);
  // componentOf[root] numbers the components in the order of their first face.
  std::vector<int> componentOf(nf, -1);
  int& numComponents = result.numComponents;
  for (int f = 0; f < nf; ++f)
    if (componentOf[uf.find(f)] < 0) componentOf[uf.find(f)] = numComponents++;
  std::vector<long> compV(numComponents, 0), compE(numComponents, 0), compF(numComponents, 0),
      compLoops(numComponents, 0);
  for (int f = 0; f < nf; ++f) {
    int c = componentOf[uf.find(f)];
    compF[c] += 1;
    for (int i = 0; i < 3; ++i)
      if (adjFace[f][i] < 0 || f < adjFace[f][i]) compE[c] += 1;
  }
  for (int v = 0; v < nv; ++v)
    if (!stars[v].empty()) compV[componentOf[uf.find(stars[v][0].face)]] += 1;
  // Border loops, from the first border edge in face order not yet walked: each border vertex
  // has exactly one outgoing border edge, its star's first face's edge from it (buildStars).
  std::vector<char> visited(nv, 0);
  for (int f = 0; f < nf; ++f)
    for (int i = 0; i < 3; ++i) {
      if (adjFace[f][i] >= 0 || visited[faces[f][i]]) continue;
      compLoops[componentOf[uf.find(f)]] += 1;
      std::vector<StarCorner> loop;
      for (StarCorner e{f, i}; !visited[faces[e.face][e.corner]];) {
        visited[faces[e.face][e.corner]] = 1;
        loop.push_back(e);
        e = stars[faces[e.face][(e.corner + 1) % 3]].front();
      }
      result.borderLoops.push_back(std::move(loop));
    }
  for (int c = 0; c < numComponents; ++c) {
    long chi = compV[c] - compE[c] + compF[c];
    result.genus += int((2 - chi - compLoops[c]) / 2);
  }
  return result;
}

}  // namespace

SurfaceMesh::SurfaceMesh(std::vector<Vec3> positions, std::vector<std::array<int, 3>> faces)
    : positions_(std::move(positions)), faces_(std::move(faces)) {
  checkIndicesAndValues(positions_, faces_);
  const double edgeLengthSum = faceGeometry(positions_, faces_, normals_, frameX_, areas_);
  {
    const HalfEdgesByOrigin halfEdges(faces_, numVertices());
    checkEdgeManifold(faces_, halfEdges);
    numEdges_ = linkEdges(faces_, halfEdges, adjFace_, adjEdge_, edgeId_);
    meanEdgeLength_ = edgeLengthSum / (3.0 * numFaces());
    numUsedVertices_ = buildStars(numVertices(), halfEdges, adjFace_, adjEdge_, stars_, borderVertex_);
  }
  Topology t = topology(faces_, numVertices(), adjFace_, stars_);
  numComponents_ = t.numComponents;
  borderLoops_ = std::move(t.borderLoops);
  genus_ = t.genus;
  if (!borderLoops_.empty()) zigzagBorder_ = zigzagBorderTangents(*this, kBorderTangentReach * boundingBoxDiagonal());
}

Vec3 SurfaceMesh::borderTangent(int f, int i) const {
  if (!isBorderEdge(f, i)) return Vec3::Zero();
  const auto it = zigzagBorder_.find(edgeId(f, i));
  if (it != zigzagBorder_.end()) return it->second;
  return edgeVector(f, i);
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
