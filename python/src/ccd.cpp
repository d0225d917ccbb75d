/// @file
/// `tailor.ccd_vertex_face` and `tailor.ccd_edge_edge`: the exact CCD on batches given as
/// eight (n, 3) arrays.

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <array>
#include <cmath>

#include "arrays.hpp"
#include "bindings.hpp"
#include "tailor/ccd/ccd.hpp"

namespace tailor::python {
namespace {

// The eight points of a query in the order of its arguments (t0 then t1).
std::array<Vec3*, 8> points_of(VertexFaceQuery& q) {
  return {&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0, &q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1};
}
std::array<Vec3*, 8> points_of(EdgeEdgeQuery& q) {
  return {&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0, &q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1};
}

using Names = std::array<const char*, 8>;
constexpr Names kVertexFaceNames{"p0", "a0", "b0", "c0", "p1", "a1", "b1", "c1"};
constexpr Names kEdgeEdgeNames{"a0", "b0", "c0", "d0", "a1", "b1", "c1", "d1"};

// The single-query CCD on each row, reading the caller's arrays in place: the library's
// batch form takes an array of query structs, which would mean copying the eight arrays
// into one; here each task assembles its query on the stack instead.
template <class Query, CcdResult (*ccd)(const Query&)>
py::tuple ccd_batch(const std::array<py::object, 8>& objects, const Names& names, int threads) {
  if (threads < 0) throw py::value_error(fmt::format("threads must be ≥ 0, got {}", threads));
  std::array<DoubleArray, 8> arrays;
  std::array<const double*, 8> rows{};
  for (std::size_t k = 0; k < 8; ++k) {
    arrays[k] = float64_rows(objects[k], names[k]);
    rows[k] = arrays[k].data();
    if (arrays[k].shape(0) != arrays[0].shape(0)) {
      throw py::value_error(fmt::format("{} has {} rows, {} has {}", names[k], arrays[k].shape(0),
                                        names[0], arrays[0].shape(0)));
    }
    for (py::ssize_t i = 0; i < arrays[k].size(); ++i) {
      if (!std::isfinite(rows[k][i])) {
        throw py::value_error(
            fmt::format("{} has a non-finite coordinate in row {}", names[k], i / 3));
      }
    }
  }
  const auto n = static_cast<std::size_t>(arrays[0].shape(0));
  py::array_t<bool> hit(static_cast<py::ssize_t>(n));
  py::array_t<double> toi(static_cast<py::ssize_t>(n));
  bool* hit_out = hit.mutable_data();
  double* toi_out = toi.mutable_data();
  {
    py::gil_scoped_release release;
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 64),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          Query query;
                          const auto points = points_of(query);
                          for (std::size_t i = range.begin(); i != range.end(); ++i) {
                            for (std::size_t k = 0; k < 8; ++k) {
                              *points[k] =
                                  Vec3(rows[k][3 * i], rows[k][3 * i + 1], rows[k][3 * i + 2]);
                            }
                            const CcdResult result = ccd(query);
                            hit_out[i] = result.hit;
                            toi_out[i] = result.toi;
                          }
                        });
    });
  }
  return py::make_tuple(hit, toi);
}

// Defines `name(<8 arrays named names>, *, threads=0)` running ccd_batch.
template <class Query, CcdResult (*ccd)(const Query&)>
void def_batch(py::module_& m, const char* name, const Names& names, const char* doc) {
  m.def(
      name,
      [names](py::object x0, py::object x1, py::object x2, py::object x3, py::object x4,
              py::object x5, py::object x6, py::object x7, int threads) {
        return ccd_batch<Query, ccd>({x0, x1, x2, x3, x4, x5, x6, x7}, names, threads);
      },
      py::arg(names[0]), py::arg(names[1]), py::arg(names[2]), py::arg(names[3]), py::arg(names[4]),
      py::arg(names[5]), py::arg(names[6]), py::arg(names[7]), py::kw_only(),
      py::arg("threads") = 0, doc);
}

}  // namespace

void bind_ccd(py::module_& m) {
  def_batch<VertexFaceQuery, &vertex_face_ccd>(
      m, "ccd_vertex_face", kVertexFaceNames,
      "Exact vertex-face CCD of n queries: point p against triangle (a, b, c), each an (n, 3) "
      "array at t=0 (p0 ...) and t=1 (p1 ...), moving linearly. Returns (hit, toi): hit[i] is "
      "True when the point meets the closed triangle at some t in [0, 1] (exactly, degenerate "
      "cases included); toi[i] is never later than the first contact (1 when no hit). "
      "float64 C-contiguous arrays are read in place; the GIL is released while it runs.");
  def_batch<EdgeEdgeQuery, &edge_edge_ccd>(
      m, "ccd_edge_edge", kEdgeEdgeNames,
      "Exact edge-edge CCD of n queries: edge (a, b) against edge (c, d), each endpoint an "
      "(n, 3) array at t=0 (a0 ...) and t=1 (a1 ...). Returns (hit, toi) as ccd_vertex_face.");
}

}  // namespace tailor::python
