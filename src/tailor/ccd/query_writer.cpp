#include "tailor/ccd/query_writer.hpp"

#include <gmpxx.h>

#include <cmath>
#include <stdexcept>

#include "tailor/io/file_bytes.hpp"

namespace tailor {

namespace {

/// "num,den" with den a power of two and num/den == x exactly.
void append_exact(std::string& out, double x) {
  if (!std::isfinite(x)) throw std::invalid_argument("ccd query writer: non-finite coordinate");
  int exponent = 0;
  const double mantissa = std::frexp(x, &exponent);  // x = mantissa 2^exponent
  // mantissa 2^53 is an integer: x = m 2^(exponent - 53).
  mpz_class num;
  mpz_set_d(num.get_mpz_t(), std::ldexp(mantissa, 53));
  mpz_class den = 1;
  const long shift = static_cast<long>(exponent) - 53;
  if (shift >= 0) {
    num <<= static_cast<mp_bitcnt_t>(shift);
  } else {
    den <<= static_cast<mp_bitcnt_t>(-shift);
  }
  // Smallest terms: drop common factors of two.
  while (den > 1 && mpz_even_p(num.get_mpz_t())) {
    num >>= 1;
    den >>= 1;
  }
  if (num == 0) den = 1;
  out += num.get_str();
  out += ',';
  out += den.get_str();
}

void append_row(std::string& out, const Vec3& x, int truth) {
  for (int k = 0; k < 3; ++k) {
    if (k > 0) out += ',';
    append_exact(out, x[k]);
  }
  if (truth >= 0) {
    out += ',';
    out += truth ? '1' : '0';
  }
  out += '\n';
}

template <class Query, class Rows>
std::string to_csv(std::span<const Query> queries, const std::vector<bool>& truth, Rows&& rows) {
  if (!truth.empty() && truth.size() != queries.size()) {
    throw std::invalid_argument("ccd query writer: truth must have one entry per query");
  }
  std::string out;
  out.reserve(queries.size() * 8 * 80);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const int t = truth.empty() ? -1 : static_cast<int>(truth[i]);
    for (const Vec3* x : rows(queries[i])) append_row(out, *x, t);
  }
  return out;
}

}  // namespace

std::string ccd_queries_csv(std::span<const VertexFaceQuery> queries,
                            const std::vector<bool>& truth) {
  return to_csv(queries, truth, [](const VertexFaceQuery& q) {
    return std::array<const Vec3*, 8>{&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0,
                                      &q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1};
  });
}

std::string ccd_queries_csv(std::span<const EdgeEdgeQuery> queries,
                            const std::vector<bool>& truth) {
  return to_csv(queries, truth, [](const EdgeEdgeQuery& q) {
    return std::array<const Vec3*, 8>{&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0,
                                      &q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1};
  });
}

void write_ccd_queries(const std::string& path, std::span<const VertexFaceQuery> queries,
                       const std::vector<bool>& truth) {
  write_file_atomically(path, ccd_queries_csv(queries, truth));
}

void write_ccd_queries(const std::string& path, std::span<const EdgeEdgeQuery> queries,
                       const std::vector<bool>& truth) {
  write_file_atomically(path, ccd_queries_csv(queries, truth));
}

}  // namespace tailor
