/// @file
/// Dropping thickness candidates that their own normal keeps apart, in vector lanes.

#include "tailor/candidates/thickness_pair_filter.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>

#include "tailor/bvh/batch_gather.hpp"
#include "tailor/bvh/lane_vectors.hpp"

namespace tailor {
namespace {

// One build of the lanes per instruction set (lanes_per_target.inc).
#define TAILOR_LANES_FILE "tailor/candidates/thickness_pair_filter_lanes.inc"
#include "tailor/candidates/lanes_per_target.inc"

using BatchKernel = std::uint32_t (*)(const MovingTriangleBatch&, const MovingTriangleBatch&, bool,
                                      double);

// Pairs a block of the parallel loop filters on its own.
constexpr std::size_t kBlock = 4096;

using Corners = std::array<Index, 3>;

// The two primitives of a pair as triangles of vertex ids (a vertex repeated, an edge with
// its second end repeated).
std::array<Corners, 2> corners_of(const TriangleMesh& mesh, const VertexFacePair& pair) {
  const auto face = mesh.faces().row(pair.face);
  return {{{pair.vertex, pair.vertex, pair.vertex}, {face[0], face[1], face[2]}}};
}
std::array<Corners, 2> corners_of(const TriangleMesh& mesh, const EdgeEdgePair& pair) {
  const auto a = mesh.edges().row(pair.edge_a), b = mesh.edges().row(pair.edge_b);
  return {{{a[0], a[1], a[1]}, {b[0], b[1], b[1]}}};
}

// Moves the pairs of [begin, end) that the kernel keeps to the front of the range, in order;
// returns how many there are.
template <class Pair>
std::size_t keep_in_place(BatchKernel kernel, const TriangleMesh& mesh, const Positions& x0,
                          const Positions& x1, double h, Pair* begin, Pair* end) {
  constexpr int kCapacity = MovingTriangleBatch::kCapacity;
  constexpr bool kVertexFace = std::is_same_v<Pair, VertexFacePair>;
  MovingTriangleBatch first, second;
  std::array<Corners, kCapacity> first_corners, second_corners;
  Pair* kept = begin;
  for (Pair* batch = begin; batch < end; batch += kCapacity) {
    const int count = static_cast<int>(std::min<std::ptrdiff_t>(kCapacity, end - batch));
    for (int lane = 0; lane < count; ++lane) {
      const auto [a, b] = corners_of(mesh, batch[lane]);
      first_corners[lane] = a;
      second_corners[lane] = b;
    }
    gather_batch(x0.data(), x1.data(), std::span(first_corners.data(), count), first);
    gather_batch(x0.data(), x1.data(), std::span(second_corners.data(), count), second);
    pad_to_eight_lanes(first);
    pad_to_eight_lanes(second);
    const std::uint32_t apart = kernel(first, second, kVertexFace, h);
    for (int lane = 0; lane < count; ++lane) {
      if (((apart >> lane) & 1u) == 0) *kept++ = batch[lane];
    }
  }
  return static_cast<std::size_t>(kept - begin);
}

// Each block keeps its pairs at its front; the kept runs are then closed up in order.
template <class Pair>
std::size_t drop_apart(BatchKernel kernel, const TriangleMesh& mesh, const Positions& x0,
                       const Positions& x1, double h, std::vector<Pair>& pairs) {
  const std::size_t blocks = (pairs.size() + kBlock - 1) / kBlock;
  std::vector<std::size_t> kept(blocks);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks), [&](const auto& range) {
    for (std::size_t block = range.begin(); block != range.end(); ++block) {
      Pair* begin = pairs.data() + block * kBlock;
      Pair* end = pairs.data() + std::min(pairs.size(), (block + 1) * kBlock);
      kept[block] = keep_in_place(kernel, mesh, x0, x1, h, begin, end);
    }
  });
  std::size_t size = 0;
  for (std::size_t block = 0; block < blocks; ++block) {
    const auto from = pairs.begin() + static_cast<std::ptrdiff_t>(block * kBlock);
    std::copy(from, from + static_cast<std::ptrdiff_t>(kept[block]),
              pairs.begin() + static_cast<std::ptrdiff_t>(size));
    size += kept[block];
  }
  const std::size_t dropped = pairs.size() - size;
  pairs.resize(size);
  return dropped;
}

std::size_t drop_both(BatchKernel kernel, const TriangleMesh& mesh, const Positions& x0,
                      const Positions& x1, double h, FeaturePairs& pairs) {
  if (!(h > 0)) throw std::invalid_argument("drop_pairs_kept_apart: h must be > 0");
  return drop_apart(kernel, mesh, x0, x1, h, pairs.vertex_face) +
         drop_apart(kernel, mesh, x0, x1, h, pairs.edge_edge);
}

}  // namespace

namespace detail {

std::size_t drop_pairs_kept_apart_two_lanes(const TriangleMesh& mesh, const Positions& x0,
                                            const Positions& x1, double h, FeaturePairs& pairs) {
  return drop_both(sse2::batch_apart, mesh, x0, x1, h, pairs);
}

}  // namespace detail

std::size_t drop_pairs_kept_apart(const TriangleMesh& mesh, const Positions& x0,
                                  const Positions& x1, double h, FeaturePairs& pairs) {
  static const BatchKernel kernel =
      lanes::widest<BatchKernel>(avx512::batch_apart, avx2::batch_apart, sse2::batch_apart);
  return drop_both(kernel, mesh, x0, x1, h, pairs);
}

}  // namespace tailor
