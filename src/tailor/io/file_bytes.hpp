#pragma once
/// @file
/// Whole-file reads and writes shared by the mesh readers and writers.

#include <filesystem>
#include <string>
#include <string_view>

namespace tailor {

/// Reads the whole file into memory. Throws InputError "cannot open" naming the path if
/// it is missing, is a directory or cannot be read.
std::string read_file_bytes(const std::filesystem::path& path);

/// Writes `bytes` to the file (replacing it). Throws InputError naming the path if the
/// file cannot be created or written.
void write_file_bytes(const std::filesystem::path& path, std::string_view bytes);

/// Writes `bytes` to `path.tmp`, then renames it over `path`, so a reader never sees
/// half a file. Throws InputError naming the path on failure.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace tailor
