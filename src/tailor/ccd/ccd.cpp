#include "tailor/ccd/ccd.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <stdexcept>

#include "tailor/ccd/ccd_exact.hpp"
#include "tailor/geometry/coplanarity_sign.hpp"

namespace tailor {

CcdResult vertex_face_ccd(const VertexFaceQuery& q) {
  // Every contact needs the four points coplanar (f = 0).
  if (coplanarity_sign(q.a_t0, q.b_t0, q.c_t0, q.p_t0, q.a_t1, q.b_t1, q.c_t1, q.p_t1) !=
      StepSign::mixed) {
    return {false, 1.0, CcdPath::filter};
  }
  if (auto r = detail::vertex_face_ccd_double(q)) return *r;
  return detail::vertex_face_ccd_exact(q);
}

CcdResult edge_edge_ccd(const EdgeEdgeQuery& q) {
  if (coplanarity_sign(q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0, q.ea0_t1, q.ea1_t1, q.eb0_t1,
                       q.eb1_t1) != StepSign::mixed) {
    return {false, 1.0, CcdPath::filter};
  }
  if (auto r = detail::edge_edge_ccd_double(q)) return *r;
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
