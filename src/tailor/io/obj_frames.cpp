/// @file
/// The first OBJ frame's face text kept; later frames compared against it while parsed.

#include "tailor/io/obj_frames.hpp"

#include <string_view>

#include "tailor/io/input_file.hpp"
#include "tailor/io/obj_parser.hpp"

namespace tailor {
namespace {

/// Most face-text bytes kept per triangle, beyond a fixed allowance: a face line takes
/// 10 to 60 bytes; more means comments or other statements, not worth keeping.
constexpr std::size_t kMaxFaceTextBytesPerFace = 256;
constexpr std::size_t kFaceTextAllowance = std::size_t{64} << 10;

}  // namespace

MeshData read_first_obj_frame(const std::filesystem::path& path,
                              std::optional<ObjFaceText>& face_text) {
  const InputFile file(path);
  ObjParseResult parsed = parse_obj_text(file.bytes(), path);
  face_text.reset();
  const std::size_t start = parsed.face_text_start;
  const std::size_t max_bytes =
      kFaceTextAllowance +
      kMaxFaceTextBytesPerFace * static_cast<std::size_t>(parsed.mesh.faces.rows());
  if (start != std::string_view::npos && file.size() - start <= max_bytes) {
    face_text.emplace();
    face_text->bytes = std::string(file.bytes().substr(start));
    face_text->num_vertices = static_cast<Index>(parsed.mesh.vertices.rows());
    face_text->faces = parsed.mesh.faces;
    face_text->num_polygons = parsed.num_polygons;
  }
  return std::move(parsed.mesh);
}

MeshData read_obj_frame(const std::filesystem::path& path, const ObjFaceText& face_text) {
  const InputFile file(path);
  return parse_obj_text(file.bytes(), path, &face_text).mesh;
}

}  // namespace tailor
