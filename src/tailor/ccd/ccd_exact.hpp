#pragma once
/// @file
/// The two decision paths behind vertex_face_ccd / edge_edge_ccd, exposed separately so
/// tests can compare them: the exact rational path (always decides) and the certified
/// double path (decides most queries, or says it cannot).

#include <optional>

#include "tailor/ccd/ccd.hpp"

namespace tailor::detail {

/// Exact VF CCD (GMP rationals, exact root isolation); path = exact. Throws
/// std::invalid_argument on a non-finite coordinate.
CcdResult vertex_face_ccd_exact(const VertexFaceQuery& query);

/// Exact EE CCD (GMP rationals, exact root isolation); path = exact. Throws
/// std::invalid_argument on a non-finite coordinate.
CcdResult edge_edge_ccd_exact(const EdgeEdgeQuery& query);

/// Certified double VF CCD: the answer (path = double_precision) when every decision it
/// makes is certified by rigorous interval bounds, nullopt when it cannot decide. When it
/// answers, the exact path gives the same `hit`, and both toi bounds are valid.
std::optional<CcdResult> vertex_face_ccd_double(const VertexFaceQuery& query);

/// Certified double EE CCD; see vertex_face_ccd_double.
std::optional<CcdResult> edge_edge_ccd_double(const EdgeEdgeQuery& query);

}  // namespace tailor::detail
