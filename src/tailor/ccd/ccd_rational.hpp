#pragma once
/// @file
/// The rational reference CCD: GMP rationals, Sturm root isolation and exact signs at
/// algebraic roots over the complete VF/EE formulation of ccd_systems.hpp. Correct on every
/// finite input but slow (~300 µs a query, milliseconds for exponent spreads of thousands
/// of bits); the library never calls it. It is the oracle the fast tiers are tested
/// against (tests, benchmarks, the degenerate query set).

#include "tailor/ccd/ccd.hpp"

namespace tailor::detail {

/// Exact VF CCD in rational arithmetic; path = exact. Throws std::invalid_argument on a
/// non-finite coordinate.
CcdResult vertex_face_ccd_rational(const VertexFaceQuery& query);

/// Exact EE CCD in rational arithmetic; path = exact. Throws std::invalid_argument on a
/// non-finite coordinate.
CcdResult edge_edge_ccd_rational(const EdgeEdgeQuery& query);

}  // namespace tailor::detail
