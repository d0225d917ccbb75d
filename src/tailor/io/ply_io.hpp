#pragma once
/// @file
/// Stanford PLY reading and writing (ASCII and binary, positions and triangle faces).

#include <filesystem>
#include <string_view>

#include "tailor/geometry/types.hpp"
#include "tailor/mesh/mesh_data.hpp"

namespace tailor {

/// Encoding of a PLY file's body.
enum class PlyFormat { ascii, binary_little_endian, binary_big_endian };

/// Scalar types of PLY properties (the header accepts both the classic names such as
/// `uchar` and the sized names such as `uint8`).
enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

/// How write_ply encodes a mesh.
struct PlyWriteOptions {
  PlyFormat format = PlyFormat::binary_little_endian;  ///< body encoding
  PlyType coordinate_type = PlyType::float64;          ///< float32 or float64
  PlyType count_type = PlyType::uint8;                 ///< type of the face list length (integer)
  PlyType index_type = PlyType::int32;                 ///< type of the face vertex ids (integer)
};

/// Reads a PLY file: ASCII or binary (either byte order), version 1.0; elements in any
/// order; `vertex` x, y, z of any scalar type; `face` list `vertex_indices` (or
/// `vertex_index`) of any integer types. Other elements and properties are skipped;
/// polygons are split into triangle fans (one warning per file). Throws InputError
/// naming the file, the line (header, ASCII body) or byte offset (binary body) and the
/// problem (truncated file, wrong counts, garbage, non-finite coordinate, index out of
/// range, bad header, missing file).
MeshData read_ply(const std::filesystem::path& path);

/// Writes a PLY file with the given encoding and types. Throws InputError if the file
/// cannot be written, the options are invalid (e.g. an integer coordinate type, or an
/// index type too small for the vertex count), a coordinate is not finite (or does not
/// fit in a float32), or a face index is out of range.
void write_ply(const std::filesystem::path& path, const Positions& vertices, const FaceArray& faces,
               const PlyWriteOptions& options = {});

/// The header name of a type (`char`, `uchar`, `short`, `ushort`, `int`, `uint`,
/// `float`, `double`).
std::string_view ply_type_name(PlyType type);

/// The header name of a format (`ascii`, `binary_little_endian`, `binary_big_endian`).
std::string_view ply_format_name(PlyFormat format);

}  // namespace tailor
