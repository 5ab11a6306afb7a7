#include "render/rasterizer.h"

#include "util/math_constants.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fcql::render {

namespace {
const float kFar = std::numeric_limits<float>::infinity();
}  // namespace

Rasterizer::Rasterizer(int width, int height, const CameraSetup& cam, Rgb background, int supersample)
    : width_(width), height_(height), ss_(supersample), W_(width * supersample), H_(height * supersample) {
  if (width < 1 || height < 1 || supersample < 1) throw std::invalid_argument("bad picture size");
  // Orbit frame: the up axis, and the horizontal directions the camera sees from at azimuth 0
  // (`front`) and at azimuth 90 (`side`): up y sees from +z and +x, up z from −y and +x (a CAD
  // front view), up x from +z and +y.
  Vec3 upWorld = Vec3::Zero(), front, side;
  upWorld[cam.upAxis] = 1;
  if (cam.upAxis == 2) front = -Vec3::UnitY(), side = Vec3::UnitX();
  else if (cam.upAxis == 0) front = Vec3::UnitZ(), side = Vec3::UnitY();
  else front = Vec3::UnitZ(), side = Vec3::UnitX();
  double az = cam.azimuthDeg * kPi / 180, el = cam.elevationDeg * kPi / 180;
  Vec3 towardsEye = std::cos(el) * (std::cos(az) * front + std::sin(az) * side) + std::sin(el) * upWorld;
  double halfFov = 0.5 * cam.fovDeg * kPi / 180;
  radius_ = cam.radius > 0 ? cam.radius : 1;
  double distance = cam.margin * radius_ / std::sin(halfFov);
  eye_ = cam.center + distance * towardsEye;
  forward_ = -towardsEye;
  right_ = forward_.cross(upWorld);
  if (right_.norm() < 1e-9) right_ = forward_.cross(side);  // looking straight down or up
  right_.normalize();
  up_ = right_.cross(forward_);
  focal_ = 0.5 * std::min(W_, H_) / std::tan(halfFov);
  cx_ = 0.5 * W_, cy_ = 0.5 * H_;
  // The light sits with the camera, a little above and to the left, so faces facing the viewer
  // are brightest and shapes still read.
  light_ = (towardsEye + 0.25 * up_ - 0.12 * right_).normalized();
  depth_.assign(std::size_t(W_) * H_, kFar);
  colour_.resize(std::size_t(W_) * H_ * 3);
  for (std::size_t i = 0; i < colour_.size(); i += 3)
    colour_[i] = background.r, colour_[i + 1] = background.g, colour_[i + 2] = background.b;
}

Rasterizer::Projected Rasterizer::project(const Vec3& p) const {
  Vec3 d = p - eye_;
  double z = std::max(d.dot(forward_), 1e-9 * radius_);
  return {cx_ + focal_ * d.dot(right_) / z, cy_ - focal_ * d.dot(up_) / z, z};
}

void Rasterizer::frame(const std::vector<Vec3>& points, double margin) {
  // Perspective division keeps straight lines and ratios on the image plane, so fitting the
  // box of the projected points is a scale and a shift of that plane.
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
  for (const Vec3& p : points) {
    Vec3 d = p - eye_;
    double z = d.dot(forward_);
    if (!(z > 1e-9 * radius_)) continue;
    double u = d.dot(right_) / z, v = d.dot(up_) / z;
    u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, v), v1 = std::max(v1, v);
  }
  if (!(u1 > u0) && !(v1 > v0)) return;
  focal_ = std::min(W_ / std::max(u1 - u0, 1e-12), H_ / std::max(v1 - v0, 1e-12)) / margin;
  cx_ = 0.5 * W_ - focal_ * 0.5 * (u0 + u1);
  cy_ = 0.5 * H_ + focal_ * 0.5 * (v0 + v1);
}

void Rasterizer::put(int x, int y, Rgb c) {
  std::uint8_t* q = &colour_[3 * (std::size_t(y) * W_ + x)];
  q[0] = c.r, q[1] = c.g, q[2] = c.b;
}

void Rasterizer::triangle(const Vec3& a, const Vec3& b, const Vec3& c, Rgb colour) {
  Vec3 n = (b - a).cross(c - a);
  if (n.squaredNorm() == 0) return;
  triangle(a, b, c, n, colour);
}

void Rasterizer::triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal, Rgb colour) {
  double len = normal.norm();
  if (!(len > 0)) return;
  double lambert = std::abs(normal.dot(light_)) / len;
  double shade = 0.36 + 0.64 * lambert;
  auto channel = [shade](std::uint8_t v) { return std::uint8_t(std::min(255.0, v * shade + 0.5)); };
  Rgb shaded{channel(colour.r), channel(colour.g), channel(colour.b)};

  Projected p[3] = {project(a), project(b), project(c)};
  double area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x);
  if (std::abs(area) < 1e-12) return;
  int x0 = std::max(0, int(std::floor(std::min({p[0].x, p[1].x, p[2].x}))));
  int x1 = std::min(W_ - 1, int(std::ceil(std::max({p[0].x, p[1].x, p[2].x}))));
  int y0 = std::max(0, int(std::floor(std::min({p[0].y, p[1].y, p[2].y}))));
  int y1 = std::min(H_ - 1, int(std::ceil(std::max({p[0].y, p[1].y, p[2].y}))));
  double inv[3] = {1 / p[0].z, 1 / p[1].z, 1 / p[2].z};
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      double px = x + 0.5, py = y + 0.5;
      // Barycentric weights from the edge functions; pixel centres on an edge count as inside.
      double w0 = ((p[1].x - px) * (p[2].y - py) - (p[1].y - py) * (p[2].x - px)) / area;
      double w1 = ((p[2].x - px) * (p[0].y - py) - (p[2].y - py) * (p[0].x - px)) / area;
      double w2 = 1 - w0 - w1;
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      float z = float(1 / (w0 * inv[0] + w1 * inv[1] + w2 * inv[2]));  // perspective-correct depth
      if (z < depth(x, y)) depth(x, y) = z, put(x, y, shaded);
    }
}

void Rasterizer::line(const Vec3& a, const Vec3& b, double width, Rgb colour, double depthOffset) {
  Projected p = project(a), q = project(b);
  double half = 0.5 * width * ss_, offset = depthOffset * radius_;
  double dx = q.x - p.x, dy = q.y - p.y, len2 = dx * dx + dy * dy;
  int x0 = std::max(0, int(std::floor(std::min(p.x, q.x) - half)));
  int x1 = std::min(W_ - 1, int(std::ceil(std::max(p.x, q.x) + half)));
  int y0 = std::max(0, int(std::floor(std::min(p.y, q.y) - half)));
  int y1 = std::min(H_ - 1, int(std::ceil(std::max(p.y, q.y) + half)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      double px = x + 0.5 - p.x, py = y + 0.5 - p.y;
      double t = len2 > 0 ? std::clamp((px * dx + py * dy) / len2, 0.0, 1.0) : 0.0;
      double ex = px - t * dx, ey = py - t * dy;
      if (ex * ex + ey * ey > half * half) continue;
      // 1/z is linear in screen space along the projected segment.
      double z = 1 / ((1 - t) / p.z + t / q.z);
      if (z - offset <= depth(x, y)) put(x, y, colour);
    }
}

void Rasterizer::dot(const Vec3& c, double radius, Rgb colour, double ring, Rgb ringColour, double depthOffset) {
  Projected p = project(c);
  int cx = int(std::floor(p.x)), cy = int(std::floor(p.y));
  if (cx < 0 || cy < 0 || cx >= W_ || cy >= H_) return;
  // Visible if any pixel next to the centre shows the surface at about this depth.
  bool visible = false;
  for (int y = std::max(0, cy - ss_); y <= std::min(H_ - 1, cy + ss_) && !visible; ++y)
    for (int x = std::max(0, cx - ss_); x <= std::min(W_ - 1, cx + ss_) && !visible; ++x)
      visible = p.z - depthOffset * radius_ <= depth(x, y);
  if (!visible) return;
  double inner = radius * ss_, outer = (radius + ring) * ss_;
  for (int y = std::max(0, int(p.y - outer - 1)); y <= std::min(H_ - 1, int(p.y + outer + 1)); ++y)
    for (int x = std::max(0, int(p.x - outer - 1)); x <= std::min(W_ - 1, int(p.x + outer + 1)); ++x) {
      double r = std::hypot(x + 0.5 - p.x, y + 0.5 - p.y);
      if (r <= inner) put(x, y, colour);
      else if (r <= outer) put(x, y, ringColour);
    }
}

void Rasterizer::outline(Rgb colour, double width) {
  // A pixel is on an outline if a neighbour within `width` is background or much deeper: a jump
  // larger than what a smooth surface could give between neighbouring pixels.
  int reach = std::max(1, int(std::lround(0.5 * width * ss_)));
  double jump = 0.03 * radius_;
  std::vector<char> mark(depth_.size(), 0);
  for (int y = 0; y < H_; ++y)
    for (int x = 0; x < W_; ++x) {
      float z = depth(x, y);
      if (z == kFar) continue;
      bool edge = false;
      for (int dy = -reach; dy <= reach && !edge; ++dy)
        for (int dx = -reach; dx <= reach && !edge; ++dx) {
          int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= W_ || ny >= H_) continue;
          float n = depth(nx, ny);
          edge = n == kFar || n - z > jump;
        }
      mark[std::size_t(y) * W_ + x] = edge;
    }
  for (int y = 0; y < H_; ++y)
    for (int x = 0; x < W_; ++x)
      if (mark[std::size_t(y) * W_ + x]) put(x, y, colour);
}

Image Rasterizer::finish() const {
  Image out(width_, height_);
  const int n = ss_ * ss_;
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x)
      for (int ch = 0; ch < 3; ++ch) {
        int sum = 0;
        for (int sy = 0; sy < ss_; ++sy)
          for (int sx = 0; sx < ss_; ++sx) sum += colour_[3 * (std::size_t(y * ss_ + sy) * W_ + x * ss_ + sx) + ch];
        out.pixel(x, y)[ch] = std::uint8_t((sum + n / 2) / n);
      }
  return out;
}

}  // namespace fcql::render
