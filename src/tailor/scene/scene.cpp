/// @file
/// Scene files: strict JSON reading (every field named in errors) and scene building.

#include "tailor/scene/scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

#include "tailor/geometry/error.hpp"
#include "tailor/io/excerpt.hpp"
#include "tailor/io/json_file.hpp"
#include "tailor/io/memory_budget.hpp"

namespace tailor {
namespace {

using nlohmann::json;

/// Reads the fields of one JSON object, remembering which it knows, so finish() can
/// reject the rest.
class FieldReader {
 public:
  FieldReader(const json& object, std::string prefix, const std::string& source)
      : m_object(object), m_prefix(std::move(prefix)), m_source(source) {
    if (!m_object.is_object()) {
      fail_type(m_prefix.empty() ? std::string("(top level)") : m_prefix, "an object", m_object);
    }
  }

  /// A number in [lo, hi] (strictly above lo when `open_lo`).
  void number(const char* key, double& out, double lo, double hi, bool open_lo = true) {
    const json* v = take(key);
    if (v == nullptr) return;
    if (!v->is_number()) fail_type(path(key), "a number", *v);
    const double x = v->get<double>();
    const bool ok = std::isfinite(x) && (open_lo ? x > lo : x >= lo) && x <= hi;
    if (!ok) {
      fail(path(key),
           fmt::format("must be {} {} and ≤ {}, got {}", open_lo ? ">" : "≥", lo, hi, x));
    }
    out = x;
  }

  /// An integer in [lo, hi].
  void integer(const char* key, int& out, int lo, int hi) {
    const json* v = take(key);
    if (v == nullptr) return;
    bool is_int = v->is_number_integer();
    if (!is_int && v->is_number_float()) {
      const double d = v->get<double>();
      is_int = std::isfinite(d) && d == std::floor(d) && std::abs(d) < 1e15;
    }
    if (!is_int) fail_type(path(key), "an integer", *v);
    const double x = v->get<double>();
    if (x < lo || x > hi)
      fail(path(key),
           fmt::format("must be an integer in [{}, {}], got {}", lo, hi, json_excerpt(*v)));
    out = static_cast<int>(x);
  }

  void string(const char* key, std::string& out) {
    const json* v = take(key);
    if (v == nullptr) return;
    if (!v->is_string()) fail_type(path(key), "a string", *v);
    out = v->get<std::string>();
  }

  void vec3(const char* key, Vec3& out, double bound) {
    const json* v = take(key);
    if (v == nullptr) return;
    if (!v->is_array() || v->size() != 3) fail_type(path(key), "an array of three numbers", *v);
    for (int i = 0; i < 3; ++i) {
      const json& c = (*v)[static_cast<std::size_t>(i)];
      if (!c.is_number()) fail_type(path(key), "an array of three numbers", *v);
      const double x = c.get<double>();
      if (!std::isfinite(x) || std::abs(x) > bound) {
        fail(path(key), fmt::format("components must be finite and at most {} in size", bound));
      }
      out[i] = x;
    }
  }

  /// The sub-object `key`, or nullptr if absent (marks it known).
  const json* object(const char* key) {
    const json* v = take(key);
    if (v != nullptr && !v->is_object()) fail_type(path(key), "an object", *v);
    return v;
  }

  std::string path(const char* key) const { return m_prefix.empty() ? key : m_prefix + "." + key; }

  /// Throws on the first field never asked for.
  void finish() const {
    for (auto it = m_object.begin(); it != m_object.end(); ++it) {
      if (m_known.count(it.key()) == 0) {
        throw InputError(
            fmt::format("{}: unknown field '{}'", m_source, excerpt(path(it.key().c_str()))));
      }
    }
  }

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw InputError(fmt::format("{}: field '{}' {}", m_source, field, what));
  }

 private:
  const json* take(const char* key) {
    m_known.insert(key);
    const auto it = m_object.find(key);
    return it == m_object.end() ? nullptr : &*it;
  }

  [[noreturn]] void fail_type(const std::string& field, const char* expected,
                              const json& got) const {
    // json_excerpt, not dump(): a value nested 100,000 deep would overflow the stack.
    throw InputError(fmt::format("{}: field '{}' must be {}, got {} {}", m_source, field, expected,
                                 got.type_name(), json_excerpt(got)));
  }

  const json& m_object;
  std::string m_prefix;
  const std::string& m_source;
  std::set<std::string> m_known;
};

constexpr double kBig = 1e12;

}  // namespace

namespace {

// The "arm" object of a scene file.
void read_arm(const json& object, const std::string& source, ArmParams& arm) {
  FieldReader r(object, "arm", source);
  r.number("upper_arm_length", arm.upper_arm_length, 0, 10);
  r.number("forearm_length", arm.forearm_length, 0, 10);
  r.number("shoulder_radius", arm.shoulder_radius, 0, 5);
  r.number("elbow_radius", arm.elbow_radius, 0, 5);
  r.number("wrist_radius", arm.wrist_radius, 0, 5);
  r.number("elbow_blend", arm.elbow_blend, 0, 5);
  r.integer("rings", arm.rings, 2, 100000);
  r.integer("segments", arm.segments, 3, 100000);
  r.integer("cap_rings", arm.cap_rings, 1, 10000);
  r.finish();
}

// The "gesture" object.
void read_gesture(const json& object, const std::string& source, GestureParams& gesture) {
  FieldReader r(object, "gesture", source);
  r.string("name", gesture.name);
  const auto names = gesture_names();
  if (std::find(names.begin(), names.end(), gesture.name) == names.end()) {
    r.fail("gesture.name",
           fmt::format("must be one of elbow, raise, twist, got \"{}\"", excerpt(gesture.name)));
  }
  r.number("max_flexion_deg", gesture.max_flexion_deg, 0, 160, false);
  r.number("speed", gesture.speed, 0, 100);
  r.number("settle_time", gesture.settle_time, 0, 1000, false);
  r.finish();
}

// The "sleeve" object and its "material".
void read_sleeve(const json& object, const std::string& source, SceneConfig& c) {
  FieldReader r(object, "sleeve", source);
  r.integer("rings", c.sleeve.rings, 2, 1 << 20);
  r.integer("segments", c.sleeve.segments, 3, 1 << 20);
  r.number("slack", c.sleeve.slack, 0, 5);
  r.number("start", c.sleeve.start, 0, 10, false);
  r.number("length", c.sleeve.length, 0, 10);
  if (const json* m = r.object("material")) {
    FieldReader mr(*m, "sleeve.material", source);
    mr.number("density", c.material.density, 0, 1000);
    mr.number("stretch_stiffness", c.material.stretch_stiffness, 0, kBig);
    mr.number("shear_stiffness", c.material.shear_stiffness, 0, kBig, false);
    mr.number("bending_stiffness", c.material.bending_stiffness, 0, kBig, false);
    mr.number("stiffness_damping", c.material.stiffness_damping, 0, 10, false);
    mr.number("air_damping", c.material.air_damping, 0, 1000, false);
    mr.number("strain_limit", c.material.strain_limit, 0, 10);
    mr.finish();
  }
  r.finish();
}

// The "contact" object.
void read_contact(const json& object, const std::string& source, ContactParams& contact) {
  FieldReader r(object, "contact", source);
  r.number("thickness", contact.thickness, 0, 1);
  r.number("friction", contact.friction, 0, 10, false);
  r.integer("max_impulse_iterations", contact.max_impulse_iterations, 1, 100000);
  r.integer("max_zone_iterations", contact.max_zone_iterations, 1, 100000);
  r.finish();
}

// Cross-field checks the per-field ranges cannot express, and the memory the scene needs.
void check_scene(const SceneConfig& c, const std::string& source, FieldReader& top) {
  const double arm_length = c.arm.upper_arm_length + c.arm.forearm_length;
  if (c.sleeve.start + c.sleeve.length > arm_length) {
    top.fail("sleeve.length",
             fmt::format("sleeve.start + sleeve.length = {} m exceeds the arm's length {} m",
                         c.sleeve.start + c.sleeve.length, arm_length));
  }
  if (std::abs(c.arm.shoulder_radius - c.arm.elbow_radius) >= c.arm.upper_arm_length) {
    top.fail("arm.elbow_radius",
             "differs from arm.shoulder_radius by more than the upper arm's length");
  }
  if (std::abs(c.arm.elbow_radius - c.arm.wrist_radius) >= c.arm.forearm_length) {
    top.fail("arm.wrist_radius", "differs from arm.elbow_radius by more than the forearm's length");
  }
  if (static_cast<std::int64_t>(c.sleeve.rings) * c.sleeve.segments > (std::int64_t{1} << 28)) {
    top.fail("sleeve.rings", "rings × segments exceeds 2^28 vertices");
  }
  check_memory_budget(sleeve_memory_estimate(c.sleeve) + arm_memory_estimate(c.arm),
                      fmt::format("{}: the scene's sleeve ({} × {} vertices) and arm ({} rings, "
                                  "{} cap rings, {} segments)",
                                  source, c.sleeve.rings, c.sleeve.segments, c.arm.rings,
                                  c.arm.cap_rings, c.arm.segments));
}

}  // namespace

SceneConfig parse_scene_config(const json& root, const std::string& source) {
  SceneConfig c;
  FieldReader top(root, "", source);
  std::string description;
  top.string("description", description);
  if (const json* arm = top.object("arm")) read_arm(*arm, source, c.arm);
  if (const json* g = top.object("gesture")) read_gesture(*g, source, c.gesture);
  if (const json* s = top.object("sleeve")) read_sleeve(*s, source, c);
  if (const json* ct = top.object("contact")) read_contact(*ct, source, c.contact);
  top.number("time_step", c.time_step, 0, 10);
  top.integer("substeps", c.substeps, 1, 100000);
  top.integer("frames", c.frames, 0, 10000000);
  top.vec3("gravity", c.gravity, 1e4);
  top.finish();
  check_scene(c, source, top);
  return c;
}

SceneConfig load_scene_config(const std::filesystem::path& path) {
  const std::string source = path.string();
  const json root = read_json_file(path);
  // Whatever nlohmann::json throws while the fields are read becomes an InputError too.
  return with_json_errors(source, [&] { return parse_scene_config(root, source); });
}

json scene_config_to_json(const SceneConfig& c) {
  json j;
  j["arm"] = {{"upper_arm_length", c.arm.upper_arm_length},
              {"forearm_length", c.arm.forearm_length},
              {"shoulder_radius", c.arm.shoulder_radius},
              {"elbow_radius", c.arm.elbow_radius},
              {"wrist_radius", c.arm.wrist_radius},
              {"elbow_blend", c.arm.elbow_blend},
              {"rings", c.arm.rings},
              {"segments", c.arm.segments},
              {"cap_rings", c.arm.cap_rings}};
  j["gesture"] = {{"name", c.gesture.name},
                  {"max_flexion_deg", c.gesture.max_flexion_deg},
                  {"speed", c.gesture.speed},
                  {"settle_time", c.gesture.settle_time}};
  j["sleeve"] = {{"rings", c.sleeve.rings},
                 {"segments", c.sleeve.segments},
                 {"slack", c.sleeve.slack},
                 {"start", c.sleeve.start},
                 {"length", c.sleeve.length},
                 {"material",
                  {{"density", c.material.density},
                   {"stretch_stiffness", c.material.stretch_stiffness},
                   {"shear_stiffness", c.material.shear_stiffness},
                   {"bending_stiffness", c.material.bending_stiffness},
                   {"stiffness_damping", c.material.stiffness_damping},
                   {"air_damping", c.material.air_damping},
                   {"strain_limit", c.material.strain_limit}}}};
  j["contact"] = {{"thickness", c.contact.thickness},
                  {"friction", c.contact.friction},
                  {"max_impulse_iterations", c.contact.max_impulse_iterations},
                  {"max_zone_iterations", c.contact.max_zone_iterations}};
  j["time_step"] = c.time_step;
  j["substeps"] = c.substeps;
  j["frames"] = c.frames;
  j["gravity"] = {c.gravity.x(), c.gravity.y(), c.gravity.z()};
  return j;
}

Scene::Scene(const SceneConfig& config)
    : m_config(config),
      m_arm(config.arm),
      m_gesture(make_gesture(config.gesture)),
      m_sleeve(make_sleeve(m_arm, config.sleeve)) {}

}  // namespace tailor
