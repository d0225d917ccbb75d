#include "tailor/ccd/rational_polynomial.hpp"

#include <algorithm>
#include <cassert>
#include <utility>

namespace tailor::detail {

namespace {

int sign_of(const mpq_class& x) {
  const int s = mpq_sgn(x.get_mpq_t());
  return (s > 0) - (s < 0);
}

// The arithmetic below writes into existing values with the mpq_* functions: gmpxx
// expressions such as `c += a * b` build a temporary rational (two allocations and two
// frees) per term, which was a quarter of the oracle's time.

/// x += a·b.
void add_product(mpq_class& x, const mpq_class& a, const mpq_class& b, mpq_class& scratch) {
  mpq_mul(scratch.get_mpq_t(), a.get_mpq_t(), b.get_mpq_t());
  mpq_add(x.get_mpq_t(), x.get_mpq_t(), scratch.get_mpq_t());
}

/// Every coefficient is an integer (denominator 1): the CCD systems are built from
/// integer coordinates (ccd_rational.cpp scales them so), and their products then need no
/// gcd at all.
bool integer_coefficients(const std::vector<mpq_class>& c) {
  return std::all_of(c.begin(), c.end(), [](const mpq_class& x) {
    return mpz_cmp_ui(mpq_denref(x.get_mpq_t()), 1) == 0;
  });
}

}  // namespace

RationalPoly::RationalPoly(const mpq_class& c) : m_c{c} {
  trim();
}

RationalPoly::RationalPoly(std::vector<mpq_class> coefficients) : m_c(std::move(coefficients)) {
  trim();
}

RationalPoly RationalPoly::linear(const mpq_class& c0, const mpq_class& c1) {
  return RationalPoly(std::vector<mpq_class>{c0, c1});
}

void RationalPoly::trim() {
  while (!m_c.empty() && sign_of(m_c.back()) == 0) m_c.pop_back();
}

mpq_class RationalPoly::operator()(const mpq_class& t) const {
  mpq_class r = 0;
  for (std::size_t i = m_c.size(); i-- > 0;) {
    mpq_mul(r.get_mpq_t(), r.get_mpq_t(), t.get_mpq_t());
    mpq_add(r.get_mpq_t(), r.get_mpq_t(), m_c[i].get_mpq_t());
  }
  return r;
}

int RationalPoly::sign_at(const mpq_class& t) const {
  return sign_of((*this)(t));
}

RationalPoly RationalPoly::derivative() const {
  std::vector<mpq_class> d;
  for (std::size_t i = 1; i < m_c.size(); ++i) d.push_back(m_c[i] * static_cast<long>(i));
  return RationalPoly(std::move(d));
}

RationalPoly operator+(const RationalPoly& a, const RationalPoly& b) {
  std::vector<mpq_class> c(std::max(a.m_c.size(), b.m_c.size()));
  for (std::size_t i = 0; i < a.m_c.size(); ++i) c[i] += a.m_c[i];
  for (std::size_t i = 0; i < b.m_c.size(); ++i) c[i] += b.m_c[i];
  return RationalPoly(std::move(c));
}

RationalPoly operator-(const RationalPoly& a, const RationalPoly& b) {
  std::vector<mpq_class> c(std::max(a.m_c.size(), b.m_c.size()));
  for (std::size_t i = 0; i < a.m_c.size(); ++i) c[i] += a.m_c[i];
  for (std::size_t i = 0; i < b.m_c.size(); ++i) c[i] -= b.m_c[i];
  return RationalPoly(std::move(c));
}

RationalPoly operator*(const RationalPoly& a, const RationalPoly& b) {
  if (a.is_zero() || b.is_zero()) return {};
  std::vector<mpq_class> c(a.m_c.size() + b.m_c.size() - 1);
  if (integer_coefficients(a.m_c) && integer_coefficients(b.m_c)) {
    for (std::size_t i = 0; i < a.m_c.size(); ++i) {
      for (std::size_t j = 0; j < b.m_c.size(); ++j) {
        mpz_addmul(mpq_numref(c[i + j].get_mpq_t()), mpq_numref(a.m_c[i].get_mpq_t()),
                   mpq_numref(b.m_c[j].get_mpq_t()));
      }
    }
    return RationalPoly(std::move(c));
  }
  mpq_class scratch;
  for (std::size_t i = 0; i < a.m_c.size(); ++i) {
    for (std::size_t j = 0; j < b.m_c.size(); ++j)
      add_product(c[i + j], a.m_c[i], b.m_c[j], scratch);
  }
  return RationalPoly(std::move(c));
}

namespace {

/// Long division: a = q b + r.
void divide(const RationalPoly& a, const RationalPoly& b, RationalPoly* quotient,
            RationalPoly* remainder) {
  assert(!b.is_zero());
  std::vector<mpq_class> r = a.coefficients();
  const auto& bc = b.coefficients();
  const int db = b.degree();
  std::vector<mpq_class> q(r.size() >= bc.size() ? r.size() - bc.size() + 1 : 0);
  mpq_class f, scratch;
  for (int i = static_cast<int>(r.size()) - 1; i >= db; --i) {
    if (sign_of(r[i]) == 0) continue;
    mpq_div(f.get_mpq_t(), r[i].get_mpq_t(), bc[db].get_mpq_t());
    for (int j = 0; j <= db; ++j) {
      mpq_mul(scratch.get_mpq_t(), f.get_mpq_t(), bc[j].get_mpq_t());
      mpq_sub(r[i - db + j].get_mpq_t(), r[i - db + j].get_mpq_t(), scratch.get_mpq_t());
    }
    mpq_swap(q[i - db].get_mpq_t(), f.get_mpq_t());
  }
  if (quotient) *quotient = RationalPoly(std::move(q));
  if (remainder) *remainder = RationalPoly(std::move(r));
}

RationalPoly monic(const RationalPoly& p) {
  if (p.is_zero()) return p;
  std::vector<mpq_class> c = p.coefficients();
  const mpq_class lead = c.back();
  for (auto& x : c) x /= lead;
  return RationalPoly(std::move(c));
}

/// The Sturm sequence p, p', -rem(...), ... of squarefree p.
std::vector<RationalPoly> sturm_sequence(const RationalPoly& p) {
  std::vector<RationalPoly> s{p, p.derivative()};
  while (!s.back().is_zero() && s.back().degree() > 0) {
    RationalPoly r = poly_remainder(s[s.size() - 2], s.back());
    if (r.is_zero()) break;
    s.push_back(RationalPoly() - r);
  }
  if (s.back().is_zero()) s.pop_back();
  return s;
}

int sign_variations(const std::vector<RationalPoly>& seq, const mpq_class& x) {
  int count = 0, last = 0;
  for (const auto& q : seq) {
    const int s = q.sign_at(x);
    if (s == 0) continue;
    if (last != 0 && s != last) ++count;
    last = s;
  }
  return count;
}

/// A split point of (lo, hi) that is not a root of q (q has finitely many roots).
mpq_class split_point(const RationalPoly& q, const mpq_class& lo, const mpq_class& hi) {
  const mpq_class w = hi - lo;
  for (unsigned long denom = 2;; denom *= 2) {
    for (unsigned long j = 1; j < denom; j += 2) {
      mpq_class m = lo + w * mpq_class(mpz_class(j), mpz_class(denom));
      if (q.sign_at(m) != 0) return m;
    }
  }
}

void isolate(const RationalPoly& q, const std::vector<RationalPoly>& sturm, const mpq_class& lo,
             const mpq_class& hi, int vlo, int vhi, std::vector<RealRoot>& out) {
  const int count = vlo - vhi;
  if (count <= 0) return;
  if (count == 1) {
    out.push_back({lo, hi, false});
    return;
  }
  const mpq_class m = split_point(q, lo, hi);
  const int vm = sign_variations(sturm, m);
  isolate(q, sturm, lo, m, vlo, vm, out);
  isolate(q, sturm, m, hi, vm, vhi, out);
}

/// Bernstein coefficients of q on [lo, hi].
std::vector<mpq_class> bernstein_on(const RationalPoly& q, const mpq_class& lo,
                                    const mpq_class& hi) {
  std::vector<mpq_class> a = q.coefficients();
  const int n = static_cast<int>(a.size()) - 1;
  mpq_class scratch;
  // Taylor shift to lo: a(t) -> a(lo + s).
  for (int i = 0; i < n; ++i) {
    for (int j = n - 1; j >= i; --j) add_product(a[j], lo, a[j + 1], scratch);
  }
  // Scale s = w x.
  const mpq_class w = hi - lo;
  mpq_class wp = 1;
  for (int i = 1; i <= n; ++i) {
    mpq_mul(wp.get_mpq_t(), wp.get_mpq_t(), w.get_mpq_t());
    mpq_mul(a[i].get_mpq_t(), a[i].get_mpq_t(), wp.get_mpq_t());
  }
  // Monomial to Bernstein: b_k = sum_{i<=k} C(k,i)/C(n,i) a_i.
  std::vector<mpz_class> binom_n(n + 1);
  for (int i = 0; i <= n; ++i) {
    mpz_bin_uiui(binom_n[i].get_mpz_t(), static_cast<unsigned long>(n),
                 static_cast<unsigned long>(i));
  }
  std::vector<mpq_class> b(n + 1);
  mpz_class binom_k;
  for (int k = 0; k <= n; ++k) {
    for (int i = 0; i <= k; ++i) {
      mpz_bin_uiui(binom_k.get_mpz_t(), static_cast<unsigned long>(k),
                   static_cast<unsigned long>(i));
      mpq_set_num(scratch.get_mpq_t(), binom_k.get_mpz_t());
      mpq_set_den(scratch.get_mpq_t(), binom_n[i].get_mpz_t());
      mpq_canonicalize(scratch.get_mpq_t());
      mpq_mul(scratch.get_mpq_t(), scratch.get_mpq_t(), a[i].get_mpq_t());
      mpq_add(b[k].get_mpq_t(), b[k].get_mpq_t(), scratch.get_mpq_t());
    }
  }
  return b;
}

}  // namespace

RationalPoly poly_remainder(const RationalPoly& a, const RationalPoly& b) {
  RationalPoly r;
  divide(a, b, nullptr, &r);
  return r;
}

RationalPoly poly_quotient(const RationalPoly& a, const RationalPoly& b) {
  RationalPoly q;
  divide(a, b, &q, nullptr);
  return q;
}

RationalPoly poly_gcd(const RationalPoly& a, const RationalPoly& b) {
  RationalPoly x = a, y = b;
  while (!y.is_zero()) {
    RationalPoly r = poly_remainder(x, y);
    x = std::move(y);
    y = monic(r);
  }
  return monic(x);
}

RationalPoly squarefree_part(const RationalPoly& p) {
  assert(!p.is_zero());
  if (p.degree() <= 0) return p;
  const RationalPoly g = poly_gcd(p, p.derivative());
  if (g.degree() <= 0) return p;
  return poly_quotient(p, g);
}

void refine_root(const RationalPoly& p, RealRoot& root) {
  if (root.exact) return;
  mpq_class m = (root.lo + root.hi) / 2;
  const int sm = p.sign_at(m);
  if (sm == 0) {
    root.lo = m;
    root.hi = m;
    root.exact = true;
  } else if (sm == p.sign_at(root.lo)) {
    root.lo = m;
  } else {
    root.hi = m;
  }
}

std::vector<RealRoot> isolate_roots_unit(const RationalPoly& p) {
  std::vector<RealRoot> out;
  if (p.degree() <= 0) return out;
  const mpq_class zero = 0, one = 1;
  RationalPoly q = p;
  const bool root0 = p.sign_at(zero) == 0;
  const bool root1 = p.sign_at(one) == 0;
  if (root0) q = poly_quotient(q, RationalPoly::linear(0, 1));
  if (root1) q = poly_quotient(q, RationalPoly::linear(-1, 1));
  if (root0) out.push_back({zero, zero, true});
  if (q.degree() >= 1) {
    const auto sturm = sturm_sequence(q);
    std::vector<RealRoot> inner;
    isolate(q, sturm, zero, one, sign_variations(sturm, zero), sign_variations(sturm, one), inner);
    for (auto& r : inner) {
      // Keep open-interval endpoints away from roots of p at 0 and 1; q changes sign on
      // the interval, so bisect with q.
      while (!r.exact && ((root0 && r.lo == 0) || (root1 && r.hi == 1))) refine_root(q, r);
      out.push_back(r);
    }
  }
  if (root1) out.push_back({one, one, true});
  return out;
}

int sign_at_root(const RationalPoly& p, RealRoot& root, const RationalPoly& q) {
  if (root.exact) return q.sign_at(root.lo);
  if (q.degree() <= 0) return q.is_zero() ? 0 : sign_of(q.coefficients()[0]);
  auto constant_sign = [&]() {
    const auto b = bernstein_on(q, root.lo, root.hi);
    bool all_pos = true, all_neg = true;
    for (const auto& x : b) {
      all_pos &= sign_of(x) > 0;
      all_neg &= sign_of(x) < 0;
    }
    return all_pos ? 1 : (all_neg ? -1 : 0);
  };
  // Cheap first: a few bisections usually leave q with one strict sign on the interval.
  for (int i = 0; i < 4; ++i) {
    if (const int s = constant_sign()) return s;
    refine_root(p, root);
    if (root.exact) return q.sign_at(root.lo);
  }
  const RationalPoly g = poly_gcd(p, q);
  if (g.degree() >= 1 && g.sign_at(root.lo) * g.sign_at(root.hi) < 0) return 0;
  // q(root) != 0: shrink the interval until q has one strict sign on all of it.
  for (;;) {
    const auto b = bernstein_on(q, root.lo, root.hi);
    bool all_pos = true, all_neg = true;
    for (const auto& x : b) {
      all_pos &= sign_of(x) > 0;
      all_neg &= sign_of(x) < 0;
    }
    if (all_pos) return 1;
    if (all_neg) return -1;
    refine_root(p, root);
    if (root.exact) return q.sign_at(root.lo);
  }
}

mpq_class root_lower_bound(const RationalPoly& p, RealRoot root, const mpq_class& tolerance) {
  while (!root.exact && root.hi - root.lo > tolerance) refine_root(p, root);
  return root.lo;
}

std::optional<mpq_class> earliest_solution(const RationalPoly& p,
                                           const std::vector<SignCondition>& conditions,
                                           const mpq_class& tolerance) {
  if (!p.is_zero()) {
    if (p.degree() == 0) return std::nullopt;
    const RationalPoly ps = squarefree_part(p);
    auto roots = isolate_roots_unit(ps);
    for (auto& r : roots) {
      bool ok = true;
      for (const auto& c : conditions) {
        if (!holds(sign_at_root(ps, r, c.poly), c.strict)) {
          ok = false;
          break;
        }
      }
      if (ok) return root_lower_bound(ps, r, tolerance);
    }
    return std::nullopt;
  }

  // p == 0: the set S where every condition holds is a union of points and intervals; its
  // infimum is 0 or a root of some condition, and a candidate c is the infimum's upper
  // bound iff c is in S or S contains (c, c + eps). Sign of q just right of c: the sign of
  // the first derivative of q that does not vanish at c.
  std::vector<const SignCondition*> moving;
  for (const auto& c : conditions) {
    if (c.poly.degree() <= 0) {
      const int s = c.poly.is_zero() ? 0 : sign_of(c.poly.coefficients()[0]);
      if (!holds(s, c.strict)) return std::nullopt;
    } else {
      moving.push_back(&c);
    }
  }
  if (moving.empty()) return mpq_class(0);

  // Signs at c and just right of c of every moving condition; `sign_of_poly(q)` gives the
  // exact sign of q at c.
  auto qualifies = [&](auto&& sign_of_poly, bool at_one) {
    bool in_set = true, right_of = !at_one;
    for (const SignCondition* c : moving) {
      const int s = sign_of_poly(c->poly);
      in_set = in_set && holds(s, c->strict);
      if (right_of) {
        int r = s;
        for (RationalPoly d = c->poly.derivative(); r == 0 && !d.is_zero(); d = d.derivative()) {
          r = sign_of_poly(d);
        }
        right_of = holds(r, c->strict);
      }
      if (!in_set && !right_of) return false;
    }
    return true;
  };

  const mpq_class zero(0);
  if (qualifies([&](const RationalPoly& q) { return q.sign_at(zero); }, false)) return zero;
  std::optional<mpq_class> best;
  for (const SignCondition* c : moving) {
    const RationalPoly d = squarefree_part(c->poly);
    for (RealRoot root : isolate_roots_unit(d)) {
      if (root.exact && root.lo == 0) continue;  // done above
      // A candidate can only improve on the best if its interval starts below it.
      if (best && root.lo >= *best) break;
      const bool at_one = root.exact && root.lo == 1;
      if (qualifies([&](const RationalPoly& q) { return sign_at_root(d, root, q); }, at_one)) {
        const mpq_class lb = root_lower_bound(d, root, tolerance);
        if (!best || lb < *best) best = lb;
        break;  // later roots of this condition are larger
      }
    }
  }
  return best;
}

}  // namespace tailor::detail
