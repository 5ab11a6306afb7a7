#include "quadrangulation/patch_sampling.h"

#include "quadrangulation/field_aligned_map.h"
#include "quadrangulation/patch_map.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <unordered_map>

namespace fcql {
namespace {

/// Weight of the pull of each shared segment parameter towards arc length in the joint
/// field-aligned solve (the rows' weights are about 1).
constexpr double kParameterPull = 1e-4;

/// Points at fractions k/n (k = 1..n−1) of the arc length along a polyline.
std::vector<Vec3> samplesAlong(const std::vector<Vec3>& poly, int n) {
  std::vector<double> acc(poly.size(), 0);
  for (std::size_t i = 1; i < poly.size(); ++i) acc[i] = acc[i - 1] + (poly[i] - poly[i - 1]).norm();
  std::vector<Vec3> out;
  std::size_t seg = 1;
  for (int k = 1; k < n; ++k) {
    double target = acc.back() * k / n;
    while (seg + 1 < poly.size() && acc[seg] < target) ++seg;
    double len = acc[seg] - acc[seg - 1];
    double t = len > 0 ? (target - acc[seg - 1]) / len : 0;
    out.push_back(poly[seg - 1] + (poly[seg] - poly[seg - 1]) * std::clamp(t, 0.0, 1.0));
  }
  return out;
}

/// Image of the point at side coordinate c on side k of a W × H rectangle.
Vec2 sideUv(int k, double c, double W, double H) {
  switch (k) {
    case 0: return Vec2(c, 0);
    case 1: return Vec2(W, c);
    case 2: return Vec2(W - c, H);
    default: return Vec2(0, H - c);
  }
}

/// Points where a monotone parameter t (per polyline point, from 0 to n) crosses 1..n−1.
std::vector<Vec3> samplesByParameter(const std::vector<Vec3>& poly, const std::vector<double>& t, int n) {
  std::vector<Vec3> out;
  std::size_t seg = 1;
  for (int k = 1; k < n; ++k) {
    while (seg + 1 < poly.size() && t[seg] < k) ++seg;
    const double len = t[seg] - t[seg - 1];
    const double s = len > 0 ? (k - t[seg - 1]) / len : 0;
    out.push_back(poly[seg - 1] + (poly[seg] - poly[seg - 1]) * std::clamp(s, 0.0, 1.0));
  }
  return out;
}

/// The inner points (i, j), 0 < i < W, 0 < j < H, of a patch's grid, row by row.
std::vector<Vec3> innerGrid(const PatchMap& map, int W, int H) {
  std::vector<Vec3> out;
  out.reserve(std::max(0, (W - 1) * (H - 1)));
  for (int j = 1; j < H; ++j)
    for (int i = 1; i < W; ++i) out.push_back(map.pointAt(Vec2(i, j)));
  return out;
}

/// The quads of a W × H grid folded in space (a corner turned against the quad's own normal),
/// given its inner points row by row and `side(i, j)`, the points on its sides.
int foldedGridQuads(const std::vector<Vec3>& inner, int W, int H, const std::function<Vec3(int, int)>& side) {
  auto position = [&](int i, int j) -> Vec3 {
    if (i > 0 && j > 0 && i < W && j < H) return inner[(j - 1) * (W - 1) + (i - 1)];
    return side(i, j);
  };
  int n = 0;
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      const std::array<Vec3, 4> c{position(i, j), position(i + 1, j), position(i + 1, j + 1), position(i, j + 1)};
      const Vec3 normal = (c[2] - c[0]).cross(c[3] - c[1]);
      bool folded = false;
      for (int k = 0; k < 4 && !folded; ++k) folded = !((c[(k + 1) % 4] - c[k]).cross(c[(k + 3) % 4] - c[k]).dot(normal) > 0);
      n += folded;
    }
  return n;
}

/// Layout patch `patch` (its `triangles`) mapped onto its W × H rectangle, its boundary loop
/// at `loopUv`: field-aligned with a `guide`, else with mean-value coordinates. A grid the
/// aligned (or blended) map folds in space (a quad turned against the surface at a corner)
/// where the mean-value map's folds fewer quads gives way to that one. `side(i, j)`: the
/// points sampled on the rectangle's sides.
SampledGrids::Grid mapPatchGrid(const PatchLayout& layout, int patch, const std::vector<int>& triangles,
                                const std::unordered_map<std::uint64_t, int>& halfEdge, const std::vector<Vec2>& loopUv,
                                int W, int H, const PatchGuide* guide, const std::function<Vec3(int, int)>& side) {
  SampledGrids::Grid grid;
  grid.W = W, grid.H = H, grid.guided = guide != nullptr, grid.boundaryUv = loopUv;
  auto boundary = [&](int k) { return loopUv[k]; };
  auto map = std::make_unique<PatchMap>(layout, patch, triangles, halfEdge, boundary, guide);
  grid.inner = innerGrid(*map, W, H);
  grid.kind = map->guided();
  if (grid.kind == GuidedMap::Aligned || grid.kind == GuidedMap::Blended) {
    const int alignedFolds = foldedGridQuads(grid.inner, W, H, side);
    if (alignedFolds > 0) {
      auto plain = std::make_unique<PatchMap>(layout, patch, triangles, halfEdge, boundary);
      std::vector<Vec3> plainInner = innerGrid(*plain, W, H);
      if (foldedGridQuads(plainInner, W, H, side) < alignedFolds)
        map = std::move(plain), grid.inner = std::move(plainInner), grid.kind = GuidedMap::MeanValue;
    }
  }
  grid.outsidePoints = map->outsidePoints();
  return grid;
}

}  // namespace

std::vector<Vec2> unitSquareBoundary(const PatchLayout& layout, int p) {
  const PatchReport& rep = layout.patches[p];
  const int m = int(rep.loop.size());
  int first = 0;
  while (first < m && !rep.loopCorner[first]) ++first;
  std::vector<Vec2> uv(m);
  // Sides by loop positions, each normalised by its arc length.
  int side = -1;
  std::vector<int> positions;
  auto flush = [&](int k, int closing) {
    if (positions.empty()) return;
    std::vector<double> acc(1, 0);
    for (std::size_t i = 1; i < positions.size(); ++i)
      acc.push_back(acc.back() + (layout.positions[rep.loop[positions[i]]] - layout.positions[rep.loop[positions[i - 1]]]).norm());
    double total = acc.back() + (layout.positions[rep.loop[closing]] - layout.positions[rep.loop[positions.back()]]).norm();
    for (std::size_t i = 0; i < positions.size(); ++i) uv[positions[i]] = sideUv(k, total > 0 ? acc[i] / total : 0, 1, 1);
    positions.clear();
  };
  for (int step = 0; step < m; ++step) {
    int k = (first + step) % m;
    if (rep.loopCorner[k]) {
      flush(side, k);
      ++side;
    }
    positions.push_back(k);
  }
  flush(side, first);
  return uv;
}

QuadMesh samplePatches(const PatchLayout& layout, const PatchGraph& graph, const SideLengths& lengths,
                       const std::vector<Vec3>* faceDirections, const std::vector<char>* meanValuePatches,
                       SampledGrids* grids) {
  if (!lengths.inconsistentPatches.empty())
    throw std::runtime_error(std::to_string(lengths.inconsistentPatches.size()) +
                             " patches have opposite sides of different lengths (zero chains)");
  QuadMesh q;
  std::unordered_map<int, int> nodeVertex;
  auto node = [&](int id) {
    auto it = nodeVertex.find(id);
    if (it != nodeVertex.end()) return it->second;
    q.positions.push_back(graph.nodePosition(layout, id));
    return nodeVertex[id] = q.numVertices() - 1;
  };
  std::unordered_map<std::uint64_t, int> halfEdge;
  for (int t = 0; t < int(layout.triangles.size()); ++t)
    for (int i = 0; i < 3; ++i)
      halfEdge[PatchMap::edgeKey(layout.triangles[t][i], layout.triangles[t][(i + 1) % 3])] = t * 3 + i;
  std::vector<std::vector<int>> trianglesOf(layout.numPatches());
  for (int t = 0; t < int(layout.triangles.size()); ++t) trianglesOf[layout.patch[t]].push_back(t);

  // Per segment the parameter (0..n) of each of its layout vertices: by arc length, or with a
  // field, where the field-aligned maps of the patches on its sides, solved together, put it
  // when its points may slide along the side (one parameter, read by both sides alike).
  const int numSegments = int(graph.segments.size());
  std::vector<std::vector<double>> parameter(numSegments);
  for (int s = 0; s < numSegments; ++s) {
    const LayoutSegment& seg = graph.segments[s];
    const int n = s < int(lengths.segments.size()) ? lengths.segments[s] : 0;
    std::vector<double> acc(seg.vertices.size(), 0);
    for (std::size_t i = 1; i < seg.vertices.size(); ++i)
      acc[i] = acc[i - 1] + (layout.positions[seg.vertices[i]] - layout.positions[seg.vertices[i - 1]]).norm();
    for (double& a : acc) a = seg.length > 0 ? n * a / seg.length : 0;
    if (!acc.empty()) acc.back() = n;
    parameter[s] = std::move(acc);
  }
  // Calls visit(k, ss, i, loopPosition, sideCoordinate) for every layout vertex of every side of
  // original patch p, i counting along the side, with the side coordinate its parameter gives.
  auto forEachSideVertex = [&](int p, const auto& visit) {
    const PatchSides& ps = graph.patches[p];
    const int loopSize = int(layout.patches[ps.layoutPatch].loop.size());
    for (int k = 0; k < 4; ++k) {
      int offset = 0;
      for (const SideSegment& ss : ps.sides[k]) {
        const LayoutSegment& seg = graph.segments[ss.segment];
        const int n = lengths.segments[ss.segment];
        const int m = int(seg.vertices.size());
        for (int i = 0; i < m; ++i) {
          const int j = ss.reversed ? m - 1 - i : i;
          const double local = ss.reversed ? n - parameter[ss.segment][j] : parameter[ss.segment][j];
          visit(k, ss, i, m, (ss.loopStart + i) % loopSize, offset + local);
        }
        offset += n;
      }
    }
  };
  auto sideLengths = [&](int p) {
    return std::pair<int, int>(lengths.sideLength(graph, p, 0), lengths.sideLength(graph, p, 1));
  };
  if (faceDirections) {
    // Segments whose points slide: every patch on their sides is a whole layout patch, none of
    // them marked in meanValuePatches (their sides go back to arc length).
    std::vector<char> shared(numSegments, 1);
    for (const auto& ps : graph.patches) {
      const bool arcLength = meanValuePatches && ps.layoutPatch >= 0 && ps.layoutPatch < int(meanValuePatches->size()) &&
                             (*meanValuePatches)[ps.layoutPatch] != kFieldPatch;
      if (ps.active && (!ps.original || arcLength))
        for (const auto& side : ps.sides)
          for (const auto& ss : side) shared[ss.segment] = 0;
    }
    std::vector<std::vector<double>> sum(numSegments);
    std::vector<std::vector<int>> count(numSegments);
    for (int s = 0; s < numSegments; ++s) {
      sum[s].assign(parameter[s].size(), 0);
      count[s].assign(parameter[s].size(), 0);
    }
    // The field-aligned maps of all whole patches, solved together: u and v of the wedges
    // inside each patch, its two scales, and one parameter per layout vertex inside a shared
    // segment, which the patches on both sides read (each along its own side, in its own
    // direction). The grid lines of both patches then meet a side where they fit best
    // together, instead of each patch's own choice averaged with its neighbour's.
    struct Piece {
      FieldAlignedProblem problem;
      std::vector<std::array<double, 3>> slide;  ///< per wedge: its segment parameter's unknown, A, B (coordinate A + B s)
      std::vector<int> slideAxis;                ///< per wedge: the axis that slides (−1: none)
    };
    std::vector<std::vector<int>> slideVar(numSegments);
    for (int s = 0; s < numSegments; ++s) slideVar[s].assign(parameter[s].size(), -1);
    int numVars = 0;
    std::vector<Piece> pieces;
    for (int p = 0; p < int(graph.patches.size()); ++p) {
      const PatchSides& ps = graph.patches[p];
      if (!ps.active || !ps.original) continue;
      const auto [W, H] = sideLengths(p);
      const int loopSize = int(layout.patches[ps.layoutPatch].loop.size());
      std::vector<Vec2> loopUv(loopSize, Vec2::Zero());
      PatchGuide guide;
      guide.faceDirections = faceDirections;
      guide.loopConstraint.assign(loopSize, FieldAlignedProblem::Fixed);
      forEachSideVertex(p, [&](int k, const SideSegment& ss, int i, int m, int pos, double c) {
        loopUv[pos] = sideUv(k, c, W, H);
        if (i > 0 && i + 1 < m && shared[ss.segment])
          guide.loopConstraint[pos] = k % 2 == 0 ? FieldAlignedProblem::FixV : FieldAlignedProblem::FixU;
      });
      std::vector<int> loopWedges;
      Piece piece;
      piece.problem = PatchMap::alignedProblem(layout, ps.layoutPatch, trianglesOf[ps.layoutPatch], halfEdge,
                                               [&](int k) { return loopUv[k]; }, guide, loopWedges);
      const int nw = int(piece.problem.start.size());
      piece.slide.assign(nw, {-1.0, 0.0, 0.0});
      piece.slideAxis.assign(nw, -1);
      forEachSideVertex(p, [&](int k, const SideSegment& ss, int i, int m, int pos, double c) {
        if (!(i > 0 && i + 1 < m && shared[ss.segment])) return;
        const int w = loopWedges[pos];
        const auto sliding = k % 2 == 0 ? FieldAlignedProblem::FixV : FieldAlignedProblem::FixU;
        if (piece.problem.constraint[w] != sliding) return;  // a wedge the loop meets twice stays fixed
        const int j = ss.reversed ? m - 1 - i : i;
        const int n = lengths.segments[ss.segment];
        int& var = slideVar[ss.segment][j];
        if (var < 0) var = numVars++;
        // c = offset + (reversed ? n − s : s) along side k, whose coordinate is c (k = 0, 1) or
        // W − c, H − c (k = 2, 3).
        const double offset = c - (ss.reversed ? n - parameter[ss.segment][j] : parameter[ss.segment][j]);
        const double base = offset + (ss.reversed ? n : 0), sign = ss.reversed ? -1 : 1;
        const double A = k < 2 ? base : (k == 2 ? W : H) - base, B = k < 2 ? sign : -sign;
        piece.slide[w] = {double(var), A, B};
        piece.slideAxis[w] = k % 2 == 0 ? 0 : 1;
      });
      pieces.push_back(std::move(piece));
    }
    const int numSlides = numVars;
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<double> rhs;
    for (const Piece& piece : pieces) {
      const FieldAlignedProblem& pb = piece.problem;
      const FieldAlignedRows rows = fieldAlignedRows(pb);
      const int nw = int(pb.start.size());
      for (int axis = 0; axis < 2; ++axis) {
        std::vector<int> var(nw, -1);
        for (int w = 0; w < nw; ++w) {
          const auto c = pb.constraint[w];
          const bool fixed = c == FieldAlignedProblem::Fixed ||
                             (axis == 0 ? c == FieldAlignedProblem::FixU : c == FieldAlignedProblem::FixV);
          if (!fixed && piece.slideAxis[w] != axis) var[w] = numVars++;
        }
        const int scale = numVars++;
        for (const FieldAlignedRows::Row& r : rows.axis[axis]) {
          const int row = int(rhs.size());
          double b = 0;
          for (int i = 0; i < 3; ++i) {
            const int w = r.wedge[i];
            if (var[w] >= 0) {
              entries.emplace_back(row, var[w], r.coefficient[i]);
            } else if (piece.slideAxis[w] == axis) {
              entries.emplace_back(row, int(piece.slide[w][0]), r.coefficient[i] * piece.slide[w][2]);
              b -= r.coefficient[i] * piece.slide[w][1];
            } else {
              b -= r.coefficient[i] * pb.start[w][axis];
            }
          }
          if (r.scale != 0) entries.emplace_back(row, scale, r.scale);
          rhs.push_back(b);
        }
      }
    }
    // A faint pull of each parameter towards arc length keeps the system definite where a
    // parameter reaches no triangle of any area.
    for (int s = 0; s < numSegments; ++s)
      for (std::size_t j = 0; j < slideVar[s].size(); ++j)
        if (slideVar[s][j] >= 0) {
          entries.emplace_back(int(rhs.size()), slideVar[s][j], kParameterPull);
          rhs.push_back(kParameterPull * parameter[s][j]);
        }
    if (numSlides > 0) {
      Eigen::SparseMatrix<double> M(int(rhs.size()), numVars);
      M.setFromTriplets(entries.begin(), entries.end());
      std::vector<Eigen::Triplet<double>>().swap(entries);
      const Eigen::Map<const Eigen::VectorXd> b(rhs.data(), Eigen::Index(rhs.size()));
      const Eigen::SparseMatrix<double> normal = M.transpose() * M;
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
      Eigen::VectorXd x;
      if (solver.info() == Eigen::Success) x = solver.solve(M.transpose() * b);
      if (solver.info() == Eigen::Success && x.allFinite())
        for (int s = 0; s < numSegments; ++s)
          for (std::size_t j = 0; j < slideVar[s].size(); ++j)
            if (slideVar[s][j] >= 0) {
              sum[s][j] = x[slideVar[s][j]];
              count[s][j] = 1;
            }
    }
    // The solved parameters, blended back towards arc length until they increase strictly.
    for (int s = 0; s < numSegments; ++s) {
      const int m = int(parameter[s].size());
      bool any = false;
      std::vector<double> mean = parameter[s];
      for (int j = 1; j + 1 < m; ++j)
        if (count[s][j] > 0) mean[j] = sum[s][j] / count[s][j], any = true;
      if (!any) continue;
      for (double share : {1.0, 0.5, 0.25, 0.0}) {
        std::vector<double> t(m);
        for (int j = 0; j < m; ++j) t[j] = share * mean[j] + (1 - share) * parameter[s][j];
        bool increasing = true;
        for (int j = 1; j < m; ++j) increasing = increasing && t[j] > t[j - 1];
        if (increasing || share == 0.0) {
          parameter[s] = t;
          break;
        }
      }
    }
  }

  // Samples of the segments used by the patches, made once and shared by both sides.
  std::vector<std::vector<int>> segmentSamples(graph.segments.size());
  std::vector<char> sampled(graph.segments.size(), 0);
  for (const auto& ps : graph.patches) {
    if (!ps.active) continue;
    for (const auto& side : ps.sides)
      for (const auto& ss : side) {
        if (sampled[ss.segment]) continue;
        sampled[ss.segment] = 1;
        const LayoutSegment& seg = graph.segments[ss.segment];
        const int n = lengths.segments[ss.segment];
        std::vector<Vec3> points;
        if (faceDirections && seg.vertices.size() >= 2) {
          std::vector<Vec3> poly;
          for (int v : seg.vertices) poly.push_back(layout.positions[v]);
          points = samplesByParameter(poly, parameter[ss.segment], n);
        } else {
          points = samplesAlong(seg.polyline, n);
        }
        for (const Vec3& p : points) {
          q.positions.push_back(p);
          segmentSamples[ss.segment].push_back(q.numVertices() - 1);
        }
      }
  }
  std::map<int, std::unique_ptr<PatchMap>> unitMaps;   // layout patch -> map onto [0,1]²
  std::map<int, std::unique_ptr<PatchMap>> chartMaps;  // polygon chart -> its map

  for (int p = 0; p < int(graph.patches.size()); ++p) {
    const PatchSides& ps = graph.patches[p];
    if (!ps.active) continue;
    const int W = lengths.sideLength(graph, p, 0), H = lengths.sideLength(graph, p, 1);
    std::vector<int> grid((W + 1) * (H + 1), -1);
    auto at = [&](int i, int j) -> int& { return grid[j * (W + 1) + i]; };
    auto sidePoint = [&](int k, int c) -> int& {
      switch (k) {
        case 0: return at(c, 0);
        case 1: return at(W, c);
        case 2: return at(W - c, H);
        default: return at(0, H - c);
      }
    };
    std::vector<Vec2> loopUv;
    if (ps.original) loopUv.assign(layout.patches[ps.layoutPatch].loop.size(), Vec2::Zero());
    for (int k = 0; k < 4; ++k) {
      int offset = 0;
      for (const SideSegment& ss : ps.sides[k]) {
        const LayoutSegment& seg = graph.segments[ss.segment];
        const int n = lengths.segments[ss.segment];
        sidePoint(k, offset) = node(ss.reversed ? seg.nodeB : seg.nodeA);
        for (int m = 1; m < n; ++m) sidePoint(k, offset + m) = segmentSamples[ss.segment][ss.reversed ? n - 1 - m : m - 1];
        if (ps.original) {  // the segment's layout vertices go where its samples are
          std::vector<int> chain = seg.vertices;
          if (ss.reversed) std::reverse(chain.begin(), chain.end());
          const int loopSize = int(loopUv.size());
          double run = 0;
          for (std::size_t i = 0; i < chain.size(); ++i) {
            if (i > 0) run += (layout.positions[chain[i]] - layout.positions[chain[i - 1]]).norm();
            loopUv[(ss.loopStart + int(i)) % loopSize] = sideUv(k, offset + (seg.length > 0 ? n * run / seg.length : 0), W, H);
          }
        }
        offset += n;
      }
    }
    if (ps.original) {
      // The patch mapped onto its integer rectangle: grid lines meet the sides at their samples.
      PatchGuide guide;
      if (faceDirections) {  // the side vertices where the segments' parameters put them
        guide.faceDirections = faceDirections;
        forEachSideVertex(p, [&](int k, const SideSegment&, int, int, int pos, double c) { loopUv[pos] = sideUv(k, c, W, H); });
      }
      const bool keepMeanValue = meanValuePatches && ps.layoutPatch < int(meanValuePatches->size()) &&
                                 (*meanValuePatches)[ps.layoutPatch] == kMeanValuePatch;
      const bool guided = faceDirections && !keepMeanValue;
      // The patch's grid: one mapped by an earlier call the same way with the same boundary,
      // else mapped now (and kept for later calls).
      std::vector<SampledGrids::Grid>* kept = grids ? &grids->byPatch[ps.layoutPatch] : nullptr;
      const SampledGrids::Grid* grid = nullptr;
      for (std::size_t g = 0; kept && g < kept->size() && !grid; ++g) {
        const SampledGrids::Grid& old = (*kept)[g];
        if (old.W == W && old.H == H && old.guided == guided && old.boundaryUv == loopUv) grid = &old;
      }
      SampledGrids::Grid mapped;
      if (!grid) {
        mapped = mapPatchGrid(layout, ps.layoutPatch, trianglesOf[ps.layoutPatch], halfEdge, loopUv, W, H,
                              guided ? &guide : nullptr, [&](int i, int j) { return q.positions[at(i, j)]; });
        grid = &mapped;
        if (kept) {
          if (kept->size() >= SampledGrids::kPerPatch) kept->erase(kept->begin());
          kept->push_back(std::move(mapped));
          grid = &kept->back();
        }
      }
      const std::vector<Vec3>& inner = grid->inner;
      const GuidedMap kind = grid->kind;
      for (int j = 1; j < H; ++j)
        for (int i = 1; i < W; ++i) {
          q.positions.push_back(inner[(j - 1) * (W - 1) + (i - 1)]);
          at(i, j) = q.numVertices() - 1;
        }
      if (faceDirections) {
        q.alignedPatches += kind == GuidedMap::Aligned;
        q.blendedPatches += kind == GuidedMap::Blended;
        q.meanValuePatches += kind == GuidedMap::MeanValue || kind == GuidedMap::None;
      }
      q.outsidePoints += grid->outsidePoints;
    } else if (ps.chart >= 0) {
      // A part of a split patch: bilinear in its quad of the layout patch's polygon chart.
      auto& map = chartMaps[ps.chart];
      if (!map) {
        const PolygonChart& chart = graph.charts[ps.chart];
        map = std::make_unique<PatchMap>(layout, chart.layoutPatch, trianglesOf[chart.layoutPatch], halfEdge,
                                         [&](int k) { return chart.loopUv[k]; });
      }
      const auto& c = ps.chartCorners;
      for (int j = 1; j < H; ++j)
        for (int i = 1; i < W; ++i) {
          const double s = double(i) / W, t = double(j) / H;
          const Vec2 uv = c[0] * ((1 - s) * (1 - t)) + c[1] * (s * (1 - t)) + c[2] * (s * t) + c[3] * ((1 - s) * t);
          q.positions.push_back(map->pointAt(uv));
          at(i, j) = q.numVertices() - 1;
        }
    } else {
      // A whole layout patch whose sides gained nodes from a neighbour's split: its unit-square map.
      auto& map = unitMaps[ps.layoutPatch];
      if (!map) {
        std::vector<Vec2> unit = unitSquareBoundary(layout, ps.layoutPatch);
        map = std::make_unique<PatchMap>(layout, ps.layoutPatch, trianglesOf[ps.layoutPatch], halfEdge,
                                         [&](int k) { return unit[k]; });
      }
      for (int j = 1; j < H; ++j)
        for (int i = 1; i < W; ++i) {
          q.positions.push_back(map->pointAt(Vec2(double(i) / W, double(j) / H)));
          at(i, j) = q.numVertices() - 1;
        }
    }
    for (int j = 0; j < H; ++j)
      for (int i = 0; i < W; ++i) {
        q.quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        q.quadPatch.push_back(ps.layoutPatch);
      }
  }
  for (const auto& m : unitMaps) q.outsidePoints += m.second->outsidePoints();
  for (const auto& m : chartMaps) q.outsidePoints += m.second->outsidePoints();
  return q;
}

}  // namespace fcql
