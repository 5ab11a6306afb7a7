// CrossField: one cross per face of a SurfaceMesh.
//
// The cross of face f is stored as one unit vector u[f] tangent to the face; its four
// directions are direction(f, j) = u[f] rotated by j·90° about the face normal, j = 0..3
// (so direction 1 is n × u). This is the vcglib PD1/PD2 convention: PD1 = direction 0,
// PD2 = direction 1.
#pragma once

#include "mesh/surface_mesh.h"

#include <complex>
#include <vector>

namespace fcql {

struct FieldError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Angle of a vector of face f's plane in the face frame (faceFrameX, faceFrameY).
double angleInFaceFrame(const SurfaceMesh& mesh, int f, const Vec3& v);

/// The smoothness term of the cross field across edge i of face f, shared with face g on the
/// other side: a field is smooth there when z_g ≈ transport · z_f (z = e^{4iθ} in each face's
/// frame), and the term weight · |z_g − transport · z_f|² enters the smoothness energy.
/// `rho` corrects the parallel transport across the edge (0: Levi-Civita); the weight
/// |e|² / (A_f + A_g) is dimensionless. Edge i must not be a border edge.
struct EdgeSmoothness {
  std::complex<double> transport;
  double weight;
};
EdgeSmoothness edgeSmoothness(const SurfaceMesh& mesh, int f, int i, double rho);

struct CrossField {
  std::vector<Vec3> u;  ///< per face, unit and tangent to the face

  int numFaces() const { return int(u.size()); }

  /// Direction j (any integer, taken mod 4) of the cross of face f.
  Vec3 direction(const SurfaceMesh& mesh, int f, int j) const {
    const Vec3& n = mesh.faceNormal(f);
    Vec3 v = n.cross(u[f]);
    switch (((j % 4) + 4) % 4) {
      case 0: return u[f];
      case 1: return v;
      case 2: return -u[f];
      default: return -v;
    }
  }

  /// Angle of u[f] in the face frame (faceFrameX, faceFrameY) of the mesh.
  double angleInFrame(const SurfaceMesh& mesh, int f) const;

  /// Builds a field from arbitrary per-face vectors: each is projected to its face plane and
  /// normalised. Throws FieldError naming the face if a vector is not finite, or (nearly)
  /// orthogonal to its face, or if the count differs from the mesh's face count.
  static CrossField fromVectors(const SurfaceMesh& mesh, const std::vector<Vec3>& vectors);
};

}  // namespace fcql
