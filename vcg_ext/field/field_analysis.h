// Field analysis: the discrete parallel transport of a cross field, per-edge matchings,
// singular vertices with their index, and the separatrix ports at each singularity.
//
// Transport (paper §3.1): two faces sharing an edge are unfolded into one plane about that
// edge; a direction of one cross is carried to the direction of the other cross that makes the
// smallest angle with it. The matching of edge i of face f is the number m of quarter turns
// such that direction j of f is carried to direction j + m (mod 4) of the neighbour.
//
// Index of an interior vertex v with star angle Θ (sum of corner angles): walk the faces of the
// star counter-clockwise in the cut-open chart of the star (each face placed rigidly, angles
// accumulated), carrying one direction with the transport; δ is the signed turn of the field at
// each step (|δ| ≤ 45°). Then index = 1 + (Σδ − Θ)/(2π), an exact multiple of 1/4. A border
// vertex gets the border index (π − Θ + Σδ − misalignment at the two border edges)/(2π),
// rounded to a quarter, so that for a closed or a bordered surface the sum of interior and
// border indices is the Euler characteristic (Poincaré–Hopf for a field tangent or normal to
// the border). Where the border zigzags and the field follows the border's mean direction
// rather than the edge's (SurfaceMesh::borderTangent; a zigzag edge may lie 60° off the
// field), the misalignment is rounded against that direction, and analyzeField moves a quarter
// that falls on a vertex of the wrong kind (convex on a reflex vertex, concave on a convex one)
// to its neighbour along the border.
//
// Ports (paper §3.2): the star is flattened conformally (chart angles scaled by 2π/Θ, or π/Θ at
// the border); a port is a direction t around the vertex where the field is radial, i.e. the
// tangent of a separatrix leaving the vertex. An interior vertex of index I has 4 − 4I ports
// (3 at +1/4, 5 at −1/4, 4 at a regular vertex). At a border vertex, only ports pointing
// strictly into the surface are kept (1 at a straight border point, 0 at a convex 90° corner, 2 at
// a concave 270° corner).
#pragma once

#include "field/cross_field.h"

#include <string>
#include <vector>

namespace fcql {

/// The tangent of a separatrix leaving a vertex.
struct Port {
  int vertex = -1;
  int face = -1;          ///< face of the star that contains the tangent
  int fieldDirection = 0; ///< the direction j of the cross of `face` the tangent follows
  Vec3 tangent;           ///< unit, in the plane of `face`
  double chartAngle = 0;  ///< angle around the vertex in the cut-open star, from star[0]'s edge
  double flatAngle = 0;   ///< the same angle after conformal flattening (sums to 2π / π)
};

struct SingularVertex {
  int vertex = -1;
  int indexQuarters = 0;  ///< index × 4: +1 for index +1/4, −1 for −1/4, ...
  bool onBorder = false;
  std::vector<Port> ports;  ///< sorted by chartAngle
};

struct FieldAnalysis {
  /// matching[f][i]: quarter turns carrying directions of face f across its edge i (0 on
  /// border edges).
  std::vector<std::array<int, 3>> matching;
  /// Per vertex: index × 4 (interior) or border index × 4 (border vertices).
  std::vector<int> vertexIndexQuarters;
  /// Per vertex: total angle of the star (Θ).
  std::vector<double> starAngle;
  /// Interior vertices with non-zero index, and border vertices with non-zero border index,
  /// each with its ports; sorted by vertex. The layout stage may append regular vertices
  /// (index 0) as virtual anchors for regions without singularities; the counts below skip
  /// them.
  std::vector<SingularVertex> singularities;

  int numInteriorSingularities() const;
  int numBorderSingularities() const;
  int numPorts() const;
  /// Sum over all vertices of the index, × 4 (interior and border): 4·χ for a field that is
  /// tangent or normal to the border.
  int indexSumQuarters() const;
  /// Histogram of interior singularities by index, keys as "-1/4", "1/4", "1/2", ...
  std::vector<std::pair<std::string, int>> interiorHistogram() const;
};

/// The cut-open chart of the star of a vertex, with one field direction carried around it
/// (see above). Star face k (mesh.star(v)[k]) covers chart angles [start[k], start[k+1]]; its
/// outgoing edge lies at start[k]. The carried direction in face k is direction carried[k] of
/// its cross, at chart angle psi[k]. Flattened angle = chart angle × flatScale.
struct StarChart {
  int vertex = -1;
  std::vector<double> start;  ///< size n+1; start[n] = theta
  std::vector<double> psi;    ///< size n
  std::vector<int> carried;   ///< size n; carried[0] = 0
  std::vector<double> delta;  ///< turn from face k to k+1 (n−1 entries; n for an interior vertex)
  double theta = 0;           ///< total angle Θ
  double flatScale = 1;       ///< 2π/Θ (interior) or π/Θ (border)
  bool loop = false;          ///< interior vertex
  /// Border vertex: the angles from its outgoing and its incoming border edge to the border
  /// direction its index is counted against there (0: the edge's own; see computeStarChart).
  double borderStart = 0, borderEnd = 0;

  /// Chart angle of a vector tangent to star face k.
  double chartAngleOf(const SurfaceMesh& mesh, int k, const Vec3& direction) const;
};

StarChart computeStarChart(const SurfaceMesh& mesh, const CrossField& field, int v);

/// Warnings about singularities the layout cannot serve well, for the log: interior ones of
/// index +3/4 or more leave at most one separatrix (a +1 "centre", typically the single
/// inner vertex of a triangle fan such as a CAD cap, leaves none), so the patch around them
/// has too few corners and is cut as a 3-gon. Names up to three vertices and says what helps
/// (a finer mesh there lets the field split them into +1/4 ones). Empty when there are none.
std::vector<std::string> fieldWarnings(const SurfaceMesh& mesh, const FieldAnalysis& analysis);

/// Formats index×4 as a reduced fraction: -1 → "-1/4", 2 → "1/2", 4 → "1", 0 → "0".
std::string formatQuarterIndex(int quarters);

/// The matching of edge i of face f (see above).
int computeMatching(const SurfaceMesh& mesh, const CrossField& field, int f, int i);

/// Signed angle that carries direction `d` of face f to direction `e` of face g = the face
/// across edge i of f, after unfolding g into f's plane about the shared edge: a rotation about
/// f's normal, in (−π, π].
double transportAngle(const SurfaceMesh& mesh, int f, int i, const Vec3& d, const Vec3& e);

/// Rotates a vector tangent to face g = adjacentFace(f, i) into the plane of face f, by the
/// hinge rotation about their common edge (the discrete Levi-Civita transport).
Vec3 unfoldIntoFace(const SurfaceMesh& mesh, int f, int i, const Vec3& vectorInG);

/// Everything above, for every vertex. Throws FieldError if the field does not match the mesh.
FieldAnalysis analyzeField(const SurfaceMesh& mesh, const CrossField& field);

/// The index ×4 of every vertex alone (what analyzeField puts in vertexIndexQuarters), without
/// matchings or ports. Throws FieldError if the field does not match the mesh.
std::vector<int> computeVertexIndices(const SurfaceMesh& mesh, const CrossField& field);

/// A rotation of `v` by `angle` about the unit `axis` (v orthogonal to the axis).
Vec3 rotateInPlane(const Vec3& v, const Vec3& axis, double angle);

/// The index ×4 of one vertex (its entry of computeVertexIndices), from its star alone.
int vertexIndexQuarters(const SurfaceMesh& mesh, const CrossField& field, int v);

/// Ports of one vertex (also used for regular vertices by the tracer when needed).
std::vector<Port> computePorts(const SurfaceMesh& mesh, const CrossField& field, int v);

}  // namespace fcql
