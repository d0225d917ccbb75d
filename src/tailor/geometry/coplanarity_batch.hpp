#pragma once
/// @file
/// The double-precision stage of the non-coplanarity (DNF) filter for several point
/// quadruples at once: detail::coplanarity_bernstein_double() (coplanarity_sign.hpp) with
/// one query per vector lane.
///
/// Why it is the same filter. Every lane runs the scalar function's operations in the
/// scalar order (the same differences, products, sums and guards; no fused multiply-add,
/// since the kernels are built for SSE2 or AVX2 only), so each lane's values and bounds are
/// bit for bit those of the scalar function, and its error analysis holds unchanged
/// (tests/geometry/test_coplanarity_batch.cpp compares them bit for bit). What the batch
/// saves is the scalar code's shuffling: on the folded cloth's low level the scalar
/// evaluation took about 640 instructions per pair.

#include <array>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// Up to kCapacity coplanarity queries: for query i, the points a, b, c, d at t = 0 and
/// t = 1 (three doubles each, e.g. rows of row-major positions) in the order
/// a_t0, b_t0, c_t0, d_t0, a_t1, b_t1, c_t1, d_t1.
struct CoplanarityBatch {
  static constexpr int kCapacity = 4;
  std::array<std::array<const double*, 8>, kCapacity> points{};
  int count = 0;
};

/// The Bernstein evaluation of one query: `ok` as the scalar function's return value; when
/// ok, `value` and `bound` as its outputs.
struct CoplanarityTerms {
  bool ok = false;
  double value[4] = {0, 0, 0, 0};
  double bound[4] = {0, 0, 0, 0};
};

/// detail::coplanarity_bernstein_double() of every query of the batch (lanes past `count`
/// are not read); picks four lanes at a time on AVX2 processors, two otherwise.
void coplanarity_bernstein_batch(const CoplanarityBatch& batch,
                                 std::array<CoplanarityTerms, CoplanarityBatch::kCapacity>& terms);

namespace detail {
/// The two lane widths, exposed so that a test can compare both with the scalar function
/// (four_lanes only where has_four_lanes()).
void coplanarity_bernstein_two_lanes(
    const CoplanarityBatch& batch,
    std::array<CoplanarityTerms, CoplanarityBatch::kCapacity>& terms);
void coplanarity_bernstein_four_lanes(
    const CoplanarityBatch& batch,
    std::array<CoplanarityTerms, CoplanarityBatch::kCapacity>& terms);
bool coplanarity_batch_has_four_lanes();
}  // namespace detail

}  // namespace tailor
