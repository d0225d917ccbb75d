/// @file
/// PLY reader: the header, checked against the file size and the memory budget, then one
/// pass over the body in either encoding.

#include "tailor/io/ply_reader.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "tailor/geometry/error.hpp"
#include "tailor/io/excerpt.hpp"
#include "tailor/io/input_file.hpp"
#include "tailor/io/memory_budget.hpp"
#include "tailor/io/ply_format.hpp"
#include "tailor/io/ply_header.hpp"
#include "tailor/io/text_scan.hpp"

namespace tailor {
namespace {

using namespace text_scan;

/// Longest ASCII body token; no number needs more.
constexpr std::size_t kMaxAsciiTokenBytes = 1024;

/// Reads a whole PLY file; every error names the file and where in it the problem is.
class PlyParser {
 public:
  PlyParser(const std::filesystem::path& path, std::string_view bytes)
      : m_path(path), m_bytes(bytes) {}

  MeshData parse() {
    PlyHeader header = parse_ply_header(m_bytes, m_path);
    m_format = header.format;
    m_elements = std::move(header.elements);
    m_pos = header.body_offset;
    m_line = header.body_line;
    m_num_vertices = header.num_vertices;
    m_declared_faces = header.num_faces;
    m_has_face_element = header.has_face_element;
    m_swap = (m_format == PlyFormat::binary_little_endian) !=
             (std::endian::native == std::endian::little);
    for (const PlyElement& element : m_elements) {
      if (m_format == PlyFormat::ascii) {
        read_ascii_element(element);
      } else {
        read_binary_element(element);
      }
    }
    check_trailing_data();
    if (m_face_ids.empty()) {  // checked last: errors in the data say more
      throw InputError(
          fmt::format("{}: no faces ({} vertices and {}; a mesh needs at least one "
                      "triangle)",
                      m_path.string(), m_num_vertices,
                      m_has_face_element ? "a face element of 0 entries" : "no face element"));
    }
    if (m_num_polygons > 0) {
      spdlog::warn("{}: {} polygons with more than 3 vertices were split into triangle fans",
                   m_path.string(), m_num_polygons);
    }
    MeshData mesh;
    mesh.vertices.resize(m_num_vertices, 3);
    std::copy(m_coords.begin(), m_coords.end(), mesh.vertices.data());
    mesh.faces.resize(static_cast<Index>(m_face_ids.size() / 3), 3);
    std::copy(m_face_ids.begin(), m_face_ids.end(), mesh.faces.data());
    return mesh;
  }

 private:
  // ---------------------------------------------------------------- errors
  [[noreturn]] void fail_line(std::size_t line, const std::string& problem) const {
    throw InputError(fmt::format("{}: line {}: {}", m_path.string(), line, problem));
  }
  [[noreturn]] void fail_byte(std::size_t offset, const std::string& problem) const {
    throw InputError(fmt::format("{}: byte {}: {}", m_path.string(), offset, problem));
  }
  /// Fails at the current body position (line for ASCII, byte offset for binary).
  [[noreturn]] void fail_here(const std::string& problem) const {
    if (m_format == PlyFormat::ascii) fail_line(m_line, problem);
    fail_byte(m_pos, problem);
  }

  // ---------------------------------------------------------------- shared body logic
  /// Called once the body is known to hold the element (so that a truncated file is
  /// reported as such): refuses counts beyond the memory budget before allocating.
  void begin_element(const PlyElement& element) {
    if (!m_budget_checked && (element.name == "vertex" || element.name == "face")) {
      // Coordinates and triangle ids live twice at the end: in the parser and in the
      // returned mesh. Polygons add triangles: see add_polygon.
      check_memory_budget(2.0 * (static_cast<double>(m_num_vertices) * 3 * sizeof(double) +
                                 static_cast<double>(m_declared_faces) * 3 * sizeof(Index)),
                          fmt::format("{}: the header's {} vertices and {} faces", m_path.string(),
                                      m_num_vertices, m_declared_faces));
      m_budget_checked = true;
    }
    if (element.name == "vertex") {
      m_coords.assign(3 * static_cast<std::size_t>(m_num_vertices), 0.0);
    } else if (element.name == "face") {
      // Reserve only what the remaining bytes could hold (a bad count must not allocate).
      const std::size_t possible = (m_bytes.size() - m_pos) / 2;
      m_face_ids.reserve(3 *
                         std::min<std::size_t>(static_cast<std::size_t>(element.count), possible));
    }
  }

  /// Stores one polygon of face `f` (as fan triangles) after checking it.
  void add_polygon(std::int64_t f, std::size_t where) {
    auto fail_at = [&](const std::string& problem) {
      if (m_format == PlyFormat::ascii) fail_line(where, problem);
      fail_byte(where, problem);
    };
    const std::size_t k = m_polygon.size();
    if (k < 3) fail_at(fmt::format("face {} has {} vertices (a face needs at least 3)", f, k));
    for (std::size_t i = 0; i < k; ++i) {
      const std::int64_t v = m_polygon[i];
      if (v < 0 || v >= m_num_vertices) {
        fail_at(fmt::format("face {} has vertex index {} out of range (the file has {} vertices)",
                            f, v, m_num_vertices));
      }
    }
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t j = i + 1; j < k && k <= 16; ++j) {
        if (m_polygon[i] == m_polygon[j])
          fail_at(fmt::format("face {} repeats vertex {}", f, m_polygon[i]));
      }
    }
    if (k > 16) {
      std::vector<std::int64_t> sorted = m_polygon;
      std::sort(sorted.begin(), sorted.end());
      const auto dup = std::adjacent_find(sorted.begin(), sorted.end());
      if (dup != sorted.end()) fail_at(fmt::format("face {} repeats vertex {}", f, *dup));
    }
    if (k > 3) ++m_num_polygons;
    if (m_face_ids.size() + 3 * (k - 2) > m_face_ids.capacity()) {
      // Growing beyond the declared count (polygons): old and new buffers, then the copy.
      check_memory_budget(
          3.0 * static_cast<double>(m_face_ids.size() + 3 * (k - 2)) * sizeof(Index) +
              2.0 * static_cast<double>(m_coords.size()) * sizeof(double),
          fmt::format("{}: face {}: triangulating the polygons", m_path.string(), f));
    }
    if (m_face_ids.size() / 3 + (k - 2) >
        static_cast<std::size_t>(std::numeric_limits<Index>::max())) {
      fail_at("too many faces");
    }
    for (std::size_t i = 1; i + 1 < k; ++i) {
      m_face_ids.push_back(static_cast<Index>(m_polygon[0]));
      m_face_ids.push_back(static_cast<Index>(m_polygon[i]));
      m_face_ids.push_back(static_cast<Index>(m_polygon[i + 1]));
    }
  }

  void store_coordinate(PlyRole role, std::int64_t v, double value) {
    if (!std::isfinite(value)) {
      fail_here(fmt::format("vertex {} has a non-finite coordinate ({})", v, value));
    }
    m_coords[3 * static_cast<std::size_t>(v) + static_cast<std::size_t>(role) - 1] = value;
  }

  // ---------------------------------------------------------------- ASCII body
  /// Moves to the start of the next non-empty line; false at the end of the file.
  bool ascii_next_record() {
    while (m_pos < m_bytes.size()) {
      const char c = m_bytes[m_pos];
      if (c == '\n') {
        ++m_line;
      } else if (!is_blank(c)) {
        return true;
      }
      ++m_pos;
    }
    return false;
  }

  /// The next token on the current line (empty at the end of the line).
  std::string_view ascii_token() {
    while (m_pos < m_bytes.size() && is_blank(m_bytes[m_pos])) ++m_pos;
    const std::size_t start = m_pos;
    const std::size_t stop = std::min(m_bytes.size(), start + kMaxAsciiTokenBytes + 1);
    while (m_pos < stop && m_bytes[m_pos] != '\n' && !is_blank(m_bytes[m_pos])) ++m_pos;
    const std::string_view token = m_bytes.substr(start, m_pos - start);
    if (token.size() > kMaxAsciiTokenBytes) {
      fail_here(fmt::format("token '{}...' is longer than {} bytes (not an ASCII PLY body?)",
                            excerpt(token.substr(0, 10)), kMaxAsciiTokenBytes));
    }
    return token;
  }

  std::string_view ascii_value(const PlyElement& element, std::int64_t i) {
    const std::string_view token = ascii_token();
    if (token.empty()) {
      fail_here(
          fmt::format("{} {} has too few values on its line (truncated file or wrong "
                      "property list?)",
                      excerpt(element.name), i));
    }
    return token;
  }

  std::int64_t ascii_integer(std::string_view token, PlyType type, std::string_view what) {
    std::int64_t value = 0;
    if (!parse_int(token, value)) {
      fail_here(fmt::format("garbage token '{}' where an integer {} was expected", excerpt(token),
                            excerpt(what)));
    }
    if (value < ply_type_min(type) || value > ply_type_max(type)) {
      fail_here(fmt::format("{} {} does not fit in type '{}'", excerpt(what), value,
                            ply_type_name(type)));
    }
    return value;
  }

  double ascii_number(std::string_view token, PlyType type, std::string_view what) {
    if (is_integer_ply_type(type)) return static_cast<double>(ascii_integer(token, type, what));
    double value = 0.0;
    if (!parse_double(token, value)) {
      fail_here(fmt::format("garbage token '{}' where a number ({}) was expected", excerpt(token),
                            excerpt(what)));
    }
    // A float property holds a float: round like a binary file would have.
    if (type == PlyType::float32) return static_cast<double>(static_cast<float>(value));
    return value;
  }

  void read_ascii_element(const PlyElement& element) {
    if (element.properties.empty()) return;  // entries without values: nothing to read
    // Every value takes at least two bytes (a digit and a separator): reject counts that
    // cannot fit before allocating for them.
    const std::size_t remaining = m_bytes.size() - m_pos;
    const std::size_t min_entry = 2 * element.properties.size();
    if (static_cast<std::uint64_t>(element.count) > (remaining + 1) / min_entry) {
      fail_here(
          fmt::format("unexpected end of file: the header declares {} '{}' entries but "
                      "only {} bytes follow, too few to hold them (truncated file?)",
                      element.count, excerpt(element.name), remaining));
    }
    begin_element(element);
    for (std::int64_t i = 0; i < element.count; ++i) {
      if (!ascii_next_record()) {
        fail_here(
            fmt::format("unexpected end of file: the header declares {} '{}' entries but "
                        "only {} were found (truncated file?)",
                        element.count, excerpt(element.name), i));
      }
      const std::size_t record_line = m_line;
      for (const PlyProperty& property : element.properties) {
        if (property.is_list) {
          const std::int64_t n =
              ascii_integer(ascii_value(element, i), property.count_type, "list length");
          if (n < 0) fail_here(fmt::format("negative list length {}", n));
          if (property.role == PlyRole::face_indices) m_polygon.clear();
          for (std::int64_t j = 0; j < n; ++j) {
            const std::string_view token = ascii_value(element, i);
            if (property.role == PlyRole::face_indices) {
              m_polygon.push_back(ascii_integer(token, property.value_type, "vertex index"));
            } else {
              ascii_number(token, property.value_type, property.name);
            }
          }
        } else {
          const double value =
              ascii_number(ascii_value(element, i), property.value_type, property.name);
          if (property.role != PlyRole::skip) store_coordinate(property.role, i, value);
        }
      }
      const std::string_view extra = ascii_token();
      if (!extra.empty()) {
        fail_here(
            fmt::format("unexpected value '{}' after the last property of {} {} (do the "
                        "counts in the header match the data?)",
                        excerpt(extra), excerpt(element.name), i));
      }
      if (element.name == "face") add_polygon(i, record_line);
    }
  }

  // ---------------------------------------------------------------- binary body
  template <typename T>
  T load() {
    T value;
    if constexpr (sizeof(T) == 1) {
      std::memcpy(&value, m_bytes.data() + m_pos, 1);
    } else {
      using U =
          std::conditional_t<sizeof(T) == 2, std::uint16_t,
                             std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>;
      U bits;
      std::memcpy(&bits, m_bytes.data() + m_pos, sizeof(T));
      if (m_swap) {
        if constexpr (sizeof(T) == 2) bits = __builtin_bswap16(bits);
        if constexpr (sizeof(T) == 4) bits = __builtin_bswap32(bits);
        if constexpr (sizeof(T) == 8) bits = __builtin_bswap64(bits);
      }
      std::memcpy(&value, &bits, sizeof(T));
    }
    m_pos += sizeof(T);
    return value;
  }

  /// Reads one scalar (bounds already checked) as a Result: double for coordinates,
  /// std::int64_t for list counts and indices, whose types the header admits only among
  /// the integer ones (a float type there reads nothing and gives 0).
  template <class Result>
  Result load_as(PlyType type) {
    switch (type) {
      case PlyType::int8:
        return load<std::int8_t>();
      case PlyType::uint8:
        return load<std::uint8_t>();
      case PlyType::int16:
        return load<std::int16_t>();
      case PlyType::uint16:
        return load<std::uint16_t>();
      case PlyType::int32:
        return load<std::int32_t>();
      case PlyType::uint32:
        return load<std::uint32_t>();
      case PlyType::float32:
        if constexpr (std::is_floating_point_v<Result>) return load<float>();
        break;
      case PlyType::float64:
        if constexpr (std::is_floating_point_v<Result>) return load<double>();
        break;
    }
    return 0;
  }

  void need(std::size_t n, const PlyElement& element, std::int64_t i) {
    if (n > m_bytes.size() - m_pos) {
      fail_byte(m_pos, fmt::format("unexpected end of file in '{}' entry {} of {} (truncated "
                                   "file?)",
                                   excerpt(element.name), i, element.count));
    }
  }

  void read_binary_element(const PlyElement& element) {
    if (element.properties.empty()) return;  // entries without values take no bytes
    // Every entry needs at least its fixed-size part: reject absurd counts up front.
    std::size_t min_entry = 0;
    for (const PlyProperty& p : element.properties) {
      min_entry += p.is_list ? ply_type_size(p.count_type) : ply_type_size(p.value_type);
    }
    const std::size_t remaining = m_bytes.size() - m_pos;
    if (min_entry > 0 && static_cast<std::uint64_t>(element.count) > remaining / min_entry) {
      fail_byte(
          m_bytes.size(),
          fmt::format("unexpected end of file: the header declares {} '{}' entries (at "
                      "least {} bytes) but only {} bytes follow from byte {} (truncated "
                      "file?)",
                      element.count, excerpt(element.name),
                      static_cast<std::uint64_t>(element.count) * min_entry, remaining, m_pos));
    }
    begin_element(element);
    for (std::int64_t i = 0; i < element.count; ++i) {
      const std::size_t record_start = m_pos;
      for (const PlyProperty& property : element.properties) {
        if (property.is_list) {
          need(ply_type_size(property.count_type), element, i);
          const std::size_t count_at = m_pos;
          const std::int64_t n = load_as<std::int64_t>(property.count_type);
          if (n < 0)
            fail_byte(count_at, fmt::format("negative list length {} in '{}' entry {}", n,
                                            excerpt(element.name), i));
          const std::size_t bytes =
              static_cast<std::size_t>(n) * ply_type_size(property.value_type);
          need(bytes, element, i);
          if (property.role == PlyRole::face_indices) {
            m_polygon.resize(static_cast<std::size_t>(n));
            for (std::int64_t j = 0; j < n; ++j)
              m_polygon[j] = load_as<std::int64_t>(property.value_type);
          } else {
            m_pos += bytes;
          }
        } else {
          need(ply_type_size(property.value_type), element, i);
          if (property.role == PlyRole::skip) {
            m_pos += ply_type_size(property.value_type);
          } else {
            const std::size_t at = m_pos;
            const double value = load_as<double>(property.value_type);
            if (!std::isfinite(value)) {
              fail_byte(at, fmt::format("vertex {} has a non-finite coordinate ({})", i, value));
            }
            m_coords[3 * static_cast<std::size_t>(i) + static_cast<std::size_t>(property.role) -
                     1] = value;
          }
        }
      }
      if (element.name == "face") add_polygon(i, record_start);
    }
  }

  void check_trailing_data() {
    if (m_format == PlyFormat::ascii) {
      if (ascii_next_record()) {
        fail_here(
            "unexpected data after the last element (do the counts in the header match "
            "the data?)");
      }
    } else if (m_pos != m_bytes.size()) {
      fail_byte(m_pos, fmt::format("{} bytes of unexpected data after the last element (do the "
                                   "counts in the header match the data?)",
                                   m_bytes.size() - m_pos));
    }
  }

  const std::filesystem::path& m_path;
  std::string_view m_bytes;
  PlyFormat m_format = PlyFormat::ascii;
  bool m_swap = false;
  std::vector<PlyElement> m_elements;
  std::size_t m_pos = 0;   // body position (byte offset)
  std::size_t m_line = 0;  // current line (header and ASCII body)
  Index m_num_vertices = 0;
  std::int64_t m_declared_faces = 0;
  bool m_has_face_element = false;
  bool m_budget_checked = false;
  std::vector<double> m_coords;
  std::vector<Index> m_face_ids;
  std::vector<std::int64_t> m_polygon;
  std::size_t m_num_polygons = 0;
};

}  // namespace

MeshData parse_ply(std::string_view bytes, const std::filesystem::path& source) {
  return PlyParser(source, bytes).parse();
}

MeshData read_ply(const std::filesystem::path& path) {
  const InputFile file(path);
  return parse_ply(file.bytes(), path);
}

}  // namespace tailor
