/// @file
/// The OBJ parser: common `v` and `f` lines in one pass (std::from_chars on the mapped
/// text), every other line, and every error, on the general line-by-line path.

#include "tailor/io/obj_parser.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "tailor/geometry/error.hpp"
#include "tailor/io/excerpt.hpp"
#include "tailor/io/memory_budget.hpp"
#include "tailor/io/obj_frames.hpp"
#include "tailor/io/text_scan.hpp"

namespace tailor {
namespace {

using namespace text_scan;

/// Longest OBJ line (a face line of about six million vertices); longer is refused
/// rather than scanned.
constexpr std::size_t kMaxObjLineBytes = std::size_t{64} << 20;
/// Bytes looked at for a line's keyword before the line's end is searched.
constexpr std::size_t kKeywordScan = 64;
/// What ObjParser::parse_plain_line() returns for a line it leaves to the general path.
constexpr std::size_t kNotPlain = std::string_view::npos;
/// Most vertices of a face parse_plain_line() reads (larger ones take the general path).
constexpr std::size_t kMaxPlainPolygon = 64;

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
  ObjParser(const std::filesystem::path& path, std::string_view text, const ObjFaceText* known)
      : m_path(path), m_text(text), m_known(known) {
    if (known) m_coords.reserve(3 * static_cast<std::size_t>(known->num_vertices));
  }

  ObjParseResult parse() {
    std::size_t pos = 0;
    while (pos < m_text.size()) {
      if (m_known && try_known_face_text(pos)) {
        pos = m_text.size();
        break;
      }
      ++m_line;
      const Index vertices_before = num_vertices();
      pos = parse_next_line(pos);
      if (num_vertices() != vertices_before) {  // a `v` line: the face text starts after it
        m_face_text_start = std::min(pos, m_text.size());
        m_faces_before_face_text = m_face_ids.size();
      }
    }
    if (m_face_ids.empty() && !m_known_faces) {
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
    ObjParseResult result;
    result.mesh.vertices.resize(num_vertices(), 3);
    std::copy(m_coords.begin(), m_coords.end(), result.mesh.vertices.data());
    if (m_known_faces) {
      result.mesh.faces = *m_known_faces;
    } else {
      result.mesh.faces.resize(static_cast<Index>(m_face_ids.size() / 3), 3);
      std::copy(m_face_ids.begin(), m_face_ids.end(), result.mesh.faces.data());
    }
    if (m_faces_before_face_text == 0) result.face_text_start = m_face_text_start;
    result.num_polygons = m_num_polygons;
    return result;
  }

 private:
  /// Parses the line at `pos` and returns where the next one starts.
  std::size_t parse_next_line(std::size_t pos) {
    if (const std::size_t next = parse_plain_line(pos); next != kNotPlain) return next;
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
    return end + 1;
  }

  /// At the first line start with all of `m_known`'s vertices and no face read: takes its
  /// faces if the rest of the text is its face text, byte for byte (tried once: a memcmp).
  bool try_known_face_text(std::size_t pos) {
    if (m_tried_known || num_vertices() != m_known->num_vertices || !m_face_ids.empty()) {
      return false;
    }
    m_tried_known = true;
    if (m_text.substr(pos) != m_known->bytes) return false;
    m_known_faces = &m_known->faces;
    m_num_polygons = m_known->num_polygons;
    return true;
  }

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

  /// Refuses to grow the arrays beyond the memory budget. Checked before a reallocation of
  /// `array` (about to take `more` elements): the peak is then about 3 times the data (old
  /// and doubled buffers; later the vectors and the returned mesh together).
  template <typename T>
  void check_growth(const std::vector<T>& array, std::size_t more) const {
    if (array.size() + more <= array.capacity()) return;
    const double bytes = 3.0 * (static_cast<double>(m_coords.size()) * sizeof(double) +
                                static_cast<double>(m_face_ids.size()) * sizeof(Index));
    check_memory_budget(bytes,
                        fmt::format("{}: line {}: reading the mesh", m_path.string(), m_line));
  }

  /// True where a plain number token may end: a blank, the line's end or the file's end.
  static bool ends_token(const char* p, const char* end) {
    return p == end || *p == '\n' || is_blank(*p);
  }

  /// Parses the common lines in one pass: `v x y z` and `f i j k ...` with plain numbers
  /// (no '+', no slashes), nothing else on the line. Returns the position after the line,
  /// or kNotPlain, having changed nothing, for any other line: parse_line() then parses
  /// it and reports its errors, so that both paths accept and refuse the same lines.
  std::size_t parse_plain_line(std::size_t pos) {
    const char* const begin = m_text.data() + pos;
    const char* const end = m_text.data() + m_text.size();
    if (end - begin < 2 || (begin[1] != ' ' && begin[1] != '\t')) return kNotPlain;
    const char* p = begin + 2;
    if (begin[0] == 'v') {
      std::array<double, 3> xyz{};
      for (double& value : xyz) {
        while (p != end && is_blank(*p)) ++p;
        const auto [stop, ec] = std::from_chars(p, end, value);
        // Out of range, non-finite and '+' numbers take the general path (strtod, errors).
        if (ec != std::errc() || !ends_token(stop, end) || !std::isfinite(value)) {
          return kNotPlain;
        }
        p = stop;
      }
      while (p != end && is_blank(*p)) ++p;
      if (p != end && *p != '\n') return kNotPlain;  // w, colours or a comment
      if (static_cast<std::size_t>(p - begin) > kMaxObjLineBytes) return kNotPlain;
      if (num_vertices() == std::numeric_limits<Index>::max()) fail("too many vertices");
      check_growth(m_coords, 3);
      m_coords.insert(m_coords.end(), xyz.begin(), xyz.end());
    } else if (begin[0] == 'f') {
      m_raw_polygon.clear();
      for (;;) {
        while (p != end && is_blank(*p)) ++p;
        if (p == end || *p == '\n') break;
        std::int64_t index = 0;
        const auto [stop, ec] = std::from_chars(p, end, index);
        if (ec != std::errc() || !ends_token(stop, end)) return kNotPlain;
        if (m_raw_polygon.size() == kMaxPlainPolygon) return kNotPlain;
        m_raw_polygon.push_back(index);
        p = stop;
      }
      if (static_cast<std::size_t>(p - begin) > kMaxObjLineBytes) return kNotPlain;
      m_polygon.clear();
      for (const std::int64_t index : m_raw_polygon) m_polygon.push_back(resolve_face_index(index));
      add_polygon();
    } else {
      return kNotPlain;
    }
    return p == end ? m_text.size() : static_cast<std::size_t>(p - m_text.data()) + 1;
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
    check_growth(m_coords, 3);
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
    return resolve_face_index(index);
  }

  /// The 0-based vertex id of a face's 1-based or negative (relative) vertex index.
  Index resolve_face_index(std::int64_t index) {
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
    add_polygon();
  }

  /// Checks the face in m_polygon and adds it (a polygon as a triangle fan).
  void add_polygon() {
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
    check_growth(m_face_ids, 3 * (m_polygon.size() - 2));
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
  std::vector<Index> m_polygon;             // the face being read, 0-based ids
  std::vector<std::int64_t> m_raw_polygon;  // its indices as written (plain lines)
  std::size_t m_num_polygons = 0;
  Index m_max_forward_index = -1;
  std::size_t m_max_forward_line = 0;
  // The face text: after the last `v` line, valid when no face came before it.
  std::size_t m_face_text_start = std::string_view::npos;
  std::size_t m_faces_before_face_text = 0;
  const ObjFaceText* m_known;                // an earlier frame's face text, or nullptr
  bool m_tried_known = false;                // try_known_face_text() compared the bytes
  const FaceArray* m_known_faces = nullptr;  // set when the face text was m_known's
};

}  // namespace

ObjParseResult parse_obj_text(std::string_view text, const std::filesystem::path& source,
                              const ObjFaceText* known) {
  return ObjParser(source, text, known).parse();
}

}  // namespace tailor
