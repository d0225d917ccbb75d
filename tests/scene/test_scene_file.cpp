/// @file
/// Scene files: defaults, the committed scene, and every kind of rejected input.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tailor/geometry/error.hpp"
#include "tailor/scene/scene.hpp"

namespace tailor {
namespace {

namespace fs = std::filesystem;

/// Writes `text` to a fresh file under the test's temporary folder.
fs::path write_temp(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "tailor_test_scene";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return path;
}

/// The InputError message load_scene_config throws for `text`, or "" if none.
std::string load_error(const std::string& name, const std::string& text) {
  const fs::path path = write_temp(name, text);
  try {
    load_scene_config(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneFile, EmptyObjectGivesDefaults) {
  const SceneConfig c = parse_scene_config(nlohmann::json::object(), "x.json");
  const SceneConfig d;
  EXPECT_EQ(c.sleeve.rings, 21);
  EXPECT_EQ(c.sleeve.segments, 33);
  EXPECT_EQ(c.gesture.name, "elbow");
  EXPECT_DOUBLE_EQ(c.time_step, d.time_step);
  EXPECT_EQ(c.frames, d.frames);
  EXPECT_EQ(c.gravity, d.gravity);
}

TEST(SceneFile, CommittedSceneEqualsTheBuiltInDefaults) {
  const SceneConfig c = load_scene_config(fs::path(TAILOR_SOURCE_DIR) / "scenes" / "sleeve.json");
  EXPECT_EQ(scene_config_to_json(c), scene_config_to_json(SceneConfig{}));
}

TEST(SceneFile, RoundTripsThroughJson) {
  SceneConfig c;
  c.sleeve.rings = 7;
  c.gesture.name = "twist";
  c.material.bending_stiffness = 3e-6;
  c.gravity = Vec3(0, 0, -9.81);
  const SceneConfig back = parse_scene_config(scene_config_to_json(c), "round-trip");
  EXPECT_EQ(scene_config_to_json(back), scene_config_to_json(c));
}

TEST(SceneFile, ReadsEveryKindOfField) {
  const fs::path p = write_temp("ok.json", R"({"sleeve": {"rings": 9, "segments": 12,
      "material": {"density": 0.2}}, "gesture": {"name": "raise"}, "frames": 5,
      "substeps": 3, "gravity": [0, 0, -9.81], "contact": {"thickness": 0.001}})");
  const SceneConfig c = load_scene_config(p);
  EXPECT_EQ(c.sleeve.rings, 9);
  EXPECT_EQ(c.sleeve.segments, 12);
  EXPECT_DOUBLE_EQ(c.material.density, 0.2);
  EXPECT_EQ(c.gesture.name, "raise");
  EXPECT_EQ(c.frames, 5);
  EXPECT_EQ(c.substeps, 3);
  EXPECT_EQ(c.gravity, Vec3(0, 0, -9.81));
  EXPECT_DOUBLE_EQ(c.contact.thickness, 0.001);
}

TEST(SceneFile, UnknownFieldIsNamedWithItsPathAndTheFile) {
  const std::string top = load_error("unknown_top.json", R"({"framez": 3})");
  EXPECT_NE(top.find("unknown field 'framez'"), std::string::npos) << top;
  EXPECT_NE(top.find("unknown_top.json"), std::string::npos) << top;
  const std::string nested =
      load_error("unknown_nested.json", R"({"sleeve": {"material": {"colour": 1}}})");
  EXPECT_NE(nested.find("'sleeve.material.colour'"), std::string::npos) << nested;
  EXPECT_NE(nested.find("unknown_nested.json"), std::string::npos) << nested;
}

TEST(SceneFile, BadValueIsNamed) {
  const std::string rings = load_error("bad_rings.json", R"({"sleeve": {"rings": 1}})");
  EXPECT_NE(rings.find("'sleeve.rings'"), std::string::npos) << rings;
  EXPECT_NE(rings.find("bad_rings.json"), std::string::npos) << rings;
  const std::string length =
      load_error("bad_length.json", R"({"arm": {"upper_arm_length": -0.3}})");
  EXPECT_NE(length.find("'arm.upper_arm_length'"), std::string::npos) << length;
  const std::string fraction = load_error("bad_int.json", R"({"frames": 2.5})");
  EXPECT_NE(fraction.find("'frames'"), std::string::npos) << fraction;
  const std::string gesture = load_error("bad_gesture.json", R"({"gesture": {"name": "wave"}})");
  EXPECT_NE(gesture.find("'gesture.name'"), std::string::npos) << gesture;
  EXPECT_NE(gesture.find("wave"), std::string::npos) << gesture;
  const std::string too_long = load_error("too_long.json", R"({"sleeve": {"length": 0.9}})");
  EXPECT_NE(too_long.find("'sleeve.length'"), std::string::npos) << too_long;
  const std::string gravity = load_error("bad_gravity.json", R"({"gravity": [0, -9.81]})");
  EXPECT_NE(gravity.find("'gravity'"), std::string::npos) << gravity;
}

TEST(SceneFile, WrongTypeIsNamed) {
  const std::string number =
      load_error("type_number.json", R"({"arm": {"forearm_length": "long"}})");
  EXPECT_NE(number.find("'arm.forearm_length'"), std::string::npos) << number;
  EXPECT_NE(number.find("must be a number"), std::string::npos) << number;
  EXPECT_NE(number.find("type_number.json"), std::string::npos) << number;
  const std::string object = load_error("type_object.json", R"({"sleeve": [21, 33]})");
  EXPECT_NE(object.find("'sleeve'"), std::string::npos) << object;
  const std::string boolean = load_error("type_bool.json", R"({"substeps": true})");
  EXPECT_NE(boolean.find("'substeps'"), std::string::npos) << boolean;
  const std::string top = load_error("type_top.json", R"([1, 2, 3])");
  EXPECT_NE(top.find("type_top.json"), std::string::npos) << top;
}

TEST(SceneFile, MissingFileIsNamed) {
  const fs::path missing = fs::temp_directory_path() / "tailor_test_scene" / "no_such_scene.json";
  fs::remove(missing);
  try {
    load_scene_config(missing);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_scene.json"), std::string::npos) << e.what();
  }
}

TEST(SceneFile, MalformedJsonIsNamed) {
  const std::string m = load_error("malformed.json", R"({"frames": 3,,})");
  EXPECT_NE(m.find("malformed.json"), std::string::npos) << m;
  EXPECT_NE(m.find("malformed JSON"), std::string::npos) << m;
}

TEST(Scene, ExposesSectionLoops) {
  const Scene scene{SceneConfig{}};
  const auto rings = scene.sleeve_rings();
  ASSERT_EQ(rings.size(), 21u);
  for (const auto& ring : rings) EXPECT_EQ(ring.size(), 33u);
  EXPECT_EQ(scene.open_end_rings()[0], 0);
  EXPECT_EQ(scene.open_end_rings()[1], 20);
  // The elbow ring lies at the elbow (x = upper arm length) within half a ring spacing.
  const double spacing = scene.config().sleeve.length / 20;
  const double x = scene.sleeve().rest(rings[static_cast<std::size_t>(scene.elbow_ring())][0], 0);
  EXPECT_NEAR(x, scene.config().arm.upper_arm_length, 0.5 * spacing + 1e-12);
  // Observers along the arm: one at the elbow ring, the others every ~0.18 m (7 rings of
  // 2.65 cm) toward both ends, never on an open end ring.
  const auto& observer_rings = scene.sleeve().observer_rings;
  const std::vector<Index> expected{4, 11, 18};
  EXPECT_EQ(observer_rings, expected);
  EXPECT_EQ(observer_rings[1], scene.elbow_ring());
  const auto observers = scene.observer_loops();
  ASSERT_EQ(observers.size(), expected.size());
  for (std::size_t i = 0; i < observers.size(); ++i) {
    EXPECT_EQ(observers[i], rings[static_cast<std::size_t>(expected[i])]);
  }
}

}  // namespace
}  // namespace tailor
