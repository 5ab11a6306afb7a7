#include "layout_step.h"

#include <map>
#include <set>

namespace fcql_meshlab {

std::vector<int> majorityPatchOfFaces(const fcql::PatchLayout& layout, int numFaces) {
  // Sub-triangles of one face are few: a small map per face is enough.
  std::vector<std::map<int, double>> area(std::max(0, numFaces));
  for (std::size_t t = 0; t < layout.triangles.size(); ++t) {
    const int f = layout.originalFace[t];
    if (f < 0 || f >= numFaces) continue;
    const auto& tri = layout.triangles[t];
    const fcql::Vec3& a = layout.positions[tri[0]];
    const fcql::Vec3 cross =
        (layout.positions[tri[1]] - a).cross(layout.positions[tri[2]] - a);
    area[f][layout.patch[t]] += cross.norm();
  }
  std::vector<int> patch(area.size(), -1);
  for (std::size_t f = 0; f < area.size(); ++f) {
    double best = -1;
    for (const auto& pa : area[f])  // ties go to the lower id (map order)
      if (pa.second > best) {
        best = pa.second;
        patch[f] = pa.first;
      }
  }
  return patch;
}

LayoutStepResult computeLayoutStep(const fcql::SurfaceMesh& mesh, const fcql::CrossField& field,
                                   const fcql::FieldAnalysis& analysis, const fcql::TraceStageResult& trace,
                                   const fcql::PipelineParameters& params, const Progress& progress) {
  LayoutStepResult r;
  r.layout = fcql::runLayoutStage(mesh, field, analysis, trace, params, observerOf(progress.sub(0, 95)));
  progress(95, "patches per face");
  const fcql::PatchLayout& p = r.layout.patches;
  r.patchOfFace = majorityPatchOfFaces(p, mesh.numFaces());

  std::vector<const fcql::TracedPath*> paths;
  for (const fcql::LayoutSeparatrix& s : r.layout.layout.separatrices) paths.push_back(&s.path);
  r.separatricesPerFace = pathsPerFace(paths, mesh.numFaces());
  r.polylines = polylineLayer(paths);

  r.patchLayer.positions = p.positions;
  r.patchLayer.triangles = p.triangles;
  r.patchLayer.facePatch = p.patch;
  r.patchLayer.vertexQuality.assign(p.positions.size(), 0.f);
  for (std::size_t v = 0; v < p.corner.size() && v < p.positions.size(); ++v)
    r.patchLayer.vertexQuality[v] = p.corner[v] ? 1.f : 0.f;
  progress(100, "layout done");
  return r;
}

void storeLayoutStep(MeshDocument& md, MeshModel& mm, const ConvertedMesh& converted,
                     const LayoutStepResult& r) {
  setPerFaceValues(mm.cm, converted, kPatchAttribute, r.patchOfFace, -1);
  colourFacesByPatch(mm, converted, r.patchOfFace);
  setPerFaceValues(mm.cm, converted, kSeparatricesAttribute, r.separatricesPerFace, 0);
  addPolylineLayer(md, QString::fromUtf8(kSeparatricesLayer), r.polylines);
  addTriangleLayer(md, QString::fromUtf8(kPatchLayoutLayer), r.patchLayer);
}

std::vector<std::string> describeLayoutLayers(const LayoutStepResult& r) {
  std::set<int> onFaces(r.patchOfFace.begin(), r.patchOfFace.end());
  onFaces.erase(-1);
  return {"Input mesh: " + std::to_string(onFaces.size()) + " of " + std::to_string(r.layout.patches.numPatches()) +
          " patches cover the majority of some face (attribute " + kPatchAttribute + ", face colour); layer \"" +
          kPatchLayoutLayer + "\": " + std::to_string(r.patchLayer.triangles.size()) +
          " triangles cut along the separatrices; layer \"" + kSeparatricesLayer + "\": " +
          std::to_string(r.layout.layout.separatrices.size()) + " polylines"};
}

}  // namespace fcql_meshlab
