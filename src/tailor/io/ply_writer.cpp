/// @file
/// PLY writer: header, then the body in the chosen encoding, written in one piece.

#include "tailor/io/ply_writer.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "tailor/geometry/error.hpp"
#include "tailor/io/file_bytes.hpp"

namespace tailor {
namespace {

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

void write_ply(const std::filesystem::path& path, const Positions& vertices, const FaceArray& faces,
               const PlyWriteOptions& options) {
  const std::string name = path.string();
  if (is_integer_ply_type(options.coordinate_type)) {
    throw InputError(fmt::format("cannot write {}: coordinate type '{}' is not float or double",
                                 name, ply_type_name(options.coordinate_type)));
  }
  if (!is_integer_ply_type(options.count_type) || !is_integer_ply_type(options.index_type)) {
    throw InputError(fmt::format("cannot write {}: face list types must be integer types", name));
  }
  const Index nv = static_cast<Index>(vertices.rows());
  const Index nf = static_cast<Index>(faces.rows());
  if (nv > 0 && nv - 1 > ply_type_max(options.index_type)) {
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
