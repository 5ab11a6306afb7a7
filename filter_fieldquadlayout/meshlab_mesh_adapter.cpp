#include "meshlab_mesh_adapter.h"

#include <string>
#include <utility>

namespace fcql_meshlab {

ConvertedMesh toSurfaceMesh(const CMeshO& cm) {
  ConvertedMesh out;
  const int nv = int(cm.vert.size());
  const int nf = int(cm.face.size());
  out.vertexOfMeshLab.assign(nv, -1);
  out.faceOfMeshLab.assign(nf, -1);

  std::vector<fcql::Vec3> positions;
  positions.reserve(cm.vn);
  for (int i = 0; i < nv; ++i) {
    const CVertexO& v = cm.vert[i];
    if (v.IsD()) continue;
    out.vertexOfMeshLab[i] = int(positions.size());
    out.meshLabVertex.push_back(i);
    const Point3m& p = v.cP();
    positions.emplace_back(double(p[0]), double(p[1]), double(p[2]));
  }

  std::vector<std::array<int, 3>> faces;
  faces.reserve(cm.fn);
  const CVertexO* base = cm.vert.empty() ? nullptr : &cm.vert[0];
  for (int i = 0; i < nf; ++i) {
    const CFaceO& f = cm.face[i];
    if (f.IsD()) continue;
    std::array<int, 3> tri;
    for (int c = 0; c < 3; ++c) {
      const CVertexO* v = f.cV(c);
      const std::ptrdiff_t index = (v && base) ? v - base : -1;
      if (index < 0 || index >= nv)
        throw fcql::MeshError("face " + std::to_string(i) + " has an invalid vertex reference");
      if (out.vertexOfMeshLab[index] < 0)
        throw fcql::MeshError("face " + std::to_string(i) + " uses the deleted vertex " +
                              std::to_string(index));
      tri[c] = out.vertexOfMeshLab[index];
    }
    out.faceOfMeshLab[i] = int(faces.size());
    out.meshLabFace.push_back(i);
    faces.push_back(tri);
  }
  if (faces.empty())
    throw fcql::MeshError("the mesh has no faces (a triangle mesh is needed, not a point cloud)");

  out.mesh = fcql::SurfaceMesh(std::move(positions), std::move(faces));
  return out;
}

bool hasFaceField(const CMeshO& cm) { return vcg::tri::HasPerFaceCurvatureDir(cm); }

fcql::CrossField readFaceField(const CMeshO& cm, const ConvertedMesh& converted) {
  if (!hasFaceField(cm)) throw fcql::FieldError("the mesh has no per-face cross field (PD1/PD2)");
  const int nf = converted.mesh.numFaces();
  std::vector<fcql::Vec3> vectors(nf);
  for (int f = 0; f < nf; ++f) {
    const auto& d = cm.face[converted.meshLabFace[f]].cPD1();
    vectors[f] = fcql::Vec3(double(d[0]), double(d[1]), double(d[2]));
  }
  return fcql::CrossField::fromVectors(converted.mesh, vectors);
}

void writeFaceField(CMeshO& cm, const ConvertedMesh& converted, const fcql::CrossField& field) {
  const int nf = converted.mesh.numFaces();
  for (int f = 0; f < nf; ++f) {
    CFaceO& face = cm.face[converted.meshLabFace[f]];
    const fcql::Vec3 d0 = field.direction(converted.mesh, f, 0);
    const fcql::Vec3 d1 = field.direction(converted.mesh, f, 1);
    face.PD1() = CFaceO::CurVecType(Scalarm(d0.x()), Scalarm(d0.y()), Scalarm(d0.z()));
    face.PD2() = CFaceO::CurVecType(Scalarm(d1.x()), Scalarm(d1.y()), Scalarm(d1.z()));
  }
}

}  // namespace fcql_meshlab
