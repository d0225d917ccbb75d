/// @file
/// A small, fast OBJ reader (std::from_chars) and writer (fmt).

#include "tailor/io/obj_io.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "tailor/geometry/error.hpp"
#include "tailor/io/excerpt.hpp"
#include "tailor/io/file_bytes.hpp"
#include "tailor/io/input_file.hpp"
#include "tailor/io/memory_budget.hpp"
#include "tailor/io/text_scan.hpp"

namespace tailor {
namespace {

using namespace text_scan;

/// Longest OBJ line (a face line of about six million vertices); longer is refused
/// rather than scanned.
constexpr std::size_t kMaxObjLineBytes = std::size_t{64} << 20;
/// Bytes looked at for a line's keyword before the line's end is searched.
constexpr std::size_t kKeywordScan = 64;

/// OBJ statements that carry nothing this reader needs.
bool is_ignored_statement(std::string_view keyword) {
  static constexpr std::array<std::string_view, 34> kIgnored = {
      "vn",     "vt",         "vp",        "g",      "o",     "s",        "usemtl",
      "mtllib", "l",          "p",         "cstype", "deg",   "bmat",     "step",
      "curv",   "curv2",      "surf",      "parm",   "trim",  "hole",     "scrv",
      "sp",     "end",        "con",       "mg",     "bevel", "c_interp", "d_interp",
      "lod",    "shadow_obj", "trace_obj", "ctech",  "stech", "maplib"};
  return std::find(kIgnored.begin(), kIgnored.end(), keyword) != kIgnored.end();
}

/// Line-aware parser state; every error names the file and line.
class ObjParser {
 public:
  ObjParser(const std::filesystem::path& path, std::string_view text)
      : m_path(path), m_text(text) {}

  MeshData parse() {
    std::size_t pos = 0;
    while (pos < m_text.size()) {
      ++m_line;
      // Reject an unknown statement before looking for the end of its line, so that a
      // binary or garbage file fails at its first bytes, not after a scan of all of them.
      check_keyword(m_text.substr(pos, kKeywordScan), pos + kKeywordScan >= m_text.size());
      const std::size_t scan = std::min(m_text.size() - pos, kMaxObjLineBytes + 1);
      const char* nl = static_cast<const char*>(std::memchr(m_text.data() + pos, '\n', scan));
      if (nl == nullptr && scan > kMaxObjLineBytes) {
        fail(fmt::format("line longer than {} (not an OBJ file?)", format_bytes(kMaxObjLineBytes)));
      }
      const std::size_t end = nl ? static_cast<std::size_t>(nl - m_text.data()) : m_text.size();
      parse_line(m_text.substr(pos, end - pos));
      pos = end + 1;
    }
    if (m_face_ids.empty()) {
      throw InputError(
          fmt::format("{}: no faces ({} vertices and no 'f' line; a mesh needs at "
                      "least one triangle)",
                      m_path.string(), num_vertices()));
    }
    if (m_max_forward_index >= 0 && m_max_forward_index >= num_vertices()) {
      fail(m_max_forward_line, fmt::format("face vertex index {} is out of range (the file has {} "
                                           "vertices)",
                                           m_max_forward_index + 1, num_vertices()));
    }
    if (m_num_polygons > 0) {
      spdlog::warn("{}: {} polygons with more than 3 vertices were split into triangle fans",
                   m_path.string(), m_num_polygons);
    }
    MeshData mesh;
    mesh.vertices.resize(num_vertices(), 3);
    std::copy(m_coords.begin(), m_coords.end(), mesh.vertices.data());
    mesh.faces.resize(static_cast<Index>(m_face_ids.size() / 3), 3);
    std::copy(m_face_ids.begin(), m_face_ids.end(), mesh.faces.data());
    return mesh;
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& problem) const {
    throw InputError(fmt::format("{}: line {}: {}", m_path.string(), line, problem));
  }
  [[noreturn]] void fail(const std::string& problem) const { fail(m_line, problem); }

  Index num_vertices() const { return static_cast<Index>(m_coords.size() / 3); }

  /// Fails on an unknown statement keyword at the start of `head` (the first bytes of a
  /// line; `to_file_end` when they are all the file has left). A keyword that does not
  /// end within `head` is unknown too (every known keyword is shorter).
  void check_keyword(std::string_view head, bool to_file_end) const {
    skip_blanks(head);
    std::size_t n = 0;
    while (n < head.size() && !is_blank(head[n]) && head[n] != '\n' && head[n] != '#') ++n;
    if (n == 0 || (n == head.size() && to_file_end)) return;  // parse_line decides
    if (n < head.size() && is_known_keyword(head.substr(0, n))) return;
    if (n == head.size()) {  // it goes on: show its start only
      fail(
          fmt::format("unknown statement '{}...' (not an OBJ file?)", excerpt(head.substr(0, 10))));
    }
    fail(fmt::format("unknown statement '{}'", excerpt(head.substr(0, n))));
  }

  static bool is_known_keyword(std::string_view keyword) {
    return keyword == "v" || keyword == "f" || is_ignored_statement(keyword);
  }

  /// Refuses to grow the arrays beyond the memory budget. Checked before a reallocation:
  /// the peak is then about 3 times the data (old and doubled buffers; later the vectors
  /// and the returned mesh together).
  void check_growth() const {
    if (m_coords.size() < m_coords.capacity() && m_face_ids.size() < m_face_ids.capacity()) {
      return;
    }
    const double bytes = 3.0 * (static_cast<double>(m_coords.size()) * sizeof(double) +
                                static_cast<double>(m_face_ids.size()) * sizeof(Index));
    check_memory_budget(bytes,
                        fmt::format("{}: line {}: reading the mesh", m_path.string(), m_line));
  }

  void parse_line(std::string_view line) {
    if (const auto hash = line.find('#'); hash != std::string_view::npos) {
      line = line.substr(0, hash);
    }
    const std::string_view keyword = next_token(line);
    if (keyword.empty()) return;
    if (keyword == "v") {
      parse_vertex(line);
    } else if (keyword == "f") {
      parse_face(line);
    } else if (!is_ignored_statement(keyword)) {
      fail(fmt::format("unknown statement '{}'", excerpt(keyword)));
    }
  }

  void parse_vertex(std::string_view rest) {
    if (num_vertices() == std::numeric_limits<Index>::max()) fail("too many vertices");
    check_growth();
    for (int axis = 0; axis < 3; ++axis) {
      const std::string_view token = next_token(rest);
      if (token.empty()) fail("vertex has fewer than 3 coordinates");
      double value = 0.0;
      if (!parse_double(token, value)) {
        fail(fmt::format("garbage token '{}' where a vertex coordinate was expected",
                         excerpt(token)));
      }
      if (!std::isfinite(value)) fail(fmt::format("non-finite coordinate '{}'", excerpt(token)));
      m_coords.push_back(value);
    }
    // Optional w or per-vertex colours: must still be numbers.
    for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
      double value = 0.0;
      if (!parse_double(token, value)) {
        fail(fmt::format("garbage token '{}' in a vertex", excerpt(token)));
      }
    }
  }

  /// Parses `i`, `i/j`, `i//k` or `i/j/k` and returns the 0-based vertex id.
  Index parse_face_vertex(std::string_view token) {
    const std::size_t slash = token.find('/');
    const std::string_view vertex_part = token.substr(0, slash);
    std::int64_t index = 0;
    if (!parse_int(vertex_part, index)) {
      fail(
          fmt::format("garbage token '{}' where a face vertex index was expected", excerpt(token)));
    }
    if (slash != std::string_view::npos) {
      // Texture and normal indices are ignored but must be well formed.
      std::string_view rest = token.substr(slash + 1);
      const std::size_t slash2 = rest.find('/');
      const std::string_view texture = rest.substr(0, slash2);
      std::int64_t ignored = 0;
      if (!texture.empty() && !parse_int(texture, ignored)) {
        fail(fmt::format("garbage token '{}' in a face", excerpt(token)));
      }
      if (slash2 != std::string_view::npos) {
        const std::string_view normal = rest.substr(slash2 + 1);
        if (!parse_int(normal, ignored)) {
          fail(fmt::format("garbage token '{}' in a face", excerpt(token)));
        }
      } else if (texture.empty()) {
        fail(fmt::format("garbage token '{}' in a face", excerpt(token)));
      }
    }
    if (index == 0) fail("face vertex index 0 is invalid (OBJ indices start at 1)");
    if (index < 0) {
      const std::int64_t resolved = num_vertices() + index;
      if (resolved < 0) {
        fail(
            fmt::format("relative face vertex index {} refers before the first vertex "
                        "({} vertices so far)",
                        index, num_vertices()));
      }
      return static_cast<Index>(resolved);
    }
    if (index > std::numeric_limits<Index>::max()) {
      fail(fmt::format("face vertex index {} is out of range", index));
    }
    const Index resolved = static_cast<Index>(index - 1);
    // Forward references are legal in OBJ; check them once all vertices are known.
    if (resolved >= num_vertices() && resolved > m_max_forward_index) {
      m_max_forward_index = resolved;
      m_max_forward_line = m_line;
    }
    return resolved;
  }

  void parse_face(std::string_view rest) {
    m_polygon.clear();
    for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
      m_polygon.push_back(parse_face_vertex(token));
    }
    if (m_polygon.size() < 3) {
      fail(fmt::format("face with {} vertices (a face needs at least 3)", m_polygon.size()));
    }
    if (m_polygon.size() <= 16) {
      for (std::size_t i = 0; i < m_polygon.size(); ++i) {
        for (std::size_t j = i + 1; j < m_polygon.size(); ++j) {
          if (m_polygon[i] == m_polygon[j]) {
            fail(fmt::format("face repeats vertex {}", m_polygon[i] + 1));
          }
        }
      }
    } else {  // huge polygons: sort a copy instead of comparing all pairs
      std::vector<Index> sorted = m_polygon;
      std::sort(sorted.begin(), sorted.end());
      const auto dup = std::adjacent_find(sorted.begin(), sorted.end());
      if (dup != sorted.end()) fail(fmt::format("face repeats vertex {}", *dup + 1));
    }
    if (m_polygon.size() > 3) ++m_num_polygons;
    if (m_face_ids.size() / 3 + (m_polygon.size() - 2) >
        static_cast<std::size_t>(std::numeric_limits<Index>::max())) {
      fail("too many faces");
    }
    check_growth();
    for (std::size_t i = 1; i + 1 < m_polygon.size(); ++i) {
      m_face_ids.push_back(m_polygon[0]);
      m_face_ids.push_back(m_polygon[i]);
      m_face_ids.push_back(m_polygon[i + 1]);
    }
  }

  const std::filesystem::path& m_path;
  std::string_view m_text;
  std::size_t m_line = 0;
  std::vector<double> m_coords;
  std::vector<Index> m_face_ids;
  std::vector<Index> m_polygon;
  std::size_t m_num_polygons = 0;
  Index m_max_forward_index = -1;
  std::size_t m_max_forward_line = 0;
};

}  // namespace

MeshData parse_obj(std::string_view text, const std::filesystem::path& source) {
  return ObjParser(source, text).parse();
}

MeshData read_obj(const std::filesystem::path& path) {
  const InputFile file(path);
  return parse_obj(file.bytes(), path);
}

void write_obj(const std::filesystem::path& path, const Positions& vertices,
               const FaceArray& faces) {
  const Index nv = static_cast<Index>(vertices.rows());
  fmt::memory_buffer out;
  out.reserve(static_cast<std::size_t>(nv) * 60 + static_cast<std::size_t>(faces.rows()) * 24);
  for (Index v = 0; v < nv; ++v) {
    const double x = vertices(v, 0), y = vertices(v, 1), z = vertices(v, 2);
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) {
      throw InputError(
          fmt::format("cannot write {}: vertex {} has a non-finite coordinate", path.string(), v));
    }
    fmt::format_to(std::back_inserter(out), "v {:.17g} {:.17g} {:.17g}\n", x, y, z);
  }
  for (Index f = 0; f < faces.rows(); ++f) {
    for (int i = 0; i < 3; ++i) {
      if (faces(f, i) < 0 || faces(f, i) >= nv) {
        throw InputError(
            fmt::format("cannot write {}: face {} has vertex index {} out of range ({} vertices)",
                        path.string(), f, faces(f, i), nv));
      }
    }
    fmt::format_to(std::back_inserter(out), "f {} {} {}\n", faces(f, 0) + 1, faces(f, 1) + 1,
                   faces(f, 2) + 1);
  }
  write_file_bytes(path, std::string_view(out.data(), out.size()));
}

}  // namespace tailor
