#include "tailor/geometry/finite_positions.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>

namespace tailor {
namespace {

// Rows per task: 64 KiB of coordinates.
constexpr Index kRowsPerTask = 2730;

// Whether any of `count` coordinates is non-finite. v·0 is ±0 for a finite v and NaN for
// an infinite or NaN one, so a sum of them is 0 exactly when all are finite. Four sums
// keep four additions in flight; no early exit. (An OR over the exponent bits needs a
// 64-bit integer compare that SSE2 lacks: it ran at a third of this speed.)
bool any_non_finite(const double* values, std::size_t count) {
  double sum0 = 0, sum1 = 0, sum2 = 0, sum3 = 0;
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4) {
    sum0 += values[i] * 0.0;
    sum1 += values[i + 1] * 0.0;
    sum2 += values[i + 2] * 0.0;
    sum3 += values[i + 3] * 0.0;
  }
  for (; i < count; ++i) sum0 += values[i] * 0.0;
  return !(sum0 + sum1 + sum2 + sum3 == 0);
}

}  // namespace

std::optional<Index> first_non_finite_vertex(const Positions& x) {
  const Index rows = static_cast<Index>(x.rows());
  const Index first = tbb::parallel_reduce(
      tbb::blocked_range<Index>(0, rows, kRowsPerTask), rows,
      [&](const tbb::blocked_range<Index>& range, Index found) {
        // A block past one already found cannot hold the first.
        if (range.begin() >= found) return found;
        const double* values = x.data() + std::size_t{3} * static_cast<std::size_t>(range.begin());
        if (!any_non_finite(values, std::size_t{3} * range.size())) return found;
        for (Index row = range.begin(); row < range.end(); ++row) {
          if (!std::isfinite(x(row, 0)) || !std::isfinite(x(row, 1)) || !std::isfinite(x(row, 2))) {
            return std::min(found, row);
          }
        }
        return found;
      },
      [](Index a, Index b) { return std::min(a, b); });
  if (first == rows) return std::nullopt;
  return first;
}

}  // namespace tailor
