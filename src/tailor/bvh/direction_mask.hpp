#pragma once
/// @file
/// Direction masks: which of 26 fixed directions make an acute angle with every normal of
/// a set of moving triangles over the whole step. They are the continuous normal cones of
/// the culling (Tang et al., ICCD 2009) in the discretised form of Volino &
/// Magnenat-Thalmann's direction sets (1994), certified in floating point.
///
/// Why a mask and not a cone (axis and half-angle): a cone merged from its children's
/// cones is wider than the smallest cone of the faces (the merge sees only the children's
/// cones), and the excess grows with every level, so a large patch whose normals all lie
/// within 90° of some direction is rarely certified at its own level. A mask merges
/// exactly (bitwise and): a node's mask holds d exactly when every face below it does.
/// A height-field cloth of a million triangles is certified at its root by +z, where
/// merged cones stopped a dozen levels lower (1.02 M candidate pairs). The price is
/// coarseness: a patch is certified only if one of the 26 directions lies within 90° of
/// all its normals, which holds whenever its normals fit a cone of half-angle below
/// 90° minus the covering radius of the 26 directions (27.6°: so below 62°). Measured on
/// the sleeve, cloth-funnel and the folded cloth, masks alone leave as many candidate
/// pairs as masks and cones together (within 2.5 %) and fewer than cones alone.
///
/// The bound. For a triangle moving linearly, n(t) = (b-a)×(c-a) is quadratic in t with
/// Bézier control normals n0, nX, n1 (nonnegative weights), so n(t)·d > 0 for all t when
/// n_i·d > 0 for i = 0, X, 1. With m the computed nX and δ >= max_i |ñ_i - m|₁ (ñ_i the
/// computed control normals), |(ñ_i - m)·d| <= δ for every d with components in
/// {-1, 0, 1}; so m·d > δ + (rounding and error bounds) proves the bit. One dot product per
/// direction and triangle instead of three, and a bound that stays tight when the normal
/// turns little during the step (as it does in cloth steps).
///
/// In float. The edge vectors are differences of the double corners rounded to float, and
/// the normals, dot products and bounds are float arithmetic (the error analysis in
/// direction_mask.cpp counts both roundings): sixteen triangles per AVX-512 register, so a
/// whole batch in one pass. The bound is relatively 2^-19 where double gave 2^-48: only a
/// normal within about 10^-5 of perpendicular to a direction loses that bit. The price is
/// range: edges longer than about 10^18 overflow a product, and normals shorter than about
/// 10^-37 fall under the bound's constant; both certify no direction (never a wrong one).
/// (The refit of the crumpling cloth, one thread, with the masks in double eight lanes at
/// a time against float sixteen lanes: 100K triangles 1.31-1.36 against 1.19-1.23 ms, 1M
/// 14.4-14.9 against 13.5-13.7 ms.)

#include <array>
#include <cstdint>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// Bit 2j is the direction +c_j, bit 2j + 1 is -c_j, for the 13 directions c_j with
/// components in {-1, 0, 1} whose first nonzero component is +1 (the axes, the face
/// diagonals and the cube diagonals of the unit cube).
using DirectionMask = std::uint32_t;

/// Number of directions a mask can hold.
inline constexpr int kMaskDirections = 26;
/// The mask of every direction (the neutral element of merging).
inline constexpr DirectionMask kAllDirections = (DirectionMask{1} << kMaskDirections) - 1;

/// Direction of bit `k` (components in {-1, 0, 1}, not normalised).
Vec3 mask_direction(int k);

/// The sum of the directions of a nonzero `mask` (integer components, exact): within 90°
/// of every normal the mask certifies (a positive combination of directions that all are)
/// and central among them, so that a projection along it distorts the least. The first
/// direction alone is often nearly perpendicular to some normal, and the contour test then
/// fails on a projected contour too thin to certify (the bending sleeve of 299K triangles:
/// 12,091 of 14,524 contour tests failed with the first direction, 1,590 of 2,259 with
/// the sum; candidate pairs 659,340 against 261,098).
Vec3 mask_axis(DirectionMask mask);

/// Up to kCapacity moving triangles in structure-of-arrays form, so that the mask of all of
/// them is computed in vectorisable loops. Corner k ∈ {a, b, c} at frame s ∈ {0, 1},
/// coordinate j is `coordinate[(3·s + k)·3 + j][i]` for triangle i.
struct MovingTriangleBatch {
  /// Most triangles a batch holds (lanes).
  static constexpr int kCapacity = 16;
  /// Corner coordinates, one lane per triangle (layout above).
  alignas(64) double coordinate[18][kCapacity];
  /// Number of triangles added (<= kCapacity).
  int count = 0;

  /// Appends a triangle moving from (a0, b0, c0) to (a1, b1, c1) (3 doubles each);
  /// count < kCapacity.
  void add(const double* a0, const double* b0, const double* c0, const double* a1, const double* b1,
           const double* c1) {
    const double* corners[6] = {a0, b0, c0, a1, b1, c1};
    for (int p = 0; p < 6; ++p) {
      for (int j = 0; j < 3; ++j) coordinate[3 * p + j][count] = corners[p][j];
    }
    ++count;
  }
  /// Number of lanes the kernels read: count rounded up to a multiple of four (the widest
  /// kernel), so that a batch of a few triangles costs a few lanes, not kCapacity.
  int padded_count() const { return (count + 3) & ~3; }
  /// Fills the lanes from `count` to padded_count() with copies of lane 0 (count >= 1), so
  /// that kernels run over whole vectors without changing any result.
  void pad() {
    for (int row = 0; row < 18; ++row) {
      for (int i = count; i < padded_count(); ++i) coordinate[row][i] = coordinate[row][0];
    }
  }
};

/// The mask of each triangle of a batch, lane by lane.
using LaneMasks = std::array<DirectionMask, MovingTriangleBatch::kCapacity>;

/// The bits k for which n(t)·d_k > 0 for every t in [0, 1], for each triangle i of the
/// batch: `masks[i]` for i < count (the entries past it are unspecified). The batch must be
/// padded (pad()) when it is not full; lanes past padded_count() are never read.
/// Certified: rounding errors (including underflow) are bounded; an edge or product beyond
/// the float range, or a NaN coordinate, clears every bit.
void lane_masks(const MovingTriangleBatch& batch, LaneMasks& masks);

/// The and of masks[begin] to masks[end - 1] (kAllDirections when empty): the mask of those
/// triangles together.
DirectionMask and_of_masks(const LaneMasks& masks, int begin, int end);

/// The mask of all the triangles of a batch (the and of lane_masks(); kAllDirections for
/// an empty batch).
DirectionMask direction_mask(const MovingTriangleBatch& batch);

namespace detail {
/// lane_masks() four triangles at a time (SSE2: every x86-64 processor), eight at a time
/// (AVX2: call only when direction_mask_has_avx2()) and sixteen (AVX-512 F and DQ: call
/// only when direction_mask_has_avx512()). Each lane does the same float operations, so
/// they agree bit for bit; lane_masks() picks the widest at run time, and they are exposed
/// so that a test can check that they agree. They write the masks of the lanes up to
/// padded_count() and may write others.
void lane_masks_sse2(const MovingTriangleBatch& batch, LaneMasks& masks);
void lane_masks_avx2(const MovingTriangleBatch& batch, LaneMasks& masks);
void lane_masks_avx512(const MovingTriangleBatch& batch, LaneMasks& masks);
bool direction_mask_has_avx2();
bool direction_mask_has_avx512();
}  // namespace detail

/// The mask of one triangle moving from (a0, b0, c0) to (a1, b1, c1).
DirectionMask direction_mask(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& a1,
                             const Vec3& b1, const Vec3& c1);

}  // namespace tailor
