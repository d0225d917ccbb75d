#pragma once
/// @file
/// Arm gestures as keyframed joint angles with smooth (C2) interpolation.

#include <string>
#include <vector>

#include "tailor/scene/arm.hpp"

namespace tailor {

/// One keyframe: the pose reached at `time` (s).
struct Keyframe {
  /// Time at which the pose is reached (s).
  double time = 0;
  /// Joint angles at that time.
  ArmPose pose;
};

/// What to play and how fast.
struct GestureParams {
  std::string name = "elbow";    ///< `elbow`, `raise` or `twist` (see gesture_names())
  double max_flexion_deg = 130;  ///< elbow flexion at the peak of the `elbow` gesture
  double speed = 1.0;            ///< time scale (2: twice as fast)
  double settle_time = 0.3;      ///< rest pose held first, so the sleeve settles (s)
};

/// Keyframed joint angles; the pose between two keyframes follows a quintic smoothstep,
/// so joint velocities and accelerations are zero at every keyframe and continuous.
class Gesture {
 public:
  /// Keyframes must have increasing times; throws InputError otherwise or if empty.
  Gesture(std::string name, std::vector<Keyframe> keyframes);

  /// The gesture's name.
  const std::string& name() const { return m_name; }
  /// Keyframes in time order.
  const std::vector<Keyframe>& keyframes() const { return m_keyframes; }
  /// Time of the last keyframe (s); the pose is held after it.
  double duration() const { return m_keyframes.back().time; }
  /// Interpolated pose at time `t` (s), clamped to the first and last keyframe.
  ArmPose pose_at(double t) const;

 private:
  std::string m_name;
  std::vector<Keyframe> m_keyframes;
};

/// Builds a named gesture: `elbow` (straight, flexion to max_flexion_deg, back),
/// `raise` (shoulder raise by 70° with the elbow bending 90°, back), `twist` (elbow bent
/// 95°, forearm twist ±70° with humeral rotation, back). Throws InputError naming the
/// gesture and the valid names if unknown, or on a non-positive speed.
Gesture make_gesture(const GestureParams& params);

/// Names make_gesture() accepts.
std::vector<std::string> gesture_names();

}  // namespace tailor
