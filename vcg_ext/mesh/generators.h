// Meshes the project generates itself, for examples and tests: all closed or bordered
// oriented 2-manifolds with outward normals and well-shaped triangles.
#pragma once

#include "mesh/surface_mesh.h"

#include <string>
#include <vector>

namespace fcql {

/// Unit-radius sphere from a subdivided icosahedron (20·4^subdivisions faces). Genus 0.
SurfaceMesh makeSphere(int subdivisions = 3);
/// Torus around the z axis: ring radius R, tube radius r, nu × nv quads split in triangles.
SurfaceMesh makeTorus(double R = 1.0, double r = 0.4, int nu = 48, int nv = 24);
/// A closed genus-2 surface (two fused tori), resolution controls the triangle count.
SurfaceMesh makeDoubleTorus(int resolution = 40);
/// Axis-aligned box of half-size `half` with edges rounded by `radius` (0 < radius < min half),
/// smooth (no sharp edges), genus 0; `resolution` segments per unit length (denser when a
/// small radius needs it: each quarter circle gets at least 4 segments, triangles stay fat).
SurfaceMesh makeRoundedBox(Vec3 half = Vec3(1.0, 0.8, 0.6), double radius = 0.2, int resolution = 16);
/// Open cylinder around z (two border loops), radius, height, nu around, nv along.
SurfaceMesh makeOpenCylinder(double radius = 0.5, double height = 2.0, int nu = 48, int nv = 32);

/// Names accepted by makeExample: "sphere", "torus", "double_torus", "rounded_box",
/// "open_cylinder".
std::vector<std::string> exampleNames();
/// Throws MeshError for an unknown name (listing the valid ones).
SurfaceMesh makeExample(const std::string& name);

}  // namespace fcql
