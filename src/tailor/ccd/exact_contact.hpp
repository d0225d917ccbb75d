#pragma once
/// @file
/// The exact tier's decision, templated on the integer type (FixedInt, or BigInt as the
/// last resort). Internal to the ccd module.
///
/// Positions are exact integers after a power-of-two scaling, taken relative to the first
/// point (a), so every quantity is a polynomial in t of degree <= 3 with integer
/// coefficients. Contacts need the four points coplanar, f(t) = 0 (ccd_systems.hpp), and
/// at a coplanar instant every condition of ccd_systems.hpp reduces to the sign of a
/// quadratic, a component of a cross product of two in-plane vectors (see
/// ccd_systems.hpp, "Projected conditions"). So:
/// - f not identically zero: walk the roots of f in [0, 1] in increasing order (exact,
///   unit_roots.hpp) and decide each with exact signs of those quadratics there
///   (algebraic_point.hpp); the first contact root is the answer.
/// - f identically zero (coplanar for the whole step): the contact set is a finite union
///   of points and intervals bounded by 0 and roots of the quadratics. Its infimum is a
///   candidate c where the conditions hold at c or just right of c (signs of the first
///   nonvanishing derivative); every candidate is checked exactly. When one axis k has
///   n_k (VF) or m_k (EE) without a root in [0, 1], that projection is valid for the
///   whole step and three (VF) or four (EE) quadratics decide; otherwise each axis is a
///   branch guarded by n_k != 0, plus the segment branches of the degenerate instants.

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <optional>
#include <limits>
#include <new>

#include "tailor/ccd/algebraic_point.hpp"
#include "tailor/ccd/ccd_systems.hpp"
#include "tailor/ccd/int_poly.hpp"
#include "tailor/ccd/unit_roots.hpp"

namespace tailor::detail {

template <class Z>
using PolyVec = V3<Poly<Z>>;

template <class Z>
const Poly<Z>& component(const PolyVec<Z>& v, int k) {
  return k == 0 ? v.x : (k == 1 ? v.y : v.z);
}

/// Axes ordered by decreasing |v_k| at r (ball estimates), to try the likeliest nonzero
/// component first.
template <class Z>
std::array<int, 3> axes_by_size(const PolyVec<Z>& v, const RootPoint<Z>& r) {
  std::array<double, 3> size{};
  const bool finite = std::isfinite(r.enc_lo) && std::isfinite(r.enc_hi);
  for (int k = 0; k < 3; ++k) {
    const Poly<Z>& p = component(v, k);
    if (p.is_zero()) {
      size[k] = -1.0;
    } else if (finite) {
      const int shift = scale_exponent(p);
      size[k] =
          std::ldexp(std::fabs(evaluate_ball(p, Ball(0.5 * r.enc_lo + 0.5 * r.enc_hi), shift).m),
                     std::min(shift, 1000));
    }
  }
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int i, int j) { return size[i] > size[j]; });
  return order;
}

/// Point p on the closed segment xy at r: cross = 0, along >= 0, within >= 0.
template <class Z>
bool on_segment_at(const PolyVec<Z>& p, const PolyVec<Z>& x, const PolyVec<Z>& y, RootPoint<Z>& r) {
  // The point_segment conditions of ccd_systems.hpp, built one at a time (most fail early).
  const PolyVec<Z> px = p - x, yx = y - x;
  for (int k = 0; k < 3; ++k) {
    if (sign_at(cross_component(px, yx, k), r) != 0) return false;
  }
  return sign_at(dot(px, yx), r) >= 0 && sign_at(dot(y - p, yx + px), r) >= 0;
}

/// A value computed on first use.
template <class T>
class Lazy {
 public:
  template <class Make>
  const T& get(Make&& make) const {
    if (!m_ready) {
      m_value = make();
      m_ready = true;
    }
    return m_value;
  }

 private:
  mutable T m_value{};
  mutable bool m_ready = false;
};

/// The VF polynomials, relative to a: u = b - a, v = c - a, w = p - a. The edge
/// orientations are built per axis on first use (most queries need one axis).
template <class Z>
struct VfPolys {
  PolyVec<Z> u, v, w, zero;
  PolyVec<Z> n;  ///< (b-a) x (c-a)
  Poly<Z> f;     ///< n . (p-a)

  VfPolys(const PolyVec<Z>& u_, const PolyVec<Z>& v_, const PolyVec<Z>& w_)
      : u(u_), v(v_), w(w_), n(cross(u, v)), f(dot(n, w)) {}

  /// Component k of (b-a) x (p-a) (edge 0), (c-b) x (p-b) (edge 1), (a-c) x (p-c) (edge 2).
  const Poly<Z>& edge(int which, int k) const {
    return m_edge[which][k].get([&] {
      if (which == 0) return cross_component(u, w, k);
      if (which == 1) return cross_component(v - u, w - u, k);
      return cross_component(zero - v, w - v, k);
    });
  }

  /// Contact at the coplanar instant r.
  bool contact_at(RootPoint<Z>& r) const {
    for (int k : axes_by_size(n, r)) {
      const int s = sign_at(component(n, k), r);
      if (s == 0) continue;
      // p in the closed triangle iff the three edge orientations agree with n_k (or vanish).
      return s * sign_at(edge(0, k), r) >= 0 && s * sign_at(edge(1, k), r) >= 0 &&
             s * sign_at(edge(2, k), r) >= 0;
    }
    // Degenerate triangle at r: p on one of its edges.
    return on_segment_at(w, zero, u, r) || on_segment_at(w, u, v, r) ||
           on_segment_at(w, v, zero, r);
  }

 private:
  Lazy<Poly<Z>> m_edge[3][3];
};

/// The EE polynomials, relative to a: u = b - a, v = c - a, w = d - a.
template <class Z>
struct EePolys {
  PolyVec<Z> u, v, w, zero;
  PolyVec<Z> m;    ///< (b-a) x (d-c)
  PolyVec<Z> abc;  ///< (b-a) x (c-a)
  Poly<Z> f;       ///< ((b-a) x (c-a)) . (d-a)

  EePolys(const PolyVec<Z>& u_, const PolyVec<Z>& v_, const PolyVec<Z>& w_)
      : u(u_), v(v_), w(w_), m(cross(u, w - v)), abc(cross(u, v)), f(dot(abc, w)) {}

  /// Component k of the orientations (b-a) x (c-a) (0), (b-a) x (d-a) (1),
  /// (d-c) x (a-c) (2), (d-c) x (b-c) (3).
  const Poly<Z>& orientation(int which, int k) const {
    if (which == 0) return component(abc, k);
    return m_orientation[which - 1][k].get([&] {
      if (which == 1) return cross_component(u, w, k);
      if (which == 2) return cross_component(w - v, zero - v, k);
      return cross_component(w - v, u - v, k);
    });
  }

  bool contact_at(RootPoint<Z>& r) const {
    for (int k : axes_by_size(m, r)) {
      if (sign_at(component(m, k), r) == 0) continue;
      // Non-parallel coplanar segments meet iff each one's ends are not strictly on one
      // side of the other's line.
      return sign_at(orientation(0, k), r) * sign_at(orientation(1, k), r) <= 0 &&
             sign_at(orientation(2, k), r) * sign_at(orientation(3, k), r) <= 0;
    }
    // Parallel (or a zero-length edge) at r: an endpoint on the other segment.
    return on_segment_at(zero, v, w, r) || on_segment_at(u, v, w, r) ||
           on_segment_at(v, zero, u, r) || on_segment_at(w, zero, u, r);
  }

 private:
  Lazy<Poly<Z>> m_orientation[3][3];
};

/// f not identically zero: the earliest contact among the roots of f in [0, 1].
template <class Z, class Polys>
std::optional<double> earliest_root_contact(const Polys& s) {
  if (s.f.deg <= 0) return std::nullopt;  // a nonzero constant: never coplanar
  UnitRoots<Z> roots;
  roots_in_unit(s.f, roots);
  for (int i = 0; i < roots.count; ++i) {
    if (s.contact_at(roots.root[i])) return lower_bound(roots.root[i]);
  }
  return std::nullopt;
}

// ---- coplanar for the whole step ------------------------------------------------------

/// A fixed-capacity vector whose elements are constructed only when pushed (large
/// default-constructed arrays of big numbers would cost more than the work itself).
template <class T, int Capacity>
class InlineVector {
 public:
  InlineVector() = default;
  InlineVector(const InlineVector&) = delete;
  InlineVector& operator=(const InlineVector&) = delete;
  ~InlineVector() {
    for (int i = 0; i < m_size; ++i) (*this)[i].~T();
  }
  void push_back(T&& x) {
    assert(m_size < Capacity);
    new (m_storage + sizeof(T) * static_cast<std::size_t>(m_size)) T(std::move(x));
    ++m_size;
  }
  int size() const { return m_size; }
  T& operator[](int i) {
    return *std::launder(reinterpret_cast<T*>(m_storage + sizeof(T) * static_cast<std::size_t>(i)));
  }

 private:
  alignas(T) unsigned char m_storage[sizeof(T) * Capacity];
  int m_size = 0;
};

/// One condition on the sign of sign * p * q (q optional).
template <class Z>
struct Condition {
  enum class Relation : unsigned char { nonnegative, nonzero, zero };
  const Poly<Z>* p = nullptr;
  const Poly<Z>* q = nullptr;
  int sign = 1;
  Relation relation = Relation::nonnegative;

  bool holds(int s) const {
    switch (relation) {
      case Relation::nonnegative:
        return s >= 0;
      case Relation::nonzero:
        return s != 0;
      case Relation::zero:
        return s == 0;
    }
    return false;
  }
  /// The signed value's sign, from the factors' signs.
  int combine(int sp, int sq) const { return sign * sp * (q != nullptr ? sq : 1); }
};

/// The infimum of {t in [0, 1] : every condition holds} as a time-of-impact lower bound,
/// or nullopt when the set is empty.
template <class Z, int MaxConditions>
std::optional<double> earliest_solution(const std::array<Condition<Z>, MaxConditions>& all,
                                        int count) {
  using Relation = typename Condition<Z>::Relation;
  // Constant factors decide their conditions at once.
  std::array<Condition<Z>, MaxConditions> conds;
  int n = 0;
  const Poly<Z>* zero_poly = nullptr;
  for (int i = 0; i < count; ++i) {
    const Condition<Z>& c = all[i];
    const bool pc = c.p->deg <= 0, qc = c.q == nullptr || c.q->deg <= 0;
    if (pc && qc) {
      const int s = c.combine(c.p->deg < 0 ? 0 : c.p->c[0].sign(),
                              c.q == nullptr || c.q->deg < 0 ? 0 : c.q->c[0].sign());
      if (!c.holds(s)) return std::nullopt;
      continue;
    }
    // A zero factor makes the product zero for all t.
    if ((c.p->is_zero()) || (c.q != nullptr && c.q->is_zero())) {
      if (!c.holds(0)) return std::nullopt;
      continue;
    }
    conds[n++] = c;
    if (c.relation == Relation::zero && zero_poly == nullptr && c.q == nullptr) zero_poly = c.p;
  }
  auto holds_at = [&](RootPoint<Z>& r, bool right_of) {
    for (int i = 0; i < n; ++i) {
      const Condition<Z>& c = conds[i];
      const int sp = right_of ? right_sign(*c.p, r) : sign_at(*c.p, r);
      const int sq = c.q == nullptr ? 1 : (right_of ? right_sign(*c.q, r) : sign_at(*c.q, r));
      if (!c.holds(c.combine(sp, sq))) return false;
    }
    return true;
  };
  if (n == 0) return 0.0;
  if (zero_poly != nullptr) {
    // The set lies in the roots of zero_poly.
    UnitRoots<Z> roots;
    roots_in_unit(*zero_poly, roots);
    for (int i = 0; i < roots.count; ++i) {
      if (holds_at(roots.root[i], false)) return lower_bound(roots.root[i]);
    }
    return std::nullopt;
  }
  // Candidates: 0 and the roots of every factor.
  constexpr int kMaxCandidates = 1 + 2 * 2 * MaxConditions;
  InlineVector<RootPoint<Z>, kMaxCandidates> candidates;  // constructed one by one
  candidates.push_back(RootPoint<Z>::rational(Z(0), Z(1)));
  const Poly<Z>* seen[2 * MaxConditions];
  int seen_count = 0;
  for (int i = 0; i < n; ++i) {
    for (const Poly<Z>* p : {conds[i].p, conds[i].q}) {
      if (p == nullptr || p->deg <= 0) continue;
      if (std::find(seen, seen + seen_count, p) != seen + seen_count) continue;
      seen[seen_count++] = p;
      UnitRoots<Z> roots;
      roots_in_unit(*p, roots);
      for (int j = 0; j < roots.count; ++j) {
        roots.root[j].clamp_to_unit();
        candidates.push_back(std::move(roots.root[j]));
      }
    }
  }
  const int m = candidates.size();
  std::array<int, kMaxCandidates> order;
  for (int i = 0; i < m; ++i) order[i] = i;
  std::sort(order.begin(), order.begin() + m,
            [&](int i, int j) { return candidates[i].enc_lo < candidates[j].enc_lo; });
  // In increasing order of certified lower ends: once a candidate qualifies, only those
  // starting below its bound can still be earlier.
  double best = std::numeric_limits<double>::infinity();
  const Dyadic<Z> one{Z(1), 0};  // NOLINT
  for (int i = 0; i < m; ++i) {
    RootPoint<Z>& c = candidates[order[i]];
    if (!(c.enc_lo < best)) break;
    bool ok = holds_at(c, false);
    if (!ok && c.compare_to(one) < 0) ok = holds_at(c, true);
    if (ok) best = std::min(best, lower_bound(c));
  }
  if (best == std::numeric_limits<double>::infinity()) return std::nullopt;
  return best;
}

/// True when q (degree <= 2) has no root in [0, 1] and is not identically zero.
template <class Z>
bool no_root_in_unit(const Poly<Z>& q) {
  if (q.is_zero()) return false;
  if (q.deg == 0) return true;
  UnitRoots<Z> roots;
  roots_in_unit(q, roots);
  return roots.count == 0;
}

/// The earliest instant in [0, 1] where the vector v (not identically zero) vanishes and
/// `holds` is true there.
template <class Z, class Holds>
std::optional<double> earliest_at_zeros(const PolyVec<Z>& v, Holds&& holds) {
  int first = 0;
  while (component(v, first).is_zero()) ++first;
  UnitRoots<Z> roots;
  roots_in_unit(component(v, first), roots);
  for (int i = 0; i < roots.count; ++i) {
    RootPoint<Z>& r = roots.root[i];
    bool zero = true;
    for (int j = first + 1; j < 3 && zero; ++j) zero = sign_at(component(v, j), r) == 0;
    if (zero && holds(r)) return lower_bound(r);
  }
  return std::nullopt;
}

/// For a normal vector v (n or m) that is not identically zero: the axes whose projection
/// branches are needed to cover every instant with v != 0. One axis k suffices when n_k
/// vanishes only where all of v does (for instance a plane of fixed orientation).
template <class Z>
int covering_axes(const PolyVec<Z>& v, std::array<int, 3>& axes) {
  for (int k = 0; k < 3; ++k) {
    const Poly<Z>& vk = component(v, k);
    if (vk.is_zero()) continue;
    UnitRoots<Z> roots;
    roots_in_unit(vk, roots);
    bool suffices = true;
    for (int i = 0; i < roots.count && suffices; ++i) {
      for (int j = 0; j < 3 && suffices; ++j) {
        if (j != k && sign_at(component(v, j), roots.root[i]) != 0) suffices = false;
      }
    }
    if (suffices) {
      axes[0] = k;
      return 1;
    }
  }
  int count = 0;
  for (int k = 0; k < 3; ++k) {
    if (!component(v, k).is_zero()) axes[count++] = k;
  }
  return count;
}

/// Coplanar VF: the earliest t where p is in the closed triangle.
template <class Z>
std::optional<double> earliest_coplanar_contact(const VfPolys<Z>& s) {
  using C = Condition<Z>;
  using R = typename C::Relation;
  for (int k = 0; k < 3; ++k) {
    const Poly<Z>& nk = component(s.n, k);
    if (!no_root_in_unit(nk)) continue;
    // n_k keeps one sign: the projection along k is valid for the whole step.
    const int sk = nk.c[0].sign();  // n_k(0) != 0 here
    const std::array<C, 3> conds{C{&s.edge(0, k), nullptr, sk, R::nonnegative},
                                 C{&s.edge(1, k), nullptr, sk, R::nonnegative},
                                 C{&s.edge(2, k), nullptr, sk, R::nonnegative}};
    return earliest_solution<Z, 3>(conds, 3);
  }
  std::optional<double> best;
  auto keep = [&](std::optional<double> t) {
    if (t && (!best || *t < *best)) best = t;
  };
  // Instants with n != 0: projected branches (guarded by n_k != 0).
  const bool ever_nondegenerate = !s.n.x.is_zero() || !s.n.y.is_zero() || !s.n.z.is_zero();
  if (ever_nondegenerate) {
    std::array<int, 3> axes{};
    const int count = covering_axes(s.n, axes);
    for (int i = 0; i < count; ++i) {
      const int k = axes[i];
      const Poly<Z>& nk = component(s.n, k);
      const std::array<C, 4> conds{
          C{&nk, nullptr, 1, R::nonzero}, C{&nk, &s.edge(0, k), 1, R::nonnegative},
          C{&nk, &s.edge(1, k), 1, R::nonnegative}, C{&nk, &s.edge(2, k), 1, R::nonnegative}};
      keep(earliest_solution<Z, 4>(conds, 4));
    }
  }
  // Instants with n = 0 (a zero-area triangle): p on one of the edges.
  const PolyVec<Z>* edges[3][2] = {{&s.zero, &s.u}, {&s.u, &s.v}, {&s.v, &s.zero}};
  if (!ever_nondegenerate) {
    for (const auto& e : edges) {
      const PointSegment<Poly<Z>> ps = point_segment(s.w, *e[0], *e[1]);
      const std::array<C, 5> conds{
          C{&ps.cross.x, nullptr, 1, R::zero}, C{&ps.cross.y, nullptr, 1, R::zero},
          C{&ps.cross.z, nullptr, 1, R::zero}, C{&ps.along, nullptr, 1, R::nonnegative},
          C{&ps.within, nullptr, 1, R::nonnegative}};
      keep(earliest_solution<Z, 5>(conds, 5));
    }
    return best;
  }
  keep(earliest_at_zeros(s.n, [&](RootPoint<Z>& r) {
    return on_segment_at(s.w, s.zero, s.u, r) || on_segment_at(s.w, s.u, s.v, r) ||
           on_segment_at(s.w, s.v, s.zero, r);
  }));
  return best;
}

/// Coplanar EE: the earliest t where the closed segments meet.
template <class Z>
std::optional<double> earliest_coplanar_contact(const EePolys<Z>& s) {
  using C = Condition<Z>;
  using R = typename C::Relation;
  for (int k = 0; k < 3; ++k) {
    const Poly<Z>& mk = component(s.m, k);
    if (!no_root_in_unit(mk)) continue;
    // Never parallel: the 2D segment test along k decides for the whole step.
    const std::array<C, 2> conds{C{&s.orientation(0, k), &s.orientation(1, k), -1, R::nonnegative},
                                 C{&s.orientation(2, k), &s.orientation(3, k), -1, R::nonnegative}};
    return earliest_solution<Z, 2>(conds, 2);
  }
  std::optional<double> best;
  auto keep = [&](std::optional<double> t) {
    if (t && (!best || *t < *best)) best = t;
  };
  // Instants where the edges are not parallel: projected branches (m_k != 0).
  const bool ever_crossing = !s.m.x.is_zero() || !s.m.y.is_zero() || !s.m.z.is_zero();
  if (ever_crossing) {
    std::array<int, 3> axes{};
    const int count = covering_axes(s.m, axes);
    for (int i = 0; i < count; ++i) {
      const int k = axes[i];
      const Poly<Z>& mk = component(s.m, k);
      const std::array<C, 3> conds{
          C{&mk, nullptr, 1, R::nonzero},
          C{&s.orientation(0, k), &s.orientation(1, k), -1, R::nonnegative},
          C{&s.orientation(2, k), &s.orientation(3, k), -1, R::nonnegative}};
      keep(earliest_solution<Z, 3>(conds, 3));
    }
  }
  // Instants with m = 0 (parallel, or a zero-length edge): an endpoint on the other edge.
  const PolyVec<Z>* cases[4][3] = {
      {&s.zero, &s.v, &s.w}, {&s.u, &s.v, &s.w}, {&s.v, &s.zero, &s.u}, {&s.w, &s.zero, &s.u}};
  if (!ever_crossing) {
    for (const auto& c : cases) {
      const PointSegment<Poly<Z>> ps = point_segment(*c[0], *c[1], *c[2]);
      const std::array<C, 5> conds{
          C{&ps.cross.x, nullptr, 1, R::zero}, C{&ps.cross.y, nullptr, 1, R::zero},
          C{&ps.cross.z, nullptr, 1, R::zero}, C{&ps.along, nullptr, 1, R::nonnegative},
          C{&ps.within, nullptr, 1, R::nonnegative}};
      keep(earliest_solution<Z, 5>(conds, 5));
    }
    return best;
  }
  keep(earliest_at_zeros(s.m, [&](RootPoint<Z>& r) {
    for (const auto& c : cases) {
      if (on_segment_at(*c[0], *c[1], *c[2], r)) return true;
    }
    return false;
  }));
  return best;
}

/// The whole decision: time of impact lower bound of the earliest contact, or nullopt.
template <class Z, class Polys>
std::optional<double> earliest_contact(const Polys& s) {
  if (!s.f.is_zero()) return earliest_root_contact<Z>(s);
  return earliest_coplanar_contact(s);
}

}  // namespace tailor::detail
