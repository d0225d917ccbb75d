#pragma once
/// @file
/// The vocabulary of PLY files: body encodings, scalar types, their names and sizes.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace tailor {

/// Encoding of a PLY file's body.
enum class PlyFormat { ascii, binary_little_endian, binary_big_endian };

/// Scalar types of PLY properties (the header accepts both the classic names such as
/// `uchar` and the sized names such as `uint8`).
enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

/// The header name of a type (`char`, `uchar`, `short`, `ushort`, `int`, `uint`,
/// `float`, `double`).
std::string_view ply_type_name(PlyType type);

/// The header name of a format (`ascii`, `binary_little_endian`, `binary_big_endian`).
std::string_view ply_format_name(PlyFormat format);

/// The type named `name` (classic or sized name), or nullopt.
std::optional<PlyType> parse_ply_type(std::string_view name);

/// Bytes of one value of `type` in a binary body.
std::size_t ply_type_size(PlyType type);

/// True for the integer types (everything but float32 and float64).
bool is_integer_ply_type(PlyType type);

/// Smallest value of an integer type (0 for the unsigned ones).
std::int64_t ply_type_min(PlyType type);

/// Largest value of an integer type (int64 max for the float types).
std::int64_t ply_type_max(PlyType type);

}  // namespace tailor
