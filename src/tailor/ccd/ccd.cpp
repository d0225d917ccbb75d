#include "tailor/ccd/ccd.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <stdexcept>

#include "tailor/ccd/ccd_double.hpp"
#include "tailor/ccd/ccd_exact.hpp"

namespace tailor {

namespace {

/// The non-coplanarity filter: f certainly keeps one strict sign over the step when all
/// four certified coefficient signs agree. (Undecided signs are not settled exactly here:
/// the later tiers handle those queries.)
bool never_coplanar(const detail::CoplanarityBernstein& f) {
  if (!f.valid) return false;
  int positive = 0, negative = 0;
  for (int i = 0; i < 4; ++i) {
    positive += f.value[i] > f.bound[i];
    negative += f.value[i] < -f.bound[i];
  }
  return positive == 4 || negative == 4;
}

}  // namespace

const char* ccd_path_name(CcdPath path) {
  switch (path) {
    case CcdPath::filter:
      return "filter";
    case CcdPath::double_precision:
      return "double";
    case CcdPath::exact_signs:
      return "exact_signs";
    case CcdPath::exact:
      return "exact";
    case CcdPath::gmp:
      return "gmp";
  }
  return "?";
}

CcdResult vertex_face_ccd(const VertexFaceQuery& q) {
  const detail::CoplanarityBernstein f = detail::coplanarity_bernstein(q);
  if (never_coplanar(f)) return {false, 1.0, CcdPath::filter};
  if (auto r = detail::vertex_face_ccd_double(q, f)) return *r;
  return detail::vertex_face_ccd_exact(q);
}

CcdResult edge_edge_ccd(const EdgeEdgeQuery& q) {
  const detail::CoplanarityBernstein f = detail::coplanarity_bernstein(q);
  if (never_coplanar(f)) return {false, 1.0, CcdPath::filter};
  if (auto r = detail::edge_edge_ccd_double(q, f)) return *r;
  return detail::edge_edge_ccd_exact(q);
}

namespace {

template <class Query, class Fn>
void run_batch(std::span<const Query> queries, std::span<CcdResult> results, Fn&& fn) {
  if (queries.size() != results.size()) {
    throw std::invalid_argument("ccd batch: results must have the size of queries");
  }
  // Each result depends on its query only, so the answer is the same for any thread count.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, queries.size(), 64),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        results[i] = fn(queries[i]);
                      }
                    });
}

}  // namespace

void vertex_face_ccd(std::span<const VertexFaceQuery> queries, std::span<CcdResult> results) {
  run_batch(queries, results, [](const VertexFaceQuery& q) { return vertex_face_ccd(q); });
}

void edge_edge_ccd(std::span<const EdgeEdgeQuery> queries, std::span<CcdResult> results) {
  run_batch(queries, results, [](const EdgeEdgeQuery& q) { return edge_edge_ccd(q); });
}

}  // namespace tailor
