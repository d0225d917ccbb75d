#pragma once
/// @file
/// Vertex normals for smooth shading that keep creases: each corner of a face gets its own
/// normal, averaged only over the faces around its vertex that meet it at less than a crease
/// angle, so a gently curved sheet shades smoothly while a sharp fold, a face whose
/// orientation is flipped against its neighbour, and the corners of open boundaries keep their
/// edge.

#include "tailor/geometry/types.hpp"

namespace tailor {

/// One unit normal per face corner: row 3 f + k is corner k of face f. A degenerate face
/// (zero area) gets zero normals at its corners and contributes to no other corner.
using CornerNormals = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// The crease-aware corner normals of a mesh: the normal of corner (f, v) is the sum of
/// the area-weighted normals of the faces g around vertex v whose unit normal n_g has
/// n_g · n_f ≥ cos(`crease_angle_deg`), normalised. A crease angle of 0 gives flat shading
/// (each corner keeps its face's normal); 180 averages every face around a vertex.
CornerNormals corner_normals(const Positions& vertices, const FaceArray& faces,
                             double crease_angle_deg = 60);

}  // namespace tailor
