#include "tailor/candidates/triangle_plane_sides.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "tailor/bvh/batch_gather.hpp"
#include "tailor/bvh/lane_vectors.hpp"

namespace tailor {
namespace {

// The two faces of up to kCapacity pairs, one batch per face of the pair.
struct PairBatches {
  MovingTriangleBatch first, second;
};

// One build of the lanes per instruction set (lanes_per_target.inc).
#define TAILOR_LANES_FILE "tailor/candidates/triangle_plane_sides_lanes.inc"
#include "tailor/candidates/lanes_per_target.inc"

using BatchKernel = void (*)(const PairBatches&, TrianglePairSides*);

void pair_sides(BatchKernel kernel, const FaceArray& faces, const Positions& x0,
                const Positions& x1, std::span<const TrianglePair> pairs,
                std::span<TrianglePairSides> sides) {
  if (sides.size() != pairs.size()) {
    throw std::invalid_argument("triangle_pair_sides: sides and pairs differ in size");
  }
  constexpr std::size_t kCapacity = MovingTriangleBatch::kCapacity;
  PairBatches batches;
  std::array<std::array<Index, 3>, kCapacity> first, second;
  std::array<TrianglePairSides, kCapacity> lane_sides;
  for (std::size_t begin = 0; begin < pairs.size(); begin += kCapacity) {
    const std::size_t count = std::min(kCapacity, pairs.size() - begin);
    for (std::size_t i = 0; i < count; ++i) {
      const TrianglePair& pair = pairs[begin + i];
      first[i] = {faces(pair.first, 0), faces(pair.first, 1), faces(pair.first, 2)};
      second[i] = {faces(pair.second, 0), faces(pair.second, 1), faces(pair.second, 2)};
    }
    gather_batch(x0.data(), x1.data(), std::span(first.data(), count), batches.first);
    gather_batch(x0.data(), x1.data(), std::span(second.data(), count), batches.second);
    pad_to_eight_lanes(batches.first);
    pad_to_eight_lanes(batches.second);
    kernel(batches, lane_sides.data());
    std::copy_n(lane_sides.begin(), count, sides.begin() + static_cast<std::ptrdiff_t>(begin));
  }
}

}  // namespace

namespace detail {

void triangle_pair_sides_two_lanes(const FaceArray& faces, const Positions& x0, const Positions& x1,
                                   std::span<const TrianglePair> pairs,
                                   std::span<TrianglePairSides> sides) {
  pair_sides(sse2::batch_sides, faces, x0, x1, pairs, sides);
}

}  // namespace detail

void triangle_pair_sides(const FaceArray& faces, const Positions& x0, const Positions& x1,
                         std::span<const TrianglePair> pairs, std::span<TrianglePairSides> sides) {
  static const BatchKernel kernel =
      lanes::widest<BatchKernel>(avx512::batch_sides, avx2::batch_sides, sse2::batch_sides);
  pair_sides(kernel, faces, x0, x1, pairs, sides);
}

}  // namespace tailor
