/// @file
/// Crash-safe output files of a simulation run.

#include "tailor/sim/frame_writer.hpp"

#include <fmt/format.h>

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

std::string frame_file_name(const std::string& prefix, int frame) {
  return fmt::format("{}_{:04d}.obj", prefix, frame);
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
