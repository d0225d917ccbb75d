/// @file
/// Crash-safe output files of a simulation run.

#include "tailor/sim/frame_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <system_error>

#include "tailor/geometry/error.hpp"
#include "tailor/io/file_bytes.hpp"
#include "tailor/io/obj_io.hpp"

namespace tailor {
namespace {

/// Writes through `write(tmp)` then renames over `path`, so readers never see half a file.
template <typename Write>
void write_atomically(const std::filesystem::path& path, Write&& write) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  write(tmp);
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec)
    throw InputError(
        fmt::format("cannot rename '{}' to '{}': {}", tmp.string(), path.string(), ec.message()));
}

}  // namespace

std::string frame_file_name(const std::string& prefix, int frame, const std::string& extension) {
  return fmt::format("{}_{:04d}{}", prefix, frame, extension);
}

nlohmann::json frame_contacts_json(int frame, const std::vector<StepRecord>& records,
                                   const std::vector<Vec3>& observers) {
  std::vector<Index> faces;
  nlohmann::json vertex_face = nlohmann::json::array(), edge_edge = nlohmann::json::array();
  for (const StepRecord& r : records) {
    faces.insert(faces.end(), r.contact.candidate_faces.begin(), r.contact.candidate_faces.end());
    for (const VertexFaceCollision& c : r.contact.first_pass_collisions.vertex_face)
      vertex_face.push_back({c.vertex, c.face, r.substep, c.toi});
    for (const EdgeEdgeCollision& c : r.contact.first_pass_collisions.edge_edge)
      edge_edge.push_back({c.a0, c.a1, c.b0, c.b1, r.substep, c.toi});
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  nlohmann::json observer_list = nlohmann::json::array();
  for (const Vec3& o : observers) observer_list.push_back({o.x(), o.y(), o.z()});
  return {{"frame", frame},
          {"candidate_triangles", faces},
          {"vertex_face", std::move(vertex_face)},
          {"edge_edge", std::move(edge_edge)},
          {"observers", std::move(observer_list)},
          {"substeps", records.size()}};
}

FrameWriter::FrameWriter(std::filesystem::path directory) : m_directory(std::move(directory)) {
  std::error_code ec;
  std::filesystem::create_directories(m_directory, ec);
  if (ec || !std::filesystem::is_directory(m_directory)) {
    throw InputError(fmt::format("cannot create output folder '{}'{}", m_directory.string(),
                                 ec ? ": " + ec.message() : std::string()));
  }
  // A stale summary from an earlier run would describe the wrong frames.
  std::filesystem::remove(m_directory / "summary.json", ec);
  m_steps.open(m_directory / "steps.jsonl", std::ios::out | std::ios::trunc);
  if (!m_steps)
    throw InputError(fmt::format("cannot write '{}'", (m_directory / "steps.jsonl").string()));
}

void FrameWriter::write_frame(int frame, const Positions& cloth, const FaceArray& cloth_faces,
                              const Positions& arm, const FaceArray& arm_faces) {
  write_atomically(m_directory / frame_file_name("cloth", frame),
                   [&](const std::filesystem::path& p) { write_obj(p, cloth, cloth_faces); });
  write_atomically(m_directory / frame_file_name("arm", frame),
                   [&](const std::filesystem::path& p) { write_obj(p, arm, arm_faces); });
}

void FrameWriter::write_contacts(int frame, const std::vector<StepRecord>& records,
                                 const std::vector<Vec3>& observers) {
  const std::string text = frame_contacts_json(frame, records, observers).dump() + "\n";
  write_file_atomically(m_directory / frame_file_name("contacts", frame, ".json"), text);
}

void FrameWriter::write_clusters(const std::vector<Index>& cluster_of_face) {
  const nlohmann::json j = {{"cluster_of_face", cluster_of_face}};
  write_file_atomically(m_directory / "clusters.json", j.dump() + "\n");
}

void FrameWriter::append_steps(const std::vector<StepRecord>& records) {
  std::string text;
  for (const StepRecord& r : records) {
    text += nlohmann::json(r).dump();
    text += '\n';
  }
  m_steps << text;
  m_steps.flush();
  if (!m_steps)
    throw InputError(fmt::format("cannot write '{}'", (m_directory / "steps.jsonl").string()));
}

void FrameWriter::write_summary(const nlohmann::json& summary) {
  write_atomically(m_directory / "summary.json", [&](const std::filesystem::path& p) {
    write_file_bytes(p, summary.dump(2) + "\n");
  });
}

}  // namespace tailor
