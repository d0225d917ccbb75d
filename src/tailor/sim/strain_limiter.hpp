#pragma once
/// @file
/// Iterative strain limiting on the edges of a cloth mesh (Provot 1995; Bridson, Fedkiw &
/// Anderson 2002 §6.2 apply it to the velocities the same way): after the implicit step,
/// every edge longer than `(1 + max_strain)` times its rest length is shortened back to
/// that length by moving its two vertices towards each other in proportion to their
/// inverse masses (pinned vertices do not move). Gauss-Seidel sweeps, ordered outwards
/// from the pinned vertices and alternating direction, until no edge is over the limit.
///
/// Woven cloth barely stretches (a cotton shirting reaches its KES extensibility EMT of a
/// few percent only under 500 gf/cm), so a stiff-enough membrane would need tiny steps;
/// the limiter lets the implicit solve use a real fabric's stiffness at the frame rate
/// and still keeps every edge within the limit. Compression is not limited: cloth buckles.

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "tailor/geometry/types.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor {

/// What one call to StrainLimiter::apply did.
struct StrainLimitStats {
  int sweeps = 0;                ///< Gauss-Seidel sweeps run
  std::int64_t corrections = 0;  ///< edge corrections applied over all sweeps
  double max_strain_before = 0;  ///< largest edge strain met in the first sweep
  double max_strain_after = 0;   ///< largest edge strain on return
};

/// Largest and 99th-percentile edge strain (`length / rest length - 1`) of a state.
struct StrainSummary {
  double max = 0;  ///< largest strain
  double p99 = 0;  ///< 99th percentile
};

/// Edge strains of `x` relative to `rest` (one per edge of `mesh`).
std::vector<double> edge_strains(const TriangleMesh& mesh, const Positions& rest,
                                 const Positions& x);
/// Maximum and 99th percentile (nearest rank) of edge_strains().
StrainSummary strain_summary(const TriangleMesh& mesh, const Positions& rest, const Positions& x);

/// Whether StrainLimiter accelerates its sweeps (StrainLimiter::accelerated()).
enum class StrainAcceleration {
  chebyshev,  ///< Chebyshev semi-iterative weights from sweep kChebyshevFrom on
  off,        ///< plain (over-relaxed) Gauss-Seidel
};

/// Edge strain limiter of one mesh (built once per topology).
class StrainLimiter {
 public:
  /// `masses` per vertex (kg; infinite for pinned vertices). Throws InputError on a
  /// size mismatch, a non-positive mass, a zero-length rest edge or a negative limit.
  StrainLimiter(const TriangleMesh& mesh, const Positions& rest, const Eigen::VectorXd& masses,
                double max_strain, StrainAcceleration acceleration = StrainAcceleration::chebyshev);

  /// Chebyshev semi-iterative acceleration of the sweeps (Wang 2015, "A Chebyshev
  /// semi-iterative approach for accelerating projective and position-based dynamics"):
  /// from sweep kChebyshevFrom on, each sweep's result is extrapolated from the state two
  /// sweeps back, with weights set by an estimate kChebyshevRadius of the sweeps' spectral
  /// radius. Gauss-Seidel moves a correction by about one edge per sweep where the arm
  /// pushes back, so plain sweeps leave a long chain over the limit. Largest strain over
  /// the elbow, raise and twist gestures with one implicit step per frame: the default
  /// sleeve 11-14 % plain, exactly the 2.5 % limit accelerated; the 10× sleeve (66 rings)
  /// 3.3-7.3 % accelerated within 400 sweeps (docs/simulation.md). Off only on request.
  bool accelerated() const { return m_accelerated; }
  /// Estimated spectral radius of the sweeps (Chebyshev weights).
  static constexpr double kChebyshevRadius = 0.995;
  /// First sweep that is extrapolated.
  static constexpr int kChebyshevFrom = 10;

  /// While the worst strain exceeds kOverRelaxedAbove times the limit, corrections remove
  /// kOverRelaxation times an edge's excess (successive over-relaxation; never shorter
  /// than the rest length). Chosen on the sleeve's three gestures (docs/simulation.md):
  /// 1.5 above 2x keeps every edge within 3 % and the sleeve's end extent at 98-99.5 %;
  /// over-relaxing down to 1.2x the limit let the elbow's forearm stay bunched (84 %).
  /// Fraction of an edge's excess a correction removes while over-relaxing.
  static constexpr double kOverRelaxation = 1.5;
  /// Over-relax while the worst strain exceeds this multiple of the limit.
  static constexpr double kOverRelaxedAbove = 2.0;

  /// The strain limit.
  double max_strain() const { return m_max_strain; }

  /// Another position constraint to satisfy together with the limit (e.g. staying out of
  /// an obstacle); it returns how many vertices it moved.
  using Constraint = std::function<std::int64_t(Positions&)>;

  /// Shortens over-long edges of `x` in place, at most `max_sweeps` sweeps, each followed
  /// by `constraint` (when given): alternating projections. Returns early once a sweep
  /// finds every edge within the limit (relative tolerance 1e-9) and the constraint moves
  /// nothing. An edge between two pinned vertices cannot be corrected (and is left as it is).
  StrainLimitStats apply(Positions& x, int max_sweeps = 200,
                         const Constraint& constraint = {}) const;

 private:
  double sweep(Positions& x, bool forward, double relaxation, std::int64_t& corrections) const;

  std::vector<std::array<Index, 2>> m_edges;   // in sweep order
  std::vector<double> m_rest_length;           // per m_edges entry
  std::vector<double> m_limit_squared;         // ((1 + max strain) rest length)², per entry
  std::vector<double> m_inverse_rest_squared;  // 1 / rest length², per entry
  std::vector<double> m_weight0;               // share of the correction on vertex 0
  double m_max_strain = 0;
  bool m_accelerated = false;
};

}  // namespace tailor
