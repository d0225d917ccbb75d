// The mesh BVH: its layout, float boxes that contain the swept triangles, and direction
// masks whose every direction makes an acute angle with every normal of every face below
// them over the whole step (checked in exact rational arithmetic at sampled times).

#include "support/sanitized.hpp"
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "support/random_steps.hpp"
#include "tailor/bvh/bvh_layout.hpp"
#include "tailor/bvh/float_box.hpp"
#include "tailor/bvh/mesh_bvh.hpp"
#include "tailor/mesh/procedural_steps.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

#include <tbb/task_arena.h>

namespace tailor {
namespace {

using tailor::testing::sanitized;

TEST(FloatBox, RoundsOutwardByAFewUlps) {
  const double values[] = {0.0,    -0.0,   1.0,   0.1,    -0.1,       1e-300, -1e-300, 1e300,
                           -1e300, 3.0e38, 1e-45, -1e-40, 123456.789, 0.5,    -0.25};
  constexpr float inf = std::numeric_limits<float>::infinity();
  for (double x : values) {
    const float low = float_at_most(x), high = float_at_least(x);
    EXPECT_LE(static_cast<double>(low), x) << x;
    EXPECT_GE(static_cast<double>(high), x) << x;
    // Close: three steps toward x pass it (or x is beyond the float range).
    float above = low, below = high;
    for (int i = 0; i < 3; ++i)
      above = std::nextafter(above, inf), below = std::nextafter(below, -inf);
    if (std::fabs(x) < 3.4e38) {
      EXPECT_GT(static_cast<double>(above), x) << x;
      EXPECT_LT(static_cast<double>(below), x) << x;
    }
  }
  EXPECT_EQ(float_at_most(1e300), std::numeric_limits<float>::max());
  EXPECT_EQ(float_at_least(1e300), inf);
  EXPECT_EQ(float_at_most(-1e300), -inf);
}

TEST(BvhLayout, IsAPreOrderTreeHoldingEveryPrimitiveOnce) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<Vec3> centers(1000);
  for (Vec3& c : centers) c = {uniform(rng), uniform(rng), uniform(rng)};
  const BvhLayout layout = build_median_split_layout(centers);
  ASSERT_EQ(layout.num_nodes(), 1999);
  EXPECT_EQ(layout.count[0], 1000);
  std::vector<int> seen(centers.size(), 0);
  for (Index node = 0; node < layout.num_nodes(); ++node) {
    if (layout.is_leaf(node)) {
      ++seen[layout.right[node]];
      continue;
    }
    const Index left = node + 1, right = layout.right[node];
    // The left subtree fills the ids up to the right child.
    EXPECT_EQ(right, left + 2 * layout.count[left] - 1);
    EXPECT_EQ(layout.count[node], layout.count[left] + layout.count[right]);
    EXPECT_GE(layout.count[left], layout.count[node] / 2);
  }
  for (int s : seen) EXPECT_EQ(s, 1);
}

// Faces under a node.
void faces_under(const MeshBvh& bvh, Index node, std::vector<Index>& out) {
  if (bvh.is_leaf(node)) {
    out.push_back(bvh.leaf_face(node));
    return;
  }
  faces_under(bvh, bvh.left(node), out);
  faces_under(bvh, bvh.right(node), out);
}

bool box_holds(const FloatBox& box, const Positions& x, Index v) {
  for (int k = 0; k < 3; ++k) {
    if (!(box.min[k] <= x(v, k) && x(v, k) <= box.max[k])) return false;
  }
  return true;
}

using Q3 = std::array<mpq_class, 3>;

Q3 exact_point(const Positions& x0, const Positions& x1, Index v, const mpq_class& t) {
  Q3 p;
  for (int k = 0; k < 3; ++k) p[k] = mpq_class(x0(v, k)) + t * (mpq_class(x1(v, k)) - x0(v, k));
  return p;
}

// Exact check that n(t)·d > 0 for the face's normal n(t) at t = k/8 and every direction d
// of `mask`.
::testing::AssertionResult mask_holds_face(DirectionMask mask, const TriangleMesh& mesh,
                                           const Positions& x0, const Positions& x1, Index f) {
  for (int step = 0; step <= 8; ++step) {
    const mpq_class t(step, 8);
    const Q3 a = exact_point(x0, x1, mesh.faces()(f, 0), t);
    const Q3 b = exact_point(x0, x1, mesh.faces()(f, 1), t);
    const Q3 c = exact_point(x0, x1, mesh.faces()(f, 2), t);
    Q3 u, v;
    for (int k = 0; k < 3; ++k) u[k] = b[k] - a[k], v[k] = c[k] - a[k];
    const Q3 n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    for (int bit = 0; bit < kMaskDirections; ++bit) {
      if (!(mask >> bit & 1)) continue;
      const Vec3 d = mask_direction(bit);
      const mpq_class dot = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
      if (dot <= 0) {
        return ::testing::AssertionFailure()
               << "face " << f << " at t=" << step << "/8, direction bit " << bit;
      }
    }
  }
  return ::testing::AssertionSuccess();
}

struct BvhCase {
  std::string name;
  MeshData mesh;
  Positions x1;
};

std::vector<BvhCase> bvh_cases() {
  std::vector<BvhCase> cases;
  // 16 also under the sanitizers: at 8 the crumpled steps leave no node flat enough for a
  // cone under 90 degrees, and the cone checks below would test nothing.
  const int resolution = 16;
  for (auto& step : testing::make_random_steps(5, resolution)) {
    cases.push_back({step.name, std::move(step.mesh), std::move(step.x1)});
  }
  // A flat patch that turns through 10 and 170 degrees during the step: its normals span
  // that angle. Within 90 degrees of all of them lie many mask directions for 10 degrees;
  // for 170 only directions within 5 degrees of the bisector do, and no mask direction is
  // among them.
  for (double degrees : {10.0, 170.0}) {
    BvhCase turning{
        "turn" + std::to_string(static_cast<int>(degrees)), make_grid(6, 6, 1.0, 1.0), {}};
    const double angle = degrees * std::numbers::pi / 180;
    turning.x1 = turning.mesh.vertices;
    for (Eigen::Index i = 0; i < turning.x1.rows(); ++i) {
      const double y = turning.mesh.vertices(i, 1);
      turning.x1(i, 1) = y * std::cos(angle);
      turning.x1(i, 2) = y * std::sin(angle);
    }
    cases.push_back(std::move(turning));
  }
  const ProceduralStep folded = make_folded_cloth_on_sphere(sanitized() ? 300 : 1200);
  cases.push_back({"folded", {folded.x0, folded.faces}, folded.x1});
  // A crumpling height field: every normal has a positive z during the step, so the root
  // holds +z however deep the tree (masks merge exactly).
  const ProceduralStep crumpling = make_crumpling_cloth_step(sanitized() ? 800 : 5000);
  cases.push_back({"crumpling", {crumpling.x0, crumpling.faces}, crumpling.x1});
  return cases;
}

TEST(MeshBvh, OneAndTwoFaceMeshesRefit) {
  // A lone face is a group without inner nodes (this once indexed an empty list).
  for (int faces : {1, 2}) {
    Positions x0(4, 3);
    x0 << 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0;
    FaceArray f(faces, 3);
    f.row(0) << 0, 1, 2;
    if (faces == 2) f.row(1) << 1, 3, 2;
    const TriangleMesh mesh(4, f);
    MeshBvh bvh(mesh, x0);
    const Positions x1 = x0.array() + 0.5;
    bvh.refit(x0, x1, true);
    ASSERT_EQ(bvh.num_nodes(), 2 * faces - 1);
    for (Index v = 0; v < (faces == 1 ? 3 : 4); ++v) {
      EXPECT_TRUE(box_holds(bvh.start_box(0), x0, v) && box_holds(bvh.end_box(0), x1, v)) << faces;
    }
    EXPECT_TRUE(bvh.direction_mask(0) >> 4 & 1) << faces;  // both face +z
  }
}

// The exact projection of vertex v on diagonal k of diagonal_bounds.hpp.
mpq_class exact_diagonal(const Positions& x, Index v, int k) {
  const mpq_class px(x(v, 0)), py(x(v, 1)), pz(x(v, 2));
  if (k == 0) return px + py + pz;
  if (k == 1) return px + py - pz;
  if (k == 2) return px - py + pz;
  return py + pz - px;
}

bool diagonals_hold(const DiagonalBox& box, const Positions& x, Index v) {
  for (int k = 0; k < kDiagonals; ++k) {
    const mpq_class p = exact_diagonal(x, v, k);
    if (mpq_class(box.min[k]) > p || mpq_class(box.max[k]) < p) return false;
  }
  return true;
}

// Every node's diagonal bounds hold the exact projections of its faces' corners, also
// where a rounded sum x + y + z would fall on the wrong side of them (terms that cancel).
TEST(MeshBvh, DiagonalBoundsHoldTheExactProjections) {
  std::vector<BvhCase> cases = bvh_cases();
  BvhCase cancelling = cases.front();
  cancelling.name = "cancelling";
  for (Index v = 0; v < cancelling.mesh.vertices.rows(); ++v) {
    // x + y + z rounds to 0 (the tiny y is lost against x), the exact sum is y > 0; and
    // likewise for the other diagonals at x1.
    const double big = 0x1p20, tiny = (1 + v % 7) * 0x1p-40;
    cancelling.mesh.vertices.row(v) = Vec3(-big, tiny, big);
    cancelling.x1.row(v) = Vec3(-big, -tiny, -big);
  }
  cases.push_back(cancelling);
  for (const BvhCase& c : cases) {
    const TriangleMesh mesh(static_cast<Index>(c.mesh.vertices.rows()), c.mesh.faces);
    MeshBvh bvh(mesh, c.mesh.vertices);
    bvh.refit(c.mesh.vertices, c.x1, false);
    for (Index node = 0; node < bvh.num_nodes(); ++node) {
      std::vector<Index> faces;
      faces_under(bvh, node, faces);
      if (faces.size() > 64 && node % 17 != 0) continue;  // exact checks are slow
      for (Index f : faces) {
        for (int k = 0; k < 3; ++k) {
          const Index v = mesh.faces()(f, k);
          ASSERT_TRUE(diagonals_hold(bvh.diagonal_start_box(node), c.mesh.vertices, v) &&
                      diagonals_hold(bvh.diagonal_end_box(node), c.x1, v))
              << c.name << " node " << node << " face " << f;
        }
      }
    }
  }
}

TEST(MeshBvh, RefitBoxesHoldTheSweptTrianglesAndMasksHoldEveryNormal) {
  for (const BvhCase& c : bvh_cases()) {
    const TriangleMesh mesh(static_cast<Index>(c.mesh.vertices.rows()), c.mesh.faces);
    MeshBvh bvh(mesh, c.mesh.vertices);
    bvh.refit(c.mesh.vertices, c.x1, true);
    ASSERT_EQ(bvh.num_nodes(), 2 * mesh.num_faces() - 1) << c.name;
    Index certified = 0;
    for (Index node = 0; node < bvh.num_nodes(); ++node) {
      std::vector<Index> faces;
      faces_under(bvh, node, faces);
      ASSERT_EQ(static_cast<Index>(faces.size()), bvh.size(node)) << c.name;
      for (Index f : faces) {
        for (int k = 0; k < 3; ++k) {
          const Index v = mesh.faces()(f, k);
          ASSERT_TRUE(box_holds(bvh.start_box(node), c.mesh.vertices, v) &&
                      box_holds(bvh.end_box(node), c.x1, v))
              << c.name << " node " << node << " face " << f;
        }
      }
      const DirectionMask mask = bvh.direction_mask(node);
      if (bvh.is_leaf(node) || mask == 0) continue;
      ++certified;
      ASSERT_TRUE(bvh.acute_axis(node).has_value());
      // Exact checks are slow: every face of small nodes, a sample of large ones.
      const std::size_t stride = std::max<std::size_t>(1, faces.size() / 16);
      for (std::size_t i = 0; i < faces.size(); i += stride) {
        ASSERT_TRUE(mask_holds_face(mask, mesh, c.mesh.vertices, c.x1, faces[i]))
            << c.name << " node " << node;
      }
    }
    const DirectionMask root = bvh.direction_mask(0);
    if (c.name == "turn10") {
      EXPECT_NE(root, 0u) << c.name;
    } else if (c.name == "turn170" || c.name == "folded" || c.name.starts_with("sphere")) {
      // Normals in opposite directions (or no mask direction within 90 degrees of all).
      EXPECT_EQ(root, 0u) << c.name;
    } else if (c.name == "crumpling") {
      EXPECT_TRUE(root & (DirectionMask{1} << 4)) << c.name << ": +z is bit 4";
      EXPECT_EQ(mask_direction(4), Vec3(0, 0, 1));
    }
    // Not vacuous, except where no patch keeps its normals within 90 degrees of one
    // direction, or the normals turn so far during the step (the large crumple and the
    // snapped grid) that the bound of direction_mask.hpp gives up.
    if (c.name != "sphere_random" && c.name != "turn170" && c.name != "grid_crumple_large" &&
        c.name != "grid_snapped") {
      EXPECT_GT(certified, 0) << c.name;
    }
  }
}

TEST(MeshBvh, DirectionsAloneGiveTheSameMasksAndLeaveTheBoxes) {
  // refit_directions() computes the masks of refit(..., true) bit for bit, writes no box
  // (they keep the last refit's step) and says so; a refit() after it makes them current.
  for (const BvhCase& c : bvh_cases()) {
    const TriangleMesh mesh(static_cast<Index>(c.mesh.vertices.rows()), c.mesh.faces);
    MeshBvh full(mesh, c.mesh.vertices), directions(mesh, c.mesh.vertices);
    EXPECT_TRUE(directions.boxes_current()) << c.name;  // the build refits
    full.refit(c.mesh.vertices, c.x1, true);
    // Another step first, so that stale boxes differ from this step's.
    const Positions shifted = c.x1.array() + 1.0;
    directions.refit(shifted, shifted, false);
    std::vector<FloatBox> before;
    for (Index node = 0; node < directions.num_nodes(); ++node) {
      before.push_back(directions.start_box(node));
      before.push_back(directions.end_box(node));
    }
    directions.refit_directions(c.mesh.vertices, c.x1);
    EXPECT_FALSE(directions.boxes_current()) << c.name;
    for (Index node = 0; node < full.num_nodes(); ++node) {
      ASSERT_EQ(directions.direction_mask(node), full.direction_mask(node))
          << c.name << " node " << node;
      const std::size_t i = 2 * static_cast<std::size_t>(node);
      ASSERT_EQ(directions.start_box(node).min, before[i].min) << c.name << " node " << node;
      ASSERT_EQ(directions.start_box(node).max, before[i].max) << c.name << " node " << node;
      ASSERT_EQ(directions.end_box(node).min, before[i + 1].min) << c.name << " node " << node;
      ASSERT_EQ(directions.end_box(node).max, before[i + 1].max) << c.name << " node " << node;
    }
    // Boxes alone then complete the step, and keep the masks.
    directions.refit(c.mesh.vertices, c.x1, false);
    EXPECT_TRUE(directions.boxes_current()) << c.name;
    for (Index node = 0; node < full.num_nodes(); ++node) {
      ASSERT_EQ(directions.start_box(node).min, full.start_box(node).min) << c.name;
      ASSERT_EQ(directions.start_box(node).max, full.start_box(node).max) << c.name;
      ASSERT_EQ(directions.end_box(node).min, full.end_box(node).min) << c.name;
      ASSERT_EQ(directions.end_box(node).max, full.end_box(node).max) << c.name;
      ASSERT_EQ(directions.direction_mask(node), full.direction_mask(node))
          << c.name << " node " << node;
    }
  }
}

TEST(MeshBvh, RefitBoxesAreTheTightestFloatBoxes) {
  // A leaf's box at each end of the step is its face's box in that frame rounded outward by
  // float_at_most/at_least, and an inner node's is the union of its children's, exactly:
  // this catches a refit that pairs a node with the wrong children, the wrong leaf or the
  // wrong frame, which the containment check above would let through whenever the wrong
  // box happens to be larger.
  for (const BvhCase& c : bvh_cases()) {
    const TriangleMesh mesh(static_cast<Index>(c.mesh.vertices.rows()), c.mesh.faces);
    MeshBvh bvh(mesh, c.mesh.vertices);
    for (const bool with_directions : {false, true}) {
      bvh.refit(c.mesh.vertices, c.x1, with_directions);
      for (const bool at_end : {false, true}) {
        const Positions& x = at_end ? c.x1 : c.mesh.vertices;
        const auto box = [&](Index node) {
          return at_end ? bvh.end_box(node) : bvh.start_box(node);
        };
        for (Index node = 0; node < bvh.num_nodes(); ++node) {
          FloatBox expected;
          if (bvh.is_leaf(node)) {
            for (int k = 0; k < 3; ++k) {
              double low = std::numeric_limits<double>::infinity(), high = -low;
              for (int corner = 0; corner < 3; ++corner) {
                const double value = x(mesh.faces()(bvh.leaf_face(node), corner), k);
                low = std::min(low, value), high = std::max(high, value);
              }
              expected.min[k] = float_at_most(low), expected.max[k] = float_at_least(high);
            }
          } else {
            expected = box(bvh.left(node));
            expected.extend(box(bvh.right(node)));
          }
          ASSERT_EQ(box(node).min, expected.min) << c.name << " node " << node << " " << at_end;
          ASSERT_EQ(box(node).max, expected.max) << c.name << " node " << node << " " << at_end;
        }
      }
    }
  }
}

}  // namespace
}  // namespace tailor

namespace tailor {
namespace {

// Subtrees are split in parallel: the tree must be the one a single thread builds, on a
// surface of several components (two sheets of a folded cloth, plus a loose strip).
TEST(BvhLayout, SurfaceLayoutDoesNotDependOnThreads) {
  const ProceduralStep step = make_folded_cloth_on_sphere(sanitized() ? 6000 : 40000, 3);
  const TriangleMesh mesh(step.x0.rows(), step.faces);
  std::vector<Index> faces;
  std::vector<Vec3> centers;
  for (Index f = 0; f < mesh.num_faces(); f += (f % 97 == 5) ? 2 : 1) {  // holes: components
    faces.push_back(f);
    centers.push_back((step.x0.row(step.faces(f, 0)) + step.x0.row(step.faces(f, 1)) +
                       step.x0.row(step.faces(f, 2)))
                          .transpose() /
                      3.0);
  }
  const BvhLayout parallel = build_surface_layout(mesh, faces, centers);
  BvhLayout sequential;
  tbb::task_arena(1).execute([&] { sequential = build_surface_layout(mesh, faces, centers); });
  ASSERT_EQ(parallel.num_nodes(), 2 * static_cast<Index>(faces.size()) - 1);
  EXPECT_EQ(parallel.right, sequential.right);
  EXPECT_EQ(parallel.count, sequential.count);
}

// The median split too: large subtrees split in parallel build the single thread's tree
// (with ties among the centres, which the primitive ids break).
TEST(BvhLayout, MedianSplitLayoutDoesNotDependOnThreads) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> coarse(0, 40);  // many equal coordinates
  std::vector<Vec3> centers(sanitized() ? 20000 : 60000);
  for (Vec3& c : centers) c = {coarse(rng) * 0.1, coarse(rng) * 0.2, coarse(rng) * 0.05};
  const BvhLayout parallel = build_median_split_layout(centers);
  BvhLayout sequential;
  tbb::task_arena(1).execute([&] { sequential = build_median_split_layout(centers); });
  ASSERT_EQ(parallel.num_nodes(), 2 * static_cast<Index>(centers.size()) - 1);
  EXPECT_EQ(parallel.right, sequential.right);
  EXPECT_EQ(parallel.count, sequential.count);
}

}  // namespace
}  // namespace tailor
