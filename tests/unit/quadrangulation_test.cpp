#include "field/field_generation.h"
#include "layout/patch_closing.h"
#include "mesh/generators.h"
#include "quadrangulation/patch_sampling.h"
#include "tracing/separatrix_graph.h"

#include <gtest/gtest.h>

using namespace fcql;

namespace {

struct Quadrangulated {
  SurfaceMesh mesh;
  CrossField field;
  FieldAnalysis analysis;
  std::unique_ptr<GeodesicGraph> graph;
  Layout layout;
  PatchLayout patches;
  PatchGraph sides;
};

std::unique_ptr<Quadrangulated> layoutOf(SurfaceMesh mesh) {
  auto q = std::make_unique<Quadrangulated>();
  q->mesh = std::move(mesh);
  q->field = generateCrossField(q->mesh);
  q->analysis = analyzeField(q->mesh, q->field);
  q->graph = std::make_unique<GeodesicGraph>(q->mesh, q->field, q->analysis, TracingParameters{});
  q->layout = solveLayout(*q->graph, traceCandidateSeparatrices(*q->graph), LayoutParameters{});
  q->patches = buildPatchLayout(*q->graph, q->layout);
  bool disks = true;
  for (const auto& p : q->patches.patches) disks = disks && p.isDisk;
  if (!disks) closeNonDiskPatches(q->mesh, q->field, q->analysis, q->graph, q->layout, q->patches);
  q->sides = buildPatchGraph(q->patches);
  return q;
}

QuadMesh quadrangulate(const Quadrangulated& q, double target, QuadMeshReport* report) {
  SideLengths lengths = solveSideLengths(q.sides, target, 10);
  EXPECT_TRUE(lengths.inconsistentPatches.empty());
  QuadMesh quads = samplePatches(q.patches, q.sides, lengths);
  *report = checkQuadMesh(quads);
  return quads;
}

}  // namespace

TEST(Quadrangulation, GeneratedMeshesGivePureManifoldQuadMeshesOfTheSameTopology) {
  for (const char* name : {"rounded_box", "torus", "open_cylinder", "double_torus"}) {
    auto q = layoutOf(makeExample(name));
    QuadMeshReport r;
    QuadMesh quads = quadrangulate(*q, 0.05 * q->mesh.boundingBoxDiagonal(), &r);
    EXPECT_TRUE(r.manifold) << name << ": " << r.problem;
    EXPECT_EQ(r.genus, q->mesh.genus()) << name;
    EXPECT_EQ(r.borderLoops, q->mesh.numBorderLoops()) << name;
    EXPECT_EQ(r.eulerCharacteristic, q->mesh.eulerCharacteristic()) << name;
    EXPECT_EQ(r.unusedVertices, 0) << name;
    EXPECT_GT(quads.numQuads(), 50) << name;
    // Every quad has 4 distinct vertices and a non-degenerate area.
    for (const auto& f : quads.quads) {
      const auto& P = quads.positions;
      double area = ((P[f[2]] - P[f[0]]).cross(P[f[3]] - P[f[1]])).norm();
      EXPECT_GT(area, 0) << name;
    }
    // The singularities of the field are the irregular vertices of the quad mesh.
    EXPECT_EQ(r.irregularVertices, q->analysis.numInteriorSingularities()) << name;
  }
}

TEST(Quadrangulation, DoublingTheResolutionQuadruplesTheQuads) {
  auto q = layoutOf(makeRoundedBox());
  QuadMeshReport coarse, fine;
  QuadMesh a = quadrangulate(*q, 0.08 * q->mesh.boundingBoxDiagonal(), &coarse);
  QuadMesh b = quadrangulate(*q, 0.04 * q->mesh.boundingBoxDiagonal(), &fine);
  double ratio = double(b.numQuads()) / a.numQuads();
  EXPECT_GT(ratio, 3.0);
  EXPECT_LT(ratio, 5.5);
  EXPECT_EQ(coarse.irregularVertices, fine.irregularVertices);
  EXPECT_EQ(coarse.irregularVertices, 8);
}

TEST(Quadrangulation, SideLengthsRejectBadTargets) {
  auto q = layoutOf(makeRoundedBox());
  EXPECT_THROW(solveSideLengths(q->sides, 0.0, 10), std::invalid_argument);
  EXPECT_THROW(solveSideLengths(q->sides, -1.0, 10), std::invalid_argument);
}

TEST(Quadrangulation, QuadMeshCheckFindsDefects) {
  QuadMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
  m.quads = {{0, 1, 2, 3}, {1, 4, 5, 2}};
  QuadMeshReport ok = checkQuadMesh(m);
  EXPECT_TRUE(ok.manifold);
  EXPECT_EQ(ok.borderLoops, 1);
  EXPECT_EQ(ok.eulerCharacteristic, 1);
  m.quads.push_back({0, 1, 2, 3});  // the same quad twice: edges used twice the same way
  QuadMeshReport bad = checkQuadMesh(m);
  EXPECT_FALSE(bad.manifold);
  EXPECT_FALSE(bad.problem.empty());
}
