#include "tailor/detection/intersection_check.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>

#include "tailor/bvh/bvh.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/geometry/triangle_intersection.hpp"

namespace tailor {
namespace {

std::array<Index, 3> face_of(const TriangleMesh& mesh, Index f) {
  return {mesh.faces()(f, 0), mesh.faces()(f, 1), mesh.faces()(f, 2)};
}

Triangle triangle_of(const TriangleMesh& mesh, const Positions& x, Index f) {
  const auto ids = face_of(mesh, f);
  return {x.row(ids[0]).transpose(), x.row(ids[1]).transpose(), x.row(ids[2]).transpose()};
}

std::vector<Aabb> face_boxes(const TriangleMesh& mesh, const Positions& x) {
  std::vector<Aabb> boxes(static_cast<std::size_t>(mesh.num_faces()));
  tbb::parallel_for(Index{0}, mesh.num_faces(), [&](Index f) {
    for (Index v : face_of(mesh, f)) boxes[f].extend(Vec3(x.row(v).transpose()));
  });
  return boxes;
}

void check_rows(const TriangleMesh& mesh, const Positions& x, const char* what) {
  if (x.rows() != mesh.num_vertices()) {
    throw InputError(fmt::format("{}: {} positions for a mesh of {} vertices", what, x.rows(),
                                 mesh.num_vertices()));
  }
  if (!x.allFinite()) throw InputError(fmt::format("{}: non-finite position", what));
}

}  // namespace

IntersectionReport check_intersections(const TriangleMesh& cloth, const Positions& x,
                                       const TriangleMesh* obstacle, const Positions* y,
                                       std::size_t max_pairs,
                                       std::span<const Index> obstacle_exempt_vertices) {
  check_rows(cloth, x, "cloth");
  IntersectionReport report;
  const Index nf = cloth.num_faces();

  report.degenerate_faces = tbb::parallel_reduce(
      tbb::blocked_range<Index>(0, nf), std::int64_t{0},
      [&](const tbb::blocked_range<Index>& r, std::int64_t n) {
        for (Index f = r.begin(); f != r.end(); ++f) {
          n += is_degenerate_triangle(triangle_of(cloth, x, f)) ? 1 : 0;
        }
        return n;
      },
      std::plus<>());

  // Cloth self pairs: collect box-overlapping pairs, sort, test in parallel.
  const std::vector<Aabb> boxes = face_boxes(cloth, x);
  const Bvh bvh(boxes);
  std::vector<std::pair<Index, Index>> pairs;
  bvh.for_each_self_overlapping_pair(
      [&](Index f, Index g) { pairs.emplace_back(std::min(f, g), std::max(f, g)); });
  std::sort(pairs.begin(), pairs.end());
  report.self_candidate_pairs = static_cast<std::int64_t>(pairs.size());
  std::vector<TrianglePairVerdict> verdicts(pairs.size());
  tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t i) {
    verdicts[i] =
        classify_face_pair(x, face_of(cloth, pairs[i].first), face_of(cloth, pairs[i].second));
  });
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const auto [f, g] = pairs[i];
    if (verdicts[i] == TrianglePairVerdict::degenerate_adjacent) {
      ++report.undecided_adjacent_pairs;
    } else if (verdicts[i] == TrianglePairVerdict::intersecting) {
      ++(cloth.faces_share_vertex(f, g) ? report.adjacent_intersections
                                        : report.self_intersections);
      if (report.self_pairs.size() < max_pairs) report.self_pairs.emplace_back(f, g);
    }
  }

  if (obstacle != nullptr && y != nullptr) {
    check_rows(*obstacle, *y, "obstacle");
    std::vector<char> exempt_face(static_cast<std::size_t>(nf), 0);
    for (Index v : obstacle_exempt_vertices) {
      if (v < 0 || v >= cloth.num_vertices()) {
        throw InputError(fmt::format("exempt vertex {} out of range", v));
      }
      for (Index f : cloth.vertex_faces(v)) exempt_face[f] = 1;
    }
    const Bvh obstacle_bvh(face_boxes(*obstacle, *y));
    std::vector<std::pair<Index, Index>> cross;
    bvh.for_each_overlapping_pair(obstacle_bvh, [&](Index f, Index g) {
      if (!exempt_face[f]) cross.emplace_back(f, g);
    });
    std::sort(cross.begin(), cross.end());
    report.obstacle_candidate_pairs = static_cast<std::int64_t>(cross.size());
    std::vector<char> hit(cross.size(), 0);
    tbb::parallel_for(std::size_t{0}, cross.size(), [&](std::size_t i) {
      hit[i] = triangles_intersect(triangle_of(cloth, x, cross[i].first),
                                   triangle_of(*obstacle, *y, cross[i].second))
                   ? 1
                   : 0;
    });
    for (std::size_t i = 0; i < cross.size(); ++i) {
      if (hit[i] == 0) continue;
      ++report.obstacle_intersections;
      if (report.obstacle_pairs.size() < max_pairs) report.obstacle_pairs.push_back(cross[i]);
    }
  }
  return report;
}

}  // namespace tailor
