#pragma once
/// @file
/// Basic numeric types shared by every module.

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products everywhere
#include <array>
#include <cstdint>

namespace tailor {

/// Index of a vertex, edge or face.
using Index = std::int32_t;

/// A 3D point or vector.
using Vec3 = Eigen::Vector3d;
/// Four points at one instant: a vertex and a face's corners, or the ends of two edges;
/// the pair tests of a linear step take them at its start and at its end.
using FourPoints = std::array<Vec3, 4>;

/// Vertex positions, one row per vertex (docs/design.md §6).
using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// Triangle faces, one row of three vertex indices per face.
using FaceArray = Eigen::Matrix<Index, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// Edges, one row of two vertex indices per edge.
using EdgeArray = Eigen::Matrix<Index, Eigen::Dynamic, 2, Eigen::RowMajor>;

/// The position of vertex `i` (row `i` of `x`) as a column vector.
inline Vec3 position(const Positions& x, Index i) {
  return x.row(i).transpose();
}

}  // namespace tailor
