/// @file
/// PLY header parsing: line by line, each line bounded, every error naming the line.

#include "tailor/io/ply_header.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <utility>

#include "tailor/geometry/error.hpp"
#include "tailor/io/excerpt.hpp"
#include "tailor/io/memory_budget.hpp"
#include "tailor/io/text_scan.hpp"

namespace tailor {
namespace {

using namespace text_scan;

class PlyHeaderParser {
 public:
  PlyHeaderParser(const std::filesystem::path& path, std::string_view bytes)
      : m_path(path), m_bytes(bytes) {}

  PlyHeader result() {
    parse();
    return std::move(m_header);
  }

 private:
  [[noreturn]] void fail_line(std::size_t line, const std::string& problem) const {
    throw InputError(fmt::format("{}: line {}: {}", m_path.string(), line, problem));
  }

  void parse() {
    std::size_t pos = 0;
    bool ended = false;
    bool have_format = false;
    while (!ended) {
      if (pos >= m_bytes.size()) {
        fail_line(m_line, "unexpected end of file in the header (no end_header line)");
      }
      ++m_line;
      // Look for the end of the line only so far: a binary file is no header.
      const std::size_t scan = std::min(m_bytes.size() - pos, kMaxPlyHeaderLineBytes + 1);
      const char* nl = static_cast<const char*>(std::memchr(m_bytes.data() + pos, '\n', scan));
      if (nl == nullptr && scan > kMaxPlyHeaderLineBytes) {
        if (m_line == 1) fail_line(1, "not a PLY file (the first line is not 'ply')");
        fail_line(m_line, fmt::format("header line longer than {} (no end_header line?)",
                                      format_bytes(kMaxPlyHeaderLineBytes)));
      }
      const std::size_t end = nl ? static_cast<std::size_t>(nl - m_bytes.data()) : m_bytes.size();
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
          m_header.format = PlyFormat::ascii;
        } else if (name == "binary_little_endian") {
          m_header.format = PlyFormat::binary_little_endian;
        } else if (name == "binary_big_endian") {
          m_header.format = PlyFormat::binary_big_endian;
        } else {
          fail_line(m_line, fmt::format("unknown format '{}'", excerpt(name)));
        }
        double v = 0.0;
        if (!parse_double(version, v) || v != 1.0) {
          fail_line(m_line, fmt::format("unsupported format version '{}' (expected 1.0)",
                                        excerpt(version)));
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
        fail_line(m_line, fmt::format("unknown header keyword '{}'", excerpt(keyword)));
      }
    }
    m_header.body_offset = std::min(pos, m_bytes.size());
    if (!have_format) fail_line(m_line, "missing format line in the header");
    check_header();
    m_header.body_line = m_line + 1;  // the line after end_header
  }

  void parse_element_line(std::string_view line) {
    PlyElement element;
    element.name = std::string(next_token(line));
    const std::string_view count = next_token(line);
    if (element.name.empty() || count.empty()) {
      fail_line(m_line, "element line needs a name and a count");
    }
    if (!parse_int(count, element.count)) {
      fail_line(m_line, fmt::format("garbage element count '{}'", excerpt(count)));
    }
    if (element.count < 0) {
      fail_line(m_line, fmt::format("negative count {} for element '{}'", element.count,
                                    excerpt(element.name)));
    }
    if (!next_token(line).empty()) fail_line(m_line, "garbage after the element count");
    for (const PlyElement& other : m_header.elements) {
      if (other.name == element.name) {
        fail_line(m_line, fmt::format("duplicate element '{}'", excerpt(element.name)));
      }
    }
    if (m_header.elements.size() == kMaxPlyElements) {
      fail_line(m_line, fmt::format("more than {} elements in the header", kMaxPlyElements));
    }
    m_header.elements.push_back(std::move(element));
  }

  void parse_property_line(std::string_view line) {
    if (m_header.elements.empty()) fail_line(m_line, "property line before any element line");
    PlyProperty property;
    std::string_view type = next_token(line);
    if (type == "list") {
      property.is_list = true;
      const std::string_view count_type = next_token(line);
      const auto ct = parse_ply_type(count_type);
      if (!ct) {
        fail_line(m_line, fmt::format("unknown list count type '{}'", excerpt(count_type)));
      }
      if (!is_integer_ply_type(*ct)) {
        fail_line(m_line,
                  fmt::format("list count type '{}' is not an integer type", excerpt(count_type)));
      }
      property.count_type = *ct;
      type = next_token(line);
    }
    const auto vt = parse_ply_type(type);
    if (!vt) fail_line(m_line, fmt::format("unknown property type '{}'", excerpt(type)));
    property.value_type = *vt;
    property.name = std::string(next_token(line));
    if (property.name.empty()) fail_line(m_line, "property line without a name");
    if (!next_token(line).empty()) fail_line(m_line, "garbage after the property name");
    for (const PlyProperty& other : m_header.elements.back().properties) {
      if (other.name == property.name) {
        fail_line(m_line, fmt::format("duplicate property '{}'", excerpt(property.name)));
      }
    }
    if (m_header.elements.back().properties.size() == kMaxPlyPropertiesPerElement) {
      fail_line(m_line,
                fmt::format("more than {} properties in element '{}'", kMaxPlyPropertiesPerElement,
                            excerpt(m_header.elements.back().name)));
    }
    m_header.elements.back().properties.push_back(std::move(property));
  }

  /// Finds the vertex and face elements and assigns roles to the properties we read.
  void check_header() {
    PlyElement* vertex = nullptr;
    PlyElement* face = nullptr;
    for (PlyElement& element : m_header.elements) {
      if (element.name == "vertex") vertex = &element;
      if (element.name == "face") face = &element;
    }
    if (vertex == nullptr) fail_line(m_line, "the header has no 'vertex' element");
    if (vertex->count > std::numeric_limits<Index>::max()) {
      fail_line(m_line, fmt::format("too many vertices ({})", vertex->count));
    }
    m_header.num_vertices = static_cast<Index>(vertex->count);
    for (const auto& [axis_name, role] :
         {std::pair{"x", PlyRole::x}, {"y", PlyRole::y}, {"z", PlyRole::z}}) {
      const std::string_view axis = axis_name;  // lambdas may not capture structured bindings
      auto it = std::find_if(vertex->properties.begin(), vertex->properties.end(),
                             [axis](const PlyProperty& p) { return p.name == axis; });
      if (it == vertex->properties.end()) {
        fail_line(m_line, fmt::format("the vertex element has no property '{}'", axis));
      }
      if (it->is_list) fail_line(m_line, fmt::format("vertex property '{}' is a list", axis));
      it->role = role;
    }
    m_header.num_faces = face ? face->count : 0;
    m_header.has_face_element = face != nullptr;
    if (face != nullptr) {
      auto it =
          std::find_if(face->properties.begin(), face->properties.end(), [](const PlyProperty& p) {
            return p.name == "vertex_indices" || p.name == "vertex_index";
          });
      if (it == face->properties.end()) {
        fail_line(m_line, "the face element has no list property 'vertex_indices'");
      }
      if (!it->is_list)
        fail_line(m_line, fmt::format("face property '{}' is not a list", excerpt(it->name)));
      if (!is_integer_ply_type(it->value_type)) {
        fail_line(m_line, fmt::format("face property '{}' has non-integer type '{}'",
                                      excerpt(it->name), ply_type_name(it->value_type)));
      }
      it->role = PlyRole::face_indices;
    }
  }

  const std::filesystem::path& m_path;
  std::string_view m_bytes;
  std::size_t m_line = 0;
  PlyHeader m_header;
};

}  // namespace

PlyHeader parse_ply_header(std::string_view bytes, const std::filesystem::path& source) {
  return PlyHeaderParser(source, bytes).result();
}

}  // namespace tailor
