#include "meshlab_mesh_adapter.h"

#include <cmath>
#include <type_traits>

#include "mesh/vertex_welding.h"

#include <string>
#include <utility>

namespace fcql_meshlab {

namespace {

// The one conversion between fcql's directions and MeshLab's PD1/PD2, both ways.
CFaceO::CurVecType toCurvatureDir(const fcql::Vec3& d) {
  return CFaceO::CurVecType(Scalarm(d.x()), Scalarm(d.y()), Scalarm(d.z()));
}
fcql::Vec3 fromCurvatureDir(const CFaceO::CurVecType& d) {
  return fcql::Vec3(double(d[0]), double(d[1]), double(d[2]));
}

}  // namespace

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
  fcql::VertexWelding welding = fcql::weldCoincidentVertices(out.mesh);
  out.weldingNote = welding.note();
  if (welding.welded) {
    out.weldedVertices = welding.merged;
    std::vector<int> first(welding.mesh.numVertices(), -1);
    for (std::size_t k = 0; k < out.meshLabVertex.size(); ++k) {
      int& f = first[welding.newIndex[k]];
      if (f < 0) f = out.meshLabVertex[k];
    }
    for (int& v : out.vertexOfMeshLab)
      if (v >= 0) v = welding.newIndex[v];
    out.meshLabVertex = std::move(first);
    out.mesh = std::move(welding.mesh);
  }
  return out;
}

bool hasFaceField(const CMeshO& cm) { return vcg::tri::HasPerFaceCurvatureDir(cm); }

fcql::CrossField readFaceField(const CMeshO& cm, const ConvertedMesh& converted) {
  if (!hasFaceField(cm)) throw fcql::FieldError("the mesh has no per-face cross field (PD1/PD2)");
  const int nf = converted.mesh.numFaces();
  std::vector<fcql::Vec3> vectors(nf);
  for (int f = 0; f < nf; ++f) vectors[f] = fromCurvatureDir(cm.face[converted.meshLabFace[f]].cPD1());
  fcql::CrossField field = fcql::CrossField::fromVectors(converted.mesh, vectors);  // checks every vector
  // A vector that is already unit and tangent (stored in double precision) is taken as it is:
  // normalising it again would move it by rounding, and the later filters would not trace
  // exactly the field All Steps and fcql trace.
  for (int f = 0; f < nf; ++f)
    if (std::abs(vectors[f].squaredNorm() - 1) < 1e-13 &&
        std::abs(vectors[f].dot(converted.mesh.faceNormal(f))) < 1e-13)
      field.u[f] = vectors[f];
  return field;
}

fcql::CrossField fieldAsStored(const ConvertedMesh& converted, const fcql::CrossField& field) {
  if (std::is_same<Scalarm, double>::value) return field;  // stored exactly, read back as it is
  const int nf = converted.mesh.numFaces();
  std::vector<fcql::Vec3> vectors(nf);
  for (int f = 0; f < nf; ++f)
    vectors[f] = fromCurvatureDir(toCurvatureDir(field.direction(converted.mesh, f, 0)));
  return fcql::CrossField::fromVectors(converted.mesh, vectors);
}

void writeFaceField(CMeshO& cm, const ConvertedMesh& converted, const fcql::CrossField& field) {
  const int nf = converted.mesh.numFaces();
  for (int f = 0; f < nf; ++f) {
    CFaceO& face = cm.face[converted.meshLabFace[f]];
    face.PD1() = toCurvatureDir(field.direction(converted.mesh, f, 0));
    face.PD2() = toCurvatureDir(field.direction(converted.mesh, f, 1));
  }
}

}  // namespace fcql_meshlab
