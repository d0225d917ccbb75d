/// @file
/// PLY reader (header, then one pass over the body in either encoding) and writer.

#include "tailor/io/ply_io.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tailor/geometry/error.hpp"
#include "tailor/io/file_bytes.hpp"
#include "tailor/io/text_scan.hpp"

namespace tailor {
namespace {

using namespace text_scan;

std::size_t type_size(PlyType type) {
  switch (type) {
    case PlyType::int8:
    case PlyType::uint8:
      return 1;
    case PlyType::int16:
    case PlyType::uint16:
      return 2;
    case PlyType::int32:
    case PlyType::uint32:
    case PlyType::float32:
      return 4;
    case PlyType::float64:
      return 8;
  }
  return 0;
}

bool is_integer(PlyType type) {
  return type != PlyType::float32 && type != PlyType::float64;
}

std::int64_t type_min(PlyType type) {
  switch (type) {
    case PlyType::int8:
      return std::numeric_limits<std::int8_t>::min();
    case PlyType::int16:
      return std::numeric_limits<std::int16_t>::min();
    case PlyType::int32:
      return std::numeric_limits<std::int32_t>::min();
    default:
      return 0;
  }
}

std::int64_t type_max(PlyType type) {
  switch (type) {
    case PlyType::int8:
      return std::numeric_limits<std::int8_t>::max();
    case PlyType::uint8:
      return std::numeric_limits<std::uint8_t>::max();
    case PlyType::int16:
      return std::numeric_limits<std::int16_t>::max();
    case PlyType::uint16:
      return std::numeric_limits<std::uint16_t>::max();
    case PlyType::int32:
      return std::numeric_limits<std::int32_t>::max();
    case PlyType::uint32:
      return std::numeric_limits<std::uint32_t>::max();
    default:
      return std::numeric_limits<std::int64_t>::max();
  }
}

std::optional<PlyType> parse_type(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType::int8;
  if (name == "uchar" || name == "uint8") return PlyType::uint8;
  if (name == "short" || name == "int16") return PlyType::int16;
  if (name == "ushort" || name == "uint16") return PlyType::uint16;
  if (name == "int" || name == "int32") return PlyType::int32;
  if (name == "uint" || name == "uint32") return PlyType::uint32;
  if (name == "float" || name == "float32") return PlyType::float32;
  if (name == "double" || name == "float64") return PlyType::float64;
  return std::nullopt;
}

/// What the reader does with a property's values.
enum class Role { skip, x, y, z, face_indices };

struct PlyProperty {
  std::string name;
  bool is_list = false;
  PlyType count_type = PlyType::uint8;  // lists only
  PlyType value_type = PlyType::float32;
  Role role = Role::skip;
};

struct PlyElement {
  std::string name;
  std::int64_t count = 0;
  std::vector<PlyProperty> properties;
};

/// Reads a whole PLY file; every error names the file and where in it the problem is.
class PlyParser {
 public:
  PlyParser(const std::filesystem::path& path, std::string_view bytes)
      : m_path(path), m_bytes(bytes) {}

  MeshData parse() {
    parse_header();
    for (const PlyElement& element : m_elements) {
      if (m_format == PlyFormat::ascii) {
        read_ascii_element(element);
      } else {
        read_binary_element(element);
      }
    }
    check_trailing_data();
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

  // ---------------------------------------------------------------- header
  void parse_header() {
    std::size_t pos = 0;
    bool ended = false;
    bool have_format = false;
    while (!ended) {
      if (pos >= m_bytes.size()) {
        fail_line(m_line, "unexpected end of file in the header (no end_header line)");
      }
      ++m_line;
      std::size_t end = m_bytes.find('\n', pos);
      if (end == std::string_view::npos) end = m_bytes.size();
      std::string_view line = m_bytes.substr(pos, end - pos);
      pos = end + 1;
      if (m_line == 1) {
        if (next_token(line) != "ply" || !next_token(line).empty()) {
          fail_line(1, "not a PLY file (the first line is not 'ply')");
        }
        continue;
      }
      const std::string_view keyword = next_token(line);
      if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
      if (keyword == "format") {
        if (have_format) fail_line(m_line, "duplicate format line");
        const std::string_view name = next_token(line);
        const std::string_view version = next_token(line);
        if (name == "ascii") {
          m_format = PlyFormat::ascii;
        } else if (name == "binary_little_endian") {
          m_format = PlyFormat::binary_little_endian;
        } else if (name == "binary_big_endian") {
          m_format = PlyFormat::binary_big_endian;
        } else {
          fail_line(m_line, fmt::format("unknown format '{}'", name));
        }
        double v = 0.0;
        if (!parse_double(version, v) || v != 1.0) {
          fail_line(m_line, fmt::format("unsupported format version '{}' (expected 1.0)", version));
        }
        if (!next_token(line).empty()) fail_line(m_line, "garbage after the format version");
        have_format = true;
      } else if (keyword == "element") {
        parse_element_line(line);
      } else if (keyword == "property") {
        parse_property_line(line);
      } else if (keyword == "end_header") {
        ended = true;
      } else {
        fail_line(m_line, fmt::format("unknown header keyword '{}'", keyword));
      }
    }
    m_pos = std::min(pos, m_bytes.size());
    if (!have_format) fail_line(m_line, "missing format line in the header");
    check_header();
    ++m_line;  // the body starts on the line after end_header
    m_swap = (m_format == PlyFormat::binary_little_endian) !=
             (std::endian::native == std::endian::little);
  }

  void parse_element_line(std::string_view line) {
    PlyElement element;
    element.name = std::string(next_token(line));
    const std::string_view count = next_token(line);
    if (element.name.empty() || count.empty()) {
      fail_line(m_line, "element line needs a name and a count");
    }
    if (!parse_int(count, element.count)) {
      fail_line(m_line, fmt::format("garbage element count '{}'", count));
    }
    if (element.count < 0) {
      fail_line(m_line,
                fmt::format("negative count {} for element '{}'", element.count, element.name));
    }
    if (!next_token(line).empty()) fail_line(m_line, "garbage after the element count");
    for (const PlyElement& other : m_elements) {
      if (other.name == element.name) {
        fail_line(m_line, fmt::format("duplicate element '{}'", element.name));
      }
    }
    m_elements.push_back(std::move(element));
  }

  void parse_property_line(std::string_view line) {
    if (m_elements.empty()) fail_line(m_line, "property line before any element line");
    PlyProperty property;
    std::string_view type = next_token(line);
    if (type == "list") {
      property.is_list = true;
      const std::string_view count_type = next_token(line);
      const auto ct = parse_type(count_type);
      if (!ct) fail_line(m_line, fmt::format("unknown list count type '{}'", count_type));
      if (!is_integer(*ct)) {
        fail_line(m_line, fmt::format("list count type '{}' is not an integer type", count_type));
      }
      property.count_type = *ct;
      type = next_token(line);
    }
    const auto vt = parse_type(type);
    if (!vt) fail_line(m_line, fmt::format("unknown property type '{}'", type));
    property.value_type = *vt;
    property.name = std::string(next_token(line));
    if (property.name.empty()) fail_line(m_line, "property line without a name");
    if (!next_token(line).empty()) fail_line(m_line, "garbage after the property name");
    for (const PlyProperty& other : m_elements.back().properties) {
      if (other.name == property.name) {
        fail_line(m_line, fmt::format("duplicate property '{}'", property.name));
      }
    }
    m_elements.back().properties.push_back(std::move(property));
  }

  /// Finds the vertex and face elements and assigns roles to the properties we read.
  void check_header() {
    PlyElement* vertex = nullptr;
    PlyElement* face = nullptr;
    for (PlyElement& element : m_elements) {
      if (element.name == "vertex") vertex = &element;
      if (element.name == "face") face = &element;
    }
    if (vertex == nullptr) fail_line(m_line, "the header has no 'vertex' element");
    if (vertex->count > std::numeric_limits<Index>::max()) {
      fail_line(m_line, fmt::format("too many vertices ({})", vertex->count));
    }
    m_num_vertices = static_cast<Index>(vertex->count);
    for (const auto& [axis, role] : {std::pair{"x", Role::x}, {"y", Role::y}, {"z", Role::z}}) {
      auto it = std::find_if(vertex->properties.begin(), vertex->properties.end(),
                             [&](const PlyProperty& p) { return p.name == axis; });
      if (it == vertex->properties.end()) {
        fail_line(m_line, fmt::format("the vertex element has no property '{}'", axis));
      }
      if (it->is_list) fail_line(m_line, fmt::format("vertex property '{}' is a list", axis));
      it->role = role;
    }
    if (face != nullptr) {
      auto it =
          std::find_if(face->properties.begin(), face->properties.end(), [](const PlyProperty& p) {
            return p.name == "vertex_indices" || p.name == "vertex_index";
          });
      if (it == face->properties.end()) {
        fail_line(m_line, "the face element has no list property 'vertex_indices'");
      }
      if (!it->is_list)
        fail_line(m_line, fmt::format("face property '{}' is not a list", it->name));
      if (!is_integer(it->value_type)) {
        fail_line(m_line, fmt::format("face property '{}' has non-integer type '{}'", it->name,
                                      ply_type_name(it->value_type)));
      }
      it->role = Role::face_indices;
    }
  }

  // ---------------------------------------------------------------- shared body logic
  void begin_element(const PlyElement& element) {
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

  void store_coordinate(Role role, std::int64_t v, double value) {
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
    while (m_pos < m_bytes.size() && m_bytes[m_pos] != '\n' && !is_blank(m_bytes[m_pos])) ++m_pos;
    return m_bytes.substr(start, m_pos - start);
  }

  std::string_view ascii_value(const PlyElement& element, std::int64_t i) {
    const std::string_view token = ascii_token();
    if (token.empty()) {
      fail_here(
          fmt::format("{} {} has too few values on its line (truncated file or wrong "
                      "property list?)",
                      element.name, i));
    }
    return token;
  }

  std::int64_t ascii_integer(std::string_view token, PlyType type, std::string_view what) {
    std::int64_t value = 0;
    if (!parse_int(token, value)) {
      fail_here(fmt::format("garbage token '{}' where an integer {} was expected", token, what));
    }
    if (value < type_min(type) || value > type_max(type)) {
      fail_here(fmt::format("{} {} does not fit in type '{}'", what, value, ply_type_name(type)));
    }
    return value;
  }

  double ascii_number(std::string_view token, PlyType type, std::string_view what) {
    if (is_integer(type)) return static_cast<double>(ascii_integer(token, type, what));
    double value = 0.0;
    if (!parse_double(token, value)) {
      fail_here(fmt::format("garbage token '{}' where a number ({}) was expected", token, what));
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
                      element.count, element.name, remaining));
    }
    begin_element(element);
    for (std::int64_t i = 0; i < element.count; ++i) {
      if (!ascii_next_record()) {
        fail_here(
            fmt::format("unexpected end of file: the header declares {} '{}' entries but "
                        "only {} were found (truncated file?)",
                        element.count, element.name, i));
      }
      const std::size_t record_line = m_line;
      for (const PlyProperty& property : element.properties) {
        if (property.is_list) {
          const std::int64_t n =
              ascii_integer(ascii_value(element, i), property.count_type, "list length");
          if (n < 0) fail_here(fmt::format("negative list length {}", n));
          if (property.role == Role::face_indices) m_polygon.clear();
          for (std::int64_t j = 0; j < n; ++j) {
            const std::string_view token = ascii_value(element, i);
            if (property.role == Role::face_indices) {
              m_polygon.push_back(ascii_integer(token, property.value_type, "vertex index"));
            } else {
              ascii_number(token, property.value_type, property.name);
            }
          }
        } else {
          const double value =
              ascii_number(ascii_value(element, i), property.value_type, property.name);
          if (property.role != Role::skip) store_coordinate(property.role, i, value);
        }
      }
      const std::string_view extra = ascii_token();
      if (!extra.empty()) {
        fail_here(
            fmt::format("unexpected value '{}' after the last property of {} {} (do the "
                        "counts in the header match the data?)",
                        extra, element.name, i));
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

  /// Reads one scalar (bounds already checked) as a double.
  double load_number(PlyType type) {
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
        return load<float>();
      case PlyType::float64:
        return load<double>();
    }
    return 0.0;
  }

  /// Reads one integer scalar (bounds already checked).
  std::int64_t load_integer(PlyType type) {
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
      default:
        return 0;  // the header admits only integer count and index types here
    }
  }

  void need(std::size_t n, const PlyElement& element, std::int64_t i) {
    if (n > m_bytes.size() - m_pos) {
      fail_byte(m_pos, fmt::format("unexpected end of file in '{}' entry {} of {} (truncated "
                                   "file?)",
                                   element.name, i, element.count));
    }
  }

  void read_binary_element(const PlyElement& element) {
    if (element.properties.empty()) return;  // entries without values take no bytes
    // Every entry needs at least its fixed-size part: reject absurd counts up front.
    std::size_t min_entry = 0;
    for (const PlyProperty& p : element.properties) {
      min_entry += p.is_list ? type_size(p.count_type) : type_size(p.value_type);
    }
    const std::size_t remaining = m_bytes.size() - m_pos;
    if (min_entry > 0 && static_cast<std::uint64_t>(element.count) > remaining / min_entry) {
      fail_byte(
          m_bytes.size(),
          fmt::format("unexpected end of file: the header declares {} '{}' entries (at "
                      "least {} bytes) but only {} bytes follow from byte {} (truncated "
                      "file?)",
                      element.count, element.name,
                      static_cast<std::uint64_t>(element.count) * min_entry, remaining, m_pos));
    }
    begin_element(element);
    for (std::int64_t i = 0; i < element.count; ++i) {
      const std::size_t record_start = m_pos;
      for (const PlyProperty& property : element.properties) {
        if (property.is_list) {
          need(type_size(property.count_type), element, i);
          const std::size_t count_at = m_pos;
          const std::int64_t n = load_integer(property.count_type);
          if (n < 0)
            fail_byte(count_at,
                      fmt::format("negative list length {} in '{}' entry {}", n, element.name, i));
          const std::size_t bytes = static_cast<std::size_t>(n) * type_size(property.value_type);
          need(bytes, element, i);
          if (property.role == Role::face_indices) {
            m_polygon.resize(static_cast<std::size_t>(n));
            for (std::int64_t j = 0; j < n; ++j) m_polygon[j] = load_integer(property.value_type);
          } else {
            m_pos += bytes;
          }
        } else {
          need(type_size(property.value_type), element, i);
          if (property.role == Role::skip) {
            m_pos += type_size(property.value_type);
          } else {
            const std::size_t at = m_pos;
            const double value = load_number(property.value_type);
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
  std::vector<double> m_coords;
  std::vector<Index> m_face_ids;
  std::vector<std::int64_t> m_polygon;
  std::size_t m_num_polygons = 0;
};

// -------------------------------------------------------------------- writer helpers
template <typename T>
void append_binary(std::string& out, T value, bool swap) {
  using U = std::conditional_t<
      sizeof(T) == 1, std::uint8_t,
      std::conditional_t<sizeof(T) == 2, std::uint16_t,
                         std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
  U bits;
  std::memcpy(&bits, &value, sizeof(T));
  if (swap) {
    if constexpr (sizeof(T) == 2) bits = __builtin_bswap16(bits);
    if constexpr (sizeof(T) == 4) bits = __builtin_bswap32(bits);
    if constexpr (sizeof(T) == 8) bits = __builtin_bswap64(bits);
  }
  char buffer[sizeof(T)];
  std::memcpy(buffer, &bits, sizeof(T));
  out.append(buffer, sizeof(T));
}

/// Appends an integer already known to fit in `type`.
void append_integer(std::string& out, PlyType type, std::int64_t value, bool binary, bool swap) {
  if (!binary) {
    fmt::format_to(std::back_inserter(out), "{}", value);
    return;
  }
  switch (type) {
    case PlyType::int8:
      return append_binary(out, static_cast<std::int8_t>(value), swap);
    case PlyType::uint8:
      return append_binary(out, static_cast<std::uint8_t>(value), swap);
    case PlyType::int16:
      return append_binary(out, static_cast<std::int16_t>(value), swap);
    case PlyType::uint16:
      return append_binary(out, static_cast<std::uint16_t>(value), swap);
    case PlyType::int32:
      return append_binary(out, static_cast<std::int32_t>(value), swap);
    case PlyType::uint32:
      return append_binary(out, static_cast<std::uint32_t>(value), swap);
    default:
      return;
  }
}

}  // namespace

std::string_view ply_type_name(PlyType type) {
  switch (type) {
    case PlyType::int8:
      return "char";
    case PlyType::uint8:
      return "uchar";
    case PlyType::int16:
      return "short";
    case PlyType::uint16:
      return "ushort";
    case PlyType::int32:
      return "int";
    case PlyType::uint32:
      return "uint";
    case PlyType::float32:
      return "float";
    case PlyType::float64:
      return "double";
  }
  return "?";
}

std::string_view ply_format_name(PlyFormat format) {
  switch (format) {
    case PlyFormat::ascii:
      return "ascii";
    case PlyFormat::binary_little_endian:
      return "binary_little_endian";
    case PlyFormat::binary_big_endian:
      return "binary_big_endian";
  }
  return "?";
}

MeshData read_ply(const std::filesystem::path& path) {
  const std::string bytes = read_file_bytes(path);
  return PlyParser(path, bytes).parse();
}

void write_ply(const std::filesystem::path& path, const Positions& vertices, const FaceArray& faces,
               const PlyWriteOptions& options) {
  const std::string name = path.string();
  if (is_integer(options.coordinate_type)) {
    throw InputError(fmt::format("cannot write {}: coordinate type '{}' is not float or double",
                                 name, ply_type_name(options.coordinate_type)));
  }
  if (!is_integer(options.count_type) || !is_integer(options.index_type)) {
    throw InputError(fmt::format("cannot write {}: face list types must be integer types", name));
  }
  const Index nv = static_cast<Index>(vertices.rows());
  const Index nf = static_cast<Index>(faces.rows());
  if (nv > 0 && nv - 1 > type_max(options.index_type)) {
    throw InputError(fmt::format("cannot write {}: index type '{}' cannot hold vertex ids up to {}",
                                 name, ply_type_name(options.index_type), nv - 1));
  }
  const bool binary = options.format != PlyFormat::ascii;
  const bool swap = binary && (options.format == PlyFormat::binary_little_endian) !=
                                  (std::endian::native == std::endian::little);
  const bool single = options.coordinate_type == PlyType::float32;

  std::string out;
  fmt::format_to(std::back_inserter(out),
                 "ply\nformat {} 1.0\ncomment written by tailor\nelement vertex {}\n"
                 "property {} x\nproperty {} y\nproperty {} z\nelement face {}\n"
                 "property list {} {} vertex_indices\nend_header\n",
                 ply_format_name(options.format), nv, ply_type_name(options.coordinate_type),
                 ply_type_name(options.coordinate_type), ply_type_name(options.coordinate_type), nf,
                 ply_type_name(options.count_type), ply_type_name(options.index_type));
  out.reserve(out.size() + static_cast<std::size_t>(nv) * (binary ? 24 : 60) +
              static_cast<std::size_t>(nf) * (binary ? 13 : 24));
  for (Index v = 0; v < nv; ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      const double value = vertices(v, axis);
      const float value32 = static_cast<float>(value);
      if (!std::isfinite(value) || (single && !std::isfinite(value32))) {
        throw InputError(
            fmt::format("cannot write {}: vertex {} has a coordinate ({}) that is "
                        "not finite{}",
                        name, v, value, single ? " as a float" : ""));
      }
      if (binary) {
        if (single) {
          append_binary(out, value32, swap);
        } else {
          append_binary(out, value, swap);
        }
      } else {
        if (single) {
          fmt::format_to(std::back_inserter(out), "{}{:.9g}", axis == 0 ? "" : " ", value32);
        } else {
          fmt::format_to(std::back_inserter(out), "{}{:.17g}", axis == 0 ? "" : " ", value);
        }
      }
    }
    if (!binary) out.push_back('\n');
  }
  for (Index f = 0; f < nf; ++f) {
    append_integer(out, options.count_type, 3, binary, swap);
    for (int i = 0; i < 3; ++i) {
      const Index id = faces(f, i);
      if (id < 0 || id >= nv) {
        throw InputError(
            fmt::format("cannot write {}: face {} has vertex index {} out of range ({} vertices)",
                        name, f, id, nv));
      }
      if (!binary) out.push_back(' ');
      append_integer(out, options.index_type, id, binary, swap);
    }
    if (!binary) out.push_back('\n');
  }
  write_file_bytes(path, out);
}

}  // namespace tailor
