#pragma once
/// @file
/// Boxes of a mesh's edges and faces from the boxes of its vertices (swept or grown ones):
/// a feature's box is the union of its vertices' boxes.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <vector>

#include "tailor/bvh/aabb.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// Grows `edges[e]` and `faces[f]` (one box per edge and per face of `mesh`, usually empty
/// ones) to hold the boxes of their vertices, `vertices[v]` (Aabb or StepBox).
/// In parallel (each box is written by one task).
template <class Box>
void bound_edges_and_faces(const TriangleMesh& mesh, const std::vector<Box>& vertices,
                           std::vector<Box>& edges, std::vector<Box>& faces) {
  tbb::parallel_for(tbb::blocked_range<Index>(0, mesh.num_edges(), 4096), [&](const auto& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      edges[e].extend(vertices[mesh.edges()(e, 0)]);
      edges[e].extend(vertices[mesh.edges()(e, 1)]);
    }
  });
  tbb::parallel_for(tbb::blocked_range<Index>(0, mesh.num_faces(), 4096), [&](const auto& range) {
    for (Index f = range.begin(); f != range.end(); ++f) {
      for (int k = 0; k < 3; ++k) faces[f].extend(vertices[mesh.faces()(f, k)]);
    }
  });
}

}  // namespace tailor
