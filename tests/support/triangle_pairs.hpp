#pragma once
// Pairs of moving triangles for the tests of the CTP filters (plane sides, separating
// direction): pair i is faces 2i and 2i + 1 over vertices 6i to 6i + 5, and whether the
// exact CCD finds a collision in each of its fifteen vertex-face and edge-edge pairs.

#include <vector>

#include "tailor/ccd/ccd.hpp"
#include "tailor/culling/triangle_pair.hpp"
#include "tailor/geometry/types.hpp"

namespace tailor::testing {

struct TrianglePairs {
  FaceArray faces;
  Positions x0, x1;
  std::vector<TrianglePair> pairs;
};

inline Vec3 at(const Positions& x, Index v) {
  return x.row(v).transpose();
}

// Corner k of side `side` (0: pairs[i].first) of pair i in frame x.
inline Vec3 corner(const TrianglePairs& t, const Positions& x, std::size_t i, int side, int k) {
  const Index face = side == 0 ? t.pairs[i].first : t.pairs[i].second;
  return at(x, t.faces(face, k));
}

// Whether corner k of side `side` of pair i hits the other side's face during the step.
inline bool vertex_face_collides(const TrianglePairs& t, std::size_t i, int side, int k) {
  const int o = 1 - side;
  const auto c = [&](const Positions& x, int s, int j) { return corner(t, x, i, s, j); };
  return vertex_face_ccd({c(t.x0, side, k), c(t.x0, o, 0), c(t.x0, o, 1), c(t.x0, o, 2),
                          c(t.x1, side, k), c(t.x1, o, 0), c(t.x1, o, 1), c(t.x1, o, 2)})
      .hit;
}

// Whether edge a of the first face (corners a, a + 1) hits edge b of the second.
inline bool edge_edge_collides(const TrianglePairs& t, std::size_t i, int a, int b) {
  const int a1 = (a + 1) % 3, b1 = (b + 1) % 3;
  const auto c = [&](const Positions& x, int s, int j) { return corner(t, x, i, s, j); };
  return edge_edge_ccd({c(t.x0, 0, a), c(t.x0, 0, a1), c(t.x0, 1, b), c(t.x0, 1, b1), c(t.x1, 0, a),
                        c(t.x1, 0, a1), c(t.x1, 1, b), c(t.x1, 1, b1)})
      .hit;
}

}  // namespace tailor::testing
