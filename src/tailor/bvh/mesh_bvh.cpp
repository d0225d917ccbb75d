#include "tailor/bvh/mesh_bvh.hpp"

#include <tbb/parallel_for.h>

#include <numeric>

namespace tailor {

MeshBvh::MeshBvh(const TriangleMesh& mesh, const Positions& x_build, std::vector<Index> faces)
    : m_mesh(&mesh), m_faces(std::move(faces)) {
  if (m_faces.empty()) {
    m_faces.resize(mesh.num_faces());
    std::iota(m_faces.begin(), m_faces.end(), 0);
  }
  m_primitive_boxes.resize(m_faces.size());
  refit(x_build, x_build, false);
  m_tree = Bvh(m_primitive_boxes);
  m_cones.assign(m_tree.num_nodes(), NormalCone::wide());
}

void MeshBvh::refit(const Positions& x0, const Positions& x1, bool with_cones) {
  const FaceArray& faces = m_mesh->faces();
  const Index n = static_cast<Index>(m_faces.size());
  tbb::parallel_for(tbb::blocked_range<Index>(0, n, 1024), [&](const auto& range) {
    for (Index p = range.begin(); p < range.end(); ++p) {
      const auto v = faces.row(m_faces[p]);
      m_primitive_boxes[p] = swept_box(x0, x1, {v[0], v[1], v[2]});
    }
  });
  if (m_tree.empty()) return;
  m_tree.refit(m_primitive_boxes);
  if (!with_cones) return;
  m_tree.for_each_node_bottom_up([&](Index node) {
    if (m_tree.is_leaf(node)) {
      const auto v = faces.row(m_faces[m_tree.primitive(node)]);
      m_cones[node] = continuous_normal_cone(x0.row(v[0]), x0.row(v[1]), x0.row(v[2]), x1.row(v[0]),
                                             x1.row(v[1]), x1.row(v[2]));
    } else {
      m_cones[node] = m_cones[m_tree.left(node)].merged(m_cones[m_tree.right(node)]);
    }
  });
}

}  // namespace tailor
