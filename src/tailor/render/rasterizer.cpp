/// @file
/// Perspective projection, edge-function rasterisation and two-sided Lambert shading.

#include "tailor/render/rasterizer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tailor/render/corner_normals.hpp"

namespace tailor {

Camera Camera::framing(const Vec3& lo, const Vec3& hi, const Vec3& view, const Vec3& up,
                       double aspect, double fov_y_deg) {
  Camera c;
  c.fov_y_deg = fov_y_deg;
  c.up = up;
  c.target = 0.5 * (lo + hi);
  const Vec3 back = view.normalized();  // from the target towards the eye
  const Vec3 right = (-back).cross(up).normalized();
  const Vec3 true_up = right.cross(-back);
  // 5 % margin on each side.
  const double tan_y = std::tan(0.5 * fov_y_deg * std::numbers::pi / 180.0) / 1.05;
  const double tan_x = tan_y * aspect;
  // The nearest eye distance at which every corner of the box projects inside the image:
  // a corner at offset o from the target has depth d - o·back, and must satisfy
  // |o·right| ≤ tan_x (d - o·back) and |o·up| ≤ tan_y (d - o·back).
  double distance = 1e-9;
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(),
                      (k & 4) ? hi.z() : lo.z());
    const Vec3 o = corner - c.target;
    const double along = o.dot(back);
    distance = std::max({distance, std::abs(o.dot(right)) / tan_x + along,
                         std::abs(o.dot(true_up)) / tan_y + along, along + 1e-6});
  }
  c.eye = c.target + back * distance;
  return c;
}

Rasterizer::Rasterizer(int width, int height, const Camera& camera, Rgb background)
    : m_image(width, height, background),
      m_depth(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0.0f),
      m_camera(camera) {
  m_forward = (camera.target - camera.eye).normalized();
  m_right = m_forward.cross(camera.up).normalized();
  m_up = m_right.cross(m_forward);
  const double half_fov = 0.5 * camera.fov_y_deg * std::numbers::pi / 180.0;
  m_focal = 0.5 * height / std::tan(half_fov);
  // Key light from above the camera's left shoulder.
  m_light = (-m_forward + 0.6 * m_up - 0.4 * m_right).normalized();
}

void Rasterizer::draw(const Positions& vertices, const FaceArray& faces, const MeshStyle& style,
                      const ShadingOptions& shading) {
  const double cx = 0.5 * m_image.width(), cy = 0.5 * m_image.height();
  const double near = 1e-3;
  const bool smooth = shading.shading == Shading::smooth;
  const CornerNormals corners =
      smooth ? corner_normals(vertices, faces, shading.crease_angle_deg) : CornerNormals();
  for (Index f = 0; f < static_cast<Index>(faces.rows()); ++f) {
    ScreenTriangle t;
    std::array<Vec3, 3> p;
    bool visible = true;
    for (int k = 0; k < 3; ++k) {
      p[k] = position(vertices, faces(f, k));
      const Vec3 d = p[k] - m_camera.eye;
      const double depth = d.dot(m_forward);
      if (!(depth > near)) {
        visible = false;
        break;
      }
      t.corner[k] = {cx + m_focal * d.dot(m_right) / depth, cy - m_focal * d.dot(m_up) / depth,
                     1.0 / depth};
    }
    if (!visible) continue;
    Vec3 n = (p[1] - p[0]).cross(p[2] - p[0]);
    if (!(n.norm() > 0)) continue;
    n.normalize();
    const bool front = n.dot(m_camera.eye - p[0]) >= 0;
    const double side = front ? 1.0 : -1.0;  // normals turned to the side the camera sees
    for (int k = 0; k < 3; ++k) {
      const Vec3 corner = smooth ? Vec3(corners.row(3 * f + k).transpose()) : n;
      t.normal[k] = side * (corner.isZero() ? n : corner);
    }
    fill_triangle(t, front ? style.front(f) : style.back(f));
  }
}

void Rasterizer::fill_triangle(const ScreenTriangle& t, Rgb colour) {
  const auto& s = t.corner;
  const double area =
      (s[1].x() - s[0].x()) * (s[2].y() - s[0].y()) - (s[2].x() - s[0].x()) * (s[1].y() - s[0].y());
  if (!(std::abs(area) > 1e-12)) return;
  const int w = m_image.width(), h = m_image.height();
  const int x0 =
      std::max(0, static_cast<int>(std::floor(std::min({s[0].x(), s[1].x(), s[2].x()}))));
  const int x1 =
      std::min(w - 1, static_cast<int>(std::ceil(std::max({s[0].x(), s[1].x(), s[2].x()}))));
  const int y0 =
      std::max(0, static_cast<int>(std::floor(std::min({s[0].y(), s[1].y(), s[2].y()}))));
  const int y1 =
      std::min(h - 1, static_cast<int>(std::ceil(std::max({s[0].y(), s[1].y(), s[2].y()}))));
  const auto edge = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b, double px, double py) {
    return (b.x() - a.x()) * (py - a.y()) - (b.y() - a.y()) * (px - a.x());
  };
  const auto scale = [](std::uint8_t c, double shade) {
    return static_cast<std::uint8_t>(std::clamp(std::lround(c * shade), 0L, 255L));
  };
  for (int y = y0; y <= y1; ++y) {
    const double py = y + 0.5;
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5;
      // Barycentric weights, sign-normalised so both windings fill; pixel centres on
      // an edge belong to the triangle (shared edges may be drawn twice; harmless).
      const double w0 = edge(s[1], s[2], px, py) / area;
      const double w1 = edge(s[2], s[0], px, py) / area;
      const double w2 = 1 - w0 - w1;
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      const double inv_depth = w0 * s[0].z() + w1 * s[1].z() + w2 * s[2].z();
      float& d = m_depth[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + x];
      if (static_cast<float>(inv_depth) <= d) continue;
      d = static_cast<float>(inv_depth);
      // Perspective-correct interpolation: screen weights times 1 / depth, renormalised.
      const Vec3 normal =
          ((w0 * s[0].z() / inv_depth) * t.normal[0] + (w1 * s[1].z() / inv_depth) * t.normal[1] +
           (w2 * s[2].z() / inv_depth) * t.normal[2])
              .normalized();
      const double shade = kAmbient + kDiffuse * std::max(0.0, normal.dot(m_light));
      m_image.at(x, y) = {scale(colour.r, shade), scale(colour.g, shade), scale(colour.b, shade)};
    }
  }
}

}  // namespace tailor
