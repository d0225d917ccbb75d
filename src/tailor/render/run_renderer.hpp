#pragma once
/// @file
/// Pictures of a whole simulation run: `render_NNNN.png` per frame and `contact_sheet.png`,
/// either on the fly (RunRenderer, used by `tailor simulate --render`) or from the folder
/// `tailor simulate` wrote (render_run, used by `tailor render`).

#include <filesystem>
#include <vector>

#include "tailor/render/frame_renderer.hpp"

namespace tailor {

/// Renders the frames of one run into a folder and collects its contact sheet.
class RunRenderer {
 public:
  /// Pictures of frames 0 .. `frames` go to `directory` (created if needed), all with
  /// the camera framing the box [lo, hi].
  RunRenderer(std::filesystem::path directory, const Vec3& lo, const Vec3& hi, int frames,
              RenderSettings settings = {});
  /// Renders frame `frame` to `render_NNNN.png` (if `write_frames`) and keeps it for the
  /// sheet when the sheet shows it.
  void add_frame(int frame, const FrameView& view);
  /// Writes `contact_sheet.png`; returns its path.
  std::filesystem::path finish();
  /// Whether per-frame pictures are written (default true).
  void set_write_frames(bool write) { m_write_frames = write; }

 private:
  std::filesystem::path m_directory;
  RenderSettings m_settings;
  Camera m_camera;
  ContactSheet m_sheet;
  bool m_write_frames = true;
};

/// What render_run did.
struct RenderRunResult {
  int frames = 0;               ///< frames rendered
  std::filesystem::path sheet;  ///< the contact sheet written
};

/// Candidate triangles of one `contacts_NNNN.json` file (its "candidate_triangles"); an
/// empty list when the file does not exist. Throws InputError naming the file when it is
/// not valid JSON, lacks the field, or holds an id outside [0, num_faces).
std::vector<Index> read_candidate_triangles(const std::filesystem::path& file, Index num_faces);

/// Renders every frame of a `tailor simulate` output folder (cloth_NNNN.obj from 0 on,
/// arm_NNNN.obj and contacts_NNNN.json when present) into `out` (the same folder when
/// empty). The camera frames all arm positions of the run and the first cloth frame.
/// Throws InputError naming the folder when it has no cloth_0000.obj, or naming a file
/// that is malformed or does not match the first frame's connectivity.
RenderRunResult render_run(const std::filesystem::path& directory,
                           const std::filesystem::path& out = {}, RenderSettings settings = {},
                           bool write_frames = true);

}  // namespace tailor
