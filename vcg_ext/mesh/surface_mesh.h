// SurfaceMesh: the triangle mesh every pipeline stage works on.
//
// A plain, double-precision, index-based triangle mesh with the adjacency the algorithms need
// (face-face across each edge, the ordered star of faces around each vertex, border flags).
// It is built once from positions and triangles (from a file, from a vcglib/MeshLab mesh, or
// from a generator) and validated on construction: a mesh that is not an oriented 2-manifold,
// has degenerate triangles, non-finite coordinates or out-of-range indices is rejected with a
// MeshError whose message names the problem. Nothing in this header asserts on user data.
//
// Conventions: face f has corners faces[f][0..2] in counter-clockwise order (outward normal by
// the right-hand rule). Edge i of face f goes from corner i to corner (i+1)%3. The opposite
// corner of edge i is (i+2)%3.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace fcql {

using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;

/// Thrown for any input mesh the pipeline cannot work on; what() is one line for the user.
struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// One corner of the star of a vertex: face `face`, in which the vertex is corner `corner`.
struct StarCorner {
  int face;
  int corner;
};

class SurfaceMesh {
public:
  SurfaceMesh() = default;

  /// Builds the mesh and its adjacency. Unreferenced vertices are kept (they have an empty
  /// star). Throws MeshError for: no faces, an index out of range, a face repeating a vertex,
  /// a non-finite coordinate, a zero-area face, an edge shared by more than two faces, two
  /// faces traversing a shared edge in the same direction (inconsistent orientation or a
  /// non-orientable surface), a vertex whose star is not a single fan (non-manifold vertex).
  SurfaceMesh(std::vector<Vec3> positions, std::vector<std::array<int, 3>> faces);

  int numVertices() const { return int(positions_.size()); }
  int numFaces() const { return int(faces_.size()); }
  int numEdges() const { return numEdges_; }

  const std::vector<Vec3>& positions() const { return positions_; }
  const Vec3& position(int v) const { return positions_[v]; }
  const std::array<int, 3>& face(int f) const { return faces_[f]; }
  const std::vector<std::array<int, 3>>& faces() const { return faces_; }
  int vertex(int f, int corner) const { return faces_[f][corner]; }

  /// Face across edge i of face f, or -1 on the border.
  int adjacentFace(int f, int i) const { return adjFace_[f][i]; }
  /// Index of the same edge inside adjacentFace(f, i).
  int adjacentEdge(int f, int i) const { return adjEdge_[f][i]; }
  bool isBorderEdge(int f, int i) const { return adjFace_[f][i] < 0; }
  /// A global id of the undirected edge i of face f, in [0, numEdges()).
  int edgeId(int f, int i) const { return edgeId_[f][i]; }

  /// Unit normal, area and local orthonormal frame (x along edge 0, y = n × x) of face f.
  const Vec3& faceNormal(int f) const { return normals_[f]; }
  double faceArea(int f) const { return areas_[f]; }
  const Vec3& faceFrameX(int f) const { return frameX_[f]; }
  Vec3 faceFrameY(int f) const { return normals_[f].cross(frameX_[f]); }
  Vec3 faceCentroid(int f) const;
  /// Interior angle of face f at its corner c.
  double cornerAngle(int f, int c) const;
  /// Vector of edge i of face f (from corner i to corner i+1).
  Vec3 edgeVector(int f, int i) const {
    return positions_[faces_[f][(i + 1) % 3]] - positions_[faces_[f][i]];
  }

  /// The border's direction at border edge i of face f, at the scale of a default quad
  /// (mesh/border_tangents.h): the edge vector itself (bit for bit, as edgeVector), or where
  /// the border zigzags from triangle to triangle, the border's mean direction there as a unit
  /// vector. Zero for an interior edge.
  Vec3 borderTangent(int f, int i) const;

  bool isBorderVertex(int v) const { return borderVertex_[v]; }
  /// Faces around v in counter-clockwise order (about the outward normal). For a border
  /// vertex the fan starts at the face whose edge leaving v... is on the border: star[0]'s
  /// edge from v (edge `corner`) is a border edge, and star.back()'s edge into v is a border
  /// edge. For an interior vertex the order is cyclic, star[0] arbitrary but deterministic.
  const std::vector<StarCorner>& star(int v) const { return stars_[v]; }

  /// Number of connected border loops, connected components, and Euler characteristic V-E+F
  /// (vertices counted only if referenced).
  int numBorderLoops() const { return int(borderLoops_.size()); }
  /// The border loops, each as its border edges in order along the border (an edge as the
  /// corner of its face it leaves: edge `corner`, from that vertex to the next), each loop
  /// starting at its first border edge in face order.
  const std::vector<std::vector<StarCorner>>& borderLoops() const { return borderLoops_; }
  int numComponents() const { return numComponents_; }
  int eulerCharacteristic() const;
  /// Genus of a connected mesh: (2 - χ - borderLoops) / 2; for several components, the sum of
  /// their genera.
  int genus() const { return genus_; }

  double boundingBoxDiagonal() const;
  double meanEdgeLength() const { return meanEdgeLength_; }

private:
  std::vector<Vec3> positions_;
  std::vector<std::array<int, 3>> faces_;
  std::vector<std::array<int, 3>> adjFace_, adjEdge_, edgeId_;
  std::vector<Vec3> normals_, frameX_;
  std::vector<double> areas_;
  std::vector<char> borderVertex_;
  std::vector<std::vector<StarCorner>> stars_;
  std::unordered_map<int, Vec3> zigzagBorder_;  ///< edge id → the border's direction (borderTangent)
  std::vector<std::vector<StarCorner>> borderLoops_;
  int numEdges_ = 0, numComponents_ = 0, genus_ = 0, numUsedVertices_ = 0;
  double meanEdgeLength_ = 0;
};

}  // namespace fcql
