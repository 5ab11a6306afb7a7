// Meshes the project generates itself, for examples and tests: all closed or bordered
// oriented 2-manifolds with outward normals and well-shaped triangles.
#pragma once

#include "mesh/surface_mesh.h"

#include <functional>
#include <string>
#include <vector>

namespace fcql {

/// How gridSurface splits each quad in two triangles.
enum class GridDiagonal {
  Shorter,  ///< along its shorter diagonal (well-shaped triangles; the examples)
  Same      ///< along the diagonal from (i, j) to (i+1, j+1) everywhere (a regular pattern:
            ///< on the torus the smoothest field then has no singularity, which tests use)
};

/// A grid of (nu+1)×(nv+1) points at(s, t), s, t ∈ [0,1], closed in u and/or v by identifying
/// the last column/row with the first, each quad split in two triangles along `diagonal`. The
/// parametric surfaces below are made with it; tests make their own surfaces with it too.
SurfaceMesh gridSurface(int nu, int nv, bool closedU, bool closedV, const std::function<Vec3(double, double)>& at,
                        GridDiagonal diagonal = GridDiagonal::Shorter);

/// Unit-radius sphere from a subdivided icosahedron (20·4^subdivisions faces). Genus 0.
SurfaceMesh makeSphere(int subdivisions = 3);
/// Torus around the z axis: ring radius R, tube radius r, nu × nv quads split in triangles.
SurfaceMesh makeTorus(double R = 1.0, double r = 0.4, int nu = 48, int nv = 24, GridDiagonal diagonal = GridDiagonal::Shorter);
/// A closed genus-2 surface (two fused tori), resolution controls the triangle count.
SurfaceMesh makeDoubleTorus(int resolution = 40);
/// Axis-aligned box of half-size `half` with edges rounded by `radius` (0 < radius < min half),
/// smooth (no sharp edges), genus 0; `resolution` segments per unit length (denser when a
/// small radius needs it: each quarter circle gets at least 4 segments, triangles stay fat).
SurfaceMesh makeRoundedBox(Vec3 half = Vec3(1.0, 0.8, 0.6), double radius = 0.2, int resolution = 16);
/// Open cylinder around z (two border loops), radius, height, nu around, nv along.
SurfaceMesh makeOpenCylinder(double radius = 0.5, double height = 2.0, int nu = 48, int nv = 32,
                             GridDiagonal diagonal = GridDiagonal::Shorter);

/// Names accepted by makeExample: "sphere", "torus", "double_torus", "rounded_box",
/// "open_cylinder".
std::vector<std::string> exampleNames();
/// Throws MeshError for an unknown name (listing the valid ones).
SurfaceMesh makeExample(const std::string& name);

}  // namespace fcql
