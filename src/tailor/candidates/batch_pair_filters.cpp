#include "tailor/candidates/batch_pair_filters.hpp"

#include <cstring>

#include "tailor/bvh/lane_vectors.hpp"
#include "tailor/candidates/projection_polynomials.hpp"

namespace tailor {
namespace {

// The polynomials of every lane, stored by the vector kernel for the per-pair steps: the
// cubic f (values, then bounds) and up to five quadratics (values, then bounds).
struct LanePolynomials {
  alignas(64) double cubic[8][PairBatch::kCapacity];
  alignas(64) double quadratic[5][6][PairBatch::kCapacity];
};

// Per-lane outcomes of the vector kernel (0 or all bits set).
struct LaneFlags {
  std::int64_t cubic_ok[PairBatch::kCapacity];      // the cubic's range check passed
  std::int64_t cubic_signed[PairBatch::kCapacity];  // f certainly of one strict sign
  std::int64_t undecided[PairBatch::kCapacity];     // a coefficient within its bound
  std::int64_t projected[PairBatch::kCapacity];     // the projection's checks passed
  std::int64_t excluded[PairBatch::kCapacity];      // excluded on the whole step
  std::int64_t halves[PairBatch::kCapacity];        // else excluded on both halves
};

// One build of the lanes per instruction set (lanes_per_target.inc).
#define TAILOR_LANES_FILE "tailor/candidates/batch_pair_filter_lanes.inc"
#include "tailor/candidates/lanes_per_target.inc"

using LaneKernel = void (*)(PairKind, const PairBatch&, LanePolynomials&, LaneFlags&);
using SubdivisionKernel = void (*)(PairKind, const PairBatch&, const LanePolynomials&, LaneFlags&);

// The kernels of one instruction set.
struct Kernels {
  LaneKernel whole_step;
  SubdivisionKernel subdivision;
};

// The exact sign of the coplanarity cubic of one lane (geometry/coplanarity_sign.hpp).
StepSign exact_lane_sign(const PairBatch& batch, int lane) {
  Vec3 p[8];
  for (int r = 0; r < 8; ++r) {
    p[r] = Vec3(batch.coordinate[3 * r][lane], batch.coordinate[3 * r + 1][lane],
                batch.coordinate[3 * r + 2][lane]);
  }
  return coplanarity_sign({p[0], p[1], p[2], p[3]}, {p[4], p[5], p[6], p[7]});
}

void verdicts_with(Kernels kernels, PairKind kind, PairBatch& batch, PairFilters filters,
                   std::span<PairVerdict, PairBatch::kCapacity> verdicts) {
  for (int row = 0; row < 24; ++row) {
    for (int i = batch.count; i < batch.padded_count(); ++i) {
      batch.coordinate[row][i] = batch.coordinate[row][0];
    }
  }
  LanePolynomials polys;
  LaneFlags flags;
  kernels.whole_step(kind, batch, polys, flags);
  if (filters.projection) kernels.subdivision(kind, batch, polys, flags);
  // The order of the one-pair filters (projection_filter.cpp): the certified double signs,
  // the projection filter, then the exact signs.
  for (int lane = 0; lane < batch.count; ++lane) {
    const bool cubic_ok = flags.cubic_ok[lane] != 0;
    PairVerdict verdict = PairVerdict::may_touch;
    if (filters.coplanarity && cubic_ok && flags.cubic_signed[lane] != 0) {
      verdict = PairVerdict::never_coplanar;
    } else if (filters.projection && cubic_ok && flags.projected[lane] != 0 &&
               (flags.excluded[lane] != 0 || flags.halves[lane] != 0)) {
      verdict = PairVerdict::apart_in_projection;
    } else if (filters.coplanarity && (!cubic_ok || flags.undecided[lane] != 0) &&
               exact_lane_sign(batch, lane) != StepSign::mixed) {
      verdict = PairVerdict::never_coplanar;
    }
    verdicts[static_cast<std::size_t>(lane)] = verdict;
  }
}

}  // namespace

namespace detail {

void pair_verdicts_two_lanes(PairKind kind, PairBatch& batch, PairFilters filters,
                             std::span<PairVerdict, PairBatch::kCapacity> verdicts) {
  verdicts_with({sse2::batch_lanes, sse2::subdivided_lanes}, kind, batch, filters, verdicts);
}

}  // namespace detail

void pair_verdicts(PairKind kind, PairBatch& batch, PairFilters filters,
                   std::span<PairVerdict, PairBatch::kCapacity> verdicts) {
  static const Kernels kernels = lanes::widest<Kernels>(
      {avx512::batch_lanes, avx512::subdivided_lanes}, {avx2::batch_lanes, avx2::subdivided_lanes},
      {sse2::batch_lanes, sse2::subdivided_lanes});
  verdicts_with(kernels, kind, batch, filters, verdicts);
}

}  // namespace tailor
