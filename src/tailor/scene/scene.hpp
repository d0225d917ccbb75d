#pragma once
/// @file
/// The arm-sleeve scene (docs/design.md §4): its settings, read from JSON, and the built
/// arm, gesture and sleeve.
///
/// Scene file (every field optional; unknown fields are errors):
/// ```json
/// { "description": "...",
///   "arm": { "upper_arm_length": 0.30, "forearm_length": 0.27, "shoulder_radius": 0.05,
///            "elbow_radius": 0.037, "wrist_radius": 0.027, "elbow_blend": 0.05,
///            "rings": 40, "segments": 24, "cap_rings": 5 },
///   "gesture": { "name": "elbow", "max_flexion_deg": 130, "speed": 1.0, "settle_time": 0.3 },
///   "sleeve": { "rings": 21, "segments": 33, "slack": 0.03, "start": 0.02, "length": 0.53,
///               "material": { "density": 0.12, "stretch_stiffness": 9800, "shear_stiffness": 45,
///                             "bending_stiffness": 7.8e-6, "stiffness_damping": 0.002,
///                             "air_damping": 0.2, "strain_limit": 0.025 } },
///   "contact": { "thickness": 0.002, "friction": 0.25, "max_impulse_iterations": 20,
///                "max_zone_iterations": 100 },
///   "time_step": 0.0333333, "substeps": 1, "frames": 80, "gravity": [0, -9.81, 0] }
/// ```

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "tailor/scene/arm.hpp"
#include "tailor/scene/cloth_material.hpp"
#include "tailor/scene/contact_params.hpp"
#include "tailor/scene/gesture.hpp"
#include "tailor/scene/sleeve.hpp"

namespace tailor {

/// Every setting of a scene, with the defaults of the demo run.
struct SceneConfig {
  /// The arm: bone lengths, radii and tessellation.
  ArmParams arm;
  /// The gesture the arm plays.
  GestureParams gesture;
  /// The sleeve: size and resolution.
  SleeveParams sleeve;
  /// The cloth material.
  ClothMaterial material;
  /// Contact handling; thickness 2 mm by default.
  ContactParams contact = [] {
    ContactParams p;
    p.thickness = 2e-3;  // 2 mm: thick enough for the default resolution's 1-3 cm edges
    return p;
  }();
  double time_step = 1.0 / 30.0;  ///< frame duration (s)
  /// Implicit steps per frame. One is enough for the sleeve: the strain limiter holds
  /// every edge within its limit and the contact solver certifies every step; three (the
  /// former default) took 2.6-3.3× as long for strains and extents no better
  /// (docs/simulation.md).
  int substeps = 1;
  int frames = 80;            ///< frames to simulate
  Vec3 gravity{0, -9.81, 0};  ///< m/s² (-y is down)
};

/// Parses a scene from JSON. `source` names the file in error messages. Throws
/// InputError naming the source and the field (e.g. `sleeve.rings`) on an unknown field,
/// a wrong type or a bad value.
SceneConfig parse_scene_config(const nlohmann::json& json, const std::string& source);

/// Reads and parses a scene file. Throws InputError naming the file if it is missing or
/// not valid JSON, and as parse_scene_config().
SceneConfig load_scene_config(const std::filesystem::path& path);

/// The scene as JSON (every field, for the summary and round trips).
nlohmann::json scene_config_to_json(const SceneConfig& config);

/// A built scene: arm, gesture and sleeve.
class Scene {
 public:
  /// Builds everything; throws InputError on inconsistent settings.
  explicit Scene(const SceneConfig& config);

  /// The settings it was built from.
  const SceneConfig& config() const { return m_config; }
  /// The skinned arm.
  const Arm& arm() const { return m_arm; }
  /// The gesture the arm plays.
  const Gesture& gesture() const { return m_gesture; }
  /// The sleeve (rest shape, connectivity, rings).
  const Sleeve& sleeve() const { return m_sleeve; }

  /// Section loops: vertex ids of each sleeve ring, shoulder end first.
  std::vector<std::vector<Index>> sleeve_rings() const { return m_sleeve.rings(); }
  /// Ring nearest to the elbow.
  Index elbow_ring() const { return m_sleeve.elbow_ring; }
  /// Section loops of the two radial-view observers (upper arm, forearm).
  std::vector<std::vector<Index>> observer_loops() const { return m_sleeve.observer_loops(); }
  /// The sleeve's open ends: {shoulder ring, wrist ring}.
  std::array<Index, 2> open_end_rings() const { return m_sleeve.open_end_rings(); }

 private:
  SceneConfig m_config;
  Arm m_arm;
  Gesture m_gesture;
  Sleeve m_sleeve;
};

}  // namespace tailor
