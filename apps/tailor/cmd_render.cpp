/// @file
/// `tailor render DIR`: PNG pictures of a `tailor simulate` output folder (render_NNNN.png
/// per frame, contact_sheet.png), candidate triangles in red.

#include <fmt/format.h>

#include <memory>
#include <string>

#include "command.hpp"
#include "tailor/render/run_renderer.hpp"

namespace tailor::cli {
namespace {

struct RenderOptions {
  std::string directory;
  std::string out;
  int width = 640, height = 480;
  bool sheet_only = false;
};

int run_render(const RenderOptions& o) {
  RenderSettings settings;
  settings.width = o.width;
  settings.height = o.height;
  const RenderRunResult result = render_run(o.directory, o.out, settings, !o.sheet_only);
  const std::string where = o.out.empty() ? o.directory : o.out;
  if (!o.sheet_only) {
    fmt::print("rendered {} frames to {}/render_NNNN.png\n", result.frames, where);
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
      return [o] { return run_render(*o); };
    }};

}  // namespace
}  // namespace tailor::cli
