#include "document_layers.h"

#include "layout/layout_io.h"

#include <vcg/complex/algorithms/update/bounding.h>

#include <algorithm>

namespace fcql_meshlab {

namespace {

Point3m toPoint(const fcql::Vec3& p) { return Point3m(Scalarm(p.x()), Scalarm(p.y()), Scalarm(p.z())); }

vcg::Color4b colourOf(int patch) {
  if (patch < 0) return vcg::Color4b(128, 128, 128, 255);
  const auto c = fcql::patchColour(patch);
  return vcg::Color4b(c[0], c[1], c[2], 255);
}

template <class T>
typename CMeshO::template PerFaceAttributeHandle<T> freshFaceAttribute(CMeshO& cm,
                                                                       const std::string& name) {
  // An attribute of that name (e.g. of another type, loaded from a file) is replaced.
  vcg::tri::Allocator<CMeshO>::DeletePerFaceAttribute(cm, name);
  return vcg::tri::Allocator<CMeshO>::template AddPerFaceAttribute<T>(cm, name);
}

}  // namespace

PolylineLayerData polylineLayer(const std::vector<const fcql::TracedPath*>& paths) {
  PolylineLayerData d;
  for (const fcql::TracedPath* path : paths) {
    int previous = -1;
    for (const fcql::PathPoint& q : path->points) {
      if (previous >= 0 && (d.positions[previous] - q.position).norm() == 0) continue;
      const int index = int(d.positions.size());
      d.positions.push_back(q.position);
      if (previous >= 0) d.edges.push_back({previous, index});
      previous = index;
    }
  }
  return d;
}

std::vector<int> pathsPerFace(const std::vector<const fcql::TracedPath*>& paths, int numFaces) {
  std::vector<int> count(std::max(0, numFaces), 0);
  std::vector<int> lastPath(count.size(), -1);  // counts each path once per face
  for (std::size_t i = 0; i < paths.size(); ++i)
    for (const fcql::PathSegment& s : paths[i]->segments)
      if (s.face >= 0 && s.face < numFaces && lastPath[s.face] != int(i)) {
        lastPath[s.face] = int(i);
        ++count[s.face];
      }
  return count;
}

void setPerFaceValues(CMeshO& cm, const ConvertedMesh& converted, const std::string& name,
                      const std::vector<int>& values, int absent) {
  auto asInt = freshFaceAttribute<int>(cm, name);
  auto asFloat = freshFaceAttribute<float>(cm, name + "_f");
  for (std::size_t i = 0; i < cm.face.size(); ++i) {
    const int f = i < converted.faceOfMeshLab.size() ? converted.faceOfMeshLab[i] : -1;
    const int v = (f >= 0 && f < int(values.size())) ? values[f] : absent;
    asInt[i] = v;
    asFloat[i] = float(v);
  }
}

void colourFacesByPatch(MeshModel& mm, const ConvertedMesh& converted,
                        const std::vector<int>& patchOfFace) {
  mm.updateDataMask(MeshModel::MM_FACECOLOR);
  for (std::size_t f = 0; f < converted.meshLabFace.size() && f < patchOfFace.size(); ++f)
    mm.cm.face[converted.meshLabFace[f]].C() = colourOf(patchOfFace[f]);
}

MeshModel* addPolylineLayer(MeshDocument& md, const QString& label, const PolylineLayerData& d) {
  MeshModel* mm = md.addNewMesh(QString(), label, false);
  CMeshO& cm = mm->cm;
  auto v = vcg::tri::Allocator<CMeshO>::AddVertices(cm, d.positions.size());
  for (const fcql::Vec3& p : d.positions) (v++)->P() = toPoint(p);
  auto e = vcg::tri::Allocator<CMeshO>::AddEdges(cm, d.edges.size());
  for (const auto& edge : d.edges) {
    e->V(0) = &cm.vert[edge[0]];
    e->V(1) = &cm.vert[edge[1]];
    ++e;
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(cm);
  return mm;
}

MeshModel* addTriangleLayer(MeshDocument& md, const QString& label, const TriangleLayerData& d) {
  MeshModel* mm = md.addNewMesh(QString(), label, false);
  int mask = 0;
  if (!d.facePatch.empty()) mask |= MeshModel::MM_FACECOLOR;
  if (!d.faceQuality.empty()) mask |= MeshModel::MM_FACEQUALITY;
  if (!d.vertexQuality.empty()) mask |= MeshModel::MM_VERTQUALITY;
  // Quads as triangle pairs whose shared diagonal is faux: flagged polygonal, as MeshLab's own
  // polygonal filters do, so that MeshLab and pymeshlab save them as quads.
  if (!d.faux.empty()) mask |= MeshModel::MM_POLYGONAL;
  if (mask) mm->updateDataMask(mask);
  CMeshO& cm = mm->cm;
  auto v = vcg::tri::Allocator<CMeshO>::AddVertices(cm, d.positions.size());
  for (std::size_t i = 0; i < d.positions.size(); ++i, ++v) {
    v->P() = toPoint(d.positions[i]);
    if (!d.vertexQuality.empty()) v->Q() = Scalarm(d.vertexQuality[i]);
  }
  auto f = vcg::tri::Allocator<CMeshO>::AddFaces(cm, d.triangles.size());
  for (std::size_t t = 0; t < d.triangles.size(); ++t, ++f) {
    for (int c = 0; c < 3; ++c) {
      f->V(c) = &cm.vert[d.triangles[t][c]];
      if (!d.faux.empty() && d.faux[t][c]) f->SetF(c);
    }
    if (!d.facePatch.empty()) f->C() = colourOf(d.facePatch[t]);
    if (!d.faceQuality.empty()) f->Q() = d.faceQuality[t];
  }
  if (!d.facePatch.empty()) {
    auto asInt = vcg::tri::Allocator<CMeshO>::AddPerFaceAttribute<int>(cm, "fcql_patch");
    auto asFloat = vcg::tri::Allocator<CMeshO>::AddPerFaceAttribute<float>(cm, "fcql_patch_f");
    for (std::size_t t = 0; t < d.triangles.size(); ++t) {
      asInt[t] = d.facePatch[t];
      asFloat[t] = float(d.facePatch[t]);
    }
  }
  updateBoxAndNormals(*mm);
  return mm;
}

}  // namespace fcql_meshlab
