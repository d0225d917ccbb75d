#pragma once
/// @file
/// Pictures of the arm-sleeve simulation: one frame (arm and cloth shaded, the cloth
/// triangles that were in candidate triangle pairs in red, as in the paper's Fig. 1) and
/// a contact sheet of several frames.

#include <vector>

#include "tailor/geometry/types.hpp"
#include "tailor/render/image.hpp"
#include "tailor/render/rasterizer.hpp"

namespace tailor {

/// Colours and size of the pictures.
struct RenderSettings {
  int width = 1280;                 ///< output width in pixels
  int height = 720;                 ///< output height in pixels
  int supersample = 2;              ///< anti-aliasing: rendered at this factor, then box-filtered
  ShadingOptions shading;           ///< smooth (crease-aware) by default
  Vec3 view{0.25, 1.0, 0.65};       ///< from the scene towards the camera
  Vec3 up{0, 0, -1};                ///< image up (projected)
  Rgb background{245, 245, 242};    ///< where nothing is drawn
  Rgb arm{222, 178, 150};           ///< the arm's skin
  Rgb cloth_outside{70, 110, 170};  ///< the sleeve's outer side (where face normals point)
  Rgb cloth_inside{150, 170, 200};  ///< the sleeve's inner side
  Rgb candidate{215, 30, 30};       ///< faces in a candidate triangle pair
};

/// What one picture shows. Arm and cloth are optional (null: not drawn).
struct FrameView {
  const Positions* arm = nullptr;          ///< the arm's vertices (null: no arm)
  const FaceArray* arm_faces = nullptr;    ///< the arm's faces
  const Positions* cloth = nullptr;        ///< the cloth's vertices (null: no cloth)
  const FaceArray* cloth_faces = nullptr;  ///< the cloth's faces
  /// Cloth faces drawn in the candidate colour (ids out of range are ignored).
  std::vector<Index> highlighted_faces;
};

/// The camera of every picture of a run: looking at the box [lo, hi] along settings.view.
Camera frame_camera(const Vec3& lo, const Vec3& hi, const RenderSettings& settings);

/// Renders one frame.
Image render_frame(const FrameView& view, const Camera& camera, const RenderSettings& settings);

/// A grid of thumbnails of evenly spaced frames of a run of `frames` frames (0 .. frames):
/// call wants() for each frame, add() the ones it wants, then compose().
class ContactSheet {
 public:
  /// At most `columns` × `rows` thumbnails, each `thumb_width` pixels wide.
  ContactSheet(int frames, int columns = 4, int rows = 3, int thumb_width = 320);
  /// Whether frame `frame` is one of the sheet's.
  bool wants(int frame) const;
  /// Adds a frame's picture (scaled to the thumbnail size); frames it does not want are
  /// ignored.
  void add(int frame, const Image& picture);
  /// The sheet: thumbnails in frame order, left to right, top to bottom, each labelled
  /// with its frame number.
  Image compose() const;
  /// The frames the sheet shows.
  const std::vector<int>& frames() const { return m_frames; }

 private:
  int m_columns, m_rows, m_thumb_width;
  std::vector<int> m_frames;
  std::vector<Image> m_thumbs;  // per m_frames entry (empty until added)
};

/// Draws `number` with a 3×5 pixel digit font scaled by `scale` at (x, y) (top left).
void draw_number(Image& image, int number, int x, int y, int scale, Rgb colour);

}  // namespace tailor
