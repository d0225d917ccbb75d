#pragma once
/// @file
/// Exact continuous collision detection for one vertex-face or edge-edge pair whose
/// vertices move linearly over the step t in [0, 1].

#include <array>
#include <cstdint>
#include <span>

#include "tailor/geometry/types.hpp"

namespace tailor {

/// Which stage of the CCD decided a query.
enum class CcdPath : std::uint8_t {
  filter,            ///< the certified non-coplanarity (Bernstein sign) filter
  double_precision,  ///< the double tier with certified error bounds
  exact_signs,       ///< the double tier, with signs too close to zero settled exactly
  exact,             ///< the exact tier on fixed-size integers (no heap, no GMP)
  gmp,               ///< the exact tier's last resort on GMP integers (numbers too wide)
};

/// Number of CcdPath values.
inline constexpr int kCcdPathCount = 5;

/// Short name of a path: "filter", "double", "exact_signs", "exact", "gmp".
const char* ccd_path_name(CcdPath path);

/// The answer for one query.
struct CcdResult {
  bool hit = false;  ///< the primitives touch at some t in [0, 1] (exactly)
  /// Time of impact when hit: never later than the earliest true contact and within 1e-6
  /// of it. 1 when there is no hit.
  double toi = 1.0;
  /// The stage that decided the query.
  CcdPath path = CcdPath::filter;
};

/// A vertex-face query: `p` against triangle `(a, b, c)`, each at t=0 and t=1.
struct VertexFaceQuery {
  ///@{
  /// Vertex and triangle corners at t=0.
  Vec3 p_t0, a_t0, b_t0, c_t0;
  ///@}
  ///@{
  /// Vertex and triangle corners at t=1.
  Vec3 p_t1, a_t1, b_t1, c_t1;
  ///@}
};

/// An edge-edge query: edge `(a0, a1)` against edge `(b0, b1)`, each at t=0 and t=1.
struct EdgeEdgeQuery {
  ///@{
  /// Endpoints of edge a and edge b at t=0.
  Vec3 ea0_t0, ea1_t0, eb0_t0, eb1_t0;
  ///@}
  ///@{
  /// Endpoints of edge a and edge b at t=1.
  Vec3 ea0_t1, ea1_t1, eb0_t1, eb1_t1;
  ///@}
};

/// Does the point meet the closed triangle at some t in [0, 1]? Exact on the input doubles
/// (every degenerate case included; invariant under scaling all coordinates by a power of
/// two). Decided by the coplanarity filter, else the certified double path, else the exact
/// rational path. Throws std::invalid_argument on a non-finite coordinate that reaches the
/// exact path.
CcdResult vertex_face_ccd(const VertexFaceQuery& query);

/// Do the two closed segments share a point at some t in [0, 1]? Exact on the input doubles;
/// see vertex_face_ccd.
CcdResult edge_edge_ccd(const EdgeEdgeQuery& query);

/// Batch form (oneTBB parallel): `results` must have the size of `queries` (else
/// std::invalid_argument). Results do not depend on the number of threads.
void vertex_face_ccd(std::span<const VertexFaceQuery> queries, std::span<CcdResult> results);
/// Batch form of edge_edge_ccd; see the vertex-face batch form.
void edge_edge_ccd(std::span<const EdgeEdgeQuery> queries, std::span<CcdResult> results);

}  // namespace tailor
