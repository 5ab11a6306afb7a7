// Smooth, curvature-aligned cross field generation. See field_generation.h.
//
// Unknown per face f: z_f = e^{4iθ_f}, θ_f the angle of the cross in the face frame (X_f, Y_f).
//
// Connection. Faces f and g share an edge; let a_f be the angle, in frame f, of the edge vector
// of f (edge i of f, corner i → i+1) and a_g the angle, in frame g, of the edge vector of g (edge
// j of g): the same edge run the other way. Unfolding g onto f about the edge preserves angles
// measured from the edge, so a direction at angle θ in frame f is carried to θ − a_f + (a_g − π)
// in frame g. For a 4-RoSy the π drops out (e^{−4iπ} = 1): z_g ≈ r z_f, r = e^{4i(a_g − a_f)}.
//
// Energy, one Hermitian quadratic form in the free z (r corrected by e^{4iρ_e}, see Scale):
//   E(z) = Σ_edges w_e |z_g − r z_f|²  +  λ Σ_f (A_f / A) |z_f − c_f|²
// with w_e = |e|² / (A_f + A_g) (dimensionless), A the total area and c_f the curvature target:
// c_f = e^{4iφ_f} · min(1, a_f / s), φ_f the direction of maximum curvature and a_f = (k1 − k2)/2
// the anisotropy of the (slightly smoothed) shape operator, s a robust scale of the anisotropy
// over the mesh (a high quantile, floored by 2 / bounding-box diagonal so that flat or umbilic
// regions give no confident target). Faces along feature lines (sharp edges) and borders are
// fixed to the edge direction, z = e^{4iβ}, and eliminated. The linear system is solved with a
// complex sparse Cholesky factorisation (CHOLMOD).
//
// Scale: the holonomy of the Levi-Civita connection around a vertex is its angle defect K_v,
// and the smoothest field puts a singularity wherever enough of it gathers, so every bump of
// noise on a scan gives a ±1/4 pair. The connection is corrected by a rotation ρ_e per edge
// (ρ = w_e (ψ_q − ψ_p), L ψ = K̃ − K, L the clamped-cotangent Laplacian of the interior
// vertices) so that the holonomy around each interior vertex becomes K̃_v, the angle defect
// diffused over a length ℓ = FieldGenerationOptions::scale × the bounding-box diagonal
// ((M + ℓ² L) κ̃ = K, K̃ = M κ̃): the curvature is seen at the scale of the layout, the field
// still follows the principal directions through c_f, and its index sum is unchanged (K̃ has
// the same total; border and feature vertices keep ψ = 0). On the shared meshes this removes
// a quarter to half of the singularities (fertility 50 → 38, rockerarm 36 → 23, the scanned
// dragon 943 → 457); diffusing the curvature tensor instead (the targets c_f) did not.
//
// Refinement: the linear relaxation lets |z| shrink freely, which leaves spurious pairs of
// singularities where the curvature data is noisy. A few MBO-style steps (implicit diffusion,
// then normalisation: Viertel & Osting 2019) fix that: z ← argmin E(z) + μ Σ_f (A_f / A) |z_f −
// ẑ_f/|ẑ_f||², with ẑ the previous iterate; the matrix is factorised once.
//
// Connected components with neither constraints nor curvature data (e.g. a perfect sphere with
// λ = 0) get the smoothest field instead: the eigenvector of the smallest eigenvalue of the
// connection Laplacian, by inverse iteration.
//
// Every term is invariant to a uniform scaling of the mesh, and the alignment and
// normalisation terms are integrals over the surface, so the balance does not depend on the
// resolution either.
#include "field/field_generation.h"
#include "field/singularity_pairs.h"

#include "field/curvature.h"
#include "field/field_analysis.h"
#include "util/math_constants.h"

#include <Eigen/Sparse>
#include <Eigen/CholmodSupport>

#include <algorithm>
#include <cmath>
#include <complex>
#include <new>
#include <numeric>
#include <string>

namespace fcql {
namespace {

using Complex = std::complex<double>;
using SparseMatrixC = Eigen::SparseMatrix<Complex>;  // lower triangles of Hermitian matrices

/// Default of FieldGenerationOptions::curvatureWeight (λ above).
constexpr double kDefaultCurvatureWeight = 200.0;
/// Default of FieldGenerationOptions::scale (a fraction of the bounding-box diagonal).
constexpr double kDefaultFieldScale = 0.02;
/// Jacobi smoothing steps applied to the shape operators before taking their directions.
constexpr int kTensorSmoothingSteps = 4;
/// The anisotropy scale s is this area-weighted quantile of the per-face anisotropy...
constexpr double kAnisotropyQuantile = 0.95;
/// ...but at least this many times 1 / (bounding-box diagonal).
constexpr double kAnisotropyFloor = 2.0;
/// MBO refinement: weight μ of the normalisation term and number of steps.
constexpr double kNormalisationWeight = 100.0;
constexpr int kNormalisationSteps = 20;
/// CHOLMOD's supernodal_switch (see FieldFactorisation).
constexpr double kSupernodalSwitch = 120;
/// Feature lines: a chain of sharp edges goes on through a vertex where exactly two sharp edges
/// meet with a turn below this angle; chains with fewer than kMinFeatureEdges edges are ignored
/// unless they are longer than kMinFeatureLength × the bounding-box diagonal (coarse meshes).
constexpr double kMaxFeatureTurnDeg = 30.0;
constexpr int kMinFeatureEdges = 4;
constexpr double kMinFeatureLength = 0.1;
/// Re-solves that keep a quarter turn of curvature at vertices left with index +1/2 or more
/// (see generateCrossField).
constexpr int kConeRounds = 2;


void checkSharpAngle(double deg) {
  if (!std::isfinite(deg) || deg < 0 || deg > 180)
    throw FieldError("the sharp edge angle must be between 0 and 180 degrees (got " + std::to_string(deg) + ")");
}

/// Connected components of the faces through interior edges.
std::vector<int> faceComponents(const SurfaceMesh& mesh, int* count) {
  std::vector<int> comp(mesh.numFaces(), -1);
  std::vector<int> stack;
  int n = 0;
  for (int s = 0; s < mesh.numFaces(); ++s) {
    if (comp[s] >= 0) continue;
    comp[s] = n;
    stack.push_back(s);
    while (!stack.empty()) {
      int f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        int g = mesh.adjacentFace(f, i);
        if (g >= 0 && comp[g] < 0) {
          comp[g] = n;
          stack.push_back(g);
        }
      }
    }
    ++n;
  }
  *count = n;
  return comp;
}

/// Area-weighted quantile q of non-negative values.
double weightedQuantile(const std::vector<double>& values, const std::vector<double>& weights, double q) {
  std::vector<int> order(values.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return values[a] < values[b]; });
  double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  double acc = 0;
  for (int k : order) {
    acc += weights[k];
    if (acc >= q * total) return values[k];
  }
  return order.empty() ? 0.0 : values[order.back()];
}

/// Sharp edges that form feature lines (see kMaxFeatureTurnDeg): short or zig-zagging runs
/// of sharp edges, as dihedral noise on scanned or coarse organic meshes makes, are dropped.
std::vector<char> featureEdges(const SurfaceMesh& mesh, const std::vector<char>& sharp) {
  const int nv = mesh.numVertices();
  const double maxTurn = kMaxFeatureTurnDeg * kPi / 180.0;
  const double minLength = kMinFeatureLength * mesh.boundingBoxDiagonal();
  std::vector<std::array<int, 2>> ends(mesh.numEdges(), {-1, -1});
  std::vector<std::vector<int>> incident(nv);
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int i = 0; i < 3; ++i) {
      int e = mesh.edgeId(f, i);
      if (!sharp[e] || ends[e][0] >= 0) continue;
      ends[e] = {mesh.vertex(f, i), mesh.vertex(f, (i + 1) % 3)};
      incident[ends[e][0]].push_back(e);
      incident[ends[e][1]].push_back(e);
    }
  auto other = [&](int e, int v) { return ends[e][0] == v ? ends[e][1] : ends[e][0]; };
  std::vector<char> through(nv, 0);
  for (int v = 0; v < nv; ++v) {
    if (incident[v].size() != 2) continue;
    Vec3 a = mesh.position(v) - mesh.position(other(incident[v][0], v));
    Vec3 b = mesh.position(other(incident[v][1], v)) - mesh.position(v);
    through[v] = std::atan2(a.cross(b).norm(), a.dot(b)) <= maxTurn;
  }
  std::vector<char> keep(mesh.numEdges(), 0), seen(mesh.numEdges(), 0);
  std::vector<int> chain;
  for (int e0 = 0; e0 < mesh.numEdges(); ++e0) {
    if (!sharp[e0] || seen[e0]) continue;
    chain.assign(1, e0);
    seen[e0] = 1;
    for (int side = 0; side < 2; ++side) {
      int e = e0, v = ends[e0][side];
      while (through[v]) {
        int next = incident[v][0] == e ? incident[v][1] : incident[v][0];
        if (seen[next]) break;  // went round a closed loop
        seen[next] = 1;
        chain.push_back(next);
        e = next;
        v = other(e, v);
      }
    }
    double length = 0;
    for (int e : chain) length += (mesh.position(ends[e][1]) - mesh.position(ends[e][0])).norm();
    if (int(chain.size()) >= kMinFeatureEdges || length >= minLength)
      for (int e : chain) keep[e] = 1;
  }
  return keep;
}

/// The smoothness term Σ w_e |z_g − r z_f|² over edges with at least one free face: its
/// diagonal (added to `diagonal`), its strictly lower triangle (free-free pairs) and its
/// right-hand side terms (a free face next to a fixed one). rho: the connection's correction
/// per face and edge (connectionCorrection).
void addSmoothness(const SurfaceMesh& mesh, const std::vector<int>& unknown, const std::vector<Complex>& z,
                   const std::vector<std::array<double, 3>>& rho, Eigen::VectorXd& diagonal,
                   std::vector<Eigen::Triplet<Complex>>& lower, Eigen::VectorXcd& rhs) {
  for (int f = 0; f < mesh.numFaces(); ++f) {
    int a = unknown[f];
    if (a < 0) continue;
    for (int i = 0; i < 3; ++i) {
      int g = mesh.adjacentFace(f, i);
      if (g < 0) continue;
      int b = unknown[g];
      if (b >= 0 && g < f) continue;  // free-free edges once, from the lower face
      const auto [r, w] = edgeSmoothness(mesh, f, i, rho[f][i]);  // z_g ≈ r z_f
      // w |z_g − r z_f|² = w |z_f|² + w |z_g|² − 2w Re(conj(z_g) r z_f)
      diagonal[a] += w;
      if (b >= 0) {
        // Unknowns follow the face order and g > f, so b > a: entry (b, a) is below the diagonal.
        diagonal[b] += w;
        lower.emplace_back(b, a, -w * r);
      } else {
        rhs[a] += w * std::conj(r) * z[g];
      }
    }
  }
}

/// The lower triangle of a Hermitian matrix from its strictly lower part and its diagonal.
SparseMatrixC lowerTriangle(int n, std::vector<Eigen::Triplet<Complex>> entries, const Eigen::VectorXd& diagonal) {
  entries.reserve(entries.size() + n);
  for (int a = 0; a < n; ++a) entries.emplace_back(a, a, diagonal[a]);
  SparseMatrixC m(n, n);
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

/// Sparse Cholesky factorisation of the field's Hermitian systems (lower triangles given):
/// CHOLMOD with an AMD ordering; matrices of one sparsity pattern share the symbolic analysis.
/// CHOLMOD picks a supernodal factorisation (dense blocks on the BLAS) when the flops per
/// entry of the factor reach `supernodal_switch`, a simplicial LDLᵀ otherwise. The switch is
/// raised from 40 to kSupernodalSwitch: on a mesh of 28K faces (78 flops per entry) the
/// simplicial one is about twice as fast, from ~100K faces (160) on the supernodal one wins
/// (947K faces: 4–7 s per factorisation with OpenBLAS, against 22–28 s for a simplicial one).
class FieldFactorisation {
public:
  FieldFactorisation() {
    cholmod_common& c = solver_.cholmod();
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_AMD;
    c.supernodal_switch = kSupernodalSwitch;
    c.print = 0;  // failures are reported as FieldError, not on stderr
  }
  void factorise(const SparseMatrixC& m) {
    if (!analysed_) {
      solver_.analyzePattern(m);
      check();
      analysed_ = true;
    }
    solver_.factorize(m);
    check();
    if (solver_.info() != Eigen::Success)
      throw FieldError("cross field generation failed: the field system could not be factorised");
  }
  Eigen::VectorXcd solve(const Eigen::VectorXcd& b) {
    Eigen::VectorXcd x = solver_.solve(b);
    check();
    return x;
  }

private:
  /// CHOLMOD's errors (negative status; positive ones are warnings, such as a matrix that is
  /// not positive definite, which info() reports).
  void check() {
    const int status = solver_.cholmod().status;
    if (status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
    if (status < 0)
      throw FieldError("cross field generation failed: the sparse solver reported error " + std::to_string(status));
  }

  Eigen::CholmodDecomposition<SparseMatrixC, Eigen::Lower> solver_;
  bool analysed_ = false;
};

/// Curvature targets c_f (see the top of the file).
std::vector<Complex> curvatureTargets(const SurfaceMesh& mesh, const std::vector<char>& creases) {
  const int nf = mesh.numFaces();
  std::vector<FaceTensor> tensors =
      smoothFaceTensors(mesh, faceShapeOperators(mesh, &creases), kTensorSmoothingSteps, 0.5, &creases);
  std::vector<double> anisotropy(nf), area(nf);
  for (int f = 0; f < nf; ++f) {
    anisotropy[f] = tensors[f].anisotropy();
    area[f] = mesh.faceArea(f);
  }
  double scale = std::max(weightedQuantile(anisotropy, area, kAnisotropyQuantile),
                          kAnisotropyFloor / mesh.boundingBoxDiagonal());
  std::vector<Complex> c(nf, 0.0);
  for (int f = 0; f < nf; ++f) {
    Complex w = tensors[f].tracelessPart();
    double a = std::abs(w);
    if (!(a > 0) || !std::isfinite(a)) continue;
    c[f] = std::min(1.0, a / scale) * (w * w) / (a * a);
  }
  return c;
}

/// Per face and edge i, an extra rotation ρ added to the connection across that edge (ρ of the
/// other face's side is −ρ), so that the holonomy around each interior vertex becomes its angle
/// defect diffused over `length`, instead of its own: the smoothest field then places its
/// singularities where the surface is curved at that scale, not at every bump of noise.
/// ρ = w_e (ψ_q − ψ_p) for the edge p→q of f, L ψ = K̃ − K on the interior vertices (ψ = 0 on
/// border and feature vertices, whose holonomy is left alone). A vertex marked in
/// `quarterCones` keeps a quarter turn of its own curvature undiffused (only the rest is
/// spread), so that the field turns by exactly a quarter around it (index +1/4).
std::vector<std::array<double, 3>> connectionCorrection(const SurfaceMesh& mesh, double length,
                                                        const std::vector<char>& creases,
                                                        const std::vector<char>& quarterCones) {
  const int nf = mesh.numFaces(), nv = mesh.numVertices();
  std::vector<std::array<double, 3>> rho(nf, {0.0, 0.0, 0.0});
  if (!(length > 0)) return rho;
  // Angle defects, vertex areas, positive edge weights (clamped cotangents).
  std::vector<double> defect(nv, 2 * kPi), vertexArea(nv, 0.0);
  std::vector<char> fixedVertex(nv, 0);
  std::vector<double> edgeWeight(mesh.numEdges(), 0.0);
  for (int f = 0; f < nf; ++f)
    for (int c = 0; c < 3; ++c) {
      int v = mesh.vertex(f, c);
      Vec3 a = mesh.position(mesh.vertex(f, (c + 1) % 3)) - mesh.position(v);
      Vec3 b = mesh.position(mesh.vertex(f, (c + 2) % 3)) - mesh.position(v);
      double angle = std::atan2(a.cross(b).norm(), a.dot(b));
      defect[v] -= angle;
      vertexArea[v] += mesh.faceArea(f) / 3;
      // The edge opposite corner c is edge (c+1) of f.
      double cot = a.dot(b) / std::max(a.cross(b).norm(), 1e-300);
      edgeWeight[mesh.edgeId(f, (c + 1) % 3)] += 0.5 * cot;
      if (mesh.isBorderVertex(v)) fixedVertex[v] = 1;
      if (creases[mesh.edgeId(f, c)]) fixedVertex[mesh.vertex(f, c)] = fixedVertex[mesh.vertex(f, (c + 1) % 3)] = 1;
    }
  for (double& w : edgeWeight) w = std::max(w, 0.05);
  std::vector<int> index(nv, -1);
  int n = 0;
  for (int v = 0; v < nv; ++v)
    if (!fixedVertex[v] && !mesh.star(v).empty()) index[v] = n++;
  if (n == 0) return rho;
  auto cone = [&](int v) { return quarterCones[v] ? kPi / 2 : 0.0; };
  // Diffuse the curvature density κ = K / A: (M + t L) κ̃ = K, K̃ = M κ̃ (the total is kept).
  std::vector<Eigen::Triplet<Complex>> lower;
  Eigen::VectorXd lapDiagonal = Eigen::VectorXd::Zero(n);
  for (int f = 0; f < nf; ++f)
    for (int i = 0; i < 3; ++i) {
      int g = mesh.adjacentFace(f, i);
      if (g >= 0 && g < f) continue;  // each interior edge once
      int a = index[mesh.vertex(f, i)], b = index[mesh.vertex(f, (i + 1) % 3)];
      double w = edgeWeight[mesh.edgeId(f, i)];
      if (a >= 0) lapDiagonal[a] += w;
      if (b >= 0) lapDiagonal[b] += w;
      if (a >= 0 && b >= 0) lower.emplace_back(std::max(a, b), std::min(a, b), -w);
    }
  const double t = length * length;
  std::vector<Eigen::Triplet<Complex>> scaled(lower);
  for (auto& e : scaled) e = Eigen::Triplet<Complex>(e.row(), e.col(), t * e.value());
  Eigen::VectorXd diagonal(n);
  Eigen::VectorXcd rhs(n);
  for (int v = 0; v < nv; ++v)
    if (index[v] >= 0) {
      diagonal[index[v]] = vertexArea[v] + t * lapDiagonal[index[v]];
      rhs[index[v]] = defect[v] - cone(v);
    }
  FieldFactorisation diffusion;
  diffusion.factorise(lowerTriangle(n, scaled, diagonal));
  Eigen::VectorXcd kappa = diffusion.solve(rhs);
  if (!kappa.allFinite()) return rho;
  // L ψ = K̃ − K, regularised by a tiny mass term (closed components: L is singular, the
  // right-hand side sums to zero on each).
  double meanDiagonal = lapDiagonal.sum() / n;
  Eigen::VectorXd lapDiag = lapDiagonal;
  for (int v = 0; v < nv; ++v)
    if (index[v] >= 0) {
      lapDiag[index[v]] += 1e-9 * meanDiagonal;
      rhs[index[v]] = vertexArea[v] * kappa[index[v]].real() + cone(v) - defect[v];
    }
  FieldFactorisation poisson;
  poisson.factorise(lowerTriangle(n, lower, lapDiag));
  Eigen::VectorXcd psi = poisson.solve(rhs);
  if (!psi.allFinite()) return rho;
  auto psiOf = [&](int v) { return index[v] >= 0 ? psi[index[v]].real() : 0.0; };
  for (int f = 0; f < nf; ++f)
    for (int i = 0; i < 3; ++i) {
      int p = mesh.vertex(f, i), q = mesh.vertex(f, (i + 1) % 3);
      rho[f][i] = edgeWeight[mesh.edgeId(f, i)] * (psiOf(q) - psiOf(p));
    }
  return rho;
}

/// Solves for the free faces with the connection corrected by `rho` (connectionCorrection);
/// z holds the fixed values on entry and every value on return.
void solveFreeFaces(const SurfaceMesh& mesh, const std::vector<int>& unknown, int n, double lambda,
                    const std::vector<std::array<double, 3>>& rho, const std::vector<char>& creases,
                    const std::vector<char>& quarterCones, std::vector<Complex>& z) {
  const int nf = mesh.numFaces();
  double totalArea = 0;
  for (int f = 0; f < nf; ++f) totalArea += mesh.faceArea(f);
  // areaWeight[a] = A_f / A of the free face f with unknown a.
  Eigen::VectorXd areaWeight(n);
  for (int f = 0; f < nf; ++f)
    if (unknown[f] >= 0) areaWeight[unknown[f]] = mesh.faceArea(f) / totalArea;

  std::vector<Eigen::Triplet<Complex>> offDiagonal;
  offDiagonal.reserve(std::size_t(n) * 3 / 2 + 16);
  Eigen::VectorXd smoothDiagonal = Eigen::VectorXd::Zero(n);
  Eigen::VectorXcd fixedRhs = Eigen::VectorXcd::Zero(n);
  addSmoothness(mesh, unknown, z, rho, smoothDiagonal, offDiagonal, fixedRhs);
  // Mean diagonal of the smoothness term (edge weights are dimensionless, ~1), a reference for
  // the tiny regularisations below; 1 if no free face has a neighbour.
  double meanDiagonal = smoothDiagonal.sum();
  meanDiagonal = meanDiagonal > 0 ? meanDiagonal / n : 1.0;

  // E(z) with the curvature term, plus a tiny regularisation that keeps the matrix definite
  // when nothing anchors a component.
  std::vector<Complex> target = lambda > 0 ? curvatureTargets(mesh, creases) : std::vector<Complex>(nf, 0.0);
  Eigen::VectorXd diagonal = smoothDiagonal;
  Eigen::VectorXcd rhs = fixedRhs;
  // The faces around a quarter cone follow the field the cone makes, not the curvature there
  // (a cone's principal directions turn around its tip, which would ask for more than a quarter).
  std::vector<char> aroundCone(nf, 0);
  for (int v = 0; v < mesh.numVertices(); ++v)
    if (quarterCones[v])
      for (const auto& corner : mesh.star(v)) aroundCone[corner.face] = 1;
  for (int f = 0; f < nf; ++f) {
    int a = unknown[f];
    if (a < 0) continue;
    double w = aroundCone[f] ? 0.0 : lambda * areaWeight[a];
    diagonal[a] += w + 1e-12 * meanDiagonal;
    rhs[a] += w * target[f];
  }
  // Every matrix below has this pattern (the full diagonal and the free-free pairs).
  SparseMatrixC system = lowerTriangle(n, offDiagonal, diagonal);
  FieldFactorisation solver;
  solver.factorise(system);
  Eigen::VectorXcd x = solver.solve(rhs);
  if (!x.allFinite()) throw FieldError("cross field generation failed: the solution is not finite");

  // Components where the solution vanishes: no constraint and no curvature data.
  int numComponents = 0;
  std::vector<int> comp = faceComponents(mesh, &numComponents);
  std::vector<double> norm2(numComponents, 0), weight(numComponents, 0);
  std::vector<char> anchored(numComponents, 0);
  for (int f = 0; f < nf; ++f) {
    if (unknown[f] < 0) {
      anchored[comp[f]] = 1;
      continue;
    }
    norm2[comp[f]] += areaWeight[unknown[f]] * std::norm(x[unknown[f]]);
    weight[comp[f]] += areaWeight[unknown[f]];
  }
  std::vector<char> degenerate(numComponents, 0);
  bool anyDegenerate = false;
  for (int c = 0; c < numComponents; ++c)
    if (!anchored[c] && weight[c] > 0 && !(norm2[c] > 1e-12 * weight[c])) degenerate[c] = anyDegenerate = true;
  if (anyDegenerate) {
    // Smallest eigenvector of the smoothness term (shifted slightly to stay definite), by
    // inverse iteration; the other components are zero in the iterate and stay so.
    Eigen::VectorXd shifted = smoothDiagonal + 1e-6 * meanDiagonal * areaWeight * double(n);
    FieldFactorisation inverse;
    inverse.factorise(lowerTriangle(n, offDiagonal, shifted));
    Eigen::VectorXcd v = Eigen::VectorXcd::Zero(n);
    for (int f = 0; f < nf; ++f)
      if (unknown[f] >= 0 && degenerate[comp[f]]) v[unknown[f]] = 1.0;
    for (int it = 0; it < 40; ++it) {
      Eigen::VectorXcd next = inverse.solve((areaWeight.cast<Complex>().array() * v.array()).matrix());
      double norm = next.norm();
      if (!(norm > 0) || !next.allFinite()) break;
      v = next / norm;
    }
    for (int f = 0; f < nf; ++f)
      if (unknown[f] >= 0 && degenerate[comp[f]]) x[unknown[f]] = v[unknown[f]];
  }
  std::vector<Eigen::Triplet<Complex>>().swap(offDiagonal);

  // MBO refinement: diffuse towards the normalised previous iterate.
  Eigen::VectorXd mu = kNormalisationWeight * areaWeight;
  SparseMatrixC& refined = system;
  for (int a = 0; a < n; ++a) refined.coeffRef(a, a) += mu[a];
  solver.factorise(refined);
  for (int step = 0; step < kNormalisationSteps; ++step) {
    Eigen::VectorXcd r = rhs;
    for (int a = 0; a < n; ++a) {
      double len = std::abs(x[a]);
      if (len > 0) r[a] += mu[a] * x[a] / len;
    }
    Eigen::VectorXcd next = solver.solve(r);
    if (!next.allFinite()) break;
    x = next;
  }
  for (int f = 0; f < nf; ++f)
    if (unknown[f] >= 0) z[f] = x[unknown[f]];
}

CrossField fieldFromValues(const SurfaceMesh& mesh, const std::vector<Complex>& z) {
  CrossField field;
  field.u.resize(mesh.numFaces());
  for (int f = 0; f < mesh.numFaces(); ++f) {
    double theta = std::abs(z[f]) > 0 ? std::arg(z[f]) / 4 : 0.0;
    field.u[f] = std::cos(theta) * mesh.faceFrameX(f) + std::sin(theta) * mesh.faceFrameY(f);
  }
  return field;
}

/// Interior singular vertices of index +1/2 or more.
std::vector<int> highIndexVertices(const SurfaceMesh& mesh, const CrossField& field) {
  std::vector<int> found;
  std::vector<int> quarters = computeVertexIndices(mesh, field);
  for (int v = 0; v < mesh.numVertices(); ++v)
    if (quarters[v] >= 2 && !mesh.isBorderVertex(v)) found.push_back(v);
  return found;
}

}  // namespace

std::vector<char> detectSharpEdges(const SurfaceMesh& mesh, double sharpAngleDeg) {
  checkSharpAngle(sharpAngleDeg);
  std::vector<char> sharp(mesh.numEdges(), 0);
  const double threshold = sharpAngleDeg * kPi / 180.0;
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int i = 0; i < 3; ++i) {
      int g = mesh.adjacentFace(f, i);
      if (g < f) continue;  // a border edge, or seen from the other face
      const Vec3& a = mesh.faceNormal(f);
      const Vec3& b = mesh.faceNormal(g);
      if (std::atan2(a.cross(b).norm(), a.dot(b)) > threshold) sharp[mesh.edgeId(f, i)] = 1;
    }
  return sharp;
}

CrossField generateCrossField(const SurfaceMesh& mesh, const FieldGenerationOptions& options,
                              FieldGenerationReport* report) {
  checkSharpAngle(options.sharpAngleDeg);
  if (!std::isfinite(options.curvatureWeight))
    throw FieldError("the curvature weight must be a finite number (negative: the default)");
  if (!std::isfinite(options.scale) || options.scale > 1)
    throw FieldError("the field scale must be at most 1 (a fraction of the bounding-box diagonal; negative: the default)");
  const int nf = mesh.numFaces();
  const double lambda = options.curvatureWeight < 0 ? kDefaultCurvatureWeight : options.curvatureWeight;
  const double scale = options.scale < 0 ? kDefaultFieldScale : options.scale;

  // Hard constraints: each face with a feature or border edge follows its longest such edge.
  std::vector<char> feature = featureEdges(mesh, detectSharpEdges(mesh, options.sharpAngleDeg));
  std::vector<Complex> z(nf, 0.0);
  std::vector<int> unknown(nf, -1);
  int n = 0, numFixed = 0;
  for (int f = 0; f < nf; ++f) {
    int best = -1;
    double bestLength = -1;
    for (int i = 0; i < 3; ++i) {
      bool constrained = mesh.isBorderEdge(f, i) ? options.alignToBorders : feature[mesh.edgeId(f, i)] != 0;
      double len = mesh.edgeVector(f, i).norm();
      if (constrained && len > bestLength) {
        bestLength = len;
        best = i;
      }
    }
    if (best >= 0) {
      // A border edge: the border's direction there (its own, unless the border zigzags).
      const Vec3 along = mesh.isBorderEdge(f, best) ? mesh.borderTangent(f, best) : mesh.edgeVector(f, best);
      z[f] = std::polar(1.0, 4 * angleInFaceFrame(mesh, f, along));
      ++numFixed;
    } else {
      unknown[f] = n++;
    }
  }
  if (report) {
    report->sharpEdges = int(std::count(feature.begin(), feature.end(), 1));
    report->constrainedFaces = numFixed;
  }
  const std::vector<Complex> fixedValues = z;
  std::vector<char> quarterCones(mesh.numVertices(), 0);
  const double curvatureLength = scale * mesh.boundingBoxDiagonal();
  std::vector<std::array<double, 3>> rho;
  if (n > 0) {
    rho = connectionCorrection(mesh, curvatureLength, feature, quarterCones);
    solveFreeFaces(mesh, unknown, n, lambda, rho, feature, quarterCones, z);
  }
  CrossField field = fieldFromValues(mesh, z);

  // Cones: an interior vertex that gathers a lot of curvature (a spike of a scan, the tip of a
  // CAD part) can end with index +1/2 or more, when the corrected connection turns the field
  // by more than a quarter within its own star. No quad layout serves that: a +1/2 singularity
  // has two ports, and the quad mesh splits it into two valence-3 vertices whose separatrices
  // cut it far finer than its layout. Such a vertex keeps a quarter turn of its curvature (the
  // rest is spread as elsewhere) and the field is solved again: it turns by exactly a quarter
  // around it (index +1/4), the remaining index goes where the spread curvature gathers. Kept
  // only where it lowers their count.
  if (n > 0 && scale > 0) {
    std::vector<int> cones = highIndexVertices(mesh, field);
    for (int round = 0; round < kConeRounds && !cones.empty(); ++round) {
      for (int v : cones) quarterCones[v] = 1;
      std::vector<Complex> retry = fixedValues;
      std::vector<std::array<double, 3>> retryRho = connectionCorrection(mesh, curvatureLength, feature, quarterCones);
      solveFreeFaces(mesh, unknown, n, lambda, retryRho, feature, quarterCones, retry);
      CrossField next = fieldFromValues(mesh, retry);
      std::vector<int> left = highIndexVertices(mesh, next);
      if (left.size() >= cones.size()) break;
      field = std::move(next);
      rho = std::move(retryRho);
      if (report) report->conesKept = int(std::count(quarterCones.begin(), quarterCones.end(), 1));
      cones = std::move(left);
    }
  }
  // Opposite singularities on the two ends of one edge (a sliver triangle of a noisy scan):
  // cancelled where turning the crosses of the edge's free triangles does it.
  std::vector<char> fixedFace(nf, 0);
  for (int f = 0; f < nf; ++f) fixedFace[f] = unknown[f] < 0;
  const int cancelled = cancelAdjacentSingularityPairs(mesh, field, fixedFace);
  if (report) report->pairsCancelled = cancelled;
  // Opposite quarters closer than the scale the curvature is seen at: patches thinner than a
  // quad between their separatrices, from noise the diffusion left.
  const int closeCancelled = rho.empty() ? 0 : cancelCloseSingularityPairs(mesh, field, curvatureLength, rho, fixedFace);
  if (report) report->closePairsCancelled = closeCancelled;
  return field;
}

}  // namespace fcql
