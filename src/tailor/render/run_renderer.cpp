/// @file
/// Rendering a simulation run, on the fly or from its output folder.

#include "tailor/render/run_renderer.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <limits>
#include <optional>

#include "tailor/geometry/error.hpp"
#include "tailor/io/file_bytes.hpp"
#include "tailor/io/obj_io.hpp"
#include "tailor/sim/frame_writer.hpp"

namespace tailor {
namespace {

/// Grows [lo, hi] to hold every row of `x`.
void extend(const Positions& x, Vec3& lo, Vec3& hi) {
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    lo = lo.cwiseMin(x.row(i).transpose());
    hi = hi.cwiseMax(x.row(i).transpose());
  }
}

/// A frame's mesh, checked against the first frame's connectivity when given.
MeshData read_frame_mesh(const std::filesystem::path& path, const MeshData* first) {
  MeshData mesh = read_obj(path);
  if (first != nullptr && (mesh.vertices.rows() != first->vertices.rows() ||
                           mesh.faces.rows() != first->faces.rows())) {
    throw InputError(fmt::format("{}: {} vertices and {} faces, the first frame has {} and {}",
                                 path.string(), mesh.vertices.rows(), mesh.faces.rows(),
                                 first->vertices.rows(), first->faces.rows()));
  }
  return mesh;
}

}  // namespace

RunRenderer::RunRenderer(std::filesystem::path directory, const Vec3& lo, const Vec3& hi,
                         int frames, RenderSettings settings)
    : m_directory(std::move(directory)),
      m_settings(settings),
      m_camera(frame_camera(lo, hi, settings)),
      m_sheet(frames) {
  std::error_code ec;
  std::filesystem::create_directories(m_directory, ec);
  if (ec || !std::filesystem::is_directory(m_directory)) {
    throw InputError(fmt::format("cannot create output folder '{}'", m_directory.string()));
  }
}

void RunRenderer::add_frame(int frame, const FrameView& view) {
  if (!m_write_frames && !m_sheet.wants(frame)) return;
  const Image picture = render_frame(view, m_camera, m_settings);
  if (m_write_frames) {
    write_png(m_directory / frame_file_name("render", frame, ".png"), picture);
  }
  m_sheet.add(frame, picture);
}

std::filesystem::path RunRenderer::finish() {
  const std::filesystem::path path = m_directory / "contact_sheet.png";
  write_png(path, m_sheet.compose());
  return path;
}

std::vector<Index> read_candidate_triangles(const std::filesystem::path& file, Index num_faces) {
  if (!std::filesystem::exists(file)) return {};
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_file_bytes(file));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: malformed JSON: {}", file.string(), e.what()));
  }
  const auto it = j.is_object() ? j.find("candidate_triangles") : j.end();
  if (it == j.end() || !it->is_array()) {
    throw InputError(fmt::format("{}: no array 'candidate_triangles'", file.string()));
  }
  std::vector<Index> faces;
  faces.reserve(it->size());
  for (const auto& value : *it) {
    if (!value.is_number_integer() || value.get<std::int64_t>() < 0 ||
        value.get<std::int64_t>() >= num_faces) {
      throw InputError(fmt::format("{}: candidate triangle {} is not a face id in [0, {})",
                                   file.string(), value.dump(), num_faces));
    }
    faces.push_back(value.get<Index>());
  }
  return faces;
}

RenderRunResult render_run(const std::filesystem::path& directory, const std::filesystem::path& out,
                           RenderSettings settings, bool write_frames) {
  const auto cloth_path = [&](int f) { return directory / frame_file_name("cloth", f); };
  const auto arm_path = [&](int f) { return directory / frame_file_name("arm", f); };
  if (!std::filesystem::is_directory(directory)) {
    throw InputError(fmt::format("'{}' is not a folder", directory.string()));
  }
  if (!std::filesystem::exists(cloth_path(0))) {
    throw InputError(fmt::format("'{}' has no {} (not a `tailor simulate` output folder)",
                                 directory.string(), frame_file_name("cloth", 0)));
  }
  int last = 0;
  while (std::filesystem::exists(cloth_path(last + 1))) ++last;

  // The camera frames every arm position and the first cloth frame.
  const MeshData cloth0 = read_frame_mesh(cloth_path(0), nullptr);
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  extend(cloth0.vertices, lo, hi);
  std::optional<MeshData> arm0;
  for (int f = 0; f <= last; ++f) {
    if (!std::filesystem::exists(arm_path(f))) continue;
    MeshData arm = read_frame_mesh(arm_path(f), arm0 ? &*arm0 : nullptr);
    extend(arm.vertices, lo, hi);
    if (!arm0) arm0 = std::move(arm);
  }

  RunRenderer renderer(out.empty() ? directory : out, lo, hi, last, settings);
  renderer.set_write_frames(write_frames);
  const Index num_faces = static_cast<Index>(cloth0.faces.rows());
  for (int f = 0; f <= last; ++f) {
    const MeshData cloth = f == 0 ? cloth0 : read_frame_mesh(cloth_path(f), &cloth0);
    std::optional<MeshData> arm;
    if (arm0 && std::filesystem::exists(arm_path(f))) arm = read_frame_mesh(arm_path(f), &*arm0);
    FrameView view;
    view.cloth = &cloth.vertices;
    view.cloth_faces = &cloth.faces;
    if (arm) {
      view.arm = &arm->vertices;
      view.arm_faces = &arm->faces;
    }
    view.highlighted_faces =
        read_candidate_triangles(directory / frame_file_name("contacts", f, ".json"), num_faces);
    renderer.add_frame(f, view);
  }
  RenderRunResult result;
  result.frames = last + 1;
  result.sheet = renderer.finish();
  return result;
}

}  // namespace tailor
