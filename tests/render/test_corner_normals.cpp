/// @file
/// Crease-aware corner normals on meshes whose normals are known: a flat sheet, a gentle
/// and a sharp fold, a face with flipped orientation, a degenerate face.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tailor/render/corner_normals.hpp"

namespace tailor {
namespace {

/// A roof along the y axis: two faces per side, the ridge (vertices 2, 3) at x = 0, z = 0,
/// each side sloping down by `tilt_deg` towards x = ∓1. Faces face +z.
void roof(double tilt_deg, Positions& x, FaceArray& f) {
  const double drop = std::tan(tilt_deg * std::numbers::pi / 180.0);
  x.resize(6, 3);
  x << -1, -1, -drop, -1, 1, -drop, 0, -1, 0, 0, 1, 0, 1, -1, -drop, 1, 1, -drop;
  f.resize(4, 3);
  f << 0, 2, 3, 0, 3, 1, 2, 4, 5, 2, 5, 3;
}

Vec3 corner(const CornerNormals& n, Index face, int k) {
  return n.row(3 * face + k).transpose();
}

TEST(CornerNormals, FlatSheetHasTheSheetNormalEverywhere) {
  Positions x;
  FaceArray f;
  roof(0, x, f);
  const CornerNormals n = corner_normals(x, f);
  ASSERT_EQ(n.rows(), 12);
  for (Eigen::Index r = 0; r < n.rows(); ++r) {
    EXPECT_NEAR((n.row(r).transpose() - Vec3::UnitZ()).norm(), 0, 1e-15) << r;
  }
}

TEST(CornerNormals, GentleFoldIsAveragedOnTheRidgeOnly) {
  Positions x;
  FaceArray f;
  roof(15, x, f);
  const double s = std::sin(15 * std::numbers::pi / 180), c = std::cos(15 * std::numbers::pi / 180);
  const Vec3 left(-s, 0, c), right(s, 0, c);
  const CornerNormals n = corner_normals(x, f, 60);
  // Ridge vertex 2 is in one left face (0) and two right faces (2, 3), all of equal area:
  // the area-weighted sum is left + 2 right; ridge vertex 3 (faces 0, 1, 3) is 2 left + right.
  const Vec3 at_2 = (left + 2 * right).normalized(), at_3 = (2 * left + right).normalized();
  EXPECT_NEAR((corner(n, 0, 1) - at_2).norm(), 0, 1e-12);
  EXPECT_NEAR((corner(n, 2, 0) - at_2).norm(), 0, 1e-12);
  EXPECT_NEAR((corner(n, 0, 2) - at_3).norm(), 0, 1e-12);
  EXPECT_NEAR((corner(n, 3, 2) - at_3).norm(), 0, 1e-12);
  // Outer corners see only their own side.
  EXPECT_NEAR((corner(n, 0, 0) - left).norm(), 0, 1e-12);
  EXPECT_NEAR((corner(n, 2, 1) - right).norm(), 0, 1e-12);
}

TEST(CornerNormals, SharpFoldKeepsItsCreaseUnlessTheCreaseAngleIsWider) {
  Positions x;
  FaceArray f;
  roof(50, x, f);  // the sides' normals are 100 degrees apart
  const double s = std::sin(50 * std::numbers::pi / 180), c = std::cos(50 * std::numbers::pi / 180);
  const Vec3 left(-s, 0, c), right(s, 0, c);
  const CornerNormals creased = corner_normals(x, f, 60);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR((corner(creased, 0, k) - left).norm(), 0, 1e-12) << k;
    EXPECT_NEAR((corner(creased, 3, k) - right).norm(), 0, 1e-12) << k;
  }
  const CornerNormals smooth = corner_normals(x, f, 120);
  EXPECT_NEAR((corner(smooth, 0, 2) - (2 * left + right).normalized()).norm(), 0, 1e-12);
  // A crease angle of 0 is flat shading, even on the flat sheet's coplanar faces.
  const CornerNormals flat = corner_normals(x, f, 0);
  EXPECT_NEAR((corner(flat, 0, 2) - left).norm(), 0, 1e-12);
}

TEST(CornerNormals, FlippedAndDegenerateFacesDoNotBleedIntoTheirNeighbours) {
  Positions x;
  FaceArray f;
  roof(0, x, f);
  f.row(3) << 2, 3, 5;  // orientation flipped: its normal is -z
  CornerNormals n = corner_normals(x, f, 60);
  EXPECT_NEAR((corner(n, 2, 0) - Vec3::UnitZ()).norm(), 0, 1e-15);
  EXPECT_NEAR((corner(n, 3, 0) + Vec3::UnitZ()).norm(), 0, 1e-15);
  // A zero-area face (all three corners on one line) gets zero normals and changes nothing.
  x.conservativeResize(7, 3);
  x.row(6) << 0.5, -1, 0;
  f.conservativeResize(5, 3);
  f.row(3) << 2, 5, 3;
  f.row(4) << 2, 6, 4;
  n = corner_normals(x, f, 60);
  EXPECT_TRUE(corner(n, 4, 0).isZero());
  EXPECT_NEAR((corner(n, 2, 0) - Vec3::UnitZ()).norm(), 0, 1e-15);
}

}  // namespace
}  // namespace tailor
