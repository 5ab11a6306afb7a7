#include "field/curvature.h"

#include <Eigen/Dense>

namespace fcql {

std::vector<Vec3> areaWeightedVertexNormals(const SurfaceMesh& mesh) {
  std::vector<Vec3> normals(mesh.numVertices(), Vec3::Zero());
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int c = 0; c < 3; ++c) normals[mesh.vertex(f, c)] += mesh.faceArea(f) * mesh.faceNormal(f);
  for (auto& n : normals) {
    double len = n.norm();
    if (len > 0) n /= len;
  }
  return normals;
}

std::vector<std::array<Vec3, 3>> cornerNormals(const SurfaceMesh& mesh, const std::vector<char>* creases) {
  std::vector<std::array<Vec3, 3>> out(mesh.numFaces());
  std::vector<int> sector;
  std::vector<Vec3> sum;
  for (int v = 0; v < mesh.numVertices(); ++v) {
    const auto& star = mesh.star(v);
    const int n = int(star.size());
    if (n == 0) continue;
    // The edge between star[k] and star[k+1] is the edge of star[k] entering v.
    auto creaseAfter = [&](int k) {
      return creases && (*creases)[mesh.edgeId(star[k].face, (star[k].corner + 2) % 3)] != 0;
    };
    sector.assign(n, 0);
    for (int k = 1; k < n; ++k) sector[k] = sector[k - 1] + (creaseAfter(k - 1) ? 1 : 0);
    const int numSectors = sector[n - 1] + 1;
    if (!mesh.isBorderVertex(v) && !creaseAfter(n - 1) && sector[n - 1] != 0) {
      // The last sector continues into the first across the start of the cycle.
      int last = sector[n - 1];
      for (int k = 0; k < n; ++k)
        if (sector[k] == last) sector[k] = 0;
    }
    sum.assign(numSectors, Vec3::Zero());
    for (int k = 0; k < n; ++k) sum[sector[k]] += mesh.faceArea(star[k].face) * mesh.faceNormal(star[k].face);
    for (int k = 0; k < n; ++k) {
      Vec3 normal = sum[sector[k]];
      double len = normal.norm();
      out[star[k].face][star[k].corner] = len > 0 ? Vec3(normal / len) : mesh.faceNormal(star[k].face);
    }
  }
  return out;
}

std::vector<FaceTensor> faceShapeOperators(const SurfaceMesh& mesh, const std::vector<char>* creases) {
  const std::vector<std::array<Vec3, 3>> normals = cornerNormals(mesh, creases);
  std::vector<FaceTensor> out(mesh.numFaces());
  for (int f = 0; f < mesh.numFaces(); ++f) {
    const Vec3& x = mesh.faceFrameX(f);
    const Vec3 y = mesh.faceFrameY(f);
    // Unknowns (xx, xy, yy); per edge e=(ex,ey), dn=(dx,dy):
    //   xx·ex + xy·ey = dx,   xy·ex + yy·ey = dy.
    Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
    Eigen::Vector3d atb = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) {
      Vec3 e = mesh.edgeVector(f, k);
      Vec3 dn = normals[f][(k + 1) % 3] - normals[f][k];
      double ex = e.dot(x), ey = e.dot(y), dx = dn.dot(x), dy = dn.dot(y);
      Eigen::Vector3d r1(ex, ey, 0), r2(0, ex, ey);
      ata += r1 * r1.transpose() + r2 * r2.transpose();
      atb += r1 * dx + r2 * dy;
    }
    // The system is well posed for a non-degenerate triangle (SurfaceMesh rejects the others).
    Eigen::Vector3d s = ata.ldlt().solve(atb);
    if (s.allFinite()) out[f] = FaceTensor{s[0], s[1], s[2]};
  }
  return out;
}

std::vector<FaceTensor> smoothFaceTensors(const SurfaceMesh& mesh, std::vector<FaceTensor> tensors,
                                          int iterations, double keep, const std::vector<char>* creases) {
  const int nf = mesh.numFaces();
  auto to3d = [&](int f, const FaceTensor& t) {
    const Vec3& x = mesh.faceFrameX(f);
    const Vec3 y = mesh.faceFrameY(f);
    return Eigen::Matrix3d(t.xx * x * x.transpose() + t.xy * (x * y.transpose() + y * x.transpose()) +
                           t.yy * y * y.transpose());
  };
  std::vector<Eigen::Matrix3d> t3(nf);
  for (int it = 0; it < iterations; ++it) {
    for (int f = 0; f < nf; ++f) t3[f] = to3d(f, tensors[f]);
    for (int f = 0; f < nf; ++f) {
      Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
      double weight = 0;
      for (int i = 0; i < 3; ++i) {
        int g = mesh.adjacentFace(f, i);
        if (g < 0 || (creases && (*creases)[mesh.edgeId(f, i)])) continue;
        sum += mesh.faceArea(g) * t3[g];
        weight += mesh.faceArea(g);
      }
      if (weight <= 0) continue;
      Eigen::Matrix3d avg = keep * t3[f] + (1 - keep) * sum / weight;
      const Vec3& x = mesh.faceFrameX(f);
      const Vec3 y = mesh.faceFrameY(f);
      tensors[f] = FaceTensor{x.dot(avg * x), 0.5 * (x.dot(avg * y) + y.dot(avg * x)), y.dot(avg * y)};
    }
  }
  return tensors;
}

}  // namespace fcql
