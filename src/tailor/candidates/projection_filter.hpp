#pragma once
/// @file
/// The projection filter: a certified test that a vertex-face or edge-edge pair cannot
/// touch during the step because its projection along one fixed direction cannot, at any
/// time at which the four points are coplanar. It runs after the non-coplanarity (DNF)
/// filter of Tang, Manocha & Tong 2010 and removes what that filter cannot: a vertex that
/// crosses the plane of a face outside the face, edges that cross each other's plane
/// beside each other, and pairs that stay coplanar while sliding apart.
///
/// Why it never drops a contact. Let D be any fixed vector and [u, w, D] = (u×w)·D.
/// - Vertex p, triangle abc. If p = a + λb(b-a) + λc(c-a) lies in the closed triangle
///   (λa, λb, λc >= 0) then, with o = [b-a, c-a, D],
///   s_ab = [b-a, p-a, D] = λc·o,  s_bc = [c-b, p-b, D] = λa·o,  s_ca = [a-c, p-c, D] = λb·o,
///   so at the contact time no two of s_ab, s_bc, s_ca have strictly opposite signs, and
///   none has the strict sign opposite to o.
/// - Edges ab and cd. If a + σ(b-a) = c + ρ(d-c), σ, ρ in [0, 1], then with
///   m = [b-a, d-c, D]: g_c = [b-a, c-a, D] = -ρm, g_d = [b-a, d-a, D] = (1-ρ)m,
///   h_a = [d-c, a-c, D] = σm, h_b = [d-c, b-c, D] = -(1-σ)m; so neither g_c, g_d nor
///   h_a, h_b share one strict sign, and with m of strict sign s: g_c ≠ s, g_d ≠ -s,
///   h_a ≠ -s, h_b ≠ s (as strict signs).
/// These are identities, valid for every D (degenerate triangles, parallel edges, D = 0
/// included). With linear motion each bracket is a quadratic in t and the coplanarity
/// function f (which vanishes at every contact) a cubic; a piece of the step is excluded
/// when f or one of the sign patterns above is certified strictly on the whole piece
/// (CertifiedBernstein), and the pair is culled when a dyadic subdivision of [0, 1]
/// excludes every piece. D only decides how sharp the test is: the coordinate axis along
/// which the triangle's normal (or the cross product of the two edges; for parallel edges
/// the normal of the plane through ab and c) at mid-step is largest, so the projection
/// keeps the pair's shape and each bracket is a 2x2 determinant.
///
/// Certified evaluation: every difference of two input coordinates is rounded once; a
/// coefficient of a bracket is one 2x2 determinant e_i·w_j - e_j·w_i of such differences
/// or the half sum of two, at most 5 roundings along each term, so its error is below
/// 16·2^-53·(the same expression on absolute values) (as in geometry/coplanarity_sign.hpp).
/// That holds while no product underflows or overflows: nonzero differences must lie in
/// [2^-250, 2^250], otherwise the filter keeps the pair. The coplanarity cubic comes with
/// the certified bounds of geometry/coplanarity_sign.hpp, and restricting a polynomial to
/// half its domain adds a certified rounding bound (CertifiedBernstein::split).

#include <cstdint>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// What the low-level filters decide for one pair.
enum class PairVerdict : std::uint8_t {
  never_coplanar,       ///< the four points are never coplanar (the DNF filter)
  apart_in_projection,  ///< coplanar only while the projections are apart (this filter)
  may_touch,            ///< neither filter excludes a contact: the exact CCD decides
};

/// Which filters vertex_face_verdict / edge_edge_verdict apply.
struct PairFilters {
  bool coplanarity = true;  ///< the non-coplanarity (DNF) filter (exact: geometry/coplanarity_sign)
  bool projection = true;   ///< this file's filter
};

/// The verdict of the enabled filters for vertex `p` against the closed triangle `abc`,
/// every point moving linearly from its t0 to its t1 position. The coplanarity cubic is
/// evaluated once for both filters; the tests run cheapest first: the DNF's certified
/// double signs, the projection filter, and only then the DNF's exact evaluation (so a
/// pair that both would cull is reported apart_in_projection).
PairVerdict vertex_face_verdict(const FourPoints& at_t0, const FourPoints& at_t1,
                                PairFilters filters);

/// The verdict of the enabled filters for the closed segments `ab` and `cd`.
PairVerdict edge_edge_verdict(const FourPoints& at_t0, const FourPoints& at_t1,
                              PairFilters filters);

/// The projection filter alone: false only when vertex `p` certainly never touches the
/// closed triangle `abc` (see the file comment); true when it may.
inline bool vertex_face_may_touch_in_projection(const FourPoints& at_t0, const FourPoints& at_t1) {
  return vertex_face_verdict(at_t0, at_t1, {false, true}) == PairVerdict::may_touch;
}

/// The projection filter alone for the closed segments `ab` and `cd`.
inline bool edge_edge_may_touch_in_projection(const FourPoints& at_t0, const FourPoints& at_t1) {
  return edge_edge_verdict(at_t0, at_t1, {false, true}) == PairVerdict::may_touch;
}

}  // namespace tailor
