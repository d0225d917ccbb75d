/// @file
/// `tailor.SceneConfig` and `tailor.Simulation` (the arm-sleeve scene); the generator
/// `tailor.simulate` is written in Python on top of them (tailor/__init__.py).

#include <fmt/format.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <tbb/global_control.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "errors.hpp"
#include "json_objects.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/scene/scene.hpp"
#include "tailor/sim/frame_writer.hpp"
#include "tailor/sim/simulation.hpp"

namespace tailor::python {
namespace {

/// A Simulation and the thread limit its steps run with.
struct PySimulation {
  Simulation simulation;
  int threads = 0;
};

using SimulationPtr = std::shared_ptr<PySimulation>;

std::shared_ptr<PySimulation> make_simulation(const SceneConfig& scene, py::handle gesture,
                                              py::handle method, int threads,
                                              bool check_intersections) {
  SceneConfig config = scene;
  if (!gesture.is_none()) config.gesture.name = py::str(gesture).cast<std::string>();
  SimulationOptions options;
  options.detection = detection_config(method, threads);
  options.check_intersections = check_intersections;
  options.check_frames = true;  // as `tailor simulate`: cheap at the default size
  py::gil_scoped_release release;
  return std::make_shared<PySimulation>(PySimulation{Simulation(config, options), threads});
}

// A Mesh sharing ownership with the simulation that holds it.
std::shared_ptr<TriangleMesh> mesh_of(const SimulationPtr& owner, const TriangleMesh& mesh) {
  return {owner, const_cast<TriangleMesh*>(&mesh)};
}

/// Runs `frames` more frames writing what `tailor simulate --out` writes (OBJ frames, steps.jsonl,
/// summary.json; no pictures) into `out`; returns the summary.
nlohmann::json run_to_folder(PySimulation& s, const std::filesystem::path& out, int frames) {
  std::optional<tbb::global_control> limit;
  if (s.threads > 0) {
    limit.emplace(tbb::global_control::max_allowed_parallelism,
                  static_cast<std::size_t>(s.threads));
  }
  Simulation& sim = s.simulation;
  FrameWriter writer(out);
  const auto& cloth_faces = sim.cloth_mesh().faces();
  const auto& arm_faces = sim.arm_mesh().faces();
  writer.write_frame(sim.frame(), sim.cloth_positions(), cloth_faces, sim.arm_positions(),
                     arm_faces);
  for (int f = 0; f < frames; ++f) {
    const auto& records = sim.step_frame();
    writer.write_frame(sim.frame(), sim.cloth_positions(), cloth_faces, sim.arm_positions(),
                       arm_faces);
    writer.append_steps(records);
  }
  nlohmann::json summary = simulation_summary(sim, false);
  writer.write_summary(summary);
  return summary;
}

}  // namespace

void bind_sim(py::module_& m) {
  py::class_<SceneConfig>(m, "SceneConfig",
                          "Settings of the arm-sleeve scene (the defaults are the demo run's; "
                          "see scenes/sleeve.json for every field).")
      .def(py::init<>())
      .def_static(
          "load",
          [](const std::filesystem::path& path) {
            SceneConfig config;
            with_file_errors(path, [&] { config = load_scene_config(path); });
            return config;
          },
          py::arg("path"), "Reads a scene file (JSON).")
      .def_static(
          "from_dict",
          [](py::handle settings) {
            return parse_scene_config(to_json_value(settings, "scene"), "scene");
          },
          py::arg("settings"),
          "A scene from a dict shaped like the scene file (every field optional; unknown "
          "fields are errors).")
      .def("to_dict", [](const SceneConfig& c) { return to_python(scene_config_to_json(c)); })
      .def_property_readonly("frames", [](const SceneConfig& c) { return c.frames; })
      .def_property_readonly("substeps", [](const SceneConfig& c) { return c.substeps; })
      .def_property_readonly("time_step", [](const SceneConfig& c) { return c.time_step; })
      .def_property_readonly("gesture", [](const SceneConfig& c) { return c.gesture.name; });

  py::class_<PySimulation, SimulationPtr>(m, "Simulation",
                                          "The arm-sleeve simulation, advanced frame by frame "
                                          "(tailor.simulate wraps it as a generator).")
      .def(py::init(&make_simulation), py::arg("scene") = SceneConfig{}, py::kw_only(),
           py::arg("gesture") = py::none(), py::arg("method") = "paper", py::arg("threads") = 0,
           py::arg("check_intersections") = false,
           "Builds the scene. `gesture` overrides the scene's (elbow, raise, twist); `method` is "
           "the detection preset or a DetectionConfig; `check_intersections` runs the static "
           "intersection check after every substep (else after every frame).")
      .def(
          "step_frame",
          [](PySimulation& s) {
            nlohmann::json records;
            {
              py::gil_scoped_release release;
              std::optional<tbb::global_control> limit;
              if (s.threads > 0) {
                limit.emplace(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(s.threads));
              }
              records = s.simulation.step_frame();
            }
            return to_python(records);
          },
          "Advances one frame; returns its substeps as dicts (as in steps.jsonl).")
      .def(
          "run_to_folder",
          [](PySimulation& s, const std::filesystem::path& out, py::handle frames) {
            const int count =
                frames.is_none() ? s.simulation.scene().config().frames : frames.cast<int>();
            if (count < 0) throw py::value_error("frames must be >= 0");
            nlohmann::json summary;
            {
              py::gil_scoped_release release;
              summary = run_to_folder(s, out, count);
            }
            return to_python(summary);
          },
          py::arg("out"), py::arg("frames") = py::none(),
          "Simulates `frames` more frames (default: the scene's) and writes the run into the "
          "folder `out` as `tailor simulate --out` does (cloth_NNNN.obj, arm_NNNN.obj from the "
          "current frame on, steps.jsonl, summary.json; no pictures); returns the summary "
          "dict. Raises InputError when the folder cannot be written.")
      .def_property_readonly("frame", [](const PySimulation& s) { return s.simulation.frame(); })
      .def_property_readonly("time", [](const PySimulation& s) { return s.simulation.time(); })
      .def_property_readonly(
          "cloth_positions",
          [](const PySimulation& s) { return adopt(Positions(s.simulation.cloth_positions())); },
          "(n, 3) cloth positions now (a copy: the simulation moves on).")
      .def_property_readonly(
          "cloth_velocities",
          [](const PySimulation& s) { return adopt(Positions(s.simulation.cloth_velocities())); })
      .def_property_readonly(
          "arm_positions",
          [](const PySimulation& s) { return adopt(Positions(s.simulation.arm_positions())); })
      .def_property_readonly(
          "cloth_mesh",
          [](const SimulationPtr& s) { return mesh_of(s, s->simulation.cloth_mesh()); },
          "The sleeve's connectivity (a Mesh).")
      .def_property_readonly(
          "arm_mesh", [](const SimulationPtr& s) { return mesh_of(s, s->simulation.arm_mesh()); })
      .def_property_readonly(
          "observer_loops",
          [](const PySimulation& s) { return s.simulation.scene().observer_loops(); },
          "Section loops of the two radial-view observers (for detect(observers=...)).")
      .def_property_readonly("scene",
                             [](const PySimulation& s) { return s.simulation.scene().config(); })
      .def(
          "summary",
          [](const PySimulation& s) { return to_python(simulation_summary(s.simulation, false)); },
          "The run so far as a dict (as summary.json): steps, collisions, intersections, "
          "times.");
}

}  // namespace tailor::python
