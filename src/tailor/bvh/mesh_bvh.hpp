#pragma once
/// @file
/// The BVH of a deforming triangle mesh: swept face boxes and continuous normal cones.

#include <vector>

#include "tailor/bvh/bvh.hpp"
#include "tailor/bvh/normal_cone.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// A BVH over a subset of the faces of a mesh (all of them by default), built once on
/// one frame and refitted every step with swept boxes (box of x0 and x1) and continuous
/// normal cones merged upward. Primitive ids of the tree index `faces()`.
class MeshBvh {
 public:
  MeshBvh() = default;
  /// Builds over `faces` (mesh face ids), or over every face when `faces` is empty.
  MeshBvh(const TriangleMesh& mesh, const Positions& x_build, std::vector<Index> faces = {});

  /// Refits boxes (and cones when `with_cones`) to the step from `x0` to `x1` (parallel).
  void refit(const Positions& x0, const Positions& x1, bool with_cones);

  const Bvh& tree() const { return m_tree; }
  /// Mesh face id of tree primitive `p`.
  Index face(Index p) const { return m_faces[p]; }
  const std::vector<Index>& faces() const { return m_faces; }
  /// Continuous normal cone of a node (valid after refit with cones).
  const NormalCone& cone(Index node) const { return m_cones[node]; }
  /// Swept box of tree primitive `p` (valid after refit).
  const Aabb& primitive_box(Index p) const { return m_primitive_boxes[p]; }

 private:
  const TriangleMesh* m_mesh = nullptr;
  std::vector<Index> m_faces;
  Bvh m_tree;
  std::vector<Aabb> m_primitive_boxes;
  std::vector<NormalCone> m_cones;
};

}  // namespace tailor
