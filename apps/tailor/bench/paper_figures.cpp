#include "bench/paper_figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "tailor/io/file_bytes.hpp"
#include "tailor/render/frame_renderer.hpp"
#include "tailor/render/image.hpp"

namespace tailor {
namespace {

/// The four panels of Fig. 1, in the paper's order.
const std::vector<std::pair<std::string, std::string>>& panels() {
  static const std::vector<std::pair<std::string, std::string>> list{
      {"basic", "basic BVH"},
      {"normal_cones", "+ normal cones"},
      {"radial_view", "+ radial view"},
      {"paper", "+ isolated set"}};
  return list;
}

}  // namespace

int peak_flexion_frame(const SceneConfig& scene) {
  const Gesture gesture = make_gesture(scene.gesture);
  int best = 1;
  double best_flexion = -std::numeric_limits<double>::infinity();
  for (int f = 1; f <= scene.frames; ++f) {
    const double flexion = gesture.pose_at(f * scene.time_step).elbow_flexion;
    if (flexion > best_flexion + 1e-12) {
      best_flexion = flexion;
      best = f;
    }
  }
  return best;
}

void PaperFigures::observe(const std::string& run, const Simulation& simulation,
                           const std::vector<StepRecord>& records) {
  if (simulation.frame() != m_frame) return;
  Shot& shot = m_shots[run];
  shot.cloth = simulation.cloth_positions();
  shot.arm = simulation.arm_positions();
  shot.cloth_faces = simulation.cloth_mesh().faces();
  shot.arm_faces = simulation.arm_mesh().faces();
  shot.candidate_faces.clear();
  for (const StepRecord& r : records) {
    shot.candidate_faces.insert(shot.candidate_faces.end(), r.contact.candidate_faces.begin(),
                                r.contact.candidate_faces.end());
  }
  std::sort(shot.candidate_faces.begin(), shot.candidate_faces.end());
  shot.candidate_faces.erase(std::unique(shot.candidate_faces.begin(), shot.candidate_faces.end()),
                             shot.candidate_faces.end());
}

void PaperFigures::write(const std::filesystem::path& dir) const {
  std::filesystem::create_directories(dir);
  RenderSettings settings;
  std::vector<Image> pictures;
  std::string md = fmt::format(
      "Fig. 1 as pictures: frame {} (peak elbow flexion); cloth triangles in a candidate "
      "triangle pair of that frame in red.\n\n| panel | file | red triangles |\n|---|---|---:|\n",
      m_frame);
  for (const auto& [run, label] : panels()) {
    const auto it = m_shots.find(run);
    if (it == m_shots.end()) continue;
    const Shot& shot = it->second;
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const Positions* x : {&shot.cloth, &shot.arm}) {
      for (Eigen::Index i = 0; i < x->rows(); ++i) {
        lo = lo.cwiseMin(x->row(i).transpose());
        hi = hi.cwiseMax(x->row(i).transpose());
      }
    }
    FrameView view;
    view.cloth = &shot.cloth;
    view.cloth_faces = &shot.cloth_faces;
    view.arm = &shot.arm;
    view.arm_faces = &shot.arm_faces;
    view.highlighted_faces = shot.candidate_faces;
    Image picture = render_frame(view, frame_camera(lo, hi, settings), settings);
    draw_number(picture, static_cast<int>(pictures.size()) + 1, 6, 6, 3, {40, 40, 40});
    const std::string file = fmt::format("fig1_{}.png", run);
    write_png(dir / file, picture);
    md += fmt::format("| {}. {} | {} | {} |\n", pictures.size() + 1, label, file,
                      shot.candidate_faces.size());
    pictures.push_back(std::move(picture));
  }
  if (pictures.empty()) return;
  Image sheet(static_cast<int>(pictures.size()) * (settings.width / 2), settings.height / 2,
              {255, 255, 255});
  for (std::size_t i = 0; i < pictures.size(); ++i)
    sheet.blit(pictures[i].downsampled(2), static_cast<int>(i) * (settings.width / 2), 0);
  write_png(dir / "fig1.png", sheet);
  md += "\nfig1.png: the four panels left to right.\n";
  write_file_atomically(dir / "fig1_images.md", md);
}

}  // namespace tailor
