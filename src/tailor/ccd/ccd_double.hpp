#pragma once
/// @file
/// The certified double tier of the exact CCD (ccd_double.cpp): the coplanarity cubic in
/// double with rigorous error bounds, roots bracketed and the projected conditions decided
/// in ball arithmetic, with the exact tier's sign assist (ccd_exact.hpp) at a root it
/// cannot separate. It answers when every decision is certified, and leaves the rest to the
/// exact tier. Internal to the ccd module.

#include <optional>

#include "tailor/ccd/ccd.hpp"

namespace tailor::detail {

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
