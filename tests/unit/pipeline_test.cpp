#include "mesh/generators.h"
#include "mesh/vertex_welding.h"
#include "pipeline/figures.h"
#include "pipeline/parameters.h"
#include "pipeline/quad_stage.h"

#include <array>
#include <cctype>
#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>

using namespace fcql;

namespace {

/// The four stages with the default parameters on one thread, as `fcql run` calls them.
struct AllStages {
  FieldStageResult field;
  TraceStageResult trace;
  LayoutStageResult layout;
  QuadStageResult quad;
};
AllStages runAllStages(const SurfaceMesh& mesh, const std::string& name) {
  PipelineParameters p;
  p.threads = 1;
  MeshInput input;
  input.mesh = &mesh;
  input.name = name;
  AllStages r;
  r.field = runFieldStage(input, p, FieldSource{}, StageObserver{});
  r.trace = runTraceStage(mesh, r.field.field, r.field.analysis, p, StageObserver{});
  r.layout = runLayoutStage(mesh, r.field.field, r.field.analysis, r.trace, p, StageObserver{});
  r.quad = runQuadStage(mesh, r.field.field, r.layout, p, StageObserver{});
  return r;
}

std::string errorOf(PipelineParameters& p, const char* name, const std::string& value, ParameterNaming naming) {
  try {
    p.setFromText(parameterSpec(name), value, naming);
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ParameterTable, DefaultsAreThoseOfTheCoreStructs) {
  const PipelineParameters p;
  const TracingParameters tracing;
  EXPECT_EQ(p.alpha, tracing.alpha);
  EXPECT_EQ(p.k, tracing.k);
  EXPECT_EQ(p.phiDeg, tracing.phiDeg);
  EXPECT_EQ(p.threads, tracing.threads);
  const LayoutParameters layout;
  EXPECT_EQ(p.ilpTimeLimit, layout.ilpTimeLimit);
  EXPECT_EQ(p.ilpStall, layout.ilpStallNodes);
  EXPECT_EQ(p.completionTrials, layout.completionTrials);
  const QuadrangulationOptions quad;
  EXPECT_EQ(p.maxDeviation, quad.maxDeviation);
  EXPECT_EQ(p.smooth, quad.smoothing.iterations);
  EXPECT_EQ(p.sharpAngleDeg, quad.smoothing.sharpAngleDeg);
  EXPECT_EQ(p.sharpAngleDeg, FieldGenerationOptions().sharpAngleDeg);
  EXPECT_EQ(p.param, "field");
  EXPECT_EQ(p.targetFaces, 0);
  EXPECT_TRUE(p.fieldFile.empty());
}

TEST(ParameterTable, NamesAreUniquePythonIdentifiersAndOptionsAreUnique) {
  std::set<std::string> names, options;
  for (const ParameterSpec& s : parameterTable()) {
    if (s.inFilters()) {
      EXPECT_TRUE(names.insert(s.name).second) << s.name;
      for (const char* c = s.name; *c; ++c) EXPECT_TRUE(std::islower(*c) || *c == '_') << s.name;
    }
    if (s.inCli()) EXPECT_TRUE(options.insert(s.option).second) << s.option;
    EXPECT_TRUE(s.inFilters() || s.inCli()) << "a parameter no front end has";
    EXPECT_GT(std::string(s.help).size(), 20u) << s.name;
    if (s.kind == ParameterSpec::Real || s.kind == ParameterSpec::Integer) {
      EXPECT_LE(s.min, s.defaultValue) << s.name;
      EXPECT_LE(s.defaultValue, s.max) << s.name;
    }
  }
  EXPECT_EQ(parameterSpec("field-scale").name, std::string("field_scale"));
  EXPECT_THROW(parameterSpec("no_such_parameter"), std::out_of_range);
}

TEST(ParameterTable, ValuesAreCheckedAndErrorsNameTheParameterAsTheFrontEndShowsIt) {
  PipelineParameters p;
  EXPECT_EQ(errorOf(p, "alpha", "-1", ParameterNaming::CliOption), "--alpha must be between 0 and 1e+06, got -1");
  EXPECT_EQ(errorOf(p, "alpha", "-1", ParameterNaming::FilterName),
            "parameter 'alpha' (drift penalty) is -1, must be between 0 and 1e+06");
  EXPECT_EQ(errorOf(p, "k", "ten", ParameterNaming::CliOption), "--k must be an integer, got 'ten'");
  EXPECT_EQ(errorOf(p, "k", "0", ParameterNaming::CliOption), "--k must be between 1 and 1000000, got 0");
  EXPECT_EQ(errorOf(p, "phi", "nan", ParameterNaming::CliOption), "--phi must be a number, got 'nan'");
  EXPECT_EQ(errorOf(p, "param", "spline", ParameterNaming::CliOption),
            "--param must be one of field/mean-value, got 'spline'");
  EXPECT_THROW(p.setReal(parameterSpec("scale"), 0, ParameterNaming::FilterName), ParameterError);
  EXPECT_THROW(p.setInteger(parameterSpec("ilp_stall"), -1, ParameterNaming::FilterName), ParameterError);
  // Nothing was changed by the refused values; accepted ones are.
  EXPECT_EQ(p.alpha, 20);
  EXPECT_EQ(p.k, 10);
  EXPECT_EQ(errorOf(p, "k", "30", ParameterNaming::CliOption), "");
  EXPECT_EQ(errorOf(p, "param", "mean-value", ParameterNaming::CliOption), "");
  EXPECT_EQ(p.k, 30);
  EXPECT_EQ(p.param, "mean-value");
}

TEST(Figures, NestDottedKeysInJsonAndKeepThemFlatOnOneLine) {
  Figures f;
  f.set("mesh.faces", 12);
  f.set("field.index_sum", std::string("2"));
  f.setCounts("field.by_index", {{"-1/4", 2}, {"1/4", 10}});
  f.set("quad.manifold", true);
  f.set("quad.hausdorff_rel", 0.00123456789);
  f.setCounts("layout.corner_histogram", {});
  f.set("mesh.faces", 14);  // replaced in place
  EXPECT_EQ(f.toJson(),
            "{\n  \"mesh\": {\n    \"faces\": 14\n  },\n  \"field\": {\n    \"index_sum\": \"2\",\n"
            "    \"by_index\": {\n      \"-1/4\": 2,\n      \"1/4\": 10\n    }\n  },\n  \"quad\": {\n"
            "    \"manifold\": true,\n    \"hausdorff_rel\": 0.00123457\n  },\n  \"layout\": {\n"
            "    \"corner_histogram\": {}\n  }\n}\n");
  EXPECT_EQ(f.toFlatJson(),
            "{\"mesh.faces\": 14, \"field.index_sum\": \"2\", \"field.by_index.-1/4\": 2, \"field.by_index.1/4\": 10, "
            "\"quad.manifold\": true, \"quad.hausdorff_rel\": 0.00123457, \"layout.corner_histogram\": {}}");
  Figures g;
  g.set("quad.faces", 3);
  g.set("mesh.faces", 15);
  f.append(g);
  ASSERT_NE(f.find("quad.faces"), nullptr);
  EXPECT_EQ(f.find("quad.faces")->integer, 3);
  EXPECT_EQ(f.find("mesh.faces")->integer, 15);
  EXPECT_EQ(f.find("no.such.key"), nullptr);
}

// The four stages on the rounded box, as every front end calls them: the figures describe
// one consistent run (6 four-sided patches, a quad mesh whose own structure is the layout's).
TEST(PipelineStages, RoundedBoxGivesOneConsistentRecord) {
  const SurfaceMesh mesh = makeExample("rounded_box");
  PipelineParameters p;
  p.threads = 1;
  MeshInput input;
  input.mesh = &mesh;
  input.name = "example:rounded_box";
  std::vector<std::string> seen;
  StageObserver observer;
  observer.line = [&seen](const LogLine& line) { seen.push_back(line.text); };
  const FieldStageResult field = runFieldStage(input, p, FieldSource{}, observer);
  const TraceStageResult trace = runTraceStage(mesh, field.field, field.analysis, p, observer);
  const LayoutStageResult layout = runLayoutStage(mesh, field.field, field.analysis, trace, p, observer);
  const QuadStageResult quad = runQuadStage(mesh, field.field, layout, p, observer);
  Figures all = field.figures;
  for (const Figures* f : {&trace.figures, &layout.figures, &quad.figures}) all.append(*f);

  EXPECT_EQ(all.find("field.singularities")->integer, 8);
  EXPECT_EQ(all.find("field.index_sum")->text, "2");
  EXPECT_EQ(all.find("graph_g.ports")->integer, 24);
  EXPECT_EQ(all.find("layout.patches")->integer, 6);
  EXPECT_EQ(all.find("layout.corner_histogram.4")->integer, 6);
  EXPECT_EQ(all.find("layout.t_junctions")->integer, 0);
  EXPECT_EQ(all.find("quad.base_complex_patches")->integer, 6);
  EXPECT_EQ(all.find("quad.irregular_vertices")->integer, 8);
  ASSERT_NE(all.find("quad.irregular_by_valence.3"), nullptr);  // the box's corners: valence 3
  EXPECT_EQ(all.find("quad.irregular_by_valence.3")->integer, 8);
  EXPECT_EQ(all.find("quad.irregular_by_valence.5"), nullptr);
  EXPECT_EQ(all.find("quad.inverted_quads")->integer, 0);
  EXPECT_EQ(all.find("quad.faces")->integer, long(quad.quad.mesh.numQuads()));
  EXPECT_EQ(all.find("params.k")->integer, 10);
  EXPECT_EQ(all.find("params.param")->text, "field");
  EXPECT_LE(all.find("quad.hausdorff_rel")->real, p.maxDeviation);
  // Every line the observer saw is in the stages' logs, in order; none is a warning.
  std::vector<std::string> logged;
  for (const auto* log : {&field.log, &trace.log, &layout.log, &quad.log})
    for (const LogLine& line : *log) {
      logged.push_back(line.text);
      EXPECT_NE(line.kind, LogLine::Warning) << line.text;
    }
  EXPECT_EQ(logged, seen);
}

// A cube of 15×15 squares a face (sharp edges, as a CAD part is): the layout's sides run
// beside its edges, in the triangles next to them; the quads must still have their vertices on
// every edge, so that the quad mesh is the cube itself. Before the grid lines were moved onto
// the creases, only the 8 corners were on them and the quads cut every edge (0.63% of the
// diagonal away).
TEST(PipelineStages, ACubesQuadsFollowItsSharpEdges) {
  const int n = 15;
  std::vector<Vec3> positions;
  std::vector<std::array<int, 3>> faces;
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-0.5, 0.5}) {
      const int base = int(positions.size());
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          Vec3 p;
          p[axis] = side;
          p[(axis + 1) % 3] = -0.5 + double(i) / n;
          p[(axis + 2) % 3] = -0.5 + double(j) / n;
          positions.push_back(p);
        }
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const int a = base + j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
          if (side > 0) faces.push_back({a, b, c}), faces.push_back({a, c, d});
          else faces.push_back({a, c, b}), faces.push_back({a, d, c});
        }
    }
  VertexWelding welded = weldCoincidentVertices(SurfaceMesh(positions, faces));
  ASSERT_TRUE(welded.welded);
  const SurfaceMesh& mesh = welded.mesh;
  ASSERT_EQ(mesh.numFaces(), 6 * 2 * n * n);
  const AllStages run = runAllStages(mesh, "cube");
  const QuadStageResult& quad = run.quad;
  EXPECT_EQ(run.layout.figures.find("layout.patches")->integer, 6);
  const QuadMesh& q = quad.quad.mesh;
  // Every quad lies in one face of the cube, and each of the 12 edges holds quad vertices
  // along its whole length.
  auto onPlane = [](const Vec3& x, int axis, double side) { return std::abs(x[axis] - side) < 1e-9; };
  int across = 0;
  for (const auto& f : q.quads) {
    bool inOneFace = false;
    for (int axis = 0; axis < 3 && !inOneFace; ++axis)
      for (double side : {-0.5, 0.5}) {
        bool all = true;
        for (int v : f) all = all && onPlane(q.positions[v], axis, side);
        inOneFace = inOneFace || all;
      }
    across += !inOneFace;
  }
  EXPECT_EQ(across, 0);
  std::vector<int> onEdge(12, 0);
  for (const Vec3& x : q.positions) {
    int e = 0;
    for (int axis = 0; axis < 3; ++axis)  // edges along `axis`: the other two coordinates at ±0.5
      for (double s1 : {-0.5, 0.5})
        for (double s2 : {-0.5, 0.5}) {
          if (onPlane(x, (axis + 1) % 3, s1) && onPlane(x, (axis + 2) % 3, s2)) ++onEdge[e];
          ++e;
        }
  }
  for (int e = 0; e < 12; ++e) EXPECT_GE(onEdge[e], 10) << "edge " << e;
  EXPECT_LT(quad.figures.find("quad.hausdorff_rel")->real, 1e-9);
  EXPECT_EQ(quad.figures.find("quad.inverted_quads")->integer, 0);
}

// A cube of 12 triangles, as CAD software exports one: half its edges are longer than its side,
// 58% of its diagonal, far too coarse for a field with one direction per triangle. The run goes
// through and the log says why its layout is poor and what to do, once, at the field stage; the
// rounded box above gets no warning.
TEST(PipelineStages, ACoarseMeshIsNamedInAWarning) {
  std::vector<Vec3> positions;
  for (int x = 0; x < 2; ++x)
    for (int y = 0; y < 2; ++y)
      for (int z = 0; z < 2; ++z) positions.push_back(Vec3(x, y, z));
  const auto at = [](int x, int y, int z) { return 4 * x + 2 * y + z; };
  const std::vector<std::array<int, 4>> sides = {
      {at(0, 0, 0), at(0, 0, 1), at(0, 1, 1), at(0, 1, 0)}, {at(1, 0, 0), at(1, 1, 0), at(1, 1, 1), at(1, 0, 1)},
      {at(0, 0, 0), at(1, 0, 0), at(1, 0, 1), at(0, 0, 1)}, {at(0, 1, 0), at(0, 1, 1), at(1, 1, 1), at(1, 1, 0)},
      {at(0, 0, 0), at(0, 1, 0), at(1, 1, 0), at(1, 0, 0)}, {at(0, 0, 1), at(1, 0, 1), at(1, 1, 1), at(0, 1, 1)}};
  std::vector<std::array<int, 3>> faces;
  for (const auto& q : sides) faces.push_back({q[0], q[1], q[2]}), faces.push_back({q[0], q[2], q[3]});
  const SurfaceMesh mesh(positions, faces);
  const AllStages run = runAllStages(mesh, "cube of 12 triangles");
  int coarse = 0;
  for (const auto* log : {&run.field.log, &run.trace.log, &run.layout.log, &run.quad.log})
    for (const LogLine& line : *log)
      if (line.kind == LogLine::Warning && line.text.find("The mesh is coarse") == 0) {
        ++coarse;
        EXPECT_NE(line.text.find("longer than 57% of its bounding-box diagonal"), std::string::npos) << line.text;
        EXPECT_NE(line.text.find("subdivide the mesh first"), std::string::npos) << line.text;
      }
  EXPECT_EQ(coarse, 1);
  EXPECT_EQ(run.quad.figures.find("quad.inverted_quads")->integer, 0);
}

TEST(PipelineStages, TooManyQuadsFailBeforeAnyWorkNamingTheFinestValue) {
  const SurfaceMesh mesh = makeExample("sphere");
  PipelineParameters p;
  p.scale = 1e-5;
  try {
    quadTargetEdge(mesh, p, ParameterNaming::CliOption);
    FAIL() << "1e-5 was accepted";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("--scale 1e-05 asks for about"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--target-faces 20000000 or fewer"), std::string::npos) << e.what();
  }
  p.scale = 0.02;
  EXPECT_GT(quadTargetEdge(mesh, p, ParameterNaming::CliOption), 0);
  p.targetFaces = 1000;
  EXPECT_NEAR(quadTargetEdge(mesh, p, ParameterNaming::CliOption), std::sqrt(4 * 3.14159 / 1000), 0.01);
}

// The misalignment threshold changes the quality figures only: at 45 degrees no quad can be
// misaligned (a cross is never farther than that), at 0 every one that is not exactly aligned.
TEST(PipelineStages, MisalignmentThresholdChangesOnlyTheFigures) {
  const SurfaceMesh mesh = makeExample("rounded_box");
  PipelineParameters p;
  MeshInput input;
  input.mesh = &mesh;
  const FieldStageResult field = runFieldStage(input, p, FieldSource{}, StageObserver{});
  const TraceStageResult trace = runTraceStage(mesh, field.field, field.analysis, p, StageObserver{});
  const LayoutStageResult layout = runLayoutStage(mesh, field.field, field.analysis, trace, p, StageObserver{});
  const QuadStageResult paper = runQuadStage(mesh, field.field, layout, p, StageObserver{});
  p.misalignmentThresholdDeg = 45;
  const QuadStageResult loose = runQuadStage(mesh, field.field, layout, p, StageObserver{});
  p.misalignmentThresholdDeg = 0;
  const QuadStageResult strict = runQuadStage(mesh, field.field, layout, p, StageObserver{});
  EXPECT_EQ(loose.quad.mesh.positions, paper.quad.mesh.positions);
  EXPECT_EQ(loose.quality.misalignedPercent, 0);
  EXPECT_GT(strict.quality.misalignedPercent, 50);
  EXPECT_LE(paper.quality.misalignedPercent, strict.quality.misalignedPercent);
  EXPECT_EQ(loose.figures.find("params.misalignment_threshold")->real, 45);
}
