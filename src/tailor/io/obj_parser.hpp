#pragma once
/// @file
/// The OBJ text parser behind read_obj() and the frame readers (obj_frames.hpp).

#include <cstddef>
#include <filesystem>
#include <string_view>

#include "tailor/mesh/mesh_data.hpp"

namespace tailor {

struct ObjFaceText;

/// What parse_obj_text() found, beyond the mesh.
struct ObjParseResult {
  MeshData mesh;  ///< the vertices and triangles (polygons split into fans)
  /// Offset of the text after the last `v` line when every face is in that text
  /// (std::string_view::npos when some face comes before a vertex line).
  std::size_t face_text_start = std::string_view::npos;
  std::size_t num_polygons = 0;  ///< faces of more than 3 vertices (split into fans)
};

/// Parses OBJ text as read_obj() documents it; `source` names it in errors. With `known`
/// (the face text of an earlier frame, see obj_frames.hpp): once `known->num_vertices`
/// vertices and no face have been read, a rest of the text equal to `known->bytes` byte for
/// byte is not parsed but taken as `known->faces`. Parsing it would give the same faces and
/// no error, since the parser's state there (vertex count, no face) is the one `known`'s
/// own parse had; any other text is parsed in full.
ObjParseResult parse_obj_text(std::string_view text, const std::filesystem::path& source,
                              const ObjFaceText* known = nullptr);

}  // namespace tailor
