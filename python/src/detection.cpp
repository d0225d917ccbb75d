/// @file
/// `tailor.detect` (the one-off form), `tailor.brute_force`, `tailor.proximity_pairs` (one
/// configuration) and `tailor.ProximitySearch` (its repeated form), `tailor.collision_free_step`,
/// `tailor.SelfCollisionDetector`
/// (for many steps of one mesh) and `tailor.DetectionResult` (DetectionConfig:
/// detection_config.cpp).

#include <fmt/format.h>
#include <pybind11/stl.h>
#include <tbb/task_arena.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "json_objects.hpp"
#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/collision_free_step.hpp"
#include "tailor/detection/proximity_pairs.hpp"
#include "tailor/detection/self_collision_detector.hpp"

namespace tailor::python {
namespace {

using MeshPtr = std::shared_ptr<TriangleMesh>;

/// The collisions of a step as NumPy arrays.
struct PyDetectionResult {
  py::array vertex_face, edge_edge, edge_ids, toi, vertex_face_toi, edge_edge_toi;
  py::object stats = py::none();
  std::size_t size = 0;
};

PyDetectionResult make_result(const CollisionSet& collisions, const DetectionStats* stats) {
  const auto nvf = static_cast<py::ssize_t>(collisions.vertex_face.size());
  const auto nee = static_cast<py::ssize_t>(collisions.edge_edge.size());
  py::array_t<Index> vf({nvf, py::ssize_t{2}}), ee({nee, py::ssize_t{4}}),
      ids({nee, py::ssize_t{2}});
  py::array_t<double> toi(nvf + nee);
  auto vf_out = vf.mutable_unchecked<2>();
  auto ee_out = ee.mutable_unchecked<2>();
  auto ids_out = ids.mutable_unchecked<2>();
  double* toi_out = toi.mutable_data();
  for (py::ssize_t i = 0; i < nvf; ++i) {
    const auto& c = collisions.vertex_face[static_cast<std::size_t>(i)];
    vf_out(i, 0) = c.vertex;
    vf_out(i, 1) = c.face;
    toi_out[i] = c.toi;
  }
  for (py::ssize_t i = 0; i < nee; ++i) {
    const auto& c = collisions.edge_edge[static_cast<std::size_t>(i)];
    ee_out(i, 0) = c.a0, ee_out(i, 1) = c.a1, ee_out(i, 2) = c.b0, ee_out(i, 3) = c.b1;
    ids_out(i, 0) = c.edge_a, ids_out(i, 1) = c.edge_b;
    toi_out[nvf + i] = c.toi;
  }
  PyDetectionResult result;
  result.vertex_face = vf;
  result.edge_edge = ee;
  result.edge_ids = ids;
  result.toi = toi;
  // Views into `toi` (no copy).
  result.vertex_face_toi = py::array_t<double>({nvf}, {py::ssize_t{sizeof(double)}}, toi_out, toi);
  result.edge_edge_toi =
      py::array_t<double>({nee}, {py::ssize_t{sizeof(double)}}, toi_out + nvf, toi);
  if (stats != nullptr) result.stats = to_python(nlohmann::json(*stats));
  result.size = collisions.size();
  return result;
}

MeshPtr mesh_from(py::handle mesh_or_faces, Index num_vertices) {
  if (py::isinstance<TriangleMesh>(mesh_or_faces)) return mesh_or_faces.cast<MeshPtr>();
  return std::make_shared<TriangleMesh>(num_vertices, to_faces(mesh_or_faces, "faces"));
}

bool overlaps(const DoubleArray& array, const Positions& buffer) {
  const double* begin = array.data();
  const double* end = begin + array.size();
  return begin < buffer.data() + buffer.size() && buffer.data() < end;
}

/// A SelfCollisionDetector with the two position buffers it detects on. The C++ API takes
/// `const Positions&`, so arrays from Python are copied into the buffers, except the
/// buffers themselves (the `x0`, `x1` views), which are used in place. The buffers are
/// never reallocated (their row count is the mesh's), so those views stay valid.
class PyDetector {
 public:
  PyDetector(MeshPtr mesh, py::handle x_build, const DetectionConfig& config,
             std::vector<std::vector<Index>> loops)
      : m_mesh(std::move(mesh)) {
    copy_positions(float64_rows(x_build, "x_build"), m_x0);
    m_x1 = m_x0;  // a step without motion until x1 is given
    py::gil_scoped_release release;
    m_detector.emplace(*m_mesh, m_x0, config, std::move(loops));
  }

  PyDetectionResult detect(py::handle x0, py::handle x1) {
    Input in0 = take(x0, m_x0, "x0");
    Input in1 = take(x1, m_x1, "x1");
    in0.write_to(m_x0);
    in1.write_to(m_x1);
    DetectionResult result;
    {
      py::gil_scoped_release release;
      result = m_detector->detect(m_x0, m_x1);
    }
    return make_result(result.collisions, &result.stats);
  }

  Positions& x0() { return m_x0; }
  Positions& x1() { return m_x1; }
  const MeshPtr& mesh() const { return m_mesh; }
  const DetectionConfig& config() const { return m_detector->config(); }

 private:
  // Positions given for one buffer: nothing to do (absent, or the buffer itself), an array
  // to copy in, or a copy already taken (when the array overlaps a buffer, so that writing
  // one buffer cannot change the other input, e.g. x0=det.x1, x1=det.x0).
  struct Input {
    std::optional<DoubleArray> array;
    std::optional<Positions> staged;
    void write_to(Positions& buffer) const {
      if (staged) buffer = *staged;  // same size: the storage is reused
      if (array) copy_positions(*array, buffer);
    }
  };

  Input take(py::handle object, const Positions& buffer, const char* name) {
    Input input;
    if (object.is_none()) return input;
    DoubleArray array = float64_rows(object, name);
    if (array.data() == buffer.data() && array.shape(0) == buffer.rows()) return input;
    if (array.shape(0) != buffer.rows() || overlaps(array, m_x0) || overlaps(array, m_x1)) {
      input.staged.emplace();
      copy_positions(array, *input.staged);
      if (input.staged->rows() != buffer.rows()) {
        // The library reports the wrong row count (the same message as the CLI's).
        const bool first = &buffer == &m_x0;
        m_detector->detect(first ? *input.staged : m_x0, first ? m_x1 : *input.staged);
      }
      return input;
    }
    input.array = std::move(array);
    return input;
  }

  MeshPtr m_mesh;
  Positions m_x0, m_x1;
  std::optional<SelfCollisionDetector> m_detector;
};

/// Proximity pairs as Python arrays: (vertex_face, edge_edge), (k, 2) each.
py::tuple pairs_to_python(const ProximityPairs& pairs) {
  py::array_t<Index> vf({static_cast<py::ssize_t>(pairs.vertex_face.size()), py::ssize_t{2}});
  py::array_t<Index> ee({static_cast<py::ssize_t>(pairs.edge_edge.size()), py::ssize_t{2}});
  auto vf_out = vf.mutable_unchecked<2>();
  auto ee_out = ee.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < vf_out.shape(0); ++i) {
    vf_out(i, 0) = pairs.vertex_face[static_cast<std::size_t>(i)].vertex;
    vf_out(i, 1) = pairs.vertex_face[static_cast<std::size_t>(i)].face;
  }
  for (py::ssize_t i = 0; i < ee_out.shape(0); ++i) {
    ee_out(i, 0) = pairs.edge_edge[static_cast<std::size_t>(i)].edge_a;
    ee_out(i, 1) = pairs.edge_edge[static_cast<std::size_t>(i)].edge_b;
  }
  return py::make_tuple(vf, ee);
}

/// A ProximitySearch with the mesh it searches (kept alive) and its worker threads.
class PyProximitySearch {
 public:
  PyProximitySearch(MeshPtr mesh, int threads)
      : m_mesh(std::move(mesh)),
        m_search(*m_mesh),
        m_arena(threads > 0 ? threads : tbb::task_arena::automatic) {}

  py::tuple pairs(py::handle x, double thickness) {
    const Positions positions = to_positions(x, "x");
    ProximityPairs pairs;
    {
      py::gil_scoped_release release;
      pairs = m_arena.execute([&] { return m_search.pairs(positions, thickness); });
    }
    return pairs_to_python(pairs);
  }

 private:
  MeshPtr m_mesh;
  ProximitySearch m_search;
  tbb::task_arena m_arena;
};

}  // namespace

void bind_detection(py::module_& m) {
  py::class_<PyDetectionResult>(m, "DetectionResult", "The collisions of one step.")
      .def_readonly("vertex_face", &PyDetectionResult::vertex_face,
                    "(n, 2) int32: vertex id, face id; sorted.")
      .def_readonly(
          "edge_edge", &PyDetectionResult::edge_edge,
          "(m, 4) int32: a0, a1, b0, b1 with a0 < a1, b0 < b1, (a0, a1) < (b0, b1); sorted.")
      .def_readonly("edge_ids", &PyDetectionResult::edge_ids,
                    "(m, 2) int32: the two edges of each edge_edge row as ids in Mesh.edges.")
      .def_readonly("toi", &PyDetectionResult::toi,
                    "(n + m,) float64: times of impact, vertex-face rows first, then edge-edge; "
                    "each never later than the first contact.")
      .def_readonly("vertex_face_toi", &PyDetectionResult::vertex_face_toi, "toi[:n] (a view)")
      .def_readonly("edge_edge_toi", &PyDetectionResult::edge_edge_toi, "toi[n:] (a view)")
      .def_readonly("stats", &PyDetectionResult::stats,
                    "Per-stage counts and times (ms) as a dict (keys: stat_fields()); None for "
                    "brute_force.")
      .def_static("stat_fields", &stat_fields,
                  "Every key of `stats` as a dict: name, unit (count or ms), stage, help.")
      .def("__len__", [](const PyDetectionResult& r) { return r.size; })
      .def("__repr__", [](const PyDetectionResult& r) {
        return fmt::format("tailor.DetectionResult({} vertex-face, {} edge-edge)",
                           r.vertex_face.shape(0), r.edge_edge.shape(0));
      });

  py::class_<PyDetector>(m, "SelfCollisionDetector",
                         "Finds every self-collision of a deforming mesh over linear steps; "
                         "built once per topology, then detect() for each step.")
      .def(py::init([](MeshPtr mesh, py::handle x_build, py::handle method, int threads,
                       py::handle observers) {
             std::vector<std::vector<Index>> loops;
             if (!observers.is_none()) loops = to_index_lists(observers, "observers");
             return std::make_unique<PyDetector>(
                 std::move(mesh), x_build, detection_config(method, threads), std::move(loops));
           }),
           py::arg("mesh"), py::arg("x_build"), py::kw_only(), py::arg("method") = "paper",
           py::arg("threads") = 0, py::arg("observers") = py::none(),
           "`x_build`: (n, 3) positions the BVH is built on (usually the first frame). "
           "`method`: a preset name or a DetectionConfig; `threads`: 0 = all cores; "
           "`observers`: section loops (lists of vertex ids) for radial-view culling.")
      .def("detect", &PyDetector::detect, py::arg("x0") = py::none(), py::arg("x1") = py::none(),
           "Every vertex-face and edge-edge pair that touches while vertices move linearly from "
           "x0 to x1 ((n, 3) arrays). An omitted argument, or the detector's own `x0`/`x1` "
           "array, is used in place (no copy); other arrays are copied into those buffers. "
           "The GIL is released while it runs.")
      .def_property_readonly(
          "x0", [](py::object self) { return view_of(self.cast<PyDetector&>().x0(), self, true); },
          "The start positions detect() uses: a writable (n, 3) view (fill it in place to "
          "avoid a copy).")
      .def_property_readonly(
          "x1", [](py::object self) { return view_of(self.cast<PyDetector&>().x1(), self, true); },
          "The end positions detect() uses: a writable (n, 3) view.")
      .def_property_readonly("mesh", &PyDetector::mesh)
      .def_property_readonly("config", &PyDetector::config);

  m.def(
      "detect",
      [](py::handle mesh_or_faces, py::handle x0, py::handle x1, py::handle method, int threads,
         py::handle observers, double thickness) {
        DetectionConfig config = detection_config(method, threads);
        if (thickness != 0) config.thickness = thickness;
        const DoubleArray start = float64_rows(x0, "x0");  // converted at most once
        std::vector<std::vector<Index>> loops;
        if (!observers.is_none()) loops = to_index_lists(observers, "observers");
        PyDetector detector(mesh_from(mesh_or_faces, static_cast<Index>(start.shape(0))), start,
                            config, std::move(loops));
        return detector.detect(py::none(), x1);
      },
      py::arg("mesh"), py::arg("x0"), py::arg("x1"), py::kw_only(), py::arg("method") = "paper",
      py::arg("threads") = 0, py::arg("observers") = py::none(), py::arg("thickness") = 0.0,
      "Every self-collision of one step (the one-off form, as C++ "
      "tailor::detect_self_collisions): `mesh` is a Mesh or (m, 3) faces; x0, x1 are (n, 3) "
      "positions at the start and end; `method` a preset name or a DetectionConfig; "
      "`thickness` > 0: every pair that comes within it, at the earliest such time "
      "(DetectionConfig.thickness). For many steps of one mesh, keep a SelfCollisionDetector "
      "(it builds its BVH once).");

  m.def(
      "collision_free_step",
      [](py::handle mesh_or_faces, py::handle x0, py::handle x1, double thickness, int threads) {
        const Positions p0 = to_positions(x0, "x0");
        const Positions p1 = to_positions(x1, "x1");
        const MeshPtr mesh = mesh_from(mesh_or_faces, static_cast<Index>(p0.rows()));
        DetectionConfig config;
        config.threads = threads;
        CollisionFreeStep step;
        {
          py::gil_scoped_release release;
          step = collision_free_step(*mesh, p0, p1, thickness, config);
        }
        py::dict out;
        out["alpha"] = step.alpha;
        out["vertex_face"] =
            step.vertex_face
                ? py::object(py::make_tuple(step.vertex_face->vertex, step.vertex_face->face))
                : py::object(py::none());
        out["edge_edge"] = step.edge_edge
                               ? py::object(py::make_tuple(step.edge_edge->a0, step.edge_edge->a1,
                                                           step.edge_edge->b0, step.edge_edge->b1))
                               : py::object(py::none());
        return out;
      },
      py::arg("mesh"), py::arg("x0"), py::arg("x1"), py::arg("thickness"), py::kw_only(),
      py::arg("threads") = 0,
      "The largest fraction alpha of the step from x0 to x1 that keeps every pair sharing no "
      "vertex farther apart than `thickness` (0: never touching), a certified lower bound "
      "(within 1e-6 of it at thickness 0; see C++ tailor::collision_free_step for a pair that "
      "grazes the thickness): a dict with 'alpha' and the pair that "
      "limits it, 'vertex_face' (vertex, face) or 'edge_edge' (a0, a1, b0, b1), None when "
      "nothing does.");

  m.def(
      "proximity_pairs",
      [](py::handle mesh_or_faces, py::handle x, double thickness, int threads) {
        const Positions positions = to_positions(x, "x");
        const MeshPtr mesh = mesh_from(mesh_or_faces, static_cast<Index>(positions.rows()));
        ProximityPairs pairs;
        {
          py::gil_scoped_release release;
          tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
          pairs = arena.execute([&] { return proximity_pairs(*mesh, positions, thickness); });
        }
        return pairs_to_python(pairs);
      },
      py::arg("mesh"), py::arg("x"), py::arg("thickness"), py::kw_only(), py::arg("threads") = 0,
      "Every vertex-face and edge-edge pair of one configuration `x` ((n, 3) positions) "
      "within `thickness` of each other, exactly (as C++ tailor::proximity_pairs): a tuple "
      "(vertex_face, edge_edge) of (k, 2) arrays of (vertex, face) and (edge, edge) ids "
      "(Mesh.edges numbering), sorted; pairs sharing a vertex are left out.");

  py::class_<PyProximitySearch>(m, "ProximitySearch",
                                "proximity_pairs for repeated calls on one mesh (a simulator's "
                                "every step): the culling trees are built on the first call and "
                                "refitted on later ones (as C++ tailor::ProximitySearch).")
      .def(py::init<MeshPtr, int>(), py::arg("mesh"), py::kw_only(), py::arg("threads") = 0,
           "`mesh`: a tailor.Mesh; `threads`: 0 = all cores.")
      .def("pairs", &PyProximitySearch::pairs, py::arg("x"), py::arg("thickness"),
           "The pairs of tailor.proximity_pairs(mesh, x, thickness): a tuple (vertex_face, "
           "edge_edge) of sorted (k, 2) id arrays. The GIL is released while it runs.");

  m.def(
      "brute_force",
      [](py::handle mesh_or_faces, py::handle x0, py::handle x1) {
        const Positions p0 = to_positions(x0, "x0");
        const Positions p1 = to_positions(x1, "x1");
        const MeshPtr mesh = mesh_from(mesh_or_faces, static_cast<Index>(p0.rows()));
        CollisionSet collisions;
        {
          py::gil_scoped_release release;
          collisions = brute_force_self_collisions(*mesh, p0, p1);
        }
        return make_result(collisions, nullptr);
      },
      py::arg("mesh"), py::arg("x0"), py::arg("x1"),
      "The oracle: every non-incident vertex-face and edge-edge pair through the exact CCD "
      "(usable up to ~20K triangles).");
}

}  // namespace tailor::python
