/// @file
/// Opening simulation outputs and detected steps for the viewer.

#include "view/view_input.hpp"

#include <fmt/format.h>

#include <memory>

#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/io/frame_sequence.hpp"
#include "tailor/mesh/triangle_mesh.hpp"
#include "tailor/sim/frame_writer.hpp"
#include "view/json_input.hpp"
#include "view/step_stats.hpp"

namespace tailor::cli {
namespace {

namespace fs = std::filesystem;

std::string contacts_file_name(int frame) {
  return fmt::format("contacts_{:04d}.json", frame);
}

// Collisions of `tailor detect --json` ({"collisions": {"vertex_face": [[v, f, toi]...],
// "edge_edge": [[a0, a1, b0, b1, toi]...]}}) as the contacts of a one-substep frame.
FrameContacts read_detected_collisions(const nlohmann::json& root, const fs::path& p,
                                       Index num_vertices, Index num_faces) {
  const auto& collisions = json_field(root, "collisions", p);
  FrameContacts contacts;
  const auto& vf = json_array(json_field(collisions, "vertex_face", p), p, "vertex_face");
  for (std::size_t i = 0; i < vf.size(); ++i) {
    const auto& c = json_array(vf[i], p, fmt::format("vertex_face[{}]", i), 3);
    const auto at = [&](std::size_t j) { return fmt::format("vertex_face[{}][{}]", i, j); };
    contacts.vertex_face.push_back(
        {static_cast<Index>(json_integer(c[0], p, at(0), 0, num_vertices - 1)),
         static_cast<Index>(json_integer(c[1], p, at(1), 0, num_faces - 1)), 0,
         json_number(c[2], p, at(2), 0.0, 1.0)});
  }
  const auto& ee = json_array(json_field(collisions, "edge_edge", p), p, "edge_edge");
  for (std::size_t i = 0; i < ee.size(); ++i) {
    const auto& c = json_array(ee[i], p, fmt::format("edge_edge[{}]", i), 5);
    const auto at = [&](std::size_t j) { return fmt::format("edge_edge[{}][{}]", i, j); };
    Index ids[4];
    for (std::size_t j = 0; j < 4; ++j) {
      ids[j] = static_cast<Index>(json_integer(c[j], p, at(j), 0, num_vertices - 1));
    }
    if (ids[0] >= ids[1] || ids[2] >= ids[3]) {
      fail_json(p, fmt::format("edge_edge[{}]", i), "edges must be given as a0 < a1, b0 < b1");
    }
    contacts.edge_edge.push_back(
        {ids[0], ids[1], ids[2], ids[3], 0, json_number(c[4], p, at(4), 0.0, 1.0)});
  }
  return contacts;
}

}  // namespace

ViewInput open_simulation_output(const fs::path& dir) {
  if (!fs::is_directory(dir)) throw InputError(fmt::format("{}: not a folder", dir.string()));
  if (!fs::exists(dir / frame_file_name("cloth", 0))) {
    throw InputError(
        fmt::format("{}: not a `tailor simulate` output folder (no {}; for one detected step use "
                    "`tailor view --detect FILE.json T0 T1`)",
                    dir.string(), frame_file_name("cloth", 0)));
  }
  auto cloth = std::make_shared<FrameSequence>(list_frame_files(dir / "cloth_%04d.obj"));
  const int num_frames = static_cast<int>(cloth->num_frames());

  std::shared_ptr<FrameSequence> arm;
  if (fs::exists(dir / frame_file_name("arm", 0))) {
    std::vector<fs::path> arm_paths;
    for (int k = 0; k < num_frames; ++k) {
      const fs::path path = dir / frame_file_name("arm", k);
      if (!fs::exists(path)) {
        throw InputError(fmt::format("{}: missing (the run has {} but no arm for that frame)",
                                     path.string(), cloth->path(k).filename().string()));
      }
      arm_paths.push_back(path);
    }
    arm = std::make_shared<FrameSequence>(std::move(arm_paths));
  }

  ViewInput input;
  input.kind = "simulation";
  input.title = dir.string();
  input.num_frames = num_frames;
  input.cloth_vertices = cloth->num_vertices();
  input.cloth_faces = cloth->faces();
  if (arm) {
    input.arm_vertices = arm->num_vertices();
    input.arm_faces = arm->faces();
  }
  const Index num_faces = static_cast<Index>(input.cloth_faces.rows());
  if (fs::exists(dir / "clusters.json")) {
    input.cluster_of_face = read_face_clusters(dir / "clusters.json", num_faces);
  }
  if (fs::exists(dir / "steps.jsonl")) {
    input.stats = read_frame_stats(dir / "steps.jsonl", num_frames);
  }
  input.load_frame = [dir, cloth, arm, num_vertices = input.cloth_vertices, num_faces](int k) {
    ViewFrame frame;
    frame.cloth = k == 0 ? cloth->first_frame().vertices : cloth->load(k);
    if (arm) frame.arm = k == 0 ? arm->first_frame().vertices : arm->load(k);
    const fs::path contacts = dir / contacts_file_name(k);
    if (k > 0 && fs::exists(contacts)) {
      frame.contacts = read_frame_contacts(contacts, k, num_vertices, num_faces);
    }
    return frame;
  };
  return input;
}

ViewInput open_detection_output(const fs::path& json, const fs::path& t0, const fs::path& t1,
                                std::optional<DetectionConfig> candidates) {
  const nlohmann::json root = read_json_file(json);
  auto meshes = std::make_shared<FrameSequence>(std::vector<fs::path>{t0, t1});
  auto x1 = std::make_shared<Positions>(meshes->load(1));  // checks the topology

  ViewInput input;
  input.kind = "detection";
  input.title = json.string();
  input.num_frames = 2;
  input.cloth_vertices = meshes->num_vertices();
  input.cloth_faces = meshes->faces();
  const Index num_faces = static_cast<Index>(input.cloth_faces.rows());
  auto contacts = std::make_shared<FrameContacts>(
      read_detected_collisions(root, json, input.cloth_vertices, num_faces));
  const auto stats = root.find("stats");
  input.stats = single_step_stats(stats == root.end() ? nlohmann::json() : *stats);

  if (candidates) {
    candidates->keep_candidate_pairs = true;
    const TriangleMesh mesh(input.cloth_vertices, input.cloth_faces);
    SelfCollisionDetector detector(mesh, meshes->first_frame().vertices, *candidates);
    const DetectionResult result = detector.detect(meshes->first_frame().vertices, *x1);
    contacts->candidate_triangles = unique_faces_of_pairs(result.candidate_triangle_pairs);
  }
  input.load_frame = [meshes, x1, contacts](int k) {
    ViewFrame frame;
    frame.cloth = k == 0 ? meshes->first_frame().vertices : *x1;
    if (k == 1) frame.contacts = *contacts;
    return frame;
  };
  return input;
}

}  // namespace tailor::cli
