#pragma once
/// @file
/// One function per bound module of the library; module.cpp calls them in layer order.

#include <pybind11/pybind11.h>

#include "tailor/detection/detection_config.hpp"

namespace tailor::python {

namespace py = pybind11;

void bind_mesh(py::module_& m);              ///< Mesh (mesh.cpp)
void bind_io(py::module_& m);                ///< read_mesh, write_mesh (io.cpp)
void bind_ccd(py::module_& m);               ///< ccd_vertex_face, ccd_edge_edge (ccd.cpp)
void bind_detection_config(py::module_& m);  ///< DetectionConfig (detection_config.cpp)
void bind_detection(py::module_& m);         ///< detect, SelfCollisionDetector, ... (detection.cpp)
void bind_sim(py::module_& m);               ///< SceneConfig, Simulation (sim.cpp)
void bind_sequence(py::module_& m);          ///< check_sequence (sequence.cpp)

/// The configuration `method` names: a preset name (str) or a DetectionConfig; `threads`
/// (0: all cores) replaces a preset's and, when positive, a DetectionConfig's. Throws
/// InputError on an unknown preset, ValueError on anything else wrong (detection_config.cpp).
DetectionConfig detection_config(py::handle method, int threads);

/// Every field of DetectionStats as a list of dicts (name, unit, stage, help)
/// (detection_config.cpp).
py::list stat_fields();

}  // namespace tailor::python
