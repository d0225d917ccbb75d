#pragma once
/// @file
/// The tiers behind vertex_face_ccd / edge_edge_ccd, exposed separately so tests and
/// benchmarks can compare them: the certified double tier (decides most queries, or says
/// it cannot) and the exact tier (always decides). Internal to the ccd module.

#include <optional>
#include <span>

#include "tailor/ccd/ccd.hpp"

namespace tailor::detail {

/// Exact VF CCD: fixed-size integers (path = exact), or, when a number outgrows them,
/// the same algorithm on GMP integers (path = gmp). Throws std::invalid_argument on a
/// non-finite coordinate.
CcdResult vertex_face_ccd_exact(const VertexFaceQuery& query);

/// Exact EE CCD; see vertex_face_ccd_exact.
CcdResult edge_edge_ccd_exact(const EdgeEdgeQuery& query);

/// The exact tier's algorithm on GMP integers only (path = gmp): the last resort, exposed
/// so tests can check that instantiation too.
CcdResult vertex_face_ccd_exact_gmp(const VertexFaceQuery& query);
/// EE form of vertex_face_ccd_exact_gmp.
CcdResult edge_edge_ccd_exact_gmp(const EdgeEdgeQuery& query);

/// A root of the coplanarity function f certified by the double tier: f has sign `sign_lo`
/// at `lo`, -sign_lo at `hi`, and one simple root between.
struct IsolatedRoot {
  double lo = 0;    ///< below the root
  double hi = 0;    ///< above the root
  int sign_lo = 0;  ///< sign of f at lo (±1)
};

/// The double tier's exact assist: exact signs of some projected conditions
/// (ccd_systems.hpp) along `axis` at the only root of f in (lo, hi), which the caller has
/// certified (f has signs sign_lo at lo and -sign_lo at hi, and one simple root between).
/// VF conditions: 0 n_k, 1 ((b-a)×(p-a))_k, 2 ((c-b)×(p-b))_k, 3 ((a-c)×(p-c))_k.
/// EE conditions: 0 m_k, 1 ((b-a)×(c-a))_k, 2 ((b-a)×(d-a))_k, 3 ((d-c)×(a-c))_k,
/// 4 ((d-c)×(b-c))_k. Fills signs[i] for which[i]; false when the fixed-size integers
/// overflow (the caller then hands the query to the exact tier).
bool vertex_face_signs_at_root(const VertexFaceQuery& query, int axis, const IsolatedRoot& root,
                               std::span<const int> which, int* signs);
/// EE form of vertex_face_signs_at_root.
bool edge_edge_signs_at_root(const EdgeEdgeQuery& query, int axis, const IsolatedRoot& root,
                             std::span<const int> which, int* signs);

}  // namespace tailor::detail
