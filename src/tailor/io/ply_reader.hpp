#pragma once
/// @file
/// Stanford PLY reading (ASCII and binary, positions and triangle faces).

#include <filesystem>
#include <string_view>

#include "tailor/mesh/mesh_data.hpp"

namespace tailor {

/// Reads a PLY file: ASCII or binary (either byte order), version 1.0; elements in any
/// order; `vertex` x, y, z of any scalar type; `face` list `vertex_indices` (or
/// `vertex_index`) of any integer types. Other elements and properties are skipped;
/// polygons are split into triangle fans (one warning per file). Throws InputError
/// naming the file, the line (header, ASCII body) or byte offset (binary body) and the
/// problem (truncated file, wrong counts, garbage, non-finite coordinate, index out of
/// range, bad header, no face, missing file, declared counts beyond the memory budget).
///
/// Hostile input: the file is mapped, not read (input_file.hpp); the header's counts are
/// checked against the bytes that follow and against the memory budget before anything
/// is allocated; a header line may not exceed 64 KiB, nor an ASCII token 1 KiB; a header
/// has at most 256 elements of at most 256 properties; quoted tokens are cut to ~40
/// bytes (excerpt.hpp).
MeshData read_ply(const std::filesystem::path& path);

/// Parses PLY bytes already in memory as read_ply() does; `source` names them in errors.
MeshData parse_ply(std::string_view bytes, const std::filesystem::path& source);

}  // namespace tailor
