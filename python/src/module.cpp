/// @file
/// The compiled part of the `tailor` Python package (`tailor._tailor`); the package's
/// __init__.py re-exports it and adds the `simulate` generator.

#include "arrays.hpp"
#include "bindings.hpp"
#include "errors.hpp"

PYBIND11_MODULE(_tailor, m) {
  namespace python = tailor::python;
  m.doc() = "tailor: exact continuous self-collision detection for cloth (compiled core)";
  python::bind_errors(m);
  python::bind_mesh(m);
  python::bind_io(m);
  python::bind_ccd(m);
  python::bind_detection_config(m);
  python::bind_detection(m);
  python::bind_sim(m);
  python::bind_sequence(m);
  m.def(
      "_input_copies", [] { return python::input_copies(); },
      "How many times the bindings have copied an input array's data (for tests).");
}
