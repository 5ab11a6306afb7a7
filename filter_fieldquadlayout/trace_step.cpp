#include "trace_step.h"

namespace fcql_meshlab {

namespace {

std::vector<const fcql::TracedPath*> candidatePaths(const fcql::SeparatrixGraph& h) {
  std::vector<const fcql::TracedPath*> paths;
  paths.reserve(h.arcs.size());
  for (const fcql::CandidateSeparatrix& arc : h.arcs) paths.push_back(&arc.path);
  return paths;
}

}  // namespace

TraceStepResult computeTraceStep(const fcql::SurfaceMesh& mesh, const fcql::CrossField& field,
                                 const fcql::FieldAnalysis& analysis,
                                 const fcql::PipelineParameters& params, const Progress& progress) {
  TraceStepResult r;
  r.trace = fcql::runTraceStage(mesh, field, analysis, params, observerOf(progress.sub(0, 95)));
  progress(95, "candidate separatrices per face");
  const auto paths = candidatePaths(r.trace.h);
  r.candidatesPerFace = pathsPerFace(paths, mesh.numFaces());
  r.polylines = polylineLayer(paths);
  progress(100, "tracing done");
  return r;
}

void storeTraceStep(MeshDocument& md, MeshModel& mm, const ConvertedMesh& converted,
                    const TraceStepResult& r) {
  setPerFaceValues(mm.cm, converted, kCandidatesAttribute, r.candidatesPerFace, 0);
  addPolylineLayer(md, QString::fromUtf8(kCandidatesLayer), r.polylines);
}

std::vector<std::string> describeTraceLayers(const TraceStepResult& r) {
  int crossed = 0;
  for (int c : r.candidatesPerFace) crossed += c > 0;
  return {"Candidate separatrices cross " + std::to_string(crossed) + " of " + std::to_string(r.candidatesPerFace.size()) +
          " faces (per-face attribute " + kCandidatesAttribute + "); layer \"" + kCandidatesLayer + "\": " +
          std::to_string(r.polylines.edges.size()) + " edges"};
}

}  // namespace fcql_meshlab
