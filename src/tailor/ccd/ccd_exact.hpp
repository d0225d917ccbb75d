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

/// The coplanarity cubic's Bernstein coefficients in double with certified error bounds
/// (geometry/coplanarity_sign.hpp; value[1], value[2] are 3 b1, 3 b2), computed once per
/// query and shared by the filter and the double tier. `valid` is false when an input is
/// outside the guarded range (then only the exact tier may decide).
struct CoplanarityBernstein {
  bool valid = false;
  double value[4] = {0, 0, 0, 0};
  double bound[4] = {0, 0, 0, 0};
};

CoplanarityBernstein coplanarity_bernstein(const VertexFaceQuery& query);
CoplanarityBernstein coplanarity_bernstein(const EdgeEdgeQuery& query);

/// Certified double VF CCD: the answer (path = double_precision) when every decision it
/// makes is certified by rigorous error bounds, nullopt when it cannot decide. When it
/// answers, the exact tier gives the same `hit`, and both toi bounds are valid.
std::optional<CcdResult> vertex_face_ccd_double(const VertexFaceQuery& query);

/// Certified double EE CCD; see vertex_face_ccd_double.
std::optional<CcdResult> edge_edge_ccd_double(const EdgeEdgeQuery& query);

/// The double tiers with the filter's coefficients already computed.
std::optional<CcdResult> vertex_face_ccd_double(const VertexFaceQuery& query,
                                                const CoplanarityBernstein& filter);
std::optional<CcdResult> edge_edge_ccd_double(const EdgeEdgeQuery& query,
                                              const CoplanarityBernstein& filter);

}  // namespace tailor::detail
