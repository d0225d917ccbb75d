#pragma once
/// @file
/// Stanford PLY writing (ASCII or binary, positions and triangle faces).

#include <filesystem>

#include "tailor/geometry/types.hpp"
#include "tailor/io/ply_format.hpp"

namespace tailor {

/// How write_ply encodes a mesh.
struct PlyWriteOptions {
  PlyFormat format = PlyFormat::binary_little_endian;  ///< body encoding
  PlyType coordinate_type = PlyType::float64;          ///< float32 or float64
  PlyType count_type = PlyType::uint8;                 ///< type of the face list length (integer)
  PlyType index_type = PlyType::int32;                 ///< type of the face vertex ids (integer)
};

/// Writes a PLY file with the given encoding and types. Throws InputError if the file
/// cannot be written, the options are invalid (e.g. an integer coordinate type, or an
/// index type too small for the vertex count), a coordinate is not finite (or does not
/// fit in a float32), or a face index is out of range.
void write_ply(const std::filesystem::path& path, const Positions& vertices, const FaceArray& faces,
               const PlyWriteOptions& options = {});

}  // namespace tailor
