#pragma once
/// @file
/// The low-level filters (non-coplanarity and projection, projection_filter.hpp) on up to
/// sixteen vertex-face or edge-edge pairs at once: the coplanarity cubic, the projected
/// brackets and the whole-step exclusion test in vector lanes (eight doubles per AVX-512
/// register), the dyadic subdivision and the exact fallback one pair at a time for the
/// few pairs that need them. Every verdict equals vertex_face_verdict() /
/// edge_edge_verdict() of the same pair, bit for bit: the lanes perform the same
/// floating-point operations in the same order (no contraction into fused multiply-adds:
/// the build sets -ffp-contract=off), so the certified bounds and their arguments are
/// those of projection_filter.hpp and geometry/coplanarity_sign.hpp.

#include <span>

#include "tailor/candidates/projection_filter.hpp"
#include "tailor/geometry/types.hpp"

namespace tailor {

/// What kind of pairs a PairBatch holds.
enum class PairKind : std::uint8_t { vertex_face, edge_edge };

/// Up to kCapacity pairs of four moving points (a, b, c, d) in structure-of-arrays form:
/// a vertex-face pair is the face's corners a, b, c and the vertex d; an edge-edge pair
/// the edges ab and cd. Each pair carries two ids for its caller.
struct PairBatch {
  /// Most pairs a batch holds (lanes).
  static constexpr int kCapacity = 16;
  /// Row 3·(4·frame + point) + k: coordinate k of point 0-3 (a-d) at frame 0-1.
  alignas(64) double coordinate[24][kCapacity];
  /// First id of each pair (the caller's; the filters do not read it).
  Index first_id[kCapacity];
  /// Second id of each pair (likewise).
  Index second_id[kCapacity];
  /// Number of pairs added (<= kCapacity).
  int count = 0;

  /// Whether no more pairs fit (count == kCapacity).
  bool full() const { return count == kCapacity; }
  /// Appends a pair (count < kCapacity): points[p] at t = 0 and t = 1 (three doubles each).
  void add(Index first, Index second, const double* const (&t0)[4], const double* const (&t1)[4]) {
    for (int p = 0; p < 4; ++p) {
      for (int k = 0; k < 3; ++k) {
        coordinate[3 * p + k][count] = t0[p][k];
        coordinate[3 * (4 + p) + k][count] = t1[p][k];
      }
    }
    first_id[count] = first;
    second_id[count] = second;
    ++count;
  }
  /// Lanes the kernels read: count rounded up to a multiple of eight.
  int padded_count() const { return (count + 7) & ~7; }
};

/// The verdicts of `filters` for the pairs of `batch` (count >= 1) into verdicts[0, count).
/// Pads the batch (lanes past count repeat lane 0).
void pair_verdicts(PairKind kind, PairBatch& batch, PairFilters filters,
                   std::span<PairVerdict, PairBatch::kCapacity> verdicts);

namespace detail {
/// pair_verdicts with two lanes per vector (SSE2, any x86-64 processor); exposed so that a
/// test can check that every build agrees with the one-pair filters.
void pair_verdicts_two_lanes(PairKind kind, PairBatch& batch, PairFilters filters,
                             std::span<PairVerdict, PairBatch::kCapacity> verdicts);
}  // namespace detail

}  // namespace tailor
