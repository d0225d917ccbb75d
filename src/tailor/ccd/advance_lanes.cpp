/// @file
/// Conservative advancement of edge-edge pairs in vector lanes (see the header).

#include "tailor/ccd/advance_lanes.hpp"

#include <algorithm>
#include <limits>

#include "tailor/bvh/lane_vectors.hpp"

namespace tailor {
namespace {

// One build of the lanes per instruction set (lanes_per_target.inc).
#define TAILOR_LANES_FILE "tailor/ccd/advance_lanes.inc"
#include "tailor/candidates/lanes_per_target.inc"

}  // namespace

namespace detail {

void advance_pairs_two_lanes(std::span<PairAdvance> pairs, PairShape shape, double h,
                             double witness_reach, int max_steps) {
  sse2::advance_pairs(pairs, shape, h, witness_reach, max_steps);
}

}  // namespace detail

void advance_pairs(std::span<PairAdvance> pairs, PairShape shape, double h, double witness_reach,
                   int max_steps) {
  using Kernel = void (*)(std::span<PairAdvance>, PairShape, double, double, int);
  static const Kernel kernel =
      lanes::widest<Kernel>(avx512::advance_pairs, avx2::advance_pairs, sse2::advance_pairs);
  kernel(pairs, shape, h, witness_reach, max_steps);
}

}  // namespace tailor
