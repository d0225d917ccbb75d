#pragma once
/// @file
/// The real roots in [0, 1] of an integer polynomial of degree <= 3, exactly and in
/// increasing order. Internal to the ccd module.
///
/// - Degree 1: the rational -c0 / c1.
/// - Degree 2: by the discriminant D: none, one rational double root, or two quadratic
///   roots whose position against 0 and 1 is decided exactly.
/// - Degree 3: Bernstein subdivision of [0, 1] in exact integers (de Casteljau at the
///   midpoint, all coefficients scaled by 8 per level so they stay integers). A node whose
///   coefficients show no sign change holds no root; one sign change (and nonzero end
///   coefficients) isolates exactly one simple root (Descartes' rule in the Bernstein
///   basis); a zero midpoint value is an exact dyadic root. Only a multiple root can keep
///   the subdivision going: past kDiscriminantDepth levels the discriminant is computed,
///   and when it is zero every root is rational and is given by the closed forms below
///   (double root (9ad - bc) / 2(b^2 - 3ac), simple root (-b^3 + 4abc - 9a^2 d) /
///   a(b^2 - 3ac), or the triple root -b / 3a).

#include <utility>

#include "tailor/ccd/algebraic_point.hpp"
#include "tailor/geometry/fixed_int.hpp"
#include "tailor/ccd/int_poly.hpp"

namespace tailor::detail {

/// At most three roots, increasing.
template <class Z>
struct UnitRoots {
  RootPoint<Z> root[3];
  int count = 0;
  void add(RootPoint<Z> r) { root[count++] = std::move(r); }
};

namespace unit_roots_detail {

/// Depth after which a stalled subdivision checks for a multiple root.
inline constexpr int kDiscriminantDepth = 24;
/// Depth limit of one subdivision with fixed-size integers (coefficients grow 3 bits a
/// level): roots closer than 2^-300 need wider numbers, and GMP takes over.
inline constexpr int kMaxFixedDepth = 300;

template <class Z>
bool in_unit(const Z& num, const Z& den) {  // den > 0
  return num.sign() >= 0 && compare(num, den) <= 0;
}

template <class Z>
void add_rational_if_in_unit(const Z& num, const Z& den, UnitRoots<Z>& out) {
  const Z n = den.sign() < 0 ? -num : num, d = den.sign() < 0 ? -den : den;
  if (in_unit(n, d)) out.add(RootPoint<Z>::rational(n, d));
}

/// The rational roots of a cubic with zero discriminant, sorted.
template <class Z>
void rational_cubic_roots(const Poly<Z>& p, UnitRoots<Z>& out) {
  const Z &a = p.c[3], &b = p.c[2], &c = p.c[1], &d = p.c[0];
  const Z e = b * b - Z(3) * a * c;
  if (e.is_zero()) {
    add_rational_if_in_unit(-b, Z(3) * a, out);
    return;
  }
  const Z n1 = Z(9) * a * d - b * c, d1 = e.shifted(1);
  const Z n2 = Z(4) * a * b * c - b * b * b - Z(9) * a * a * d, d2 = a * e;
  UnitRoots<Z> tmp;
  add_rational_if_in_unit(n1, d1, tmp);
  add_rational_if_in_unit(n2, d2, tmp);
  if (tmp.count == 2 &&
      compare(tmp.root[0].num * tmp.root[1].den, tmp.root[1].num * tmp.root[0].den) > 0) {
    std::swap(tmp.root[0], tmp.root[1]);
  }
  for (int i = 0; i < tmp.count; ++i) out.add(std::move(tmp.root[i]));
}

template <class Z>
Z cubic_discriminant(const Poly<Z>& p) {
  const Z &a = p.c[3], &b = p.c[2], &c = p.c[1], &d = p.c[0];
  return Z(18) * a * b * c * d - Z(4) * b * b * b * d + b * b * c * c - Z(4) * a * c * c * c -
         Z(27) * a * a * d * d;
}

/// Sign changes of the sequence, zeros skipped.
template <class Z>
int variations(const Z (&b)[4]) {
  int count = 0, last = 0;
  for (const Z& x : b) {
    const int s = x.sign();
    if (s == 0) continue;
    if (last != 0 && s != last) ++count;
    last = s;
  }
  return count;
}

template <class Z>
void quadratic_roots_in_unit(const Poly<Z>& p, UnitRoots<Z>& out) {
  const Z D = p.c[1] * p.c[1] - Z(4) * p.c[2] * p.c[0];
  if (D.sign() < 0) return;
  if (D.is_zero()) {
    add_rational_if_in_unit(-p.c[1], p.c[2].shifted(1), out);
    return;
  }
  const Dyadic<Z> zero{Z(), 0}, one{Z(1), 0};
  for (bool larger : {false, true}) {
    RootPoint<Z> r = RootPoint<Z>::quadratic(p, D, larger);
    // The certified enclosure settles membership unless it straddles 0 or 1.
    if (r.enc_hi < 0.0 || r.enc_lo > 1.0) continue;
    const int at0 = r.enc_lo > 0.0 ? 1 : r.compare_to(zero);
    const int at1 = r.enc_hi < 1.0 ? -1 : r.compare_to(one);
    if (at0 < 0 || at1 > 0) continue;
    if (at0 == 0) {
      out.add(RootPoint<Z>::rational(Z(0), Z(1)));
    } else if (at1 == 0) {
      out.add(RootPoint<Z>::rational(Z(1), Z(1)));
    } else {
      r.clamp_to_unit();
      out.add(std::move(r));
    }
  }
}

/// A node of the cubic's subdivision: its Bernstein coefficients (up to a positive factor)
/// on [k / 2^j, (k + 1) / 2^j].
template <class Z>
struct BernsteinNode {
  Z b[4];     ///< Bernstein coefficients, up to a positive factor
  Z k;        ///< the node's left end is k / 2^j
  int j = 0;  ///< depth
};

/// Whether the node certainly holds exactly one root, in its interior.
template <class Z>
bool isolates_one_root(const BernsteinNode<Z>& n) {
  return variations(n.b) == 1 && !n.b[0].is_zero() && !n.b[3].is_zero();
}

/// The root node [0, 1] of p (coefficients times 3).
template <class Z>
BernsteinNode<Z> unit_node(const Poly<Z>& p) {
  const Z c0 = p.at(0), c1 = p.at(1), c2 = p.at(2), c3 = p.at(3);
  BernsteinNode<Z> n;
  n.b[0] = Z(3) * c0;
  n.b[1] = Z(3) * c0 + c1;
  n.b[2] = Z(3) * c0 + c1.shifted(1) + c2;
  n.b[3] = Z(3) * (c0 + c1 + c2 + c3);
  return n;
}

/// The halves of `n` by de Casteljau at its midpoint, coefficients times 8; left.b[3] =
/// right.b[0] is the value at the split point (zero when it is a root).
template <class Z>
void split_in_halves(const BernsteinNode<Z>& n, BernsteinNode<Z>& left, BernsteinNode<Z>& right) {
  const Z &b0 = n.b[0], &b1 = n.b[1], &b2 = n.b[2], &b3 = n.b[3];
  const Z b01 = b0 + b1, b12 = b1 + b2, b23 = b2 + b3;
  const Z b012 = b01 + b12, b123 = b12 + b23;
  const Z mid = b012 + b123;
  right.b[0] = mid;
  right.b[1] = b123.shifted(1);
  right.b[2] = b23.shifted(2);
  right.b[3] = b3.shifted(3);
  right.k = n.k.shifted(1) + Z(1);
  right.j = n.j + 1;
  left.b[0] = b0.shifted(3);
  left.b[1] = b01.shifted(2);
  left.b[2] = b012.shifted(1);
  left.b[3] = mid;
  left.k = n.k.shifted(1);
  left.j = n.j + 1;
}

/// Work left to do, last in first out: a node to subdivide, a node known to isolate one
/// root, or a dyadic root at a split point. Subdivision diminishes variations (those of
/// the two halves add up to at most the parent's, <= 3), so at most one pending node can
/// hold two or more, and the stack stays short however deep the subdivision goes (close
/// roots need depth, not memory).
template <class Z>
class PendingWork {
 public:
  /// What a pending entry is.
  enum class Kind : unsigned char { node, isolated, root };
  /// Adds an entry; throws CapacityExceeded past the fixed capacity.
  void push(Kind kind, const BernsteinNode<Z>& n) {
    if (m_top == kCapacity) throw CapacityExceeded{};
    m_items[m_top].kind = kind;
    m_items[m_top].node = n;
    ++m_top;
  }
  /// Whether nothing is pending.
  bool empty() const { return m_top == 0; }
  /// Takes the last entry into `n`; returns its kind.
  Kind pop(BernsteinNode<Z>& n) {
    --m_top;
    n = std::move(m_items[m_top].node);
    return m_items[m_top].kind;
  }

 private:
  static constexpr int kCapacity = 12;
  struct Item {
    Kind kind = Kind::node;
    BernsteinNode<Z> node;
  };
  Item m_items[kCapacity];
  int m_top = 0;
};

template <class Z>
void cubic_roots_in_unit(const Poly<Z>& p, UnitRoots<Z>& out) {
  using Node = BernsteinNode<Z>;
  using Kind = typename PendingWork<Z>::Kind;
  PendingWork<Z> pending;
  auto isolated_root = [&](const Node& n) {
    return RootPoint<Z>::isolated(p, Dyadic<Z>{n.k, n.j}, Dyadic<Z>{n.k + Z(1), n.j},
                                  n.b[0].sign());
  };
  Node cur = unit_node(p);
  const bool root_at_one = cur.b[3].is_zero();
  if (cur.b[0].is_zero()) out.add(RootPoint<Z>::rational(Z(0), Z(1)));
  bool discriminant_checked = false;
  bool have = true;
  while (have) {
    const int v = variations(cur.b);
    if (v == 1 && isolates_one_root(cur)) {
      out.add(isolated_root(cur));
    } else if (v > 0) {
      if (cur.j >= kDiscriminantDepth && !discriminant_checked) {
        discriminant_checked = true;
        if (cubic_discriminant(p).is_zero()) {
          out.count = 0;
          rational_cubic_roots(p, out);
          return;
        }
      }
      if (Z::kBounded && cur.j >= kMaxFixedDepth) throw CapacityExceeded{};
      Node left, right;
      split_in_halves(cur, left, right);
      // Pushed in reverse order of the roots: right half, then the split point.
      if (variations(right.b) > 0) {
        pending.push(isolates_one_root(right) ? Kind::isolated : Kind::node, right);
      }
      if (right.b[0].is_zero()) pending.push(Kind::root, right);
      cur = std::move(left);
      continue;
    }
    // Next pending work.
    have = false;
    while (!pending.empty()) {
      Node next;
      const Kind kind = pending.pop(next);
      if (kind == Kind::root) {
        out.add(RootPoint<Z>::dyadic(Dyadic<Z>{next.k, next.j}));
      } else if (kind == Kind::isolated) {
        out.add(isolated_root(next));
      } else {
        cur = std::move(next);
        have = true;
        break;
      }
    }
  }
  if (root_at_one) out.add(RootPoint<Z>::rational(Z(1), Z(1)));
}

}  // namespace unit_roots_detail

/// The roots of p in [0, 1], increasing (p must not be the zero polynomial).
template <class Z>
void roots_in_unit(const Poly<Z>& p, UnitRoots<Z>& out) {
  out.count = 0;
  switch (p.deg) {
    case 1:
      unit_roots_detail::add_rational_if_in_unit(-p.c[0], p.c[1], out);
      return;
    case 2:
      unit_roots_detail::quadratic_roots_in_unit(p, out);
      return;
    case 3:
      unit_roots_detail::cubic_roots_in_unit(p, out);
      return;
    default:
      return;
  }
}

}  // namespace tailor::detail
