#pragma once
/// @file
/// The contact data `tailor view` overlays on a frame: the cloth faces in candidate
/// triangle pairs, the vertex-face and edge-edge collisions with their times of impact,
/// and the radial-view observers. Read from `contacts_NNNN.json` / `clusters.json` (the
/// per-frame contact files of `tailor simulate`, format in docs/viewer.md) or made from
/// the JSON of `tailor detect`.

#include <filesystem>
#include <vector>

#include "tailor/culling/triangle_pair.hpp"
#include "tailor/geometry/types.hpp"

namespace tailor::cli {

/// A vertex touching a face at time `toi` (in [0, 1]) of substep `substep` of the frame.
struct ContactVertexFace {
  Index vertex = -1, face = -1;
  int substep = 0;
  double toi = 0.0;
};

/// Edges (a0, a1) and (b0, b1), as vertex ids, touching at `toi` of substep `substep`.
struct ContactEdgeEdge {
  Index a0 = -1, a1 = -1, b0 = -1, b1 = -1;
  int substep = 0;
  double toi = 0.0;
};

/// The contacts of the step that ends at one frame.
struct FrameContacts {
  std::vector<Index> candidate_triangles;  ///< sorted unique cloth face ids
  std::vector<ContactVertexFace> vertex_face;
  std::vector<ContactEdgeEdge> edge_edge;
  std::vector<Vec3> observers;  ///< radial-view observer positions at the end of the frame
  int substeps = 1;             ///< substeps of the frame (a detect step has one)
};

/// Reads `contacts_NNNN.json` of frame `frame` for a cloth of `num_vertices` vertices and
/// `num_faces` faces. Throws InputError naming the file and the entry on a malformed
/// file, a frame number other than `frame`, an id out of range, a substep outside
/// [0, substeps), a time of impact outside [0, 1] or a non-finite observer. Unknown
/// fields are ignored (the format may grow).
FrameContacts read_frame_contacts(const std::filesystem::path& path, int frame, Index num_vertices,
                                  Index num_faces);

/// Reads `clusters.json`: the radial-view cluster id (>= 0) of each of `num_faces` faces.
/// Throws InputError naming the file if the list is malformed or of the wrong length.
std::vector<Index> read_face_clusters(const std::filesystem::path& path, Index num_faces);

/// Sorted unique face ids of the candidate triangle pairs.
std::vector<Index> unique_faces_of_pairs(const std::vector<TrianglePair>& pairs);

}  // namespace tailor::cli
