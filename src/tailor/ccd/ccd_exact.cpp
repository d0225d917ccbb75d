/// @file
/// Entry points of the exact tier: the query's doubles as exact integers relative to its
/// first point, then the decision of exact_contact.hpp on FixedInt, or on BigInt when a
/// number does not fit.

#include "tailor/ccd/ccd_exact.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "tailor/ccd/big_int.hpp"
#include "tailor/ccd/exact_contact.hpp"
#include "tailor/geometry/common_scale_integers.hpp"
#include "tailor/geometry/fixed_int.hpp"

namespace tailor::detail {

namespace {

/// 32 limbs (2048 bits): the largest intermediate of the exact tier is about 16 times the
/// bit width of the query's coordinate differences (a pseudo-remainder chain), so every
/// query whose coordinates span up to ~120 bits (after the common power-of-two scaling)
/// stays on the stack; float data spans ~30, double data of one scene ~50-100. Only the
/// used limbs are ever touched or copied, so the capacity costs stack space, not time.
using Fixed = FixedInt<32>;

using Points = std::array<const Vec3*, 8>;  // four points at t0, then the same at t1

void check_finite(const Points& x) {
  for (const Vec3* p : x) {
    if (!p->allFinite()) throw std::invalid_argument("ccd: non-finite coordinate");
  }
}

/// Points 1..3 minus point 0, as linear polynomials in t, all coordinates scaled by one
/// power of two that makes them integers (which scales every condition by a positive
/// constant: signs and roots do not change).
template <class Z>
std::array<PolyVec<Z>, 3> relative_polys(const Points& x) {
  const auto value = common_scale_integers<Z>(x);
  std::array<PolyVec<Z>, 3> out;
  for (int i = 1; i <= 3; ++i) {
    Poly<Z>* comp[3] = {&out[i - 1].x, &out[i - 1].y, &out[i - 1].z};
    for (int k = 0; k < 3; ++k) {
      const Z d0 = value[i][k] - value[0][k];
      const Z d1 = value[i + 4][k] - value[4][k];
      *comp[k] = Poly<Z>::linear(d0, d1 - d0);
    }
  }
  return out;
}

CcdResult to_result(const std::optional<double>& toi, CcdPath path) {
  return toi ? CcdResult{true, *toi, path} : CcdResult{false, 1.0, path};
}

template <class Z>
CcdResult vertex_face_with(const VertexFaceQuery& q, CcdPath path) {
  const auto rel =
      relative_polys<Z>({&q.a_t0, &q.b_t0, &q.c_t0, &q.p_t0, &q.a_t1, &q.b_t1, &q.c_t1, &q.p_t1});
  const VfPolys<Z> s(rel[0], rel[1], rel[2]);
  return to_result(earliest_contact<Z>(s), path);
}

template <class Z>
CcdResult edge_edge_with(const EdgeEdgeQuery& q, CcdPath path) {
  const auto rel = relative_polys<Z>(
      {&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0, &q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1});
  const EePolys<Z> s(rel[0], rel[1], rel[2]);
  return to_result(earliest_contact<Z>(s), path);
}

/// Exact signs of the listed conditions at the root of s.f in (lo, hi).
template <class Z, class Polys, class Condition>
void signs_at_root(const Polys& s, Condition&& condition, const IsolatedRoot& root,
                   std::span<const int> which, int* signs) {
  RootPoint<Z> r = RootPoint<Z>::isolated(s.f, Dyadic<Z>::from_double(root.lo),
                                          Dyadic<Z>::from_double(root.hi), root.sign_lo);
  for (std::size_t i = 0; i < which.size(); ++i) {
    const Poly<Z>& q = condition(which[i]);
    // The double tier could not separate these from zero: test for zero first.
    signs[i] =
        r.kind == RootPoint<Z>::Kind::isolated && vanishes_at_isolated(q, r) ? 0 : sign_at(q, r);
  }
}

}  // namespace

bool vertex_face_signs_at_root(const VertexFaceQuery& q, int axis, const IsolatedRoot& root,
                               std::span<const int> which, int* signs) {
  try {
    const auto rel = relative_polys<Fixed>(
        {&q.a_t0, &q.b_t0, &q.c_t0, &q.p_t0, &q.a_t1, &q.b_t1, &q.c_t1, &q.p_t1});
    const VfPolys<Fixed> s(rel[0], rel[1], rel[2]);
    signs_at_root<Fixed>(
        s,
        [&](int c) -> const Poly<Fixed>& {
          return c == 0 ? component(s.n, axis) : s.edge(c - 1, axis);
        },
        root, which, signs);
    return true;
  } catch (const CapacityExceeded&) {
    return false;
  }
}

bool edge_edge_signs_at_root(const EdgeEdgeQuery& q, int axis, const IsolatedRoot& root,
                             std::span<const int> which, int* signs) {
  try {
    const auto rel = relative_polys<Fixed>(
        {&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0, &q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1});
    const EePolys<Fixed> s(rel[0], rel[1], rel[2]);
    signs_at_root<Fixed>(
        s,
        [&](int c) -> const Poly<Fixed>& {
          return c == 0 ? component(s.m, axis) : s.orientation(c - 1, axis);
        },
        root, which, signs);
    return true;
  } catch (const CapacityExceeded&) {
    return false;
  }
}

CcdResult vertex_face_ccd_exact(const VertexFaceQuery& q) {
  check_finite({&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0, &q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1});
  try {
    return vertex_face_with<Fixed>(q, CcdPath::exact);
  } catch (const CapacityExceeded&) {
    return vertex_face_with<BigInt>(q, CcdPath::gmp);
  }
}

CcdResult edge_edge_ccd_exact(const EdgeEdgeQuery& q) {
  check_finite(
      {&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0, &q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1});
  try {
    return edge_edge_with<Fixed>(q, CcdPath::exact);
  } catch (const CapacityExceeded&) {
    return edge_edge_with<BigInt>(q, CcdPath::gmp);
  }
}

CcdResult vertex_face_ccd_exact_gmp(const VertexFaceQuery& q) {
  check_finite({&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0, &q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1});
  return vertex_face_with<BigInt>(q, CcdPath::gmp);
}

CcdResult edge_edge_ccd_exact_gmp(const EdgeEdgeQuery& q) {
  check_finite(
      {&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0, &q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1});
  return edge_edge_with<BigInt>(q, CcdPath::gmp);
}

}  // namespace tailor::detail
