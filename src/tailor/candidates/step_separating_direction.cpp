#include "tailor/candidates/step_separating_direction.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "tailor/bvh/batch_gather.hpp"
#include "tailor/bvh/lane_vectors.hpp"

namespace tailor {
namespace {

// One build of the lanes per instruction set (lanes_per_target.inc).
#define TAILOR_LANES_FILE "tailor/candidates/step_separating_direction_lanes.inc"
#include "tailor/candidates/lanes_per_target.inc"

using BatchKernel = std::uint32_t (*)(const MovingTriangleBatch&, const MovingTriangleBatch&);

void mark_apart(BatchKernel kernel, const FaceArray& faces, const Positions& x0,
                const Positions& x1, std::span<const TrianglePair> pairs,
                std::span<TrianglePairSides> sides) {
  if (sides.size() != pairs.size()) {
    throw std::invalid_argument("mark_pairs_apart: sides and pairs differ in size");
  }
  constexpr int kCapacity = MovingTriangleBatch::kCapacity;
  MovingTriangleBatch first, second;
  std::array<std::array<Index, 3>, kCapacity> first_faces, second_faces;
  std::array<std::size_t, kCapacity> lane_pair;
  int count = 0;
  const auto run = [&] {
    gather_batch(x0.data(), x1.data(), std::span(first_faces.data(), count), first);
    gather_batch(x0.data(), x1.data(), std::span(second_faces.data(), count), second);
    pad_to_eight_lanes(first);
    pad_to_eight_lanes(second);
    const std::uint32_t apart = kernel(first, second);
    for (int lane = 0; lane < count; ++lane) sides[lane_pair[lane]].apart = (apart >> lane) & 1u;
    count = 0;
  };
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    sides[i].apart = 0;
    if (sides[i].separated()) continue;
    const TrianglePair& pair = pairs[i];
    first_faces[count] = {faces(pair.first, 0), faces(pair.first, 1), faces(pair.first, 2)};
    second_faces[count] = {faces(pair.second, 0), faces(pair.second, 1), faces(pair.second, 2)};
    lane_pair[count] = i;
    if (++count == kCapacity) run();
  }
  if (count > 0) run();
}

}  // namespace

namespace detail {

void mark_pairs_apart_two_lanes(const FaceArray& faces, const Positions& x0, const Positions& x1,
                                std::span<const TrianglePair> pairs,
                                std::span<TrianglePairSides> sides) {
  mark_apart(sse2::batch_apart, faces, x0, x1, pairs, sides);
}

}  // namespace detail

void mark_pairs_apart(const FaceArray& faces, const Positions& x0, const Positions& x1,
                      std::span<const TrianglePair> pairs, std::span<TrianglePairSides> sides) {
  static const BatchKernel kernel =
      lanes::widest<BatchKernel>(avx512::batch_apart, avx2::batch_apart, sse2::batch_apart);
  mark_apart(kernel, faces, x0, x1, pairs, sides);
}

}  // namespace tailor
