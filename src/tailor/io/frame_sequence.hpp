#pragma once
/// @file
/// A sequence of mesh frames (same connectivity, moving vertices) read one at a time.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tailor/geometry/types.hpp"
#include "tailor/io/obj_frames.hpp"
#include "tailor/mesh/mesh_data.hpp"

namespace tailor {

/// Lists the frame files named by `folder_or_pattern`:
/// - a folder: every `.obj`/`.ply` file in it (any case), in natural order
///   (sort_frame_files: by the number in the file name, names without a number last);
/// - a printf pattern such as `frames/%d.ply` or `out/cloth_%04d.obj` (one `%d`, `%i` or
///   `%u` with an optional `0` flag and width; `%%` is a literal `%`): indices from the
///   first existing one of 0 and 1, up to the first missing file;
/// - a glob such as `out/cloth_*.obj` (see expand_frame_glob): the matching mesh files, in
///   the same order as a folder's.
/// Throws InputError if nothing matches or the argument is none of these.
std::vector<std::filesystem::path> list_frame_files(const std::filesystem::path& folder_or_pattern);

/// Frames of one animated mesh. Reads the first frame at construction; every other frame
/// is read only when asked for, so long sequences never sit in memory. OBJ frames whose
/// faces are written as in the first frame are read without parsing the faces again
/// (obj_frames.hpp).
class FrameSequence {
 public:
  /// Lists the frames (see list_frame_files) and reads the first one.
  explicit FrameSequence(const std::filesystem::path& folder_or_pattern);
  /// Uses the given frame files (at least one) and reads the first one.
  explicit FrameSequence(std::vector<std::filesystem::path> paths);

  /// Number of frames.
  Index num_frames() const { return static_cast<Index>(m_paths.size()); }
  /// All frame files, in order.
  const std::vector<std::filesystem::path>& paths() const { return m_paths; }
  /// The file of frame `i`.
  const std::filesystem::path& path(Index i) const {
    return m_paths.at(static_cast<std::size_t>(i));
  }
  /// Vertex count shared by every frame.
  Index num_vertices() const { return static_cast<Index>(m_first.vertices.rows()); }
  /// Faces shared by every frame (those of the first frame).
  const FaceArray& faces() const { return m_first.faces; }
  /// The first frame (positions and faces).
  const MeshData& first_frame() const { return m_first; }

  /// Reads frame `i` and returns its positions. Throws InputError naming the frame file
  /// if it cannot be read, or if its vertex count or faces differ from the first frame.
  /// Safe to call from several threads at once.
  Positions load(Index i) const;

 private:
  std::vector<std::filesystem::path> m_paths;
  MeshData m_first;
  std::optional<ObjFaceText> m_obj_face_text;  // the first frame's, if an OBJ file
};

}  // namespace tailor
