#pragma once
/// @file
/// Output of a simulation run: per-frame OBJ meshes, steps.jsonl and summary.json, each
/// file complete on disk at every moment (written to a temporary name, then renamed;
/// steps.jsonl is appended whole lines and flushed once per frame).

#include <filesystem>
#include <fstream>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "tailor/geometry/types.hpp"
#include "tailor/sim/simulation.hpp"

namespace tailor {

/// Writes a run's files into one folder.
class FrameWriter {
 public:
  /// Creates `directory` (and parents) and starts an empty steps.jsonl. Throws
  /// InputError naming the folder if it cannot be created or written.
  explicit FrameWriter(std::filesystem::path directory);

  /// Writes `cloth_NNNN.obj` and `arm_NNNN.obj` for frame `frame` (0 is the initial state).
  void write_frame(int frame, const Positions& cloth, const FaceArray& cloth_faces,
                   const Positions& arm, const FaceArray& arm_faces);
  /// Writes `contacts_NNNN.json` for frame `frame` (≥ 1) from that frame's substeps (run
  /// with SimulationOptions::record_contacts) and the observers at its end:
  /// `{"frame", "candidate_triangles" (sorted unique faces in a CTP of any substep's first
  /// detection pass), "vertex_face": [[vertex, face, substep, toi]...], "edge_edge":
  /// [[a0, a1, b0, b1, substep, toi]...], "observers": [[x, y, z]...], "substeps"}`.
  void write_contacts(int frame, const std::vector<StepRecord>& records,
                      const std::vector<Vec3>& observers);
  /// Writes `clusters.json`: `{"cluster_of_face": [...]}` (the radial-view cluster of
  /// every cloth face).
  void write_clusters(const std::vector<Index>& cluster_of_face);
  /// Appends one JSON line per record to steps.jsonl and flushes.
  void append_steps(const std::vector<StepRecord>& records);
  /// Writes summary.json (pretty-printed).
  void write_summary(const nlohmann::json& summary);

  /// The output directory given to the constructor.
  const std::filesystem::path& directory() const { return m_directory; }

 private:
  std::filesystem::path m_directory;
  std::ofstream m_steps;
};

/// `cloth_0007.obj`-style name: `prefix`, an underscore, the frame on four digits (more if
/// needed) and `extension`.
std::string frame_file_name(const std::string& prefix, int frame,
                            const std::string& extension = ".obj");

/// The contact-file JSON of one frame (see FrameWriter::write_contacts).
nlohmann::json frame_contacts_json(int frame, const std::vector<StepRecord>& records,
                                   const std::vector<Vec3>& observers);

}  // namespace tailor
