#pragma once
/// @file
/// A small z-buffered triangle rasteriser with a perspective camera and two-sided Lambert
/// shading, flat or smooth (per-pixel interpolated crease-aware corner normals).

#include <array>
#include <functional>
#include <vector>

#include "tailor/geometry/types.hpp"
#include "tailor/render/image.hpp"

namespace tailor {

/// A pinhole camera looking from `eye` at `target`.
struct Camera {
  Vec3 eye{0, 0, 1};           ///< where the camera is
  Vec3 target = Vec3::Zero();  ///< the point at the image's centre
  Vec3 up = Vec3::UnitY();     ///< the direction that appears up (projected)
  double fov_y_deg = 30;       ///< vertical field of view

  /// A camera looking at the centre of the box [lo, hi] from direction `view` (from the
  /// target towards the eye), just far enough that every corner of the box projects inside
  /// an image of aspect `aspect` (w / h) with a 5 % margin.
  static Camera framing(const Vec3& lo, const Vec3& hi, const Vec3& view, const Vec3& up,
                        double aspect, double fov_y_deg = 30);
};

/// Colours of one mesh: a face's colour on the side its normal points to (front) and on
/// the other side (back).
struct MeshStyle {
  std::function<Rgb(Index face)> front;  ///< colour of a face seen from its normal's side
  std::function<Rgb(Index face)> back;   ///< colour of a face seen from behind
};

/// How a mesh's faces are shaded.
enum class Shading {
  flat,    ///< one normal per face: facets show
  smooth,  ///< per-pixel normals interpolated from crease-aware corner normals
};

/// How to shade one mesh.
struct ShadingOptions {
  Shading shading = Shading::smooth;  ///< flat or smooth
  /// Smooth shading averages normals only across faces meeting at less than this angle
  /// (degrees; see corner_normals), so folds sharper than it stay creased.
  double crease_angle_deg = 60;
};

/// Draws triangles into a colour image with a depth buffer.
class Rasterizer {
 public:
  /// A `width` × `height` canvas cleared to `background`.
  Rasterizer(int width, int height, const Camera& camera, Rgb background);

  /// Share of a colour that every lit pixel keeps, whatever its normal.
  static constexpr double kAmbient = 0.35;
  /// Share that a pixel whose normal points at the light adds.
  static constexpr double kDiffuse = 0.65;

  /// Draws every face of a mesh, two-sided: a pixel gets its face's colour (front or back,
  /// by the side of the face the camera sees) times kAmbient + kDiffuse · max(0, n · light),
  /// with n the face normal (flat) or the interpolated corner normal (smooth), turned
  /// towards the camera's side of the face.
  void draw(const Positions& vertices, const FaceArray& faces, const MeshStyle& style,
            const ShadingOptions& shading = {});

  /// The colour image.
  const Image& image() const { return m_image; }
  /// The unit direction towards the light (above the camera's left shoulder).
  const Vec3& light() const { return m_light; }

 private:
  /// A face on screen: pixel x, pixel y, 1 / view depth per corner, and the unit normal
  /// per corner (already on the side the camera sees).
  struct ScreenTriangle {
    std::array<Eigen::Vector3d, 3> corner;
    std::array<Vec3, 3> normal;
  };
  void fill_triangle(const ScreenTriangle& triangle, Rgb colour);

  Image m_image;
  std::vector<float> m_depth;  // 1 / view depth; larger is nearer; 0 is empty
  Camera m_camera;
  Vec3 m_forward, m_right, m_up;
  double m_focal = 1;  // pixels per unit at depth 1
  Vec3 m_light;
};

}  // namespace tailor
