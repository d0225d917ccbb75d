/// @file
/// Reading the per-frame contact files written by `tailor simulate`.

#include "view/frame_contacts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "tailor/geometry/error.hpp"
#include "view/json_input.hpp"

namespace tailor::cli {
namespace {

// Substeps per frame above this are certainly a corrupted file, not a simulation.
constexpr std::int64_t kMaxSubsteps = 1 << 20;

std::string item(const char* list, std::size_t i) {
  return fmt::format("{}[{}]", list, i);
}
std::string item(const char* list, std::size_t i, std::size_t j) {
  return fmt::format("{}[{}][{}]", list, i, j);
}

}  // namespace

FrameContacts read_frame_contacts(const std::filesystem::path& path, int frame, Index num_vertices,
                                  Index num_faces) {
  const nlohmann::json root = read_json_file(path);
  const auto& p = path;
  FrameContacts contacts;
  const std::int64_t found_frame =
      json_integer(json_field(root, "frame", p), p, "frame", 0, std::numeric_limits<int>::max());
  if (found_frame != frame) {
    throw InputError(fmt::format("{}: frame: {} does not match the file name (frame {})",
                                 p.string(), found_frame, frame));
  }
  contacts.substeps = static_cast<int>(
      json_integer(json_field(root, "substeps", p), p, "substeps", 1, kMaxSubsteps));
  const Index last_vertex = num_vertices - 1, last_face = num_faces - 1;
  const int last_substep = contacts.substeps - 1;

  const auto& faces =
      json_array(json_field(root, "candidate_triangles", p), p, "candidate_triangles");
  contacts.candidate_triangles.reserve(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const auto face =
        static_cast<Index>(json_integer(faces[i], p, item("candidate_triangles", i), 0, last_face));
    if (!contacts.candidate_triangles.empty() && face <= contacts.candidate_triangles.back()) {
      fail_json(p, item("candidate_triangles", i), "ids must be sorted and unique");
    }
    contacts.candidate_triangles.push_back(face);
  }

  const auto& vf = json_array(json_field(root, "vertex_face", p), p, "vertex_face");
  for (std::size_t i = 0; i < vf.size(); ++i) {
    const auto& c = json_array(vf[i], p, item("vertex_face", i), 4);
    contacts.vertex_face.push_back(
        {static_cast<Index>(json_integer(c[0], p, item("vertex_face", i, 0), 0, last_vertex)),
         static_cast<Index>(json_integer(c[1], p, item("vertex_face", i, 1), 0, last_face)),
         static_cast<int>(json_integer(c[2], p, item("vertex_face", i, 2), 0, last_substep)),
         json_number(c[3], p, item("vertex_face", i, 3), 0.0, 1.0)});
  }

  const auto& ee = json_array(json_field(root, "edge_edge", p), p, "edge_edge");
  for (std::size_t i = 0; i < ee.size(); ++i) {
    const auto& c = json_array(ee[i], p, item("edge_edge", i), 6);
    Index ids[4];
    for (std::size_t j = 0; j < 4; ++j) {
      ids[j] = static_cast<Index>(json_integer(c[j], p, item("edge_edge", i, j), 0, last_vertex));
    }
    if (ids[0] >= ids[1] || ids[2] >= ids[3]) {
      fail_json(p, item("edge_edge", i), "edges must be given as a0 < a1, b0 < b1");
    }
    contacts.edge_edge.push_back(
        {ids[0], ids[1], ids[2], ids[3],
         static_cast<int>(json_integer(c[4], p, item("edge_edge", i, 4), 0, last_substep)),
         json_number(c[5], p, item("edge_edge", i, 5), 0.0, 1.0)});
  }

  const auto& observers = json_array(json_field(root, "observers", p), p, "observers");
  constexpr double kLargest = std::numeric_limits<float>::max();  // shown as float32
  for (std::size_t i = 0; i < observers.size(); ++i) {
    const auto& o = json_array(observers[i], p, item("observers", i), 3);
    Vec3 position;
    for (std::size_t j = 0; j < 3; ++j) {
      position[static_cast<Index>(j)] =
          json_number(o[j], p, item("observers", i, j), -kLargest, kLargest);
    }
    contacts.observers.push_back(position);
  }
  return contacts;
}

std::vector<Index> read_face_clusters(const std::filesystem::path& path, Index num_faces) {
  const nlohmann::json root = read_json_file(path);
  const auto& list =
      json_array(json_field(root, "cluster_of_face", path), path, "cluster_of_face", num_faces);
  std::vector<Index> clusters;
  clusters.reserve(list.size());
  for (std::size_t i = 0; i < list.size(); ++i) {
    clusters.push_back(static_cast<Index>(json_integer(list[i], path, item("cluster_of_face", i), 0,
                                                       std::numeric_limits<Index>::max())));
  }
  return clusters;
}

std::vector<Index> unique_faces_of_pairs(const std::vector<TrianglePair>& pairs) {
  std::vector<Index> faces;
  faces.reserve(2 * pairs.size());
  for (const TrianglePair& pair : pairs) {
    faces.push_back(pair.first);
    faces.push_back(pair.second);
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

}  // namespace tailor::cli
