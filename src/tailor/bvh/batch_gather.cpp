#include "tailor/bvh/batch_gather.hpp"

#include <immintrin.h>

#include "tailor/bvh/lane_vectors.hpp"

namespace tailor {
namespace {

// The position of vertex v as (x, y, z, 0); the fourth double is not read.
[[gnu::target("avx2"), gnu::always_inline]] inline __m256d corner(const double* x, Index v,
                                                                  __m256i first_three) {
  return _mm256_maskload_pd(x + 3 * static_cast<std::ptrdiff_t>(v), first_three);
}

[[gnu::target("avx2")]] void gather_avx2(const double* x0, const double* x1,
                                         std::span<const std::array<Index, 3>> faces,
                                         MovingTriangleBatch& batch) {
  const __m256i first_three = _mm256_set_epi64x(0, -1, -1, -1);
  const int count = static_cast<int>(faces.size());
  batch.count = count;
  for (int first = 0; first < batch.padded_count(); first += 4) {
    // Lanes past the last triangle repeat the first one (pad()).
    const std::array<Index, 3>* face[4];
    for (int i = 0; i < 4; ++i) face[i] = &faces[first + i < count ? first + i : 0];
    for (int frame = 0; frame < 2; ++frame) {
      const double* x = frame == 0 ? x0 : x1;
      for (int k = 0; k < 3; ++k) {
        // Rows (x, y, z, -) of four corners to columns x, y, z.
        const __m256d r0 = corner(x, (*face[0])[k], first_three);
        const __m256d r1 = corner(x, (*face[1])[k], first_three);
        const __m256d r2 = corner(x, (*face[2])[k], first_three);
        const __m256d r3 = corner(x, (*face[3])[k], first_three);
        const __m256d xz01 = _mm256_unpacklo_pd(r0, r1), y01 = _mm256_unpackhi_pd(r0, r1);
        const __m256d xz23 = _mm256_unpacklo_pd(r2, r3), y23 = _mm256_unpackhi_pd(r2, r3);
        const int r = 3 * (3 * frame + k);
        _mm256_store_pd(&batch.coordinate[r][first], _mm256_permute2f128_pd(xz01, xz23, 0x20));
        _mm256_store_pd(&batch.coordinate[r + 1][first], _mm256_permute2f128_pd(y01, y23, 0x20));
        _mm256_store_pd(&batch.coordinate[r + 2][first], _mm256_permute2f128_pd(xz01, xz23, 0x31));
      }
    }
  }
}

}  // namespace

namespace detail {

void gather_batch_one_by_one(const double* x0, const double* x1,
                             std::span<const std::array<Index, 3>> faces,
                             MovingTriangleBatch& batch) {
  batch.count = 0;
  for (const auto& v : faces) {
    batch.add(x0 + 3 * v[0], x0 + 3 * v[1], x0 + 3 * v[2], x1 + 3 * v[0], x1 + 3 * v[1],
              x1 + 3 * v[2]);
  }
  batch.pad();
}

void gather_batch_four_lanes(const double* x0, const double* x1,
                             std::span<const std::array<Index, 3>> faces,
                             MovingTriangleBatch& batch) {
  gather_avx2(x0, x1, faces, batch);
}

}  // namespace detail

void gather_batch(const double* x0, const double* x1, std::span<const std::array<Index, 3>> faces,
                  MovingTriangleBatch& batch) {
  lanes::widest(detail::gather_batch_four_lanes, detail::gather_batch_one_by_one)(x0, x1, faces,
                                                                                  batch);
}

void pad_to_eight_lanes(MovingTriangleBatch& batch) {
  const int padded = (batch.count + 7) & ~7;
  for (int row = 0; row < 18; ++row) {
    for (int i = batch.count; i < padded; ++i) batch.coordinate[row][i] = batch.coordinate[row][0];
  }
}

}  // namespace tailor
