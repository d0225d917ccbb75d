/// @file
/// `tailor render DIR`: PNG pictures of a `tailor simulate` output folder (render_NNNN.png
/// per frame, contact_sheet.png, and animation.mp4 through ffmpeg), candidate triangles in
/// red.

#include <fmt/format.h>

#include <memory>
#include <string>

#include "command.hpp"
#include "tailor/render/animation.hpp"
#include "tailor/render/run_renderer.hpp"

namespace tailor::cli {
namespace {

struct RenderOptions {
  std::string directory;
  std::string out;
  int width = RenderSettings{}.width, height = RenderSettings{}.height;
  bool sheet_only = false;
  bool flat = false;
  bool animation = true;
  double fps = 30;
};

/// Writes animation.mp4 from the frames in `where` and says what happened.
void report_animation(const std::string& where, double fps) {
  const AnimationResult animation = write_animation(where, fps);
  if (animation.written) {
    fmt::print("animation: {} ({} frames at {} fps)\n", animation.path.string(), animation.frames,
               fps);
  } else {
    fmt::print("animation: not written: {}\n", animation.reason);
  }
}

int run_render(const RenderOptions& o) {
  RenderSettings settings;
  settings.width = o.width;
  settings.height = o.height;
  if (o.flat) settings.shading.shading = Shading::flat;
  const RenderRunResult result = render_run(o.directory, o.out, settings, !o.sheet_only);
  const std::string where = o.out.empty() ? o.directory : o.out;
  if (!o.sheet_only) {
    fmt::print("rendered {} frames to {}/render_NNNN.png\n", result.frames, where);
    if (o.animation) report_animation(where, o.fps);
  }
  fmt::print("contact sheet: {}\n", result.sheet.string());
  return kSuccess;
}

const CommandRegistration render_registration{
    "render", [](CLI::App& app) -> std::function<int()> {
      CLI::App* cmd = app.add_subcommand(
          "render", "PNG pictures of a `tailor simulate` folder (frames and a contact sheet)");
      auto o = std::make_shared<RenderOptions>();
      cmd->add_option("directory", o->directory, "Output folder of `tailor simulate`")->required();
      cmd->add_option("--out", o->out, "Where the PNGs go (default: the same folder)");
      cmd->add_option("--width", o->width, "Picture width in pixels")
          ->check(CLI::Range(16, 4096))
          ->capture_default_str();
      cmd->add_option("--height", o->height, "Picture height in pixels")
          ->check(CLI::Range(16, 4096))
          ->capture_default_str();
      cmd->add_flag("--sheet-only", o->sheet_only, "Write only contact_sheet.png");
      cmd->add_flag("--flat", o->flat, "Flat shading (facets show) instead of smooth");
      cmd->add_flag("!--no-animation", o->animation,
                    "Do not encode the frames into animation.mp4 (ffmpeg)");
      cmd->add_option("--fps", o->fps, "Frames per second of animation.mp4")
          ->check(CLI::Range(1.0, 1000.0))
          ->capture_default_str();
      return [o] { return run_render(*o); };
    }};

}  // namespace
}  // namespace tailor::cli
