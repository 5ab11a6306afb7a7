// A small software rasterizer for pictures of meshes without a display: a perspective camera
// orbiting the object, a z-buffer, flat Lambert shading with a light attached to the camera,
// wide lines and dots drawn over the surface with a depth test and a small depth offset.
// Drawing happens at `supersample` times the output size; finish() averages it down (the
// anti-aliasing). Sizes of lines and dots are in output pixels.
#pragma once

#include "render/png.h"

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace fcql::render {

using Vec3 = Eigen::Vector3d;

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

/// Where the camera is: on a sphere around `center`, at `azimuthDeg` around the up axis (0 looks
/// along −z for up = y, i.e. from +z) and `elevationDeg` above the horizon; the object's bounding
/// sphere (`center`, `radius`) fills the view with a small margin.
struct CameraSetup {
  Vec3 center = Vec3::Zero();
  double radius = 1;
  double azimuthDeg = 30, elevationDeg = 20;
  int upAxis = 1;           ///< 0 = x, 1 = y, 2 = z
  double fovDeg = 30;       ///< field of view across the smaller side of the picture
  double margin = 1.04;     ///< >1 leaves room around the bounding sphere
};

class Rasterizer {
public:
  Rasterizer(int width, int height, const CameraSetup& camera, Rgb background, int supersample = 3);

  /// Zooms and shifts the view (the camera stays where it is) so that the picture of `points`
  /// just fills the frame, leaving `margin` − 1 of it free around; call before drawing.
  void frame(const std::vector<Vec3>& points, double margin = 1.1);

  /// A triangle, shaded by the angle between its normal and the direction to the camera
  /// (both sides lit).
  void triangle(const Vec3& a, const Vec3& b, const Vec3& c, Rgb colour);
  /// Same, with the normal given (e.g. a quad's normal for both its triangles).
  void triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal, Rgb colour);
  /// A segment `width` output pixels wide with round ends; visible where it is no farther than
  /// the surface plus `depthOffset` (a fraction of the bounding radius). Lines do not write depth,
  /// so draw them after the surfaces.
  void line(const Vec3& a, const Vec3& b, double width, Rgb colour, double depthOffset = 0.004);
  /// A disc of `radius` output pixels with a ring of `ring` pixels in `ringColour`, drawn whole
  /// if its centre is visible (no farther than the surface plus depthOffset × bounding radius).
  void dot(const Vec3& p, double radius, Rgb colour, double ring, Rgb ringColour, double depthOffset = 0.02);
  /// Darkens pixels where the depth jumps (silhouettes and creases seen edge-on), `width`
  /// output pixels wide; call after the surfaces, before lines.
  void outline(Rgb colour, double width = 1.0);

  /// The picture at the output size.
  Image finish() const;

  int width() const { return width_; }
  int height() const { return height_; }

private:
  struct Projected {
    double x, y, z;  // pixel coordinates (supersampled) and distance along the view axis
  };
  Projected project(const Vec3& p) const;
  float& depth(int x, int y) { return depth_[std::size_t(y) * W_ + x]; }
  void put(int x, int y, Rgb c);

  int width_, height_, ss_, W_, H_;
  Vec3 eye_, right_, up_, forward_;
  double focal_ = 1, radius_ = 1, cx_ = 0, cy_ = 0;  // pixels per unit of x/z, principal point
  Vec3 light_;
  std::vector<float> depth_;
  std::vector<std::uint8_t> colour_;
};

}  // namespace fcql::render
