#pragma once
/// @file
/// `tailor bench paper`: the paper's Fig. 1 as pictures. The same frame (peak elbow
/// flexion) of the runs basic BVH, + normal cones, + radial view and + isolated set, with
/// the cloth triangles of that frame's candidate triangle pairs in red.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "tailor/scene/scene.hpp"
#include "tailor/sim/simulation.hpp"

namespace tailor {

/// The frame (≥ 1) at which the gesture's elbow is most flexed (the first such frame).
int peak_flexion_frame(const SceneConfig& scene);

/// Collects one frame of several runs and draws it.
class PaperFigures {
 public:
  /// Draws frame `frame` of each run.
  explicit PaperFigures(int frame) : m_frame(frame) {}
  /// Call after every frame of run `run` (run with SimulationOptions::record_contacts):
  /// keeps the positions and candidate faces when it is the frame drawn.
  void observe(const std::string& run, const Simulation& simulation,
               const std::vector<StepRecord>& records);
  /// Writes fig1_<run>.png for the runs basic, normal_cones, radial_view and paper (the
  /// isolated set), fig1.png (the four side by side, in that order) and fig1_images.md.
  void write(const std::filesystem::path& dir) const;

 private:
  struct Shot {
    Positions cloth, arm;
    FaceArray cloth_faces, arm_faces;
    std::vector<Index> candidate_faces;
  };
  int m_frame;
  std::map<std::string, Shot> m_shots;
};

}  // namespace tailor
