/// @file
/// Crease-aware corner normals through a vertex-to-face incidence table.

#include "tailor/render/corner_normals.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace tailor {

CornerNormals corner_normals(const Positions& vertices, const FaceArray& faces,
                             double crease_angle_deg) {
  const Eigen::Index num_faces = faces.rows();
  // Area-weighted (cross product) and unit normal of every face.
  Positions weighted(num_faces, 3), unit(num_faces, 3);
  for (Eigen::Index f = 0; f < num_faces; ++f) {
    const Vec3 a = position(vertices, faces(f, 0));
    const Vec3 n = (position(vertices, faces(f, 1)) - a).cross(position(vertices, faces(f, 2)) - a);
    const double length = n.norm();
    weighted.row(f) = n.transpose();
    const Vec3 direction = length > 0 ? Vec3(n / length) : Vec3::Zero();
    unit.row(f) = direction.transpose();
  }
  // Faces around each vertex, compressed rows.
  std::vector<Index> start(static_cast<std::size_t>(vertices.rows()) + 1, 0);
  for (Eigen::Index f = 0; f < num_faces; ++f) {
    for (int k = 0; k < 3; ++k) ++start[static_cast<std::size_t>(faces(f, k)) + 1];
  }
  for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<Index> around(static_cast<std::size_t>(start.back()));
  std::vector<Index> fill(start.begin(), start.end() - 1);
  for (Eigen::Index f = 0; f < num_faces; ++f) {
    for (int k = 0; k < 3; ++k)
      around[static_cast<std::size_t>(fill[static_cast<std::size_t>(faces(f, k))]++)] =
          static_cast<Index>(f);
  }

  const double min_cosine = std::cos(crease_angle_deg * std::numbers::pi / 180.0);
  CornerNormals normals = CornerNormals::Zero(3 * num_faces, 3);
  for (Eigen::Index f = 0; f < num_faces; ++f) {
    const Vec3 own = unit.row(f).transpose();
    if (own.isZero()) continue;
    for (int k = 0; k < 3; ++k) {
      const auto v = static_cast<std::size_t>(faces(f, k));
      Vec3 sum = Vec3::Zero();
      for (Index i = start[v]; i < start[v + 1]; ++i) {
        const Index g = around[static_cast<std::size_t>(i)];
        // The face itself always counts (even at a crease angle of 0, against rounding).
        if (g == f || unit.row(g).dot(own.transpose()) >= min_cosine)
          sum += weighted.row(g).transpose();
      }
      normals.row(3 * f + k) = sum.normalized().transpose();
    }
  }
  return normals;
}

}  // namespace tailor
