#pragma once
/// @file
/// Reading the OBJ frames of a sequence: a simulator writes every frame's faces the same
/// way, so a later frame's text after its vertices is usually the first frame's, byte for
/// byte. Such a frame's faces are compared (one memcmp) instead of parsed again.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "tailor/geometry/types.hpp"
#include "tailor/mesh/mesh_data.hpp"

namespace tailor {

/// An OBJ file's face text: the bytes after its last `v` line (its faces, and any comments
/// or groups among them), with what they parse to.
struct ObjFaceText {
  std::string bytes;             ///< the text after the last `v` line, to the end
  Index num_vertices = 0;        ///< the vertices before it (all of the file's)
  FaceArray faces;               ///< what `bytes` parses to (all of the file's faces)
  std::size_t num_polygons = 0;  ///< faces of more than 3 vertices among them
};

/// Reads a sequence's first OBJ frame as read_obj() does (same mesh, same errors) and keeps
/// its face text in `face_text`; std::nullopt when some face comes before the last vertex,
/// or the face text is much longer than its faces need (over 256 bytes a triangle: kept in
/// memory, it must stay small).
MeshData read_first_obj_frame(const std::filesystem::path& path,
                              std::optional<ObjFaceText>& face_text);

/// Reads a later OBJ frame: the same mesh and the same errors as read_obj(path). When the
/// file has `face_text.num_vertices` vertices and then `face_text.bytes`, its faces are
/// `face_text.faces` without being parsed; any other file is parsed in full.
MeshData read_obj_frame(const std::filesystem::path& path, const ObjFaceText& face_text);

}  // namespace tailor
