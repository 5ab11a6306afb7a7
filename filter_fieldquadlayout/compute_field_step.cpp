#include "compute_field_step.h"

#include "field/field_io.h"

#include <cstdio>
#include <utility>

namespace fcql_meshlab {

FieldStepResult computeFieldStep(const CMeshO& cm, const FieldParameters& params,
                                 const Progress& progress) {
  FieldStepResult r;
  progress(0, "converting the mesh");
  auto t0 = Clock::now();
  r.converted = toSurfaceMesh(cm);
  r.conversionSeconds = secondsSince(t0);

  progress(10, "cross field");
  auto t1 = Clock::now();
  if (!params.fieldFile.empty()) {
    r.field = fcql::loadField(r.converted.mesh, params.fieldFile);  // throws FieldError
    r.fieldFile = params.fieldFile;
  } else if (params.useExisting && hasFaceField(cm)) {
    r.field = readFaceField(cm, r.converted);
    r.keptExistingField = true;
  } else {
    r.existingFieldMissing = params.useExisting;
    fcql::FieldGenerationOptions options;
    options.sharpAngleDeg = params.sharpAngleDeg;
    options.scale = params.fieldScale;
    r.field = fcql::generateCrossField(r.converted.mesh, options, &r.generation);
  }
  r.fieldSeconds = secondsSince(t1);

  progress(80, "singularities and ports");
  auto t2 = Clock::now();
  r.analysis = fcql::analyzeField(r.converted.mesh, r.field);
  r.analysisSeconds = secondsSince(t2);
  progress(100, "cross field done");
  return r;
}

void storeFieldStep(MeshModel& mm, const FieldStepResult& r) {
  // Enable the optional components before touching them (MeshLab crashes otherwise).
  // EnableCurvatureDir keeps the values already there, so a kept field is not lost.
  mm.updateDataMask(MeshModel::MM_FACECURVDIR | MeshModel::MM_VERTQUALITY);
  CMeshO& cm = mm.cm;
  const ConvertedMesh& cv = r.converted;

  writeFaceField(cm, cv, r.field);

  // Per-vertex index × 4 in the quality; the singular flag as a bool attribute and selection.
  for (auto& v : cm.vert)
    if (!v.IsD()) {
      v.Q() = 0;
      v.ClearS();
    }
  const int nv = cv.mesh.numVertices();
  for (int v = 0; v < nv && v < int(r.analysis.vertexIndexQuarters.size()); ++v)
    cm.vert[cv.meshLabVertex[v]].Q() = Scalarm(r.analysis.vertexIndexQuarters[v]);

  // An attribute of the same name but another type (e.g. loaded from a file) is replaced.
  auto singular = vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<bool>(cm, kSingularAttribute);
  if (!vcg::tri::Allocator<CMeshO>::IsValidHandle(cm, singular)) {
    vcg::tri::Allocator<CMeshO>::DeletePerVertexAttribute(cm, kSingularAttribute);
    singular = vcg::tri::Allocator<CMeshO>::AddPerVertexAttribute<bool>(cm, kSingularAttribute);
  }
  for (size_t i = 0; i < cm.vert.size(); ++i) singular[i] = false;
  for (const auto& s : r.analysis.singularities) {
    if (s.indexQuarters == 0 || s.vertex < 0 || s.vertex >= nv) continue;
    CVertexO& v = cm.vert[cv.meshLabVertex[s.vertex]];
    singular[v] = true;
    v.SetS();
  }
}

std::string formatHistogram(const fcql::FieldAnalysis& analysis) {
  std::string out;
  for (const auto& h : analysis.interiorHistogram())
    out += (out.empty() ? "" : ", ") + h.first + ": " + std::to_string(h.second);
  return out.empty() ? std::string("none") : out;
}

std::vector<std::string> describeFieldStep(const FieldStepResult& r,
                                           const FieldParameters& params) {
  const fcql::SurfaceMesh& m = r.converted.mesh;
  const fcql::FieldAnalysis& a = r.analysis;
  std::vector<std::string> lines;
  lines.push_back("Mesh: " + std::to_string(m.numFaces()) + " faces, " +
                  std::to_string(m.numVertices()) + " vertices, genus " +
                  std::to_string(m.genus()) + ", " + std::to_string(m.numBorderLoops()) +
                  " border loops");
  if (!r.converted.weldingNote.empty()) lines.push_back("Mesh: " + r.converted.weldingNote);
  if (!r.fieldFile.empty()) {
    lines.push_back("Cross field: read from " + r.fieldFile);
  } else if (r.keptExistingField) {
    lines.push_back("Cross field: kept the field already on the mesh (per-face PD1/PD2)");
  } else {
    char angle[64];
    std::snprintf(angle, sizeof angle, "%g deg, field scale %g", params.sharpAngleDeg, params.fieldScale);
    lines.push_back(std::string("Cross field: computed") +
                    (r.existingFieldMissing ? " (the mesh had no field to keep)" : "") +
                    ", sharp angle " + angle + ": " + std::to_string(r.generation.sharpEdges) +
                    " sharp edges, " + std::to_string(r.generation.constrainedFaces) +
                    " constrained faces");
  }
  lines.push_back("Singularities: " + std::to_string(a.numInteriorSingularities()) +
                  " (by index: " + formatHistogram(a) + "), border singularities: " +
                  std::to_string(a.numBorderSingularities()) + ", ports: " +
                  std::to_string(a.numPorts()) + ", index sum: " +
                  fcql::formatQuarterIndex(a.indexSumQuarters()) + " (Euler characteristic " +
                  std::to_string(m.eulerCharacteristic()) + ")");
  for (const std::string& warning : fcql::fieldWarnings(m, a)) lines.push_back("Warning: " + warning);
  lines.push_back("Time: field " + formatSeconds(r.fieldSeconds) + ", analysis " +
                  formatSeconds(r.analysisSeconds) + ", total " +
                  formatSeconds(r.conversionSeconds + r.fieldSeconds + r.analysisSeconds));
  return lines;
}

}  // namespace fcql_meshlab
