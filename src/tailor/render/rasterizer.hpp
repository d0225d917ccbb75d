#pragma once
/// @file
/// A small z-buffered triangle rasteriser with a perspective camera and flat shading.

#include <functional>
#include <vector>

#include "tailor/geometry/types.hpp"
#include "tailor/render/image.hpp"

namespace tailor {

/// A pinhole camera looking from `eye` at `target`.
struct Camera {
  Vec3 eye{0, 0, 1};
  Vec3 target = Vec3::Zero();
  Vec3 up = Vec3::UnitY();
  double fov_y_deg = 30;  ///< vertical field of view

  /// A camera looking at the centre of the box [lo, hi] from direction `view` (from the
  /// target towards the eye), just far enough that every corner of the box projects inside
  /// an image of aspect `aspect` (w / h) with a 5 % margin.
  static Camera framing(const Vec3& lo, const Vec3& hi, const Vec3& view, const Vec3& up,
                        double aspect, double fov_y_deg = 30);
};

/// Colours of one mesh: a face's colour on the side its normal points to (front) and on
/// the other side (back).
struct MeshStyle {
  std::function<Rgb(Index face)> front;
  std::function<Rgb(Index face)> back;
};

/// Draws triangles into a colour image with a depth buffer.
class Rasterizer {
 public:
  /// A `width` × `height` canvas cleared to `background`.
  Rasterizer(int width, int height, const Camera& camera, Rgb background);

  /// Draws every face of a mesh, flat-shaded: the colour times (ambient + diffuse) from a
  /// light over the camera's shoulder, two-sided.
  void draw(const Positions& vertices, const FaceArray& faces, const MeshStyle& style);

  /// The colour image.
  const Image& image() const { return m_image; }

 private:
  void fill_triangle(const std::array<Eigen::Vector3d, 3>& screen, Rgb colour);

  Image m_image;
  std::vector<float> m_depth;  // 1 / view depth; larger is nearer; 0 is empty
  Camera m_camera;
  Vec3 m_forward, m_right, m_up;
  double m_focal = 1;  // pixels per unit at depth 1
  Vec3 m_light;
};

}  // namespace tailor
