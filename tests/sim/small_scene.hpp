#pragma once
// The sleeve scenes of the simulation tests: small and fast versions of the default scene.

#include <string>

#include "tailor/sim/simulation.hpp"

namespace tailor::testing {

/// The default scene with a 13 × 20 sleeve, `gesture` played twice as fast after a 0.1 s
/// settle. Callers pick the substeps (the arm moves twice as far per substep as in the
/// default scene unless they double them).
inline SceneConfig small_fast_scene(const std::string& gesture) {
  SceneConfig c;
  c.sleeve.rings = 13;
  c.sleeve.segments = 20;
  c.gesture.name = gesture;
  c.gesture.settle_time = 0.1;
  c.gesture.speed = 2.0;
  return c;
}

}  // namespace tailor::testing
