#include "tailor/bvh/group_boxes.hpp"

#include <immintrin.h>

#include "tailor/bvh/lane_vectors.hpp"

namespace tailor {
namespace {

static_assert(sizeof(FloatBox) == 6 * sizeof(float), "a box is six contiguous floats");

FloatBox& box_at(FloatBox* first, std::size_t stride, int node) {
  return *reinterpret_cast<FloatBox*>(reinterpret_cast<char*>(first) +
                                      stride * static_cast<std::size_t>(node));
}

// A box as one vector (min x, y, z, -max x, y, z, -, -): the union of two is their
// minimum. Each record's 32 bytes are written at once, the eight after the box with the
// value they held.
[[gnu::target("avx2")]] void one_vector_per_box(const BatchBounds& bounds, int first_lane,
                                                std::uint32_t leaf_bits, int count, FloatBox* first,
                                                std::size_t stride) {
  // The box just written stays in a register (`top`): the next inner node joins it with
  // the box below it on the stack, so the chain of joins never waits on a store to the
  // stack and its load back (that round trip was the kernel's critical path).
  __m256 below[MovingTriangleBatch::kCapacity];
  int depth = 0;  // boxes in `below`
  __m256 top = _mm256_setzero_ps();
  const __m256 negate_max = _mm256_setr_ps(0.0f, 0.0f, 0.0f, -0.0f, -0.0f, -0.0f, 0.0f, 0.0f);
  int lane = first_lane + count - 1;
  for (int node = 2 * count - 2; node >= 0; --node) {
    if ((leaf_bits >> node) & 1) {
      if (node != 2 * count - 2) below[depth++] = top;
      top = _mm256_setr_ps(bounds.low[0][lane], bounds.low[1][lane], bounds.low[2][lane],
                           -bounds.high[0][lane], -bounds.high[1][lane], -bounds.high[2][lane],
                           0.0f, 0.0f);
      --lane;
    } else {
      top = _mm256_min_ps(top, below[--depth]);
    }
    auto* record = reinterpret_cast<float*>(&box_at(first, stride, node));
    _mm256_storeu_ps(
        record, _mm256_blend_ps(_mm256_xor_ps(top, negate_max), _mm256_loadu_ps(record), 0xc0));
  }
}

DiagonalBox& diagonal_box_at(DiagonalBox* first, std::size_t stride, int node) {
  return *reinterpret_cast<DiagonalBox*>(reinterpret_cast<char*>(first) +
                                         stride * static_cast<std::size_t>(node));
}

static_assert(sizeof(DiagonalBox) == 8 * sizeof(float), "a diagonal box is eight floats");

// One vector per diagonal box, (min 0-3, -max 0-3), as in one_vector_per_box().
[[gnu::target("avx2")]] void diagonal_boxes_avx2(const DiagonalBatchBounds& bounds, int first_lane,
                                                 std::uint32_t leaf_bits, int count,
                                                 DiagonalBox* first, std::size_t stride) {
  __m256 below[MovingTriangleBatch::kCapacity];
  int depth = 0;
  __m256 top = _mm256_setzero_ps();
  const __m256 negate_max = _mm256_setr_ps(0.0f, 0.0f, 0.0f, 0.0f, -0.0f, -0.0f, -0.0f, -0.0f);
  int lane = first_lane + count - 1;
  for (int node = 2 * count - 2; node >= 0; --node) {
    if ((leaf_bits >> node) & 1) {
      if (node != 2 * count - 2) below[depth++] = top;
      top = _mm256_setr_ps(bounds.low[0][lane], bounds.low[1][lane], bounds.low[2][lane],
                           bounds.low[3][lane], -bounds.high[0][lane], -bounds.high[1][lane],
                           -bounds.high[2][lane], -bounds.high[3][lane]);
      --lane;
    } else {
      top = _mm256_min_ps(top, below[--depth]);
    }
    _mm256_storeu_ps(reinterpret_cast<float*>(&diagonal_box_at(first, stride, node)),
                     _mm256_xor_ps(top, negate_max));
  }
}

}  // namespace

namespace detail {

void write_group_diagonal_boxes_sse2(const DiagonalBatchBounds& bounds, int first_lane,
                                     std::uint32_t leaf_bits, int count, DiagonalBox* first,
                                     std::size_t stride) {
  // Two vectors per box, (min 0-3) and (-max 0-3), as in write_group_boxes_sse2().
  __m128 below_min[MovingTriangleBatch::kCapacity], below_max[MovingTriangleBatch::kCapacity];
  int depth = 0;
  __m128 low = _mm_setzero_ps(), negated_high = _mm_setzero_ps();
  int lane = first_lane + count - 1;
  for (int node = 2 * count - 2; node >= 0; --node) {
    if ((leaf_bits >> node) & 1) {
      if (node != 2 * count - 2) below_min[depth] = low, below_max[depth] = negated_high, ++depth;
      low = _mm_setr_ps(bounds.low[0][lane], bounds.low[1][lane], bounds.low[2][lane],
                        bounds.low[3][lane]);
      negated_high = _mm_setr_ps(-bounds.high[0][lane], -bounds.high[1][lane],
                                 -bounds.high[2][lane], -bounds.high[3][lane]);
      --lane;
    } else {
      --depth;
      low = _mm_min_ps(low, below_min[depth]);
      negated_high = _mm_min_ps(negated_high, below_max[depth]);
    }
    auto* record = reinterpret_cast<float*>(&diagonal_box_at(first, stride, node));
    _mm_storeu_ps(record, low);
    _mm_storeu_ps(record + 4, _mm_xor_ps(negated_high, _mm_set1_ps(-0.0f)));
  }
}

void write_group_diagonal_boxes_avx2(const DiagonalBatchBounds& bounds, int first_lane,
                                     std::uint32_t leaf_bits, int count, DiagonalBox* first,
                                     std::size_t stride) {
  diagonal_boxes_avx2(bounds, first_lane, leaf_bits, count, first, stride);
}

void write_group_boxes_sse2(const BatchBounds& bounds, int first_lane, std::uint32_t leaf_bits,
                            int count, FloatBox* first, std::size_t stride) {
  // Two vectors per box, (min x, y, z, -) and (-max x, y, z, -): a union is two minima. The
  // box just written stays in registers, as in one_vector_per_box().
  __m128 below_min[MovingTriangleBatch::kCapacity], below_max[MovingTriangleBatch::kCapacity];
  int depth = 0;
  __m128 low = _mm_setzero_ps(), negated_high = _mm_setzero_ps();
  int lane = first_lane + count - 1;
  for (int node = 2 * count - 2; node >= 0; --node) {
    if ((leaf_bits >> node) & 1) {
      if (node != 2 * count - 2) below_min[depth] = low, below_max[depth] = negated_high, ++depth;
      low = _mm_setr_ps(bounds.low[0][lane], bounds.low[1][lane], bounds.low[2][lane], 0.0f);
      negated_high =
          _mm_setr_ps(-bounds.high[0][lane], -bounds.high[1][lane], -bounds.high[2][lane], 0.0f);
      --lane;
    } else {
      --depth;
      low = _mm_min_ps(low, below_min[depth]);
      negated_high = _mm_min_ps(negated_high, below_max[depth]);
    }
    const __m128 high = _mm_xor_ps(negated_high, _mm_set1_ps(-0.0f));
    // (min x, y, z, max x) and (max y, z): the six floats of the box and nothing more.
    const __m128 z_x = _mm_shuffle_ps(low, high, _MM_SHUFFLE(0, 0, 2, 2));
    auto* box = reinterpret_cast<float*>(&box_at(first, stride, node));
    _mm_storeu_ps(box, _mm_shuffle_ps(low, z_x, _MM_SHUFFLE(2, 0, 1, 0)));
    _mm_storel_pi(reinterpret_cast<__m64*>(box + 4),
                  _mm_shuffle_ps(high, high, _MM_SHUFFLE(3, 3, 2, 1)));
  }
}

void write_group_boxes_avx2(const BatchBounds& bounds, int first_lane, std::uint32_t leaf_bits,
                            int count, FloatBox* first, std::size_t stride) {
  one_vector_per_box(bounds, first_lane, leaf_bits, count, first, stride);
}

}  // namespace detail

void write_group_boxes(const BatchBounds& bounds, int first_lane, std::uint32_t leaf_bits,
                       int count, FloatBox* first, std::size_t stride) {
  lanes::widest(detail::write_group_boxes_avx2, detail::write_group_boxes_sse2)(
      bounds, first_lane, leaf_bits, count, first, stride);
}

void write_group_diagonal_boxes(const DiagonalBatchBounds& bounds, int first_lane,
                                std::uint32_t leaf_bits, int count, DiagonalBox* first,
                                std::size_t stride) {
  lanes::widest(detail::write_group_diagonal_boxes_avx2, detail::write_group_diagonal_boxes_sse2)(
      bounds, first_lane, leaf_bits, count, first, stride);
}

}  // namespace tailor
