#include "quad_step.h"

#include "metrics/quad_quality.h"

namespace fcql_meshlab {

QuadStepResult computeQuadStep(const fcql::SurfaceMesh& mesh, const fcql::CrossField& field,
                               const fcql::LayoutStageResult& layout, const fcql::PipelineParameters& params,
                               const Progress& progress) {
  QuadStepResult r;
  r.quad = fcql::runQuadStage(mesh, field, layout, params, observerOf(progress.sub(0, 90)));
  progress(90, "quad layer");
  const fcql::QuadMesh& q = r.quad.quad.mesh;
  TriangleLayerData& l = r.layer;
  l.positions = q.positions;
  l.triangles.reserve(2 * q.quads.size());
  const fcql::QuadJacobian jacobianOf(q);  // as quad.min_scaled_jacobian measures it
  for (std::size_t i = 0; i < q.quads.size(); ++i) {
    const auto& quad = q.quads[i];
    const fcql::Vec3 &a = q.positions[quad[0]], &b = q.positions[quad[1]], &c = q.positions[quad[2]],
                     &d = q.positions[quad[3]];
    const float jacobian = float(jacobianOf(int(i)));
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
  progress(100, "quad mesh done");
  return r;
}

void storeQuadStep(MeshDocument& md, const QuadStepResult& r) {
  addTriangleLayer(md, QString::fromUtf8(kQuadLayer), r.layer);
}

std::vector<std::string> describeQuadLayer(const QuadStepResult& r) {
  return {"Layer \"" + std::string(kQuadLayer) + "\": " + std::to_string(r.layer.triangles.size()) +
          " triangles, in pairs sharing a faux diagonal; face quality: the quad's scaled Jacobian"};
}

}  // namespace fcql_meshlab
