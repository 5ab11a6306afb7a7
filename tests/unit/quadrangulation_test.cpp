#include "field/field_generation.h"
#include "layout/patch_closing.h"
#include "mesh/generators.h"
#include "field/field_io.h"
#include "metrics/base_complex.h"
#include "metrics/quad_quality.h"
#include "mesh/mesh_io.h"
#include "quadrangulation/far_point_snapping.h"
#include "quadrangulation/quadrangulation.h"
#include "test_support.h"
#include "tracing/separatrix_graph.h"

#include <map>

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

std::unique_ptr<Quadrangulated> layoutOf(SurfaceMesh mesh, const CrossField* given = nullptr,
                                         const LayoutParameters& parameters = {}) {
  auto q = std::make_unique<Quadrangulated>();
  q->mesh = std::move(mesh);
  q->field = given ? *given : generateCrossField(q->mesh);
  q->analysis = analyzeField(q->mesh, q->field);
  q->graph = std::make_unique<GeodesicGraph>(q->mesh, q->field, q->analysis, TracingParameters{});
  q->layout = solveLayout(*q->graph, traceCandidateSeparatrices(*q->graph), parameters);
  q->patches = buildPatchLayout(*q->graph, q->layout);
  bool disks = true;
  for (const auto& p : q->patches.patches) disks = disks && p.isDisk;
  if (!disks) closeNonDiskPatches(q->mesh, q->field, q->analysis, q->graph, q->layout, q->patches);
  q->sides = buildPatchGraph(q->patches);
  return q;
}

/// Quads of 2% of the diagonal that follow the layout's field, within `maxDeviation` (0: no bound).
QuadrangulationOptions fieldAlignedOptions(const Quadrangulated& q, double maxDeviation) {
  QuadrangulationOptions options;
  options.targetEdgeLength = 0.02 * q.mesh.boundingBoxDiagonal();
  options.maxDeviation = maxDeviation;
  options.fieldDirections = q.field.u;
  return options;
}

/// The layout without its coverage repair and completion steps: it keeps the t-junctions (and
/// zero chains) that the tests of their handling need.
LayoutParameters withTJunctions() {
  LayoutParameters p;
  p.completionTrials = 0;
  p.coverageRepair = false;
  return p;
}

/// Valence of every vertex of a quad mesh (number of distinct edge neighbours).
std::vector<int> valences(const QuadMesh& m) {
  std::vector<std::vector<int>> nb(m.numVertices());
  for (const auto& f : m.quads)
    for (int i = 0; i < 4; ++i) {
      nb[f[i]].push_back(f[(i + 1) % 4]);
      nb[f[(i + 1) % 4]].push_back(f[i]);
    }
  std::vector<int> v(m.numVertices());
  for (int i = 0; i < m.numVertices(); ++i) {
    std::sort(nb[i].begin(), nb[i].end());
    v[i] = int(std::unique(nb[i].begin(), nb[i].end()) - nb[i].begin());
  }
  return v;
}

/// The properties every output must have: pure quads (by type), manifold, the input's
/// topology, no folded quad, within 1% of the bounding-box diagonal of the input.
void checkQuadMesh(const Quadrangulated& q, const QuadrangulationResult& r, const std::string& name) {
  EXPECT_TRUE(r.report.manifold) << name << ": " << r.report.problem;
  EXPECT_EQ(r.report.genus, q.mesh.genus()) << name;
  EXPECT_EQ(r.report.borderLoops, q.mesh.numBorderLoops()) << name;
  EXPECT_EQ(r.report.eulerCharacteristic, q.mesh.eulerCharacteristic()) << name;
  EXPECT_EQ(r.report.unusedVertices, 0) << name;
  const ClosestPointIndex index(q.mesh);
  const QuadQuality quality = measureQuadQuality(r.mesh, q.mesh, q.field, index);
  EXPECT_LT(quality.hausdorffRelative, 0.01) << name;
  EXPECT_EQ(quality.invertedQuads, 0) << name;
  EXPECT_GT(quality.minScaledJacobian, 0) << name;
  std::cout << name << ": " << r.mesh.numQuads() << " quads, " << r.report.irregularVertices << " irregular, "
            << r.splitPatches << " zero-chain splits, misaligned " << quality.misalignedPercent << "%, Jacobian min "
            << quality.minScaledJacobian << " mean " << quality.meanScaledJacobian << ", Hausdorff "
            << 100 * quality.hausdorffRelative << "%" << std::endl;
}

/// The stage at `target` twice, without and with 10 rounds of smoothing, on the same sampling:
/// no refinement (the unsmoothed mesh could need one where the smoothed one does not).
std::pair<QuadrangulationResult, QuadrangulationResult> rawAndSmoothed(const Quadrangulated& q, double target) {
  QuadrangulationOptions options;
  options.targetEdgeLength = target;
  options.maxDeviation = 0;
  options.smoothing.iterations = 0;
  QuadrangulationResult raw = quadrangulate(q.patches, options);
  options.smoothing.iterations = 10;
  return {std::move(raw), quadrangulate(q.patches, options)};
}

QuadrangulationResult quadrangulateWithDefaults(const Quadrangulated& q, double scale) {
  QuadrangulationOptions options;
  options.targetEdgeLength = scale * q.mesh.boundingBoxDiagonal();
  options.ilpTimeLimit = 30;
  return quadrangulate(q.patches, options);
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
  EXPECT_EQ(ok.components, 1);
  EXPECT_EQ(ok.genus, 0);
  // A second strip apart from the first: two components, two border loops, genus still 0.
  QuadMesh two = m;
  for (const Vec3& p : m.positions) two.positions.push_back(p + Vec3(5, 0, 0));
  two.quads.push_back({6, 7, 8, 9});
  two.quads.push_back({7, 10, 11, 8});
  const QuadMeshReport apart = checkQuadMesh(two);
  EXPECT_EQ(apart.components, 2);
  EXPECT_EQ(apart.borderLoops, 2);
  EXPECT_EQ(apart.eulerCharacteristic, 2);
  EXPECT_EQ(apart.genus, 0);
  // The same count for triangles: a split square has one border loop, χ = 1.
  const SurfaceTopology square = triangleMeshTopology(5, {{0, 1, 2}, {0, 2, 3}});
  EXPECT_EQ(square.borderLoops, 1);
  EXPECT_EQ(square.eulerCharacteristic, 1);
  EXPECT_EQ(square.components, 1);
  m.quads.push_back({0, 1, 2, 3});  // the same quad twice: edges used twice the same way
  QuadMeshReport bad = checkQuadMesh(m);
  EXPECT_FALSE(bad.manifold);
  EXPECT_FALSE(bad.problem.empty());
}

TEST(Quadrangulation, BorderVerticesAreTheEndsOfEdgesOfOneQuad) {
  // A 3 × 3 grid of quads: its 12 outer vertices are on the border, the 4 inner ones not.
  QuadMesh m;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) m.positions.emplace_back(i, j, 0);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) m.quads.push_back({4 * j + i, 4 * j + i + 1, 4 * j + i + 5, 4 * j + i + 4});
  m.positions.emplace_back(9, 9, 9);  // used by no quad: not on the border
  const std::vector<char> border = quadBorderVertices(m);
  ASSERT_EQ(border.size(), m.positions.size());
  for (int v = 0; v < 16; ++v) {
    const int i = v % 4, j = v / 4;
    EXPECT_EQ(border[v], (i == 0 || i == 3 || j == 0 || j == 3) ? 1 : 0) << v;
  }
  EXPECT_EQ(border[16], 0);
  // The middle quad gone: a hole, whose 4 corners join the border.
  m.quads.erase(m.quads.begin() + 4);
  const std::vector<char> holed = quadBorderVertices(m);
  for (int v : {5, 6, 9, 10}) EXPECT_EQ(holed[v], 1) << v;
}

TEST(Quadrangulation, TwoComponentsGiveTwoClosedQuadMeshes) {
  // A rounded box and a torus beside it, in one mesh: each component gets its own layout and
  // quads; the result has both, closed, with the genus of the torus.
  SurfaceMesh box = makeRoundedBox(), torus = makeTorus();
  std::vector<Vec3> positions = box.positions();
  std::vector<std::array<int, 3>> faces = box.faces();
  const int n = int(positions.size());
  for (const Vec3& p : torus.positions()) positions.push_back(p + Vec3(4, 0, 0));
  for (const auto& f : torus.faces()) faces.push_back({f[0] + n, f[1] + n, f[2] + n});
  auto q = layoutOf(SurfaceMesh(positions, faces));
  ASSERT_EQ(q->mesh.numComponents(), 2);
  const QuadrangulationResult r = quadrangulateWithDefaults(*q, 0.02);
  EXPECT_EQ(r.report.components, 2);
  EXPECT_EQ(r.report.genus, 1);
  checkQuadMesh(*q, r, "box and torus");
}

TEST(Quadrangulation, FullStageOnGeneratedMeshesIsCloseToTheSurfaceAndUnfolded) {
  for (const char* name : {"rounded_box", "torus", "open_cylinder", "double_torus", "sphere"}) {
    auto q = layoutOf(makeExample(name));
    const QuadrangulationResult r = quadrangulateWithDefaults(*q, 0.02);
    checkQuadMesh(*q, r, name);
  }
}

TEST(Quadrangulation, AConformingLayoutsQuadMeshHasItsPatchesAsBaseComplex) {
  // The rounded box's layout is conforming (no t-junction, no zero-chain split): the quad
  // mesh's own separatrices are the layout's, and its base complex is the layout's patches.
  auto q = layoutOf(makeExample("rounded_box"));
  ASSERT_EQ(q->layout.tJunctions, 0);
  ASSERT_TRUE(q->layout.unresolvedPorts.empty());
  const QuadrangulationResult r = quadrangulateWithDefaults(*q, 0.02);
  ASSERT_EQ(r.splitPatches, 0);
  const BaseComplex complex = measureBaseComplex(r.mesh);
  EXPECT_EQ(complex.patches, int(q->patches.patches.size()));
  EXPECT_EQ(complex.irregularVertices, q->analysis.numInteriorSingularities());
}

TEST(Quadrangulation, SmoothingKeepsBordersAndImprovesTheWorstQuad) {
  auto q = layoutOf(makeExample("open_cylinder"));
  const auto [raw, smooth] = rawAndSmoothed(*q, 0.03 * q->mesh.boundingBoxDiagonal());
  ASSERT_EQ(raw.mesh.numVertices(), smooth.mesh.numVertices());
  // Border vertices (valence 3 or less on a cylinder cut into one patch) do not move.
  const std::vector<int> valence = valences(raw.mesh);
  int border = 0;
  for (int v = 0; v < raw.mesh.numVertices(); ++v)
    if (valence[v] < 4) {
      ++border;
      EXPECT_EQ(raw.mesh.positions[v], smooth.mesh.positions[v]) << "border vertex " << v << " moved";
    }
  EXPECT_GT(border, 0);
  EXPECT_GT(smooth.smoothing.fixedVertices, 0);
  // Every smoothed vertex is on the surface.
  const ClosestPointIndex index(q->mesh);
  for (const Vec3& p : smooth.mesh.positions) EXPECT_LT(index.closest(p).distance, 1e-9);
  double rawWorst = 1, smoothWorst = 1;
  for (int i = 0; i < raw.mesh.numQuads(); ++i) rawWorst = std::min(rawWorst, scaledJacobian(raw.mesh, i));
  for (int i = 0; i < smooth.mesh.numQuads(); ++i) smoothWorst = std::min(smoothWorst, scaledJacobian(smooth.mesh, i));
  EXPECT_GE(smoothWorst, rawWorst - 1e-9);
  EXPECT_THROW({
    QuadrangulationOptions bad;
    bad.targetEdgeLength = 0.03 * q->mesh.boundingBoxDiagonal();
    bad.maxDeviation = 0;
    bad.smoothing.iterations = 10;
    bad.smoothing.step = 0;
    quadrangulate(q->patches, bad);
  }, std::invalid_argument);
}

TEST(Quadrangulation, SmoothingGivesTheSameQuadsOnAnyNumberOfThreads) {
  // The fandisk's creases make the untangling run twice (without and with snapping to them),
  // side by side on two threads; the smoothing steps share the vertices among the threads.
  // Neither may change the result.
  FCQL_REQUIRE_SHARED(fandisk, "fandisk.obj");
  auto q = layoutOf(loadMesh(fandisk));
  QuadrangulationOptions options = fieldAlignedOptions(*q, 0);
  options.smoothing.threads = 1;
  const QuadrangulationResult one = quadrangulate(q->patches, options);
  options.smoothing.threads = 2;
  const QuadrangulationResult two = quadrangulate(q->patches, options);
  ASSERT_EQ(one.mesh.quads, two.mesh.quads);
  ASSERT_EQ(one.mesh.positions.size(), two.mesh.positions.size());
  for (std::size_t v = 0; v < one.mesh.positions.size(); ++v)
    ASSERT_EQ(one.mesh.positions[v], two.mesh.positions[v]) << "vertex " << v;
  EXPECT_EQ(one.smoothing.snappedMoves, two.smoothing.snappedMoves);
  EXPECT_EQ(one.smoothing.untangledMoves, two.smoothing.untangledMoves);
  EXPECT_GT(one.smoothing.snappedMoves, 0) << "no crease was snapped to: the case no longer tests the second untangling";
}

TEST(Quadrangulation, CoarseTargetsAreRefinedUntilCloseToTheSurface) {
  // Quads of a third of the diagonal on a rounded box cut its rounded edges by far more than
  // 1%: the stage samples again with smaller quads until within the bound, and says so.
  auto q = layoutOf(makeRoundedBox());
  const double diagonal = q->mesh.boundingBoxDiagonal();
  QuadrangulationOptions options;
  options.targetEdgeLength = 0.3 * diagonal;
  options.maxDeviation = 0;
  const QuadrangulationResult coarse = quadrangulate(q->patches, options);
  EXPECT_EQ(coarse.refinements, 0);
  const ClosestPointIndex index(q->mesh);
  const double coarseHausdorff = measureQuadQuality(coarse.mesh, q->mesh, q->field, index).hausdorffRelative;
  ASSERT_GT(coarseHausdorff, 0.01) << "the unrefined mesh is already close: pick a coarser target";
  options.maxDeviation = 0.01;
  const QuadrangulationResult refined = quadrangulate(q->patches, options);
  EXPECT_GT(refined.refinements, 0);
  EXPECT_LT(refined.targetEdgeLength, options.targetEdgeLength);
  EXPECT_GT(refined.mesh.numQuads(), coarse.mesh.numQuads());
  EXPECT_LE(refined.deviation, refined.deviationLimit);
  EXPECT_NEAR(refined.deviationLimit, 0.01 * diagonal, 1e-9 * diagonal);
  // Measured against the input mesh as the CLI does: within the bound too.
  EXPECT_LT(measureQuadQuality(refined.mesh, q->mesh, q->field, index).hausdorffRelative, 0.01);
  const std::vector<std::string> notes = refinementNotes(refined, options);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("refined " + std::to_string(refined.refinements) + " time(s)"), std::string::npos) << notes[0];
  options.maxDeviation = 0;
  EXPECT_TRUE(refinementNotes(coarse, options).empty());
  options.maxDeviation = -1;
  EXPECT_THROW(quadrangulate(q->patches, options), std::invalid_argument);
}

TEST(Quadrangulation, PatchWithASlitIsRejectedClearly) {
  // A square patch (corners 0, 2, 8, 6 of a 3×3 grid) whose boundary runs from the middle of
  // its bottom side to the centre and straight back: a separatrix that ends inside it. Its
  // grid would fold onto itself, so the stage must refuse it and say why.
  PatchLayout layout;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) layout.positions.push_back(Vec3(i, j, 0));
  layout.numOriginalVertices = 9;
  layout.corner = {1, 1, 1, 0, 1, 0, 1, 0, 1};
  PatchReport rep;
  rep.valid = rep.isDisk = true;
  rep.corners = 4;
  rep.boundaryLoops = 1;
  rep.loop = {0, 1, 4, 1, 2, 5, 8, 7, 6, 3};
  rep.loopCorner = {1, 0, 0, 0, 1, 0, 1, 0, 1, 0};
  rep.loopTriangle.assign(rep.loop.size(), 0);
  layout.patches = {rep};
  try {
    buildPatchGraph(layout);
    FAIL() << "a patch with a slit was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("slit"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("vertex 4"), std::string::npos) << e.what();
  }
}

TEST(Quadrangulation, UnusedVerticesDoNotCountAsSurface) {
  // A mesh file may hold vertices no face uses (here far away from the box): the distance check
  // must measure the surface only, not refine again and again towards points that are not on it.
  SurfaceMesh box = makeRoundedBox();
  std::vector<Vec3> positions = box.positions();
  positions.push_back(Vec3(40, 40, 40));
  positions.push_back(Vec3(-40, 0, 0));
  auto q = layoutOf(SurfaceMesh(positions, box.faces()));
  QuadrangulationOptions options;
  options.targetEdgeLength = 0.03 * makeRoundedBox().boundingBoxDiagonal();
  const QuadrangulationResult r = quadrangulate(q->patches, options);
  EXPECT_EQ(r.refinements, 0);
  EXPECT_LE(r.deviation, r.deviationLimit);
  EXPECT_LT(r.deviationLimit, 0.011 * makeRoundedBox().boundingBoxDiagonal()) << "the limit follows the surface's size";
}

namespace {

/// Three patches around one t-junction, segments of the given lengths (11): A (bottom 5, right
/// 1 + 2, top 6, left 0), B (7, 3, 8, 1) and C (9, 4, 10, 2); B and C sit on A's right side.
PatchGraph tJunctionGraph(const std::vector<double>& length) {
  PatchGraph graph;
  for (double l : length) {
    LayoutSegment seg;
    seg.length = l;
    graph.segments.push_back(seg);
  }
  auto patch = [](std::vector<int> bottom, std::vector<int> right, std::vector<int> top, std::vector<int> left) {
    PatchSides ps;
    int k = 0;
    for (const auto& side : {bottom, right, top, left}) {
      for (int s : side) ps.sides[k].push_back({s, false, 0});
      ++k;
    }
    return ps;
  };
  graph.patches = {patch({5}, {1, 2}, {6}, {0}), patch({7}, {3}, {8}, {1}), patch({9}, {4}, {10}, {2})};
  return graph;
}

}  // namespace

TEST(Quadrangulation, SideLengthsSolvedByPartsAreOptimal) {
  // A t-junction: patch A's right side is two segments (1, 2), the left sides of patches B and
  // C; A's left side is segment 0. Opposite single segments are chord classes: {1, 3}, {2, 4},
  // {5, 6} (A's top and bottom), {7, 8} (B's), {9, 10} (C's). Only A's left-right equality
  // links classes: 0 = 1 + 2. Target edge 1, so the ideal counts are the lengths.
  const std::vector<double> length = {10, 3, 3, 3.2, 2.9, 4, 5, 6, 6.4, 2.2, 2.6};
  const PatchGraph graph = tJunctionGraph(length);
  const SideLengths lengths = solveSideLengths(graph, 1.0, 30);
  EXPECT_EQ(lengths.parts, 4);     // {0, 1–3, 2–4}, {5, 6}, {7, 8}, {9, 10}
  EXPECT_EQ(lengths.programs, 1);  // only the first needs lp_solve
  EXPECT_TRUE(lengths.inconsistentPatches.empty());
  const auto& n = lengths.segments;
  EXPECT_EQ(n[0], n[1] + n[2]);
  EXPECT_EQ(n[1], n[3]);
  EXPECT_EQ(n[2], n[4]);
  // Brute force of the documented cost: Σ max(n − ideal, 3·(ideal − n)), counts of a class at
  // least floor(max ideal / 1.5), and 0 = 1 + 2.
  auto cost = [](int count, std::initializer_list<double> ideals) {
    double c = 0;
    for (double ideal : ideals) c += std::max(count - ideal, 3 * (ideal - count));
    return c;
  };
  double best = 1e300;
  for (int a = 2; a < 20; ++a)
    for (int b = 2; b < 20; ++b)
      if (a + b >= 6) best = std::min(best, cost(a + b, {10}) + cost(a, {3, 3.2}) + cost(b, {3, 2.9}));
  EXPECT_NEAR(cost(n[0], {10}) + cost(n[1], {3, 3.2}) + cost(n[2], {3, 2.9}), best, 1e-9);
  for (auto [i, j] : {std::pair{5, 6}, {7, 8}, {9, 10}}) {
    EXPECT_EQ(n[i], n[j]);
    for (int other = 1; other < 20; ++other)
      EXPECT_LE(cost(n[i], {length[i], length[j]}), cost(other, {length[i], length[j]})) << "segments " << i << ", " << j;
  }
}

TEST(Quadrangulation, SideLengthsCanDropTheStretchBound) {
  // The same t-junction (0 = 1 + 2), but segment 3 (opposite 1) is 75 long: its class must get
  // at least floor(75 / 1.5) = 50 quads, while segment 0 (10 long) may get at most
  // 4·10 + 4 = 44. With the bound, A's sides cannot agree; without it they do.
  const std::vector<double> length = {10, 3, 3, 75, 2.9, 4, 5, 6, 6.4, 2.2, 2.6};
  const PatchGraph graph = tJunctionGraph(length);
  const SideLengths bounded = solveSideLengths(graph, 1.0, 30);
  EXPECT_EQ(bounded.inconsistentPatches, std::vector<int>{0});
  EXPECT_GE(bounded.segments[3], 50);
  const SideLengths free = solveSideLengths(graph, 1.0, 30, false);
  EXPECT_TRUE(free.inconsistentPatches.empty());
  EXPECT_EQ(free.segments[0], free.segments[1] + free.segments[2]);
  EXPECT_EQ(free.segments[1], free.segments[3]);
}

TEST(Quadrangulation, SplittingAPatchWithTJunctionsGivesConsistentParts) {
  // The torus example's layout is one patch with t-junctions on its sides: split it as a zero
  // chain would be split, and check the result is consistent: every part a regular grid, the
  // centre of the n-gon of valence n, the valence defects still adding up to 4·χ.
  auto q = layoutOf(makeExample("torus"));
  ASSERT_GT(q->layout.tJunctions, 0);
  PatchGraph graph = buildPatchGraph(q->patches);
  int target = -1, segments = 0;
  for (int p = 0; p < int(graph.patches.size()); ++p) {
    int n = 0;
    for (const auto& side : graph.patches[p].sides) n += int(side.size());
    if (n > 4 && target < 0) target = p, segments = n;
  }
  ASSERT_GE(target, 0) << "no patch with a t-junction on its sides";
  splitPatches(graph, q->patches, {target});
  EXPECT_FALSE(graph.patches[target].active);
  int parts = 0;
  for (const auto& ps : graph.patches)
    if (ps.active && ps.chart >= 0) {
      ++parts;
      for (const auto& side : ps.sides) EXPECT_EQ(side.size(), 1u);
    }
  EXPECT_EQ(parts, segments);
  const SideLengths lengths = solveSideLengths(graph, 0.03 * q->mesh.boundingBoxDiagonal(), 30);
  ASSERT_TRUE(lengths.inconsistentPatches.empty());
  const QuadMesh mesh = samplePatches(q->patches, graph, lengths);
  const QuadMeshReport report = checkQuadMesh(mesh);
  EXPECT_TRUE(report.manifold) << report.problem;
  EXPECT_EQ(report.genus, 1);
  std::map<int, int> histogram;
  for (int v : valences(mesh)) ++histogram[v];
  EXPECT_EQ(histogram[segments], 1) << "the centre of the split has valence " << segments;
  // Closed surface: the valence defects add up to 4·χ (0 on the torus), split or not.
  int defect = 0;
  for (const auto& h : histogram) defect += (4 - h.first) * h.second;
  EXPECT_EQ(defect, 4 * q->mesh.eulerCharacteristic());
}

TEST(Quadrangulation, NeighboursSplitInOneRoundShareTheMiddleOfTheirSide) {
  // Two adjacent patches of the rounded box split in one round: their shared segment is
  // halved once, so each becomes 4 quads (a Catmull-Clark step of both). Halving it again for
  // the second patch would make that one a pentagon of 5 parts, with a t-junction against
  // the first one's parts.
  auto q = layoutOf(makeRoundedBox());
  ASSERT_EQ(q->patches.numPatches(), 6);
  PatchGraph graph = buildPatchGraph(q->patches);
  int a = -1, b = -1;
  for (const auto& s : graph.segments)
    if (s.patchA >= 0 && s.patchB >= 0 && s.patchA != s.patchB) {
      a = s.patchA, b = s.patchB;
      break;
    }
  ASSERT_GE(a, 0);
  splitPatches(graph, q->patches, {a, b});
  int parts = 0;
  for (const auto& p : graph.patches) {
    if (!p.active) continue;
    if (p.layoutPatch != a && p.layoutPatch != b) continue;
    ++parts;
    int segments = 0;
    for (const auto& side : p.sides) segments += int(side.size());
    EXPECT_EQ(segments, 4) << "a part of layout patch " << p.layoutPatch << " has a t-junction";
  }
  EXPECT_EQ(parts, 8);
  const SideLengths lengths = solveSideLengths(graph, 0.05 * q->mesh.boundingBoxDiagonal(), 10);
  EXPECT_TRUE(lengths.inconsistentPatches.empty());
}

TEST(Quadrangulation, WarmRoundsSolveAgainAroundTheSplitsOnly) {
  // A warm round (the last counts given) after a split: the counts agree on every patch, as a
  // whole solve's do. Given counts of the same graph (nothing split since), every class keeps
  // its count.
  auto q = layoutOf(makeRoundedBox());
  PatchGraph graph = buildPatchGraph(q->patches);
  const double target = 0.05 * q->mesh.boundingBoxDiagonal();
  const SideLengths before = solveSideLengths(graph, target, 10);
  ASSERT_TRUE(before.inconsistentPatches.empty());
  const SideLengths same = solveSideLengths(graph, target, 10, true, &before.segments);
  EXPECT_EQ(same.segments, before.segments);
  EXPECT_EQ(same.programs, 0);
  splitPatches(graph, q->patches, {0});
  const SideLengths warm = solveSideLengths(graph, target, 10, true, &before.segments);
  EXPECT_TRUE(warm.inconsistentPatches.empty());
  ASSERT_EQ(warm.segments.size(), graph.segments.size());
  for (int n : warm.segments) EXPECT_GE(n, 1);
}

TEST(Quadrangulation, SharedMeshesGiveCloseManifoldQuadMeshes) {
  FCQL_REQUIRE_SHARED_WITH_FIELD(mesh, field, "eight");
  auto q = layoutOf(mesh, &field);
  checkQuadMesh(*q, quadrangulateWithDefaults(*q, 0.02), "eight");
  FCQL_REQUIRE_SHARED(kitten, "kitten.obj");
  auto k = layoutOf(loadMesh(kitten));
  checkQuadMesh(*k, quadrangulateWithDefaults(*k, 0.02), "kitten");
}

TEST(Quadrangulation, PatchesWhereTheFieldAlignedQuadsStrayGetArcLengthSidesAlone) {
  // The eight's field-aligned quads at 2% of the diagonal stray past a bound of 0.7% (its
  // patches' grids, stretched along the field and their sides sampled unevenly to follow it,
  // cut across the holes' curvature). The patches near the points found too far get arc
  // length on their sides (mean-value coordinates inside only if that is not enough), the
  // others keep the field, and the mesh meets the bound at the asked size: no refinement, not
  // the whole stage without the field.
  FCQL_REQUIRE_SHARED_WITH_FIELD(mesh, field, "eight");
  auto q = layoutOf(mesh, &field);
  QuadrangulationOptions options = fieldAlignedOptions(*q, 0.007);
  options.ilpTimeLimit = 30;
  const QuadrangulationResult r = quadrangulate(q->patches, options);
  const int marked = r.boundArcLengthPatches + r.boundMeanValuePatches;
  EXPECT_GT(marked, 0) << "the eight's field-aligned quads now meet 0.7%: pick another case";
  EXPECT_LT(marked, q->patches.numPatches());
  ASSERT_EQ(int(r.meanValuePatches.size()), q->patches.numPatches());
  EXPECT_EQ(std::count(r.meanValuePatches.begin(), r.meanValuePatches.end(), kMeanValuePatch), r.boundMeanValuePatches);
  EXPECT_EQ(std::count(r.meanValuePatches.begin(), r.meanValuePatches.end(), kArcLengthSides), r.boundArcLengthPatches);
  EXPECT_FALSE(r.boundWithoutField);
  EXPECT_EQ(r.refinements, 0);
  EXPECT_GT(r.mesh.alignedPatches, 0);
  EXPECT_LE(r.deviationBound, r.deviationLimit);
  // Independently of the stage's own measure: dense samples both ways.
  const ClosestPointIndex index(q->mesh);
  const QuadQuality quality = measureQuadQuality(r.mesh, q->mesh, q->field, index);
  EXPECT_LE(quality.hausdorffRelative, 0.007);
  EXPECT_EQ(quality.invertedQuads, 0);
  EXPECT_TRUE(r.report.manifold);
  EXPECT_EQ(r.report.genus, q->mesh.genus());
}

TEST(Quadrangulation, ZeroChainOfTheBunnyIsResolved) {
  FCQL_REQUIRE_SHARED(bunny, "bunny.obj");
  auto q = layoutOf(loadMesh(bunny), nullptr, withTJunctions());
  const QuadrangulationResult r = quadrangulateWithDefaults(*q, 0.02);
  EXPECT_GT(r.splitPatches, 0) << "the bunny's layout no longer has a zero chain: pick another case";
  EXPECT_TRUE(r.lengths.inconsistentPatches.empty());
  checkQuadMesh(*q, r, "bunny");
}

TEST(Quadrangulation, ZeroChainsLeftWhenTheRoundsRunOutAreResolvedBySplittingEveryPatch) {
  // The kitten's layout has zero chains that one round of splits resolves. Without any round,
  // the side lengths are solved once more without the bound on stretching (which alone can
  // contradict the t-junction equalities), and when patches still disagree every patch is
  // split once (§4.4's worst case): its parts have single-segment sides only, so the counts
  // agree and the stage never fails on a valid layout.
  FCQL_REQUIRE_SHARED(kitten, "kitten.obj");
  auto q = layoutOf(loadMesh(kitten), nullptr, withTJunctions());
  QuadrangulationOptions options;
  options.targetEdgeLength = 0.02 * q->mesh.boundingBoxDiagonal();
  options.maxSplitRounds = 0;
  const QuadrangulationResult all = quadrangulate(q->patches, options);
  EXPECT_TRUE(all.stretchBoundDropped);
  EXPECT_TRUE(all.splitEverything);
  EXPECT_EQ(all.splitRounds, 0);
  EXPECT_GE(all.splitPatches, q->patches.numPatches()) << "every patch was split";
  EXPECT_TRUE(all.lengths.inconsistentPatches.empty());
  checkQuadMesh(*q, all, "kitten, every patch split");
  options.maxSplitRounds = 1;
  const QuadrangulationResult r = quadrangulate(q->patches, options);
  EXPECT_GT(r.splitPatches, 0);
  EXPECT_EQ(r.splitRounds, 1);
  EXPECT_FALSE(r.stretchBoundDropped);
  EXPECT_FALSE(r.splitEverything);
  // A patch without t-junctions is split into four quads around a regular vertex: the last
  // resort adds irregular vertices only at the centres of patches with t-junctions.
  EXPECT_LE(all.report.irregularVertices, r.report.irregularVertices + 2 * q->layout.tJunctions);
  checkQuadMesh(*q, r, "kitten, one round of splits");
}

TEST(Quadrangulation, PatchWithFiveCornersIsCutIntoQuads) {
  // Give one patch of the rounded box an extra corner in the middle of a side (as a layout with
  // a wrongly placed corner would): it is quadrangulated as a pentagon, with a valence-5 centre.
  auto q = layoutOf(makeRoundedBox());
  PatchReport& patch = q->patches.patches[0];
  int extra = -1;
  for (std::size_t k = 0, run = 0; k < patch.loop.size(); ++k) {
    run = patch.loopCorner[k] ? 0 : run + 1;
    if (run == 4 && !q->patches.corner[patch.loop[k]]) {
      extra = int(k);
      break;
    }
  }
  ASSERT_GE(extra, 0);
  patch.loopCorner[extra] = 1;
  q->patches.corner[patch.loop[extra]] = 1;
  patch.corners = 5;
  patch.valid = false;
  patch.problem = "5 corners";
  const QuadrangulationResult r = quadrangulateWithDefaults(*q, 0.03);
  EXPECT_EQ(r.polygonPatches, 1);
  EXPECT_TRUE(r.report.manifold) << r.report.problem;
  EXPECT_EQ(r.report.genus, 0);
  std::map<int, int> histogram;
  for (int v : valences(r.mesh)) ++histogram[v];
  EXPECT_GE(histogram[5], 1);
  int defect = 0;
  for (const auto& h : histogram) defect += (4 - h.first) * h.second;
  EXPECT_EQ(defect, 4 * 2);
  // A patch that is not a disk still fails with the reason.
  patch.isDisk = false;
  EXPECT_THROW(quadrangulateWithDefaults(*q, 0.03), std::runtime_error);
}

TEST(Quadrangulation, CoarseInputsGiveAValidQuadMeshOrAClearError) {
  // A tetrahedron (its layout has triangles and a patch the sampling cannot handle) and a flat
  // square: the stage either returns a manifold quad mesh of the right topology or throws
  // with a reason; it never returns a broken mesh.
  SurfaceMesh tet({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
  std::vector<Vec3> grid;
  std::vector<std::array<int, 3>> squares;
  const int n = 10;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) grid.push_back({double(i) / n, double(j) / n, 0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      squares.push_back({a, a + 1, a + n + 2});
      squares.push_back({a, a + n + 2, a + n + 1});
    }
  int succeeded = 0;
  for (const SurfaceMesh& mesh : {tet, SurfaceMesh(grid, squares)}) {
    try {
      auto q = layoutOf(mesh);  // its patch graph may already refuse the layout (a slit)
      const QuadrangulationResult r = quadrangulateWithDefaults(*q, 0.05);
      EXPECT_TRUE(r.report.manifold) << r.report.problem;
      EXPECT_EQ(r.report.genus, q->mesh.genus());
      EXPECT_EQ(r.report.borderLoops, q->mesh.numBorderLoops());
      ++succeeded;
    } catch (const std::runtime_error& e) {
      EXPECT_GT(std::string(e.what()).size(), 10u);
    }
  }
  EXPECT_GE(succeeded, 1) << "the flat square must quadrangulate";
}

TEST(Quadrangulation, SmoothingUntanglesAFoldedQuad) {
  // A 3×3 grid of unit quads on the plane z = 0 with one inner vertex pushed across the
  // diagonal of its quad: three quads fold. One round with a tiny Laplacian step cannot undo
  // that; the untangling pass must, keeping the vertex on the surface.
  QuadMesh grid;
  for (int j = 0; j <= 3; ++j)
    for (int i = 0; i <= 3; ++i) grid.positions.push_back(Vec3(i, j, 0));
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) grid.quads.push_back({4 * j + i, 4 * j + i + 1, 4 * (j + 1) + i + 1, 4 * (j + 1) + i});
  grid.positions[5] = Vec3(2.3, 2.3, 0);  // vertex (1, 1) beyond (2, 2)
  int folded = 0;
  for (int q = 0; q < grid.numQuads(); ++q) folded += scaledJacobian(grid, q) <= 0;
  ASSERT_GE(folded, 2);
  const std::vector<Vec3> plane = {Vec3(-1, -1, 0), Vec3(4, -1, 0), Vec3(4, 4, 0), Vec3(-1, 4, 0)};
  const std::vector<std::array<int, 3>> triangles = {{0, 1, 2}, {0, 2, 3}};
  SmoothingOptions options;
  options.iterations = 1;
  options.step = 0.01;
  const SmoothingReport report = smoothQuadMesh(grid, plane, triangles, options);
  EXPECT_GT(report.untangledMoves, 0);
  for (int q = 0; q < grid.numQuads(); ++q) EXPECT_GT(scaledJacobian(grid, q), 0.1) << "quad " << q;
  for (const Vec3& p : grid.positions) EXPECT_NEAR(p.z(), 0, 1e-12);
}

TEST(Quadrangulation, SmoothingMovesOnlyTheVerticesNotFrozen) {
  // A 10×10 grid of unit quads on the plane z = 0 with two inner vertices pushed across the
  // diagonals of their quads: one fold in the left half, one in the right. With the right half
  // frozen (as reduceFolds freezes all but the region around the folds it samples again), the
  // smoothing unfolds the left fold and leaves every frozen vertex exactly where it was, the
  // right fold included.
  const int n = 10;
  QuadMesh grid = test::planarGrid(n);
  auto vertex = [&](int i, int j) { return (n + 1) * j + i; };
  grid.positions[vertex(2, 5)] = Vec3(3.3, 6.3, 0);  // left: beyond (3, 6)
  grid.positions[vertex(8, 5)] = Vec3(9.3, 6.3, 0);  // right: beyond (9, 6)
  auto foldedIn = [&](bool left) {
    int folded = 0;
    for (int q = 0; q < grid.numQuads(); ++q)
      folded += scaledJacobian(grid, q) <= 0 && (q % n < n / 2) == left;
    return folded;
  };
  ASSERT_GE(foldedIn(true), 1);
  ASSERT_GE(foldedIn(false), 1);
  const std::vector<Vec3> plane = {Vec3(-1, -1, 0), Vec3(n + 1, -1, 0), Vec3(n + 1, n + 1, 0), Vec3(-1, n + 1, 0)};
  const std::vector<std::array<int, 3>> triangles = {{0, 1, 2}, {0, 2, 3}};
  SmoothingOptions options;
  options.iterations = 3;
  options.frozen.assign(grid.positions.size(), 0);
  for (int j = 0; j <= n; ++j)
    for (int i = n / 2 + 1; i <= n; ++i) options.frozen[vertex(i, j)] = 1;
  const QuadMesh start = grid;
  smoothQuadMesh(grid, plane, triangles, options);
  EXPECT_EQ(foldedIn(true), 0);
  EXPECT_GE(foldedIn(false), 1);
  int moved = 0;
  for (std::size_t v = 0; v < grid.positions.size(); ++v) {
    if (options.frozen[v]) EXPECT_EQ(grid.positions[v], start.positions[v]) << "frozen vertex " << v << " moved";
    else moved += grid.positions[v] != start.positions[v];
    EXPECT_NEAR(grid.positions[v].z(), 0, 1e-12);
  }
  EXPECT_GT(moved, 0);
  options.frozen.pop_back();
  EXPECT_THROW(smoothQuadMesh(grid, plane, triangles, options), std::invalid_argument);
}

TEST(Quadrangulation, UntanglingSlidesAVertexAlongACrease) {
  // A sheet bent at a right angle along the x axis: the face y = 0..2 on z = 0 and the face
  // z = 0..-2 on y = 0, quads of 0.5 on both, their middle row of vertices on the crease. One
  // crease vertex is pushed along the crease beyond its neighbour: the quads on both sides of it
  // fold, and no vertex off the crease can unfold them (the crease's order is wrong). Feature
  // vertices stay in smoothing; the untangling slides it back along the crease, never off it.
  const int n = 8;  // quads along x
  auto at = [&](int i, int k) { return k * (n + 1) + i; };  // k = 0..8: z = -2 .. 0 .. y = 2
  auto point = [&](int i, int k) {
    const double x = 0.5 * i, s = 0.5 * (k - 4);
    return s <= 0 ? Vec3(x, 0, s) : Vec3(x, s, 0);
  };
  QuadMesh grid;
  for (int k = 0; k <= 8; ++k)
    for (int i = 0; i <= n; ++i) grid.positions.push_back(point(i, k));
  for (int k = 0; k < 8; ++k)
    for (int i = 0; i < n; ++i) grid.quads.push_back({at(i, k), at(i, k + 1), at(i + 1, k + 1), at(i + 1, k)});
  // The surface: the same grid, each square cut into two triangles (the crease is sharp).
  std::vector<std::array<int, 3>> triangles;
  for (const auto& q : grid.quads) triangles.push_back({q[0], q[1], q[2]}), triangles.push_back({q[0], q[2], q[3]});
  const std::vector<Vec3> surface = grid.positions;
  const QuadJacobian before(grid);
  for (int q = 0; q < grid.numQuads(); ++q) ASSERT_GT(before(q), 0.5) << "the bent grid must start unfolded";
  const int pushed = at(4, 4);
  grid.positions[pushed] = Vec3(2.7, 0, 0);  // from x = 2 beyond its neighbour at 2.5
  int folded = 0;
  for (int q = 0; q < grid.numQuads(); ++q) folded += QuadJacobian(grid)(q) <= 0;
  ASSERT_GE(folded, 2) << "pushing the crease vertex must fold quads for this test to mean anything";
  SmoothingOptions options;
  options.iterations = 3;
  const SmoothingReport report = smoothQuadMesh(grid, surface, triangles, options);
  EXPECT_GT(report.untangledMoves, 0);
  const QuadJacobian after(grid);
  for (int q = 0; q < grid.numQuads(); ++q) EXPECT_GT(after(q), 0) << "quad " << q << " is still folded";
  // Still on the crease, now between its neighbours there.
  EXPECT_NEAR(grid.positions[pushed].y(), 0, 1e-9);
  EXPECT_NEAR(grid.positions[pushed].z(), 0, 1e-9);
  EXPECT_GT(grid.positions[pushed].x(), 1.5);
  EXPECT_LT(grid.positions[pushed].x(), 2.5);
  // The other crease vertices did not move.
  for (int i = 0; i <= n; ++i)
    if (at(i, 4) != pushed) EXPECT_EQ(grid.positions[at(i, 4)], surface[at(i, 4)]) << "crease vertex " << i;
}

TEST(Quadrangulation, ASmoothingStepThatWouldFoldAQuadIsNotTaken) {
  // A 2×2 grid on the plane z = 0 whose only free vertex is the centre (the others are on the
  // border). Its star is not convex: the average of its four neighbours, where one full step
  // (step 1) takes it, folds the second quad. The step is refused and no quad folds.
  QuadMesh grid;
  grid.positions = {Vec3(0.5, -0.5, 0), Vec3(1, 0, 0),  Vec3(1.5, -1.5, 0), Vec3(0, 0.5, 0), Vec3(1, 1, 0),
                    Vec3(1.5, 1, 0),    Vec3(-1, 2, 0), Vec3(-0.5, 2.5, 0), Vec3(1.5, 2, 0)};
  grid.quads = {{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 7, 6}, {4, 5, 8, 7}};
  const Vec3 centre = grid.positions[4];
  const Vec3 average = (grid.positions[1] + grid.positions[3] + grid.positions[5] + grid.positions[7]) / 4;
  for (int q = 0; q < grid.numQuads(); ++q) ASSERT_GT(QuadJacobian(grid)(q), 0.3) << "quad " << q;
  grid.positions[4] = average;
  ASSERT_LE(QuadJacobian(grid)(1), 0) << "the unguarded step must fold a quad for this test to mean anything";
  grid.positions[4] = centre;
  const std::vector<Vec3> plane = {Vec3(-3, -3, 0), Vec3(4, -3, 0), Vec3(4, 4, 0), Vec3(-3, 4, 0)};
  const std::vector<std::array<int, 3>> triangles = {{0, 1, 2}, {0, 2, 3}};
  SmoothingOptions options;
  options.iterations = 3;
  options.step = 1;
  const SmoothingReport report = smoothQuadMesh(grid, plane, triangles, options);
  EXPECT_EQ(report.fixedVertices, 8);
  EXPECT_GT(report.revertedMoves, 0);
  EXPECT_EQ(grid.positions[4], centre);
  const QuadJacobian jacobian(grid);
  for (int q = 0; q < grid.numQuads(); ++q) EXPECT_GT(jacobian(q), 0.1) << "quad " << q;
}

TEST(Quadrangulation, AnInnerVertexInTwoQuadsIsDissolved) {
  // Two quads (v, a, x, b) and (v, b, y, a) around v = (0, 0): whatever v does, one of them is
  // folded on the plane. They become the diamond (a, x, b, y); a grid keeps all its vertices.
  QuadMesh pair;
  pair.positions = {Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0), Vec3(1, 0, 0)};
  pair.quads = {{0, 1, 2, 3}, {0, 3, 4, 1}};
  pair.quadPatch = {7, 8};
  EXPECT_EQ(dissolveTwoValentVertices(pair), 1);
  ASSERT_EQ(pair.numQuads(), 1);
  ASSERT_EQ(pair.numVertices(), 4);
  EXPECT_EQ(pair.quadPatch, std::vector<int>{7});
  const std::array<Vec3, 4> expected = {Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0), Vec3(1, 0, 0)};
  for (int i = 0; i < 4; ++i) EXPECT_EQ(pair.positions[pair.quads[0][i]], expected[i]) << "corner " << i;
  EXPECT_GT(scaledJacobian(pair, 0), 0.99);
  QuadMesh grid;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i) grid.positions.push_back(Vec3(i, j, 0));
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) grid.quads.push_back({3 * j + i, 3 * j + i + 1, 3 * (j + 1) + i + 1, 3 * (j + 1) + i});
  EXPECT_EQ(dissolveTwoValentVertices(grid), 0);
  EXPECT_EQ(grid.numQuads(), 4);
  EXPECT_EQ(grid.numVertices(), 9);
}

TEST(Quadrangulation, AQuadTurnedAgainstTheSurfaceCountsAsFolded) {
  // A 3×3 grid on z = 0 whose centre quad is turned over: its four corners mirrored across
  // x = 1.5 and lifted, so it faces −z while agreeing with its own normal at every corner.
  // Against its own normal alone it looks perfect; against the surface normal it is folded.
  QuadMesh grid;
  for (int j = 0; j <= 3; ++j)
    for (int i = 0; i <= 3; ++i) grid.positions.push_back(Vec3(i, j, 0));
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) grid.quads.push_back({4 * j + i, 4 * j + i + 1, 4 * (j + 1) + i + 1, 4 * (j + 1) + i});
  for (int v : {5, 6, 9, 10}) grid.positions[v] = Vec3(3 - grid.positions[v].x(), grid.positions[v].y(), 0.01);
  EXPECT_GT(scaledJacobian(grid, 4), 0.9);
  EXPECT_LE(QuadJacobian(grid)(4), 0);
  EXPECT_EQ(QuadJacobian(grid, false)(4), scaledJacobian(grid, 4));
}

TEST(Quadrangulation, SmoothingIsUndoneAroundPointsFarFromTheSurface) {
  // A 9×9 grid of unit quads; "smoothing" moved every vertex by (0.2, 0.1). Around a far point
  // at vertex (4, 4) with radius 2: vertices within 1 go back all the way, those between 1
  // and 2 part of the way, the others not at all. A return that would fold a quad is skipped.
  const int n = 9;
  QuadMesh grid = test::planarGrid(n);
  const std::vector<Vec3> sampled = grid.positions;
  const Vec3 shift(0.2, 0.1, 0);
  for (Vec3& p : grid.positions) p += shift;
  const Vec3 far = Vec3(4, 4, 0) + shift;
  const int restored = restoreSampledPositions(grid, sampled, {far}, 2.0);
  int expected = 0;
  for (int v = 0; v < grid.numVertices(); ++v) {
    const double d = (sampled[v] + shift - far).norm();
    const double share = d < 1 ? 1 : d < 2 ? 2 * (1 - d / 2) : 0;
    expected += share > 0;
    EXPECT_LT((grid.positions[v] - (sampled[v] + shift * (1 - share))).norm(), 1e-12) << "vertex " << v;
  }
  EXPECT_EQ(restored, expected);
  EXPECT_GE(restored, 9);

  // The sampled position of vertex (4, 4) lies beyond its neighbour (5, 5): going back would
  // fold its quads, so it keeps its smoothed position; the others still go back.
  std::vector<Vec3> folding = sampled;
  folding[(n + 1) * 4 + 4] = Vec3(5.5, 5.5, 0);
  for (int v = 0; v < grid.numVertices(); ++v) grid.positions[v] = sampled[v] + shift;
  const int partly = restoreSampledPositions(grid, folding, {far}, 2.0);
  EXPECT_EQ(partly, expected - 1);
  EXPECT_EQ(grid.positions[(n + 1) * 4 + 4], Vec3(4, 4, 0) + shift);
  for (int q = 0; q < grid.numQuads(); ++q) EXPECT_GT(scaledJacobian(grid, q), 0.1) << "quad " << q;
  EXPECT_EQ(restoreSampledPositions(grid, sampled, {}, 2.0), 0);
  EXPECT_THROW(restoreSampledPositions(grid, {Vec3::Zero()}, {far}, 2.0), std::invalid_argument);
}

namespace {

/// The surface of an n × n grid of unit squares in z = 0 with one more vertex, `tip`: inside a
/// cell, that cell's square becomes a pyramid onto it; at a grid point, it replaces that vertex.
std::pair<std::vector<Vec3>, std::vector<std::array<int, 3>>> gridSurfaceWithTip(int n, const Vec3& tip) {
  std::vector<Vec3> positions;
  std::vector<std::array<int, 3>> triangles;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) positions.push_back(Vec3(i, j, 0));
  const int apex = int(positions.size());
  positions.push_back(tip);
  const int ci = int(std::floor(tip.x())), cj = int(std::floor(tip.y()));
  const bool inCell = tip.x() != ci || tip.y() != cj;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = (n + 1) * j + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      if (inCell && i == ci && j == cj) {
        for (auto [u, v] : {std::pair{a, b}, {b, c}, {c, d}, {d, a}}) triangles.push_back({u, v, apex});
      } else {
        triangles.push_back({a, b, c});
        triangles.push_back({a, c, d});
      }
    }
  if (!inCell)  // the tip replaces the grid vertex under it
    for (auto& t : triangles)
      for (int& v : t)
        if (v == (n + 1) * cj + ci) v = apex;
  return std::make_pair(positions, triangles);
}

}  // namespace

TEST(Quadrangulation, VerticesGoOntoTheTipsTheQuadsMiss) {
  // A flat 9×9 grid of unit quads over a surface that is the same grid with one vertex lifted
  // 0.8 (a spike narrower than a quad), the bound 0.5. The quad vertex under the spike goes onto
  // its tip, one vertex for all the points of the spike farther than the bound; a point off the
  // surface is not taken. A tip at a border vertex, or over the middle of a quad (where its
  // nearest corners would fold their quads), moves nothing.
  const int n = 9;
  auto surfaceWithTip = [&](const Vec3& tip) { return gridSurfaceWithTip(n, tip); };
  const double limit = 0.5;

  const Vec3 tip(4, 4, 0.8);
  const auto [P, T] = surfaceWithTip(tip);
  const ClosestPointIndex surface(P, T);
  QuadMesh grid = test::planarGrid(n);
  const std::vector<Vec3> flat = grid.positions;
  const std::vector<Vec3> far = {Vec3(4.1, 4, 0.72), tip, Vec3(3.9, 4.05, 0.7), Vec3(2, 2, 0.9)};
  EXPECT_EQ(snapVerticesToFarPoints(grid, surface, far, limit, 0.1), 1);
  for (int v = 0; v < grid.numVertices(); ++v)
    EXPECT_EQ(grid.positions[v], v == (n + 1) * 4 + 4 ? tip : flat[v]) << "vertex " << v;
  for (int q = 0; q < grid.numQuads(); ++q) EXPECT_GT(scaledJacobian(grid, q), 0.1) << "quad " << q;
  SurfaceDeviation d = measureDeviation(grid, surface, limit, 0.01);
  EXPECT_LE(d.bound, limit) << "the quads still miss the tip";
  EXPECT_EQ(snapVerticesToFarPoints(grid, surface, d.farPoints, limit, 0.1), 0);

  // At a border vertex: that vertex stays on the border (an inner neighbour may go to the tip).
  {
    const Vec3 onBorder(0, 4, 0.8);
    const auto [P2, T2] = surfaceWithTip(onBorder);
    const ClosestPointIndex other(P2, T2);
    QuadMesh bordered = test::planarGrid(n);
    EXPECT_GT(measureDeviation(bordered, other, limit, 0.01).bound, limit);
    snapVerticesToFarPoints(bordered, other, {onBorder}, limit, 0.1);
    for (int j = 0; j <= n; ++j)
      EXPECT_EQ(bordered.positions[(n + 1) * j], flat[(n + 1) * j]) << "border vertex (0, " << j << ")";
    for (int q = 0; q < bordered.numQuads(); ++q) EXPECT_GT(scaledJacobian(bordered, q), 0.1) << "quad " << q;
  }
  // A tip across a gap: the surface is two flat sheets, the quads cover one; the point on the
  // other sheet (1.2 above, the bound 0.5) would need quad edges through the gap: nothing moves.
  {
    std::vector<Vec3> P2;
    std::vector<std::array<int, 3>> T2;
    for (double z : {0.0, 1.2}) {
      const int o = int(P2.size());
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) P2.push_back(Vec3(i, j, z));
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const int a = o + (n + 1) * j + i;
          T2.push_back({a, a + 1, a + n + 2});
          T2.push_back({a, a + n + 2, a + n + 1});
        }
    }
    const ClosestPointIndex sheets(P2, T2);
    QuadMesh one = test::planarGrid(n);
    EXPECT_EQ(snapVerticesToFarPoints(one, sheets, {Vec3(4, 4, 1.2)}, limit, 0.1), 0);
    EXPECT_EQ(one.positions, flat);
  }
  // Over the middle of a quad: a corner goes onto it, its quads still at a scaled Jacobian of
  // about 0.75; asked to keep them above 0.9, none moves.
  {
    const Vec3 middle(4.5, 4.5, 0.8);
    const auto [P2, T2] = surfaceWithTip(middle);
    const ClosestPointIndex other(P2, T2);
    QuadMesh strict = test::planarGrid(n);
    EXPECT_EQ(snapVerticesToFarPoints(strict, other, {middle}, limit, 0.9), 0);
    EXPECT_EQ(strict.positions, flat);
    QuadMesh loose = test::planarGrid(n);
    EXPECT_EQ(snapVerticesToFarPoints(loose, other, {middle}, limit, 0.1), 1);
    EXPECT_EQ(std::count(loose.positions.begin(), loose.positions.end(), middle), 1);
    for (int q = 0; q < loose.numQuads(); ++q) EXPECT_GT(scaledJacobian(loose, q), 0.1) << "quad " << q;
    EXPECT_LE(measureDeviation(loose, other, limit, 0.01).bound, limit);
  }
}

TEST(Quadrangulation, QuadsArePulledUpASpikeLongerThanTheyAreWide) {
  // The 9 × 9 grid of unit squares with the vertex (4, 4) lifted 3.5: a spike three and a half
  // quads tall and two wide, the bound 0.5. Snapping, in rounds as the quad stage runs it (each
  // round on the points still too far, kept while the bound drops), takes vertices only part of
  // the way up (higher, their quads would be nearly flat against the surface normal there): the
  // quads still miss the tip by more than three times the bound. Pulled, the vertex under the
  // tip goes onto it and the quads around follow: within 1.5 times the bound (what is left is
  // the bend of the quads at the spike's foot), no quad folded, the border in place, every
  // vertex on the surface.
  const int n = 9;
  const Vec3 tip(4, 4, 3.5);
  const auto [P, T] = gridSurfaceWithTip(n, tip);
  const ClosestPointIndex surface(P, T);
  const double limit = 0.5;
  auto rounds = [&](QuadMesh& m, const auto& move) {
    for (int round = 0; round < 3; ++round) {
      const SurfaceDeviation d = measureDeviation(m, surface, limit, 0.01);
      if (d.bound <= limit) return;
      const std::vector<Vec3> was = m.positions;
      if (move(m, d.farPoints) == 0) return;
      if (!(measureDeviation(m, surface, limit, 0.01).bound < d.bound)) return void(m.positions = was);
    }
  };
  auto snap = [&](QuadMesh& m, const std::vector<Vec3>& far) {
    return snapVerticesToFarPoints(m, surface, far, limit, 0.1);
  };
  auto pull = [&](QuadMesh& m, const std::vector<Vec3>& far) {
    return pullVerticesToFarPoints(m, P, T, surface, far, limit, 0.1, SmoothingOptions(), 3);
  };
  QuadMesh snapped = test::planarGrid(n);
  rounds(snapped, snap);
  EXPECT_GT(measureDeviation(snapped, surface, limit, 0.01).bound, 3 * limit) << "snapping alone reached the tip";
  QuadMesh grid = test::planarGrid(n);
  const std::vector<Vec3> flat = grid.positions;
  rounds(grid, pull);
  EXPECT_LE(measureDeviation(grid, surface, limit, 0.01).bound, 1.5 * limit);
  EXPECT_EQ(std::count(grid.positions.begin(), grid.positions.end(), tip), 1);
  for (int q = 0; q < grid.numQuads(); ++q) EXPECT_GT(scaledJacobian(grid, q), 0) << "quad " << q;
  for (int v = 0; v < grid.numVertices(); ++v) {
    const int i = v % (n + 1), j = v / (n + 1);
    if (i == 0 || j == 0 || i == n || j == n) EXPECT_EQ(grid.positions[v], flat[v]) << "border vertex " << v;
    EXPECT_LT(surface.closest(grid.positions[v]).distance, 1e-9) << "vertex " << v;
  }
}

TEST(Quadrangulation, FandiskNeedsNoFinerPassOnceSmoothingSparesItsTips) {
  // Smoothing slid vertices off the fandisk's pointed corners and the quads strayed 1.1% from
  // the surface, so the whole stage ran again with smaller quads. Undoing the smoothing there
  // keeps the requested size within 1%.
  // The layout of this case is the one with t-junctions: the conforming one (completion) has
  // three nearly flat quads on a crease, a known exception of e2e.cli_run_shared (issue 21).
  FCQL_REQUIRE_SHARED(fandisk, "fandisk.obj");
  auto q = layoutOf(loadMesh(fandisk), nullptr, withTJunctions());
  const QuadrangulationResult r = quadrangulateWithDefaults(*q, 0.02);
  EXPECT_GT(r.restoredVertices, 0);
  EXPECT_EQ(r.refinements, 0);
  EXPECT_LE(r.deviation, r.deviationLimit);
  checkQuadMesh(*q, r, "fandisk");
}

TEST(Quadrangulation, ExitMeansTheDistanceBoundHoldsOnFandisk) {
  // The stage returns a mesh only within maxDeviation (1% of the diagonal) of the surface.
  // Checked here independently: both surfaces sampled on uniform barycentric grids 0.1% of the
  // diagonal apart (inside every triangle and along every edge), each sample against the
  // other surface. The measure the stage decides with must also bound this from above.
  FCQL_REQUIRE_SHARED(fandisk, "fandisk.obj");
  auto q = layoutOf(loadMesh(fandisk));
  const QuadrangulationResult r = quadrangulateWithDefaults(*q, 0.02);
  const double diagonal = q->mesh.boundingBoxDiagonal();
  const double limit = 0.01 * diagonal;
  const double spacing = 0.001 * diagonal;
  const ClosestPointIndex surface(q->mesh);
  std::vector<std::array<int, 3>> quadTris;
  for (const auto& f : r.mesh.quads) {  // shorter diagonal, as the mesh is read
    if ((r.mesh.positions[f[2]] - r.mesh.positions[f[0]]).squaredNorm() <=
        (r.mesh.positions[f[3]] - r.mesh.positions[f[1]]).squaredNorm())
      quadTris.push_back({f[0], f[1], f[2]}), quadTris.push_back({f[0], f[2], f[3]});
    else
      quadTris.push_back({f[0], f[1], f[3]}), quadTris.push_back({f[1], f[2], f[3]});
  }
  const ClosestPointIndex quads(r.mesh.positions, quadTris);
  const double dense = std::max(test::sampledOneWayDistance(r.mesh.positions, quadTris, surface, spacing),
                                test::sampledOneWayDistance(q->mesh.positions(), q->mesh.faces(), quads, spacing));
  std::cout << "fandisk: dense two-sided distance " << 100 * dense / diagonal << "% of the diagonal, stage bound "
            << 100 * r.deviationBound / diagonal << "%" << std::endl;
  EXPECT_LE(dense, limit);
  EXPECT_LE(r.deviationBound, r.deviationLimit);
  EXPECT_GE(r.deviationBound, dense - 1e-9 * diagonal);
}

TEST(Quadrangulation, ABoundThatCannotBeMetIsAnError) {
  // Quads of a third of the diagonal on a rounded box stray more than 1% from its rounded
  // edges; without refinements the stage cannot meet the bound and says so instead of
  // returning the mesh.
  auto q = layoutOf(makeRoundedBox());
  QuadrangulationOptions options;
  options.targetEdgeLength = 0.3 * q->mesh.boundingBoxDiagonal();
  options.maxRefinements = 0;
  try {
    quadrangulate(q->patches, options);
    ADD_FAILURE() << "a mesh farther than the bound was returned";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("above the bound of 1%"), std::string::npos) << e.what();
  }
}

TEST(Quadrangulation, SmoothingPutsVerticesOnSharpEdges) {
  // The cube's 12 sharp edges are separatrices of its layout, traced through the triangles next
  // to them: smoothing snaps the quad vertices close to the edges onto them, keeps those already
  // there, and none leaves the surface.
  SurfaceMesh cube = test::sharpCube(6);
  const CrossField field = test::axisField(cube);
  auto q = layoutOf(cube, &field);
  const auto [raw, smooth] = rawAndSmoothed(*q, 0.05 * q->mesh.boundingBoxDiagonal());
  ASSERT_EQ(raw.mesh.numVertices(), smooth.mesh.numVertices());
  auto onCubeEdge = [](const Vec3& p) {
    int atFace = 0;
    for (int k = 0; k < 3; ++k) atFace += std::abs(std::abs(p[k]) - 1) < 1e-9;
    return atFace >= 2;
  };
  int rawOnEdges = 0, smoothOnEdges = 0;
  for (int v = 0; v < raw.mesh.numVertices(); ++v) {
    if (onCubeEdge(raw.mesh.positions[v])) {
      ++rawOnEdges;
      EXPECT_EQ(raw.mesh.positions[v], smooth.mesh.positions[v]) << "vertex " << v << " left a sharp edge";
    }
    smoothOnEdges += onCubeEdge(smooth.mesh.positions[v]);
    EXPECT_LT(std::abs(smooth.mesh.positions[v].cwiseAbs().maxCoeff() - 1), 1e-9) << "vertex " << v << " is off the cube";
  }
  // The 8 corners are there from the start; vertices of the separatrices that run within a
  // third of a quad edge of the cube's edges are snapped onto them.
  EXPECT_GE(rawOnEdges, 8);
  EXPECT_GT(smoothOnEdges, rawOnEdges + 12);
  EXPECT_GT(smooth.smoothing.snappedMoves, 0);
  std::cout << "cube: " << rawOnEdges << " vertices on sharp edges before smoothing, " << smoothOnEdges << " after"
            << std::endl;
}

TEST(Quadrangulation, DeadEndSeparatrixIsRemovedAndItsPatchStillCut) {
  // The rounded box's layout with two of the three separatrices at one of its singularities
  // taken away: the third runs into the merged patch and stops there (a slit). removeDeadEnds
  // must drop it, leaving the singularity inside a disk patch with at least 3 corners, and the
  // quad stage must cut that patch into quads: pure, manifold, the box's topology.
  auto q = layoutOf(makeRoundedBox());
  ASSERT_EQ(q->layout.separatrices.size(), 12u);
  const int v = q->graph->ports()[q->layout.separatrices[0].portA].vertex;
  std::vector<LayoutSeparatrix> kept;
  int droppedAtV = 0;
  for (const auto& s : q->layout.separatrices) {
    const bool atV = q->graph->ports()[s.portA].vertex == v || q->graph->ports()[s.portB].vertex == v;
    if (atV && droppedAtV < 2) {
      ++droppedAtV;
      continue;
    }
    kept.push_back(s);
  }
  q->layout.separatrices = kept;
  ASSERT_EQ(q->layout.separatrices.size(), 10u);
  {
    PatchLayout withSlit = buildPatchLayout(*q->graph, q->layout);
    bool slit = false;
    for (const auto& p : withSlit.patches) slit = slit || p.problem.find("slit") != std::string::npos;
    EXPECT_TRUE(slit) << "the test set-up should leave a slit";
  }
  EXPECT_EQ(removeDeadEnds(*q->graph, q->layout), 1);
  EXPECT_EQ(q->layout.separatrices.size(), 9u);
  EXPECT_EQ(q->layout.unresolvedPorts.size(), 2u);  // the removed separatrix's two ports
  // No interior singular vertex keeps a single separatrix.
  std::map<int, int> ends;
  for (const auto& s : q->layout.separatrices)
    for (int p : {s.portA, s.portB})
      if (p >= 0) ++ends[q->graph->ports()[p].vertex];
  for (const auto& [vertex, count] : ends) EXPECT_NE(count, 1) << "vertex " << vertex;
  EXPECT_EQ(ends.count(v), 0u);
  q->patches = buildPatchLayout(*q->graph, q->layout);
  for (const auto& p : q->patches.patches) {
    EXPECT_TRUE(p.isDisk) << p.problem;
    EXPECT_GE(p.corners, 3) << p.problem;
    EXPECT_EQ(p.problem.find("slit"), std::string::npos) << p.problem;
  }
  QuadrangulationResult r = quadrangulateWithDefaults(*q, 0.05);
  // The topology and the distance as for any output; the merged patch holds the box corner's
  // cone point, which its flat chart does not see, so a few quads next to it may fold (3 of
  // about 5400 here): bounded, not zero.
  EXPECT_TRUE(r.report.manifold) << r.report.problem;
  EXPECT_EQ(r.report.genus, 0);
  EXPECT_EQ(r.report.eulerCharacteristic, 2);
  EXPECT_EQ(r.report.unusedVertices, 0);
  const ClosestPointIndex index(q->mesh);
  const QuadQuality quality = measureQuadQuality(r.mesh, q->mesh, q->field, index);
  EXPECT_LT(quality.hausdorffRelative, 0.01);
  EXPECT_LT(quality.invertedQuads, r.mesh.numQuads() / 200);
  EXPECT_GT(quality.meanScaledJacobian, 0.9);
}

TEST(Quadrangulation, UnresolvedPortIsNoCornerOfThePatchItOpensInto) {
  // The rounded box's layout (a cube: 8 singularities of index 1/4, 3 ports each, 12
  // separatrices, 6 patches) with one separatrix taken away: its two ends keep two
  // separatrices each, 180° apart on the side of the merged patch, whose boundary runs straight
  // on through them. The merged patch has the 4 corners of a 2×1 rectangle, not 6; the others
  // keep theirs, and the quad stage cuts it like any 4-sided patch.
  auto q = layoutOf(makeRoundedBox());
  ASSERT_EQ(q->layout.separatrices.size(), 12u);
  ASSERT_EQ(q->patches.numPatches(), 6);
  const LayoutSeparatrix removed = q->layout.separatrices[0];
  q->layout.separatrices.erase(q->layout.separatrices.begin());
  q->layout.unresolvedPorts = {removed.portA, removed.portB};
  q->patches = buildPatchLayout(*q->graph, q->layout);
  ASSERT_EQ(q->patches.numPatches(), 5);
  for (const auto& p : q->patches.patches) {
    EXPECT_TRUE(p.valid) << p.problem;
    EXPECT_EQ(p.corners, 4) << p.problem;
  }
  // The two ends are still corners, of the patches beyond the remaining separatrices.
  for (int port : {removed.portA, removed.portB}) EXPECT_TRUE(q->patches.corner[q->graph->ports()[port].vertex]);
  QuadrangulationResult r = quadrangulateWithDefaults(*q, 0.05);
  checkQuadMesh(*q, r, "box without a separatrix");
  EXPECT_EQ(r.polygonPatches, 0) << "no patch needed cutting as an n-gon";
}

TEST(Quadrangulation, UnresolvedPortAtAFiveValentSingularityIsNoCornerEither) {
  // The same on the double torus, whose layout has 16 singularities of index −1/4 (5 ports):
  // a separatrix with an end at one is taken away. At that end the merged patch spans two of
  // the five sectors (180°): 4 corners, like every other patch, and the quads are clean.
  auto q = layoutOf(makeDoubleTorus());
  ASSERT_EQ(q->patches.numInvalidPatches(), 0);
  const int before = q->patches.numPatches();
  auto atFiveValent = [&](int port) {
    const PortNode& pn = q->graph->ports()[port];
    return q->analysis.singularities[pn.singularity].indexQuarters == -1;
  };
  auto it = std::find_if(q->layout.separatrices.begin(), q->layout.separatrices.end(), [&](const LayoutSeparatrix& s) {
    return s.kind == LayoutSeparatrix::Full && atFiveValent(s.portA) && atFiveValent(s.portB);
  });
  ASSERT_NE(it, q->layout.separatrices.end());
  const LayoutSeparatrix removed = *it;
  q->layout.separatrices.erase(it);
  q->patches = buildPatchLayout(*q->graph, q->layout);
  EXPECT_LT(q->patches.numPatches(), before);
  for (const auto& p : q->patches.patches) EXPECT_TRUE(p.valid) << p.problem;
  for (int port : {removed.portA, removed.portB}) EXPECT_TRUE(q->patches.corner[q->graph->ports()[port].vertex]);
  QuadrangulationResult r = quadrangulateWithDefaults(*q, 0.05);
  checkQuadMesh(*q, r, "double torus without a separatrix");
  EXPECT_EQ(r.polygonPatches, 0);
  // Both ends keep valence 5 in the quads (three 90° corners and one straight side; counted
  // as a corner of the merged patch too they would get 4, and the n-gon's centre 6): the quads'
  // valences are those of the field's singularities, 16 of 5 and 8 of 3.
  std::map<int, int> valence, histogram;
  for (const auto& f : r.mesh.quads)
    for (int v : f) ++valence[v];
  for (const auto& [v, n] : valence) ++histogram[n];
  EXPECT_EQ(histogram[5], 16);
  EXPECT_EQ(histogram[3], 8);
  EXPECT_EQ(histogram[6], 0);
  EXPECT_EQ(histogram[4] + histogram[5] + histogram[3], int(valence.size()));
}

TEST(Quadrangulation, TeardropPatchGetsCornersAddedOnItsBoundary) {
  // A disk patch with a single corner (a teardrop, as around a singularity of index 3/4): its
  // boundary, the 8 outer vertices of a 3×3 grid, has only vertex 0 as a corner. Corners are
  // added until it has 3, each in the middle of the longest stretch between corners, then the
  // patch graph cuts it as a 3-gon with its sides split at the new corners.
  PatchLayout layout;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) layout.positions.push_back(Vec3(i, j, 0));
  layout.numOriginalVertices = 9;
  layout.corner.assign(9, 0);
  layout.corner[0] = 1;
  PatchReport rep;
  rep.isDisk = true;
  rep.corners = 1;
  rep.boundaryLoops = 1;
  rep.loop = {0, 1, 2, 5, 8, 7, 6, 3};
  rep.loopCorner = {1, 0, 0, 0, 0, 0, 0, 0};
  rep.loopTriangle.assign(rep.loop.size(), 0);
  layout.patches = {rep};
  EXPECT_EQ(addBoundaryCorners(layout, 0), 2);
  const PatchReport& r = layout.patches[0];
  EXPECT_EQ(r.corners, 3);
  // The loop is 8 long: the first split is opposite vertex 0 (vertex 8, 4 along), the second
  // in the middle of one of the two halves (2 along from a corner: vertex 2 or 6).
  EXPECT_EQ(r.loopCorner, (std::vector<char>{1, 0, 1, 0, 1, 0, 0, 0}));
  EXPECT_EQ(layout.corner[8], 1);
  EXPECT_EQ(layout.corner[2], 1);
  EXPECT_EQ(layout.addedCorners, 2);
  // A patch that has 3 corners is left as it is.
  EXPECT_EQ(addBoundaryCorners(layout, 0), 0);
  PatchGraph g = buildPatchGraph(layout);
  ASSERT_EQ(g.patches.size(), 1u);
  EXPECT_EQ(g.patches[0].polygonCorners, 3);
  EXPECT_EQ(g.segments.size(), 3u);
}

TEST(Quadrangulation, ThePatchesOnBothSidesOfASeparatrixAreMappedTogether) {
  // The points inside the layout's sides slide along them to where the field-aligned maps of
  // the patches on both sides, solved together, fit best. Each patch solved alone with the
  // mean of both sides' choices sheared the quads along the separatrices: the fandisk had
  // 19.7% of its quads more than π/16 off the field (25% of those next to a separatrix), and
  // the kitten 21.7%.
  FCQL_REQUIRE_SHARED(fandisk, "fandisk.obj");
  auto q = layoutOf(loadMesh(fandisk));
  const QuadrangulationResult r = quadrangulate(q->patches, fieldAlignedOptions(*q, 0.01));
  const ClosestPointIndex index(q->mesh);
  const QuadQuality quality = measureQuadQuality(r.mesh, q->mesh, q->field, index);
  std::cout << "fandisk: " << r.mesh.numQuads() << " quads, " << quality.misalignedPercent << "% misaligned, "
            << quality.misalignedFacesPercent << "% of the faces, scaled Jacobian min " << quality.minScaledJacobian << "\n";
  EXPECT_FALSE(r.boundWithoutField || r.foldsWithoutField) << "the field was dropped";
  EXPECT_LE(quality.misalignedPercent, 12.0);
  EXPECT_GT(quality.minScaledJacobian, 0);
}

TEST(Quadrangulation, TheFieldAlignedGridIsSmoothedOnlyAroundItsPoorQuads) {
  // Smoothing towards the field everywhere turns the sampled field-aligned grid away from it
  // (each quad fitted to one field direction, the fits averaged at each vertex). The stage
  // smooths only around quads of scaled Jacobian below 0.5: more quads follow the field, and
  // the vertices far from poor quads stay where the maps put them. (The smoothing rounds alone:
  // the relaxation towards the field that follows them moves the whole grid; it has its own
  // tests.)
  FCQL_REQUIRE_SHARED(fandisk, "fandisk.obj");
  auto q = layoutOf(loadMesh(fandisk));
  QuadrangulationOptions options = fieldAlignedOptions(*q, 0.01);
  options.smoothing.fieldRelaxationRounds = 0;
  const QuadrangulationResult kept = quadrangulate(q->patches, options);
  options.keepFieldGrid = false;
  const QuadrangulationResult everywhere = quadrangulate(q->patches, options);
  ASSERT_TRUE(kept.fieldGridKept) << "the grid was smoothed everywhere: the kept one missed the bound";
  EXPECT_FALSE(everywhere.fieldGridKept);
  ASSERT_EQ(kept.mesh.quads, everywhere.mesh.quads) << "the same sampling, smoothed differently";
  int unmoved = 0;
  for (std::size_t v = 0; v < kept.mesh.positions.size(); ++v)
    unmoved += kept.mesh.positions[v] == kept.sampledPositions[v];
  EXPECT_GT(unmoved, int(kept.mesh.positions.size()) / 4) << "the grid was smoothed nearly everywhere";
  const ClosestPointIndex index(q->mesh);
  const QuadQuality a = measureQuadQuality(kept.mesh, q->mesh, q->field, index);
  const QuadQuality b = measureQuadQuality(everywhere.mesh, q->mesh, q->field, index);
  std::cout << "fandisk misaligned: kept grid " << a.misalignedPercent << "%, smoothed everywhere " << b.misalignedPercent
            << "%; " << unmoved << " of " << kept.mesh.positions.size() << " vertices where sampled\n";
  EXPECT_LT(a.misalignedPercent, b.misalignedPercent);
  EXPECT_EQ(a.invertedQuads, 0);
  EXPECT_LE(a.hausdorffRelative, 0.01);
}

TEST(Quadrangulation, TheRelaxationTowardsTheFieldTurnsTheQuadsAlongTheLayoutsSides) {
  // Eight with its own field: the quads along the layout's sides follow the sides, which leave
  // the singularities within the tracing's tolerance of the field; the relaxation solved for
  // all vertices at once turns them to the field. Fewer quads off it, none folded, the same
  // sampling within the same bound.
  FCQL_REQUIRE_SHARED_WITH_FIELD(mesh, field, "eight");
  auto q = layoutOf(mesh, &field);
  QuadrangulationOptions options = fieldAlignedOptions(*q, 0.01);
  options.smoothing.fieldRelaxationRounds = 0;
  const QuadrangulationResult without = quadrangulate(q->patches, options);
  options.smoothing.fieldRelaxationRounds = SmoothingOptions{}.fieldRelaxationRounds;
  ASSERT_GT(options.smoothing.fieldRelaxationRounds, 0);
  const QuadrangulationResult with = quadrangulate(q->patches, options);
  ASSERT_EQ(with.mesh.quads, without.mesh.quads) << "the same sampling, smoothed differently";
  EXPECT_GT(with.smoothing.relaxedMoves, 0);
  const ClosestPointIndex index(q->mesh);
  const QuadQuality a = measureQuadQuality(without.mesh, q->mesh, q->field, index);
  const QuadQuality b = measureQuadQuality(with.mesh, q->mesh, q->field, index);
  std::cout << "eight misaligned: " << a.misalignedPercent << "% without the relaxation, " << b.misalignedPercent
            << "% with it (per face " << a.misalignedFacesPercent << "%, " << b.misalignedFacesPercent << "%)\n";
  EXPECT_LT(b.misalignedPercent, 0.75 * a.misalignedPercent);
  EXPECT_LT(b.misalignedFacesPercent, a.misalignedFacesPercent);
  EXPECT_EQ(b.invertedQuads, 0);
  EXPECT_LE(b.hausdorffRelative, 0.01);
}
