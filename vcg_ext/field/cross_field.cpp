#include "field/cross_field.h"

#include <cmath>

namespace fcql {

double angleInFaceFrame(const SurfaceMesh& mesh, int f, const Vec3& v) {
  return std::atan2(v.dot(mesh.faceFrameY(f)), v.dot(mesh.faceFrameX(f)));
}

EdgeSmoothness edgeSmoothness(const SurfaceMesh& mesh, int f, int i, double rho) {
  const int g = mesh.adjacentFace(f, i), j = mesh.adjacentEdge(f, i);
  const double af = angleInFaceFrame(mesh, f, mesh.edgeVector(f, i));
  const double ag = angleInFaceFrame(mesh, g, mesh.edgeVector(g, j));
  return {std::polar(1.0, 4 * (ag - af + rho)),
          mesh.edgeVector(f, i).squaredNorm() / (mesh.faceArea(f) + mesh.faceArea(g))};
}

double CrossField::angleInFrame(const SurfaceMesh& mesh, int f) const { return angleInFaceFrame(mesh, f, u[f]); }

CrossField CrossField::fromVectors(const SurfaceMesh& mesh, const std::vector<Vec3>& vectors) {
  if (int(vectors.size()) != mesh.numFaces())
    throw FieldError("the field has " + std::to_string(vectors.size()) + " vectors but the mesh has " +
                     std::to_string(mesh.numFaces()) + " faces");
  CrossField field;
  field.u.resize(vectors.size());
  for (int f = 0; f < mesh.numFaces(); ++f) {
    const Vec3& w = vectors[f];
    if (!w.allFinite()) throw FieldError("the vector of face " + std::to_string(f) + " is not finite");
    double len = w.norm();
    if (!(len > 0)) throw FieldError("the vector of face " + std::to_string(f) + " is zero");
    const Vec3& n = mesh.faceNormal(f);
    Vec3 t = w - n * n.dot(w);
    // A vector almost along the normal has no meaningful tangent direction.
    if (!(t.norm() > 1e-3 * len))
      throw FieldError("the vector of face " + std::to_string(f) + " is orthogonal to the face");
    field.u[f] = t.normalized();
  }
  return field;
}

}  // namespace fcql
