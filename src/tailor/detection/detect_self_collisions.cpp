#include "tailor/detection/detect_self_collisions.hpp"

#include <utility>

namespace tailor {

DetectionResult detect_self_collisions(const TriangleMesh& mesh, const Positions& x0,
                                       const Positions& x1, const DetectionConfig& config,
                                       std::vector<std::vector<Index>> section_loops) {
  SelfCollisionDetector detector(mesh, x0, config, std::move(section_loops));
  return detector.detect(x0, x1);
}

}  // namespace tailor
