#include "compute_field_step.h"

#include "field/field_io.h"

#include <utility>

namespace fcql_meshlab {

namespace {

bool hasStoredField(const CMeshO& cm) {
  if (!hasFaceField(cm)) return false;
  for (const CFaceO& f : cm.face)
    if (!f.IsD() && f.cPD1().SquaredNorm() > 0) return true;
  return false;
}

fcql::MeshInput meshInput(const ConvertedMesh& converted, const std::string& meshName) {
  fcql::MeshInput input;
  input.mesh = &converted.mesh;
  input.name = meshName;
  input.weldedVertices = converted.weldedVertices;
  input.weldingNote = converted.weldingNote;
  return input;
}

}  // namespace

FieldStepResult computeFieldStep(const CMeshO& cm, const std::string& meshName, const fcql::PipelineParameters& params,
                                 const Progress& progress) {
  FieldStepResult r;
  progress(0, "converting the mesh");
  const auto start = Clock::now();
  r.converted = toSurfaceMesh(cm);
  fcql::MeshInput input = meshInput(r.converted, meshName);
  input.loadSeconds = secondsSince(start);
  fcql::CrossField existing;
  fcql::FieldSource source;
  if (params.useExisting && hasFaceField(cm)) {
    existing = readFaceField(cm, r.converted);
    source.kept = &existing;
  }
  const ConvertedMesh& converted = r.converted;
  source.asStored = [&converted](const fcql::CrossField& field) { return fieldAsStored(converted, field); };
  r.stage = fcql::runFieldStage(input, params, source, observerOf(progress));
  return r;
}

FieldStepResult readStoredFieldStep(const CMeshO& cm, const std::string& meshName,
                                    const fcql::PipelineParameters& params, const Progress& progress) {
  if (!hasStoredField(cm)) throw fcql::FieldError(kNoFieldMessage);
  FieldStepResult r;
  const auto start = Clock::now();
  r.converted = toSurfaceMesh(cm);
  fcql::MeshInput input = meshInput(r.converted, meshName);
  input.loadSeconds = secondsSince(start);
  const fcql::CrossField stored = readFaceField(cm, r.converted);
  fcql::PipelineParameters keep = params;
  keep.fieldFile.clear();
  keep.useExisting = true;
  fcql::FieldSource source;
  source.kept = &stored;
  r.stage = fcql::runFieldStage(input, keep, source, observerOf(progress));
  return r;
}

void storeFieldStep(MeshModel& mm, const FieldStepResult& r) {
  // Enable the optional components before touching them (MeshLab crashes otherwise).
  // EnableCurvatureDir keeps the values already there, so a kept field is not lost.
  mm.updateDataMask(MeshModel::MM_FACECURVDIR | MeshModel::MM_VERTQUALITY);
  CMeshO& cm = mm.cm;
  const ConvertedMesh& cv = r.converted;

  const fcql::FieldAnalysis& analysis = r.stage.analysis;
  writeFaceField(cm, cv, r.stage.field);

  // Per-vertex index × 4 in the quality; the singular flag as a bool attribute and selection.
  for (auto& v : cm.vert)
    if (!v.IsD()) {
      v.Q() = 0;
      v.ClearS();
    }
  const int nv = cv.mesh.numVertices();
  for (int v = 0; v < nv && v < int(analysis.vertexIndexQuarters.size()); ++v)
    cm.vert[cv.meshLabVertex[v]].Q() = Scalarm(analysis.vertexIndexQuarters[v]);

  // An attribute of the same name but another type (e.g. loaded from a file) is replaced.
  auto singular = vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<bool>(cm, kSingularAttribute);
  if (!vcg::tri::Allocator<CMeshO>::IsValidHandle(cm, singular)) {
    vcg::tri::Allocator<CMeshO>::DeletePerVertexAttribute(cm, kSingularAttribute);
    singular = vcg::tri::Allocator<CMeshO>::AddPerVertexAttribute<bool>(cm, kSingularAttribute);
  }
  for (size_t i = 0; i < cm.vert.size(); ++i) singular[i] = false;
  for (const auto& s : analysis.singularities) {
    if (s.indexQuarters == 0 || s.vertex < 0 || s.vertex >= nv) continue;
    CVertexO& v = cm.vert[cv.meshLabVertex[s.vertex]];
    singular[v] = true;
    v.SetS();
  }
}

}  // namespace fcql_meshlab
