#include "quad_step.h"

#include "metrics/base_complex.h"
#include "metrics/quad_quality.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace fcql_meshlab {
namespace {

/// The options the filter runs the stage with (the library's defaults, including the 1%
/// bound on the distance to the surface), apart from the target and the time limit.
const fcql::QuadrangulationOptions& options() {
  static const fcql::QuadrangulationOptions defaults;
  return defaults;
}

}  // namespace

QuadStepResult computeQuadStep(const fcql::SurfaceMesh& mesh, const fcql::CrossField& field, const LayoutResult& layout,
                               const LayoutParameters& layoutParams,
                               const QuadParameters& params, const Progress& progress) {
  const auto start = Clock::now();
  QuadStepResult r;
  r.targetEdgeLength = params.scale * mesh.boundingBoxDiagonal();
  progress(0, "side lengths and patch sampling");
  fcql::QuadrangulationOptions stage = options();
  stage.targetEdgeLength = r.targetEdgeLength;
  stage.ilpTimeLimit = layoutParams.ilpTimeLimit;
  stage.fieldDirections = field.u;
  r.quad = fcql::quadrangulate(layout.patches, stage);
  r.layoutPatches = int(layout.patches.patches.size());
  if (r.quad.report.manifold) r.baseComplexPatches = fcql::measureBaseComplex(r.quad.mesh).patches;

  progress(90, "quad layer");
  const fcql::QuadMesh& q = r.quad.mesh;
  TriangleLayerData& l = r.layer;
  l.positions = q.positions;
  l.triangles.reserve(2 * q.quads.size());
  const fcql::QuadJacobian jacobianOf(q);  // the CLI's measure (quad.min_scaled_jacobian)
  for (std::size_t i = 0; i < q.quads.size(); ++i) {
    const auto& quad = q.quads[i];
    const fcql::Vec3 &a = q.positions[quad[0]], &b = q.positions[quad[1]],
                     &c = q.positions[quad[2]], &d = q.positions[quad[3]];
    const double exact = jacobianOf(int(i));
    r.invertedQuads += exact <= 0;
    const float jacobian = float(exact);
    r.scaledJacobian.push_back(jacobian);
    // Split along the shorter diagonal; it is edge 2 of the first triangle, edge 0 of the
    // second (edge i runs from corner i to corner i+1).
    const int s = (a - c).norm() <= (b - d).norm() ? 0 : 1;
    const int v0 = quad[s], v1 = quad[s + 1], v2 = quad[s + 2], v3 = quad[(s + 3) % 4];
    l.triangles.push_back({v0, v1, v2});
    l.faux.push_back({0, 0, 1});
    l.triangles.push_back({v0, v2, v3});
    l.faux.push_back({1, 0, 0});
    const int patch = i < q.quadPatch.size() ? q.quadPatch[i] : -1;
    for (int k = 0; k < 2; ++k) {
      l.facePatch.push_back(patch);
      l.faceQuality.push_back(jacobian);
    }
  }
  r.seconds = secondsSince(start);
  progress(100, "quad mesh done");
  return r;
}

void storeQuadStep(MeshDocument& md, const QuadStepResult& r) {
  addTriangleLayer(md, QString::fromUtf8(kQuadLayer), r.layer);
}

std::vector<std::string> describeQuadStep(const QuadStepResult& r) {
  const fcql::QuadMesh& q = r.quad.mesh;
  const fcql::QuadMeshReport& rep = r.quad.report;
  char target[48];
  std::snprintf(target, sizeof target, "%.6g", r.targetEdgeLength);
  std::vector<std::string> lines;
  lines.push_back("Quad mesh: " + std::to_string(q.numQuads()) + " quads, " +
                  std::to_string(q.numVertices()) + " vertices, " +
                  std::to_string(rep.irregularVertices) + " irregular vertices, genus " +
                  std::to_string(rep.genus) + ", " + std::to_string(rep.borderLoops) +
                  " border loops (target edge length " + target + ")");
  if (r.baseComplexPatches >= 0)
    lines.push_back("Base complex of the quad mesh: " + std::to_string(r.baseComplexPatches) + " patches (the layout has " +
                    std::to_string(r.layoutPatches) + ")");
  if (r.quad.splitPatches > 0)
    lines.push_back("Zero chains: " + std::to_string(r.quad.splitPatches) +
                    " patches split by Catmull-Clark steps (" + std::to_string(r.quad.splitRounds) + " rounds)");
  if (r.quad.timeLimitedParts > 0)
    lines.push_back("Warning: the side-length time limit (a safety stop) cut " + std::to_string(r.quad.timeLimitedParts) +
                    " parts short: these quads depend on the machine's speed");
  fcql::QuadrangulationOptions used = options();
  used.targetEdgeLength = r.targetEdgeLength;
  for (std::string note : fcql::refinementNotes(r.quad, used)) {
    note[0] = char(std::toupper(static_cast<unsigned char>(note[0])));  // log lines start with a capital
    lines.push_back(note);
  }
  if (r.quad.polygonPatches > 0)
    lines.push_back(std::to_string(r.quad.polygonPatches) +
                    " layout patches with 3, 5 or more corners cut into quads as n-gons");
  if (q.outsidePoints > 0)
    lines.push_back("Warning: " + std::to_string(q.outsidePoints) +
                    " grid points fell outside their patch map (degenerate patches): their quads are distorted");
  if (!r.scaledJacobian.empty()) {
    double sum = 0, low = 1;
    for (float j : r.scaledJacobian) {
      sum += j;
      low = std::min(low, double(j));
    }
    char quality[128];
    std::snprintf(quality, sizeof quality,
                  "Scaled Jacobian (face quality): min %.3f, mean %.3f, %d quads <= 0", low,
                  sum / r.scaledJacobian.size(), r.invertedQuads);
    lines.push_back(quality);
  }
  if (r.invertedQuads > 0)
    lines.push_back("Warning: " + std::to_string(r.invertedQuads) +
                    " quads are folded or turned against the surface (scaled Jacobian <= 0) after smoothing and untangling");
  lines.push_back("Layer \"" + std::string(kQuadLayer) + "\": " +
                  std::to_string(r.layer.triangles.size()) +
                  " triangles, in pairs sharing a faux diagonal");
  lines.push_back("Time: quadrangulation " + formatSeconds(r.seconds));
  return lines;
}

}  // namespace fcql_meshlab
