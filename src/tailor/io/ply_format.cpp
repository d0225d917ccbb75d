/// @file
/// Names, sizes and ranges of the PLY scalar types.

#include "tailor/io/ply_format.hpp"

#include <limits>

namespace tailor {

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

std::optional<PlyType> parse_ply_type(std::string_view name) {
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

std::size_t ply_type_size(PlyType type) {
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

bool is_integer_ply_type(PlyType type) {
  return type != PlyType::float32 && type != PlyType::float64;
}

std::int64_t ply_type_min(PlyType type) {
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

std::int64_t ply_type_max(PlyType type) {
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

}  // namespace tailor
