/// @file
/// Frame listing (folder or printf pattern) and checked, lazy frame loading.

#include "tailor/io/frame_sequence.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>
#include <system_error>

#include "tailor/geometry/error.hpp"
#include "tailor/io/frame_files.hpp"
#include "tailor/io/mesh_io.hpp"

namespace tailor {
namespace {

/// A printf-style pattern with exactly one integer conversion.
struct FramePattern {
  std::string prefix, suffix;
  bool zero_pad = false;
  int width = 0;

  std::filesystem::path format(long long index) const {
    const std::string digits = width == 0 ? fmt::format("{}", index)
                               : zero_pad ? fmt::format("{:0{}}", index, width)
                                          : fmt::format("{:>{}}", index, width);
    return std::filesystem::path(prefix + digits + suffix);
  }
};

std::optional<FramePattern> parse_pattern(const std::string& text) {
  FramePattern pattern;
  bool found = false;
  std::string* out = &pattern.prefix;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '%') {
      out->push_back(text[i]);
      continue;
    }
    if (i + 1 < text.size() && text[i + 1] == '%') {
      out->push_back('%');
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    bool zero = false;
    if (j < text.size() && text[j] == '0') {
      zero = true;
      ++j;
    }
    int width = 0;
    while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])) && width < 1000) {
      width = 10 * width + (text[j] - '0');
      ++j;
    }
    if (j >= text.size() || (text[j] != 'd' && text[j] != 'i' && text[j] != 'u')) {
      throw InputError(
          fmt::format("frame pattern '{}': unsupported conversion at position {} "
                      "(use %d, %04d, ...; %% for a literal %)",
                      text, i));
    }
    if (found) {
      throw InputError(fmt::format("frame pattern '{}' has more than one %d conversion", text));
    }
    found = true;
    pattern.zero_pad = zero;
    pattern.width = width;
    out = &pattern.suffix;
    i = j;
  }
  if (!found) return std::nullopt;
  return pattern;
}

bool is_obj_file(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".obj";
}

bool is_file(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

std::vector<std::filesystem::path> list_folder(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> paths;
  std::error_code ec;
  for (auto it = std::filesystem::directory_iterator(folder, ec);
       !ec && it != std::filesystem::directory_iterator(); it.increment(ec)) {
    std::error_code type_ec;
    if (!it->is_regular_file(type_ec) || !is_mesh_file_name(it->path())) continue;
    paths.push_back(it->path());
  }
  if (ec) {
    throw InputError(fmt::format("cannot read folder {}: {}", folder.string(), ec.message()));
  }
  if (paths.empty()) {
    throw InputError(fmt::format("no .obj or .ply files in folder {}", folder.string()));
  }
  sort_frame_files(paths);
  return paths;
}

}  // namespace

std::vector<std::filesystem::path> list_frame_files(
    const std::filesystem::path& folder_or_pattern) {
  const std::string text = folder_or_pattern.string();
  if (text.find('%') != std::string::npos) {
    if (const auto pattern = parse_pattern(text)) {
      long long first = 0;
      if (!is_file(pattern->format(0))) {
        if (!is_file(pattern->format(1))) {
          throw InputError(fmt::format("no frame files match '{}' (tried {} and {})", text,
                                       pattern->format(0).string(), pattern->format(1).string()));
        }
        first = 1;
      }
      std::vector<std::filesystem::path> paths;
      for (long long i = first; is_file(pattern->format(i)); ++i) {
        paths.push_back(pattern->format(i));
      }
      return paths;
    }
  }
  std::error_code ec;
  if (std::filesystem::is_directory(folder_or_pattern, ec)) return list_folder(folder_or_pattern);
  if (has_glob_wildcard(text)) return expand_frame_glob(text);
  throw InputError(
      fmt::format("cannot open frames '{}': not a folder, and not a pattern such "
                  "as frames/%d.ply or 'frames/*.ply'",
                  text));
}

FrameSequence::FrameSequence(const std::filesystem::path& folder_or_pattern)
    : FrameSequence(list_frame_files(folder_or_pattern)) {}

FrameSequence::FrameSequence(std::vector<std::filesystem::path> paths) : m_paths(std::move(paths)) {
  if (m_paths.empty()) throw InputError("a frame sequence needs at least one frame file");
  m_first = is_obj_file(m_paths.front()) ? read_first_obj_frame(m_paths.front(), m_obj_face_text)
                                         : read_mesh(m_paths.front());
}

Positions FrameSequence::load(Index i) const {
  if (i < 0 || i >= num_frames()) {
    throw InputError(
        fmt::format("frame {} does not exist (the sequence has {} frames)", i, num_frames()));
  }
  if (i == 0) return m_first.vertices;
  const std::filesystem::path& file = m_paths[static_cast<std::size_t>(i)];
  MeshData frame = m_obj_face_text && is_obj_file(file) ? read_obj_frame(file, *m_obj_face_text)
                                                        : read_mesh(file);
  const std::string first = m_paths.front().string();
  if (frame.vertices.rows() != m_first.vertices.rows()) {
    throw InputError(fmt::format("{}: frame has {} vertices but the first frame {} has {}",
                                 file.string(), frame.vertices.rows(), first,
                                 m_first.vertices.rows()));
  }
  if (frame.faces.rows() != m_first.faces.rows()) {
    throw InputError(fmt::format("{}: frame has {} faces but the first frame {} has {}",
                                 file.string(), frame.faces.rows(), first, m_first.faces.rows()));
  }
  if (frame.faces == m_first.faces) return std::move(frame.vertices);  // the common case
  for (Index f = 0; f < frame.faces.rows(); ++f) {
    if (frame.faces.row(f) != m_first.faces.row(f)) {
      throw InputError(fmt::format(
          "{}: faces differ from the first frame {} (face {} is {} {} {} "
          "here but {} {} {} there)",
          file.string(), first, f, frame.faces(f, 0), frame.faces(f, 1), frame.faces(f, 2),
          m_first.faces(f, 0), m_first.faces(f, 1), m_first.faces(f, 2)));
    }
  }
  return std::move(frame.vertices);
}

}  // namespace tailor
