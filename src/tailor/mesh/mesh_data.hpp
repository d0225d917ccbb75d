#pragma once
/// @file
/// A triangle mesh as read from or written to a file: positions and faces, no topology.

#include "tailor/geometry/types.hpp"

namespace tailor {

/// Vertex positions and triangle faces of a mesh file. Readers return only complete,
/// valid data: every face index is in range and no face repeats a vertex.
struct MeshData {
  Positions vertices;  ///< one row (x, y, z) per vertex
  FaceArray faces;     ///< one row of three 0-based vertex ids per triangle
};

}  // namespace tailor
