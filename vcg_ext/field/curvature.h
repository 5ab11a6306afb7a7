// Per-face curvature tensor (second fundamental form) of a triangle mesh.
//
// Estimated as in Rusinkiewicz 2004, "Estimating Curvatures and Their Derivatives on Triangle
// Meshes", but kept per face: the shape operator II of face f is the symmetric 2×2 matrix, in
// the face frame (faceFrameX, faceFrameY), that best maps each edge vector e_k of the face to the
// change of the vertex normals along it, II·e_k ≈ n_{k+1} − n_k (least squares, 3 edges, 6
// equations, 3 unknowns, normal changes projected onto the face plane). Vertex normals are
// area-weighted averages of the face normals (split at creases, if given). With
// outward normals a convex region has positive curvatures (a sphere of radius R: II = I / R).
#pragma once

#include "mesh/surface_mesh.h"

#include <array>
#include <complex>
#include <vector>

namespace fcql {

/// Symmetric 2×2 tensor [[xx, xy], [xy, yy]] in a face frame.
struct FaceTensor {
  double xx = 0, xy = 0, yy = 0;

  double meanCurvature() const { return 0.5 * (xx + yy); }
  /// (k1 − k2) / 2 ≥ 0: half the difference of the principal curvatures.
  double anisotropy() const { return std::abs(tracelessPart()); }
  /// Traceless part as a complex number (xx − yy)/2 + i·xy: its argument is twice the angle (in
  /// the face frame) of the principal direction of maximum curvature, its modulus is
  /// anisotropy().
  std::complex<double> tracelessPart() const { return {0.5 * (xx - yy), xy}; }
  /// Angle in the face frame of the direction of maximum curvature k1.
  double maxDirectionAngle() const { return 0.5 * std::arg(tracelessPart()); }
  /// Principal curvatures k1 ≥ k2.
  double k1() const { return meanCurvature() + anisotropy(); }
  double k2() const { return meanCurvature() - anisotropy(); }
};

/// Unit vertex normals, area-weighted averages of the incident face normals (zero for an
/// unreferenced vertex).
std::vector<Vec3> areaWeightedVertexNormals(const SurfaceMesh& mesh);

/// Per face corner, the unit normal of the vertex averaged (area-weighted) over the faces of its
/// star that can be reached from the face without crossing a crease edge. `creases` (per edge
/// id, may be null) marks the creases; without creases these are the area-weighted vertex
/// normals.
std::vector<std::array<Vec3, 3>> cornerNormals(const SurfaceMesh& mesh, const std::vector<char>* creases = nullptr);

/// The shape operator of each face in its frame (see the top of this header), from the corner
/// normals above: with creases, a face next to a sharp edge sees only its own side of it, so
/// creases add no spurious curvature to the flat regions they bound.
std::vector<FaceTensor> faceShapeOperators(const SurfaceMesh& mesh, const std::vector<char>* creases = nullptr);

/// Smooths per-face tensors by `iterations` Jacobi steps of area-weighted averaging over the
/// edge-adjacent faces (not across creases, if given); tensors are carried between faces through
/// 3D (expressed in 3D, averaged, projected back onto each face plane). `keep` in [0,1] is the
/// weight of the face's own tensor.
std::vector<FaceTensor> smoothFaceTensors(const SurfaceMesh& mesh, std::vector<FaceTensor> tensors,
                                          int iterations, double keep = 0.5,
                                          const std::vector<char>* creases = nullptr);

}  // namespace fcql
