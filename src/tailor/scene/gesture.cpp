/// @file
/// Keyframed gestures.

#include "tailor/scene/gesture.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tailor/geometry/error.hpp"

namespace tailor {
namespace {

double deg(double d) {
  return d * std::numbers::pi / 180.0;
}

/// Quintic smoothstep: zero first and second derivatives at both ends.
double smootherstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * t * (t * (6 * t - 15) + 10);
}

ArmPose lerp(const ArmPose& a, const ArmPose& b, double s) {
  const auto mix = [s](double x, double y) { return x + s * (y - x); };
  return {mix(a.shoulder_raise, b.shoulder_raise), mix(a.shoulder_swing, b.shoulder_swing),
          mix(a.humeral_rotation, b.humeral_rotation), mix(a.elbow_flexion, b.elbow_flexion),
          mix(a.forearm_twist, b.forearm_twist)};
}

}  // namespace

Gesture::Gesture(std::string name, std::vector<Keyframe> keyframes)
    : m_name(std::move(name)), m_keyframes(std::move(keyframes)) {
  if (m_keyframes.empty()) throw InputError(fmt::format("gesture '{}' has no keyframe", m_name));
  for (std::size_t i = 1; i < m_keyframes.size(); ++i) {
    if (!(m_keyframes[i].time > m_keyframes[i - 1].time)) {
      throw InputError(fmt::format("gesture '{}': keyframe times must increase", m_name));
    }
  }
}

ArmPose Gesture::pose_at(double t) const {
  if (t <= m_keyframes.front().time) return m_keyframes.front().pose;
  if (t >= m_keyframes.back().time) return m_keyframes.back().pose;
  const auto it = std::upper_bound(m_keyframes.begin(), m_keyframes.end(), t,
                                   [](double value, const Keyframe& k) { return value < k.time; });
  const Keyframe& b = *it;
  const Keyframe& a = *(it - 1);
  return lerp(a.pose, b.pose, smootherstep((t - a.time) / (b.time - a.time)));
}

std::vector<std::string> gesture_names() {
  return {"elbow", "raise", "twist"};
}

Gesture make_gesture(const GestureParams& params) {
  if (!(params.speed > 0) || !std::isfinite(params.speed)) {
    throw InputError(fmt::format("gesture speed must be positive, got {}", params.speed));
  }
  if (!(params.settle_time >= 0) || !std::isfinite(params.settle_time)) {
    throw InputError(fmt::format("gesture settle_time must be ≥ 0, got {}", params.settle_time));
  }
  // Times below are for speed 1, after the settle time.
  std::vector<Keyframe> keys;
  const auto key = [&](double t, ArmPose pose) {
    keys.push_back({params.settle_time + t / params.speed, pose});
  };
  ArmPose rest;
  if (params.settle_time > 0) keys.push_back({0.0, rest});
  if (params.name == "elbow") {
    ArmPose bent;
    bent.elbow_flexion = deg(params.max_flexion_deg);
    key(0.0, rest);
    key(1.0, bent);
    key(1.2, bent);
    key(2.2, rest);
  } else if (params.name == "raise") {
    ArmPose up;
    up.shoulder_raise = deg(70);
    up.elbow_flexion = deg(90);
    key(0.0, rest);
    key(1.0, up);
    key(1.2, up);
    key(2.2, rest);
  } else if (params.name == "twist") {
    ArmPose bent, in, out;
    bent.elbow_flexion = deg(95);
    in = bent;
    in.forearm_twist = deg(70);
    in.humeral_rotation = deg(-30);
    out = bent;
    out.forearm_twist = deg(-70);
    out.humeral_rotation = deg(30);
    key(0.0, rest);
    key(0.5, bent);
    key(0.95, in);
    key(1.45, out);
    key(1.9, bent);
    key(2.3, rest);
  } else {
    throw InputError(fmt::format("unknown gesture '{}' (known: {})", params.name,
                                 fmt::join(gesture_names(), ", ")));
  }
  return Gesture(params.name, std::move(keys));
}

}  // namespace tailor
