/// @file
/// Box culling with three BVHs, then the exact predicates in parallel.

#include "tailor/detection/proximity_pairs.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>

#include "tailor/bvh/aabb.hpp"
#include "tailor/detection/feature_box_pairs.hpp"
#include "tailor/ccd/proximity_predicates.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/geometry/finite_positions.hpp"

namespace tailor {
namespace {

void check_configuration(const TriangleMesh& mesh, const Positions& x, double thickness) {
  if (x.rows() != mesh.num_vertices()) {
    throw InputError(
        fmt::format("proximity: {} positions for {} vertices", x.rows(), mesh.num_vertices()));
  }
  if (const std::optional<Index> vertex = first_non_finite_vertex(x)) {
    throw InputError(fmt::format("proximity: a non-finite coordinate at vertex {}", *vertex));
  }
  if (!(thickness >= 0) || !std::isfinite(thickness)) {
    throw InputError(
        fmt::format("proximity: the thickness must be finite and >= 0, got {}", thickness));
  }
}

FourPoints vertex_face_points(const TriangleMesh& mesh, const Positions& x, Index v, Index f) {
  const auto face = mesh.faces().row(f);
  return {position(x, v), position(x, face[0]), position(x, face[1]), position(x, face[2])};
}

FourPoints edge_edge_points(const TriangleMesh& mesh, const Positions& x, Index e, Index g) {
  const auto a = mesh.edges().row(e), b = mesh.edges().row(g);
  return {position(x, a[0]), position(x, a[1]), position(x, b[0]), position(x, b[1])};
}

/// Keeps the candidates the exact predicate accepts (in parallel; order kept).
template <class Pair, class Within>
std::vector<Pair> keep_within(std::vector<Pair> candidates, Within&& within) {
  std::vector<char> keep(candidates.size(), 0);
  tbb::parallel_for(std::size_t{0}, candidates.size(),
                    [&](std::size_t i) { keep[i] = within(candidates[i]) ? 1 : 0; });
  std::vector<Pair> kept;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (keep[i] != 0) kept.push_back(candidates[i]);
  }
  return kept;
}

}  // namespace

ProximityPairs proximity_pairs(const TriangleMesh& mesh, const Positions& x, double thickness) {
  return ProximitySearch(mesh).pairs(x, thickness);
}

ProximityPairs ProximitySearch::pairs(const Positions& x, double thickness) {
  const TriangleMesh& mesh = *m_mesh;
  check_configuration(mesh, x, thickness);
  // One instant: each box at both ends of a "step" (StepBox: float, rounded outwards), so
  // that the trees compare their leaves in buckets (bvh/step_bound_columns.hpp). The pairs
  // are those of the double boxes and perhaps a few more, which the exact tests drop.
  std::vector<StepBox> vertices(static_cast<std::size_t>(mesh.num_vertices()));
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    Aabb point;
    point.extend(position(x, v));
    const Aabb grown = grown_outwards(point, 0.5 * thickness);
    vertices[v] = StepBox::holding(grown, grown);
  }
  m_trees.update(mesh, vertices);
  FeaturePairs candidates = m_trees.overlapping_pairs(mesh);
  const auto by_vertex = [](const VertexFacePair& a, const VertexFacePair& b) {
    return a.vertex != b.vertex ? a.vertex < b.vertex : a.face < b.face;
  };
  const auto by_edges = [](const EdgeEdgePair& a, const EdgeEdgePair& b) {
    return a.edge_a != b.edge_a ? a.edge_a < b.edge_a : a.edge_b < b.edge_b;
  };
  ProximityPairs pairs;
  pairs.vertex_face = keep_within(std::move(candidates.vertex_face), [&](const VertexFacePair& p) {
    return vertex_face_within(vertex_face_points(mesh, x, p.vertex, p.face), thickness);
  });
  pairs.edge_edge = keep_within(std::move(candidates.edge_edge), [&](const EdgeEdgePair& p) {
    return edge_edge_within(edge_edge_points(mesh, x, p.edge_a, p.edge_b), thickness);
  });
  // Each pair once, so the order is total: the same on any number of threads.
  tbb::parallel_sort(pairs.vertex_face.begin(), pairs.vertex_face.end(), by_vertex);
  tbb::parallel_sort(pairs.edge_edge.begin(), pairs.edge_edge.end(), by_edges);
  return pairs;
}

ProximityPairs proximity_pairs_brute_force(const TriangleMesh& mesh, const Positions& x,
                                           double thickness) {
  check_configuration(mesh, x, thickness);
  ProximityPairs pairs;
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    for (Index f = 0; f < mesh.num_faces(); ++f) {
      if (!face_holds(mesh, f, v) &&
          vertex_face_within(vertex_face_points(mesh, x, v, f), thickness)) {
        pairs.vertex_face.push_back({v, f});
      }
    }
  }
  for (Index e = 0; e < mesh.num_edges(); ++e) {
    for (Index g = e + 1; g < mesh.num_edges(); ++g) {
      if (!edges_share_an_end(mesh, e, g) &&
          edge_edge_within(edge_edge_points(mesh, x, e, g), thickness)) {
        pairs.edge_edge.push_back({e, g});
      }
    }
  }
  return pairs;
}

}  // namespace tailor
