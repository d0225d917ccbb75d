#pragma once
/// @file
/// The header of a PLY file: format, elements and properties, checked and annotated with
/// what the body reader does with each property.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "tailor/geometry/types.hpp"
#include "tailor/io/ply_format.hpp"

namespace tailor {

/// Longest PLY header line; a binary file without a newline is refused that soon.
inline constexpr std::size_t kMaxPlyHeaderLineBytes = std::size_t{64} << 10;
/// Most elements in a header (the duplicate-name checks are quadratic in this count; real
/// files have a handful).
inline constexpr std::size_t kMaxPlyElements = 256;
/// Most properties per element (likewise).
inline constexpr std::size_t kMaxPlyPropertiesPerElement = 256;

/// What the body reader does with a property's values.
enum class PlyRole { skip, x, y, z, face_indices };

/// One property of an element.
struct PlyProperty {
  std::string name;                       ///< as in the header
  bool is_list = false;                   ///< a list (count, then values)
  PlyType count_type = PlyType::uint8;    ///< type of a list's count (lists only)
  PlyType value_type = PlyType::float32;  ///< type of the value(s)
  PlyRole role = PlyRole::skip;           ///< what the reader does with it
};

/// One element: a name, a count and the properties of each entry.
struct PlyElement {
  std::string name;                     ///< as in the header
  std::int64_t count = 0;               ///< entries in the body (≥ 0)
  std::vector<PlyProperty> properties;  ///< in body order
};

/// A parsed PLY header.
struct PlyHeader {
  PlyFormat format = PlyFormat::ascii;  ///< body encoding
  std::vector<PlyElement> elements;     ///< in body order
  std::size_t body_offset = 0;          ///< byte where the body starts
  std::size_t body_line = 0;            ///< line number of the body's first line
  Index num_vertices = 0;               ///< entries of the `vertex` element
  std::int64_t num_faces = 0;           ///< entries of the `face` element (0 without one)
  bool has_face_element = false;        ///< whether there is a `face` element
};

/// Parses the header at the start of `bytes` (`source` names the file in errors). Throws
/// InputError naming the file and the line on anything but a version 1.0 header in a
/// known format with a `vertex` element having scalar x, y, z properties and, if there
/// is a `face` element, an integer list `vertex_indices` (or `vertex_index`); or on a
/// header line over kMaxPlyHeaderLineBytes, more elements or properties than the limits,
/// duplicate names, unknown types or keywords. Quoted tokens are cut (excerpt.hpp).
PlyHeader parse_ply_header(std::string_view bytes, const std::filesystem::path& source);

}  // namespace tailor
